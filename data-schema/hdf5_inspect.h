// Looking at an HDF5 file without trusting it: what kind of object sits at a
// path, what type and shape a dataset or attribute has, and how to print them
// in the words of the profile. Nothing here throws for a malformed file.
#pragma once
#include <hdf5.h>

#include <string>
#include <string_view>
#include <vector>

#include "common/trajectory/h5md_profile.h"

namespace coolgas::schema {

// kDamaged: its object header, or a group on its path, cannot be read.
enum class ObjectKind { kMissing, kGroup, kDataset, kOther, kDamaged };
ObjectKind kind_of(hid_t file, std::string_view path);

// "int32", "uint8", "float32", "vlen str", "fixed str", "compound", ...
std::string describe_type(hid_t type);
bool type_matches(DataType want, hid_t type);

// "(3, 100, 3)"; "()" for a scalar.
std::string shape_text(const std::vector<hsize_t>& dims);
// "[1, 0, 2]": the multi-index of element `flat` in row-major order.
std::string index_text(const std::vector<hsize_t>& dims, hsize_t flat);
// Shortest text that reads back as the same double ("5", "0.1", "nan").
std::string number_text(double v);

// An attribute as found in the file.
struct AttributeFound {
  std::string type;             // describe_type()
  std::vector<hsize_t> dims;    // empty: scalar
  std::string text;             // the value printed as in AttributeSpec::equals; empty if unreadable
  long long first_integer = 0;  // first element, if integer
  double first_number = 0;      // first element, if floating point
};
// Reads attribute `name` of the object at `path`; false if it does not exist.
bool read_attribute(hid_t file, std::string_view path, std::string_view name, AttributeFound& out);

}  // namespace coolgas::schema
