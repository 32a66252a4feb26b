// What the benchmarks read about their own process: resident memory and
// CPU time.
#pragma once
#include <sys/resource.h>

#include <fstream>
#include <string>

namespace coolgas::bench {

// A field of /proc/self/status in bytes: VmHWM (peak resident memory so
// far) or VmRSS (resident now).
inline double status_bytes(const std::string& field) {
  std::ifstream f("/proc/self/status");
  std::string key;
  double kb = 0;
  while (f >> key) {
    if (key == field) {
      f >> kb;
      break;
    }
    std::getline(f, key);
  }
  return kb * 1024.0;
}

// CPU seconds (user + system) this process has used so far.
inline double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

}  // namespace coolgas::bench
