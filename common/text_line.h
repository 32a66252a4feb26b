// Reading text line by line without trusting it: a device or file without
// newlines (/dev/zero: one endless line) must not make a reader grow
// without bound. Every coolgas reader of text (tables, extended XYZ) reads
// its lines here, against one bound.
#pragma once
#include <cstddef>
#include <istream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace coolgas {

// The longest line a reader accepts, its newline not counted: 1 MiB, far
// above any line coolgas writes (a table row, an XYZ comment line with its
// provenance: a few kB) or a program that writes these formats would.
inline constexpr std::size_t kMaxLineBytes = std::size_t(1) << 20;

// Why next_line refused a line, without the file and line number, which
// each reader adds in its own style.
struct LineRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// std::getline with a bound: the next line of `in` (without its newline)
// into `line`, false at the end of the input. LineRefused:
// - "a line longer than LIMIT bytes; WHOSE lines are at most LIMIT bytes"
//   as soon as its limit + 1st byte is read (so /dev/zero costs at most
//   `limit` bytes); `whose`: "a table's", "an extended XYZ file's";
// - "a read failed: CAUSE" when the system's read fails (a directory, an
//   I/O error), where std::getline would only set badbit.
bool next_line(std::istream& in, std::string& line, std::size_t limit, std::string_view whose);

}  // namespace coolgas
