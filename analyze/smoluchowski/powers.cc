#include "analyze/smoluchowski/powers.h"

#include <cmath>

namespace coolgas::smoluchowski {

KernelPowers::KernelPowers(const Kernel& kernel, const std::vector<double>& mass) {
  for (double e : kernel.exponents()) {
    std::vector<double> row(mass.size());
    for (std::size_t i = 0; i < mass.size(); ++i) row[i] = std::pow(mass[i], e);
    table.push_back(std::move(row));
  }
  for (const auto& t : kernel.terms) terms.push_back({t.c, kernel.exponent_index(t.p), kernel.exponent_index(t.q)});
}

}  // namespace coolgas::smoluchowski
