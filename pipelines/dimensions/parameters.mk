# The parameters of the dimension study (pipelines/dimensions/Makefile).
# Time in initial mean collision times; L in particle diameters. A model's
# value in dimension d is NAME_D<d>: GAS_L_D2 is the gas's box side in 2D.
# Each theta is fitted over WINDOW (TMIN:TMAX), which starts where E(t) has
# left Haff's law (gas) or the start-up (BA), and ends before the finite-size
# crossover t = 0.1 L^z, z = (d+2)/2 (the mean-field z: L^(5/2) in 3D, L^2
# in 2D, L^(3/2) in 1D); dimensions.tsv's regime column checks both ends.
SEEDS ?= 1 2 3

# The inelastic gas: the paper's strongly inelastic r0 = 0.1 with its
# cut-off delta = 1e-4 (elastic below that normal speed) in every
# dimension, at the paper's phi = 0.208 (the covered fraction).
GAS_R0_D1 := 0.1
GAS_R0_D2 := 0.1
GAS_R0_D3 := 0.1
GAS_DELTA_D1 := 1e-4
GAS_DELTA_D2 := 1e-4
GAS_DELTA_D3 := 1e-4
GAS_PHI_D1 := 0.208
GAS_PHI_D2 := 0.208
GAS_PHI_D3 := 0.208
# 3D: the demo's largest box (x = 0.1 at t = 3800); theta over the demo's window.
GAS_L_D3 := 68
GAS_T_END_D3 := 3000
GAS_WINDOW_D3 := 100:3000
# 2D: N = 23 835 disks (x = 0.1 at t = 9000); the local slope of E(t) is
# near 1 from t = 30 and falls below 0.9 after t = 2000, so the window ends there.
GAS_L_D2 := 300
GAS_T_END_D2 := 2000
GAS_WINDOW_D2 := 100:2000

# Ballistic aggregation at the same phi: spheres, disks or rods that merge
# on contact (volumes, areas, lengths add; momentum conserved). It has no
# Haff regime: E(t) falls as a power law once aggregates have met a few
# times (t ~ 10).
BA_PHI_D1 := 0.208
BA_PHI_D2 := 0.208
BA_PHI_D3 := 0.208
BA_L_D3 := 68
BA_T_END_D3 := 400
BA_WINDOW_D3 := 10:400
BA_L_D2 := 600
BA_T_END_D2 := 1000
BA_WINDOW_D2 := 10:1000
