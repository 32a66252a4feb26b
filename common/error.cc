#include "common/error.h"

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <vector>

namespace coolgas {

namespace {

// The text split into printable pieces: one UTF-8 character, or the escape
// of one control byte.
std::vector<std::string> printable_characters(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) {
      char esc[8];
      if (c == '\n') std::snprintf(esc, sizeof esc, "\\n");
      else if (c == '\t') std::snprintf(esc, sizeof esc, "\\t");
      else std::snprintf(esc, sizeof esc, "\\x%02x", c);
      out.emplace_back(esc);
      ++i;
      continue;
    }
    std::size_t len = 1;  // a UTF-8 lead byte and its continuation bytes
    while (i + len < text.size() && (static_cast<unsigned char>(text[i + len]) & 0xC0) == 0x80) ++len;
    out.push_back(text.substr(i, len));
    i += len;
  }
  return out;
}

using Chars = std::vector<std::string>;

std::string joined(const Chars& chars, std::size_t from, std::size_t to) {
  std::string out;
  for (std::size_t i = from; i < to; ++i) out += chars[i];
  return out;
}

// chars[from, to) cut to `keep` characters: its first and last halves around "…".
Chars cut_middle(const Chars& chars, std::size_t from, std::size_t to, std::size_t keep, std::size_t tail) {
  Chars out(chars.begin() + std::ptrdiff_t(from), chars.begin() + std::ptrdiff_t(from + keep - 1 - tail));
  out.emplace_back("…");
  out.insert(out.end(), chars.begin() + std::ptrdiff_t(to - tail), chars.begin() + std::ptrdiff_t(to));
  return out;
}

// The longest value of the message, as [begin, end): a quoted text ('...' or
// "...", inside the quotes) or a word without spaces (an unquoted path).
std::pair<std::size_t, std::size_t> longest_value(const Chars& chars) {
  std::pair<std::size_t, std::size_t> best{0, 0};
  auto consider = [&](std::size_t b, std::size_t e) {
    if (e - b > best.second - best.first) best = {b, e};
  };
  for (std::size_t i = 0; i < chars.size(); ++i) {
    if (chars[i] == "'" || chars[i] == "\"") {
      std::size_t j = i + 1;
      while (j < chars.size() && chars[j] != chars[i]) ++j;
      if (j < chars.size()) {
        consider(i + 1, j);
        i = j;
        continue;
      }
    }
    std::size_t j = i;
    while (j < chars.size() && chars[j] != " ") ++j;
    consider(i, j);
    i = j;
  }
  return best;
}

}  // namespace

std::string one_line(const std::string& text, std::size_t max_chars) {
  Chars chars = printable_characters(text);
  // Long values (paths, scene strings) are shortened first, so that the
  // message keeps the rule and the fix.
  constexpr std::size_t kMinQuoted = 24;
  while (chars.size() > max_chars) {
    const auto [b, e] = longest_value(chars);
    if (e - b <= kMinQuoted) break;
    const std::size_t excess = chars.size() - max_chars;
    const std::size_t keep = e - b > kMinQuoted + excess ? (e - b) - excess : kMinQuoted;
    Chars cut = cut_middle(chars, b, e, keep, keep / 2);
    cut.insert(cut.begin(), chars.begin(), chars.begin() + std::ptrdiff_t(b));
    cut.insert(cut.end(), chars.begin() + std::ptrdiff_t(e), chars.end());
    chars = std::move(cut);
  }
  if (chars.size() <= max_chars) return joined(chars, 0, chars.size());
  // The end of a message usually holds the rule and the fix: keep it.
  return joined(cut_middle(chars, 0, chars.size(), max_chars, (max_chars - 1) / 3), 0, max_chars);
}

}  // namespace coolgas
