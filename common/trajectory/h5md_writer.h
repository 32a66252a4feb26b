// Writes trajectory files in the coolgas H5MD profile (data-schema/h5md-profile.md).
//
// Writes happen in bursts: observables are buffered in memory and written,
// together with a frame, by add_frame(), which ends with an HDF5 flush. A
// process killed between bursts leaves a file whose earlier frames all read.
// The /restart row is written last in each burst: it marks the frame complete.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "common/hdf5_file.h"

namespace coolgas {

// The run's inputs, stored as /parameters attributes.
struct RunParameters {
  std::string scene_toml;  // the complete effective scene
  std::int64_t seed = 0;
  std::int64_t N = 0;
  double L = 0, phi = 0, T0 = 0;
  std::string model = "elastic";
  double r0 = 1, delta = 0;
  double viscoelastic_b = 0;  // written for model "viscoelastic" only (schema version 2)
};

// Files of model "aggregation" hold, besides the version-1 layout, per-particle
// id, mass and diameter and the aggregate observables (schema version 2).
bool is_aggregation_model(const std::string& model);

// One row of /observables.
struct ObservableRow {
  double time = 0;
  std::int64_t collisions = 0;
  std::int64_t below_delta = 0;
  double kinetic_energy = 0;  // per particle (aggregation: per initial particle)
  std::array<double, 3> momentum{};
  // aggregation only
  std::int64_t aggregates = 0;
  double mean_mass = 0, largest_mass = 0;
};

// One dump: N particles in particle-id order. Particle i's position is
// position[i * position_stride + 0..2] (likewise velocity), so the records of
// an engine can be written where they are, without a copy.
struct FrameView {
  double time = 0;
  std::int64_t collisions = 0;
  std::int64_t below_delta = 0;
  const double* position = nullptr;
  const std::int32_t* image = nullptr;
  const double* velocity = nullptr;
  int position_stride = 3;
  int velocity_stride = 3;
  // aggregation only: per slot id (-1: absent), mass and diameter (0 when absent)
  const std::int32_t* id = nullptr;
  const double* mass = nullptr;
  const double* diameter = nullptr;
};

class H5mdWriter {
 public:
  // Creates a new file (fails if it exists unless overwrite).
  static H5mdWriter create(const std::string& path, const RunParameters& params, bool overwrite);
  // Opens an existing file to append after its last complete frame; rows
  // written after that frame (an interrupted burst) are dropped.
  static H5mdWriter reopen(const std::string& path);

  void add_observables(const ObservableRow& row) { pending_.push_back(row); }
  // Writes the buffered observables, then the frame, then its restart row, then flushes.
  void add_frame(const FrameView& frame);
  // Writes buffered observables and flushes (end of run).
  void flush();
  // Replaces the stored scene text (a resumed run may extend run.t_end).
  void update_scene(const std::string& scene_toml);

  std::int64_t particles() const { return n_; }

 private:
  H5mdWriter() = default;
  void open_elements();
  void write_pending();

  h5::Handle file_;
  std::int64_t n_ = 0;
  double box_ = 0;
  bool aggregation_ = false;
  std::vector<ObservableRow> pending_;
};

}  // namespace coolgas
