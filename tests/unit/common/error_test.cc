// One-line error messages (common/error.h): control characters escaped,
// long texts cut around "…" without splitting a UTF-8 character.
#include "common/error.h"

#include <gtest/gtest.h>

namespace coolgas {
namespace {

std::size_t characters(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

TEST(OneLine, ControlCharactersAreEscaped) {
  EXPECT_EQ(one_line("a\nb\tc\x01" "d\x7f"), "a\\nb\\tc\\x01d\\x7f");
  EXPECT_EQ(one_line("plain text, φ = 0.2"), "plain text, φ = 0.2");
}

TEST(OneLine, LongTextKeepsItsBeginningAndEnd) {
  const std::string text = "head:" + std::string(1000, 'x') + ":the rule and the fix";
  const std::string line = one_line(text);
  EXPECT_EQ(characters(line), kMaxMessageChars);
  EXPECT_EQ(line.rfind("head:", 0), 0u);
  EXPECT_EQ(line.substr(line.size() - 21), ":the rule and the fix");
  EXPECT_NE(line.find("…"), std::string::npos);
}

TEST(OneLine, MultibyteCharactersAreNeverSplit) {
  std::string text;
  for (int i = 0; i < 300; ++i) text += "φ";
  const std::string line = shown(text);
  EXPECT_EQ(characters(line), kMaxQuotedChars);
  for (std::size_t i = 0; i < line.size();) {  // every character is "φ" (2 bytes) or "…" (3 bytes)
    const bool phi = line.compare(i, 2, "φ") == 0;
    ASSERT_TRUE(phi || line.compare(i, 3, "…") == 0) << i;
    i += phi ? 2 : 3;
  }
}

TEST(OneLine, LongQuotedValuesAreCutBeforeTheRule) {
  const std::string folder(150, 'd');
  std::string text = "cannot write '/";
  text.append(folder).append("/out.h5': no directory '/").append(folder).append("'");
  const std::string line = one_line(text);
  EXPECT_LE(characters(line), kMaxMessageChars);
  EXPECT_EQ(line.rfind("cannot write '/ddd", 0), 0u) << line;
  EXPECT_NE(line.find("/out.h5': no directory '/dd"), std::string::npos) << line;
}

// Many values, none long enough to take the whole excess (a case the fuzz corpus found).
TEST(OneLine, ManyMediumValuesStillFit) {
  std::string text;
  for (int i = 0; i < 40; ++i) text += std::string(30, char('a' + i % 26)) + " ";
  EXPECT_LE(characters(one_line(text)), kMaxMessageChars);
}

}  // namespace
}  // namespace coolgas
