# The frame of a self-contained study (pipelines/dimensions,
# pipelines/effects), included by its Makefile after it sets OUT: the
# programs (BIN, lib.mk), LAUNCH, the parameter file (PARAMETERS, default
# parameters.mk; tiny.mk: seconds, for the test) and the output folders.
PIPE := ../
LAUNCH ?=
include ../lib.mk
PARAMETERS ?= parameters.mk
include $(PARAMETERS)

SCENES := $(OUT)/scenes
RUNS := $(OUT)/runs
TABLES := $(OUT)/tables
KNOBS := $(OUT)/knobs
FIGURES := $(OUT)/figures
.DELETE_ON_ERROR:
.SECONDARY:
