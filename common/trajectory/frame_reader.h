// Reads the dumps (frames) of a coolgas trajectory file
// (data-schema/h5md-profile.md) for the analysis tools.
//
// A Trajectory is opened for the per-particle elements a tool needs; it checks
// they exist with the same shape (F, N, 3) and lists the dump times. A frame is
// read element by element with one hyperslab read each, straight into the
// frame's buffers, which are reused from frame to frame.
//
// To read another per-particle element, add a Field bit, a buffer in Frame
// and a row in the element table of frame_reader.cc.
//
// A mixture's files (schema version 6) hold each particle's species; a
// Trajectory of such a file opened for kMass or kDiameter reads them and
// fills each particle's mass and diameter from the species table.
//
// Ballistic aggregation files (model "aggregation", schema version 2 or 3) keep N
// slots per dump and mark empty ones with id -1 (H5MD's convention for a
// varying number of particles). A Trajectory of such a file always reads id
// and mass too and hands out only the aggregates present: the arrays of a
// Frame then hold one entry per aggregate, with its mass in `mass`.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "common/geometry.h"
#include "common/hdf5_file.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas {

// Per-particle elements, combinable as a bit set. kAnyDimension is no
// element: it lets a reader that handles disks and rods open a 2D or 1D file,
// whose frames then hold z = 0 (and y = 0 in 1D); a reader without it
// refuses them.
enum Field : unsigned {
  kPosition = 1u,
  kVelocity = 2u,
  kImage = 4u,
  kId = 8u,
  kMass = 16u,
  kDiameter = 32u,
  kAnyDimension = 64u,
  kAngularVelocity = 128u,  // rough runs' spins; read where the file has them (else left empty)
  kSpecies = 256u           // a mixture's species; read where the file has them (else left empty)
};

// One dump. Arrays hold 3 numbers per particle, in particle-id order (for a
// 2D file opened with kAnyDimension, the third is 0; for a 1D file, the
// second and third).
struct Frame {
  std::size_t dump = 0;  // index in the file
  double time = 0;
  std::int64_t step = 0;
  double L = 0;  // box side at this dump
  std::vector<double> position;
  std::vector<double> velocity;
  std::vector<std::int32_t> image;
  // aggregation files only (empty otherwise): id and mass of each aggregate present,
  // and its diameter when the Trajectory was opened for kDiameter
  std::vector<std::int32_t> id;
  std::vector<double> mass;
  std::vector<double> diameter;
  // rough runs only (empty otherwise), when opened for kAngularVelocity: 3 per particle in every dimension
  std::vector<double> angular_velocity;
  // mixtures only (empty otherwise), when opened for kSpecies, kMass or kDiameter: each particle's species
  // (an index into /parameters/species_*), from which its mass and diameter are filled when asked for
  std::vector<std::int32_t> species;

  std::size_t particles() const { return id.empty() ? std::max({position.size(), velocity.size(), image.size()}) / 3 : id.size(); }
};

class Trajectory {
 public:
  // Opens `path` for reading the elements in `fields` (InputError naming the
  // file and the missing dataset if it is not a coolgas trajectory).
  Trajectory(const std::string& path, unsigned fields);
  // Whether frames hold `f` (an element asked for that the file has: a smooth run has no spins).
  bool has(Field f) const { return ((fields_ | filled_) & f) != 0; }

  const std::string& path() const { return path_; }
  std::int64_t particles() const { return n_; }  // N (slots, for aggregation files)
  bool aggregates() const { return aggregates_; }  // an aggregation file: frames hold the aggregates present
  std::size_t species_count() const { return species_count_; }  // a mixture's species (0: particles all alike)
  int dimension() const { return dimension_; }     // 3, or 2 or 1 (opened with kAnyDimension)
  Geometry geometry() const { return Geometry(dimension_); }
  const std::vector<double>& dump_times() const { return times_; }
  // Index of the dump whose time is nearest t (the earlier one on a tie).
  std::size_t nearest_dump(double t) const;
  // The dumps nearest each of `times` in the order given; all dumps if `times`
  // is empty. A time no dump has (to 1e-9, relative) is snapped to the
  // nearest dump with a note on stderr naming both, or, with `exact`
  // (--exact-time), refused (InputError).
  std::vector<std::size_t> dumps_nearest(const std::vector<double>& times, bool exact = false) const;
  std::size_t dump_at(double t, bool exact) const;  // one of them

  // Reads dump `dump` into `frame` (its buffers are reused). Non-finite
  // numbers in a double element are an InputError naming dump and particle.
  void read(std::size_t dump, Frame& frame) const;
  // The tools' loop: reads each of `dumps` into `frame` in turn and calls
  // f(frame), stopping between dumps on SIGINT or SIGTERM (Interrupted).
  template <class F>
  void for_each_dump(const std::vector<std::size_t>& dumps, Frame& frame, F f) const {
    for (std::size_t i = 0; i < dumps.size(); ++i) {
      throw_if_interrupted(i, dumps.size(), "dumps");
      read(dumps[i], frame);
      f(frame);
    }
  }
  // The box side at dump `dump` (InputError for a box that is not one).
  double box_side(std::size_t dump) const;

  // "input", then seed and the physics fields of /parameters
  // (run_parameters.h: N, L, phi, T0, model and the model's own), for the
  // provenance block of a table.
  Provenance provenance() const;

 private:
  [[noreturn]] void missing(const std::string& what) const;
  void check_element(const std::string& element, bool vector, hsize_t per_particle);
  void keep_present(Frame& frame) const;
  void fill_from_species(Frame& frame, const std::string& where) const;

  std::string path_;
  unsigned fields_;
  bool aggregates_ = false;
  int dimension_ = 3;
  std::vector<double> species_mass_, species_diameter_;  // a mixture's table (else empty)
  unsigned filled_ = 0;  // fields filled from the species (a mixture's kMass, kDiameter), not read
  std::size_t species_count_ = 0;
  h5::Handle file_;
  std::int64_t n_ = 0;
  std::vector<double> times_;
  std::vector<std::int64_t> steps_;
};

}  // namespace coolgas
