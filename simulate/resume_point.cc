#include "simulate/resume_point.h"

#include <cstring>

#include "common/error.h"
#include "common/hdf5_file.h"

namespace coolgas {

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
  return rp;
}

}  // namespace coolgas
