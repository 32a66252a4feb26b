#include "common/trajectory/layout.h"

#include "common/error.h"
#include "common/hdf5_file.h"

namespace coolgas::layout {

std::string step_of(std::string_view element) { return std::string(element) + "/step"; }
std::string time_of(std::string_view element) { return std::string(element) + "/time"; }
std::string value_of(std::string_view element) { return std::string(element) + "/value"; }

std::string in_group(std::string_view element, std::string_view group) {
  return std::string(kParticles) + "/" + std::string(group) + std::string(element.substr(kAll.size()));
}

hsize_t complete_dumps(hid_t file) {
  if (!h5::exists(file, std::string(kRestartTime))) return 0;
  h5::Handle t = h5::open_dataset(file, std::string(kRestartTime));
  return h5::shape(t.id()).at(0);
}

std::optional<double> last_dump_time(hid_t file) {
  const hsize_t n = complete_dumps(file);
  if (n == 0) return std::nullopt;
  h5::Handle t = h5::open_dataset(file, std::string(kRestartTime));
  return h5::read_row<double>(t.id(), n - 1).at(0);
}

int dimension_of(hid_t file) {
  const std::string box(kBox);
  if (!h5::exists(file, box)) return 3;
  h5::Handle g = h5::open_group(file, box);
  if (!h5::has_attr(g.id(), "dimension")) return 3;
  const std::int64_t d = h5::read_attr_int(g.id(), "dimension");
  if (d < 1 || d > 3)
    throw InputError("'" + h5::file_of(file) + "': attribute 'dimension' of '" + box + "' is " + std::to_string(d) +
                     "; a coolgas file has dimension 1, 2 or 3");
  return int(d);
}

Layout layout_of(hid_t file) { return h5::exists(file, value_of(kId)) ? Layout::kAggregation : Layout::kGas; }

bool is_coolgas(hid_t file) {
  return h5::exists(file, std::string(kParameters)) && h5::exists(file, std::string(kPosition));
}

}  // namespace coolgas::layout
