// SPDX-License-Identifier: Apache-2.0
#include "ctab/io/gap_csv.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include "ctab/core/error.hpp"
#include "ctab/io/text_input.hpp"

namespace ctab::gen {

namespace {

constexpr std::array<std::string_view, 4> kColumns = {"y_m", "h_m", "A_per_m", "B_per_m"};
// h is the separation of the undeformed bodies: never negative beyond the rounding of a computed gap (1 nm).
constexpr double kMinSeparation_m = -1e-9;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(
        trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

std::optional<double> parse_number(std::string_view text) {
  double value = 0.0;
  if (text.size() > 1 && text.front() == '+') text.remove_prefix(1);  // from_chars rejects a leading '+'
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || text.empty()) return std::nullopt;
  return value;
}

bool is_blank_or_comment(std::string_view line) {
  const std::string_view t = trim(line);
  return t.empty() || t.front() == '#';
}

}  // namespace

GapProfile parse_gap_csv(std::istream& in, const std::string& source) {
  GapProfile gap;
  gap.source = source;
  std::vector<std::size_t> line_of_row;
  std::array<std::size_t, 4> column_index{};
  std::size_t field_count = 0;
  bool have_header = false;
  std::string line;
  LineReader reader(in);  // skips a UTF-8 byte-order mark
  std::size_t line_number = 0;
  while (reader.next(line)) {
    line_number = reader.line();
    if (is_blank_or_comment(line)) continue;
    const auto fields = split_fields(line);
    if (!have_header) {
      for (std::size_t c = 0; c < kColumns.size(); ++c) {
        std::size_t found = fields.size();
        for (std::size_t f = 0; f < fields.size(); ++f)
          if (fields[f] == kColumns[c]) found = f;
        if (found == fields.size())
          throw InputError(source, line_number,
                           "header must name the columns y_m,h_m,A_per_m,B_per_m; missing '" +
                               std::string(kColumns[c]) + "'");
        column_index[c] = found;
      }
      field_count = fields.size();
      have_header = true;
      continue;
    }
    if (fields.size() != field_count)
      throw InputError(source, line_number,
                       "expected " + std::to_string(field_count) + " fields, got " + std::to_string(fields.size()));
    std::array<double, 4> values{};
    for (std::size_t c = 0; c < kColumns.size(); ++c) {
      const auto value = parse_number(fields[column_index[c]]);
      if (!value)
        throw InputError(source, line_number,
                         "field '" + std::string(kColumns[c]) + "': expected a number, got " +
                             quote_user_text(fields[column_index[c]]));
      if (!std::isfinite(*value))
        throw InputError(source, line_number, "field '" + std::string(kColumns[c]) + "': value is not finite");
      values[c] = *value;
    }
    if (!(values[1] >= kMinSeparation_m))
      throw InputError(source, line_number,
                       "field 'h_m': a separation must not be negative (the bodies' gap before loading), got " +
                           quote_user_text(fields[column_index[1]]));
    if (!(values[2] > 0.0))
      throw InputError(source, line_number,
                       "field 'A_per_m': must be positive, got " + quote_user_text(fields[column_index[2]]));
    if (!gap.y_m.empty() && !(values[0] > gap.y_m.back()))
      throw InputError(source, line_number, "field 'y_m': strips must be strictly increasing in y");
    gap.y_m.push_back(values[0]);
    gap.h_m.push_back(values[1]);
    gap.A_per_m.push_back(values[2]);
    gap.B_per_m.push_back(values[3]);
    line_of_row.push_back(line_number);
  }
  if (!have_header) throw InputError(source, 0, "empty gap file: expected a header y_m,h_m,A_per_m,B_per_m and rows");
  if (gap.size() < 3)
    throw InputError(source, line_number, "need at least 3 rows of gap data, got " + std::to_string(gap.size()));
  validate(gap);
  return gap;
}

GapProfile read_gap_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open gap file");
  return parse_gap_csv(in, path);
}

void write_gap_csv(const GapProfile& gap, std::ostream& out) {
  out << "y_m,h_m,A_per_m,B_per_m\n" << std::setprecision(std::numeric_limits<double>::max_digits10);
  for (std::size_t i = 0; i < gap.size(); ++i)
    out << gap.y_m[i] << ',' << gap.h_m[i] << ',' << gap.A_per_m[i] << ',' << gap.B_per_m[i] << '\n';
}

}  // namespace ctab::gen
