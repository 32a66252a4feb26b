// One writer per trajectory. HDF5 drops its own file lock once SWMR writing
// starts, and a resumed run clears the flags a killed writer leaves, so
// nothing in HDF5 stops a second --resume of a file that is still being
// written; this lock does. It is an open-file-description record lock
// (fcntl F_OFD_SETLK, Linux): the kernel releases it when its descriptor is
// closed or the process ends however it ends, and, unlike a classic POSIX
// record lock, not when the process closes another descriptor of the same
// file (as every HDF5 open and close of it does). Neither HDF5's own flock
// nor any reader takes it, so readers are never blocked. A process takes it
// once per file: a second take, even in the same process, is refused.
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
  explicit operator bool() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace coolgas
