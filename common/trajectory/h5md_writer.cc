#include "common/trajectory/h5md_writer.h"

#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <stdexcept>

#include "common/error.h"
#include "common/version.h"

namespace coolgas {
namespace {

// Version 1 for the elastic and inelastic models (their files are exactly as
// before version 2 existed); version 2 for what version 2 added.
constexpr std::int64_t kSchemaVersion = 1;
constexpr std::int64_t kSchemaVersionEffects = 2;
constexpr std::int32_t kAbsentId = -1;  // H5MD fill value of particles/all/id: no particle in this slot
constexpr hsize_t kFrameChunk = 1;      // one frame per chunk: frames are large
constexpr hsize_t kObservableChunk = 256;

void create_element(hid_t file, const std::string& path, h5::Type type, const std::vector<hsize_t>& inner,
                    hsize_t chunk) {
  h5::Handle g = h5::create_group(file, path);
  h5::create_series(g.id(), "step", h5::Type::kInt64, {}, chunk);
  h5::create_series(g.id(), "time", h5::Type::kFloat64, {}, chunk);
  h5::create_series(g.id(), "value", type, inner, chunk);
}

// Appends (step, time, value) to the element at path; a row of N x 3 values
// may be spread in memory with `stride` elements per particle.
void append(hid_t file, const std::string& path, std::int64_t step, double time, h5::Type type, const void* value,
            int stride = 0) {
  h5::Handle s = h5::open_dataset(file, path + "/step");
  h5::Handle t = h5::open_dataset(file, path + "/time");
  h5::Handle v = h5::open_dataset(file, path + "/value");
  h5::append_row(s.id(), h5::Type::kInt64, &step);
  h5::append_row(t.id(), h5::Type::kFloat64, &time);
  h5::append_row(v.id(), type, value, hsize_t(stride));
}

void truncate_element(hid_t file, const std::string& path, hsize_t rows) {
  for (const char* d : {"/step", "/time", "/value"}) {
    h5::Handle ds = h5::open_dataset(file, path + d);
    h5::resize_rows(ds.id(), rows);
  }
}

const char* const kParticleElements[] = {"particles/all/box/edges", "particles/all/position", "particles/all/image",
                                         "particles/all/velocity"};
const char* const kObservableElements[] = {"observables/kinetic_energy", "observables/collisions",
                                           "observables/collisions_per_particle",
                                           "observables/collisions_below_delta", "observables/total_momentum"};
const char* const kAggregateParticleElements[] = {"particles/all/id", "particles/all/mass", "particles/all/diameter"};
const char* const kAggregateObservableElements[] = {"observables/aggregates", "observables/mean_mass",
                                                    "observables/largest_mass"};

void create_aggregate_elements(hid_t f, hsize_t n, hsize_t frame_chunk, hsize_t observable_chunk) {
  h5::Handle id = h5::create_group(f, "particles/all/id");
  h5::create_series(id.id(), "step", h5::Type::kInt64, {}, frame_chunk);
  h5::create_series(id.id(), "time", h5::Type::kFloat64, {}, frame_chunk);
  h5::create_series(id.id(), "value", h5::Type::kInt32, {n}, frame_chunk, kAbsentId);
  create_element(f, "particles/all/mass", h5::Type::kFloat64, {n}, frame_chunk);
  create_element(f, "particles/all/diameter", h5::Type::kFloat64, {n}, frame_chunk);
  create_element(f, "observables/aggregates", h5::Type::kInt64, {}, observable_chunk);
  create_element(f, "observables/mean_mass", h5::Type::kFloat64, {}, observable_chunk);
  create_element(f, "observables/largest_mass", h5::Type::kFloat64, {}, observable_chunk);
}

void write_metadata(hid_t file, const RunParameters& p) {
  h5::Handle h5md = h5::create_group(file, "h5md");
  h5::write_attr(h5md.id(), "version", std::vector<std::int32_t>{1, 1});
  h5::Handle author = h5::create_group(file, "h5md/author");
  const char* user = std::getenv("USER");
  h5::write_attr(author.id(), "name", std::string(user ? user : "unknown"));
  h5::Handle creator = h5::create_group(file, "h5md/creator");
  h5::write_attr(creator.id(), "name", std::string("coolgas-simulate"));
  h5::write_attr(creator.id(), "version", program_version());

  h5::Handle box = h5::create_group(file, "particles/all/box");
  h5::write_attr(box.id(), "dimension", std::int64_t{3});
  h5::write_attr(box.id(), "boundary", std::vector<std::string>{"periodic", "periodic", "periodic"});

  h5::Handle par = h5::create_group(file, "parameters");
  const bool effects = p.model == "viscoelastic" || is_aggregation_model(p.model);
  h5::write_attr(par.id(), "schema_version", effects ? kSchemaVersionEffects : kSchemaVersion);
  h5::write_attr(par.id(), "program_version", program_version());
  h5::write_attr(par.id(), "scene", p.scene_toml);
  h5::write_attr(par.id(), "seed", p.seed);
  h5::write_attr(par.id(), "N", p.N);
  h5::write_attr(par.id(), "L", p.L);
  h5::write_attr(par.id(), "phi", p.phi);
  h5::write_attr(par.id(), "T0", p.T0);
  h5::write_attr(par.id(), "model", p.model);
  h5::write_attr(par.id(), "r0", p.r0);
  h5::write_attr(par.id(), "delta", p.delta);
  if (p.model == "viscoelastic") h5::write_attr(par.id(), "viscoelastic_b", p.viscoelastic_b);
}

}  // namespace

H5mdWriter H5mdWriter::create(const std::string& path, const RunParameters& params, bool overwrite) {
  if (!overwrite && std::filesystem::exists(path))
    throw InputError("output '" + path + "' exists; pass --force to overwrite it");
  H5mdWriter w;
  w.file_ = h5::open_file(path, overwrite ? h5::Mode::kCreateTruncate : h5::Mode::kCreateExclusive);
  w.n_ = params.N;
  w.box_ = params.L;
  const hid_t f = w.file_.id();
  write_metadata(f, params);
  const auto n = static_cast<hsize_t>(params.N);
  create_element(f, "particles/all/box/edges", h5::Type::kFloat64, {3, 3}, kFrameChunk);
  create_element(f, "particles/all/position", h5::Type::kFloat64, {n, 3}, kFrameChunk);
  create_element(f, "particles/all/image", h5::Type::kInt32, {n, 3}, kFrameChunk);
  create_element(f, "particles/all/velocity", h5::Type::kFloat64, {n, 3}, kFrameChunk);
  create_element(f, "observables/kinetic_energy", h5::Type::kFloat64, {}, kObservableChunk);
  create_element(f, "observables/collisions", h5::Type::kInt64, {}, kObservableChunk);
  create_element(f, "observables/collisions_per_particle", h5::Type::kFloat64, {}, kObservableChunk);
  create_element(f, "observables/collisions_below_delta", h5::Type::kInt64, {}, kObservableChunk);
  create_element(f, "observables/total_momentum", h5::Type::kFloat64, {3}, kObservableChunk);
  w.aggregation_ = is_aggregation_model(params.model);
  if (w.aggregation_) create_aggregate_elements(f, n, kFrameChunk, kObservableChunk);
  h5::Handle restart = h5::create_group(f, "restart");
  h5::create_series(restart.id(), "time", h5::Type::kFloat64, {}, kObservableChunk);
  h5::create_series(restart.id(), "collisions", h5::Type::kInt64, {}, kObservableChunk);
  h5::create_series(restart.id(), "collisions_below_delta", h5::Type::kInt64, {}, kObservableChunk);
  h5::flush(w.file_);
  return w;
}

H5mdWriter H5mdWriter::reopen(const std::string& path) {
  H5mdWriter w;
  w.file_ = h5::open_file(path, h5::Mode::kReadWrite);
  const hid_t f = w.file_.id();
  if (!h5::exists(f, "restart/time")) throw InputError("'" + path + "' is not a coolgas trajectory (no /restart)");
  h5::Handle par = h5::open_group(f, "parameters");
  w.n_ = h5::read_attr_int(par.id(), "N");
  w.box_ = h5::read_attr_double(par.id(), "L");
  h5::Handle rt = h5::open_dataset(f, "restart/time");
  const auto times = h5::read_all<double>(rt.id());
  if (times.empty()) throw InputError("'" + path + "' holds no complete dump to resume from");
  const hsize_t frames = times.size();
  const double last = times.back();
  w.aggregation_ = h5::exists(f, "particles/all/id");
  std::vector<const char*> particle_elements(std::begin(kParticleElements), std::end(kParticleElements));
  std::vector<const char*> observable_elements(std::begin(kObservableElements), std::end(kObservableElements));
  if (w.aggregation_) {
    particle_elements.insert(particle_elements.end(), std::begin(kAggregateParticleElements),
                             std::end(kAggregateParticleElements));
    observable_elements.insert(observable_elements.end(), std::begin(kAggregateObservableElements),
                               std::end(kAggregateObservableElements));
  }
  // Drop anything an interrupted burst wrote after the last complete frame.
  for (const char* e : particle_elements) truncate_element(f, e, frames);
  for (const char* e : observable_elements) {
    h5::Handle t = h5::open_dataset(f, std::string(e) + "/time");
    const auto ot = h5::read_all<double>(t.id());
    hsize_t keep = 0;
    while (keep < ot.size() && ot[keep] <= last) ++keep;
    truncate_element(f, e, keep);
  }
  h5::flush(w.file_);
  return w;
}

void H5mdWriter::write_pending() {
  const hid_t f = file_.id();
  for (const auto& r : pending_) {
    const double per_particle = 2.0 * double(r.collisions) / double(n_);
    append(f, "observables/kinetic_energy", r.collisions, r.time, h5::Type::kFloat64, &r.kinetic_energy);
    append(f, "observables/collisions", r.collisions, r.time, h5::Type::kInt64, &r.collisions);
    append(f, "observables/collisions_per_particle", r.collisions, r.time, h5::Type::kFloat64, &per_particle);
    append(f, "observables/collisions_below_delta", r.collisions, r.time, h5::Type::kInt64, &r.below_delta);
    append(f, "observables/total_momentum", r.collisions, r.time, h5::Type::kFloat64, r.momentum.data());
    if (!aggregation_) continue;
    append(f, "observables/aggregates", r.collisions, r.time, h5::Type::kInt64, &r.aggregates);
    append(f, "observables/mean_mass", r.collisions, r.time, h5::Type::kFloat64, &r.mean_mass);
    append(f, "observables/largest_mass", r.collisions, r.time, h5::Type::kFloat64, &r.largest_mass);
  }
  pending_.clear();
}

void H5mdWriter::add_frame(const FrameView& fr) {
  write_pending();
  const hid_t f = file_.id();
  const double edges[9] = {box_, 0, 0, 0, box_, 0, 0, 0, box_};
  append(f, "particles/all/box/edges", fr.collisions, fr.time, h5::Type::kFloat64, edges);
  append(f, "particles/all/position", fr.collisions, fr.time, h5::Type::kFloat64, fr.position, fr.position_stride);
  append(f, "particles/all/image", fr.collisions, fr.time, h5::Type::kInt32, fr.image);
  append(f, "particles/all/velocity", fr.collisions, fr.time, h5::Type::kFloat64, fr.velocity, fr.velocity_stride);
  if (aggregation_) {
    if (!fr.id || !fr.mass || !fr.diameter) throw std::logic_error("aggregation frame without id, mass or diameter");
    append(f, "particles/all/id", fr.collisions, fr.time, h5::Type::kInt32, fr.id);
    append(f, "particles/all/mass", fr.collisions, fr.time, h5::Type::kFloat64, fr.mass);
    append(f, "particles/all/diameter", fr.collisions, fr.time, h5::Type::kFloat64, fr.diameter);
  }
  h5::Handle rt = h5::open_dataset(f, "restart/time");
  h5::Handle rc = h5::open_dataset(f, "restart/collisions");
  h5::Handle rb = h5::open_dataset(f, "restart/collisions_below_delta");
  h5::append_row(rc.id(), h5::Type::kInt64, &fr.collisions);
  h5::append_row(rb.id(), h5::Type::kInt64, &fr.below_delta);
  h5::append_row(rt.id(), h5::Type::kFloat64, &fr.time);  // last: marks the frame complete
  h5::flush(file_);
}

bool is_aggregation_model(const std::string& model) { return model == "aggregation"; }

void H5mdWriter::flush() {
  write_pending();
  h5::flush(file_);
}

void H5mdWriter::update_scene(const std::string& scene_toml) {
  h5::Handle par = h5::open_group(file_.id(), "parameters");
  h5::write_attr(par.id(), "scene", scene_toml);
  h5::flush(file_);
}

}  // namespace coolgas
