// Issue 52, classes 4 and 5: what a Smoluchowski run may ask for. --M is
// refused when the run would not fit the memory available (counted before
// anything is allocated), a start holding a mass above the cut-off is
// refused before the vector of masses grows to it, and a signal stops the
// kernel's tabulation and a long evaluation inside a step.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <sstream>

#include "analyze/smoluchowski/direct.h"
#include "analyze/smoluchowski/initial.h"
#include "analyze/smoluchowski/integrator.h"
#include "analyze/smoluchowski/method.h"
#include "analyze/smoluchowski/run.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {
namespace {

std::string memory_refusal(const RunOptions& o, double memory) {
  try {
    check_run_memory(o, parse_kernel(o.kernel), memory);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(fits)";
}

// The run's bytes are counted as its parts allocate them: the FFT's
// buffer and spectra for 2^k >= 2M points, a power table per exponent, the
// stepper's stages.
TEST(SmoluchowskiBounds, TheBytesOfARunAreItsPartsCounted) {
  RunOptions o;
  o.kernel = "constant";  // one exponent, 0
  o.method.M = 1000;
  const double cells = 1000, length = 2048;
  const double method = (2 * cells + 1 + cells + length + 2 * (length / 2 + 1) * 2) * 8;
  EXPECT_EQ(method_bytes(parse_kernel(o.kernel), o.method), method);
  EXPECT_EQ(integrator_bytes(cells, Stepper::Rkck), 13 * cells * 8);
  EXPECT_EQ(run_bytes(o, parse_kernel(o.kernel)), method + 13 * cells * 8 + 3 * cells * 8);
  o.initial = "table.tsv";  // its masses 1..M besides the grid
  EXPECT_EQ(run_bytes(o, parse_kernel(o.kernel)), method + 13 * cells * 8 + 3 * cells * 8 + 1001 * 8);
}

// --M 1e8 asked ~30 GB, and ran 45 s before "out of memory": refused in one
// line naming --M, the bytes, the memory and the largest --M that fits.
TEST(SmoluchowskiBounds, AnMBeyondTheMemoryIsRefusedNamingTheLargestThatFits) {
  RunOptions o;
  o.method.M = 100000000;
  const double memory = 4e9;
  const std::string line = memory_refusal(o, memory);
  EXPECT_EQ(line.find("cut-off mass --M 100000000 would need "), 0u) << line;
  EXPECT_NE(line.find(" (method fft, kernel 'ballistic'); the memory available is 4 GB: --M at most "),
            std::string::npos)
      << line;
  const std::int64_t fits = std::stoll(line.substr(line.rfind(' ') + 1));
  o.method.M = fits;
  EXPECT_EQ(memory_refusal(o, memory), "(fits)");
  o.method.M = fits + 1;
  EXPECT_NE(memory_refusal(o, memory), "(fits)");
  for (const Method m : {Method::Direct, Method::Geometric}) {
    o.method.method = m;
    o.method.grid_ratio = 1.0000001;  // as many cells as masses
    o.method.M = 100000000;
    EXPECT_EQ(memory_refusal(o, memory).find("cut-off mass --M 100000000 would need "), 0u) << method_name(m);
  }
  o.method.grid_ratio = 1.05;  // a few hundred cells: fits
  EXPECT_EQ(memory_refusal(o, memory), "(fits)");
}

Table table_of(const std::string& text) {
  std::istringstream in(text);
  return read_table(in, "start.tsv");
}

// A mass of 1e15 grew the vector of masses to 8 PB ("out of memory").
TEST(SmoluchowskiBounds, AStartAboveTheCutOffIsRefusedBeforeTheMassesAreAllocated) {
  const auto refusal = [](const std::string& text) {
    try {
      initial_masses(table_of(text), 64);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(read)");
  };
  EXPECT_EQ(refusal("m\tN\n1\t1\n1e15\t1\n"),
            "start.tsv: initial distribution row 2 holds mass 1e+15 above the cut-off M = 64; raise --M");
  EXPECT_EQ(refusal("m\tN\n1e300\t1\n"),
            "start.tsv: initial distribution row 1 holds mass 1e+300 above the cut-off M = 64; raise --M");
  EXPECT_EQ(refusal("m\tN\n65\t1\n"),
            "start.tsv: initial distribution row 1 holds mass 65 above the cut-off M = 64; raise --M");
  EXPECT_EQ(refusal("m\tdm\tN\n30\t1e12\t1\n"),
            "start.tsv: initial distribution row 1 holds mass 1e+12 above the cut-off M = 64; raise --M");
  // A bin of centre 60 and width 10 reaches 64 + 1: its upper edge is refused.
  EXPECT_EQ(refusal("m\tdm\tN\n60\t11\t1\n").find("start.tsv: initial distribution row 1 holds mass "), 0u);
  EXPECT_EQ(initial_masses(table_of("m\tN\n64\t2\n"), 64).size(), 65u);
}

// With a signal recorded, the first look stops the run: an evaluation
// inside a step, or the kernel's table (10^8 powers take seconds). In a
// child process (the flag, once set, stays set): exit code 0 when both stop
// as they should.
void stopped_by_a_signal() {
  const Kernel k = parse_kernel("constant");
  DirectRhs rhs(k, 4096);
  std::vector<double> c(4096, 0.0);
  c[0] = 1;
  Integrator it(rhs, c, {});
  watch_interrupts();
  std::raise(SIGTERM);
  int stopped = 0;
  try {
    it.step(1.0);
  } catch (const Interrupted& e) {
    stopped += e.signal == SIGTERM && std::string(e.what()).find("during a step from t = 0") != std::string::npos;
  }
  try {
    const KernelPowers powers(k, std::vector<double>(10, 1.0));
  } catch (const Interrupted& e) {
    stopped += std::string(e.what()) == "interrupted by SIGTERM while tabulating the kernel; no table written";
  }
  std::exit(stopped == 2 ? 0 : 1);
}

TEST(SmoluchowskiBounds, ASignalStopsTheStepAndTheKernelTable) {
  EXPECT_EXIT(stopped_by_a_signal(), ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace coolgas::smoluchowski
