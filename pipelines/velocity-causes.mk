# Why the velocity rows of the exponent table differ from the paper's
# numbers (included by common.mk after Fig. 5): alpha, beta and kappa of the
# snapshot run against time and against the start y_from of the tail fit,
# kinetic theory's alpha for this r0, and kappa and beta of the size runs
# (mean over seeds, per L), in tables/velocity_causes.tsv
# with tables/velocity_causes_beta.tsv and _kappa.tsv
# (pipelines/velocity-causes.sh says what each holds) and the figure
# velocity_causes.png. exponents.sh reads its verdicts from these tables.
# Knobs (scale file; defaults from Fig. 5's times):
#   VCAUSE_ALPHA_TIMES  dumps for alpha against t (the early tail forms, then
#                       leaves as the gas clusters); 0 is the Maxwellian start
#   VCAUSE_BETA_TIMES   dumps for beta against the window (0, early, late)
#   VCAUSE_FROMS        the windows' starts y_from, smallest first (the first is
#                       coolgas-velocity's default 1.5, that of Fig. 5 and the table)
#   VCAUSE_ALPHA_FROM   the window of the exponent table's alpha row
#   VCAUSE_SIZE_TIMES   times at which kappa and beta are averaged over each L's seeds
VCAUSE_ALPHA_TIMES ?= 0 $(PHI_EARLY_TIMES)
VCAUSE_BETA_TIMES ?= 0 $(lastword $(PHI_EARLY_TIMES)) $(PHI_LATE_TIMES)
VCAUSE_FROMS ?= 1.5 2 2.5 3
VCAUSE_ALPHA_FROM ?= 2.5
VCAUSE_SIZE_TIMES ?= $(lastword $(PHI_LATE_TIMES))
VCAUSE_SIZE_RUNS := $(foreach L,$(SIZE_L),$(call size_runs,$(L)))
VCAUSE_ARGS = "$(VCAUSE_ALPHA_TIMES)" "$(VCAUSE_BETA_TIMES)" "$(VCAUSE_FROMS)" $(VCAUSE_ALPHA_FROM) "$(VCAUSE_SIZE_TIMES)"

VCAUSE_TABLES := $(TABLES)/velocity_causes.tsv $(TABLES)/velocity_causes_beta.tsv $(TABLES)/velocity_causes_kappa.tsv

$(TABLES)/velocity_causes.tsv: $(SNAP_RUN) $(VCAUSE_SIZE_RUNS) $(PIPE)velocity-causes.sh \
    $(call knob,velocity_causes,$(VCAUSE_ARGS))
	@mkdir -p $(@D)
	sh $(PIPE)velocity-causes.sh $(TABLES)/velocity_causes $(BIN) $(SNAP_RUN) $(VCAUSE_ARGS) $(VCAUSE_SIZE_RUNS)
# Written by the step above, after velocity_causes.tsv (so never older).
$(TABLES)/velocity_causes_beta.tsv $(TABLES)/velocity_causes_kappa.tsv: $(TABLES)/velocity_causes.tsv
	@test -f $@ || { echo "$@ missing: remove $< and rerun"; exit 1; }

$(OUT)/velocity_causes.png: $(VCAUSE_TABLES) $(PLOTS)/velocity_causes.gp
	for o in $@ $(@:.png=.pdf); do gnuplot -e "causes='$(TABLES)/velocity_causes'; late='$(lastword $(PHI_LATE_TIMES))'; \
	  out='$$o'" $(PLOTS)/velocity_causes.gp || exit 1; done

# The exponent table's velocity rows read the tables; 'all' draws the figure
# (extra prerequisites: the rules themselves are in common.mk).
$(OUT)/exponents.tsv: $(VCAUSE_TABLES)
all figures: $(OUT)/velocity_causes.png
RESULTS += $(OUT)/velocity_causes.png
