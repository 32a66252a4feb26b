# Figs. 3 and 4 by the second cluster definition, particles in contact
# (coolgas-clusters --definition contact:CUTOFF), beside the paper's unit
# cells: at the paper's phi = 0.208 the unit cells are occupied above the
# site-percolation threshold and their largest cluster spans the box from
# t = 0, so N(m), tau and the jump of M_max mean little by them there; the
# contact clusters start far below percolation (coolgas-clusters --help,
# pipelines/contact-percolation.sh). The tables are those of the unit cells,
# under the same names, in $(TABLES)/contact/:
#   nm_gas.tsv, fit_nm_gas.tsv  N(m) of the snapshot run at NM_TIMES, its
#       power-law fit at the last of them (Fig. 3; the tau row)
#   mmax_RUN.tsv, jump_mmax_RUN.tsv  M_max(t) of each gas run of Fig. 4 and
#       its steepest rise (pipelines/mmax-jump.sh, against the same run's E(t))
# Ballistic aggregation has no second definition: its clusters are its
# aggregates (coolgas-clusters refuses --definition contact on its files).
# Included by pipelines/common.mk, whose variables it uses:
#   BIN  TABLES  RUNS  SNAP_RUN  NM_TIMES  NM_FIT_WINDOW  MMAX_GAS_RUNS  PIPE
# and its own, which a scale file may set:
#   CONTACT_DEFINITION     the definition (default contact:1.1, the tool's
#                          default bond length, 1.1 sigma)
#   CONTACT_NM_FIT_WINDOW  the m window of its N(m) fit (default NM_FIT_WINDOW)
CONTACT_DEFINITION ?= contact:1.1
CONTACT_NM_FIT_WINDOW ?= $(NM_FIT_WINDOW)
CONTACT := $(TABLES)/contact
contact_clusters = $(BIN)/coolgas-clusters --definition $(CONTACT_DEFINITION)
CONTACT_KNOB := $(call knob,contact,$(CONTACT_DEFINITION))

$(CONTACT)/nm_gas.tsv: $(SNAP_RUN) $(CONTACT_KNOB) $(call knob,nm_times,$(NM_TIMES))
	@mkdir -p $(@D)
	$(contact_clusters) $< $(foreach t,$(NM_TIMES),--time $(t)) > $@
$(CONTACT)/fit_nm_gas.tsv: $(SNAP_RUN) $(CONTACT_KNOB) \
    $(call knob,contact_nm_fit,$(lastword $(NM_TIMES)) $(CONTACT_NM_FIT_WINDOW))
	@mkdir -p $(@D)
	$(contact_clusters) $< --time $(lastword $(NM_TIMES)) \
	  | $(BIN)/coolgas-fit --power --t-column m --e-column N --no-weights --t-window $(CONTACT_NM_FIT_WINDOW) - > $@

$(CONTACT)/mmax_%.tsv: $(RUNS)/%.h5 $(CONTACT_KNOB)
	@mkdir -p $(@D)
	$(contact_clusters) $< --series > $@
$(CONTACT)/jump_mmax_%.tsv: $(CONTACT)/mmax_%.tsv $(TABLES)/energy_run_%.tsv $(PIPE)mmax-jump.sh
	sh $(PIPE)mmax-jump.sh $< $(TABLES)/energy_run_$*.tsv > $@

# (expanded where used: MMAX_GAS_RUNS is set after this file is included)
CONTACT_MMAX = $(foreach r,$(MMAX_GAS_RUNS),$(CONTACT)/mmax_$(notdir $(basename $(r))).tsv)
CONTACT_TABLES = $(CONTACT)/nm_gas.tsv $(CONTACT)/fit_nm_gas.tsv $(CONTACT_MMAX) $(subst mmax_,jump_mmax_,$(CONTACT_MMAX))
