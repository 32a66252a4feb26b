#include "common/memory.h"

#include <unistd.h>

#include <limits>
#include <sstream>

namespace coolgas {

double physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && size > 0 ? double(pages) * double(size) : std::numeric_limits<double>::infinity();
}

std::string bytes_text(double b) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (b >= 1000 && u < 6) b /= 1000, ++u;
  std::ostringstream s;
  s.precision(3);
  s << b << " " << units[u];
  return s.str();
}

}  // namespace coolgas
