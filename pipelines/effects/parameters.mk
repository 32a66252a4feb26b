# The effects pipeline's parameters (pipelines/effects/Makefile): sizes that
# run in under a minute on two cores. tiny.mk overrides them for the test.
#
# The driven gas: the white-noise thermostat's steady state at r0 = 0.5,
# delta = 0, phi = 0.05 (dilute enough for Enskog's energy balance within a
# few per cent), N = 5240 (L = 38). POWER = (1 - r0^2)/2 in T0 per initial
# collision time is what the collisions lose at T = T0, so the first run
# stays near T0 and the second, at 8 times the power, heats to 4 T0
# (T ~ P^(2/3) exactly at delta = 0). Both relax for DRIVEN_T_RELAX (1/zeta
# is about 3 collision times at r0 = 0.5), then a dump every
# DRIVEN_DUMP_EVERY samples a2 up to DRIVEN_T_END (about 200 samples, a2 to
# +- 0.001). DRIVEN_PERIOD is the kicks' interval in collision times
# (driving.period; its default).
DRIVEN_L := 38
DRIVEN_PHI := 0.05
DRIVEN_R0 := 0.5
DRIVEN_POWER := 0.375
DRIVEN_T_RELAX := 20
DRIVEN_T_END := 220
DRIVEN_DUMP_EVERY := 1
DRIVEN_PERIOD := 0.5

# Rough spheres: the homogeneous cooling state at r0 = 0.9 (nearly elastic,
# so the gas stays homogeneous over the run), phi = 0.05, N = 8134 (L = 44),
# uniform balls (inertia 2/5), tangential restitution beta = 0, 0.5 and 1
# (spins slow to follow at beta near -1 are not drawn). Spins and velocities
# start at T0 each; T_rot/T_tr settles within about 20 collision times, so
# the ratio is averaged from ROUGH_T_FROM to ROUGH_T_END.
ROUGH_L := 44
ROUGH_PHI := 0.05
ROUGH_R0 := 0.9
ROUGH_INERTIA := 0.4
ROUGH_BETAS := 0 0.5 1
ROUGH_T_FROM := 30
ROUGH_T_END := 150

# A binary mixture: half diameter 1, mass 1 and half diameter 1.5, mass
# 1.5^3, inelastic (r0 = 0.8, delta = 0), dilute (phi = 0.02: the contact
# values within 3 % of 1, no clustering yet), N = 20000, cooling from equal
# temperatures. T_1/T_2 settles within about 5 collisions per particle
# (t ~ 6) and is averaged from MIXTURE_T_FROM to MIXTURE_T_END (about 30
# collisions per particle).
MIXTURE_N := 20000
MIXTURE_PHI := 0.02
MIXTURE_R0 := 0.8
MIXTURE_DIAMETER := 1.5
MIXTURE_T_FROM := 6
MIXTURE_T_END := 100
