#include "common/trajectory/h5md_writer.h"

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "common/durable_file.h"
#include "common/error.h"
#include "common/fault_point.h"
#include "common/interrupt.h"
#include "common/trajectory/collision_models.h"
#include "common/trajectory/h5md_profile.h"
#include "common/version.h"

namespace coolgas {
namespace {

using namespace layout;

constexpr hsize_t kFrameChunk = 1;  // one frame per chunk: frames are large
constexpr hsize_t kObservableChunk = 256;

// A file-size limit (ulimit -f) must make write() fail with EFBIG, which is
// reported like a full disk, instead of killing the process with SIGXFSZ.
void ignore_file_size_signal() { std::signal(SIGXFSZ, SIG_IGN); }

h5::Type h5_type(schema::DataType t) {
  switch (t) {
    case schema::DataType::kInt32: return h5::Type::kInt32;
    case schema::DataType::kInt64: return h5::Type::kInt64;
    default: return h5::Type::kFloat64;
  }
}

// Whether files of layout l (rough or not; a mixture or not) hold element e.
bool in_file(const schema::ElementSpec& e, Layout l, bool rough, bool mixture) {
  return (!e.only_in || *e.only_in == l) && (!e.rough_only || rough) && (!e.mixture_only || mixture);
}

// Per-particle series of the dumps are cut and compressed (DumpStorage); the
// small ones (box edges, observables, steps, times) are kept as they are.
h5::Storage storage_of(const schema::ElementSpec& e, const DumpStorage& s) {
  if (e.rows != schema::RowCount::kFrames || e.row.empty() || !e.row.front().particles) return {};
  return {.chunk_inner = static_cast<hsize_t>(s.particles_per_chunk), .deflate_level = s.deflate_level};
}

void create_element(hid_t file, const schema::ElementSpec& e, hsize_t n, int dimension, hsize_t species,
                    const DumpStorage& storage) {
  std::vector<hsize_t> inner;
  for (const schema::Extent& x : e.row)
    inner.push_back(x.particles ? n : x.dimension ? hsize_t(dimension) : x.species ? species : x.size);
  const hsize_t chunk = e.rows == schema::RowCount::kFrames ? kFrameChunk : kObservableChunk;
  h5::Handle g = h5::create_group(file, std::string(e.path));
  h5::create_series(g.id(), "step", h5::Type::kInt64, {}, chunk);
  h5::create_series(g.id(), "time", h5::Type::kFloat64, {}, chunk);
  h5::create_series(g.id(), "value", h5_type(e.type), inner, chunk, e.fill, storage_of(e, storage));
}

void write_metadata(hid_t file, int dimension) {
  h5::Handle h5md = h5::open_group(file, std::string(kH5md));
  h5::write_attr(h5md.id(), "version", std::vector<std::int32_t>{1, 1});
  h5::Handle author = h5::open_group(file, std::string(kAuthor));
  const char* user = std::getenv("USER");
  h5::write_attr(author.id(), "name", std::string(user ? user : "unknown"));
  h5::Handle creator = h5::open_group(file, std::string(kCreator));
  h5::write_attr(creator.id(), "name", std::string("coolgas-simulate"));
  h5::write_attr(creator.id(), "version", program_version());
  h5::Handle box = h5::open_group(file, std::string(kBox));
  h5::write_attr(box.id(), "dimension", std::int64_t{dimension});
  h5::write_attr(box.id(), "boundary", std::vector<std::string>(std::size_t(dimension), "periodic"));
}

// The largest chunk of the per-particle series, in bytes, uncompressed (a
// deflated chunk is no larger, give or take its header).
hsize_t largest_frame_chunk(hid_t file, Layout layout, bool rough, bool mixture) {
  hsize_t most = 0;
  for (const schema::ElementSpec& e : schema::h5md_profile().elements)
    if (in_file(e, layout, rough, mixture) && e.rows == schema::RowCount::kFrames)
      most = std::max(most, h5::chunk_bytes(h5::open_dataset(file, value_of(e.path)).id()));
  return most;
}

void truncate_element(hid_t file, std::string_view element, hsize_t rows) {
  for (const std::string& d : {step_of(element), time_of(element), value_of(element)}) {
    h5::Handle ds = h5::open_dataset(file, d);
    h5::resize_rows(ds.id(), rows);
  }
}

// Opens the file read-only. A writer of an earlier version killed before it
// started SWMR writing leaves a flag that no reader gets past; opening the
// file for writing and closing it clears that (as `h5clear -s` does).
h5::Handle open_clearing_flags(const std::string& path) {
  try {
    return h5::open_file(path, h5::Mode::kReadOnly);
  } catch (const InputError&) {
    h5::open_file(path, h5::Mode::kReadWrite).close_checked();
    return h5::open_file(path, h5::Mode::kReadOnly);
  }
}

}  // namespace

template <class F>
void H5mdWriter::writing(F&& body) {
  try {
    body();
  } catch (const h5::Error& e) {
    throw WriteError("cannot write '" + path_ + "': " + (e.cause.empty() ? std::string(e.what()) : e.cause));
  }
}

H5mdWriter H5mdWriter::create(const std::string& path, const RunParameters& params, bool overwrite,
                              Geometry g, const DumpStorage& storage) {
  if (storage.particles_per_chunk < 1 || storage.deflate_level < 0 || storage.deflate_level > 9)
    throw std::logic_error("dump storage: particles_per_chunk >= 1 and deflate_level 0-9 required");
  if (!overwrite && std::filesystem::exists(path))
    throw InputError("output '" + path + "' exists; pass --force to overwrite it");
  const CollisionModelSpec* model = find_collision_model(params.model);
  if (!model) throw std::logic_error("writing a run of unknown model '" + params.model + "'");
  ignore_file_size_signal();
  H5mdWriter w;
  w.path_ = path;
  w.file_ = h5::open_file(path, overwrite ? h5::Mode::kCreateTruncate : h5::Mode::kCreateExclusive);
  w.lock_ = WriterLock::take(path);
  w.n_ = params.N;
  w.box_ = params.L;
  w.dimension_ = g.d();
  w.layout_ = model->layout;
  w.rough_ = is_rough(params.collision);
  w.species_ = has_particle_species(params) ? params.species_fraction.size() : 0;
  RunParameters p = params;
  p.schema_version = schema_version_of(p, model->schema_version);
  p.program_version = program_version();
  w.writing([&] { w.create_objects(p, storage); });
  return w;
}

// Every object the file will ever hold, from the profile's tables: SWMR
// writing allows no new object later.
void H5mdWriter::create_objects(const RunParameters& params, const DumpStorage& storage) {
  const hid_t f = file_.id();
  const schema::Profile& profile = schema::h5md_profile();
  for (const schema::GroupSpec& g : profile.groups) h5::create_group(f, std::string(g.path));
  write_metadata(f, dimension_);
  h5::Handle par = h5::open_group(f, std::string(kParameters));
  write_parameters(par.id(), params);
  for (const schema::ElementSpec& e : profile.elements)
    if (in_file(e, layout_, rough_, species_ > 0))
      create_element(f, e, static_cast<hsize_t>(n_), dimension_, species_, storage);
  for (const schema::DatasetSpec& d : profile.datasets)
    h5::create_series(f, std::string(d.path), h5_type(d.type), {}, kObservableChunk);
  flush_file();
}

WriterLock H5mdWriter::claim(const std::string& path) {
  WriterLock lock = WriterLock::take(path);
  // Zeros past the last complete burst, which reopen() drops.
  try {
    h5::cover_recorded_allocation(path);
  } catch (const h5::Error& e) {
    throw WriteError("cannot write '" + path + "': " + e.cause);
  }
  fault_point(FaultPoint::kResumeClaimed);
  return lock;
}

H5mdWriter H5mdWriter::reopen(const std::string& path, const std::string* new_scene, WriterLock lock) {
  ignore_file_size_signal();
  H5mdWriter w;
  w.path_ = path;
  w.lock_ = lock ? std::move(lock) : claim(path);  // before the status flags are cleared
  const bool current = check_resumable(path);
  if (new_scene || !current) w.lock_ = rewrite_through_copy(path, new_scene, !current);
  w.file_ = h5::open_file(path, h5::Mode::kAppend);
  w.appending_ = true;
  const hid_t f = w.file_.id();
  const RunParameters p = read_file_parameters(f, path);
  w.n_ = p.N;
  w.box_ = p.L;
  w.dimension_ = dimension_of(f);
  if (!Geometry::valid(w.dimension_))
    throw InputError("cannot append to '" + path + "': its box/dimension is " + std::to_string(w.dimension_) +
                     "; allowed are 1, 2 and 3");
  w.layout_ = layout_of(f);
  w.rough_ = is_rough(p.collision);
  w.species_ = has_particle_species(p) ? p.species_fraction.size() : 0;
  w.writing([&] {
    // A writer killed while it wrote a frame leaves chunks past the recorded
    // end of allocation; dropping them (below) would fail, or the file's close
    // would. One chunk more than the file's size covers any half-written one.
    h5::extend_allocation_past_file_end(
        w.file_, largest_frame_chunk(f, w.layout_, w.rough_, w.species_ > 0) + (hsize_t{1} << 16));
    w.drop_interrupted_burst();
  });
  fault_point(FaultPoint::kResumeReopened);
  return w;
}

// Read-only: a file that cannot be resumed is refused before a byte of it
// changes. Whether it can be opened for SWMR writing as it is (files of
// earlier versions cannot: h5::appends_in_swmr).
bool H5mdWriter::check_resumable(const std::string& path) {
  h5::Handle f = open_clearing_flags(path);
  if (!h5::exists(f.id(), std::string(kRestartTime)))
    throw InputError("'" + path + "' is not a coolgas trajectory (no /restart)");
  return h5::appends_in_swmr(f);
}

// Whatever a resume must change besides appending rows is changed in a copy
// that replaces the file only when whole, so a kill at any moment leaves the
// old file or the new one: the scene, an attribute, which SWMR writing
// cannot change and which HDF5 rewriting it in place (the attribute, its
// heap, the group's header) can leave torn; and, once, a file of an earlier
// version, which HDF5 cannot open for SWMR writing (`migrate`: its objects
// are copied into a file of the current format). The copy is locked before
// it takes the file's place, so no second writer slips in between.
WriterLock H5mdWriter::rewrite_through_copy(const std::string& path, const std::string* scene, bool migrate) {
  const std::string copy = path + ".partial";
  if (!migrate) copy_file_durably(path, copy);
  try {
    if (migrate) {
      h5::Handle from = h5::open_file(path, h5::Mode::kReadOnly);
      h5::copy_into_new_file(from, copy, [] {
        fault_point(FaultPoint::kConvert);
        throw_if_interrupted("while converting the trajectory; it is unchanged");
      });
    }
    WriterLock lock = WriterLock::take(copy);
    if (scene) {
      h5::Handle f = h5::open_file(copy, h5::Mode::kReadWrite);
      h5::Handle par = h5::open_group(f.id(), std::string(kParameters));
      h5::write_attr(par.id(), "scene", *scene);
      par.close_checked();
      f.close_checked();
    }
    sync_file(copy);
    replace_file(copy, path);
    return lock;
  } catch (const h5::Error& e) {
    std::filesystem::remove(copy);
    throw WriteError("cannot write '" + copy + "': " + (e.cause.empty() ? std::string(e.what()) : e.cause));
  } catch (...) {
    std::filesystem::remove(copy);
    throw;
  }
}

// Drops anything an interrupted burst wrote after the last complete frame.
void H5mdWriter::drop_interrupted_burst() {
  const hid_t f = file_.id();
  const auto times = h5::read_all<double>(h5::open_dataset(f, std::string(kRestartTime)).id());
  if (times.empty()) throw InputError("'" + path_ + "' holds no complete dump to resume from");
  const hsize_t frames = times.size();
  for (const schema::ElementSpec& e : schema::h5md_profile().elements) {
    if (!in_file(e, layout_, rough_, species_ > 0)) continue;
    if (e.rows == schema::RowCount::kFrames) {
      truncate_element(f, e.path, frames);
      continue;
    }
    const auto t = h5::read_all<double>(h5::open_dataset(f, time_of(e.path)).id());
    hsize_t keep = 0;
    while (keep < t.size() && t[keep] <= times.back()) ++keep;
    truncate_element(f, e.path, keep);
  }
  for (const schema::DatasetSpec& d : schema::h5md_profile().datasets)
    h5::resize_rows(h5::open_dataset(f, std::string(d.path)).id(), frames);
  flush_file();
}

// The last moment objects and attributes may change; from here on, rows only grow.
void H5mdWriter::begin_appending() {
  if (appending_) return;
  h5::start_swmr_write(file_);
  appending_ = true;
}

void H5mdWriter::append(std::string_view element, std::int64_t step, double time, h5::Type type, const void* value,
                        int stride) {
  const hid_t f = file_.id();
  h5::Handle s = h5::open_dataset(f, step_of(element));
  h5::Handle t = h5::open_dataset(f, time_of(element));
  h5::Handle v = h5::open_dataset(f, value_of(element));
  h5::append_row(s.id(), h5::Type::kInt64, &step);
  h5::append_row(t.id(), h5::Type::kFloat64, &time);
  h5::append_row(v.id(), type, value, hsize_t(stride));
  s.close_checked();
  t.close_checked();
  v.close_checked();
}

void H5mdWriter::write_pending() {
  for (const auto& r : pending_) {
    const double per_particle = 2.0 * double(r.collisions) / double(n_);
    append(kKineticEnergy, r.collisions, r.time, h5::Type::kFloat64, &r.kinetic_energy);
    append(kCollisions, r.collisions, r.time, h5::Type::kInt64, &r.collisions);
    append(kCollisionsPerParticle, r.collisions, r.time, h5::Type::kFloat64, &per_particle);
    append(kCollisionsBelowDelta, r.collisions, r.time, h5::Type::kInt64, &r.below_delta);
    append(kTotalMomentum, r.collisions, r.time, h5::Type::kFloat64, r.momentum.data());
    if (rough_) append(kRotationalEnergy, r.collisions, r.time, h5::Type::kFloat64, &r.rotational_energy);
    if (species_ > 0) append(kSpeciesKineticEnergy, r.collisions, r.time, h5::Type::kFloat64, r.species_energy.data());
    if (layout_ != Layout::kAggregation) continue;
    append(kAggregates, r.collisions, r.time, h5::Type::kInt64, &r.aggregates);
    append(kMeanMass, r.collisions, r.time, h5::Type::kFloat64, &r.mean_mass);
    append(kLargestMass, r.collisions, r.time, h5::Type::kFloat64, &r.largest_mass);
  }
  pending_.clear();
}

void H5mdWriter::write_frame(const FrameView& fr) {
  double edges[9] = {};  // diag(L, ..., L), d x d
  for (int k = 0; k < dimension_; ++k) edges[k * (dimension_ + 1)] = box_;
  append(kBoxEdges, fr.collisions, fr.time, h5::Type::kFloat64, edges);
  append(kPosition, fr.collisions, fr.time, h5::Type::kFloat64, fr.position, fr.position_stride);
  append(kImage, fr.collisions, fr.time, h5::Type::kInt32, fr.image, 3);  // the first d of each 3
  append(kVelocity, fr.collisions, fr.time, h5::Type::kFloat64, fr.velocity, fr.velocity_stride);
  if (rough_) {
    if (!fr.angular_velocity) throw std::logic_error("a rough run's frame without angular velocities");
    append(kAngularVelocity, fr.collisions, fr.time, h5::Type::kFloat64, fr.angular_velocity);
  }
  if (species_ > 0) {
    if (!fr.species) throw std::logic_error("a mixture's frame without species");
    append(kSpecies, fr.collisions, fr.time, h5::Type::kInt32, fr.species);
  }
  if (layout_ != Layout::kAggregation) return;
  if (!fr.id || !fr.mass || !fr.diameter) throw std::logic_error("aggregation frame without id, mass or diameter");
  append(kId, fr.collisions, fr.time, h5::Type::kInt32, fr.id);
  append(kMass, fr.collisions, fr.time, h5::Type::kFloat64, fr.mass);
  append(kDiameter, fr.collisions, fr.time, h5::Type::kFloat64, fr.diameter);
}

void H5mdWriter::write_restart_row(const FrameView& fr) {
  const hid_t f = file_.id();
  h5::Handle rc = h5::open_dataset(f, std::string(kRestartCollisions));
  h5::Handle rb = h5::open_dataset(f, std::string(kRestartBelowDelta));
  h5::Handle rt = h5::open_dataset(f, std::string(kRestartTime));
  h5::append_row(rc.id(), h5::Type::kInt64, &fr.collisions);
  h5::append_row(rb.id(), h5::Type::kInt64, &fr.below_delta);
  h5::append_row(rt.id(), h5::Type::kFloat64, &fr.time);  // last: marks the frame complete
  rc.close_checked();
  rb.close_checked();
  rt.close_checked();
}

// What a burst adds to the file: the frame, the pending observable rows,
// and room for the chunks and index blocks HDF5 allocates with them. The
// frame is counted uncompressed: deflate may grow incompressible data by
// 0.03 % and a few bytes per chunk, well inside the 1/64 added here.
hsize_t H5mdWriter::burst_bytes(bool with_frame) const {
  const auto n = static_cast<hsize_t>(n_);
  hsize_t frame = n * (3 * 8 + 3 * 4 + 3 * 8) + 9 * 8 + 4 * 16;
  if (layout_ == Layout::kAggregation) frame += n * (4 + 8 + 8) + 3 * 16;
  if (rough_) frame += n * 3 * 8 + 16;
  if (species_ > 0) frame += n * 4 + 16;
  const hsize_t rows = pending_.size() * (8 * 48 + species_ * 8);
  return (with_frame ? frame + frame / 64 : 0) + rows + (hsize_t{1} << 20);
}

void H5mdWriter::add_frame(const FrameView& fr) {
  writing([&] {
    h5::reserve_space(file_, burst_bytes(true));
    begin_appending();
    write_pending();
    write_frame(fr);
    fault_point(FaultPoint::kDumpFrame);
    flush_file();  // the frame is on disk before the row that declares it complete
    fault_point(FaultPoint::kDumpFlushed);
    write_restart_row(fr);
    flush_file();
  });
}

void H5mdWriter::flush() {
  writing([&] {
    h5::reserve_space(file_, burst_bytes(false));
    begin_appending();
    write_pending();
    flush_file();
    h5::release_reserve(file_);
  });
}

void H5mdWriter::rename(const std::string& to) {
  std::filesystem::rename(path_, to);
  path_ = to;
}

void H5mdWriter::flush_file() { h5::flush(file_); }

}  // namespace coolgas
