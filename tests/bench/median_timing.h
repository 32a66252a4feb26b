// Timing a step the way the analysis benchmarks report it: the median over
// repeats of wall-clock time and of this thread's CPU time (on a shared
// machine the CPU time tells what one core costs when other processes run).
#pragma once
#include <algorithm>
#include <chrono>
#include <ctime>
#include <functional>
#include <vector>

namespace coolgas::bench {

inline double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

inline double thread_cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct Timing {
  double wall, cpu;  // medians over the repeats, seconds
};

inline Timing median_time(int repeats, const std::function<void()>& f) {
  std::vector<double> wall, cpu;
  for (int r = 0; r < repeats; ++r) {
    const double w0 = wall_seconds(), c0 = thread_cpu_seconds();
    f();
    wall.push_back(wall_seconds() - w0);
    cpu.push_back(thread_cpu_seconds() - c0);
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  return {wall[wall.size() / 2], cpu[cpu.size() / 2]};
}

}  // namespace coolgas::bench
