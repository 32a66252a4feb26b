#include "common/hdf5_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <algorithm>
#include <functional>
#include <numeric>
#include <stdexcept>

#include "common/error.h"
#include "common/memory.h"

namespace coolgas::h5 {
namespace {

// The system error message HDF5's file driver put on the error stack, e.g.
// "... errno = 28, error message = 'No space left on device', ...".
herr_t find_system_message(unsigned, const H5E_error2_t* e, void* out) {
  const std::string desc = e->desc ? e->desc : "";
  const std::string key = "error message = '";
  const auto at = desc.find(key);
  if (at == std::string::npos) return 0;
  const auto end = desc.find('\'', at + key.size());
  *static_cast<std::string*>(out) = desc.substr(at + key.size(), end - at - key.size());
  return 1;  // stop at the innermost one
}

std::string system_cause() {
  std::string cause;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, find_system_message, &cause);
  return cause;
}

[[noreturn]] void fail(const std::string& what) { throw Error("HDF5: " + what, system_cause()); }

hid_t check(hid_t id, const std::string& what) {
  if (id < 0) fail(what);
  return id;
}

void check_status(herr_t st, const std::string& what) {
  if (st < 0) fail(what);
}

// A failure the library met while writing to the file (its cache flushing
// what a writer changed): the writer's to report (WriteError), not damage.
bool is_write_failure(const std::string& cause) {
  for (const int err : {ENOSPC, EDQUOT, EFBIG})
    if (cause == std::strerror(err)) return true;
  return false;
}

// Reading the file's structure failed (an object header, a link, an
// attribute table or message HDF5 cannot decode): the file is damaged, an
// InputError naming the file and the object. A write failure met on the
// way stays an Error, which a writer reports as a failed write.
[[noreturn]] void fail_reading(hid_t loc, const std::string& what) {
  const std::string cause = system_cause();
  if (is_write_failure(cause)) throw Error("HDF5: " + what, cause);
  throw Damaged("'" + file_of(loc) + "': cannot " + what + ": the file is damaged" +
                (cause.empty() ? "" : " (" + cause + ")"));
}

hid_t check_reading(hid_t id, hid_t loc, const std::string& what) {
  if (id < 0) fail_reading(loc, what);
  return id;
}

hid_t mem_type(Type t) {
  switch (t) {
    case Type::kFloat64: return H5T_NATIVE_DOUBLE;
    case Type::kInt64: return H5T_NATIVE_INT64;
    case Type::kInt32: return H5T_NATIVE_INT32;
  }
  return H5T_NATIVE_DOUBLE;
}

hid_t file_type(Type t) {
  switch (t) {
    case Type::kFloat64: return H5T_IEEE_F64LE;
    case Type::kInt64: return H5T_STD_I64LE;
    case Type::kInt32: return H5T_STD_I32LE;
  }
  return H5T_IEEE_F64LE;
}

template <class T>
Type type_of();
template <>
Type type_of<double>() { return Type::kFloat64; }
template <>
Type type_of<std::int64_t>() { return Type::kInt64; }
template <>
Type type_of<std::int32_t>() { return Type::kInt32; }

Handle vlen_string_type() {
  Handle t(check(H5Tcopy(H5T_C_S1), "string type"));
  check_status(H5Tset_size(t.id(), H5T_VARIABLE), "string type size");
  check_status(H5Tset_cset(t.id(), H5T_CSET_UTF8), "string charset");
  return t;
}

// The memory type for reading a variable-length string stored as `stored`:
// its character set kept (HDF5 converts no ASCII string to UTF-8, and h5py
// writes bytes as ASCII).
Handle vlen_string_type_like(hid_t stored) {
  Handle t = vlen_string_type();
  const H5T_cset_t cset = H5Tget_cset(stored);
  if (cset >= 0) check_status(H5Tset_cset(t.id(), cset), "string charset");
  return t;
}

Handle replace_attr(hid_t obj, const std::string& name, hid_t type, hid_t space) {
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  return Handle(check(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT),
                      "create attribute '" + name + "'"));
}

// "attribute 'dimension' of '/particles/all/box'", for messages.
std::string attr_text(hid_t obj, const std::string& name) {
  return "attribute '" + name + "' of '" + name_of(obj) + "'";
}

Handle open_attr(hid_t obj, const std::string& name) {
  const htri_t found = H5Aexists(obj, name.c_str());
  if (found < 0) fail_reading(obj, "look up " + attr_text(obj, name));
  if (found == 0) throw InputError("'" + file_of(obj) + "': missing " + attr_text(obj, name));
  return Handle(check_reading(H5Aopen(obj, name.c_str(), H5P_DEFAULT), obj, "open " + attr_text(obj, name)));
}

}  // namespace

std::string name_of(hid_t object) {
  const ssize_t n = H5Iget_name(object, nullptr, 0);
  if (n <= 0) return "(unnamed)";
  std::string s(std::size_t(n) + 1, '\0');
  H5Iget_name(object, s.data(), s.size());
  s.resize(std::size_t(n));
  return s;
}

std::string file_of(hid_t object) {
  const ssize_t n = H5Fget_name(object, nullptr, 0);
  if (n <= 0) return "(unnamed file)";
  std::string s(std::size_t(n) + 1, '\0');
  H5Fget_name(object, s.data(), s.size());
  s.resize(std::size_t(n));
  return s;
}

void Handle::close() {
  if (id_ < 0) return;
  switch (H5Iget_type(id_)) {
    case H5I_FILE: H5Fclose(id_); break;
    case H5I_GROUP: H5Gclose(id_); break;
    case H5I_DATASET: H5Dclose(id_); break;
    case H5I_ATTR: H5Aclose(id_); break;
    case H5I_DATATYPE: H5Tclose(id_); break;
    case H5I_DATASPACE: H5Sclose(id_); break;
    case H5I_GENPROP_LST: H5Pclose(id_); break;
    default: break;
  }
  id_ = H5I_INVALID_HID;
}

void Handle::close_checked() {
  if (id_ < 0) return;
  herr_t st = 0;
  switch (H5Iget_type(id_)) {
    case H5I_FILE: st = H5Fclose(id_); break;
    case H5I_DATASET: st = H5Dclose(id_); break;
    default: close(); return;
  }
  id_ = H5I_INVALID_HID;
  check_status(st, "close");
}

void silence_library_errors() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

namespace {

// The 1.10 format (superblock version 3) is the oldest SWMR writing accepts;
// pinned, so a newer library writes the same format.
Handle fapl_v110() {
  Handle fapl(check(H5Pcreate(H5P_FILE_ACCESS), "file access property list"));
  check_status(H5Pset_libver_bounds(fapl.id(), H5F_LIBVER_V110, H5F_LIBVER_V110), "format version");
  return fapl;
}

// Paged aggregation: no metadata block smaller than a page straddles a page
// boundary. A SIGKILL can cut a write() between two pages of the page cache
// (never inside one), so an object header the writer rewrites at every
// append is then always whole on disk: a straddling one could be left torn,
// its checksum wrong, and the dataset unreadable for good.
// The free space is not kept in the file (persist = false): a list of free
// space saved at one close goes stale the moment a later writer allocates
// from it and is killed, and the next writer would then hand out space that
// live objects hold.
constexpr hsize_t kFilePageBytes = 4096;
Handle fcpl_paged() {
  Handle fcpl(check(H5Pcreate(H5P_FILE_CREATE), "file creation property list"));
  check_status(H5Pset_file_space_strategy(fcpl.id(), H5F_FSPACE_STRATEGY_PAGE, false, 1), "file space strategy");
  check_status(H5Pset_file_space_page_size(fcpl.id(), kFilePageBytes), "file space page size");
  return fcpl;
}

// A SWMR reader retries a block whose checksum is wrong, as the writer may be
// rewriting it. HDF5's default (100 attempts, doubling delays of up to 36 s)
// waits an hour on a block a killed writer left torn; 30 attempts wait about
// a second in all, far longer than any live write takes.
constexpr unsigned kSwmrReadAttempts = 30;
Handle fapl_swmr_read() {
  Handle fapl(check(H5Pcreate(H5P_FILE_ACCESS), "file access property list"));
  check_status(H5Pset_metadata_read_attempts(fapl.id(), kSwmrReadAttempts), "metadata read attempts");
  return fapl;
}

// For a writer of an existing file. A writer killed while it wrote leaves
// the superblock's "open for writing" flags set, and HDF5 then refuses to
// open the file for writing: "clear_status_flags" (what h5clear -s sets)
// clears them on open. A file that keeps its free space (as coolgas wrote
// them before) holds the list as of its last close, stale if a later writer
// was killed: "null_fsm_addr" (HDF5's property for h5clear) drops it, so
// space comes only from the end of the file; the few bytes freed before are
// lost, never handed out twice. (HDF5 fails to allocate with it in a file
// that keeps no such list.) SWMR writing (kAppend) needs the 1.10 format.
Handle fapl_writer(Mode mode, bool drop_free_space) {
  Handle fapl = mode == Mode::kAppend ? fapl_v110() : Handle(check(H5Pcreate(H5P_FILE_ACCESS), "file access property list"));
  hbool_t yes = true;
  check_status(H5Pset(fapl.id(), "clear_status_flags", &yes), "clear status flags");
  if (drop_free_space) check_status(H5Pset(fapl.id(), "null_fsm_addr", &yes), "drop the saved free space");
  return fapl;
}

bool keeps_free_space(hid_t file) {
  Handle fcpl(H5Fget_create_plist(file));
  H5F_fspace_strategy_t strategy{};
  hbool_t persist = false;
  hsize_t threshold = 0;
  return fcpl.valid() && H5Pget_file_space_strategy(fcpl.id(), &strategy, &persist, &threshold) >= 0 && persist;
}

hid_t open_existing(const std::string& path, Mode mode) {
  if (mode == Mode::kReadWrite || mode == Mode::kAppend) {
    const hid_t probe = open_existing(path, Mode::kReadOnly);
    const bool drop = probe >= 0 && keeps_free_space(Handle(probe).id());
    Handle fapl = fapl_writer(mode, drop);
    const unsigned swmr = mode == Mode::kAppend ? H5F_ACC_SWMR_WRITE : 0;
    return H5Fopen(path.c_str(), H5F_ACC_RDWR | swmr, fapl.id());
  }
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id >= 0) return id;
  // Being written, or left by a killed writer: only a SWMR reader may open it.
  Handle fapl = fapl_swmr_read();
  return H5Fopen(path.c_str(), H5F_ACC_RDONLY | H5F_ACC_SWMR_READ, fapl.id());
}

}  // namespace

namespace {

// The errno HDF5's file driver put on the error stack ("..., errno = 28, ..."), or 0.
herr_t find_errno(unsigned, const H5E_error2_t* e, void* out) {
  const std::string desc = e->desc ? e->desc : "";
  const std::string key = "errno = ";
  const auto at = desc.find(key);
  if (at == std::string::npos) return 0;
  *static_cast<int*>(out) = std::atoi(desc.c_str() + at + key.size());
  return 1;
}

// A file that cannot be created, with the system's reason: a full disk, a
// quota or a size limit is a failed write (WriteError, exit code 5), any
// other reason (a folder missing or not writable) the user's (InputError).
[[noreturn]] void create_failed(const std::string& path) {
  int err = 0;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, find_errno, &err);
  const std::string cause = system_cause();
  const std::string what = "cannot create '" + path + "': ";
  if (err == ENOSPC || err == EDQUOT || err == EFBIG || err == EIO) throw WriteError(what + std::strerror(err));
  throw InputError(what + (cause.empty() ? "directory missing or not writable?" : cause));
}

}  // namespace

Handle open_file(const std::string& path, Mode mode) {
  silence_library_errors();
  hid_t id = H5I_INVALID_HID;
  if (mode == Mode::kCreateExclusive || mode == Mode::kCreateTruncate) {
    Handle fapl = fapl_v110();
    Handle fcpl = fcpl_paged();
    id = H5Fcreate(path.c_str(), mode == Mode::kCreateExclusive ? H5F_ACC_EXCL : H5F_ACC_TRUNC, fcpl.id(),
                   fapl.id());
    if (id < 0) create_failed(path);  // now: closing the property lists clears HDF5's error stack
  } else {
    id = open_existing(path, mode);
  }
  if (id < 0) {
    switch (mode) {
      case Mode::kReadOnly:
        // An HDF5 file that HDF5 will not open was most often left "open for
        // writing" by a program killed before it started SWMR writing.
        if (H5Fis_hdf5(path.c_str()) > 0)
          throw InputError("cannot open '" + path + "': HDF5 refuses it (left by a killed writer? " +
                           "'h5clear -s --increment " + path + "' or a --resume repairs that; else the file is damaged)");
        throw InputError("cannot open '" + path + "' as an HDF5 file (missing, unreadable or not HDF5)");
      case Mode::kReadWrite:
      case Mode::kAppend:
        throw InputError("cannot open '" + path + "' to append (missing, not HDF5, or open in another program)");
      default:
        create_failed(path);
    }
  }
  return Handle(id);
}

namespace {

herr_t collect_name(hid_t, const char* name, const H5L_info_t*, void* names) {
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}

}  // namespace

void copy_into_new_file(const Handle& from, const std::string& to, const std::function<void()>& between) {
  Handle out = open_file(to, Mode::kCreateTruncate);
  std::vector<std::string> names;
  check_status(H5Literate(from.id(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_name, &names), "list the root group");
  for (const std::string& name : names) {
    between();
    check_status(H5Ocopy(from.id(), name.c_str(), out.id(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), "copy " + name);
  }
  out.close_checked();
}

bool appends_in_swmr(const Handle& file) {
  H5F_info2_t info{};
  check_status(H5Fget_info2(file.id(), &info), "file info");
  return info.super.version >= 3 && !keeps_free_space(file.id());
}

bool start_swmr_write(const Handle& file) {
  H5F_info2_t info{};
  check_status(H5Fget_info2(file.id(), &info), "file info");
  if (info.super.version < 3) return false;
  check_status(H5Fset_libver_bounds(file.id(), H5F_LIBVER_V110, H5F_LIBVER_V110), "format version");
  check_status(H5Fstart_swmr_write(file.id()), "start SWMR writing");
  return true;
}

namespace {

// The file's descriptor under the sec2 driver, or -1.
int descriptor(const Handle& file) {
  int* fd = nullptr;
  if (H5Fget_vfd_handle(file.id(), H5P_DEFAULT, reinterpret_cast<void**>(&fd)) < 0 || !fd) return -1;
  return *fd;
}

}  // namespace

// HDF5 allocates new space at the end of its allocated address space (EOA),
// so that is where the reservation starts; a reservation already there is
// reused, not repeated.
void reserve_space(const Handle& file, hsize_t bytes) {
  haddr_t eoa = 0;
  const int fd = descriptor(file);
  if (fd < 0 || H5Fget_eoa(file.id(), &eoa) < 0) return;
  const int err = posix_fallocate(fd, static_cast<off_t>(eoa), static_cast<off_t>(bytes));
  if (err == 0 || err == EOPNOTSUPP || err == EINVAL) return;
  throw Error("HDF5: reserve " + std::to_string(bytes) + " bytes", std::strerror(err));
}

void release_reserve(const Handle& file) {
  haddr_t eoa = 0;
  struct stat st {};
  const int fd = descriptor(file);
  if (fd < 0 || H5Fget_eoa(file.id(), &eoa) < 0 || fstat(fd, &st) != 0) return;
  if (static_cast<haddr_t>(st.st_size) > eoa && ftruncate(fd, static_cast<off_t>(eoa)) != 0)
    throw Error("HDF5: release reserved space", std::strerror(errno));
}

void flush(const Handle& file) { check_status(H5Fflush(file.id(), H5F_SCOPE_GLOBAL), "flush"); }

namespace {

// Makes the file at least `end` bytes long, with disk blocks where the file
// system can reserve them; returns errno or 0.
int grow_file(int fd, off_t end) {
  struct stat st {};
  if (fstat(fd, &st) != 0) return errno;
  if (st.st_size >= end) return 0;
  const int err = posix_fallocate(fd, st.st_size, end - st.st_size);
  if (err != EOPNOTSUPP && err != EINVAL) return err;
  return ftruncate(fd, end) == 0 ? 0 : errno;
}

}  // namespace

// The file grows first: HDF5 writes the new end into the superblock at its
// next flush, also the one of a close after an error.
void extend_allocation_past_file_end(const Handle& file, hsize_t margin) {
  haddr_t eoa = 0;
  struct stat st {};
  const int fd = descriptor(file);
  if (fd >= 0 && H5Fget_eoa(file.id(), &eoa) >= 0 && fstat(fd, &st) == 0) {
    const haddr_t end = std::max<haddr_t>(eoa, static_cast<haddr_t>(st.st_size)) + margin;
    if (const int err = grow_file(fd, static_cast<off_t>(end)); err != 0)
      throw Error("HDF5: extend the file to its allocation", std::strerror(err));
  }
  check_status(H5Fincrement_filesize(file.id(), margin), "extend the allocation to the file's end");
}

bool cover_recorded_allocation(const std::string& path) {
  // Superblock version 2/3: signature (8), version, sizes of offsets and
  // lengths, flags, then base address, extension address, end of file
  // address (8 bytes each, little-endian) at byte 28.
  const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  if (fd < 0) return false;
  unsigned char sb[36] = {};
  bool grew = false;
  if (pread(fd, sb, sizeof sb, 0) == static_cast<ssize_t>(sizeof sb) &&
      std::memcmp(sb, "\x89HDF\r\n\x1a\n", 8) == 0 && (sb[8] == 2 || sb[8] == 3) && sb[9] == 8) {
    std::uint64_t end = 0;
    for (int i = 7; i >= 0; --i) end = (end << 8) | sb[28 + i];
    struct stat st {};
    if (fstat(fd, &st) == 0 && end > static_cast<std::uint64_t>(st.st_size) && end < (std::uint64_t{1} << 62)) {
      const int err = grow_file(fd, static_cast<off_t>(end));
      if (err == 0 && fsync(fd) == 0) {
        grew = true;
      } else {
        ::close(fd);
        throw Error("HDF5: grow '" + path + "' to its recorded size", std::strerror(err ? err : errno));
      }
    }
  }
  ::close(fd);
  return grew;
}

hsize_t chunk_bytes(hid_t dataset) {
  Handle plist(check(H5Dget_create_plist(dataset), "dataset creation properties"));
  if (H5Pget_layout(plist.id()) != H5D_CHUNKED) return 0;
  Handle space(check(H5Dget_space(dataset), "dataspace"));
  const int rank = H5Sget_simple_extent_ndims(space.id());
  std::vector<hsize_t> dims(rank > 0 ? std::size_t(rank) : 1);
  check_status(H5Pget_chunk(plist.id(), rank, dims.data()), "chunk dimensions");
  Handle type(check(H5Dget_type(dataset), "datatype"));
  hsize_t bytes = H5Tget_size(type.id());
  for (int i = 0; i < rank; ++i) bytes *= dims[std::size_t(i)];
  return bytes;
}

namespace {

// What `path` is (H5I_GROUP, H5I_DATASET, ...), for a link known to exist;
// H5I_BADID if its object header cannot be read.
H5I_type_t object_type(hid_t loc, const std::string& path) {
  Handle o(H5Oopen(loc, path.c_str(), H5P_DEFAULT));
  return o.valid() ? H5Iget_type(o.id()) : H5I_BADID;
}

// Opens the existing `path` as a `want` (H5I_GROUP or H5I_DATASET) with
// `open`: a missing path, an object of the other kind and a damaged object
// are InputErrors naming the file and the path.
Handle open_object(hid_t loc, const std::string& path, H5I_type_t want, hid_t (*open)(hid_t, const char*, hid_t)) {
  const std::string kind = want == H5I_GROUP ? "group" : "dataset";
  if (!exists(loc, path)) throw InputError("'" + file_of(loc) + "': missing " + kind + " '" + path + "'");
  const hid_t id = open(loc, path.c_str(), H5P_DEFAULT);
  if (id >= 0) return Handle(id);
  const H5I_type_t found = object_type(loc, path);
  if (found == H5I_GROUP || found == H5I_DATASET)
    throw InputError("'" + file_of(loc) + "': '" + path + "' is a " + (found == H5I_GROUP ? "group" : "dataset") +
                     ", not a " + kind);
  fail_reading(loc, "open " + kind + " '" + path + "'");
}

}  // namespace

bool exists(hid_t loc, const std::string& path) {
  std::size_t pos = 0;
  while (true) {
    pos = path.find('/', pos + 1);
    const std::string prefix = path.substr(0, pos);
    if (!prefix.empty()) {
      const htri_t found = H5Lexists(loc, prefix.c_str(), H5P_DEFAULT);
      if (found == 0) return false;
      if (found < 0) {
        // Not found because the parent is no group (a dataset), or because
        // the parent's links cannot be read: the file is damaged.
        const std::size_t slash = prefix.find_last_of('/');
        const std::string parent = slash == std::string::npos ? "." : slash == 0 ? "/" : prefix.substr(0, slash);
        const H5I_type_t type = object_type(loc, parent);
        if (type == H5I_GROUP || type == H5I_BADID) fail_reading(loc, "look up '" + prefix + "'");
        return false;
      }
    }
    if (pos == std::string::npos) return true;
  }
}

Handle open_group(hid_t loc, const std::string& path) { return open_object(loc, path, H5I_GROUP, H5Gopen2); }

Handle create_group(hid_t loc, const std::string& path) {
  Handle lcpl(check(H5Pcreate(H5P_LINK_CREATE), "link property list"));
  H5Pset_create_intermediate_group(lcpl.id(), 1);
  return Handle(check(H5Gcreate2(loc, path.c_str(), lcpl.id(), H5P_DEFAULT, H5P_DEFAULT),
                      "create group '" + path + "'"));
}

Handle open_dataset(hid_t loc, const std::string& path) { return open_object(loc, path, H5I_DATASET, H5Dopen2); }

void write_attr(hid_t obj, const std::string& name, const std::string& value) {
  Handle type = vlen_string_type();
  Handle space(check(H5Screate(H5S_SCALAR), "scalar space"));
  Handle a = replace_attr(obj, name, type.id(), space.id());
  const char* p = value.c_str();
  check_status(H5Awrite(a.id(), type.id(), &p), "write attribute '" + name + "'");
}

void write_attr(hid_t obj, const std::string& name, const std::vector<std::string>& values) {
  Handle type = vlen_string_type();
  const hsize_t n = values.size();
  Handle space(check(H5Screate_simple(1, &n, nullptr), "string array space"));
  Handle a = replace_attr(obj, name, type.id(), space.id());
  std::vector<const char*> ptrs;
  for (const auto& v : values) ptrs.push_back(v.c_str());
  check_status(H5Awrite(a.id(), type.id(), ptrs.data()), "write attribute '" + name + "'");
}

void write_attr(hid_t obj, const std::string& name, double value) {
  Handle space(check(H5Screate(H5S_SCALAR), "scalar space"));
  Handle a = replace_attr(obj, name, H5T_IEEE_F64LE, space.id());
  check_status(H5Awrite(a.id(), H5T_NATIVE_DOUBLE, &value), "write attribute '" + name + "'");
}

void write_attr(hid_t obj, const std::string& name, std::int64_t value) {
  Handle space(check(H5Screate(H5S_SCALAR), "scalar space"));
  Handle a = replace_attr(obj, name, H5T_STD_I64LE, space.id());
  check_status(H5Awrite(a.id(), H5T_NATIVE_INT64, &value), "write attribute '" + name + "'");
}

void write_attr(hid_t obj, const std::string& name, const std::vector<std::int32_t>& values) {
  const hsize_t n = values.size();
  Handle space(check(H5Screate_simple(1, &n, nullptr), "int array space"));
  Handle a = replace_attr(obj, name, H5T_STD_I32LE, space.id());
  check_status(H5Awrite(a.id(), H5T_NATIVE_INT32, values.data()), "write attribute '" + name + "'");
}

void write_attr(hid_t obj, const std::string& name, const std::vector<double>& values) {
  const hsize_t n = values.size();
  Handle space(check(H5Screate_simple(1, &n, nullptr), "float array space"));
  Handle a = replace_attr(obj, name, H5T_IEEE_F64LE, space.id());
  check_status(H5Awrite(a.id(), H5T_NATIVE_DOUBLE, values.data()), "write attribute '" + name + "'");
}

bool has_attr(hid_t obj, const std::string& name) {
  const htri_t found = H5Aexists(obj, name.c_str());
  if (found < 0) fail_reading(obj, "look up " + attr_text(obj, name));  // a damaged attribute table is not "missing"
  return found > 0;
}

namespace {

// An open attribute with its type and the number of values it holds.
struct OpenAttr {
  Handle attr, type;
  hssize_t count = 0;
  H5T_class_t cls = H5T_NO_CLASS;
};

OpenAttr open_attr_typed(hid_t obj, const std::string& name) {
  OpenAttr a{open_attr(obj, name), {}, 0, H5T_NO_CLASS};
  const std::string what = attr_text(obj, name);
  a.type = Handle(check_reading(H5Aget_type(a.attr.id()), obj, "read the type of " + what));
  Handle space(check_reading(H5Aget_space(a.attr.id()), obj, "read the shape of " + what));
  a.count = H5Sget_simple_extent_npoints(space.id());
  if (a.count < 0) fail_reading(obj, "read the shape of " + what);
  a.cls = H5Tget_class(a.type.id());
  return a;
}

// Up to `most` values of a numeric attribute as text ("2", "2.5", "[2, 2]",
// "[1, 2, 3, … (10 values)]"), for messages.
std::string numbers_text(const OpenAttr& a, hid_t obj, const std::string& name, std::size_t most = 4) {
  std::vector<double> v(static_cast<std::size_t>(a.count));
  if (a.count == 0) return "[] (no value)";
  if (H5Aread(a.attr.id(), H5T_NATIVE_DOUBLE, v.data()) < 0) fail_reading(obj, "read " + attr_text(obj, name));
  std::string s;
  for (std::size_t k = 0; k < std::min(most, v.size()); ++k) {
    char b[32];
    std::snprintf(b, sizeof b, "%.17g", v[k]);
    std::string x = b;
    if (a.cls == H5T_FLOAT && x.find_first_not_of("-0123456789") == std::string::npos) x += ".0";
    s += (k ? ", " : "") + x;
  }
  if (v.size() == 1) return s;
  if (v.size() > most) s += ", … (" + std::to_string(v.size()) + " values)";
  return "[" + s + "]";
}

// What a non-numeric attribute holds, for messages: its strings, or its class.
std::string other_text(const OpenAttr& a, hid_t obj, const std::string& name) {
  if (a.cls != H5T_STRING) return "not a number (HDF5 type class " + std::to_string(int(a.cls)) + ")";
  const std::vector<std::string> v = read_attr_strings(obj, name);
  std::string s;
  for (std::size_t k = 0; k < std::min<std::size_t>(v.size(), 4); ++k) s += (k ? ", " : "") + ("'" + shown(v[k]) + "'");
  return "the string " + (v.size() == 1 ? s : "array [" + s + (v.size() > 4 ? ", …" : "") + "]");
}

// The attribute opened for reading one number: a scalar or a one-element
// array of an integer class (or, unless `integer`, a float class). Anything
// else (an array, a string, 2.5 for an integer) is an InputError naming the
// file, the object, the attribute and what it holds: never a read of several
// values into one.
OpenAttr open_one_number(hid_t obj, const std::string& name, bool integer) {
  OpenAttr a = open_attr_typed(obj, name);
  const bool number = a.cls == H5T_INTEGER || a.cls == H5T_FLOAT;
  const bool right_class = a.cls == H5T_INTEGER || (!integer && a.cls == H5T_FLOAT);
  if (right_class && a.count == 1) return a;
  throw InputError("'" + file_of(obj) + "': " + attr_text(obj, name) + " is " +
                   (number ? numbers_text(a, obj, name) : other_text(a, obj, name)) + "; expected one " +
                   (integer ? "integer" : "number"));
}

// The attribute opened for reading one string (a scalar or a one-element array).
OpenAttr open_one_string(hid_t obj, const std::string& name) {
  OpenAttr a = open_attr_typed(obj, name);
  if (a.cls != H5T_STRING)
    throw InputError("'" + file_of(obj) + "': " + attr_text(obj, name) + " is " +
                     (a.cls == H5T_INTEGER || a.cls == H5T_FLOAT ? numbers_text(a, obj, name) : other_text(a, obj, name)) +
                     "; expected a string");
  if (a.count != 1)
    throw InputError("'" + file_of(obj) + "': " + attr_text(obj, name) + " holds " + std::to_string(a.count) +
                     " strings; expected one");
  return a;
}

}  // namespace

H5T_class_t attr_class(hid_t obj, const std::string& name) { return open_attr_typed(obj, name).cls; }

std::string read_attr_string(hid_t obj, const std::string& name) {
  const OpenAttr a = open_one_string(obj, name);
  const std::string what = "read " + attr_text(obj, name);
  if (H5Tis_variable_str(a.type.id()) > 0) {
    Handle type = vlen_string_type_like(a.type.id());
    char* p = nullptr;
    if (H5Aread(a.attr.id(), type.id(), &p) < 0) fail_reading(obj, what);
    std::string s = p ? p : "";
    H5free_memory(p);
    return s;
  }
  const std::size_t n = H5Tget_size(a.type.id());
  std::string s(n, '\0');
  if (H5Aread(a.attr.id(), a.type.id(), s.data()) < 0) fail_reading(obj, what);
  s.erase(s.find_last_not_of('\0') + 1);
  return s;
}

std::vector<std::string> read_attr_strings(hid_t obj, const std::string& name) {
  const OpenAttr a = open_attr_typed(obj, name);
  if (a.cls != H5T_STRING)
    throw InputError("'" + file_of(obj) + "': " + attr_text(obj, name) + " is not a string");
  const std::string what = "read " + attr_text(obj, name);
  const auto n = static_cast<std::size_t>(a.count);
  std::vector<std::string> out;
  if (H5Tis_variable_str(a.type.id()) > 0) {
    Handle type = vlen_string_type_like(a.type.id());
    Handle space(check_reading(H5Aget_space(a.attr.id()), obj, what));
    std::vector<char*> p(n, nullptr);
    if (H5Aread(a.attr.id(), type.id(), p.data()) < 0) fail_reading(obj, what);
    for (char* c : p) out.emplace_back(c ? c : "");
    H5Dvlen_reclaim(type.id(), space.id(), H5P_DEFAULT, p.data());
    return out;
  }
  const std::size_t size = H5Tget_size(a.type.id());
  std::string buf(size * n, '\0');
  if (H5Aread(a.attr.id(), a.type.id(), buf.data()) < 0) fail_reading(obj, what);
  for (std::size_t i = 0; i < n; ++i) {
    std::string s = buf.substr(i * size, size);
    out.push_back(s.erase(s.find_last_not_of('\0') + 1));
  }
  return out;
}

std::vector<double> read_attr_doubles(hid_t obj, const std::string& name, std::size_t most) {
  const OpenAttr a = open_attr_typed(obj, name);
  Handle space(check_reading(H5Aget_space(a.attr.id()), obj, "read the shape of " + attr_text(obj, name)));
  const bool number = a.cls == H5T_INTEGER || a.cls == H5T_FLOAT;
  if (!number || H5Sget_simple_extent_ndims(space.id()) != 1 || a.count < 1 || std::size_t(a.count) > most)
    throw InputError("'" + file_of(obj) + "': " + attr_text(obj, name) + " is " +
                     (number ? numbers_text(a, obj, name) : other_text(a, obj, name)) + "; expected an array of 1 to " +
                     std::to_string(most) + " numbers");
  std::vector<double> v(static_cast<std::size_t>(a.count));
  if (H5Aread(a.attr.id(), H5T_NATIVE_DOUBLE, v.data()) < 0) fail_reading(obj, "read " + attr_text(obj, name));
  return v;
}

bool is_group(hid_t loc, const std::string& path) {
  const H5I_type_t type = object_type(loc, path);
  if (type == H5I_BADID) fail_reading(loc, "open '" + path + "'");
  return type == H5I_GROUP;
}

double read_attr_double(hid_t obj, const std::string& name) {
  const OpenAttr a = open_one_number(obj, name, false);
  double v = 0;
  if (H5Aread(a.attr.id(), H5T_NATIVE_DOUBLE, &v) < 0) fail_reading(obj, "read " + attr_text(obj, name));
  return v;
}

std::int64_t read_attr_int(hid_t obj, const std::string& name) {
  const OpenAttr a = open_one_number(obj, name, true);
  std::int64_t v = 0;
  if (H5Aread(a.attr.id(), H5T_NATIVE_INT64, &v) < 0) fail_reading(obj, "read " + attr_text(obj, name));
  return v;
}

std::vector<hsize_t> shape(hid_t dataset) {
  Handle space(check_reading(H5Dget_space(dataset), dataset, "read the shape of '" + name_of(dataset) + "'"));
  const int rank = H5Sget_simple_extent_ndims(space.id());
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr);
  return dims;
}

Handle create_series(hid_t loc, const std::string& name, Type type, const std::vector<hsize_t>& inner,
                     hsize_t chunk_rows, std::optional<std::int64_t> fill_value, const Storage& storage) {
  std::vector<hsize_t> dims{0}, maxdims{H5S_UNLIMITED}, chunk{chunk_rows};
  for (hsize_t d : inner) {
    dims.push_back(d);
    maxdims.push_back(d);
    chunk.push_back(d);
  }
  // A chunk may not exceed a fixed dimension, nor be empty.
  if (storage.chunk_inner > 0 && chunk.size() > 1) chunk[1] = std::clamp<hsize_t>(chunk[1], 1, storage.chunk_inner);
  for (hsize_t& c : chunk) c = std::max<hsize_t>(c, 1);
  Handle space(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), maxdims.data()), "series space"));
  Handle dcpl(check(H5Pcreate(H5P_DATASET_CREATE), "dataset property list"));
  check_status(H5Pset_chunk(dcpl.id(), static_cast<int>(chunk.size()), chunk.data()), "chunking");
  if (storage.deflate_level > 0) {
    check_status(H5Pset_shuffle(dcpl.id()), "shuffle filter");
    check_status(H5Pset_deflate(dcpl.id(), static_cast<unsigned>(storage.deflate_level)), "deflate filter");
  }
  if (fill_value) check_status(H5Pset_fill_value(dcpl.id(), H5T_NATIVE_INT64, &*fill_value), "fill value");
  return Handle(check(H5Dcreate2(loc, name.c_str(), file_type(type), space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT),
                      "create dataset '" + name + "'"));
}

void append_row(hid_t dataset, Type type, const void* data, hsize_t stride) {
  auto dims = shape(dataset);
  const hsize_t row = dims[0];
  dims[0] = row + 1;
  check_status(H5Dset_extent(dataset, dims.data()), "extend dataset");
  Handle fspace(check(H5Dget_space(dataset), "dataspace"));
  std::vector<hsize_t> start(dims.size(), 0), count = dims;
  start[0] = row;
  count[0] = 1;
  check_status(H5Sselect_hyperslab(fspace.id(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
               "select row");
  std::vector<hsize_t> mem_dims = count;
  if (stride > mem_dims.back()) mem_dims.back() = stride;  // memory rows are wider: select their first columns
  Handle mspace(check(H5Screate_simple(static_cast<int>(mem_dims.size()), mem_dims.data(), nullptr), "memory space"));
  if (mem_dims != count) {
    const std::vector<hsize_t> zero(count.size(), 0);
    check_status(H5Sselect_hyperslab(mspace.id(), H5S_SELECT_SET, zero.data(), nullptr, count.data(), nullptr),
                 "select columns");
  }
  check_status(H5Dwrite(dataset, mem_type(type), mspace.id(), fspace.id(), H5P_DEFAULT, data), "write row");
}

void resize_rows(hid_t dataset, hsize_t n) {
  auto dims = shape(dataset);
  dims[0] = n;
  check_status(H5Dset_extent(dataset, dims.data()), "resize dataset");
}

namespace {

// A read of stored values failed: a damaged chunk (its filter fails), bytes
// cut off or an I/O error. That is damaged input, named with its file and
// dataset, never an internal error.
void check_read(herr_t status, hid_t dataset, const std::string& rows) {
  if (status >= 0) return;
  const std::string cause = system_cause();
  throw InputError("'" + file_of(dataset) + "': dataset '" + name_of(dataset) + "' cannot be read" + rows + ": " +
                   (cause.empty() ? "its stored data is damaged (a corrupt chunk?)" : cause));
}

}  // namespace

void read_rows(hid_t dataset, Type type, hsize_t first, hsize_t count_rows, void* out) {
  auto dims = shape(dataset);
  if (dims.empty()) {  // scalar dataset
    check_read(H5Dread(dataset, mem_type(type), H5S_ALL, H5S_ALL, H5P_DEFAULT, out), dataset, "");
    return;
  }
  if (first + count_rows > dims[0]) throw InputError("dataset has fewer rows than requested");
  Handle fspace(check(H5Dget_space(dataset), "dataspace"));
  std::vector<hsize_t> start(dims.size(), 0), count = dims;
  start[0] = first;
  count[0] = count_rows;
  check_status(H5Sselect_hyperslab(fspace.id(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
               "select rows");
  Handle mspace(check(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr), "memory space"));
  check_read(H5Dread(dataset, mem_type(type), mspace.id(), fspace.id(), H5P_DEFAULT, out), dataset,
             count_rows == 1 ? " (row " + std::to_string(first) + ")"
                             : " (rows " + std::to_string(first) + " to " + std::to_string(first + count_rows - 1) + ")");
}

namespace {

// Dimensions [from, end) as "(a, b, c)" of the whole shape.
std::string shape_text(const std::vector<hsize_t>& dims) {
  std::string s = "(";
  for (std::size_t k = 0; k < dims.size(); ++k) s += (k ? ", " : "") + std::to_string(dims[k]);
  return s + ")";
}

}  // namespace

void check_read_fits(hid_t dataset, double values, std::size_t value_size, const std::string& what) {
  const double memory = usable_memory_bytes(), bytes = values * double(value_size);
  if (bytes > memory)
    throw InputError("'" + file_of(dataset) + "': dataset '" + name_of(dataset) + "' of shape " +
                     shape_text(shape(dataset)) + " would need " + bytes_text(bytes) + " to read" + what +
                     "; the memory available is " + bytes_text(memory) + " (a damaged file?)");
}

namespace {

// The values of dims[from..]: counted in double, as a damaged or hostile
// file may declare a shape whose product overflows; refused (InputError)
// when they would not fit in the memory available, before any allocation.
std::size_t values_to_read(hid_t dataset, const std::vector<hsize_t>& dims, std::size_t from, std::size_t value_size) {
  double n = 1;
  for (std::size_t k = from; k < dims.size(); ++k) n *= double(dims[k]);
  check_read_fits(dataset, n, value_size, from ? " one row" : "");
  return static_cast<std::size_t>(n);
}

}  // namespace

template <class T>
std::vector<T> read_all(hid_t dataset) {
  auto dims = shape(dataset);
  const std::size_t n = values_to_read(dataset, dims, 0, sizeof(T));
  std::vector<T> v(static_cast<std::size_t>(n));
  if (n == 0) return v;
  if (dims.empty()) {
    read_rows(dataset, type_of<T>(), 0, 1, v.data());
  } else {
    read_rows(dataset, type_of<T>(), 0, dims[0], v.data());
  }
  return v;
}

template <class T>
std::vector<T> read_row(hid_t dataset, hsize_t row) {
  auto dims = shape(dataset);
  std::vector<T> v(values_to_read(dataset, dims, 1, sizeof(T)));
  read_rows(dataset, type_of<T>(), row, 1, v.data());
  return v;
}

template std::vector<double> read_all<double>(hid_t);
template std::vector<std::int64_t> read_all<std::int64_t>(hid_t);
template std::vector<std::int32_t> read_all<std::int32_t>(hid_t);
template std::vector<double> read_row<double>(hid_t, hsize_t);
template std::vector<std::int64_t> read_row<std::int64_t>(hid_t, hsize_t);
template std::vector<std::int32_t> read_row<std::int32_t>(hid_t, hsize_t);

}  // namespace coolgas::h5
