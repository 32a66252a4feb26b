// The cases of the physics tests that run an equilibrium gas at several
// densities in each dimension: a dimension, a covered fraction phi and a
// seed, with the names gtest prints for them ("3D_phi0208").
#pragma once
#include <gtest/gtest.h>

#include <cstdint>
#include <ostream>
#include <string>

namespace coolgas::test {

struct Density {
  int dimension;
  double phi;
  std::int64_t seed;
};

inline void PrintTo(const Density& d, std::ostream* os) { *os << d.dimension << "D, phi = " << d.phi; }

inline std::string density_case_name(const ::testing::TestParamInfo<Density>& info) {
  std::string phi = std::to_string(info.param.phi).substr(2, 3);  // 0.208 -> "208"
  return std::to_string(info.param.dimension) + "D_phi0" + phi;
}

}  // namespace coolgas::test
