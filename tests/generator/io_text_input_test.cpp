// SPDX-License-Identifier: Apache-2.0
// Text-input helpers: user text quoted for messages (bounded, printable, UTF-8 safe), byte-order mark, lines.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "ctab/io/text_input.hpp"

using namespace ctab::gen;

TEST(TextInput, QuotesShortTextAsIs) {
  EXPECT_EQ(quote_user_text("abc"), "'abc'");
  EXPECT_EQ(quote_user_text(""), "''");
  EXPECT_EQ(quote_user_text(std::string(60, 'x')), "'" + std::string(60, 'x') + "'");
}

TEST(TextInput, CutsLongTextAt60CharactersWithEllipsis) {
  const std::string huge(2'000'000, '7');  // a 2 MB field
  const std::string quoted = quote_user_text(huge);
  EXPECT_EQ(quoted, "'" + std::string(60, '7') + "\xE2\x80\xA6'");
  EXPECT_EQ(quote_user_text("abcdef", 3), "'abc\xE2\x80\xA6'");
}

TEST(TextInput, CountsAndCutsWholeUtf8Characters) {
  std::string accents;
  for (int i = 0; i < 70; ++i) accents += "\xC3\xA9";  // U+00E9, two bytes each
  std::string expected = "'";
  for (int i = 0; i < 60; ++i) expected += "\xC3\xA9";
  EXPECT_EQ(quote_user_text(accents), expected + "\xE2\x80\xA6'");
}

TEST(TextInput, ShowsControlBytesAsQuestionMarks) {
  EXPECT_EQ(quote_user_text(std::string("a\tb\nc\0d\x7F", 8)), "'a?b?c?d?'");
}

TEST(TextInput, StripsAByteOrderMarkOnly) {
  std::string line = "\xEF\xBB\xBFy_m,h_m";
  strip_utf8_bom(line);
  EXPECT_EQ(line, "y_m,h_m");
  strip_utf8_bom(line);
  EXPECT_EQ(line, "y_m,h_m");
  std::string short_line = "\xEF\xBB";
  strip_utf8_bom(short_line);
  EXPECT_EQ(short_line, "\xEF\xBB");
}

TEST(TextInput, LineReaderCountsLinesDropsBomAndCrAndSeesACutLastLine) {
  std::istringstream in("\xEF\xBB\xBF"
                        "first\r\nsecond\nthird");
  LineReader reader(in);
  std::string text;
  ASSERT_TRUE(reader.next(text));
  EXPECT_EQ(text, "first");
  EXPECT_EQ(reader.line(), 1u);
  EXPECT_FALSE(reader.unterminated());
  ASSERT_TRUE(reader.next(text));
  EXPECT_EQ(text, "second");
  EXPECT_FALSE(reader.unterminated());
  ASSERT_TRUE(reader.next(text));
  EXPECT_EQ(text, "third");
  EXPECT_EQ(reader.line(), 3u);
  EXPECT_TRUE(reader.unterminated());
  EXPECT_FALSE(reader.next(text));
  std::istringstream terminated("a\nb\n");
  LineReader second(terminated);
  while (second.next(text)) {
  }
  EXPECT_EQ(second.line(), 2u);
  EXPECT_FALSE(second.unterminated());
}
