// Checking, before any work, that a program can write the file it was asked
// for (-o): a typo in a path should cost nothing and say exactly what is wrong.
#pragma once
#include <string>

namespace coolgas {

// Room a writer may add to the name for its temporary file (".partial").
inline constexpr std::size_t kTemporarySuffixChars = 8;

// Throws InputError (one line, exit code 2) when `path` is empty, names a
// directory or anything but a regular file (a device node, pipe or socket
// is never replaced, even with `replace`), exists and !replace, has a name
// too long for its file system (leaving room for the temporary suffix), or
// lies in a folder that is missing, not a folder, or not writable.
void check_output_file(const std::string& path, bool replace);

}  // namespace coolgas
