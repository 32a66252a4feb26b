// The scene of a small cooling run of hard disks (system.dimension = 2) for
// the command-line tests: 6000 disks at area fraction 0.3, inelastic, to
// t = 300; a test changes what it needs with --set.
#pragma once

namespace coolgas::test {

inline constexpr const char* kInelasticDisksToml = R"([system]
dimension = 2
N = 6000
phi = 0.3
seed = 5
equilibrate = 1
[collision]
model = "inelastic"
r0 = 0.5
delta = 1e-3
[run]
t_end = 300
[output]
dumps_per_decade = 10
)";

}  // namespace coolgas::test
