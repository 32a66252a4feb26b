# The robustness block of the exponent table (included by common.mk): theta,
# z and eta of Fig. 1's collapse again under other reasonable analysis
# choices, from the same runs, side by side with the pipeline's own
# (tables/collapse.tsv), in $(OUT)/robustness.tsv and at the end of
# exponents.md (pipelines/robustness.sh judges them). One collapse per choice,
# each changing one thing:
#   start   the time window starts later, ROBUST_T_WINDOW (default: three
#           times COLLAPSE_T_WINDOW's start): what the crossover from Haff's
#           law, still in the first times, does to theta and z
#   weights the other weighting (seeds <-> none; seeds needs 2+ runs of every L)
#   eta     the tail exponent over another window of x, ROBUST_ETA_WINDOW
#   drop    without the smallest L (furthest from the scaling limit, and its
#           late times are the noisiest); needs three or more sizes
# (The paper's method, z theta held at 3, is no choice of this block: the
# exponent table gives its z beside the free fit's, common.mk.)
# A choice whose collapse cannot be made (e.g. no overlap once a size is
# dropped) is written as a table holding the tool's one-line error, which
# robustness.sh reports in its row: every other row stays.
ifndef ROBUST_T_WINDOW
ROBUST_T_WINDOW := $(shell awk -v w='$(COLLAPSE_T_WINDOW)' 'BEGIN { split(w, p, ":"); printf "%g:%s", 3 * (p[1] == "" ? 1 : p[1]), p[2] }')
endif
ROBUST_ETA_WINDOW ?= 1:
ROBUST_OTHER_WEIGHTS := $(if $(filter seeds,$(COLLAPSE_WEIGHTS)),none,seeds)
# The sizes from the second smallest on, and their runs' tables.
ROBUST_DROP_L := $(wordlist 2,99,$(call numeric_sort,$(SIZE_L)))
ROBUST_DROP_TABLES := $(foreach L,$(ROBUST_DROP_L),$(patsubst $(RUNS)/%.h5,$(TABLES)/energy_run_%.tsv,$(call size_runs,$(L))))

# $(call robust_args,T_WINDOW,ETA_WINDOW,WEIGHTS): the pipeline's collapse with these three changed.
robust_args = --optimize --bootstrap $(COLLAPSE_BOOTSTRAP) --seed 1 --t-window $(1) --eta-window $(2) --weights $(3) --summary
ROBUST_ARGS_start := $(call robust_args,$(ROBUST_T_WINDOW),$(COLLAPSE_ETA_WINDOW),$(COLLAPSE_WEIGHTS))
ROBUST_ARGS_weights := $(call robust_args,$(COLLAPSE_T_WINDOW),$(COLLAPSE_ETA_WINDOW),$(ROBUST_OTHER_WEIGHTS))
ROBUST_ARGS_eta := $(call robust_args,$(COLLAPSE_T_WINDOW),$(ROBUST_ETA_WINDOW),$(COLLAPSE_WEIGHTS))
ROBUST_ARGS_drop := $(call robust_args,$(COLLAPSE_T_WINDOW),$(COLLAPSE_ETA_WINDOW),$(COLLAPSE_WEIGHTS))
ROBUST_CHOICES := start weights eta drop
ROBUST_TABLES := $(foreach c,$(ROBUST_CHOICES),$(TABLES)/collapse_robust_$(c).tsv)
robust_inputs = $(if $(filter drop,$(1)),$(ROBUST_DROP_TABLES),$(SIZE_RUN_TABLES))

# The collapse of one choice; when the tool cannot make it (exit code 2: no
# collapse of these data), its error line as '# error: ...'; any other
# failure (an interrupt: 3) fails the step, to be made again.
# (Explicit rules, one per choice: a pattern rule with these prerequisites
# was not found by make -j on a fresh OUT, while the runs were being made.)
define robust_rule
$(TABLES)/collapse_robust_$(1).tsv: $(call robust_inputs,$(1)) $(call knob,robust_$(1),$(ROBUST_ARGS_$(1)))
	@rc=0; $(BIN)/coolgas-collapse $(ROBUST_ARGS_$(1)) $(call robust_inputs,$(1)) > $$@.tmp 2> $$@.err || rc=$$$$?; \
	if [ $$$$rc -eq 0 ]; then mv $$@.tmp $$@; \
	elif [ $$$$rc -eq 2 ]; then printf '# error: %s\n' "$$$$(tail -n 1 $$@.err)" > $$@; rm -f $$@.tmp; cat $$@; \
	else cat $$@.err >&2; rm -f $$@.tmp $$@.err; exit $$$$rc; fi; rm -f $$@.err
endef
$(foreach c,$(ROBUST_CHOICES),$(eval $(call robust_rule,$(c))))

$(OUT)/robustness.tsv: $(TABLES)/collapse.tsv $(ROBUST_TABLES) $(PIPE)robustness.sh $(PIPE)tsv-value.sh
	sh $(PIPE)robustness.sh $(TABLES) "$(ROBUST_T_WINDOW)" "$(ROBUST_OTHER_WEIGHTS)" "$(ROBUST_ETA_WINDOW)" \
	  "$(firstword $(call numeric_sort,$(SIZE_L)))" > $@
