# SCALE = demo: the paper's result at the smallest sizes that show it
# (about 1 000 core-seconds for the whole pipeline; pipelines/README.md).
# Every box is chosen so its quantity is measured in its own regime: Fig. 1
# needs L >= 34 (smaller boxes stay in the finite-size regime), and the
# exponent table (exponents.md) says for each quantity whether the run
# reached the paper's regime. Every variable is documented in pipelines/common.mk.

# The paper's gas (all figures unless varied).
PHI := 0.208
R0 := 0.1
DELTA := 1e-4

# Fig. 1: energy decay for L = 34, 48, 68 (the paper's smallest sizes are 34
# and 68), three seeds of the two small boxes and two of L = 68 (which costs
# as much as all the others), to x = t/L^(5/2) of about 8-15. The collapse is
# weighted by the scatter of each L's runs (COLLAPSE_WEIGHTS, common.mk): with
# equal weights the late, wandering times of the small boxes decided it, and
# z came out 3.1 +- 3.2 from these runs. Its errors are the jackknife over the
# seeds; a size with two runs cannot estimate its weights again in the
# replicas, so they come out somewhat small (coolgas-collapse --help). From
# t = 100, where the gas has left Haff's law (which has another theta).
SIZE_L := 34 48 68
SIZE_SEEDS := 1 2 3
SIZE_SEEDS_L68 := 1 2
SIZE_T_END := 100000
SIZE_T_END_L48 := 200000
SIZE_T_END_L68 := 300000
THETA_WINDOW := 100:3000
COLLAPSE_T_WINDOW := 100:
COLLAPSE_WEIGHTS := seeds
# x >= 1: the finite-size regime, where E(t) L^(z theta) ~ x^-eta.
COLLAPSE_ETA_WINDOW := 1:
COLLAPSE_BOOTSTRAP := 100
# The robustness block (pipelines/robustness.mk): the same collapse from
# t = 300, three times later, away from the crossover from Haff's law that
# ends near t = 100, and eta over x >= 3 only, deeper in the finite-size
# regime (the scaled data reach x = 8-15).
ROBUST_T_WINDOW := 300:
ROBUST_ETA_WINDOW := 3:

# Fig. 2: E(t) for several phi, r0, delta, fitted between the crossover from
# Haff's regime (t ~ 100 at phi = 0.208) and the finite-size crossover
# (x = t/L^(5/2) = 0.1: t = 3800 at L = 68). Dilute gases leave Haff's regime
# later (local slope of E below 3/2 from t ~ 300 at phi = 0.104, ~500 at
# 0.052) and need larger boxes to reach it before the finite-size regime:
# L = 100 (x = 0.1 at t = 1e4) and L = 136 (x = 0.1 at t = 2.2e4). At
# phi = 0.052 the local slope of E(t) has no plateau (it dips to 1.0 at
# t = 2000-5000 and rises to 1.5 by 2e4), so theta is its mean over the whole
# scaling regime, t_inhom = 500 to x = 0.1: to t = 1e4 it was 1.136 +- 0.011,
# to 2e4 (134 CPU-s) 1.202 +- 0.015. r0 = 0.9 leaves the homogeneous
# regime too late for these boxes. The cut-offs are 1e-3 ... 1e-5, as in the
# paper scale: with delta = 1e-2 the relative speeds inside clusters fall
# below delta by t ~ 300, those collisions turn elastic and E(t) decays ever
# more slowly (local slope 0.7 at t = 2400 in L = 68), a regime of its own.
# The snapshot run of Figs. 3-5 is the phi = 0.208 run here (SNAP_TWIN,
# pipelines/common.mk): same box, end time and seed, so one run serves both.
PARAM_L := 68
PARAM_L_phi0.104_r0.1_d1e-4 := 100
PARAM_L_phi0.052_r0.1_d1e-4 := 136
PARAM_SEEDS := 1
PARAM_T_END := 10000
PARAM_T_END_phi0.052_r0.1_d1e-4 := 20000
PARAM_PHIS := 0.052 0.104 0.208
PARAM_R0S := 0.1 0.3 0.5
PARAM_DELTAS := 1e-3 1e-4 1e-5
PARAM_FIT_WINDOW := 100:3000
PARAM_FIT_WINDOW_phi0.052_r0.1_d1e-4 := 500:20000
PARAM_FIT_WINDOW_phi0.104_r0.1_d1e-4 := 300:10000
# Fig. 4 draws M_max(t) of the phi runs: enough dumps to see its rapid rise.
PARAM_OUTPUT = observables_per_decade = 20$(newline)dumps_per_decade = 5

# Figs. 3-5: one run at L = 68 dumped at the paper's times (its late times
# 2000-8000 lie past this box's finite-size crossover; the table says so);
# it is Fig. 2's phi = 0.208 run, which adds these dump times.
SNAP_L := 68
SNAP_SEED := 1
SNAP_T_END := 10000
SNAP_DUMP_TIMES := 5, 10, 100, 1000, 2000, 4000, 8000
SNAPSHOT_TIME := 1000
NM_TIMES := 1000 2000 4000 8000
NM_FIT_WINDOW := 1:100
PHI_EARLY_TIMES := 5 10
PHI_LATE_TIMES := 2000 4000 8000
# Why the velocity rows differ (pipelines/velocity-causes.mk): alpha through
# the homogeneous state and out of it (the snapshot run dumps five a decade),
# kappa and beta of the size runs (seeds' means) at their decade dumps.
VCAUSE_ALPHA_TIMES := 0 1 2.5 5 10 25 63 100 250 1000
VCAUSE_BETA_TIMES := 0 10 100 1000 2000 4000 8000
VCAUSE_SIZE_TIMES := 100 1000 10000 100000

# Smoluchowski equation (paper Eq. 3-4), beside the simulations.
SMOL_M := 131072
SMOL_T_END := 300
SMOL_TIMES := 3,30,300
SMOL_FIT_WINDOW := 10:300

# Ballistic aggregation (BA = 1).
BA_L := 48
BA_PHIS := 0.052 0.208
BA_SEED := 1
BA_THETA_WINDOW := 10:200
BA_MMAX_FIT_WINDOW := 10:200
# N = 43933 at phi = 0.208: the aggregates must stay narrower than L/2 = 24.
BA_T_END := 200
BA_DUMP_TIMES := 10, 25, 50, 100, 200
BA_SNAPSHOT_TIME := 100
BA_NM_TIMES := 25 50 100
BA_PHI_TIMES := 10 25 50

# The growing length (structure.png, z from L_t and L_C in exponents.md): the
# Fig. 2 run at the paper's gas, L = 68, dumped 5 times a decade (the snapshot
# run, its twin, only twice; the Fig. 1 runs once). Fit window t = 20-400:
# clusters have formed by t = 20 (L_C has left its t = 0 value 2.2), and L_C
# stays below L/4 = 17 to t = 400 (12.4 there), while L_t = 2 pi/<k> is 12 at
# t = 20 and 24 at t = 400: in this box L_t is box-limited over the whole
# window (its row in exponents.md says so), and L_C is the length to trust.
STRUCTURE_GAS := param_phi0.208_r0.1_d1e-4_s1
STRUCTURE_BA := ba_phi0.208_s1
LT_FIT_WINDOW := 20:400
COLLAPSE_FROM := 20

# What decides theta_BA (pipelines/theta-causes.mk): the aggregation run of
# this box with seven more seeds (1 CPU-s each), and one at L = 100 to
# t = 2000 (13 CPU-s), whose aggregates stay narrower than L/2 four times
# longer: theta_BA over the same window in both boxes, and to t = 2000.
CAUSES_BA_BOXES := 48 100
CAUSES_BA_SEEDS_L48 := 1 2 3 4 5 6 7 8
CAUSES_BA_SEEDS_L100 := 1
CAUSES_BA_T_END_L100 := 2000
