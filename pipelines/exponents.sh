#!/bin/sh
# exponents.sh TABLES SNAP_RUN LATE_TIME
# Gathers the exponents a figure pipeline measured into one TSV row (the
# coolgas table format: provenance, column line, one row). TABLES is the
# pipeline's tables folder, SNAP_RUN the name of the run of Figs. 3-5 and
# LATE_TIME the time at which its late-time values are read.
set -e
tables=$1
snap=$2
late=$3
here=$(dirname "$0")
value() { sh "$here/tsv-value.sh" "$@"; }
# Column $2 of table $1 in the row whose t is nearest $3.
at_time() {
  awk -F '\t' -v want="$2" -v t="$3" '
    /^#/ { line = substr($0, 3); if (index(line, ":") == 0 && !header) { n = split(line, names, "\t"); for (i = 1; i <= n; i++) { if (names[i] == want) col = i; if (names[i] == "t") tc = i } header = 1 } next }
    NF > 0 { d = $tc - t; if (d < 0) d = -d; if (best == "" || d < best) { best = d; v = $col } }
    END { print v }' "$1"
}
collapse=$tables/collapse.tsv
printf '# tool: pipelines/exponents.sh\n'
printf '# input: %s\n' collapse.tsv fit_size_Lmax.tsv fit_nm_gas.tsv "mmax_$snap.tsv" velocity_series.tsv \
  fit_smoluchowski_M_max.tsv fit_smoluchowski_M_avg.tsv
printf '# late_time: %s\n' "$late"
printf '# theta\ttheta_err\tz\tz_err\teta\teta_err\tcollapse_quality\ttheta_Lmax\ttheta_Lmax_err'
printf '\tmass_exponent\tmass_exponent_err\tlargest_fraction\tmmax_exponent\tmmax_exponent_err'
printf '\tbeta_late\tbeta_late_err\tkappa_late\tsmol_mmax_exponent\tsmol_mavg_exponent\n'
# Growth exponents are minus the fitted decay exponent theta of coolgas-fit.
printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' \
  "$(value "$collapse" theta '#')" "$(value "$collapse" theta_err '#')" \
  "$(value "$collapse" z '#')" "$(value "$collapse" z_err '#')" \
  "$(value "$collapse" eta '#')" "$(value "$collapse" eta_err '#')" "$(value "$collapse" quality '#')" \
  "$(value "$tables/fit_size_Lmax.tsv" theta)" "$(value "$tables/fit_size_Lmax.tsv" theta_err)" \
  "$(value "$tables/fit_nm_gas.tsv" theta)" "$(value "$tables/fit_nm_gas.tsv" theta_err)" \
  "$(at_time "$tables/mmax_$snap.tsv" largest_fraction "$late")" \
  "$(awk "BEGIN { print -($(value "$tables/fit_mmax_$snap.tsv" theta)) }")" \
  "$(value "$tables/fit_mmax_$snap.tsv" theta_err)" \
  "$(at_time "$tables/velocity_series.tsv" beta "$late")" "$(at_time "$tables/velocity_series.tsv" beta_err "$late")" \
  "$(at_time "$tables/velocity_series.tsv" kappa "$late")" \
  "$(awk "BEGIN { print -($(value "$tables/fit_smoluchowski_M_max.tsv" theta)) }")" \
  "$(awk "BEGIN { print -($(value "$tables/fit_smoluchowski_M_avg.tsv" theta)) }")"
