#include "simulate/run/checkpoint.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "common/durable_file.h"
#include "common/error.h"
#include "common/fault_point.h"
#include "common/memory.h"
#include "common/tsv.h"
#include "simulate/engine/state_archive.h"
#include "simulate/run/engine_factory.h"

namespace coolgas {

namespace {

std::vector<char> bytes_of(const std::string& s) { return {s.begin(), s.end()}; }

// A checkpoint that cannot be written (disk full, quota, I/O error) is a
// failed write of the run's output: WriteError, exit code 5, like the
// trajectory's own. `error` is the errno of the failure, taken before the
// clean-up calls that may change it.
[[noreturn]] void fail_io(const std::string& what, const std::string& path, int error) {
  throw WriteError("cannot write checkpoint '" + path + "': " + what + " (" + std::strerror(error) +
                   "); the previous checkpoint is kept");
}

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
  throw InputError("cannot resume from checkpoint '" + path + "': " + why +
                   " (remove it to resume from the last dump)");
}

// The checkpoint's bytes, or nothing when there is none. Only a regular file
// is read: a device (a link to /dev/zero) would be read without end, a
// directory fails inside the stream. Its size is checked against the memory
// before the bytes are allocated; the sections inside are checked against
// the size by StateReader.
std::optional<std::vector<char>> checkpoint_bytes(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno == ENOENT) return std::nullopt;
    refuse(path, std::strerror(errno));
  }
  if (!S_ISREG(st.st_mode)) refuse(path, "it is not a regular file (a directory, device, pipe or socket)");
  const double memory = usable_memory_bytes();
  if (double(st.st_size) > memory)
    refuse(path, "its " + bytes_text(double(st.st_size)) + " do not fit in the memory available (" + bytes_text(memory) + ")");
  std::ifstream f(path, std::ios::binary);
  std::vector<char> bytes(static_cast<std::size_t>(st.st_size));
  if (!f || !f.read(bytes.data(), std::streamsize(bytes.size())) || f.peek() != std::ifstream::traits_type::eof())
    refuse(path, "it cannot be read whole (it changed while being read, or a read failed)");
  return bytes;
}

// The run's times beside the engine's: the last dump and the pending rows
// lie in [0, now], the rows in order after the dump, their values finite (a
// forged checkpoint would otherwise write them into the trajectory).
void check_run_times(const StateReader& in, const RunCheckpoint& c) {
  const double now = c.engine->now();
  if (!(std::isfinite(c.last_dump) && c.last_dump >= 0 && c.last_dump <= now))
    in.fail("run/last_dump = " + format_number(c.last_dump) + "; must be finite and in [0, now = " +
            format_number(now) + "]");
  double previous = c.last_dump;
  for (std::size_t k = 0; k < c.pending.size(); ++k) {
    const ObservableRow& r = c.pending[k];
    const bool finite = std::isfinite(r.kinetic_energy) && std::isfinite(r.momentum[0]) &&
                        std::isfinite(r.momentum[1]) && std::isfinite(r.momentum[2]) && std::isfinite(r.mean_mass) &&
                        std::isfinite(r.largest_mass);
    if (!(std::isfinite(r.time) && r.time >= previous && r.time <= now) || !finite || r.collisions < 0 ||
        r.below_delta < 0 || r.aggregates < 0)
      in.fail("run/pending_observables[" + std::to_string(k) + "] at t = " + format_number(r.time) +
              ": times must not decrease from the last dump (t = " + format_number(c.last_dump) + ") up to now = " +
              format_number(now) + ", values be finite and counts >= 0");
    previous = r.time;
  }
}

}  // namespace

std::string checkpoint_path(const std::string& trajectory) { return trajectory + ".checkpoint"; }

void write_checkpoint(const std::string& trajectory, const Scene& scene, const EngineBase& engine, double last_dump,
                      const std::vector<ObservableRow>& pending) {
  const std::string path = checkpoint_path(trajectory), tmp = path + ".partial";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) fail_io("cannot create '" + tmp + "'", path, errno);
  try {
    StateWriter out(f);
    out.put("run/physics", bytes_of(physics_toml(scene)));
    out.put("run/model", bytes_of(scene.model_name()));
    out.put_value("run/last_dump", last_dump);
    out.put("run/pending_observables", pending);
    engine.save(out);
    fault_point(FaultPoint::kCheckpointWrite);
    out.finish();
  } catch (const std::exception&) {
    const int error = errno;
    std::fclose(f);
    std::remove(tmp.c_str());
    fail_io("a write failed", path, error);
  }
  const bool synced = ::fsync(fileno(f)) == 0;
  int error = errno;
  const bool closed = std::fclose(f) == 0;
  if (!closed) error = errno;
  if (!closed || !synced) {
    std::remove(tmp.c_str());
    fail_io("flushing to disk failed", path, error);
  }
  fault_point(FaultPoint::kCheckpointRename);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    error = errno;
    std::remove(tmp.c_str());
    fail_io("renaming into place failed", path, error);
  }
  const auto dir = std::filesystem::path(path).parent_path();
  sync_directory(dir.empty() ? "." : dir.string());
}

std::optional<RunCheckpoint> read_checkpoint(const std::string& trajectory, const Scene& scene) {
  const std::string path = checkpoint_path(trajectory);
  std::optional<std::vector<char>> bytes = checkpoint_bytes(path);
  if (!bytes) return std::nullopt;
  const StateReader in(std::move(*bytes), path);
  const auto physics = in.get<char>("run/physics");
  if (std::string(physics.begin(), physics.end()) != physics_toml(scene))
    in.fail("it belongs to a run of other physics than '" + trajectory + "' (remove it to resume from the last dump)");
  RunCheckpoint c;
  c.last_dump = in.get_value<double>("run/last_dump");
  c.pending = in.get<ObservableRow>("run/pending_observables");
  c.engine = restore_engine(scene, in);
  check_run_times(in, c);
  return c;
}

void remove_checkpoint(const std::string& trajectory) {
  std::error_code ignored;
  std::filesystem::remove(checkpoint_path(trajectory), ignored);
}

}  // namespace coolgas
