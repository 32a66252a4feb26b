#include "common/trajectory/resume_frame.h"

#include "common/error.h"
#include "common/hdf5_file.h"
#include "common/memory.h"
#include "common/trajectory/layout.h"
#include "common/trajectory/widen_rows.h"

namespace coolgas {
namespace {

using namespace layout;

struct Reader {
  hid_t file;
  std::string path;

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError("cannot resume from '" + path + "': " + what);
  }

  // Row `row` of an element's value, whose rows must have the shape `inner`
  // ({N, 3} or {N}): checked before anything is read, so a file that
  // declares a huge shape allocates nothing.
  template <class T>
  std::vector<T> row(std::string_view element, hsize_t row, const std::vector<hsize_t>& inner) const {
    const std::string value = value_of(element);
    if (!h5::exists(file, value)) fail("missing " + value);
    h5::Handle ds = h5::open_dataset(file, value);
    const auto dims = h5::shape(ds.id());
    if (dims.empty() || dims[0] <= row) fail(value + " has no row for the last complete dump");
    if (std::vector<hsize_t>(dims.begin() + 1, dims.end()) != inner)
      fail(value + " has shape " + shape_text(dims) + ", but /parameters/N = " + std::to_string(inner[0]) +
           " asks for rows of shape " + shape_text(inner));
    return h5::read_row<T>(ds.id(), row);
  }

  static std::string shape_text(const std::vector<hsize_t>& dims) {
    std::string s = "(";
    for (std::size_t k = 0; k < dims.size(); ++k) s += (k ? ", " : "") + std::to_string(dims[k]);
    return s + ")";
  }

  // The last dump's arrays, N times `bytes_per_particle`, must fit in memory.
  void check_memory(std::int64_t N, double bytes_per_particle) const {
    const double need = double(N) * bytes_per_particle, have = usable_memory_bytes();
    if (need > have)
      fail("/parameters/N = " + std::to_string(N) + " particles need " + bytes_text(need) +
           " for the last dump alone; the memory available is " + bytes_text(have));
  }

  std::int64_t counter(std::string_view dataset, hsize_t row) const {
    const std::string d(dataset);
    if (!h5::exists(file, d)) fail("missing " + d);
    h5::Handle ds = h5::open_dataset(file, d);
    if (h5::shape(ds.id()).at(0) <= row) fail(d + " has no row for the last complete dump");
    return h5::read_row<std::int64_t>(ds.id(), row).at(0);
  }

  // Slots hold either aggregate i (id i, mass and diameter at least 1) or nothing (id -1).
  void check_aggregates(const ResumeFrame& r) const {
    for (std::size_t i = 0; i < r.particles; ++i) {
      const bool present = r.id[i] >= 0;
      if ((present && (r.id[i] != std::int32_t(i) || !(r.mass[i] >= 1) || !(r.diameter[i] >= 1))) ||
          (!present && r.id[i] != kAbsentId))
        fail("slot " + std::to_string(i) + " of the last dump holds id " + std::to_string(r.id[i]) +
             " with mass and diameter below 1 or in the wrong slot (ids are slot numbers, -1 when absent)");
    }
  }
};

}  // namespace

ResumeFrame read_resume_frame(const std::string& path) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  const Reader in{f.id(), path};
  if (!h5::exists(f.id(), std::string(kParameters))) in.fail("missing " + std::string(kParameters));
  ResumeFrame r;
  r.params = read_file_parameters(f.id(), path);
  r.aggregates = layout_of(f.id()) == Layout::kAggregation;
  const bool rough = is_rough(r.params.collision);
  in.check_memory(r.params.N, 3 * 8 + 3 * 8 + 3 * 4 + (r.aggregates ? 4 + 8 + 8 : 0) + (rough ? 3 * 8 : 0) +
                                 (has_particle_species(r.params) ? 4 : 0));
  const auto last_time = last_dump_time(f.id());
  if (!last_time) in.fail("it holds no complete dump");
  const hsize_t last = complete_dumps(f.id()) - 1;  // rows after it belong to an interrupted burst
  r.time = *last_time;
  r.collisions = in.counter(kRestartCollisions, last);
  r.below_delta = in.counter(kRestartBelowDelta, last);
  r.particles = static_cast<std::size_t>(r.params.N);
  r.dimension = dimension_of(f.id());
  if (r.dimension < 1 || r.dimension > 3)
    in.fail("box/dimension = " + std::to_string(r.dimension) + "; a run is in dimension 1, 2 or 3");
  const auto n = static_cast<hsize_t>(r.particles), d = static_cast<hsize_t>(r.dimension);
  r.position = in.row<double>(kPosition, last, {n, d});
  r.velocity = in.row<double>(kVelocity, last, {n, d});
  r.image = in.row<std::int32_t>(kImage, last, {n, d});
  widen_to_three(r.position, r.particles, d);
  widen_to_three(r.velocity, r.particles, d);
  widen_to_three(r.image, r.particles, d);
  if (rough) r.angular_velocity = in.row<double>(kAngularVelocity, last, {n, 3});
  if (has_particle_species(r.params)) r.species = in.row<std::int32_t>(kSpecies, last, {n});
  if (r.aggregates) {
    r.id = in.row<std::int32_t>(kId, last, {n});
    r.mass = in.row<double>(kMass, last, {n});
    r.diameter = in.row<double>(kDiameter, last, {n});
    in.check_aggregates(r);
  }
  return r;
}

}  // namespace coolgas
