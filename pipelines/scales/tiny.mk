# SCALE = tiny: the end-to-end test (tests/cli/pipeline_test.cc), seconds in
# all. The numbers it gives are not physics, only a check that every recipe
# runs and every table parses.
PHI := 0.208
R0 := 0.1
DELTA := 1e-4

SIZE_L := 8 10 12
SIZE_SEEDS := 1 2
SIZE_T_END := 2000
THETA_WINDOW := 10:300
COLLAPSE_T_WINDOW := 10:
COLLAPSE_ETA_WINDOW := 0.3:
COLLAPSE_BOOTSTRAP := 10

PARAM_L := 12
PARAM_SEEDS := 1
PARAM_T_END := 1000
PARAM_PHIS := 0.104 0.208
PARAM_R0S := 0.1 0.5
PARAM_DELTAS := 1e-3 1e-4
PARAM_FIT_WINDOW := 10:1000
# Five dumps a decade, as Fig. 4's rule for the rapid growth of M_max needs.
PARAM_OUTPUT = observables_per_decade = 20$(newline)dumps_per_decade = 5

SNAP_L := 16
SNAP_SEED := 1
SNAP_T_END := 1000
SNAP_DUMP_TIMES := 5, 10, 100, 500, 1000
SNAPSHOT_TIME := 500
NM_TIMES := 500 1000
NM_FIT_WINDOW := 1:30
PHI_EARLY_TIMES := 5 10
PHI_LATE_TIMES := 500 1000
# pipelines/velocity-causes.mk: a few dumps of each kind (the tails of
# N = 1627 particles have few bins: only windows from y = 1.5 have 3 or more,
# so that is the alpha row's window here).
VCAUSE_ALPHA_TIMES := 0 5 10 100
VCAUSE_SIZE_TIMES := 100 1000
VCAUSE_ALPHA_FROM := 1.5

SMOL_M := 4096
SMOL_T_END := 30
SMOL_TIMES := 3,30
SMOL_FIT_WINDOW := 3:30

BA_L := 16
BA_PHIS := 0.208
BA_SEED := 1
BA_THETA_WINDOW := 2:16
BA_MMAX_FIT_WINDOW := 2:16
# Aggregates reach half this small box (the engine's limit) later than BA_T_END (when: pipelines/README.md).
BA_T_END := 16
BA_DUMP_TIMES := 1, 2, 4, 8, 16
BA_SNAPSHOT_TIME := 8
BA_NM_TIMES := 8 16
BA_PHI_TIMES := 1 2

# The growing length: the snapshot run (L = 16, box-limited from the start).
STRUCTURE_GAS := snap_s1
STRUCTURE_BA := ba_phi0.208_s1
LT_FIT_WINDOW := 10:1000
COLLAPSE_FROM := 10

# What decides theta_BA (pipelines/theta-causes.mk): the BA run and one more seed.
CAUSES_BA_SEEDS := 1 2
CAUSES_PARAM_SETS := phi0.208_r0.5_d1e-4
CAUSES_PARAM_SEEDS := 2
