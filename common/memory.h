// The machine's memory, against which sizes read from a scene or a file are
// checked before anything is allocated for them: an absurd size is refused
// with one line naming it, never met by "out of memory" or the kernel's
// out-of-memory killer.
#pragma once
#include <string>

namespace coolgas {

// Physical memory in bytes (infinity if the system does not tell).
double physical_memory_bytes();

// The memory this process may use: the physical memory, or less when the
// process is limited: an address-space limit (ulimit -v, RLIMIT_AS) or its
// cgroup's memory.max (a batch job's or a container's share). What a giant
// request is refused against when the limit, not the machine, decides
// whether it can be allocated.
double usable_memory_bytes();

// Bytes with a decimal unit and three significant digits: "180 TB".
std::string bytes_text(double bytes);

}  // namespace coolgas
