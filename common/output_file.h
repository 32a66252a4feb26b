// Checking, before any work, that a program can write the file it was asked
// for (-o): a typo in a path should cost nothing and say exactly what is wrong.
#pragma once
#include <string>
#include <string_view>

namespace coolgas {

// The longest suffix a writer adds to an output's name: coolgas-simulate
// writes FILE.partial, then FILE.checkpoint beside FILE, through
// FILE.checkpoint.partial. A name is refused unless this longest one fits
// too, so the limit stated is the limit every file of the run meets.
inline constexpr std::string_view kLongestSuffix = ".checkpoint.partial";
inline constexpr std::size_t kTemporarySuffixChars = kLongestSuffix.size();

// Throws InputError (one line, exit code 2) when `path` is empty, names a
// directory or anything but a regular file (a device node, pipe or socket
// is never replaced, even with `replace`), exists and !replace, has a name
// too long for its file system (leaving room for the longest suffix), or
// lies in a folder that is missing, not a folder, or not writable.
// `or_else`: another way out the message offers beside --force ("--resume it").
void check_output_file(const std::string& path, bool replace, const std::string& or_else = "");

}  // namespace coolgas
