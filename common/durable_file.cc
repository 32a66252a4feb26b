#include "common/durable_file.h"

#include <fcntl.h>
#include <sys/statvfs.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "common/error.h"
#include "common/fault_point.h"
#include "common/interrupt.h"

namespace coolgas {

namespace {

// Copied in pieces of this size, so a signal is noticed within a fraction
// of a second.
constexpr std::size_t kPieceBytes = std::size_t{64} << 20;

// Closes a descriptor when it goes out of scope.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

[[noreturn]] void fail(const std::string& to, const std::string& what, int err) {
  std::error_code ignored;
  std::filesystem::remove(to, ignored);
  throw WriteError("cannot write '" + to + "': " + what + (err ? std::string(": ") + std::strerror(err) : ""));
}

std::string parent_folder(const std::string& path) {
  const auto dir = std::filesystem::path(path).parent_path();
  return dir.empty() ? "." : dir.string();
}

// Bytes the file system still gives an unprivileged writer in `dir`, or -1
// where it cannot tell.
double bytes_free(const std::string& dir) {
  struct statvfs s {};
  if (::statvfs(dir.c_str(), &s) != 0) return -1;
  return double(s.f_bavail) * double(s.f_frsize);
}

// One piece: copy_file_range (in the kernel, no bytes through this process),
// else read and write.
ssize_t copy_piece(int in, int out, char* buffer) {
  const ssize_t n = ::copy_file_range(in, nullptr, out, nullptr, kPieceBytes, 0);
  if (n >= 0 || (errno != EXDEV && errno != ENOSYS && errno != EOPNOTSUPP && errno != EINVAL)) return n;
  const ssize_t got = ::read(in, buffer, kPieceBytes);
  if (got <= 0) return got;
  for (ssize_t done = 0; done < got;) {
    const ssize_t put = ::write(out, buffer + done, std::size_t(got - done));
    if (put < 0) return -1;
    done += put;
  }
  return got;
}

}  // namespace

void copy_file_durably(const std::string& from, const std::string& to) {
  Fd in{::open(from.c_str(), O_RDONLY | O_CLOEXEC)};
  if (in.fd < 0) throw InputError("cannot read '" + from + "': " + std::strerror(errno));
  struct stat st {};
  if (::fstat(in.fd, &st) != 0) throw InputError("cannot read '" + from + "': " + std::strerror(errno));
  const double room = bytes_free(parent_folder(to));
  if (room >= 0 && room < double(st.st_size))
    throw WriteError("cannot write '" + to + "': a copy of '" + from + "' needs " + std::to_string(st.st_size >> 20) +
                     " MB and the disk has " + std::to_string(std::int64_t(room) >> 20) + " MB free");
  Fd out{::open(to.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644)};
  if (out.fd < 0) throw WriteError("cannot create '" + to + "': " + std::strerror(errno));
  std::string buffer;
  for (off_t copied = 0; copied < st.st_size;) {
    if (interrupted()) {
      std::filesystem::remove(to);
      throw_if_interrupted("while copying the trajectory; it is unchanged");
    }
    if (buffer.empty()) buffer.resize(kPieceBytes);
    const ssize_t n = copy_piece(in.fd, out.fd, buffer.data());
    if (n < 0) fail(to, "copying '" + from + "'", errno);
    if (n == 0) fail(to, "'" + from + "' ended while being copied", 0);
    copied += n;
  }
  if (::fsync(out.fd) != 0) fail(to, "flushing to disk", errno);
}

void sync_file(const std::string& path) {
  Fd fd{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (fd.fd < 0 || ::fsync(fd.fd) != 0) throw WriteError("cannot write '" + path + "': flushing to disk: " + std::strerror(errno));
}

void sync_directory(const std::string& dir) {
  Fd fd{::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)};
  if (fd.fd >= 0) ::fsync(fd.fd);
}

void replace_file(const std::string& from, const std::string& to) {
  fault_point(FaultPoint::kReplaceRename);
  if (std::rename(from.c_str(), to.c_str()) != 0) fail(from, "moving it to '" + to + "'", errno);
  sync_directory(parent_folder(to));
}

}  // namespace coolgas
