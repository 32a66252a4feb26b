#include "common/text_line.h"

#include <cerrno>
#include <cstring>
#include <exception>

namespace coolgas {

bool next_line(std::istream& in, std::string& line, std::size_t limit, std::string_view whose) {
  line.clear();
  std::streambuf* buf = in.rdbuf();
  if (!buf) return false;
  // A file buffer throws when the system's read fails.
  const auto next = [&] {
    errno = 0;
    try {
      return buf->sbumpc();
    } catch (const std::exception&) {
      throw LineRefused(std::string("a read failed: ") + (errno ? std::strerror(errno) : "no cause given"));
    }
  };
  bool any = false;
  for (int c = next(); c != std::char_traits<char>::eof(); c = next()) {
    any = true;
    if (c == '\n') return true;
    if (line.size() == limit)
      throw LineRefused("a line longer than " + std::to_string(limit) + " bytes; " + std::string(whose) +
                        " lines are at most " + std::to_string(limit) + " bytes");
    line.push_back(char(c));
  }
  in.setstate(std::ios::eofbit);
  return any;
}

}  // namespace coolgas
