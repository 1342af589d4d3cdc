// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Helpers shared by the text-file readers: user text quoted in error messages (bounded and printable), a
//! UTF-8 byte-order mark skipped, and a line reader that counts lines and knows whether the last one was cut.
#include <cstddef>
#include <istream>
#include <string>
#include <string_view>

namespace ctab::gen {

//! Characters of user text echoed in one error message; longer text is cut and ends in "…".
inline constexpr std::size_t kQuotedTextMaxChars = 60;

//! `text` in single quotes for an error message: control bytes shown as '?', cut after `max_chars`
//! characters (counted and cut at UTF-8 character boundaries) with "…" appended. One helper for every echo of
//! file or option text, so a 2 MB field never floods a message.
[[nodiscard]] inline std::string quote_user_text(std::string_view text, std::size_t max_chars = kQuotedTextMaxChars) {
  std::string out = "'";
  std::size_t chars = 0;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    const bool continuation = (byte & 0xC0) == 0x80;
    if (!continuation && chars++ == max_chars) {
      out += "\xE2\x80\xA6";  // U+2026 HORIZONTAL ELLIPSIS
      break;
    }
    out += (byte < 0x20 || byte == 0x7F) ? '?' : c;
  }
  return out + "'";
}

//! Removes a UTF-8 byte-order mark (EF BB BF) from the start of `line`; call it on a file's first line.
inline void strip_utf8_bom(std::string& line) {
  if (line.size() >= 3 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
}

//! Reads a stream line by line: counts lines (from 1), skips a byte-order mark on the first line and drops a
//! trailing '\r' (CRLF files).
class LineReader {
 public:
  explicit LineReader(std::istream& in) : in_(in) {}
  //! The next line into `text`; false at the end of the stream.
  bool next(std::string& text) {
    if (!std::getline(in_, text)) return false;
    unterminated_ = in_.eof();  // getline stopped at the end of the stream, not at a '\n'
    if (++line_ == 1) strip_utf8_bom(text);
    if (!text.empty() && text.back() == '\r') text.pop_back();
    return true;
  }
  //! Number of the line last read (0 before the first).
  [[nodiscard]] std::size_t line() const noexcept { return line_; }
  //! True when the line last read ended the stream without a newline (a file may have been cut there).
  [[nodiscard]] bool unterminated() const noexcept { return unterminated_; }

 private:
  std::istream& in_;
  std::size_t line_ = 0;
  bool unterminated_ = false;
};

}  // namespace ctab::gen
