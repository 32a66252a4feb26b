# Included by the pipelines that plan their runs (pipelines/paper/Makefile,
# pipelines/workstation/Makefile), after ../common.mk.
# make estimate (in pipelines/paper or pipelines/workstation): the whole scale planned, one line
# per run (L N mem_GB hours dumps disk_GB peak_GB plan_cpu_h, by coolgas-simulate
# --estimate: a pilot run of each scene fed to the progress line's cost
# model, simulate/run/run_plan.h), then the totals: core-hours, the largest
# run's memory, disk, the longest run.
# It reads the scenes this pipeline would run (make writes them into
# $(OUT)/scenes when it reads common.mk; only the pilots are simulated, a
# fraction of a second each). plan_cpu_h is
# the run's expected CPU hours (--estimate's cpu_h, without the margin);
# measured_cpu_h beside it the CPU time of the run in OUT when it is complete
# (NAME.cpu_s of pipelines/timed-run.sh, '-' before; of a run made in
# slices, all of them but any killed by SIGKILL), so the plan stands beside what it cost.
# (sorted: the snapshot run may be a Fig. 2 run too, counted once)
ESTIMATE_RUNS := $(sort $(SNAP_RUN) $(foreach L,$(SIZE_L),$(call size_runs,$(L))) \
                 $(foreach p,$(PARAM_SETS),$(call param_runs,$(p))) $(BA_RUNS) $(CAUSES_RUNS))
.PHONY: estimate
estimate:
	@printf 'run\tL\tN\tmem_GB\thours\tdumps\tdisk_GB\tpeak_GB\tplan_cpu_h\tmeasured_cpu_h\n'
	@for run in $(notdir $(basename $(ESTIMATE_RUNS))); do \
	  printf '%s\t' $$run; \
	  plan=$$($(BIN)/coolgas-simulate --estimate $(SCENES)/$$run.toml) || exit 1; \
	  printf '%s' "$$plan" | tail -n 1 | cut -f1-8 | tr -d '\n'; \
	  measured=-; [ -f $(RUNS)/$$run.h5 ] && [ -f $(RUNS)/$$run.cpu_s ] && measured=$$(cat $(RUNS)/$$run.cpu_s); \
	  printf '\t%s\n' "$$measured"; \
	done | awk -F'\t' -v OFS='\t' '{ m = ($$10 == "-" ? "-" : sprintf("%.3f", $$10 / 3600)); print $$1, $$2, $$3, $$4, $$5, $$6, $$7, $$8, sprintf("%.3f", $$9), m } \
	  $$10 != "-" { done_plan += $$9; done_cpu += $$10 / 3600; done_runs++ } \
	  { hours += $$5; cpu += $$9; disk += $$7; if ($$8 > peak) { peak = $$8; mem = $$4; big = $$1 } if ($$5 > long) { long = $$5; longest = $$1 } } \
	  END { printf "total: %d runs, %.2f core-hours (%.1f with the 1.5 margin of a request); peak memory %.2f GB (%s; %d GB requested); disk %.0f GB; longest run %s, %.2g hours (%.2g requested)\n", \
	        NR, cpu, hours, peak, big, mem, disk, longest, long / 1.5, long; \
	        if (done_runs) printf "measured: %d runs complete in OUT took %.2f CPU hours, planned %.2f\n", done_runs, done_cpu, done_plan }'

# make run-list: each run of the scale, one a line: its name, its target as
# make names it and its scene (pipelines/cluster/submit-runs.sh submits each
# incomplete one as a job of its own).
.PHONY: run-list
run-list:
	@$(foreach r,$(ESTIMATE_RUNS),printf '%s\t%s\t%s\n' $(notdir $(basename $(r))) $(r) $(SCENES)/$(notdir $(basename $(r))).toml;)
