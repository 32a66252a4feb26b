#include "simulate/engine/state_archive.h"

#include <stdexcept>

#include "common/error.h"

namespace coolgas {

namespace {

// The file starts with these 16 bytes and the format version; a reader
// refuses anything else (another program's file, another byte order).
constexpr char kMagic[16] = {'c', 'o', 'o', 'l', 'g', 'a', 's', '-', 'c', 'k', 'p', 't', '\0', '\0', '\0', '\0'};
constexpr std::uint32_t kFormatVersion = 1;
constexpr std::uint32_t kByteOrderMark = 0x01020304;
constexpr char kTrailer[8] = {'e', 'n', 'd', '\0', '\0', '\0', '\0', '\0'};

// FNV-1a, 64 bit: detects a torn or damaged file (not an attacker).
constexpr std::uint64_t kFnvOffset = 14695981039346656037ull, kFnvPrime = 1099511628211ull;
std::uint64_t fnv1a(std::uint64_t h, const void* data, std::size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * kFnvPrime;
  return h;
}

}  // namespace

StateWriter::StateWriter(std::FILE* file) : file_(file), hash_(kFnvOffset) {
  raw(kMagic, sizeof kMagic);
  raw(&kFormatVersion, sizeof kFormatVersion);
  raw(&kByteOrderMark, sizeof kByteOrderMark);
}

void StateWriter::raw(const void* data, std::size_t bytes) {
  if (bytes == 0) return;
  hash_ = fnv1a(hash_, data, bytes);
  failed_ |= std::fwrite(data, 1, bytes, file_) != bytes;
}

void StateWriter::write(const std::string& name, const void* data, std::size_t element_size, std::size_t count) {
  const auto name_length = std::uint32_t(name.size());
  const std::uint64_t sizes[2] = {element_size, count};
  raw(&name_length, sizeof name_length);
  raw(name.data(), name.size());
  raw(sizes, sizeof sizes);
  raw(data, element_size * count);
}

void StateWriter::finish() {
  const std::uint64_t h = hash_;
  raw(kTrailer, sizeof kTrailer);
  failed_ |= std::fwrite(&h, 1, sizeof h, file_) != sizeof h;
  failed_ |= std::fflush(file_) != 0;
  if (failed_) throw std::runtime_error("writing the checkpoint failed");
}

StateReader::StateReader(std::vector<char> bytes, const std::string& origin)
    : bytes_(std::move(bytes)), origin_(origin) {
  std::size_t at = 0;
  auto take = [&](void* out, std::size_t n) {
    if (bytes_.size() - at < n) fail("it ends early (a torn write?)");
    std::memcpy(out, bytes_.data() + at, n);
    at += n;
  };
  char magic[16];
  std::uint32_t version = 0, mark = 0;
  take(magic, sizeof magic);
  take(&version, sizeof version);
  take(&mark, sizeof mark);
  if (std::memcmp(magic, kMagic, sizeof magic) != 0) fail("it is not a coolgas checkpoint");
  if (mark != kByteOrderMark) fail("it was written with another byte order");
  if (version != kFormatVersion)
    fail("format version " + std::to_string(version) + ", this program reads " + std::to_string(kFormatVersion));
  while (true) {
    if (bytes_.size() - at >= sizeof kTrailer + 8 && std::memcmp(bytes_.data() + at, kTrailer, sizeof kTrailer) == 0)
      break;
    std::uint32_t name_length = 0;
    take(&name_length, sizeof name_length);
    if (name_length > 256) fail("a section name of " + std::to_string(name_length) + " bytes");
    std::string name(name_length, '\0');
    take(name.data(), name_length);
    std::uint64_t sizes[2];
    take(sizes, sizeof sizes);
    if (sizes[0] == 0 || sizes[1] > (bytes_.size() - at) / sizes[0]) fail("section '" + name + "' ends early");
    sections_[name] = {at, std::size_t(sizes[0]), std::size_t(sizes[1])};
    at += std::size_t(sizes[0] * sizes[1]);
  }
  const std::uint64_t h = fnv1a(kFnvOffset, bytes_.data(), at);
  std::uint64_t stored = 0;
  at += sizeof kTrailer;
  take(&stored, sizeof stored);
  if (stored != h) fail("its hash does not match its contents (a damaged file)");
  if (at != bytes_.size()) fail("bytes follow its trailer");
}

void StateReader::fail(const std::string& what) const {
  throw InputError("cannot resume from checkpoint '" + origin_ + "': " + what);
}

const StateReader::Section& StateReader::section(const std::string& name, std::size_t element_size) const {
  const auto it = sections_.find(name);
  if (it == sections_.end()) fail("section '" + name + "' is missing");
  if (it->second.element_size != element_size)
    fail("section '" + name + "' has elements of " + std::to_string(it->second.element_size) + " bytes, not " +
         std::to_string(element_size));
  return it->second;
}

}  // namespace coolgas
