#include "data-schema/hdf5_inspect.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>

#include "common/hdf5_file.h"

namespace coolgas::schema {
namespace {

// "[a, b, c]" (built by appending: GCC 12 gives a false -Wrestrict for "(" + std::string&&).
std::string enclose(const char* open, const std::vector<std::string>& items, const char* close) {
  std::string s = open;
  for (std::size_t i = 0; i < items.size(); ++i) s.append(i ? ", " : "").append(items[i]);
  return s.append(close);
}

hsize_t element_count(const std::vector<hsize_t>& dims) {
  return std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
}

// Reads every element of a numeric attribute as text (and the first as a
// number into `found`); empty on failure.
std::vector<std::string> numeric_values(hid_t attr, hid_t type, hsize_t n, AttributeFound& found) {
  std::vector<std::string> out;
  if (H5Tget_class(type) == H5T_INTEGER) {
    std::vector<long long> v(n);
    if (n == 0 || H5Aread(attr, H5T_NATIVE_LLONG, v.data()) < 0) return {};
    for (long long x : v) out.push_back(std::to_string(x));
    found.first_integer = v[0];
  } else {
    std::vector<double> v(n);
    if (n == 0 || H5Aread(attr, H5T_NATIVE_DOUBLE, v.data()) < 0) return {};
    for (double x : v) out.push_back(number_text(x));
    found.first_number = v[0];
  }
  return out;
}

std::vector<std::string> vlen_strings(hid_t attr, hsize_t n) {
  h5::Handle mem(H5Tcopy(H5T_C_S1));
  H5Tset_size(mem.id(), H5T_VARIABLE);
  H5Tset_cset(mem.id(), H5T_CSET_UTF8);
  std::vector<char*> p(n, nullptr);
  if (H5Aread(attr, mem.id(), p.data()) < 0) return {};
  std::vector<std::string> out;
  for (char* s : p) {
    out.emplace_back(s ? s : "");
    H5free_memory(s);
  }
  return out;
}

}  // namespace

ObjectKind kind_of(hid_t file, std::string_view path) {
  try {
    if (!h5::exists(file, std::string(path))) return ObjectKind::kMissing;
  } catch (const h5::Damaged&) {  // a group on the way cannot be read
    return ObjectKind::kDamaged;
  }
  h5::Handle obj(H5Oopen(file, std::string(path).c_str(), H5P_DEFAULT));
  if (!obj.valid()) {  // a dangling soft link, or a damaged object
    H5L_info_t link{};
    const bool hard = H5Lget_info(file, std::string(path).c_str(), &link, H5P_DEFAULT) >= 0 && link.type == H5L_TYPE_HARD;
    return hard ? ObjectKind::kDamaged : ObjectKind::kMissing;
  }
  switch (H5Iget_type(obj.id())) {
    case H5I_GROUP:
      return ObjectKind::kGroup;
    case H5I_DATASET:
      return ObjectKind::kDataset;
    default:
      return ObjectKind::kOther;
  }
}

std::string describe_type(hid_t type) {
  const std::string bits = std::to_string(8 * H5Tget_size(type));
  switch (H5Tget_class(type)) {
    case H5T_INTEGER:
      return (H5Tget_sign(type) == H5T_SGN_NONE ? "uint" : "int") + bits;
    case H5T_FLOAT:
      return "float" + bits;
    case H5T_STRING:
      return H5Tis_variable_str(type) > 0 ? "vlen str" : "fixed str";
    case H5T_COMPOUND:
      return "compound";
    case H5T_ENUM:
      return "enum";
    case H5T_ARRAY:
      return "array";
    case H5T_VLEN:
      return "vlen sequence";
    default:
      return "other";
  }
}

bool type_matches(DataType want, hid_t type) {
  const std::string have = describe_type(type);
  if (want == DataType::kInteger) return have.starts_with("int");
  return have == type_name(want);
}

std::string shape_text(const std::vector<hsize_t>& dims) {
  std::vector<std::string> items;
  for (hsize_t d : dims) items.push_back(std::to_string(d));
  return enclose("(", items, dims.size() == 1 ? ",)" : ")");
}

std::string index_text(const std::vector<hsize_t>& dims, hsize_t flat) {
  std::vector<std::string> items(dims.size());
  for (std::size_t k = dims.size(); k-- > 0;) {
    items[k] = std::to_string(flat % dims[k]);
    flat /= dims[k];
  }
  return enclose("[", items, "]");
}

std::string number_text(double v) {
  if (std::isnan(v)) return "nan";  // whatever its sign bit
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

bool read_attribute(hid_t file, std::string_view path, std::string_view name, AttributeFound& out) {
  const std::string p(path), n(name);
  if (H5Aexists_by_name(file, p.c_str(), n.c_str(), H5P_DEFAULT) <= 0) return false;
  h5::Handle attr(H5Aopen_by_name(file, p.c_str(), n.c_str(), H5P_DEFAULT, H5P_DEFAULT));
  h5::Handle type(H5Aget_type(attr.id()));
  h5::Handle space(H5Aget_space(attr.id()));
  if (!attr.valid() || !type.valid() || !space.valid()) return true;  // exists but unreadable: empty text
  out.type = describe_type(type.id());
  out.dims.assign(static_cast<std::size_t>(std::max(0, H5Sget_simple_extent_ndims(space.id()))), 0);
  H5Sget_simple_extent_dims(space.id(), out.dims.data(), nullptr);
  const hsize_t count = element_count(out.dims);
  std::vector<std::string> values;
  const H5T_class_t cls = H5Tget_class(type.id());
  if (cls == H5T_INTEGER || cls == H5T_FLOAT) values = numeric_values(attr.id(), type.id(), count, out);
  if (cls == H5T_STRING && H5Tis_variable_str(type.id()) > 0) values = vlen_strings(attr.id(), count);
  if (values.empty()) return true;
  out.text = out.dims.empty() ? values[0] : enclose("[", values, "]");
  return true;
}

}  // namespace coolgas::schema
