# SCALE = paper: the parameters of Pathak, Jabeen, Das, Rajesh (2014).
# N up to 8e6 (L = 272): weeks of core time in all; run on a cluster,
#   make -C pipelines/paper -j200 LAUNCH='srun -n1 -c1 --mem=8G' BIN=... OUT=...
# Dumps of 8e6 particles take about 0.5 GB each, so the big runs dump only at
# the times the figures use.
PHI := 0.208
R0 := 0.1
DELTA := 1e-4

# Fig. 1: L = 34 ... 272 (N = 8e3 ... 8e6), 8 seeds each (fewer for the largest is
# fine: set SIZE_SEEDS on the command line and rerun; finished runs are kept).
SIZE_L := 34 68 136 272
SIZE_SEEDS := 1 2 3 4 5 6 7 8
SIZE_T_END := 1000000
# t_end about 10 L^z (z = 5/2) for the small boxes, where the tail x >> 1 is cheap.
SIZE_T_END_L34 := 100000
SIZE_T_END_L68 := 300000
THETA_WINDOW := 30:30000
COLLAPSE_T_WINDOW := 30:
COLLAPSE_WEIGHTS := seeds
COLLAPSE_ETA_WINDOW := 3:300
COLLAPSE_BOOTSTRAP := 200

# Fig. 2: L = 272, N from 2e6 (phi = 0.052) to 8e6 (phi = 0.208).
PARAM_L := 272
PARAM_SEEDS := 1
PARAM_T_END := 100000
PARAM_PHIS := 0.052 0.104 0.156 0.208
PARAM_R0S := 0.1 0.3 0.5 0.7 0.9
PARAM_DELTAS := 1e-3 1e-4 1e-5
PARAM_FIT_WINDOW := 100:30000

# Figs. 3-5 at the paper's times (Fig. 5: t = 5, 10 and 2000 ... 8000).
SNAP_L := 272
SNAP_SEED := 1
SNAP_T_END := 10000
SNAP_DUMP_TIMES := 5, 10, 100, 1000, 2000, 4000, 6000, 8000
SNAPSHOT_TIME := 8000
NM_TIMES := 2000 4000 8000
NM_FIT_WINDOW := 1:1000
PHI_EARLY_TIMES := 5 10
PHI_LATE_TIMES := 2000 4000 6000 8000
# Why the velocity rows differ (pipelines/velocity-causes.mk); the snapshot
# run dumps twice a decade besides SNAP_DUMP_TIMES.
VCAUSE_ALPHA_TIMES := 0 1 3 5 10 30 100 300 1000
VCAUSE_BETA_TIMES := 0 10 100 1000 2000 4000 6000 8000
VCAUSE_SIZE_TIMES := 100 1000 10000 100000

SMOL_M := 1048576
SMOL_T_END := 100000
SMOL_TIMES := 10,100,1000,10000
SMOL_FIT_WINDOW := 100:100000

# Ballistic aggregation: phi from 0.005 to 0.208 (theta_BA from 1.283 to 1.206).
BA_L := 272
BA_PHIS := 0.005 0.052 0.104 0.208
BA_SEED := 1
BA_THETA_WINDOW := 100:100000
BA_MMAX_FIT_WINDOW := 100:100000
BA_T_END := 100000
BA_DUMP_TIMES := 400, 800, 1600
BA_SNAPSHOT_TIME := 1600
BA_NM_TIMES := 400 800 1600
BA_PHI_TIMES := 400 800 1600

# The growing length: the snapshot run at L = 272 (dumped twice a decade and
# at the Fig. 5 times). L_C ~ 1.7 t^0.34 (the demo's L = 68) reaches
# L/4 = 68 near t = 5e4, past this run's end.
STRUCTURE_GAS := snap_s1
STRUCTURE_BA := ba_phi0.208_s1
LT_FIT_WINDOW := 30:10000
COLLAPSE_FROM := 30
