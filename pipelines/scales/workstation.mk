# SCALE = workstation: the closest one 2-core, 24 GB machine gets to the
# paper in hours. Planned by coolgas-simulate --estimate (a pilot of
# each scene and the measured rates, simulate/run/run_plan.h):
#   make -C pipelines/workstation estimate OUT=...
# The plan's total and wall time are stated once, in docs/studies.md
# ("The scales, planned and run"; tests/cli/docs_agree.py compares it with
# the plan).
# The scale before (Fig. 1 to L = 100) was run at 7dc619d: 1.66
# core-hours of runs, 61 minutes on 2 cores, 8.1 GB. Every run resumes
# (coolgas-simulate --resume; make reruns only what is missing), so it can be
# run in slices. Every variable is documented in pipelines/common.mk.
PHI := 0.208
R0 := 0.1
DELTA := 1e-4

# Fig. 1: the paper's L = 34, 68, 136 with 48 and 96 between (steps of
# sqrt 2), so that the crossover of the largest boxes pins z. The scale
# before stopped at L = 100 to t = 1e5 (x = t/L^(5/2) = 1) with 2 seeds: its
# weighted collapse gave z = 3.63 +- 0.41 (its quality falls steadily with
# z: the power-law part collapses at any z, and only the crossovers of boxes
# of different sizes fix their shift), at that z no point lay in x = 3-20 and
# eta was nan. The crossover of a box of side L lies near x = 0.1-1, so
# L = 136 runs to t = 2e5 (x = 0.93) and L = 96 to 3e5 (x = 3.3); three seeds
# of each, because the jackknife over runs with two of a size comes out about
# half the true error (analyze/collapse/seed_weights.h).
# The late end of the small boxes is set by the cut-off: once E(t) falls to
# about delta^2 = 1e-8 the relative speeds inside clusters drop below delta,
# those collisions turn elastic and E(t) flattens (a single L = 34 run: local
# slope of E 1.8-2.0 at x = 5-26, 1.5 at x = 47, 0.4 at x = 450). E ~ L^-3
# f(x) reaches 1e-8 at x ~ 25 for L = 34 and at smaller x in larger boxes,
# so eta is fitted over x = 3-20 and the small boxes end near x = 30. That x
# is the paper's, t/L^z at z ~ 2.5: eta comes from the collapse with
# z theta = 3 held (common.mk), whose z = 2.55 puts L = 34 at x = 25 and
# L = 48 at x = 21 (17 and 16 of their mean E(t)'s points in x = 3-20, in
# this plan's runs); the free fit's z = 3.16 would put them at x = 2.9 and
# leave the window empty.
# What each run costs, planned and (once run) measured:
#   make -C pipelines/workstation estimate OUT=...
SIZE_L := 34 48 68 96 136
SIZE_SEEDS := 1 2 3 4 5 6 7 8
SIZE_SEEDS_L48 := 1 2 3 4 5 6
SIZE_SEEDS_L68 := 1 2 3 4
SIZE_SEEDS_L96 := 1 2 3
SIZE_SEEDS_L136 := 1 2 3
SIZE_T_END := 200000
SIZE_T_END_L48 := 400000
SIZE_T_END_L68 := 500000
SIZE_T_END_L96 := 300000
SIZE_T_END_L136 := 200000
# Dumps through the late decade, where one a decade gives two: the
# velocity and cluster statistics of the largest boxes (beta, kappa, the
# largest cluster's share) as they cross over to the finite-size regime, for
# their trends with L and t (47 MB a dump at L = 136, 0.6 GB for the 12).
# (Restarts need no dumps: the checkpoint, every 5 minutes of wall time, is
# where an interrupted run resumes; docs/reliability.md.)
ENERGY_OUTPUT = observables_per_decade = 20$(newline)dumps_per_decade = 1$(newline)dump_times = [2e4, 3e4, 4e4, \
  5e4, 6e4, 7e4, 8e4, 9e4, 1.2e5, 1.4e5, 1.6e5, 1.8e5]
THETA_WINDOW := 100:10000
COLLAPSE_T_WINDOW := 100:
COLLAPSE_WEIGHTS := seeds
COLLAPSE_ETA_WINDOW := 3:20
COLLAPSE_BOOTSTRAP := 200
# The robustness block (pipelines/robustness.mk): the collapse from t = 300
# (three times later, away from the crossover from Haff's law near t = 100),
# and eta over x = 1-10, nearer the crossover than 3-20.
ROBUST_T_WINDOW := 300:
ROBUST_ETA_WINDOW := 1:10

# Fig. 2 at L = 100 (x = 0.1 at t = 1e4), the paper's four phi, five r0 and
# three delta. Dilute gases and nearly elastic ones leave Haff's regime later,
# so they get larger boxes: phi = 0.104 at L = 136 and 0.052 at L = 170
# (N = 5e5 each, cheap because they collide less), r0 = 0.9 at L = 136 to
# t = 3e4 (x = 0.14). Each window starts where the local slope of E(t)
# falls below 3/2 after its peak and ends near x = 0.1. Measured in this
# scale's runs (seed 1): theta = 1.186 +- 0.012 at phi = 0.052 (L = 170),
# 1.218 +- 0.009 at phi = 0.104 (L = 136), 1.182 +- 0.005 at r0 = 0.5 and
# 1.140 +- 0.006 at r0 = 0.7 (its local slope still rises from 1.08 at
# t = 3000 to 1.22 at 1e4: a larger box would tell).
PARAM_L := 100
PARAM_L_phi0.104_r0.1_d1e-4 := 136
PARAM_L_phi0.052_r0.1_d1e-4 := 170
PARAM_L_phi0.208_r0.9_d1e-4 := 136
PARAM_SEEDS := 1
PARAM_T_END := 10000
PARAM_T_END_phi0.052_r0.1_d1e-4 := 20000
PARAM_T_END_phi0.104_r0.1_d1e-4 := 20000
PARAM_T_END_phi0.208_r0.9_d1e-4 := 30000
PARAM_PHIS := 0.052 0.104 0.156 0.208
PARAM_R0S := 0.1 0.3 0.5 0.7 0.9
PARAM_DELTAS := 1e-3 1e-4 1e-5
PARAM_FIT_WINDOW := 100:10000
PARAM_FIT_WINDOW_phi0.156_r0.1_d1e-4 := 200:10000
PARAM_FIT_WINDOW_phi0.104_r0.1_d1e-4 := 300:20000
PARAM_FIT_WINDOW_phi0.052_r0.1_d1e-4 := 500:20000
PARAM_FIT_WINDOW_phi0.208_r0.7_d1e-4 := 300:10000
PARAM_FIT_WINDOW_phi0.208_r0.9_d1e-4 := 1000:20000
PARAM_OUTPUT = observables_per_decade = 20$(newline)dumps_per_decade = 5
# The three sets furthest from 6/5 run again with seeds 2 and 3 (about
# 1000 CPU-s in all; energy only): how far one run's theta lies from
# another's (pipelines/theta-causes.mk).
CAUSES_PARAM_SETS := phi0.156_r0.1_d1e-4 phi0.208_r0.3_d1e-4 phi0.208_r0.7_d1e-4
CAUSES_PARAM_SEEDS := 1 2 3

# Figs. 3-5 at the paper's times, from Fig. 2's phi = 0.208 run (SNAP_TWIN):
# L = 100, where t = 8000 is still at x = 0.08.
SNAP_L := 100
SNAP_SEED := 1
SNAP_T_END := 10000
SNAP_DUMP_TIMES := 5, 10, 100, 1000, 2000, 4000, 6000, 8000
SNAPSHOT_TIME := 8000
NM_TIMES := 2000 4000 8000
NM_FIT_WINDOW := 1:300
PHI_EARLY_TIMES := 5 10
PHI_LATE_TIMES := 2000 4000 6000 8000
# Why the velocity rows differ (pipelines/velocity-causes.mk): alpha at the
# snapshot run's dumps through the homogeneous state and out of it (five a
# decade; 0 is the Maxwellian start), beta at the start, t = 10 and the late
# times, kappa and beta of the size runs (seeds' means) at their decade dumps.
# alpha's row fits y >= 2.5, where kinetic theory's one-component form fits
# the tail at t = 10 (chi2/dof 1.9 against 27 for a straight line from 1.5).
VCAUSE_ALPHA_TIMES := 0 1 1.6 2.5 4 5 6.3 10 16 25 40 63 100 160 250 400 630 1000
VCAUSE_BETA_TIMES := 0 10 100 1000 2000 4000 6000 8000
VCAUSE_FROMS := 1.5 2 2.5 3
VCAUSE_ALPHA_FROM := 2.5
VCAUSE_SIZE_TIMES := 10 100 1000 10000 100000

SMOL_M := 262144
SMOL_T_END := 3000
SMOL_TIMES := 10,100,1000,3000
SMOL_FIT_WINDOW := 30:3000

# Ballistic aggregation at L = 100: N = 4e5 at phi = 0.208. The aggregates
# must stay narrower than L/2 = 50: in this scene's run (seed 1, 20 CPU-s)
# the largest held 17 959 particles (diameter 26) at t = 2000, and a merger
# of two such (33) still fits. That run gave theta_BA = 1.199 +- 0.002 and
# M_avg ~ t^1.08 over t = 10-2000.
BA_L := 100
BA_PHIS := 0.052 0.104 0.208
BA_SEED := 1
BA_THETA_WINDOW := 10:2000
BA_MMAX_FIT_WINDOW := 10:2000
BA_T_END := 2000
BA_DUMP_TIMES := 10, 30, 100, 300, 1000, 2000
BA_SNAPSHOT_TIME := 1000
BA_NM_TIMES := 300 1000 2000
# The velocity tails of BA while enough aggregates remain for tail bins of
# 25 samples beyond y = 1.5 (N = 4e5: at t = 1000 none is left; t = 30, 100,
# 300 have 28, 15 and 5 such bins, beta = 0.80 +- 0.01, 0.77 +- 0.05 and
# 0.86 +- 0.29). The exponent table reads the last time: 100, the latest
# with a tail of more than a few bins.
BA_PHI_TIMES := 10 30 100
# What decides theta_BA (pipelines/theta-causes.mk): the demo's box L = 48
# to t = 200 with eight seeds (1 CPU-s each) beside this L = 100 with three
# (13-16 CPU-s each): theta_BA over the demo's window in both boxes, and to
# t = 2000.
CAUSES_BA_BOXES := 48 100
CAUSES_BA_SEEDS_L48 := 1 2 3 4 5 6 7 8
CAUSES_BA_T_END_L48 := 200
CAUSES_BA_SEEDS_L100 := 1 2 3

# The growing length: Fig. 2's phi = 0.208 run (L = 100, five dumps a
# decade). L_C ~ 1.7 t^0.34 (the demo's L = 68) reaches L/4 = 25 near
# t = 2700: fitted over t = 20-2000.
STRUCTURE_GAS := param_phi0.208_r0.1_d1e-4_s1
STRUCTURE_BA := ba_phi0.208_s1
LT_FIT_WINDOW := 20:2000
COLLAPSE_FROM := 20
