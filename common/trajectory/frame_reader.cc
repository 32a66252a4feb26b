#include "common/trajectory/frame_reader.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/dimension_line.h"
#include "common/error.h"
#include "common/memory.h"
#include "common/tool_main.h"
#include "common/tsv.h"
#include "common/trajectory/compact_slots.h"
#include "common/trajectory/layout.h"
#include "common/trajectory/run_parameters.h"
#include "common/trajectory/widen_rows.h"

namespace coolgas {

namespace {

struct ElementSpec {
  std::string_view path;  // the H5MD element (group holding step, time, value)
  hsize_t per_particle;   // numbers per particle: value is (F, N, 3) or (F, N)
  Field field;
  bool per_axis = true;   // a vector of the box's d components (else of 3 in every dimension: spins)
};

// The per-particle elements a Trajectory can read.
constexpr ElementSpec kElements[] = {
    {layout::kPosition, 3, Field::kPosition},
    {layout::kVelocity, 3, Field::kVelocity},
    {layout::kImage, 3, Field::kImage},
    {layout::kId, 1, Field::kId},
    {layout::kMass, 1, Field::kMass},
    {layout::kDiameter, 1, Field::kDiameter},
    {layout::kAngularVelocity, 3, Field::kAngularVelocity, false},
    {layout::kSpecies, 1, Field::kSpecies},
};

std::string value_of(const ElementSpec& e) { return layout::value_of(e.path); }

// Rejects NaN and infinities, naming the first offending particle.
void check_finite(const std::vector<double>& v, const std::string& where, std::size_t per_particle = 3) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i]))
      throw InputError(where + " has a non-finite value (" + format_number(v[i]) + ") for particle " +
                       std::to_string(i / per_particle));
  }
}

}  // namespace

Trajectory::Trajectory(const std::string& path, unsigned fields) : path_(path), fields_(fields) {
  if (fields == 0) throw std::logic_error("Trajectory opened for no element");
  file_ = h5::open_file(path, h5::Mode::kReadOnly);
  aggregates_ = layout::layout_of(file_.id()) == layout::Layout::kAggregation;
  dimension_ = layout::dimension_of(file_.id());
  if (dimension_ != 3 && (!(fields & Field::kAnyDimension) || dimension_ < 1 || dimension_ > 2))
    throw InputError(path + ": a " + std::to_string(dimension_) +
                     "D trajectory (box/dimension = " + std::to_string(dimension_) +
                     "); this tool reads 3D trajectories only for now");
  const bool mixture = !aggregates_ && h5::exists(file_.id(), std::string(layout::kSpecies));
  if (mixture) {
    const RunParameters run = read_file_parameters(file_.id(), path);
    species_count_ = run.species_fraction.size();
    if (fields_ & (Field::kMass | Field::kDiameter)) {
      species_mass_ = run.species_mass;
      species_diameter_ = run.species_diameter;
      fields_ |= Field::kSpecies;
    }
  }
  if (!mixture) fields_ &= ~unsigned(Field::kSpecies);  // equal particles' files have no species
  if (aggregates_) fields_ |= Field::kId | Field::kMass;
  // A gas file's masses and diameters: none stored (unit spheres), or a mixture's from its species.
  const unsigned from_species = fields_ & (Field::kMass | Field::kDiameter);
  if (!aggregates_) fields_ &= ~unsigned(Field::kDiameter | Field::kMass);
  if (!h5::exists(file_.id(), std::string(layout::kAngularVelocity)))
    fields_ &= ~unsigned(Field::kAngularVelocity);  // smooth particles' files have no spins
  std::size_t frames = SIZE_MAX;
  for (const auto& e : kElements) {
    if (!(fields_ & e.field)) continue;
    check_element(std::string(e.path), e.per_particle == 3,
                  e.per_particle == 3 ? (e.per_axis ? hsize_t(dimension_) : 3) : 1);
    h5::Handle value = h5::open_dataset(file_.id(), value_of(e));
    h5::Handle time = h5::open_dataset(file_.id(), layout::time_of(e.path));
    frames = std::min<std::size_t>({frames, h5::shape(value.id())[0], h5::shape(time.id())[0]});
    if (times_.empty()) {
      times_ = h5::read_all<double>(time.id());
      h5::Handle step = h5::open_dataset(file_.id(), layout::step_of(e.path));
      steps_ = h5::read_all<std::int64_t>(step.id());
      frames = std::min(frames, steps_.size());
    }
  }
  // A frame is complete once its /restart row exists (the writer adds it last);
  // rows beyond it belong to a burst still being written or cut short by a crash.
  if (h5::exists(file_.id(), std::string(layout::kRestartTime)))
    frames = std::min<std::size_t>(frames, layout::complete_dumps(file_.id()));
  if (frames == 0) throw InputError(path_ + ": the trajectory holds no dumps");
  if (!aggregates_ && mixture) filled_ = from_species;  // filled in read(), not read as elements
  times_.resize(frames);
  steps_.resize(frames);
  // Every tool writes the dump's time in its rows: a NaN there is a row of nan
  // with exit 0 (coolgas-validate reports such a file).
  for (std::size_t k = 0; k < frames; ++k)
    if (!std::isfinite(times_[k]))
      throw InputError(path_ + ": dump " + std::to_string(k) + " has time " + format_number(times_[k]) +
                       "; dump times must be finite (coolgas-validate lists the file's problems)");
}

void Trajectory::missing(const std::string& what) const {
  throw InputError(path_ + ": not a coolgas trajectory: missing " + what);
}

// Checks that an element has value/time/step and that value is (F, N, d) for
// a vector (d = 1 too: a rod's position is a 1-vector), or (F, N) for one
// number per particle, with the same N as the elements checked before.
void Trajectory::check_element(const std::string& element, bool vector, hsize_t per_particle) {
  for (const std::string& d : {layout::value_of(element), layout::time_of(element), layout::step_of(element)})
    if (!h5::exists(file_.id(), d)) missing(d);
  h5::Handle value = h5::open_dataset(file_.id(), layout::value_of(element));
  const auto dims = h5::shape(value.id());
  const bool fits = !vector ? dims.size() == 2 : (dims.size() == 3 && dims[2] == per_particle);
  if (!fits)
    throw InputError(path_ + ": " + element + "/value has the wrong shape (expected frames x particles" +
                     (!vector ? ")" : " x " + std::to_string(per_particle) + ")"));
  const auto n = static_cast<std::int64_t>(dims[1]);
  if (n < 1) throw InputError(path_ + ": " + element + "/value holds no particles");
  // Checked before a frame's buffers are sized by it (a damaged file may declare any shape).
  const double bytes = double(n) * double(per_particle) * 8, memory = usable_memory_bytes();
  if (n > kMaxStoredParticles || bytes > memory)
    throw InputError(path_ + ": " + element + "/value holds rows of " + std::to_string(n) + " particles (" +
                     bytes_text(bytes) + " per dump); a trajectory holds at most " +
                     std::to_string(kMaxStoredParticles) + " (32-bit ids), and the memory available is " + bytes_text(memory));
  if (n_ != 0 && n != n_)
    throw InputError(path_ + ": " + element + "/value has " + std::to_string(n) + " particles, other elements " +
                     std::to_string(n_));
  n_ = n;
}

std::size_t Trajectory::nearest_dump(double t) const {
  std::size_t best = 0;
  for (std::size_t i = 1; i < times_.size(); ++i)
    if (std::abs(times_[i] - t) < std::abs(times_[best] - t)) best = i;
  return best;
}

std::size_t Trajectory::dump_at(double t, bool exact) const {
  const std::size_t d = nearest_dump(t);
  if (times_.empty() || std::abs(times_[d] - t) <= 1e-9 * std::max(std::abs(t), 1.0)) return d;
  const std::string what = "--time " + format_number(t) + ": no dump at that time, the nearest is t = " +
                           format_number(times_[d]) + " (" + std::to_string(times_.size()) + " dumps, t = " +
                           format_number(times_.front()) + " to " + format_number(times_.back()) + ")";
  if (exact) throw InputError(path_ + ": " + what);
  note(what + "; using it (--exact-time refuses instead)");
  return d;
}

std::vector<std::size_t> Trajectory::dumps_nearest(const std::vector<double>& times, bool exact) const {
  std::vector<std::size_t> dumps;
  if (times.empty()) {
    for (std::size_t i = 0; i < times_.size(); ++i) dumps.push_back(i);
  } else {
    for (double t : times) dumps.push_back(dump_at(t, exact));
  }
  return dumps;
}

double Trajectory::box_side(std::size_t dump) const {
  const std::string edges_value = layout::value_of(layout::kBoxEdges);
  if (h5::exists(file_.id(), edges_value)) {
    h5::Handle edges = h5::open_dataset(file_.id(), edges_value);
    const auto dims = h5::shape(edges.id());
    const auto d = hsize_t(dimension_);
    if (dims.size() == 3 && dims[1] == d && dims[2] == d && dump < dims[0]) {
      const auto m = h5::read_row<double>(edges.id(), dump);
      const double last = m[d * d - 1];  // the diagonal: 0, 4, 8 (2D: 0, 3; 1D: the one edge)
      std::string edges;
      bool equal = true;
      for (hsize_t k = 0; k < d; ++k) {
        edges += (k ? ", " : "") + format_number(m[k * (d + 1)]);
        equal = equal && m[k * (d + 1)] == m[0];
      }
      if (!equal || m[0] != last)
        throw InputError(path_ + ": dump " + std::to_string(dump) + ": the box is not " +
                         Geometry(dimension_).box_adjective() + " (edges " + edges + ")");
      return m[0];
    }
  }
  const std::string parameters(layout::kParameters);
  if (h5::exists(file_.id(), parameters)) {
    h5::Handle par = h5::open_group(file_.id(), parameters);
    if (h5::has_attr(par.id(), "L")) return h5::read_attr_double(par.id(), "L");
  }
  missing(std::string(layout::kBoxEdges));
}

void Trajectory::read(std::size_t dump, Frame& frame) const {
  if (dump >= times_.size())
    throw InputError(path_ + ": no dump " + std::to_string(dump) + " (the file holds " + std::to_string(times_.size()) +
                     ")");
  frame.dump = dump;
  frame.time = times_[dump];
  frame.step = steps_[dump];
  frame.L = box_side(dump);
  const auto size = static_cast<std::size_t>(dimension_ * n_), n = static_cast<std::size_t>(n_);
  const auto d = static_cast<std::size_t>(dimension_);
  const std::string where = path_ + ": dump " + std::to_string(dump) + " (t = " + format_number(frame.time) + "): ";
  for (const auto& e : kElements) {
    if (!(fields_ & e.field)) continue;
    h5::Handle value = h5::open_dataset(file_.id(), value_of(e));
    switch (e.field) {
      case Field::kPosition:
        frame.position.resize(size);
        h5::read_rows(value.id(), h5::Type::kFloat64, dump, 1, frame.position.data());
        widen_to_three(frame.position, n, d);
        check_finite(frame.position, where + std::string(e.path));
        break;
      case Field::kVelocity:
        frame.velocity.resize(size);
        h5::read_rows(value.id(), h5::Type::kFloat64, dump, 1, frame.velocity.data());
        widen_to_three(frame.velocity, n, d);
        check_finite(frame.velocity, where + std::string(e.path));
        break;
      case Field::kImage:
        frame.image.resize(size);
        h5::read_rows(value.id(), h5::Type::kInt32, dump, 1, frame.image.data());
        widen_to_three(frame.image, n, d);
        break;
      case Field::kId:
        frame.id.resize(std::size_t(n_));
        h5::read_rows(value.id(), h5::Type::kInt32, dump, 1, frame.id.data());
        break;
      case Field::kMass:
        frame.mass.resize(std::size_t(n_));
        h5::read_rows(value.id(), h5::Type::kFloat64, dump, 1, frame.mass.data());
        check_finite(frame.mass, where + std::string(e.path), 1);
        break;
      case Field::kDiameter:
        frame.diameter.resize(std::size_t(n_));
        h5::read_rows(value.id(), h5::Type::kFloat64, dump, 1, frame.diameter.data());
        check_finite(frame.diameter, where + std::string(e.path), 1);
        break;
      case Field::kAngularVelocity:
        frame.angular_velocity.resize(3 * n);
        h5::read_rows(value.id(), h5::Type::kFloat64, dump, 1, frame.angular_velocity.data());
        check_finite(frame.angular_velocity, where + std::string(e.path));
        break;
      case Field::kSpecies:
        frame.species.resize(n);
        h5::read_rows(value.id(), h5::Type::kInt32, dump, 1, frame.species.data());
        break;
      case Field::kAnyDimension:  // not an element (it is never in kElements)
        break;
    }
  }
  if (aggregates_) keep_present(frame);
  if (filled_) fill_from_species(frame, where);
}

// A mixture's masses and diameters, by each particle's species.
void Trajectory::fill_from_species(Frame& frame, const std::string& where) const {
  const std::size_t n = frame.species.size();
  if (filled_ & Field::kMass) frame.mass.resize(n);
  if (filled_ & Field::kDiameter) frame.diameter.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t k = frame.species[i];
    if (k < 0 || std::size_t(k) >= species_mass_.size() || species_diameter_.size() != species_mass_.size())
      throw InputError(where + std::string(layout::kSpecies) + " gives particle " + std::to_string(i) + " species " +
                       std::to_string(k) + "; the table of /parameters has " + std::to_string(species_mass_.size()));
    if (filled_ & Field::kMass) frame.mass[i] = species_mass_[std::size_t(k)];
    if (filled_ & Field::kDiameter) frame.diameter[i] = species_diameter_[std::size_t(k)];
  }
}

// Keeps the slots whose id is not the fill value -1: one entry per aggregate.
void Trajectory::keep_present(Frame& frame) const {
  std::vector<bool> keep(frame.id.size());
  for (std::size_t i = 0; i < keep.size(); ++i) keep[i] = frame.id[i] >= 0;
  compact_slots(frame.position, keep, 3);
  compact_slots(frame.velocity, keep, 3);
  compact_slots(frame.image, keep, 3);
  compact_slots(frame.mass, keep, 1);
  compact_slots(frame.diameter, keep, 1);
  compact_slots(frame.id, keep, 1);
  if (frame.id.empty())
    throw InputError(path_ + ": dump " + std::to_string(frame.dump) + " holds no aggregate (every id is -1)");
}

// Tolerant of files without /parameters (the frames are all a tool needs);
// a file that has them must have them right.
Provenance Trajectory::provenance() const {
  Provenance p{{"input", path_}};
  const std::string parameters(layout::kParameters);
  if (!h5::exists(file_.id(), parameters)) {
    add_dimension_line(p, dimension_);
    return p;
  }
  const RunParameters run = read_file_parameters(file_.id(), path_);
  p.emplace_back("seed", std::to_string(run.seed));
  for (auto& entry : physics_provenance(run)) p.push_back(std::move(entry));
  add_dimension_line(p, dimension_);
  // Which build made the run, as coolgas-energy says it: a table made from
  // dumps is traceable to its simulator too.
  p.emplace_back("simulator_version", run.program_version);
  return p;
}

}  // namespace coolgas
