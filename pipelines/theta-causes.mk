# What decides the exponent table's theta of Fig. 2's sets, theta_BA and the
# largest cluster's share (included by common.mk), from the pipeline's own
# runs and a few cheap aggregation runs:
#   tables/theta_causes.tsv  each Fig. 2 set's theta over its window, a later
#       start and the last half decade, with the local slope of E(t) at its
#       lowest and at the window's end; the paper's gas of Fig. 1 in every box
#       to x = 0.1 (the same window's trend with L); theta_BA in each box
#       of CAUSES_BA_BOXES over the pipeline's window and to the run's end,
#       with the scatter of its seeds (pipelines/theta-causes.sh fits)
#   tables/largest_share.tsv  the largest cluster's share at t = 0 and at the
#       late time against the particles per unit cell, for Fig. 2's phi and
#       Fig. 1's boxes (pipelines/theta-causes.sh share)
#   theta_causes.png  the local slopes against t with the fit windows, theta_BA
#       against the window's end, the share against the cells' density
# exponents.sh reads both tables for the verdicts of those rows.
#
# Knobs (a scale may set them; the defaults add no run):
#   CAUSES_BA_BOXES    box sides of the aggregation runs at PHI (default BA_L)
#   CAUSES_BA_SEEDS    their seeds (default BA_SEED); CAUSES_BA_SEEDS_L<L> per box
#   CAUSES_BA_T_END_L<L>  a box's end time (default BA_T_END): aggregates must
#                      stay narrower than about L/2
#   CAUSES_PARAM_SETS  Fig. 2 sets (names as phi0.156_r0.1_d1e-4) run again with
#   CAUSES_PARAM_SEEDS more seeds, in the set's box to its end time: how much
#                      one run's theta differs from another's, which its fit
#                      error (its own points only) does not say
# The box BA_L with seed BA_SEED to BA_T_END is the pipeline's own BA run, not
# simulated again.

CAUSES_BA_BOXES ?= $(BA_L)
CAUSES_BA_SEEDS ?= $(BA_SEED)
causes_ba_t_end = $(or $(CAUSES_BA_T_END_L$(1)),$(BA_T_END))
causes_ba_seeds = $(or $(CAUSES_BA_SEEDS_L$(1)),$(CAUSES_BA_SEEDS))
# The run of box $(1), seed $(2): the pipeline's own when it is the same scene.
causes_ba_name = $(if $(and $(filter $(BA_L),$(1)),$(filter $(BA_SEED),$(2)),$(filter \
  $(BA_T_END),$(call causes_ba_t_end,$(1))),$(filter $(PHI),$(BA_PHIS))),ba_phi$(PHI)_s$(2),babox_L$(1)_phi$(PHI)_s$(2))
# Energy only: one dump a decade.
CAUSES_OUTPUT ?= observables_per_decade = 20$(newline)dumps_per_decade = 1

CAUSES_PARAM_SETS ?=
CAUSES_PARAM_SEEDS ?=

ifeq ($(ARCHIVE),)
CAUSES_PARAM_SETS := $(filter $(PARAM_SETS),$(CAUSES_PARAM_SETS))
$(foreach p,$(CAUSES_PARAM_SETS),$(foreach s,$(filter-out $(PARAM_SEEDS),$(CAUSES_PARAM_SEEDS)),$(call \
  keep,$(SCENES)/pseed_$(p)_s$(s).toml,$(call gas_scene,pseed_$(p)_s$(s),$(call param_l,$(p)),$(call \
  field,phi,x_$(p)),$(call field,r,x_$(p)),$(call field,d,x_$(p)),$(call param_t_end,$(p)),$(s),$(CAUSES_OUTPUT)))))
causes_seed_runs = $(call param_runs,$(1)) $(foreach s,$(filter-out $(PARAM_SEEDS),$(CAUSES_PARAM_SEEDS)),$(RUNS)/pseed_$(1)_s$(s).h5)
ifeq ($(BA),1)
$(foreach L,$(CAUSES_BA_BOXES),$(foreach s,$(call causes_ba_seeds,$(L)),$(if $(filter babox_%,$(call \
  causes_ba_name,$(L),$(s))),$(call keep,$(SCENES)/$(call causes_ba_name,$(L),$(s)).toml,$(call \
  ba_scene,$(call causes_ba_name,$(L),$(s)),$(L),$(PHI),$(call causes_ba_t_end,$(L)),$(s),$(CAUSES_OUTPUT))))))
causes_ba_runs = $(foreach s,$(call causes_ba_seeds,$(1)),$(RUNS)/$(call causes_ba_name,$(1),$(s)).h5)
else
CAUSES_BA_BOXES :=
endif
else
# Reanalysis: the sets, boxes and seeds the archive holds.
CAUSES_PARAM_SETS := $(sort $(foreach f,$(wildcard $(RUNS)/pseed_*.h5),$(call param_name,$(call field,phi,$(f)),$(call \
  field,r,$(f)),$(call field,d,$(f)))))
causes_seed_runs = $(call param_runs,$(1)) $(sort $(wildcard $(RUNS)/pseed_$(1)_s*.h5))
CAUSES_BA_BOXES := $(if $(filter 1,$(BA)),$(call numeric_sort,$(sort $(foreach f,$(wildcard \
  $(RUNS)/babox_L*_phi$(PHI)_s*.h5),$(call field,L,$(f))))))
causes_ba_runs = $(sort $(wildcard $(RUNS)/babox_L$(1)_phi$(PHI)_s*.h5) $(if $(filter $(BA_L),$(1)),$(wildcard \
  $(RUNS)/ba_phi$(PHI)_s*.h5)))
endif
causes_run_tables = $(patsubst $(RUNS)/%.h5,$(TABLES)/energy_run_%.tsv,$(1))
# The runs this step adds to the pipeline's (for the plan, pipelines/cluster/estimate.mk).
CAUSES_RUNS := $(filter $(RUNS)/pseed_% $(RUNS)/babox_%,$(foreach p,$(CAUSES_PARAM_SETS),$(call \
  causes_seed_runs,$(p))) $(foreach L,$(CAUSES_BA_BOXES),$(call causes_ba_runs,$(L))))

# E(t) of a box's runs together (the mean and its standard error); of a Fig. 2 set's seeds.
$(TABLES)/energy_babox_L%.tsv: $$(call causes_ba_runs,$$*)
	@mkdir -p $(@D)
	$(BIN)/coolgas-energy $^ > $@
$(TABLES)/energy_pseeds_%.tsv: $$(call causes_seed_runs,$$*)
	@mkdir -p $(@D)
	$(BIN)/coolgas-energy $^ > $@

# One line per measured table: "KIND WINDOW MEAN_TABLE RUN_TABLES" (theta-causes.sh).
CAUSES_SPECS := $(foreach p,$(PARAM_SETS),param $(call param_window,$(p)) $(TABLES)/energy_param_$(p).tsv \
    $(call causes_run_tables,$(call param_runs,$(p)))$(newline))$(foreach p,$(CAUSES_PARAM_SETS),param $(call \
    param_window,$(p)) $(TABLES)/energy_pseeds_$(p).tsv $(call causes_run_tables,$(call \
    causes_seed_runs,$(p)))$(newline))$(foreach L,$(SIZE_L),size $(THETA_WINDOW) \
    $(TABLES)/energy_size_L$(L).tsv $(call causes_run_tables,$(call size_runs,$(L)))$(newline))$(foreach \
    L,$(CAUSES_BA_BOXES),ba $(BA_THETA_WINDOW) $(TABLES)/energy_babox_L$(L).tsv $(call \
    causes_run_tables,$(call causes_ba_runs,$(L)))$(newline))
CAUSES_TABLES := $(filter %.tsv,$(CAUSES_SPECS))
$(TABLES)/theta_causes.tsv: $(CAUSES_TABLES) $(call knob,theta_causes,$(CAUSES_SPECS)) $(PIPE)theta-causes.sh
	sh $(PIPE)theta-causes.sh fits $(BIN) < $(KNOBS)/theta_causes.txt > $@

# The largest cluster's share: Fig. 2's phi (at R0, DELTA) and the first run of each Fig. 1 box.
SHARE_RUNS := $(foreach p,$(PARAM_PHIS),$(firstword $(call param_runs,$(call param_name,$(p),$(R0),$(DELTA))))) \
              $(foreach L,$(SIZE_L),$(firstword $(call size_runs,$(L))))
SHARE_TABLES := $(foreach r,$(SHARE_RUNS),$(call mmax_table,$(r)))
$(TABLES)/largest_share.tsv: $(SHARE_TABLES) $(call knob,largest_share,$(lastword $(PHI_LATE_TIMES))) $(PIPE)theta-causes.sh
	sh $(PIPE)theta-causes.sh share $(lastword $(PHI_LATE_TIMES)) $(SHARE_TABLES) > $@

# Local slopes of E(t) for the figure.
$(TABLES)/slope_%.tsv: $(TABLES)/energy_%.tsv
	$(BIN)/coolgas-fit --local-slope $< > $@
CAUSES_SLOPES := $(patsubst $(TABLES)/energy_%,$(TABLES)/slope_%,$(filter $(TABLES)/energy_param_% \
  $(TABLES)/energy_size_% $(TABLES)/energy_babox_%,$(CAUSES_TABLES)))

$(OUT)/theta_causes.png: $(TABLES)/theta_causes.tsv $(TABLES)/largest_share.tsv $(CAUSES_SLOPES) $(PLOTS)/theta_causes.gp
	for o in $@ $(@:.png=.pdf); do gnuplot -e "causes='$(TABLES)/theta_causes.tsv'; share='$(TABLES)/largest_share.tsv'; \
	  tables='$(TABLES)'; phis='$(PARAM_PHIS)'; r0s='$(PARAM_R0S)'; sizes='$(SIZE_L)'; boxes='$(CAUSES_BA_BOXES)'; \
	  phi0='$(PHI)'; r00='$(R0)'; delta0='$(DELTA)'; out='$$o'" $(PLOTS)/theta_causes.gp || exit 1; done

all figures: $(OUT)/theta_causes.png
$(OUT)/exponents.tsv: $(TABLES)/theta_causes.tsv $(TABLES)/largest_share.tsv
RESULTS += $(OUT)/theta_causes.png
