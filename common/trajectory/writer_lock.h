// One writer per trajectory. HDF5 drops its own file lock once SWMR writing
// starts, and a resumed run clears the flags a killed writer leaves, so
// nothing in HDF5 stops a second --resume of a file that is still being
// written; this lock does. It is a POSIX record lock (fcntl), which the
// kernel releases when the process ends however it ends, and which neither
// HDF5's own flock nor any reader takes, so readers are never blocked.
#pragma once
#include <string>
#include <utility>

namespace coolgas {

class WriterLock {
 public:
  WriterLock() = default;
  // Locks `path` for writing; InputError if another process holds the lock.
  static WriterLock take(const std::string& path);
  WriterLock(WriterLock&& o) noexcept : fd_(std::exchange(o.fd_, -1)) {}
  WriterLock& operator=(WriterLock&& o) noexcept {
    std::swap(fd_, o.fd_);
    return *this;
  }
  WriterLock(const WriterLock&) = delete;
  WriterLock& operator=(const WriterLock&) = delete;
  ~WriterLock();

 private:
  int fd_ = -1;
};

}  // namespace coolgas
