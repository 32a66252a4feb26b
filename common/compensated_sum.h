// Neumaier's compensated summation: the sum of many terms exact to about one
// rounding, whatever their number, so that E/E0 stays accurate down to 1e-12
// and below in very long runs.
#pragma once
#include <cmath>

namespace coolgas {

class CompensatedSum {
 public:
  void add(double x) {
    const double s = sum_ + x;
    c_ += std::fabs(sum_) >= std::fabs(x) ? (sum_ - s) + x : (x - s) + sum_;
    sum_ = s;
  }
  double value() const { return sum_ + c_; }

 private:
  double sum_ = 0, c_ = 0;
};

}  // namespace coolgas
