// The memory available, against which every size read from a scene, a file
// or an option is checked before anything is allocated for it: an absurd
// size is refused with one line naming it and "the memory available is
// ...", never met by "out of memory" or the kernel's out-of-memory killer.
// One limit for every check, so that a size is accepted or refused alike
// wherever it comes from.
#pragma once
#include <string>

namespace coolgas {

// The memory this process may use: the physical memory, or less when the
// process is limited: an address-space limit (ulimit -v, RLIMIT_AS) or its
// cgroup's memory.max (a batch job's or a container's share). Infinity if
// the system tells none of them.
double usable_memory_bytes();

// Bytes with a decimal unit and three significant digits: "180 TB".
std::string bytes_text(double bytes);

}  // namespace coolgas
