// Size and write time of one dump as coolgas-simulate writes it
// (common/trajectory/h5md_writer.h, DumpStorage), for a real frame.
//
//   dump_bench TRAJECTORY DUMP REPEATS DEFLATE_LEVEL [PARTICLES_PER_CHUNK]
//
// Reads dump DUMP (-1: the last) of a gas trajectory, writes it REPEATS
// times into a new file `dump_bench.h5` in the current folder with the given
// storage (deflate level 0: uncompressed), times each dump's add_frame
// (buffered observables, frame, two flushes: the whole burst), reads the
// last dump back with the analysis tools' reader, checks it is bit for bit
// the frame written, and deletes the file. Prints one line:
//   N=... deflate=... chunk=... bytes_per_dump=... bytes_per_particle=... write_s=... write_cpu_s=... read_s=...
// write_s (wall), write_cpu_s (this thread's CPU time, user and system: what
// a dump costs a core on a shared machine) and read_s are medians over the
// repeats. bytes_per_dump is the
// file's growth per dump (chunks, their index and the file's page rounding).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "common/trajectory/frame_reader.h"
#include "common/trajectory/h5md_writer.h"
#include "common/trajectory/run_parameters.h"
#include "tests/bench/median_timing.h"

namespace {

using namespace coolgas;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: dump_bench TRAJECTORY DUMP REPEATS DEFLATE_LEVEL [PARTICLES_PER_CHUNK]\n");
    return 2;
  }
  const std::string input = argv[1];
  const long dump_arg = std::atol(argv[2]);
  const int repeats = std::max(1, std::atoi(argv[3]));
  DumpStorage storage;
  storage.deflate_level = std::atoi(argv[4]);
  if (argc > 5) storage.particles_per_chunk = std::atoll(argv[5]);

  Trajectory in(input, kPosition | kVelocity | kImage);
  if (in.aggregates()) {
    std::fprintf(stderr, "dump_bench: '%s' is an aggregation file; give a gas trajectory\n", input.c_str());
    return 2;
  }
  const std::size_t dump = dump_arg < 0 ? in.dump_times().size() - 1 : std::size_t(dump_arg);
  Frame frame;
  in.read(dump, frame);
  RunParameters params;
  {
    h5::Handle f = h5::open_file(input, h5::Mode::kReadOnly);
    params = read_file_parameters(f.id(), input);
  }

  const std::string out = "dump_bench.h5";
  std::vector<double> write_s, write_cpu_s, read_s;
  std::uintmax_t empty_bytes = 0;
  {
    H5mdWriter w = H5mdWriter::create(out, params, true, Geometry(3), storage);
    w.flush();
    empty_bytes = std::filesystem::file_size(out);
    for (int r = 0; r < repeats; ++r) {
      const double t = frame.time + r;
      const std::int64_t collisions = frame.step + r;
      w.add_observables({.time = t, .collisions = collisions});
      const double t0 = bench::wall_seconds(), c0 = bench::thread_cpu_seconds();
      w.add_frame({.time = t, .collisions = collisions, .position = frame.position.data(),
                   .image = frame.image.data(), .velocity = frame.velocity.data()});
      write_s.push_back(bench::wall_seconds() - t0);
      write_cpu_s.push_back(bench::thread_cpu_seconds() - c0);
    }
  }
  const double bytes_per_dump = double(std::filesystem::file_size(out) - empty_bytes) / repeats;

  Trajectory back(out, kPosition | kVelocity | kImage);
  Frame copy;
  for (int r = 0; r < repeats; ++r) {
    const double t0 = bench::wall_seconds();
    back.read(std::size_t(r), copy);
    read_s.push_back(bench::wall_seconds() - t0);
  }
  const bool same = copy.position == frame.position && copy.velocity == frame.velocity && copy.image == frame.image;
  std::filesystem::remove(out);
  if (!same) {
    std::fprintf(stderr, "dump_bench: the dump read back differs from the one written\n");
    return 1;
  }
  const double n = double(in.particles());
  std::printf(
      "N=%.0f deflate=%d chunk=%lld bytes_per_dump=%.0f bytes_per_particle=%.2f write_s=%.4f write_cpu_s=%.4f "
      "read_s=%.4f\n",
      n, storage.deflate_level, static_cast<long long>(storage.particles_per_chunk), bytes_per_dump, bytes_per_dump / n,
      median(write_s), median(write_cpu_s), median(read_s));
  return 0;
}
