# The parameters of the dimension study (pipelines/dimensions/Makefile).
# Time in initial mean collision times; L in particle diameters. A model's
# value in dimension d is NAME_D<d>: GAS_L_D2 is the gas's box side in 2D.
# Each theta is fitted over WINDOW (TMIN:TMAX), which starts where E(t) has
# left Haff's law (gas) or the start-up (BA), and ends before the finite-size
# crossover t = 0.1 L^z, z = (d+2)/2 (the mean-field z: L^(5/2) in 3D, L^2
# in 2D, L^(3/2) in 1D); dimensions.tsv's regime column checks both ends.
SEEDS ?= 1 2 3

# The inelastic gas: the paper's strongly inelastic r0 = 0.1 with its
# cut-off delta = 1e-4 (elastic below that normal speed) in 2D and 3D, at
# the paper's phi = 0.208 (the covered fraction). In 1D, Ben-Naim et al.'s
# r0 = 0.9 and cut-off 0.01 (PRL 83, 4069 (1999)): rods of r0 = 0.1 form
# clusters that collide so often that a run to t = 1000 would take
# 10^10 collisions (coolgas-simulate --estimate), and at r0 = 0.9 the
# cut-off 1e-4 lets a cluster collapse (t = 389 in L = 1e5); E(t) is the
# same with 1e-3 and 1e-2 up to t = 1000, and 1e-2 costs 7 times less.
GAS_R0_D1 := 0.9
GAS_R0_D2 := 0.1
GAS_R0_D3 := 0.1
GAS_DELTA_D1 := 1e-2
GAS_DELTA_D2 := 1e-4
GAS_DELTA_D3 := 1e-4
GAS_PHI_D1 := 0.208
GAS_PHI_D2 := 0.208
GAS_PHI_D3 := 0.208
# 1D: N = 20 800 rods on a ring of 1e5 (x = 0.1 at t = 3e6). E(t)'s local
# slope peaks (1.17) at t ~ 30 and reaches 2/3 by t ~ 200; the window
# starts a decade after the peak.
GAS_L_D1 := 100000
GAS_T_END_D1 := 10000
GAS_WINDOW_D1 := 300:10000
# 3D: N = 397 251 spheres, to the finite-size crossover (x = 0.1 at
# t = 10 000), from t = 100, where the gas has left Haff's law.
GAS_L_D3 := 100
GAS_T_END_D3 := 10000
GAS_WINDOW_D3 := 100:10000
# 2D: N = 95 340 disks (x = 0.1 at t = 36 000). E(t)'s local slope peaks
# (1.12) at t ~ 30 and settles near 0.95 by t ~ 300; the window ends at
# t = 2000, x = 0.006, where the velocities are still those of the bulk (in
# L = 300 the gas's kappa falls below 0 sooner).
GAS_L_D2 := 600
GAS_T_END_D2 := 2000
GAS_WINDOW_D2 := 100:2000

# Ballistic aggregation at the same phi: spheres, disks or rods that merge
# on contact (volumes, areas, lengths add; momentum conserved). It has no
# Haff regime: E(t) falls as a power law once aggregates have met a few
# times (t ~ 10).
BA_PHI_D1 := 0.208
BA_PHI_D2 := 0.208
BA_PHI_D3 := 0.208
# 1D: N = 208 000 rods, ten times the gas's (a few seconds): at t = 1e4 a
# ring of 20 800 holds too few aggregates for a steady slope.
BA_L_D1 := 1000000
BA_T_END_D1 := 10000
BA_WINDOW_D1 := 10:10000
BA_L_D3 := 68
BA_T_END_D3 := 400
BA_WINDOW_D3 := 10:400
BA_L_D2 := 600
BA_T_END_D2 := 1000
BA_WINDOW_D2 := 10:1000
