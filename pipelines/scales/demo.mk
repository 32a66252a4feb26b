# SCALE = demo: small systems that still show the physics, about 3 minutes
# with make -j2 on a laptop-class machine (one core per run).
# Every variable is documented in pipelines/common.mk.

# The paper's gas (all figures unless varied).
PHI := 0.208
R0 := 0.1
DELTA := 1e-4

# Fig. 1: energy decay for several L, seeds averaged, finite-size collapse.
SIZE_L := 12 16 24 32
SIZE_SEEDS := 1 2 3 4
SIZE_T_END := 30000
THETA_WINDOW := 20:300
COLLAPSE_T_WINDOW := 20:
COLLAPSE_ETA_WINDOW := 0.3:
COLLAPSE_BOOTSTRAP := 100

# Fig. 2: E(t) for several phi, r0, delta at fixed L.
PARAM_L := 40
PARAM_SEEDS := 1
PARAM_T_END := 10000
PARAM_PHIS := 0.052 0.104 0.208
PARAM_R0S := 0.1 0.5 0.9
PARAM_DELTAS := 1e-2 1e-3 1e-4
PARAM_FIT_WINDOW := 30:1000

# Figs. 3-5: one larger run dumped at the paper's times.
SNAP_L := 48
SNAP_SEED := 1
SNAP_T_END := 10000
SNAP_DUMP_TIMES := 5, 10, 100, 1000, 2000, 4000, 8000
SNAPSHOT_TIME := 2000
NM_TIMES := 1000 2000 4000 8000
NM_FIT_WINDOW := 1:100
MMAX_FIT_WINDOW := 100:10000
PHI_EARLY_TIMES := 5 10
PHI_LATE_TIMES := 2000 4000 8000

# Smoluchowski equation (paper Eq. 3-4), beside the simulations.
SMOL_M := 131072
SMOL_T_END := 300
SMOL_TIMES := 3,30,300
SMOL_FIT_WINDOW := 10:300

# Ballistic aggregation (with BA = 1, once coolgas-simulate has collision.model = "aggregation").
BA_L := 48
BA_PHIS := 0.052 0.208
BA_SEED := 1
BA_THETA_WINDOW := 10:200
BA_MMAX_FIT_WINDOW := 10:200
# N = 43933 at phi = 0.208: the aggregates must stay narrower than L/3 = 16.
BA_T_END := 200
BA_DUMP_TIMES := 10, 25, 50, 100, 200
BA_SNAPSHOT_TIME := 100
BA_NM_TIMES := 25 50 100
BA_PHI_TIMES := 10 25 50
