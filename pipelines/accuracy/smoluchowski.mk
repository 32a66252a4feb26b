# What accuracy costs in time for coolgas-smoluchowski: every method over its
# knobs (M, tolerances, grid ratio), error against wall time, as a table and a
# figure. Usable alone or included from another Makefile in this folder:
#   make -f smoluchowski.mk                  full study (a few minutes on one core)
#   make -f smoluchowski.mk SMOL_QUICK=1     quick study (constant and ballistic only)
# BIN is the folder of the built tools; LAUNCH an optional prefix (e.g. srun -n1).
BIN ?= ../../build/bin
LAUNCH ?=
OUT ?= out
SMOL_QUICK ?= 0
SMOL_DIR := $(dir $(lastword $(MAKEFILE_LIST)))

.PHONY: smoluchowski-accuracy
smoluchowski-accuracy: $(OUT)/smoluchowski_accuracy.png

$(OUT)/smoluchowski_accuracy.tsv:
	mkdir -p $(OUT)
	$(LAUNCH) $(BIN)/coolgas-smoluchowski --accuracy-study $(if $(filter 1,$(SMOL_QUICK)),--quick,) > $@.tmp
	mv $@.tmp $@

$(OUT)/smoluchowski_accuracy.png: $(OUT)/smoluchowski_accuracy.tsv $(SMOL_DIR)smoluchowski.gp
	gnuplot -e "in='$<'; out='$@'" $(SMOL_DIR)smoluchowski.gp
