# size_ladder.awk: the box-size ladder of the simulator study, from
# simulator_runs.tsv (columns L delta seed t_end theta theta_err collisions
# cpu_s wall_s). For each L at the given delta (awk -v delta=...): the mean
# theta of its seeds, its standard error (seed spread / sqrt(seeds): the fit
# error treats one run's correlated times as independent), and the deviation
# from theta_ref, the mean theta of the largest L, with the two standard
# errors combined. Writes '# theta_ref' lines, then one row per L (ascending):
# L t_end seeds theta theta_err theta_sd error error_err cpu_s cpu_s_run.
NR == 1 || /^#/ || NF == 0 || $2 != delta { next }
{
  L = $1 + 0
  if (!(L in n)) { sizes[++count] = L; t_end[L] = $4 }
  n[L]++; sum[L] += $5; sum2[L] += $5 * $5; cpu[L] += $8
}
END {
  if (count == 0) { print "size_ladder.awk: no runs with delta = " delta > "/dev/stderr"; exit 2 }
  for (i = 2; i <= count; i++)  # insertion sort: a handful of sizes
    for (j = i; j > 1 && sizes[j] < sizes[j - 1]; j--) { t = sizes[j]; sizes[j] = sizes[j - 1]; sizes[j - 1] = t }
  for (i = 1; i <= count; i++) {
    L = sizes[i]; mean[L] = sum[L] / n[L]
    var = n[L] > 1 ? (sum2[L] - n[L] * mean[L] ^ 2) / (n[L] - 1) : 0
    sd[L] = var > 0 ? sqrt(var) : 0; sem[L] = sd[L] / sqrt(n[L])
  }
  ref = sizes[count]
  printf "# theta_ref: %.4f +- %.4f (mean of the %d seeds of L = %s, the largest L)\n", mean[ref], sem[ref], n[ref], ref
  printf "# error: theta - theta_ref; error_err: the standard errors of both combined (at L = %s: that of theta_ref)\n", ref
  printf "# cpu_s: summed CPU time of the seeds of L, seconds (one core); cpu_s_run: per run\n"
  for (i = 1; i <= count; i++) {
    L = sizes[i]
    err = L == ref ? sem[L] : sqrt(sem[L] ^ 2 + sem[ref] ^ 2)
    printf "%s\t%s\t%d\t%.4f\t%.4f\t%.4f\t%.4f\t%.4f\t%.2f\t%.2f\n", L, t_end[L], n[L], mean[L], sem[L], sd[L],
           mean[L] - mean[ref], err, cpu[L], cpu[L] / n[L]
  }
}
