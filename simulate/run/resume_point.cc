#include "simulate/run/resume_point.h"

#include <cstring>

#include "common/error.h"
#include "common/hdf5_file.h"
#include "simulate/start/configuration_check.h"

namespace coolgas {

namespace {

// The aggregates of dump `row`: slots whose id is the fill value -1 are empty.
AggregateState read_aggregates(hid_t file, const std::string& path, hsize_t row, std::size_t n) {
  AggregateState a;
  a.id.resize(n);
  a.mass.resize(n);
  a.diameter.resize(n);
  for (const char* need : {"particles/all/mass/value", "particles/all/diameter/value"})
    if (!h5::exists(file, need)) throw InputError("cannot resume from '" + path + "': missing /" + need);
  h5::Handle id = h5::open_dataset(file, "particles/all/id/value");
  h5::Handle mass = h5::open_dataset(file, "particles/all/mass/value");
  h5::Handle diam = h5::open_dataset(file, "particles/all/diameter/value");
  h5::read_rows(id.id(), h5::Type::kInt32, row, 1, a.id.data());
  h5::read_rows(mass.id(), h5::Type::kFloat64, row, 1, a.mass.data());
  h5::read_rows(diam.id(), h5::Type::kFloat64, row, 1, a.diameter.data());
  for (std::size_t i = 0; i < n; ++i) {
    const bool present = a.id[i] >= 0;
    if ((present && (a.id[i] != std::int32_t(i) || !(a.mass[i] >= 1) || !(a.diameter[i] >= 1))) ||
        (!present && a.id[i] != -1))
      throw InputError("cannot resume from '" + path + "': slot " + std::to_string(i) +
                       " of the last dump holds id " + std::to_string(a.id[i]) +
                       " with mass and diameter below 1 or in the wrong slot (ids are slot numbers, -1 when absent)");
  }
  return a;
}

}  // namespace

ResumePoint read_resume_point(const std::string& path) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  const hid_t id = f.id();
  for (const char* need : {"parameters", "restart/time", "particles/all/position/value", "particles/all/velocity/value",
                           "particles/all/image/value"})
    if (!h5::exists(id, need)) throw InputError("cannot resume from '" + path + "': missing /" + need);
  ResumePoint rp;
  h5::Handle par = h5::open_group(id, "parameters");
  rp.scene_toml = h5::read_attr_string(par.id(), "scene");
  rp.particles.L = h5::read_attr_double(par.id(), "L");
  const auto n = static_cast<std::size_t>(h5::read_attr_int(par.id(), "N"));
  h5::Handle rt = h5::open_dataset(id, "restart/time");
  const auto times = h5::read_all<double>(rt.id());
  if (times.empty()) throw InputError("cannot resume from '" + path + "': it holds no complete dump");
  const hsize_t last = times.size() - 1;  // rows after it belong to an interrupted burst
  rp.time = times.back();
  h5::Handle rc = h5::open_dataset(id, "restart/collisions");
  h5::Handle rb = h5::open_dataset(id, "restart/collisions_below_delta");
  rp.counters.collisions = h5::read_row<std::int64_t>(rc.id(), last)[0];
  rp.counters.below_delta = h5::read_row<std::int64_t>(rb.id(), last)[0];

  rp.particles.resize(n);
  h5::Handle pos = h5::open_dataset(id, "particles/all/position/value");
  h5::Handle vel = h5::open_dataset(id, "particles/all/velocity/value");
  h5::Handle img = h5::open_dataset(id, "particles/all/image/value");
  if (h5::shape(pos.id()).size() != 3 || h5::shape(pos.id())[1] != n)
    throw InputError("cannot resume from '" + path + "': positions are not N x 3 with N = " + std::to_string(n));
  h5::read_rows(pos.id(), h5::Type::kFloat64, last, 1, rp.particles.r.data());
  h5::read_rows(vel.id(), h5::Type::kFloat64, last, 1, rp.particles.v.data());
  h5::read_rows(img.id(), h5::Type::kInt32, last, 1, rp.particles.image.data());
  std::fill(rp.particles.t.begin(), rp.particles.t.end(), rp.time);
  if (h5::exists(id, "particles/all/id/value")) rp.aggregates = read_aggregates(id, path, last, n);
  check_configuration(rp.particles, rp.aggregates ? &*rp.aggregates : nullptr, "cannot resume from '" + path + "'");
  return rp;
}

}  // namespace coolgas
