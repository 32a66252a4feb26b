#include "common/trajectory/h5md_frame.h"

#include <cmath>

#include "common/error.h"
#include "common/geometry.h"
#include "common/hdf5_file.h"
#include "common/limits.h"
#include "common/memory.h"
#include "common/trajectory/compact_slots.h"
#include "common/trajectory/layout.h"
#include "common/trajectory/widen_rows.h"
#include "common/tsv.h"

namespace coolgas {
namespace {

struct Reader {
  hid_t file;
  std::string path;

  [[noreturn]] void fail(const std::string& what) const { throw InputError(path + ": " + what); }

  // "all" if present, else the one group of /particles.
  std::string particle_group() const {
    const std::string particles(layout::kParticles);
    if (!h5::exists(file, particles) || !h5::is_group(file, particles))
      fail("not an H5MD file with particles: no " + particles + " group");
    const std::string all(layout::kAll);
    if (h5::exists(file, all)) return all.substr(particles.size() + 1);
    h5::Handle g = h5::open_group(file, particles);
    H5G_info_t info{};
    if (H5Gget_info(g.id(), &info) < 0 || info.nlinks == 0) fail(particles + " holds no particle group");
    std::vector<std::string> names;
    for (hsize_t i = 0; i < info.nlinks; ++i) {
      char name[256] = {};
      H5Lget_name_by_idx(g.id(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT);
      names.emplace_back(name);
    }
    if (names.size() > 1) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      fail(particles + " holds several particle groups (" + list + "); coolgas reads 'all' or a single group");
    }
    return names[0];
  }

  // The value dataset of an element and whether it varies in time.
  std::pair<std::string, bool> value_path(const std::string& element) const {
    if (!h5::exists(file, element)) fail("missing " + element);
    const bool varies = h5::is_group(file, element);
    return {varies ? layout::value_of(element) : element, varies};
  }

  // Times of a time-varying element: a (F,) dataset, or a scalar step with
  // an optional `offset` attribute (H5MD 1.1, fixed sampling).
  std::vector<double> times(const std::string& element, std::size_t frames) const {
    const std::string t = layout::time_of(element);
    if (!h5::exists(file, t)) return {};
    h5::Handle ds = h5::open_dataset(file, t);
    std::vector<double> v = h5::read_all<double>(ds.id());
    if (h5::shape(ds.id()).empty()) {
      const double offset = h5::has_attr(ds.id(), "offset") ? h5::read_attr_double(ds.id(), "offset") : 0.0;
      const double step = v.at(0);
      v.resize(frames);
      for (std::size_t i = 0; i < frames; ++i) v[i] = offset + double(i) * step;
    }
    // H5MD gives step, time and value one row per frame: any other count is
    // a damaged or half-written file, whose times would name the wrong frames.
    if (v.size() != frames)
      fail(t + " holds " + std::to_string(v.size()) + " times for " + std::to_string(frames) + " frames");
    return v;
  }

  // Row `index` of a per-particle element (k numbers per particle), or the
  // whole dataset when it does not vary in time; N is taken from the first read.
  std::vector<double> per_particle(const std::string& element, std::size_t index, std::size_t frames,
                                   std::size_t k, std::size_t* n) const {
    const auto [value, varies] = value_path(element);
    h5::Handle ds = h5::open_dataset(file, value);
    auto dims = h5::shape(ds.id());
    if (varies) {
      if (dims.empty() || dims[0] != frames)
        fail(value + " has " + (dims.empty() ? std::string("no") : std::to_string(dims[0])) + " frames, position has " +
             std::to_string(frames));
      dims.erase(dims.begin());
    }
    const bool fits = k == 1 ? dims.size() == 1 || (dims.size() == 2 && dims[1] == 1)
                             : dims.size() == 2 && dims[1] == k;
    if (!fits) fail(value + " has the wrong shape (expected " + (varies ? "frames x " : "") + "particles" +
                    (k == 1 ? "" : " x " + std::to_string(k)) + ")");
    if (*n == 0) *n = dims[0];
    if (dims[0] != *n) fail(value + " holds " + std::to_string(dims[0]) + " particles, position " + std::to_string(*n));
    h5::check_read_fits(ds.id(), double(*n) * double(k), sizeof(double), varies ? " one frame" : "");
    std::vector<double> v(*n * k);
    if (*n > 0) h5::read_rows(ds.id(), h5::Type::kFloat64, varies ? index : 0, varies ? 1 : dims[0], v.data());
    return v;
  }

  // The box's dimension: its `dimension` attribute (H5MD requires one), else 3.
  int box_dimension(const std::string& group) const {
    const std::string box = layout::in_group(layout::kBox, group);
    if (!h5::exists(file, box)) fail("missing " + box);
    h5::Handle g = h5::open_group(file, box);
    if (!h5::has_attr(g.id(), "dimension")) return 3;
    const int d = h5::read_attr_int(g.id(), "dimension");
    if (d < 1 || d > 3) fail(box + " has dimension " + std::to_string(d) + "; coolgas reads 1 (rods), 2 (disks) or 3");
    return d;
  }

  // The side of a periodic box of equal edges in `d` dimensions: edges a
  // vector (d) or a matrix (d x d), fixed or one row per frame.
  double box_side(const std::string& group, std::size_t index, std::size_t frames, int d) const {
    const std::string box = layout::in_group(layout::kBox, group);
    h5::Handle g = h5::open_group(file, box);
    if (h5::has_attr(g.id(), "boundary"))
      for (const std::string& b : h5::read_attr_strings(g.id(), "boundary"))
        if (b != "periodic") fail(box + " has boundary '" + shown(b) + "'; coolgas boxes are periodic");
    const auto [value, varies] = value_path(layout::in_group(layout::kBoxEdges, group));
    h5::Handle ds = h5::open_dataset(file, value);
    auto dims = h5::shape(ds.id());
    std::size_t row = 0;
    if (varies) {
      if (dims.empty() || (dims[0] != frames && dims[0] != 1))
        fail(value + " has " + (dims.empty() ? std::string("no") : std::to_string(dims[0])) + " rows, position has " +
             std::to_string(frames) + " frames");
      row = dims[0] == 1 ? 0 : index;
      dims.erase(dims.begin());
    }
    const hsize_t k = hsize_t(d);
    const bool vector = dims == std::vector<hsize_t>{k}, matrix = dims == std::vector<hsize_t>{k, k};
    if (!vector && !matrix)
      fail(value + " has the wrong shape (expected " + std::to_string(d) + " or " + std::to_string(d) + " x " +
           std::to_string(d) + " for a box of dimension " + std::to_string(d) + ")");
    std::vector<double> e(matrix ? k * k : k);
    h5::read_rows(ds.id(), h5::Type::kFloat64, varies ? row : 0, varies ? 1 : dims[0], e.data());
    std::vector<double> side(k);
    for (hsize_t i = 0; i < k; ++i) side[i] = matrix ? e[i * k + i] : e[i];
    if (matrix)
      for (hsize_t i = 0; i < k * k; ++i)
        if (i % (k + 1) != 0 && e[i] != 0)
          fail(value + " is not an orthogonal box (off-diagonal " + format_number(e[i]) + ")");
    for (double s : side)
      if (s != side[0]) {
        std::string list;
        for (double x : side) list += (list.empty() ? "" : ", ") + format_number(x);
        fail("the box is not " + std::string(Geometry(d).box_adjective()) + " (edges " + list +
             "); coolgas boxes are " + Geometry(d).boxes());
      }
    return side[0];
  }

  // The particles a frame of the position dataset `value` (of `frames` rows
  // when it varies) claims, refused beyond 32-bit ids or when the frame's
  // arrays and `extra` bytes a particle need more than the memory available.
  // Counted in doubles: a hostile shape's product may overflow.
  void check_claimed_particles(const std::string& group, const std::string& value, bool varies, int d,
                               double extra) const {
    h5::Handle ds = h5::open_dataset(file, value);
    const auto dims = h5::shape(ds.id());
    if (dims.size() != (varies ? 3u : 2u)) return;  // misshapen: per_particle names it
    const double n = double(dims[varies ? 1 : 0]);
    std::string shape;
    for (const hsize_t x : dims) shape += (shape.empty() ? "" : ", ") + std::to_string(x);
    const std::string claims = value + " of shape (" + shape + ") holds " + format_number(n) + " particles";
    if (n > double(kMaxIndex32)) fail(claims + "; coolgas reads at most 2^31 - 1 (32-bit particle ids)");
    // Each vector element read in rows of d, then widened to 3; the scalars one number each.
    double per_particle = 8.0 * (3 + d);
    if (h5::exists(file, layout::in_group(layout::kVelocity, group))) per_particle += 8.0 * (3 + d);
    for (const std::string_view scalar : {layout::kMass, layout::kDiameter, layout::kId})
      if (h5::exists(file, layout::in_group(scalar, group))) per_particle += 8;
    const double need = n * (per_particle + extra), memory = usable_memory_bytes();
    if (need > memory)
      fail(claims + ": " + bytes_text(need) + " to read" + (extra > 0 ? " and use" : "") + " (" +
           format_number(per_particle + extra) + " B a particle); the memory available is " + bytes_text(memory));
  }

  std::string unit_of(const std::string& element) const {
    const auto [value, varies] = value_path(element);
    h5::Handle ds = h5::open_dataset(file, value);
    return h5::has_attr(ds.id(), "unit") ? h5::read_attr_string(ds.id(), "unit") : "";
  }
};

std::size_t nearest(const std::vector<double>& times, double t) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < times.size(); ++i)
    if (std::abs(times[i] - t) < std::abs(times[best] - t)) best = i;
  return best;
}

// The frame nearest `time`, or frame `index`, or the last.
H5mdFrame read_frame(const std::string& path, std::optional<double> time, std::optional<std::size_t> index,
                     double extra_bytes_per_particle) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  const Reader in{f.id(), path};
  if (!h5::exists(f.id(), std::string(layout::kH5md))) in.fail("not an H5MD file: no /h5md group");
  H5mdFrame fr;
  fr.group = in.particle_group();
  const std::string position = layout::in_group(layout::kPosition, fr.group);
  const auto [value, varies] = in.value_path(position);
  {
    h5::Handle ds = h5::open_dataset(f.id(), value);
    const auto dims = h5::shape(ds.id());
    fr.frames = varies ? (dims.empty() ? 0 : dims[0]) : 1;
  }
  if (fr.frames == 0) in.fail(value + " holds no frames");
  const std::vector<double> times = varies ? in.times(position, fr.frames) : std::vector<double>{};
  fr.index = time && !times.empty() ? nearest(times, *time) : fr.frames - 1;
  if (index) {
    if (*index >= fr.frames)
      in.fail("no frame " + std::to_string(*index) + ": " + value + " holds " + std::to_string(fr.frames) + " (0 to " +
              std::to_string(fr.frames - 1) + ")");
    fr.index = *index;
  }
  if (time && times.empty() && fr.frames > 1) in.fail(position + " has no times to pick the frame nearest t = " + format_number(*time));
  if (!times.empty()) fr.time = times[fr.index];
  fr.times = times;
  std::size_t n = 0;
  fr.dimension = in.box_dimension(fr.group);
  const std::size_t d = std::size_t(fr.dimension);
  in.check_claimed_particles(fr.group, value, varies, fr.dimension, extra_bytes_per_particle);
  fr.position = in.per_particle(position, fr.index, fr.frames, d, &n);
  widen_to_three(fr.position, n, d);
  if (n == 0) in.fail(value + " holds no particles");
  fr.length_unit = in.unit_of(position);
  fr.L = in.box_side(fr.group, fr.index, fr.frames, fr.dimension);
  auto optional = [&](std::string_view element, std::size_t k) {
    const std::string e = layout::in_group(element, fr.group);
    return h5::exists(f.id(), e) ? in.per_particle(e, fr.index, fr.frames, k, &n) : std::vector<double>{};
  };
  fr.velocity = optional(layout::kVelocity, d);
  widen_to_three(fr.velocity, fr.velocity.size() / d, d);
  fr.mass = optional(layout::kMass, 1);
  fr.diameter = optional(layout::kDiameter, 1);
  std::vector<double> id = optional(layout::kId, 1);
  if (!id.empty()) {
    std::vector<bool> present(n);
    for (std::size_t i = 0; i < n; ++i) present[i] = id[i] != layout::kAbsentId;
    compact_slots(fr.position, present, 3);
    compact_slots(fr.velocity, present, 3);
    compact_slots(fr.mass, present, 1);
    compact_slots(fr.diameter, present, 1);
    compact_slots(id, present, 1);
    fr.id = std::move(id);
    if (fr.position.empty()) in.fail("frame " + std::to_string(fr.index) + " holds no particle (every id is -1)");
  }
  return fr;
}

}  // namespace

H5mdFrame read_h5md_frame(const std::string& path, std::optional<double> time, double extra_bytes_per_particle) {
  return read_frame(path, time, {}, extra_bytes_per_particle);
}

H5mdFrame read_h5md_frame_at(const std::string& path, std::size_t index) { return read_frame(path, {}, index, 0); }

}  // namespace coolgas
