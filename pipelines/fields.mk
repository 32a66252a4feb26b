# The flow fields behind clustering (coolgas-fields): vortices, then clusters.
# Slabs of the density and of the vorticity at three times, and the shear
# (transverse) and sound (longitudinal) flow energies over their noise levels
# beside the density's variance over its start, against t.
# Included by pipelines/common.mk, whose variables it uses:
#   BIN  TABLES  RUNS  OUT  PLOTS
# and its own, which a scale file may set:
#   FIELDS_RUN    the run ($(RUNS)/NAME.h5) drawn; default the first of STRUCTURE_GAS
#   FIELDS_TIMES  the three times of the slabs [1/omega0]; the dumps nearest them
#   FIELDS_CELL   the cell side [sigma] (coolgas-fields --cell)
# Standalone: make -f pipelines/fields.mk fields BIN=build/bin RUNS=... TABLES=... OUT=... \
#             PLOTS=pipelines/plots FIELDS_RUN=gas
FIELDS_RUN ?= $(firstword $(STRUCTURE_GAS))
FIELDS_TIMES ?= 10 100 1000
FIELDS_CELL ?= 4
FIELDS_KNOB := $(if $(value knob),$(call knob,fields,$(FIELDS_CELL) $(FIELDS_TIMES)))

.PHONY: fields
fields: $(OUT)/fields.png

$(TABLES)/fields_%.tsv: $(RUNS)/%.h5 $(FIELDS_KNOB)
	@mkdir -p $(@D)
	$(BIN)/coolgas-fields --cell $(FIELDS_CELL) $< > $@
$(TABLES)/slab_%.tsv: $(RUNS)/%.h5 $(FIELDS_KNOB)
	@mkdir -p $(@D)
	$(BIN)/coolgas-fields --slab --cell $(FIELDS_CELL) $(foreach t,$(FIELDS_TIMES),--time $(t)) $< > $@

# PNG and PDF (plots/common.gp's term() picks the terminal from the name).
$(OUT)/fields.png: $(TABLES)/fields_$(FIELDS_RUN).tsv $(TABLES)/slab_$(FIELDS_RUN).tsv $(PLOTS)/fields.gp
	@mkdir -p $(@D)
	for o in $@ $(@:.png=.pdf); do gnuplot -e "series='$(TABLES)/fields_$(FIELDS_RUN).tsv'; \
	  slab='$(TABLES)/slab_$(FIELDS_RUN).tsv'; out='$$o'" $(PLOTS)/fields.gp || exit 1; done
