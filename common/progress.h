// Progress on stderr for long runs: one line rewritten in place, at most
// twice a second, only when stderr is a terminal (and not --quiet).
#pragma once
#include <chrono>
#include <string>

namespace coolgas {

class Progress {
 public:
  explicit Progress(bool enabled);
  ~Progress();
  // True when it is time to show a new line (cheap; call often).
  bool due();
  // Shows `line` in place of the previous one.
  void show(const std::string& line);
  // Seconds since construction.
  double elapsed() const;
  // "1h02m", "3m05s" or "12s".
  static std::string format_duration(double seconds);

 private:
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace coolgas
