// Thin RAII layer over the HDF5 C API: handles that close themselves and the
// few typed operations coolgas needs (attributes, extendable time series,
// whole-dataset reads). Every failure becomes an exception naming the object.
#pragma once
#include <hdf5.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/error.h"

namespace coolgas::h5 {

// An HDF5 call failed. `cause` is the operating system's reason when the
// library failed to read or write the file ("No space left on device",
// "File too large"), empty otherwise.
struct Error : std::runtime_error {
  Error(const std::string& what, std::string cause) : std::runtime_error(what), cause(std::move(cause)) {}
  std::string cause;
};

// Reading the file's structure failed: an object header, a link table or
// an attribute HDF5 cannot decode. An InputError (exit code 2) naming the
// file and the object; every reading function below throws it for a damaged
// file, never an Error.
struct Damaged : InputError {
  using InputError::InputError;
};

// Owns one hid_t and closes it with the matching H5*close.
class Handle {
 public:
  Handle() = default;
  explicit Handle(hid_t id) : id_(id) {}
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      close();
      id_ = std::exchange(o.id_, H5I_INVALID_HID);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { close(); }
  hid_t id() const { return id_; }
  bool valid() const { return id_ >= 0; }
  void close();  // errors ignored: for handles that wrote nothing
  // Closes and throws Error if closing failed: closing a dataset or file
  // writes what HDF5 still caches, so a writer must know.
  void close_checked();

 private:
  hid_t id_ = H5I_INVALID_HID;
};

// For messages: the path of an object in its file, and the name of the file
// it lies in.
std::string name_of(hid_t object);
std::string file_of(hid_t object);

// Turns off HDF5's own error printing; coolgas reports errors itself.
void silence_library_errors();

// Files are created in the HDF5 1.10 format, which SWMR writing needs.
// kReadOnly also opens a file that a SWMR writer has open, or left behind
// when it was killed (as a SWMR reader). kReadWrite and kAppend clear the
// status flags such a writer leaves (as `h5clear -s` does), so a killed run
// can resume. kAppend opens straight into SWMR writing (start_swmr_write), so
// the file is consistent on disk from the first byte written: a writer killed
// at any moment leaves it readable. It fails for a file that
// appends_in_swmr() says cannot, which only kReadWrite opens.
enum class Mode { kCreateExclusive, kCreateTruncate, kReadOnly, kReadWrite, kAppend };
Handle open_file(const std::string& path, Mode mode);
void flush(const Handle& file);
// A writer killed in the middle of a write can leave the file's recorded end
// of allocation (EOA) short of chunks its index already lists; HDF5 then
// fails when it frees them (shrinking the dataset) or closes the file. Sets
// the EOA to the file's size plus `margin` bytes, as `h5clear -i` does, and
// grows the file to that end at once (before the EOA reaches the superblock):
// a file whose superblock records more than its size is refused by HDF5 as
// truncated, so a kill or a failed write (a full disk, a size limit) after
// the next flush must not find it shorter. Throws Error with the system's
// reason when the file cannot grow; the file is then unchanged.
void extend_allocation_past_file_end(const Handle& file, hsize_t margin);

// A file whose superblock records an end of allocation beyond its size
// (written by a version that grew the allocation before the file, then
// killed or out of space) is refused by HDF5 as truncated. Grows the file
// with zeros to the recorded end, as `h5clear --increment` would, so that it
// opens; the bytes already there are not touched. Returns whether it grew.
// Only files with a version 2/3 superblock at offset 0 (all coolgas writes).
bool cover_recorded_allocation(const std::string& path);
// The bytes of one chunk of a chunked dataset, uncompressed; 0 if not chunked.
hsize_t chunk_bytes(hid_t dataset);
// Whether the open file can be opened with kAppend: it is in the 1.10
// format and keeps no list of its free space (HDF5 cannot open such a file
// for SWMR writing; earlier versions of coolgas wrote them so).
bool appends_in_swmr(const Handle& file);
// Copies every object of the open file `from` into a new file `to` (created
// as kCreateTruncate creates files: the format appends_in_swmr() wants),
// calling `between` before each object of the root group (it may throw, to
// stop). The raw data is copied as it is stored, the filters kept.
void copy_into_new_file(const Handle& from, const std::string& to, const std::function<void()>& between);
// Starts single-writer/multiple-reader writing: from here on the file is
// consistent on disk at every moment, readers may open it, and no object
// may be created or attribute written. Returns false, doing nothing, for a
// file in the pre-1.10 format (written by an older coolgas).
bool start_swmr_write(const Handle& file);
// Makes sure the next `bytes` bytes past the end of the file can be written
// (posix_fallocate), so that a full disk, a quota or a file-size limit fails
// here, before HDF5 writes a byte, instead of in the middle of a write that
// would leave its metadata pointing past the end of the file. Throws Error
// with the system's reason; does nothing where the file system cannot tell.
void reserve_space(const Handle& file, hsize_t bytes);
// Gives back what the last reservation left unused (the end of a run).
void release_reserve(const Handle& file);

// Whether the link exists (each path component checked); Damaged if a
// group on the way cannot be read.
bool exists(hid_t loc, const std::string& path);
// A missing path, an object of the other kind (a dataset for a group) or a
// damaged one: InputError naming the file and the path.
Handle open_group(hid_t loc, const std::string& path);
Handle create_group(hid_t loc, const std::string& path);  // creates parents as needed
Handle open_dataset(hid_t loc, const std::string& path);

// Attributes. Strings are variable-length UTF-8, as MDAnalysis requires.
void write_attr(hid_t obj, const std::string& name, const std::string& value);
void write_attr(hid_t obj, const std::string& name, const std::vector<std::string>& values);
void write_attr(hid_t obj, const std::string& name, double value);
void write_attr(hid_t obj, const std::string& name, std::int64_t value);
void write_attr(hid_t obj, const std::string& name, const std::vector<std::int32_t>& values);
void write_attr(hid_t obj, const std::string& name, const std::vector<double>& values);
bool has_attr(hid_t obj, const std::string& name);  // Damaged if the attribute table cannot be read
H5T_class_t attr_class(hid_t obj, const std::string& name);  // H5T_INTEGER, H5T_FLOAT, H5T_STRING, ...
// One value: a scalar or a one-element array. An array of more, or a value
// of another kind (a string for a number, 2.5 for an integer), is an
// InputError naming the file, the object, the attribute and what it holds.
std::string read_attr_string(hid_t obj, const std::string& name);
double read_attr_double(hid_t obj, const std::string& name);  // an integer or a float
std::int64_t read_attr_int(hid_t obj, const std::string& name);
// A one-dimensional array of 1 to `most` numbers (integers or floats); any
// other shape or kind, or more values, is an InputError naming the file,
// the object, the attribute and what it holds.
std::vector<double> read_attr_doubles(hid_t obj, const std::string& name, std::size_t most);
// A string or an array of strings, variable or fixed length (as other programs write them).
std::vector<std::string> read_attr_strings(hid_t obj, const std::string& name);
// The object at `path` is a group (an H5MD element that varies in time), not a dataset.
bool is_group(hid_t loc, const std::string& path);

// Element types of datasets.
enum class Type { kFloat64, kInt64, kInt32 };

// The shape of a dataset (dimensions, slowest first).
std::vector<hsize_t> shape(hid_t dataset);

// How a series' chunks are cut and filtered. `chunk_inner` > 0 cuts the
// first inner dimension (the particles) into chunks of that many; 0 keeps it
// whole. `deflate_level` 1-9 stores the chunks through HDF5's shuffle filter
// and deflate (zlib), lossless; 0 stores them as they are.
struct Storage {
  hsize_t chunk_inner = 0;
  int deflate_level = 0;
};

// Creates a chunked dataset whose first dimension grows: shape (0, inner...).
// `fill_value`: the dataset's HDF5 fill value (H5MD marks absent particles with it).
Handle create_series(hid_t loc, const std::string& name, Type type, const std::vector<hsize_t>& inner,
                     hsize_t chunk_rows, std::optional<std::int64_t> fill_value = std::nullopt,
                     const Storage& storage = {});
// Appends one row (a block of prod(inner) elements) at the end of the first
// dimension. With a row shape (N, k) and stride > k, the k elements of item i
// are read from data[i * stride ...] (HDF5 gathers them; nothing is copied).
void append_row(hid_t dataset, Type type, const void* data, hsize_t stride = 0);
// Shrinks or grows the first dimension to n rows (used to drop rows after a resume point).
void resize_rows(hid_t dataset, hsize_t n);
// Reads rows [first, first+count) of a dataset into a flat buffer. A read
// that fails (a damaged chunk, an I/O error) is an InputError naming the
// file, the dataset and the rows.
void read_rows(hid_t dataset, Type type, hsize_t first, hsize_t count, void* out);

// Refuses (InputError naming the file, the dataset and its shape) a read of
// `values` values of `value_size` bytes each from `dataset` that would not
// fit in the memory available (common/memory.h); `what` says what is read (" one row"). For
// readers that allocate themselves, before they do.
void check_read_fits(hid_t dataset, double values, std::size_t value_size, const std::string& what = "");

// Both refuse (InputError naming the dataset and its shape) a read that would
// not fit in the memory available, before allocating anything.
template <class T>
std::vector<T> read_all(hid_t dataset);
// Reads row `row` of a dataset of shape (F, inner...) as a flat vector.
template <class T>
std::vector<T> read_row(hid_t dataset, hsize_t row);

}  // namespace coolgas::h5
