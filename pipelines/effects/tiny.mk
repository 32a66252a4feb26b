# The effects pipeline at sizes of seconds (tests/cli/pipeline_test.cc runs
# every recipe with them): the same scenes in a box far too small and a run
# far too short for the numbers to mean anything.
include parameters.mk
DRIVEN_L := 10
DRIVEN_T_RELAX := 5
DRIVEN_T_END := 25
ROUGH_L := 12
ROUGH_BETAS := 0.5
ROUGH_T_FROM := 5
ROUGH_T_END := 20
MIXTURE_N := 1000
MIXTURE_T_FROM := 2
MIXTURE_T_END := 10
