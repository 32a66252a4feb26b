# Make helpers shared by the pipelines (common.mk, accuracy/, dimensions/,
# effects/). Needs PIPE (this folder, with a trailing '/') and LAUNCH.
# BIN, the programs, unless the pipeline names them: a source tree's build;
# in an installed tree (PREFIX/share/coolgas/pipelines/NAME) the installed
# ones, PREFIX/bin.
BIN ?= $(if $(wildcard ../../../../bin/coolgas-simulate),$(if $(wildcard ../../build/bin),../../build/bin,../../../../bin),../../build/bin)
define newline


endef
# $(call streq,A,B): non-empty if A and B are the same text.
streq = $(and $(findstring x$(1),x$(2)),$(findstring x$(2),x$(1)))
# $(call keep,PATH,TEXT): write TEXT to PATH unless PATH already holds it
# (up to white space).
keep = $(if $(call streq,$(strip $(file <$(1))),$(strip $(2))),,$(shell mkdir -p $(dir $(1)))$(file >$(1),$(2)))
# $(call knob,NAME,TEXT): a file recording the knobs of one analysis step;
# a step depends on its knob file, so changing a knob reruns just that step.
knob = $(KNOBS)/$(1).txt$(call keep,$(KNOBS)/$(1).txt,$(2))
# $(call field,PREFIX,NAME): the value of PREFIXvalue in a run name such as
# param_phi0.208_r0.1_d1e-4_s1 (words after the first, split at '_').
field = $(patsubst $(1)%,%,$(filter $(1)%,$(wordlist 2,99,$(subst _, ,$(notdir $(patsubst %.h5,%,$(2)))))))
# $(call numeric_sort,LIST): LIST in increasing numeric order.
numeric_sort = $(shell printf '%s\n' $(1) | sort -g)

# The recipe of one run, $(RUNS)/NAME.h5 from $(SCENES)/NAME.toml: LAUNCH
# prefixes the simulation (on a cluster it runs there), its wall time goes to
# NAME.wall_s, and the trajectory is renamed into place only when complete.
# An interrupted run (wall-time limit, pre-emption, Ctrl-C) leaves NAME.h5.part,
# which the next make continues with --resume when it is newer than the scene;
# only a .part that cannot be resumed (exit code 2: unreadable, no complete
# dump) starts over. The wall time is then that of the last part. The run's
# checkpoint moves with it (NAME.h5.checkpoint: extending run.t_end with
# --resume NAME.h5 continues exactly), so no stale NAME.h5.part.checkpoint
# is left, nor an older run's NAME.h5.checkpoint.
define simulate
@mkdir -p $(@D)
$(LAUNCH) sh $(PIPE)timed-run.sh $(basename $@).wall_s sh -c '\
  if [ -f "$$1.part" ] && [ "$$1.part" -nt "$$2" ]; then \
    "$$0" --resume "$$1.part" --quiet; rc=$$?; [ $$rc -eq 2 ] || exit $$rc; \
  fi; exec "$$0" "$$2" -o "$$1.part" --force --quiet' $(BIN)/coolgas-simulate $@ $<
mv $@.part $@
if [ -f $@.part.checkpoint ]; then mv -f $@.part.checkpoint $@.checkpoint; else rm -f $@.checkpoint; fi
endef
