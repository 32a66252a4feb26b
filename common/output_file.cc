#include "common/output_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>

#include "common/error.h"

namespace coolgas {

namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
  throw InputError("cannot write '" + path + "': " + why);
}

std::string folder_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

void check_name_length(const std::string& path, const std::string& folder) {
  if (path.size() + kTemporarySuffixChars >= PATH_MAX)
    refuse(path, "the path has " + std::to_string(path.size()) + " characters; the limit is " +
                     std::to_string(PATH_MAX - 1 - kTemporarySuffixChars));
  const std::string name = path.substr(path.find_last_of('/') + 1);
  long max = pathconf(folder.c_str(), _PC_NAME_MAX);
  if (max <= 0) max = NAME_MAX;
  if (name.size() + kTemporarySuffixChars > std::size_t(max))
    refuse(path, "the file name has " + std::to_string(name.size()) + " characters; the limit here is " +
                     std::to_string(max - long(kTemporarySuffixChars)));
}

void check_existing(const std::string& path, bool replace, const std::string& or_else) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) {
    if (errno == ENOENT) return;
    if (errno == ENOTDIR) refuse(path, "a folder on its path is a file");
    refuse(path, std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode)) refuse(path, "it is a directory; give a file name");
  if (!S_ISREG(st.st_mode))
    refuse(path, "it is not a regular file (a device, pipe or socket); only regular files are replaced");
  if (!replace)
    throw InputError("output '" + path + "' exists; pass --force to overwrite it" + (or_else.empty() ? "" : ", or " + or_else));
}

void check_folder(const std::string& path, const std::string& folder) {
  struct stat st {};
  if (stat(folder.c_str(), &st) != 0) refuse(path, "no directory '" + folder + "'");
  if (!S_ISDIR(st.st_mode)) refuse(path, "'" + folder + "' is not a directory");
  if (access(folder.c_str(), W_OK) != 0) refuse(path, "directory '" + folder + "' is not writable");
}

}  // namespace

void check_output_file(const std::string& path, bool replace, const std::string& or_else) {
  if (path.empty()) throw InputError("the output file name is empty");
  if (path.back() == '/') refuse(path, "it names a directory; give a file name");
  const std::string folder = folder_of(path);
  check_folder(path, folder);
  check_name_length(path, folder);
  check_existing(path, replace, or_else);
}

}  // namespace coolgas
