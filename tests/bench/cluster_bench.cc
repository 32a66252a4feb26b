// Speed of coolgas-clusters on the paper's largest system: N = 8e6 particles at
// phi = 0.208 (L = 272.1, a 272^3 cell grid).
//   1. labelling + binning one frame (file reading excluded), for uniformly
//      random centres and for a clustered configuration;
//   2. reading one frame's positions from an H5MD file written by H5mdWriter
//      (the file is deleted afterwards).
// Prints one line per figure: medians of several repeats, wall-clock and
// this thread's CPU time.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "analyze/labelling/cluster_labeller.h"
#include "analyze/clusters/mass_distribution.h"
#include "common/random.h"
#include "common/trajectory/frame_reader.h"
#include "common/trajectory/h5md_writer.h"
#include "tests/bench/median_timing.h"

namespace {

using coolgas::ClusterGrid;
using coolgas::ClusterLabeller;
using coolgas::MassHistogram;

constexpr std::int64_t kN = 8'000'000;
constexpr double kPhi = 0.208;
const double kL = std::cbrt(kN * M_PI / (6 * kPhi));

using coolgas::bench::median_time;
using coolgas::bench::Timing;

std::vector<double> uniform_positions(std::uint64_t seed) {
  coolgas::Random rng(seed);
  std::vector<double> pos(3 * kN);
  for (double& x : pos) x = kL * rng.uniform();
  return pos;
}

// Clustered: 3/4 of the particles in Gaussian clumps strung along random-walk
// filaments (extended clusters as in the paper's Fig. 3), the rest uniform.
// Particle order is shuffled, as in a run where particles have mixed.
std::vector<double> clustered_positions(std::uint64_t seed) {
  coolgas::Random rng(seed);  // portable: the same positions with every standard library
  const auto u = [&] { return kL * rng.uniform(); };
  const auto g = [&] { return rng.normal(); };
  std::vector<double> pos;
  pos.reserve(3 * kN);
  const std::int64_t in_filaments = 3 * kN / 4, per_clump = 200;
  double c[3] = {u(), u(), u()};
  for (std::int64_t p = 0; p < in_filaments; ++p) {
    if (p % per_clump == 0) {
      if (p % (per_clump * 500) == 0) c[0] = u(), c[1] = u(), c[2] = u();  // new filament
      for (double& x : c) x += 2.5 * g();
    }
    for (double x : c) pos.push_back(x + 1.5 * g());
  }
  while (std::int64_t(pos.size()) < 3 * kN) pos.push_back(u());
  for (double& x : pos) x = std::fmod(std::fmod(x, kL) + kL, kL);
  std::vector<std::int64_t> order(kN);
  for (std::int64_t i = 0; i < kN; ++i) order[i] = i;
  for (std::int64_t i = kN - 1; i > 0; --i) std::swap(order[i], order[rng.below(std::uint64_t(i) + 1)]);  // Fisher-Yates
  std::vector<double> shuffled(3 * kN);
  for (std::int64_t i = 0; i < kN; ++i)
    for (int d = 0; d < 3; ++d) shuffled[3 * i + d] = pos[3 * order[i] + d];
  return shuffled;
}

void bench_labelling(const char* name, const std::vector<double>& pos) {
  const ClusterGrid grid(kL, coolgas::Geometry(3));
  ClusterLabeller lab;
  MassHistogram hist(10, kN);
  auto frame = [&] {
    lab.label(grid, pos);
    hist.clear();
    lab.for_each_mass([&](std::int64_t m) { hist.add(m); });
  };
  frame();  // first call allocates the buffers; the tool reuses them from dump to dump
  const Timing t = median_time(9, frame);
  const auto& mo = hist.moments();
  std::printf("label+bin %-9s N=%lld grid=%d^3: %.1f ms wall, %.1f ms cpu (clusters %lld, largest %lld = %.1f%%)\n",
              name, (long long)kN, grid.per_side(), 1e3 * t.wall, 1e3 * t.cpu, (long long)mo.clusters,
              (long long)mo.largest, 100.0 * double(mo.largest) / double(mo.mass));
}

// Drops the file's pages from the page cache (written back first), so the
// next read comes from the disk; other files are not touched.
void evict_from_page_cache(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY);
  if (fd < 0) return;
  fdatasync(fd);
  posix_fadvise(fd, 0, 0, POSIX_FADV_DONTNEED);
  close(fd);
}

void bench_frame_read(const std::vector<double>& pos) {
  const auto dir = std::filesystem::temp_directory_path() / ("coolgas-cluster-bench-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "run.h5").string();
  {
    coolgas::RunParameters p;
    p.N = kN;
    p.L = kL;
    p.phi = kPhi;
    auto w = coolgas::H5mdWriter::create(path, p, true, coolgas::Geometry(3));
    std::vector<std::int32_t> img(3 * kN, 0);
    std::vector<double> vel(3 * kN, 0.5);
    w.add_frame({0.0, 0, 0, pos.data(), img.data(), vel.data()});
  }
  const double mb = 3.0 * kN * sizeof(double) / 1e6;
  coolgas::Frame frame;
  {
    evict_from_page_cache(path);
    coolgas::Trajectory traj(path, coolgas::kPosition);
    const Timing cold = median_time(1, [&] { traj.read(0, frame); });
    std::printf("read positions of one frame (%.0f MB, from disk, finiteness check included): %.1f ms = %.0f MB/s\n",
                mb, 1e3 * cold.wall, mb / cold.wall);
  }
  coolgas::Trajectory traj(path, coolgas::kPosition);
  const Timing t = median_time(5, [&] { traj.read(0, frame); });
  std::printf(
      "read positions of one frame (%.0f MB, page cache warm, finiteness check included): %.1f ms = %.0f MB/s\n", mb,
      1e3 * t.wall, mb / t.wall);
  std::filesystem::remove_all(dir);
}

}  // namespace

int main() {
  std::printf("N = %lld, phi = %.3f, L = %.2f\n", (long long)kN, kPhi, kL);
  const auto uniform = uniform_positions(1);
  bench_labelling("uniform", uniform);
  bench_labelling("clustered", clustered_positions(2));
  bench_frame_read(uniform);
  return 0;
}
