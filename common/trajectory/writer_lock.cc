#include "common/trajectory/writer_lock.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "common/error.h"

namespace coolgas {

WriterLock WriterLock::take(const std::string& path) {
  WriterLock lock;
  lock.fd_ = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  if (lock.fd_ < 0) throw InputError("cannot open '" + path + "' to append: " + std::strerror(errno));
  struct flock whole {};
  whole.l_type = F_WRLCK;
  whole.l_whence = SEEK_SET;  // l_start = l_len = 0 (the whole file), l_pid = 0 (as OFD locks need)
  if (fcntl(lock.fd_, F_OFD_SETLK, &whole) != 0) {
    if (errno == EACCES || errno == EAGAIN)
      throw InputError("'" + path + "' is being written by another coolgas-simulate; let it finish (or stop it) first");
    throw InputError("cannot lock '" + path + "' for writing: " + std::strerror(errno));
  }
  return lock;
}

// The lock belongs to this descriptor alone (an OFD lock): HDF5 and the
// readers of this process open and close the file freely meanwhile.
WriterLock::~WriterLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace coolgas
