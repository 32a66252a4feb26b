// Reads of damaged or hostile HDF5 files: a dataset whose declared shape
// would not fit in memory, and a stored chunk that cannot be decoded, are
// each one InputError naming the file and the dataset (exit code 2, damaged
// input), never "out of memory" or an internal HDF5 error.
#include "common/hdf5_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <vector>

#include "common/error.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

// The message of the InputError `read` throws, or "" if it throws none.
template <class F>
std::string input_error_of(F&& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A chunked dataset "/x" of `dims`; nothing written, so it takes no space on disk.
void create_declared(const std::string& path, const std::vector<hsize_t>& dims) {
  h5::Handle f = h5::open_file(path, h5::Mode::kCreateTruncate);
  std::vector<hsize_t> chunk(dims.size(), 1);
  chunk.back() = dims.back();
  h5::Handle space(H5Screate_simple(int(dims.size()), dims.data(), nullptr)), dcpl(H5Pcreate(H5P_DATASET_CREATE));
  H5Pset_chunk(dcpl.id(), int(chunk.size()), chunk.data());
  h5::Handle ds(H5Dcreate2(f.id(), "x", H5T_IEEE_F64LE, space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT));
  ASSERT_TRUE(ds.valid());
}

TEST(Hdf5File, AShapeBeyondTheMemoryIsRefusedNamingTheFileAndDataset) {
  const std::string path = test::scratch_dir("hdf5_file_huge") + "/huge.h5";
  create_declared(path, {2, 1000000000000ULL, 3});
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  h5::Handle ds = h5::open_dataset(f.id(), "x");
  const std::string all = input_error_of([&] { h5::read_all<double>(ds.id()); });
  EXPECT_NE(all.find("'" + path + "': dataset '/x' of shape (2, 1000000000000, 3) would need 48 TB to read;"),
            std::string::npos)
      << all;
  const std::string row = input_error_of([&] { h5::read_row<double>(ds.id(), 1); });
  EXPECT_NE(row.find("would need 24 TB to read one row"), std::string::npos) << row;
  // The check readers call before allocating for themselves.
  const std::string own = input_error_of([&] { h5::check_read_fits(ds.id(), 3e12, 8, " one frame"); });
  EXPECT_NE(own.find("'" + path + "': dataset '/x' of shape"), std::string::npos) << own;
  EXPECT_EQ(input_error_of([&] { h5::check_read_fits(ds.id(), 1e6, 8); }), "");
}

// One chunk of a deflated dataset with bytes flipped in its middle: zlib
// cannot decode it, and the read names the file, the dataset and the row.
TEST(Hdf5File, ADamagedChunkIsDamagedInputNamingTheFileAndDataset) {
  const std::string path = test::scratch_dir("hdf5_file_chunk") + "/damaged.h5";
  haddr_t offset = 0;
  hsize_t bytes = 0;
  {
    h5::Handle f = h5::open_file(path, h5::Mode::kCreateTruncate);
    h5::Handle ds = h5::create_series(f.id(), "x", h5::Type::kFloat64, {1000}, 1, std::nullopt, {0, 6});
    std::vector<double> row(1000);
    for (std::size_t i = 0; i < row.size(); ++i) row[i] = 0.37 * double(i * i % 101);
    for (int r = 0; r < 3; ++r) h5::append_row(ds.id(), h5::Type::kFloat64, row.data());
    h5::flush(f);
    const hsize_t at[2] = {1, 0};
    ASSERT_GE(H5Dget_chunk_info_by_coord(ds.id(), at, nullptr, &offset, &bytes), 0);
  }
  {
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(std::streamoff(offset + bytes / 3));
    const std::string garbage(32, '\x5a');
    file.write(garbage.data(), std::streamsize(garbage.size()));
  }
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  h5::Handle ds = h5::open_dataset(f.id(), "x");
  std::vector<double> out(1000);
  EXPECT_EQ(input_error_of([&] { h5::read_rows(ds.id(), h5::Type::kFloat64, 0, 1, out.data()); }), "");
  const std::string e = input_error_of([&] { h5::read_rows(ds.id(), h5::Type::kFloat64, 1, 1, out.data()); });
  EXPECT_NE(e.find("'" + path + "': dataset '/x' cannot be read (row 1): "), std::string::npos) << e;
  const std::string all = input_error_of([&] { h5::read_all<double>(ds.id()); });
  EXPECT_NE(all.find("dataset '/x' cannot be read (rows 0 to 2)"), std::string::npos) << all;
}

// An attribute that holds more than the one value a reader takes, or a value
// of another kind: one InputError naming the file, the object, the attribute
// and what it holds (an array was read into one number: a stack overwrite).
TEST(Hdf5File, AnAttributeOfTheWrongShapeOrKindIsRefusedNamingItsValue) {
  const std::string path = test::scratch_dir("hdf5_file_attributes") + "/attributes.h5";
  {
    h5::Handle f = h5::open_file(path, h5::Mode::kCreateTruncate);
    h5::Handle g = h5::create_group(f.id(), "/box");
    h5::write_attr(g.id(), "pair", std::vector<std::int32_t>{2, 2});
    h5::write_attr(g.id(), "many", std::vector<std::int32_t>(100, 3));
    h5::write_attr(g.id(), "text", std::string("3"));
    h5::write_attr(g.id(), "texts", std::vector<std::string>{"a", "b"});
    h5::write_attr(g.id(), "half", 2.5);
    h5::write_attr(g.id(), "whole", std::int64_t{3});
    h5::write_attr(g.id(), "one", std::vector<std::int32_t>{7});
  }
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  h5::Handle g = h5::open_group(f.id(), "/box");
  const std::string where = "'" + path + "': attribute ";
  EXPECT_EQ(input_error_of([&] { h5::read_attr_int(g.id(), "pair"); }),
            where + "'pair' of '/box' is [2, 2]; expected one integer");
  EXPECT_EQ(input_error_of([&] { h5::read_attr_double(g.id(), "many"); }),
            where + "'many' of '/box' is [3, 3, 3, 3, … (100 values)]; expected one number");
  EXPECT_EQ(input_error_of([&] { h5::read_attr_int(g.id(), "text"); }),
            where + "'text' of '/box' is the string '3'; expected one integer");
  EXPECT_EQ(input_error_of([&] { h5::read_attr_int(g.id(), "half"); }),
            where + "'half' of '/box' is 2.5; expected one integer");
  EXPECT_EQ(input_error_of([&] { h5::read_attr_string(g.id(), "texts"); }),
            where + "'texts' of '/box' holds 2 strings; expected one");
  EXPECT_EQ(input_error_of([&] { h5::read_attr_string(g.id(), "whole"); }),
            where + "'whole' of '/box' is 3; expected a string");
  EXPECT_EQ(input_error_of([&] { h5::read_attr_int(g.id(), "absent"); }),
            "'" + path + "': missing attribute 'absent' of '/box'");
  EXPECT_EQ(h5::read_attr_int(g.id(), "whole"), 3);
  EXPECT_EQ(h5::read_attr_double(g.id(), "whole"), 3.0);  // integers are numbers
  EXPECT_EQ(h5::read_attr_int(g.id(), "one"), 7);          // a one-element array is one value
}

// Variable-length strings in ASCII, as h5py writes bytes (a foreign box's
// `boundary`): read as they are, not refused as a damaged attribute.
TEST(Hdf5File, AsciiStringAttributesAreRead) {
  const std::string path = test::scratch_dir("hdf5_file_ascii") + "/ascii.h5";
  {
    h5::Handle f = h5::open_file(path, h5::Mode::kCreateTruncate);
    h5::Handle type(H5Tcopy(H5T_C_S1));
    H5Tset_size(type.id(), H5T_VARIABLE);
    H5Tset_cset(type.id(), H5T_CSET_ASCII);
    const hsize_t n = 3;
    h5::Handle space(H5Screate_simple(1, &n, nullptr)), scalar(H5Screate(H5S_SCALAR));
    h5::Handle a(H5Acreate2(f.id(), "boundary", type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT));
    const char* values[3] = {"periodic", "periodic", "none"};
    ASSERT_GE(H5Awrite(a.id(), type.id(), values), 0);
    h5::Handle b(H5Acreate2(f.id(), "unit", type.id(), scalar.id(), H5P_DEFAULT, H5P_DEFAULT));
    const char* unit = "nm";
    ASSERT_GE(H5Awrite(b.id(), type.id(), &unit), 0);
  }
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  EXPECT_EQ(h5::read_attr_strings(f.id(), "boundary"), (std::vector<std::string>{"periodic", "periodic", "none"}));
  EXPECT_EQ(h5::read_attr_string(f.id(), "unit"), "nm");
}

// An object header overwritten: opening the object, or looking up a path
// through it, is Damaged (an InputError) naming the file and the object,
// never "internal error: HDF5: open group".
TEST(Hdf5File, ADamagedObjectHeaderIsDamagedInputNamingTheFileAndObject) {
  const std::string path = test::scratch_dir("hdf5_file_header") + "/header.h5";
  haddr_t at = 0;
  {
    h5::Handle f = h5::open_file(path, h5::Mode::kCreateTruncate);
    h5::Handle g = h5::create_group(f.id(), "/particles/box");
    h5::write_attr(g.id(), "dimension", std::int64_t{3});
    h5::Handle d = h5::create_series(g.id(), "edges", h5::Type::kFloat64, {3}, 1);
    H5O_info_t info{};
    ASSERT_GE(H5Oget_info2(g.id(), &info, H5O_INFO_BASIC), 0);
    at = info.addr;
  }
  {
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(std::streamoff(at));
    file.write("\xff\xff\xff\xff", 4);
  }
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  const std::string group = input_error_of([&] { h5::open_group(f.id(), "/particles/box"); });
  EXPECT_EQ(group, "'" + path + "': cannot open group '/particles/box': the file is damaged");
  const std::string through = input_error_of([&] { h5::exists(f.id(), "/particles/box/edges"); });
  EXPECT_EQ(through, "'" + path + "': cannot look up '/particles/box/edges': the file is damaged");
  EXPECT_THROW(h5::open_dataset(f.id(), "/particles/box/edges"), h5::Damaged);
  EXPECT_EQ(input_error_of([&] { h5::open_dataset(f.id(), "/particles"); }),
            "'" + path + "': '/particles' is a group, not a dataset");
  EXPECT_EQ(input_error_of([&] { h5::open_group(f.id(), "/nothing"); }), "'" + path + "': missing group '/nothing'");
}

}  // namespace
}  // namespace coolgas
