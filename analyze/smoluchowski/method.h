// Choosing a method: the right-hand side that a run integrates.
//   direct     DirectRhs, O(M^2) per evaluation: the reference for small M
//   fft        FftRhs, O(M log M): the default, same equation as direct
//   geometric  GeometricRhs, O(cells^2) on a geometric grid of ratio r: long times
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "analyze/smoluchowski/fft.h"
#include "analyze/smoluchowski/grid.h"
#include "analyze/smoluchowski/kernel.h"

namespace coolgas::smoluchowski {

enum class Method { Direct, Fft, Geometric };

Method parse_method(const std::string& name);  // InputError naming the choices
std::string method_name(Method m);

struct MethodOptions {
  Method method = Method::Fft;
  std::int64_t M = 1 << 14;      // cut-off: largest mass kept
  double grid_ratio = 1.05;      // geometric: growth factor of the pivots
  double fft_floor = FftRhs::kDefaultFloor;  // fft: support threshold (see fft.h)
};

// InputError for M < 2 (nothing could coagulate) or out-of-range knobs.
void validate(const MethodOptions& o);

std::unique_ptr<CoagulationRhs> make_rhs(const Kernel& kernel, const MethodOptions& o);

// The cells of the method's grid (M, or the geometric grid's pivots, at
// most), without making the grid.
double grid_cells(const MethodOptions& o);
// The bytes make_rhs(kernel, o) allocates: the grid, the kernel's power
// tables (one per exponent) and the method's own (the direct method's
// table; the FFT's buffer and one spectrum per exponent, 2^k >= 2M long;
// the geometric method's losses). Counted before anything is allocated.
double method_bytes(const Kernel& kernel, const MethodOptions& o);

}  // namespace coolgas::smoluchowski
