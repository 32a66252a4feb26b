// Tables of m^e for every exponent e of a kernel and every cell mass m, so
// that right-hand sides never call pow() in their inner loops.
#pragma once
#include <vector>

#include "analyze/smoluchowski/kernel.h"

namespace coolgas::smoluchowski {

struct KernelPowers {
  // One term of the kernel with its exponents replaced by table indices.
  struct Term {
    double c;
    int p, q;
  };
  std::vector<std::vector<double>> table;  // table[e][i] = mass[i]^exponent[e]
  std::vector<Term> terms;

  KernelPowers(const Kernel& kernel, const std::vector<double>& mass);
  // K between cells i and j.
  double k(std::size_t i, std::size_t j) const {
    double s = 0;
    for (const auto& t : terms) s += t.c * (table[t.p][i] * table[t.q][j] + table[t.q][i] * table[t.p][j]);
    return s;
  }
};

}  // namespace coolgas::smoluchowski
