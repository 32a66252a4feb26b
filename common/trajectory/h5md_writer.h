// Writes trajectory files in the coolgas H5MD profile (data-schema/h5md-profile.md).
//
// Crash safety. Every object is created up front (by walking the profile,
// h5md_profile.h); then the file is switched to HDF5's single-writer /
// multiple-reader mode (SWMR), in which the library orders its writes so
// that the file on disk is consistent at every moment, and the analysis
// tools may read it while it grows. Writes happen in bursts: add_frame()
// writes the buffered observables and the frame, flushes, and only then
// appends the frame's /restart row and flushes again. A /restart row thus
// marks a frame complete; a process killed at any moment leaves every
// earlier frame readable and the file resumable (reopen()). reopen() opens
// straight into SWMR mode, so a resumed run is as safe from its first write.
// A kill in the
// middle of a frame can leave chunks past the end of allocation the file
// records; reopen() first moves that end past the file's size (as
// `h5clear -i` does), else dropping the half-written rows failed on close.
//
// Write errors. Each burst first reserves the disk space it needs, so a
// full disk, a quota or a file-size limit fails before HDF5 writes anything;
// every HDF5 write, flush and close is checked too. A failure is a
// WriteError naming the file and the system's reason; the frames before it
// stay complete. SIGXFSZ
// is ignored from create()/reopen() on, so a file-size limit makes the write
// fail with EFBIG instead of killing the process.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "common/geometry.h"
#include "common/hdf5_file.h"
#include "common/trajectory/layout.h"
#include "common/trajectory/run_parameters.h"
#include "common/trajectory/writer_lock.h"

namespace coolgas {

// One row of /observables.
struct ObservableRow {
  double time = 0;
  std::int64_t collisions = 0;
  std::int64_t below_delta = 0;
  double kinetic_energy = 0;  // per particle (aggregation: per initial particle)
  std::array<double, 3> momentum{};  // the first d components are written
  // aggregation only
  std::int64_t aggregates = 0;
  double mean_mass = 0, largest_mass = 0;
  double rotational_energy = 0;  // rough runs only: per particle
  // mixtures only: per particle of each species, the first S of kMaxFileSpecies
  // (a fixed array: rows are plain records, kept as they are in checkpoints)
  std::array<double, kMaxFileSpecies> species_energy{};
};

// One dump: N particles in particle-id order. Particle i's position is
// position[i * position_stride + 0..d-1] (likewise velocity; its image
// image[3 i + 0..d-1]), so the records of an engine can be written where
// they are, without a copy; a 2D file takes the first two components.
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
  // rough runs only: angular velocities, 3 per particle
  const double* angular_velocity = nullptr;
  // mixtures only: each particle's species
  const std::int32_t* species = nullptr;
};

// How the per-particle series of the dumps (positions, velocities, images
// and the aggregation fields) are stored: chunks of one dump's
// `particles_per_chunk` particles through shuffle + deflate at
// `deflate_level`, lossless (0: uncompressed, as coolgas wrote before).
// The defaults were chosen by measurement (tests/bench/history.md, "Dump size
// and write cost"): 32768 particles keep a chunk below HDF5's 1 MB chunk
// cache, so a reader that reads part of a dump inflates each chunk once.
// A chunk holds part of one dump only and is written once, whole, in that
// dump's burst: compressed chunks (whose size varies) are never rewritten in
// place, so the crash safety above is unchanged.
struct DumpStorage {
  std::int64_t particles_per_chunk = 32768;
  int deflate_level = 1;
};

class H5mdWriter {
 public:
  // Creates a new file (fails if it exists unless overwrite) for a run in
  // the geometry g (the box's `dimension`, and d components per vector).
  // The schema and program versions of `params` are set here.
  static H5mdWriter create(const std::string& path, const RunParameters& params, bool overwrite,
                           Geometry g, const DumpStorage& storage = {});
  // Opens an existing file to append after its last complete frame; rows
  // written after that frame (an interrupted burst) are dropped. InputError
  // if another process is writing it (writer_lock.h) or it is no coolgas
  // trajectory. `new_scene`, if given, replaces the stored scene text (a
  // resumed run may change run.* and output.* keys). That change, and the
  // conversion of a file of an earlier version, are made in a copy of the
  // file (FILE.partial, moved into place whole): a kill at any moment of a
  // reopen leaves a file that resumes.
  // `lock`: the file's writer lock, taken by claim() before the file was
  // read (taken here when not given).
  static H5mdWriter reopen(const std::string& path, const std::string* new_scene = nullptr, WriterLock lock = {});
  // The first step of a resume, before anything is read: takes the writer
  // lock (InputError if another process writes the file) and grows a file
  // an earlier version left recording more bytes than it holds
  // (h5::cover_recorded_allocation), which HDF5 would refuse to open.
  static WriterLock claim(const std::string& path);

  void add_observables(const ObservableRow& row) { pending_.push_back(row); }
  // Writes the buffered observables, then the frame, flushes, then its restart row, and flushes.
  void add_frame(const FrameView& frame);
  // Writes buffered observables and flushes (end of run).
  void flush();
  // Renames the file (the simulator writes its first dump under a temporary
  // name); later errors name the new path.
  void rename(const std::string& to);

  std::int64_t particles() const { return n_; }

 private:
  H5mdWriter() = default;
  static bool check_resumable(const std::string& path);
  static WriterLock rewrite_through_copy(const std::string& path, const std::string* scene, bool migrate);
  void create_objects(const RunParameters& params, const DumpStorage& storage);
  void drop_interrupted_burst();
  void begin_appending();
  void write_pending();
  void write_frame(const FrameView& frame);
  void write_restart_row(const FrameView& frame);
  void append(std::string_view element, std::int64_t step, double time, h5::Type type, const void* value,
              int stride = 0);
  void flush_file();
  hsize_t burst_bytes(bool with_frame) const;
  // Runs `body`, turning an HDF5 failure into a WriteError naming the file.
  template <class F>
  void writing(F&& body);

  std::string path_;
  WriterLock lock_;  // declared before file_: released after the file is closed
  h5::Handle file_;
  std::int64_t n_ = 0;
  double box_ = 0;
  int dimension_ = 3;
  layout::Layout layout_ = layout::Layout::kGas;
  bool rough_ = false;  // rough particles: their spins and rotational energy are written too
  // A mixture's species, where particles keep them (0: none, or aggregation's;
  // has_particle_species): each particle's species and their energies written too.
  std::size_t species_ = 0;
  bool appending_ = false;  // SWMR writing started (or, for an old-format file, first row written)
  std::vector<ObservableRow> pending_;
};

}  // namespace coolgas
