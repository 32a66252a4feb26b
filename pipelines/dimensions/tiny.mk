# The dimension study at sizes that run in seconds (tests/cli/pipeline_test.cc
# runs every recipe with them): the same models and windows' logic as
# parameters.mk, in boxes far too small for the exponents to mean anything.
include parameters.mk
SEEDS := 1 2
GAS_L_D3 := 14
GAS_T_END_D3 := 50
GAS_WINDOW_D3 := 5:50
GAS_L_D2 := 40
GAS_T_END_D2 := 50
GAS_WINDOW_D2 := 5:50
BA_L_D3 := 14
BA_T_END_D3 := 50
BA_WINDOW_D3 := 5:50
BA_L_D2 := 40
BA_T_END_D2 := 50
BA_WINDOW_D2 := 5:50
GAS_L_D1 := 400
GAS_T_END_D1 := 50
GAS_WINDOW_D1 := 5:50
BA_L_D1 := 400
BA_T_END_D1 := 50
BA_WINDOW_D1 := 5:50
