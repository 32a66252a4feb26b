# The growing length and the shape of clusters (coolgas-structure, coolgas-shape)
# for the figure pipelines: S(k, t) and its dynamic-scaling collapse, L_t(t)
# with its power-law fit (z from L_t ~ t^{1/z}), and d_f(t) of gas and BA.
# Included by pipelines/common.mk, whose variables it uses:
#   BIN  RUNS  TABLES  OUT  PLOTS  (and KNOBS, knob from pipelines/lib.mk, when there)
# and its own, set by each scale file (pipelines/scales/*.mk):
#   STRUCTURE_GAS   names of gas runs ($(RUNS)/NAME.h5) to draw, e.g. snap_s1;
#                   they need several dumps per decade over LT_FIT_WINDOW
#   STRUCTURE_BA    names of ballistic-aggregation runs for the d_f panel (may be empty)
#   LT_FIT_WINDOW   t window of the fits L_t = A t^{1/z} and L_C = A t^{1/z}, e.g. 20:300
#                   (after clusters form, before the length nears the box)
#   COLLAPSE_FROM   earliest t drawn in the S(k, t) collapse
# Standalone: make -f pipelines/structure.mk structure BIN=build/bin RUNS=... TABLES=... OUT=... \
#             PLOTS=pipelines/plots STRUCTURE_GAS=gas LT_FIT_WINDOW=20:300 COLLAPSE_FROM=20
LT_FIT_WINDOW ?= 20:300
COLLAPSE_FROM ?= 20
STRUCTURE_BA ?=
STRUCTURE_TABLES := $(foreach r,$(STRUCTURE_GAS),$(TABLES)/sk_$(r).tsv $(TABLES)/lt_$(r).tsv \
                      $(TABLES)/fit_lt_$(r).tsv $(TABLES)/fit_lc_$(r).tsv) \
                    $(foreach r,$(STRUCTURE_GAS) $(STRUCTURE_BA),$(TABLES)/shape_$(r).tsv)
# A changed window refits (the knob file; standalone there is none).
LT_FIT_KNOB := $(if $(value knob),$(call knob,lt_fit,$(LT_FIT_WINDOW)))

.PHONY: structure
structure: $(OUT)/structure.png

$(TABLES)/sk_%.tsv: $(RUNS)/%.h5
	@mkdir -p $(@D)
	$(BIN)/coolgas-structure $< > $@
$(TABLES)/lt_%.tsv: $(RUNS)/%.h5
	@mkdir -p $(@D)
	$(BIN)/coolgas-structure --series $< > $@
# L_t = A t^{1/z}: coolgas-fit's E = A t^-theta with theta = -1/z.
$(TABLES)/fit_lt_%.tsv: $(TABLES)/lt_%.tsv $(LT_FIT_KNOB)
	$(BIN)/coolgas-fit --power --t-window $(LT_FIT_WINDOW) --e-column L_t --no-weights $< > $@
$(TABLES)/fit_lc_%.tsv: $(TABLES)/lt_%.tsv $(LT_FIT_KNOB)
	$(BIN)/coolgas-fit --power --t-window $(LT_FIT_WINDOW) --e-column L_C --no-weights $< > $@
$(TABLES)/shape_%.tsv: $(RUNS)/%.h5
	@mkdir -p $(@D)
	$(BIN)/coolgas-shape --series $< > $@

# PNG and PDF (plots/common.gp's term() picks the terminal from the name).
$(OUT)/structure.png: $(STRUCTURE_TABLES) $(PLOTS)/structure.gp $(if $(value knob),$(call knob,collapse_from,$(COLLAPSE_FROM)))
	@mkdir -p $(@D)
	for o in $@ $(@:.png=.pdf); do gnuplot -e "sk='$(TABLES)/sk_$(firstword $(STRUCTURE_GAS)).tsv'; \
	  lt='$(foreach r,$(STRUCTURE_GAS),$(TABLES)/lt_$(r).tsv)'; \
	  shape_gas='$(foreach r,$(STRUCTURE_GAS),$(TABLES)/shape_$(r).tsv)'; \
	  shape_ba='$(foreach r,$(STRUCTURE_BA),$(TABLES)/shape_$(r).tsv)'; \
	  window='$(LT_FIT_WINDOW)'; collapse_from=$(COLLAPSE_FROM); out='$$o'" $(PLOTS)/structure.gp || exit 1; done
