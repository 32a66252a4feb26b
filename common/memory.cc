#include "common/memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

namespace coolgas {

namespace {

double physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && size > 0 ? double(pages) * double(size) : std::numeric_limits<double>::infinity();
}

// memory.max of this process's cgroup (version 2), if it has a number there.
double cgroup_limit_bytes() {
  std::ifstream self("/proc/self/cgroup");
  std::string line, path;
  while (std::getline(self, line))
    if (line.rfind("0::", 0) == 0) path = line.substr(3);
  if (path.empty()) return std::numeric_limits<double>::infinity();
  std::ifstream max("/sys/fs/cgroup" + (path == "/" ? std::string() : path) + "/memory.max");
  double bytes = 0;
  if (max >> bytes && bytes > 0) return bytes;  // "max" reads as no number: no limit
  return std::numeric_limits<double>::infinity();
}

}  // namespace

double usable_memory_bytes() {
  double bytes = std::min(physical_memory_bytes(), cgroup_limit_bytes());
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) bytes = std::min(bytes, double(as.rlim_cur));
  return bytes;
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
