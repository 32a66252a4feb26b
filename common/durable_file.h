// Files replaced whole or not at all: a copy made, changed and moved over the
// original, so that a process killed at any moment (or a power loss) leaves
// either the old file or the new one, never a mixture.
#pragma once
#include <string>

namespace coolgas {

// Copies `from` to `to` (created or truncated) and syncs it to disk. Checks
// first that the file system holds a second copy; WriteError (naming `to`
// and the system's reason) if not, or if a write fails, and `to` is removed.
// Stops with Interrupted between pieces of the copy on SIGINT/SIGTERM
// (common/interrupt.h), `to` removed.
void copy_file_durably(const std::string& from, const std::string& to);

// Syncs `path`'s data to disk; WriteError if that fails.
void sync_file(const std::string& path);

// Makes a rename inside `dir` durable (best effort: some file systems cannot
// sync a directory, and the data itself is already on disk).
void sync_directory(const std::string& dir);

// Moves `from` over `to` (one rename, atomic) and makes the move durable.
void replace_file(const std::string& from, const std::string& to);

}  // namespace coolgas
