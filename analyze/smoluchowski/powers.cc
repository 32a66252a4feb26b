#include "analyze/smoluchowski/powers.h"

#include <cmath>

#include "common/interrupt.h"

namespace coolgas::smoluchowski {

KernelPowers::KernelPowers(const Kernel& kernel, const std::vector<double>& mass) {
  for (double e : kernel.exponents()) {
    std::vector<double> row(mass.size());
    // A row of 10^8 masses takes seconds: the interrupt flag is looked at
    // every 2^20 of them (common/interrupt.h).
    for (std::size_t i = 0; i < mass.size(); ++i) {
      if (i % (std::size_t(1) << 20) == 0) throw_if_interrupted("while tabulating the kernel; no table written");
      row[i] = std::pow(mass[i], e);
    }
    table.push_back(std::move(row));
  }
  for (const auto& t : kernel.terms) terms.push_back({t.c, kernel.exponent_index(t.p), kernel.exponent_index(t.q)});
}

}  // namespace coolgas::smoluchowski
