# The recipes of the figure pipelines (demo, paper, tiny): included by
# pipelines/demo/Makefile and pipelines/paper/Makefile, which only choose the
# parameter set. See pipelines/README.md for the figures and how to run them.
#
# Variables a user sets on the command line:
#   SCALE   parameter set: demo | paper | tiny (pipelines/scales/$(SCALE).mk)
#   BIN     folder of the built tools (coolgas-simulate, coolgas-energy, ...)
#   OUT     folder of the results; runs in $(OUT)/runs, tables in $(OUT)/tables
#   LAUNCH  prefix of every simulation command, e.g. 'srun -n1 -c1' (Slurm);
#           empty by default. make -j200 LAUNCH='srun -n1 -c1' spreads the
#           independent runs over a cluster.
#   BA      1 (default) adds the ballistic-aggregation runs and curves; 0 leaves them out
#   ARCHIVE with the target 'reanalyze': a folder of archived runs (*.h5, named
#           as in $(OUT)/runs) to redraw every figure from, without simulating
#
# How it stays reproducible and incremental:
#   - every run is one target $(OUT)/runs/NAME.h5 made from its scene
#     $(OUT)/scenes/NAME.toml, which holds every input of the run (seed too);
#   - scenes, and the knobs of each analysis step ($(OUT)/knobs/*.txt), are
#     written when make reads this file, but only if their text changed: so a
#     changed parameter reruns exactly the runs and steps that use it, and a
#     finished pipeline has nothing to do (make -q exits 0);
#   - .DELETE_ON_ERROR: a failed step leaves no target behind; runs are
#     written to NAME.h5.part and renamed when complete.

SCALE ?= demo
PIPE := $(dir $(lastword $(MAKEFILE_LIST)))
include $(PIPE)scales/$(SCALE).mk

OUT ?= ../../out/$(SCALE)
LAUNCH ?=
BA ?= 1
ARCHIVE ?=

# Output grids of the runs (scene [output] tables).
ENERGY_OUTPUT ?= observables_per_decade = 20$(newline)dumps_per_decade = 1
PARAM_OUTPUT ?= $(ENERGY_OUTPUT)
SNAP_OUTPUT ?= observables_per_decade = 20$(newline)dumps_per_decade = 2$(newline)dump_times = [$(SNAP_DUMP_TIMES)]
BA_OUTPUT ?= observables_per_decade = 20$(newline)dumps_per_decade = 2$(newline)dump_times = [$(BA_DUMP_TIMES)]
EQUILIBRATE ?= 5

SCENES := $(OUT)/scenes
TABLES := $(OUT)/tables
KNOBS := $(OUT)/knobs
RUNS := $(if $(ARCHIVE),$(ARCHIVE),$(OUT)/runs)
PLOTS := $(PIPE)plots
VALUE := sh $(PIPE)tsv-value.sh

.DELETE_ON_ERROR:
# Keep every file made on the way (runs, tables): none is an 'intermediate'.
.SECONDARY:
.SECONDEXPANSION:
.PHONY: all figures reanalyze clean-figures

include $(PIPE)lib.mk

# ---------------------------------------------------------------- runs
# Run names: size_L<L>_s<seed> (Fig. 1), param_phi<phi>_r<r0>_d<delta>_s<seed>
# (Fig. 2), snap_s<seed> (Figs. 3-5), ba_phi<phi>_s<seed> (aggregation).
# A size run's end time is SIZE_T_END unless SIZE_T_END_L<L> is set, its seeds
# SIZE_SEEDS unless SIZE_SEEDS_L<L> is (small boxes are cheap; SIZE_SEEDS
# given on the command line applies to every L); a Fig. 2
# run's box side is PARAM_L unless PARAM_L_<set> is set (e.g.
# PARAM_L_phi0.052_r0.1_d1e-4: dilute gases cluster later and need larger boxes),
# its end time PARAM_T_END unless PARAM_T_END_<set> is.
size_t_end = $(or $(SIZE_T_END_L$(1)),$(SIZE_T_END))
size_seeds = $(if $(filter command line,$(origin SIZE_SEEDS)),$(SIZE_SEEDS),$(or $(SIZE_SEEDS_L$(1)),$(SIZE_SEEDS)))
param_name = phi$(1)_r$(2)_d$(3)
param_l = $(or $(PARAM_L_$(1)),$(PARAM_L))
param_t_end = $(or $(PARAM_T_END_$(1)),$(PARAM_T_END))
PARAM_SETS := $(sort $(foreach p,$(PARAM_PHIS),$(call param_name,$(p),$(R0),$(DELTA))) \
                     $(foreach r,$(PARAM_R0S),$(call param_name,$(PHI),$(r),$(DELTA))) \
                     $(foreach d,$(PARAM_DELTAS),$(call param_name,$(PHI),$(R0),$(d))))
# The snapshot run of Figs. 3-5 is the paper's gas; when Fig. 2 has that gas in
# the same box, to the same end time and with the same seed, it is the same
# trajectory: that Fig. 2 run adds the snapshot times to its dumps and serves
# both (SNAP_TWIN is its name), instead of being simulated twice.
BASE_SET := $(call param_name,$(PHI),$(R0),$(DELTA))
SNAP_TWIN := $(if $(and $(filter $(BASE_SET),$(PARAM_SETS)),$(filter $(SNAP_L),$(call param_l,$(BASE_SET))),$(filter \
  $(SNAP_T_END),$(call param_t_end,$(BASE_SET))),$(filter $(SNAP_SEED),$(PARAM_SEEDS))),param_$(BASE_SET)_s$(SNAP_SEED))
param_output = $(PARAM_OUTPUT)$(if $(filter $(SNAP_TWIN),param_$(1)_s$(2)),$(newline)dump_times = [$(SNAP_DUMP_TIMES)])

# $(call gas_scene,NAME,L,phi,r0,delta,t_end,seed,OUTPUT)
define gas_scene
# $(1): written by pipelines/common.mk (SCALE = $(SCALE)); the run is
#   coolgas-simulate $(1).toml -o $(1).h5
[system]
L = $(2)
phi = $(3)
seed = $(7)
equilibrate = $(EQUILIBRATE)

[collision]
model = "inelastic"
r0 = $(4)
delta = $(5)

[run]
t_end = $(6)

[output]
$(8)
endef

# $(call ba_scene,NAME,L,phi,t_end,seed,OUTPUT): ballistic aggregation (the
# paper's BA: colliding spheres merge, volumes add, momentum conserved).
define ba_scene
# $(1): written by pipelines/common.mk (SCALE = $(SCALE)); the run is
#   coolgas-simulate $(1).toml -o $(1).h5
[system]
L = $(2)
phi = $(3)
seed = $(5)
equilibrate = $(EQUILIBRATE)

[collision]
model = "aggregation"

[run]
t_end = $(4)

[output]
$(6)
endef

ifeq ($(ARCHIVE),)
# Scenes: written now, only where their text changed.
$(foreach L,$(SIZE_L),$(foreach s,$(call size_seeds,$(L)),$(call keep,$(SCENES)/size_L$(L)_s$(s).toml,$(call \
  gas_scene,size_L$(L)_s$(s),$(L),$(PHI),$(R0),$(DELTA),$(call size_t_end,$(L)),$(s),$(ENERGY_OUTPUT)))))
$(foreach p,$(PARAM_SETS),$(foreach s,$(PARAM_SEEDS),$(call keep,$(SCENES)/param_$(p)_s$(s).toml,$(call \
  gas_scene,param_$(p)_s$(s),$(call param_l,$(p)),$(call field,phi,x_$(p)),$(call field,r,x_$(p)),$(call \
  field,d,x_$(p)),$(call param_t_end,$(p)),$(s),$(call param_output,$(p),$(s))))))
ifeq ($(SNAP_TWIN),)
$(call keep,$(SCENES)/snap_s$(SNAP_SEED).toml,$(call \
  gas_scene,snap_s$(SNAP_SEED),$(SNAP_L),$(PHI),$(R0),$(DELTA),$(SNAP_T_END),$(SNAP_SEED),$(SNAP_OUTPUT)))
endif
ifeq ($(BA),1)
$(foreach p,$(BA_PHIS),$(call keep,$(SCENES)/ba_phi$(p)_s$(BA_SEED).toml,$(call \
  ba_scene,ba_phi$(p)_s$(BA_SEED),$(BA_L),$(p),$(BA_T_END),$(BA_SEED),$(BA_OUTPUT))))
endif

size_runs = $(foreach s,$(call size_seeds,$(1)),$(RUNS)/size_L$(1)_s$(s).h5)
param_runs = $(foreach s,$(PARAM_SEEDS),$(RUNS)/param_$(1)_s$(s).h5)
SNAP_RUN := $(RUNS)/$(or $(SNAP_TWIN),snap_s$(SNAP_SEED)).h5
BA_RUNS := $(if $(filter 1,$(BA)),$(foreach p,$(BA_PHIS),$(RUNS)/ba_phi$(p)_s$(BA_SEED).h5))

# One run: its scene in, its trajectory out (and its wall time in NAME.wall_s).
$(RUNS)/%.h5: $(SCENES)/%.toml
	$(simulate)
else
# Reanalysis: the runs are whatever the archive holds, found by name; there is
# no rule that makes a run, so nothing can be simulated.
archived := $(notdir $(wildcard $(ARCHIVE)/*.h5))
SIZE_L := $(call numeric_sort,$(sort $(foreach f,$(filter size_%,$(archived)),$(call field,L,$(f)))))
size_runs = $(sort $(wildcard $(RUNS)/size_L$(1)_s*.h5))
PARAM_SETS := $(sort $(foreach f,$(filter param_%,$(archived)),$(call \
  param_name,$(call field,phi,$(f)),$(call field,r,$(f)),$(call field,d,$(f)))))
PARAM_PHIS := $(sort $(foreach p,$(PARAM_SETS),$(if $(and $(filter $(R0),$(call field,r,x_$(p))),$(filter \
  $(DELTA),$(call field,d,x_$(p)))),$(call field,phi,x_$(p)))))
PARAM_R0S := $(sort $(foreach p,$(PARAM_SETS),$(if $(and $(filter $(PHI),$(call field,phi,x_$(p))),$(filter \
  $(DELTA),$(call field,d,x_$(p)))),$(call field,r,x_$(p)))))
PARAM_DELTAS := $(sort $(foreach p,$(PARAM_SETS),$(if $(and $(filter $(PHI),$(call field,phi,x_$(p))),$(filter \
  $(R0),$(call field,r,x_$(p)))),$(call field,d,x_$(p)))))
param_runs = $(sort $(wildcard $(RUNS)/param_$(1)_s*.h5))
SNAP_RUN := $(firstword $(sort $(wildcard $(RUNS)/snap_s*.h5)) $(wildcard $(RUNS)/param_$(BASE_SET)_s$(SNAP_SEED).h5))
BA_RUNS := $(sort $(wildcard $(RUNS)/ba_phi*.h5))
BA_PHIS := $(foreach f,$(BA_RUNS),$(call field,phi,$(f)))
BA := $(if $(BA_RUNS),1,0)
endif

# ---------------------------------------------------------------- figures
FIGURES := $(OUT)/fig1_energy_size.png $(OUT)/fig2_energy_parameters.png $(OUT)/fig3_clusters.png \
           $(OUT)/fig4_largest_mass.png $(OUT)/fig5_velocity.png $(OUT)/smoluchowski.png $(OUT)/structure.png $(OUT)/fields.png
RESULTS := $(FIGURES) $(OUT)/exponents.tsv $(OUT)/robustness.tsv $(OUT)/exponents.md

# No recipes here, so that 'make -q' after a finished run exits 0. The longest
# run (Figs. 3-5) is listed first so that make -j starts it first.
all: $(SNAP_RUN) $(RESULTS)
figures: $(SNAP_RUN) $(RESULTS)

# Redraw every figure from archived runs: make reanalyze ARCHIVE=dir [OUT=dir2]
reanalyze:
ifeq ($(ARCHIVE),)
	@echo "usage: make reanalyze ARCHIVE=folder-of-runs [OUT=folder]  (runs named as in OUT/runs)"; exit 2
else
	@test -n "$(SIZE_L)$(PARAM_SETS)$(SNAP_RUN)" || { echo "reanalyze: no runs named size_*, param_*, snap_* in $(ARCHIVE)"; exit 2; }
	$(MAKE) -f $(firstword $(MAKEFILE_LIST)) ARCHIVE=$(ARCHIVE) OUT=$(OUT) SCALE=$(SCALE) figures
endif

clean-figures:
	rm -rf $(TABLES) $(KNOBS) $(RESULTS)

# ---- Fig. 1: E(t) for several L, power-law fit, finite-size collapse (paper Eq. 2)
SIZE_TABLES := $(foreach L,$(SIZE_L),$(TABLES)/energy_size_L$(L).tsv)
L_MAX := $(lastword $(call numeric_sort,$(SIZE_L)))

$(TABLES)/energy_size_L%.tsv: $$(call size_runs,$$*)
	@mkdir -p $(@D)
	$(BIN)/coolgas-energy $^ > $@

$(TABLES)/energy_param_%.tsv: $$(call param_runs,$$*)
	@mkdir -p $(@D)
	$(BIN)/coolgas-energy $^ > $@

# Unweighted, as the single-seed fits of Fig. 2: weights 1/E_err^2 from a few
# seeds are nearly infinite wherever the seeds happen to agree, and those
# points then decide (at L = 68 with two seeds: theta = 1.237 +- 0.0001 at
# chi^2/dof = 270, the seeds alone 1.190 and 1.223).
$(TABLES)/fit_size_Lmax.tsv: $(TABLES)/energy_size_L$(L_MAX).tsv $(call knob,theta,--no-weights $(THETA_WINDOW))
	$(BIN)/coolgas-fit --power --no-weights --t-window $(THETA_WINDOW) $< > $@

# E(t) of each run alone: the collapse resamples whole runs for its errors
# (a jackknife over seeds; one table per L would treat times as independent).
$(TABLES)/energy_run_%.tsv: $(RUNS)/%.h5
	@mkdir -p $(@D)
	$(BIN)/coolgas-energy $< > $@
SIZE_RUN_TABLES := $(foreach L,$(SIZE_L),$(patsubst $(RUNS)/%.h5,$(TABLES)/energy_run_%.tsv,$(call size_runs,$(L))))

# COLLAPSE_WEIGHTS: seeds weighs the collapse by the scatter of each L's runs
# (coolgas-collapse --weights; needs two or more seeds of every L), none not.
COLLAPSE_WEIGHTS ?= none
COLLAPSE_ARGS := --optimize --bootstrap $(COLLAPSE_BOOTSTRAP) --seed 1 --t-window $(COLLAPSE_T_WINDOW) \
                 --eta-window $(COLLAPSE_ETA_WINDOW) --weights $(COLLAPSE_WEIGHTS)
$(TABLES)/collapse.tsv: $(SIZE_RUN_TABLES) $(call knob,collapse,$(COLLAPSE_ARGS))
	$(BIN)/coolgas-collapse $(COLLAPSE_ARGS) $(SIZE_RUN_TABLES) > $@

# The paper's method (its Fig. 1: E L^3 against t/L^(5/2)): z theta held at
# COLLAPSE_Z_THETA = d = 3 and z alone fitted, the same runs, window and
# weights; the exponent table gives its z beside the free fit's, and eta
# from it: its x = t/L^z reaches further than the free fit's where that z is
# larger (coolgas-collapse --z-theta). Started at z = 2.5: the search for z
# alone needs no better start.
COLLAPSE_Z_THETA ?= 3
COLLAPSE_Z_THETA_ARGS := $(COLLAPSE_ARGS) --z-theta $(COLLAPSE_Z_THETA) --z 2.5
$(TABLES)/collapse_z_theta.tsv: $(SIZE_RUN_TABLES) $(call knob,collapse_z_theta,$(COLLAPSE_Z_THETA_ARGS))
	$(BIN)/coolgas-collapse $(COLLAPSE_Z_THETA_ARGS) $(SIZE_RUN_TABLES) > $@

# The paper's own collapse, theta = 6/5 and z = 5/2, for comparison.
$(TABLES)/collapse_paper.tsv: $(SIZE_TABLES)
	$(BIN)/coolgas-collapse --theta 1.2 --z 2.5 --t-window $(COLLAPSE_T_WINDOW) $(SIZE_TABLES) > $@

$(OUT)/fig1_energy_size.png: $(SIZE_TABLES) $(TABLES)/fit_size_Lmax.tsv $(TABLES)/collapse.tsv \
    $(TABLES)/collapse_paper.tsv $(PLOTS)/fig1_energy_size.gp
	for o in $@ $(@:.png=.pdf); do gnuplot -e "tables='$(SIZE_TABLES)'; fit='$(TABLES)/fit_size_Lmax.tsv'; collapse='$(TABLES)/collapse.tsv'; \
	  paper='$(TABLES)/collapse_paper.tsv'; out='$$o'" $(PLOTS)/fig1_energy_size.gp || exit 1; done

# ---- Fig. 2: E(t) for several phi, r0, delta, each with its fitted theta
PARAM_TABLES := $(foreach p,$(PARAM_SETS),$(TABLES)/energy_param_$(p).tsv)
PARAM_FITS := $(foreach p,$(PARAM_SETS),$(TABLES)/fit_param_$(p).tsv)
panel_tables = $(foreach v,$(2),$(TABLES)/energy_param_$(call param_name,$(if $(filter phi,$(1)),$(v),$(PHI)),$(if \
  $(filter r,$(1)),$(v),$(R0)),$(if $(filter d,$(1)),$(v),$(DELTA))).tsv)

# Each parameter set's scaling regime has its own window: PARAM_FIT_WINDOW_<set>
# (e.g. PARAM_FIT_WINDOW_phi0.052_r0.1_d1e-4) where the scale sets one, else PARAM_FIT_WINDOW.
param_window = $(or $(PARAM_FIT_WINDOW_$(1)),$(PARAM_FIT_WINDOW))
# (the knob files are written now, while make reads this file)
PARAM_FIT_KNOBS := $(foreach p,$(PARAM_SETS),$(call knob,param_fit_$(p),$(call param_window,$(p))))
$(TABLES)/fit_param_%.tsv: $(TABLES)/energy_param_%.tsv $(KNOBS)/param_fit_%.txt
	$(BIN)/coolgas-fit --power --t-window $(call param_window,$*) $< > $@

$(OUT)/fig2_energy_parameters.png: $(PARAM_TABLES) $(PARAM_FITS) $(PLOTS)/fig2_energy_parameters.gp
	for o in $@ $(@:.png=.pdf); do gnuplot -e "phi_tables='$(call panel_tables,phi,$(PARAM_PHIS))'; phis='$(PARAM_PHIS)'; \
	  r0_tables='$(call panel_tables,r,$(PARAM_R0S))'; r0s='$(PARAM_R0S)'; \
	  delta_tables='$(call panel_tables,d,$(PARAM_DELTAS))'; deltas='$(PARAM_DELTAS)'; \
	  phi0='$(PHI)'; r00='$(R0)'; delta0='$(DELTA)'; L='$(PARAM_L)'; out='$$o'" \
	  $(PLOTS)/fig2_energy_parameters.gp || exit 1; done

# ---- Figs. 3 and 4 by the contact definition beside the unit cells: its
# tables in $(TABLES)/contact/ (pipelines/contact-clusters.mk; the scale file
# may set CONTACT_DEFINITION, CONTACT_NM_FIT_WINDOW).
include $(PIPE)contact-clusters.mk

# ---- Fig. 3: snapshot of the gas, scaled cluster-mass distribution N(m,t)
$(TABLES)/snapshot_gas.png: $(SNAP_RUN) $(call knob,snapshot,$(SNAPSHOT_TIME))
	@mkdir -p $(@D)
	$(BIN)/coolgas-snapshot $< --time $(SNAPSHOT_TIME) --size 700 --force -o $@ > $(TABLES)/snapshot_gas.tsv

$(TABLES)/nm_gas.tsv: $(SNAP_RUN) $(call knob,nm_times,$(NM_TIMES))
	@mkdir -p $(@D)
	$(BIN)/coolgas-clusters $< $(foreach t,$(NM_TIMES),--time $(t)) > $@

# Power-law fit of N(m) below the largest cluster, at the last of NM_TIMES.
$(TABLES)/fit_nm_gas.tsv: $(SNAP_RUN) $(call knob,nm_fit,$(lastword $(NM_TIMES)) $(NM_FIT_WINDOW))
	@mkdir -p $(@D)
	$(BIN)/coolgas-clusters $< --time $(lastword $(NM_TIMES)) \
	  | $(BIN)/coolgas-fit --power --t-column m --e-column N --no-weights --t-window $(NM_FIT_WINDOW) - > $@

ifeq ($(BA),1)
BA_SNAP := $(lastword $(BA_RUNS))
$(TABLES)/snapshot_ba.png: $(BA_SNAP) $(call knob,ba_snapshot,$(BA_SNAPSHOT_TIME))
	@mkdir -p $(@D)
	$(BIN)/coolgas-snapshot $< --time $(BA_SNAPSHOT_TIME) --size 700 --force -o $@ > $(TABLES)/snapshot_ba.tsv
$(TABLES)/nm_ba.tsv: $(BA_SNAP) $(call knob,ba_nm_times,$(BA_NM_TIMES))
	@mkdir -p $(@D)
	$(BIN)/coolgas-clusters $< $(foreach t,$(BA_NM_TIMES),--time $(t)) > $@
FIG3_BA := $(TABLES)/snapshot_ba.png $(TABLES)/nm_ba.tsv
# BA's N(m) below its mean mass M_avg at the last of BA_NM_TIMES, fitted as a
# power law (the paper: m^-0.2 there, then an exponential tail; the gas's is
# m^-2.7): the window is m = 1 to that frame's M_avg, read from the table.
$(TABLES)/fit_nm_ba.tsv: $(BA_SNAP) $(call knob,ba_nm_times,$(BA_NM_TIMES))
	@mkdir -p $(@D)
	$(BIN)/coolgas-clusters $< --time $(lastword $(BA_NM_TIMES)) > $@.clusters
	m=$$(sed -n 's/^# t = .*M_avg = \([^;]*\);.*/\1/p' $@.clusters | head -n 1); \
	  $(BIN)/coolgas-fit --power --t-column m --e-column N --no-weights --t-window 1:$$m $@.clusters > $@.partial
	mv $@.partial $@ && rm -f $@.clusters
BA_NM_FIT := $(TABLES)/fit_nm_ba.tsv
endif

$(OUT)/fig3_clusters.png: $(TABLES)/snapshot_gas.png $(TABLES)/nm_gas.tsv $(TABLES)/fit_nm_gas.tsv $(FIG3_BA) \
    $(CONTACT)/nm_gas.tsv $(CONTACT)/fit_nm_gas.tsv $(PLOTS)/fig3_clusters.gp
	for o in $@ $(@:.png=.pdf); do gnuplot -e "snapshot='$(TABLES)/snapshot_gas.png'; nm='$(TABLES)/nm_gas.tsv'; fit='$(TABLES)/fit_nm_gas.tsv'; \
	  contact_nm='$(CONTACT)/nm_gas.tsv'; contact_fit='$(CONTACT)/fit_nm_gas.tsv'; \
	  ba_snapshot='$(if $(FIG3_BA),$(TABLES)/snapshot_ba.png)'; ba_nm='$(if $(FIG3_BA),$(TABLES)/nm_ba.tsv)'; \
	  snapshot_time='$(SNAPSHOT_TIME)'; out='$$o'" $(PLOTS)/fig3_clusters.gp || exit 1; done

# ---- Fig. 4: largest cluster M_max(t), gas for each phi of Fig. 2 and the snapshot run, BA
# (the Fig. 2 run at PHI is the snapshot run's twin when both use one box: left out)
MMAX_PHIS := $(if $(filter $(SNAP_L),$(call param_l,$(BASE_SET))),$(filter-out $(PHI),$(PARAM_PHIS)),$(PARAM_PHIS))
MMAX_GAS_RUNS := $(SNAP_RUN) $(foreach p,$(MMAX_PHIS),$(firstword $(call param_runs,$(call param_name,$(p),$(R0),$(DELTA)))))
mmax_table = $(TABLES)/mmax_$(notdir $(basename $(1))).tsv
MMAX_GAS := $(foreach r,$(MMAX_GAS_RUNS),$(call mmax_table,$(r)))
MMAX_BA := $(foreach r,$(BA_RUNS),$(call mmax_table,$(r)))

$(TABLES)/mmax_%.tsv: $(RUNS)/%.h5
	@mkdir -p $(@D)
	$(BIN)/coolgas-clusters $< --series > $@

# The gas's M_max does not grow as a power law but jumps: its steepest rise
# (t_jump) and the onset of inhomogeneous cooling in the same run's E(t)
# (pipelines/mmax-jump.sh states the rules); for BA only the steepest rise is used.
$(TABLES)/jump_mmax_%.tsv: $(TABLES)/mmax_%.tsv $(TABLES)/energy_run_%.tsv $(PIPE)mmax-jump.sh
	sh $(PIPE)mmax-jump.sh $< $(TABLES)/energy_run_$*.tsv > $@
$(TABLES)/jump_mmax_ba_%.tsv: $(TABLES)/mmax_ba_%.tsv $(TABLES)/energy_ba_%.tsv $(PIPE)mmax-jump.sh
	sh $(PIPE)mmax-jump.sh $< $(TABLES)/energy_ba_$*.tsv > $@

# Aggregates grow as a power law from the start and outgrow small boxes early: their own window.
# The mean aggregate mass over the same window (the paper: exponent 1.06 at phi = 0.005 to 1.19 at 0.313).
ba_mass_fit = $(BIN)/coolgas-fit --power --t-column t --e-column $(1) --no-weights --t-window $(BA_MMAX_FIT_WINDOW)
$(TABLES)/fit_mmax_ba_%.tsv: $(TABLES)/mmax_ba_%.tsv $(call knob,ba_mmax_fit,$(BA_MMAX_FIT_WINDOW))
	$(call ba_mass_fit,M_max) $< > $@
$(TABLES)/fit_mavg_ba_%.tsv: $(TABLES)/mmax_ba_%.tsv $(call knob,ba_mmax_fit,$(BA_MMAX_FIT_WINDOW))
	$(call ba_mass_fit,M_avg) $< > $@

$(OUT)/fig4_largest_mass.png: $(MMAX_GAS) $(MMAX_BA) $(subst mmax_,jump_mmax_,$(MMAX_GAS)) \
    $(subst mmax_,fit_mmax_,$(MMAX_BA)) $(CONTACT_MMAX) $(subst mmax_,jump_mmax_,$(CONTACT_MMAX)) $(PLOTS)/fig4_largest_mass.gp
	for o in $@ $(@:.png=.pdf); do gnuplot -e "gas='$(MMAX_GAS)'; contact='$(CONTACT_MMAX)'; ba='$(MMAX_BA)'; \
	  ba_window='$(BA_MMAX_FIT_WINDOW)'; out='$$o'" \
	  $(PLOTS)/fig4_largest_mass.gp || exit 1; done

# ---- Fig. 5: Phi(y) early and late, kurtosis kappa(t), tails -ln Phi(y)
$(TABLES)/phi_early.tsv: $(SNAP_RUN) $(call knob,phi_early,$(PHI_EARLY_TIMES))
	@mkdir -p $(@D)
	$(BIN)/coolgas-velocity $< $(foreach t,$(PHI_EARLY_TIMES),--time $(t)) > $@
$(TABLES)/phi_late.tsv: $(SNAP_RUN) $(call knob,phi_late,$(PHI_LATE_TIMES))
	@mkdir -p $(@D)
	$(BIN)/coolgas-velocity $< $(foreach t,$(PHI_LATE_TIMES),--time $(t)) > $@
# The early tails, fitted by exponents.sh as -ln Phi = alpha y + c (kinetic theory's exponential tail).
$(TABLES)/tail_early.tsv: $(SNAP_RUN) $(call knob,phi_early,$(PHI_EARLY_TIMES))
	@mkdir -p $(@D)
	$(BIN)/coolgas-velocity $< --tail $(foreach t,$(PHI_EARLY_TIMES),--time $(t)) > $@
$(TABLES)/velocity_series.tsv: $(SNAP_RUN)
	@mkdir -p $(@D)
	$(BIN)/coolgas-velocity $< --series > $@
$(TABLES)/tail_gas.tsv: $(SNAP_RUN) $(call knob,phi_late,$(PHI_LATE_TIMES))
	@mkdir -p $(@D)
	$(BIN)/coolgas-velocity $< --tail $(foreach t,$(PHI_LATE_TIMES),--time $(t)) > $@

ifeq ($(BA),1)
$(TABLES)/tail_ba.tsv: $(lastword $(BA_RUNS)) $(call knob,ba_phi,$(BA_PHI_TIMES))
	@mkdir -p $(@D)
	$(BIN)/coolgas-velocity $< --tail $(foreach t,$(BA_PHI_TIMES),--time $(t)) > $@
FIG5_BA := $(TABLES)/tail_ba.tsv
endif

$(OUT)/fig5_velocity.png: $(TABLES)/phi_early.tsv $(TABLES)/phi_late.tsv $(TABLES)/velocity_series.tsv \
    $(TABLES)/tail_gas.tsv $(FIG5_BA) $(PLOTS)/fig5_velocity.gp
	for o in $@ $(@:.png=.pdf); do gnuplot -e "early='$(TABLES)/phi_early.tsv'; late='$(TABLES)/phi_late.tsv'; series='$(TABLES)/velocity_series.tsv'; \
	  tail_gas='$(TABLES)/tail_gas.tsv'; tail_ba='$(FIG5_BA)'; out='$$o'" $(PLOTS)/fig5_velocity.gp || exit 1; done
# Why alpha, beta and kappa differ from the paper: against t and fit window (pipelines/velocity-causes.mk).
include $(PIPE)velocity-causes.mk

# ---- Smoluchowski equation (paper Eqs. 3-4) beside the simulated gas
# Volume = N of the snapshot run (c_1(0) = 1), so its M_max is that of a system
# of the same size.
SMOL_ARGS = --kernel ballistic --M $(SMOL_M) --t-end $(SMOL_T_END) --time $(SMOL_TIMES)
$(TABLES)/smoluchowski_nm.tsv: $(TABLES)/mmax_$(notdir $(basename $(SNAP_RUN))).tsv $(call knob,smoluchowski,$(SMOL_ARGS))
	$(LAUNCH) $(BIN)/coolgas-smoluchowski $(SMOL_ARGS) --volume $$($(VALUE) $< N '#') \
	  --series-file $(TABLES)/smoluchowski_series.tsv > $@
	touch $(TABLES)/smoluchowski_series.tsv
# Written by the step above (touched after it, so it is never older).
$(TABLES)/smoluchowski_series.tsv: $(TABLES)/smoluchowski_nm.tsv
	@test -f $@ || { echo "$@ missing: remove $< and rerun"; exit 1; }
$(TABLES)/fit_smoluchowski_%.tsv: $(TABLES)/smoluchowski_series.tsv $(call knob,smoluchowski_fit,$(SMOL_FIT_WINDOW))
	$(BIN)/coolgas-fit --power --t-column t --e-column $* --no-weights --t-window $(SMOL_FIT_WINDOW) $< > $@

$(OUT)/smoluchowski.png: $(TABLES)/smoluchowski_nm.tsv $(TABLES)/smoluchowski_series.tsv \
    $(TABLES)/fit_smoluchowski_M_max.tsv $(TABLES)/fit_smoluchowski_M_avg.tsv $(TABLES)/nm_gas.tsv \
    $(call mmax_table,$(SNAP_RUN)) $(PLOTS)/smoluchowski.gp
	for o in $@ $(@:.png=.pdf); do gnuplot -e "nm='$(TABLES)/smoluchowski_nm.tsv'; series='$(TABLES)/smoluchowski_series.tsv'; \
	  fit_max='$(TABLES)/fit_smoluchowski_M_max.tsv'; fit_avg='$(TABLES)/fit_smoluchowski_M_avg.tsv'; \
	  gas_nm='$(TABLES)/nm_gas.tsv'; gas_series='$(call mmax_table,$(SNAP_RUN))'; out='$$o'" $(PLOTS)/smoluchowski.gp || exit 1; done

# ---- theta_BA: E(t) of each aggregation run (per initial particle) and its power law
BA_FITS := $(foreach r,$(BA_RUNS),$(TABLES)/fit_energy_$(notdir $(basename $(r))).tsv)
$(TABLES)/energy_ba_%.tsv: $(RUNS)/ba_%.h5
	@mkdir -p $(@D)
	$(BIN)/coolgas-energy $< > $@
$(TABLES)/fit_energy_ba_%.tsv: $(TABLES)/energy_ba_%.tsv $(call knob,ba_theta_fit,$(BA_THETA_WINDOW))
	$(BIN)/coolgas-fit --power --t-window $(BA_THETA_WINDOW) $< > $@

# ---- The growing length: S(k, t), its dynamic-scaling collapse, L_t(t) and L_C(t)
# with their fits, d_f(t) (pipelines/structure.mk; the scale file names the runs
# STRUCTURE_GAS, STRUCTURE_BA and sets LT_FIT_WINDOW, COLLAPSE_FROM; a scale
# that sets none gets the snapshot run and structure.mk's defaults).
STRUCTURE_GAS ?= $(notdir $(basename $(SNAP_RUN)))
ifneq ($(ARCHIVE),)
# Reanalysis: the scale's runs where the archive has them, else its snapshot run.
STRUCTURE_GAS := $(or $(foreach r,$(STRUCTURE_GAS),$(if $(wildcard $(RUNS)/$(r).h5),$(r))),$(notdir $(basename $(SNAP_RUN))))
STRUCTURE_BA := $(foreach r,$(STRUCTURE_BA),$(if $(wildcard $(RUNS)/$(r).h5),$(r)))
endif
ifneq ($(BA),1)
STRUCTURE_BA :=
endif
include $(PIPE)structure.mk

# ---- The flow fields: vortices, then clusters (pipelines/fields.mk; the scale
# file may set FIELDS_RUN, FIELDS_TIMES, FIELDS_CELL).
include $(PIPE)fields.mk

# ---- The measured exponents, one row (exponents.tsv) and against the paper (exponents.md)
EXPONENT_INPUTS := $(TABLES)/collapse.tsv $(TABLES)/collapse_z_theta.tsv $(TABLES)/fit_size_Lmax.tsv $(TABLES)/fit_nm_gas.tsv \
  $(TABLES)/nm_gas.tsv $(call mmax_table,$(SNAP_RUN)) $(subst mmax_,jump_mmax_,$(MMAX_GAS) $(MMAX_BA)) \
  $(subst mmax_,fit_mmax_,$(MMAX_BA)) $(subst mmax_,fit_mavg_,$(MMAX_BA)) $(FIG5_BA) \
  $(TABLES)/velocity_series.tsv $(TABLES)/tail_early.tsv \
  $(TABLES)/fit_smoluchowski_M_max.tsv $(TABLES)/fit_smoluchowski_M_avg.tsv $(PARAM_FITS) \
  $(foreach r,$(STRUCTURE_GAS),$(TABLES)/lt_$(r).tsv $(TABLES)/fit_lt_$(r).tsv $(TABLES)/fit_lc_$(r).tsv) $(CONTACT_TABLES)
$(OUT)/exponents.tsv: $(EXPONENT_INPUTS) $(BA_FITS) $(BA_NM_FIT) $(PIPE)tsv-value.sh $(PIPE)exponents.sh \
    $(PIPE)row-verdict.sh
	sh $(PIPE)exponents.sh $(TABLES) $(notdir $(basename $(SNAP_RUN))) "$(lastword $(PHI_LATE_TIMES))" \
	  $(L_MAX) $(SNAP_L) "$(PARAM_SETS)" "$(BA_FITS)" "$(STRUCTURE_GAS)" \
	  "$(notdir $(basename $(MMAX_GAS_RUNS)))" "$(notdir $(basename $(BA_RUNS)))" > $@

# Fig. 1's collapse under other analysis choices, side by side (pipelines/robustness.mk).
include $(PIPE)robustness.mk
# What decides theta of Fig. 2's sets, theta_BA and the largest cluster's share (pipelines/theta-causes.mk).
include $(PIPE)theta-causes.mk

$(OUT)/exponents.md: $(OUT)/exponents.tsv $(OUT)/robustness.tsv $(PIPE)exponents-md.sh $(PIPE)verdicts.sh
	sh $(PIPE)exponents-md.sh $< "$(SCALE)" $(OUT)/robustness.tsv > $@
	@echo "$(SCALE) pipeline: figures and tables in $(OUT)"; cat $@
