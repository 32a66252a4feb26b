// The exact state of an engine as named arrays of plain records, written
// and read back byte for byte (checkpoints). The byte layout of the file
// that holds them is data-schema/h5md-profile.md, "Checkpoint files".
//
// An engine writes every field its future depends on (positions, own times,
// counters, internal order, cell lists, the calendar's internals) and reads
// them back in a constructor of its own; nothing is recomputed, so a restored
// engine replays the same events by construction.
#pragma once
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace coolgas {

class StateWriter {
 public:
  // Appends to `file` (opened for writing by the caller), hashing as it goes.
  explicit StateWriter(std::FILE* file);
  // One section: `count` elements of `element_size` bytes each.
  void write(const std::string& name, const void* data, std::size_t element_size, std::size_t count);
  template <class T>
  void put(const std::string& name, const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    write(name, v.data(), sizeof(T), v.size());
  }
  template <class T>
  void put_value(const std::string& name, const T& x) {
    static_assert(std::is_trivially_copyable_v<T>);
    write(name, &x, sizeof(T), 1);
  }
  // Writes the trailer (the hash of everything before it). Throws
  // std::runtime_error if any write failed.
  void finish();

 private:
  void raw(const void* data, std::size_t bytes);
  std::FILE* file_;
  std::uint64_t hash_;
  bool failed_ = false;
};

class StateReader {
 public:
  // Parses a whole file's bytes; throws InputError naming `origin` if the
  // header, a section or the hash is wrong (a torn or foreign file).
  StateReader(std::vector<char> bytes, const std::string& origin);
  bool has(const std::string& name) const { return sections_.count(name) != 0; }
  // Throws InputError if the section is missing or of another element size.
  template <class T>
  std::vector<T> get(const std::string& name) const {
    const Section& s = section(name, sizeof(T));
    std::vector<T> v(s.count);
    if (s.count) std::memcpy(static_cast<void*>(v.data()), bytes_.data() + s.offset, s.count * sizeof(T));
    return v;
  }
  template <class T>
  T get_value(const std::string& name) const {
    const std::vector<T> v = get<T>(name);
    if (v.size() != 1) fail("section '" + name + "' holds " + std::to_string(v.size()) + " values, not 1");
    return v[0];
  }
  // The number of elements of a section (InputError if it is missing or of
  // another element size): a size is checked before anything is allocated.
  std::size_t count(const std::string& name, std::size_t element_size) const {
    return section(name, element_size).count;
  }
  // Throws InputError naming the file, with `what` as the reason.
  [[noreturn]] void fail(const std::string& what) const;

 private:
  struct Section {
    std::size_t offset, element_size, count;
  };
  const Section& section(const std::string& name, std::size_t element_size) const;
  std::vector<char> bytes_;
  std::string origin_;
  std::map<std::string, Section> sections_;
};

}  // namespace coolgas
