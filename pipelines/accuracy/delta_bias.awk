# delta_bias.awk: what the cut-off delta costs and saves, from
# simulator_runs.tsv (columns L delta seed t_end theta theta_err collisions
# cpu_s wall_s) at one L (awk -v L=...). Every delta is run with the same
# seeds, i.e. the same initial states, so the bias theta(delta) -
# theta(delta_min) is averaged over seeds pairwise: the seed-to-seed scatter
# of theta, larger than the bias, cancels. Writes one row per delta (largest
# first): delta seeds theta theta_err bias bias_err collisions collisions_rel
# cpu_s_run, with errors the standard errors over seeds and collisions_rel
# the mean collisions relative to delta_min.
NR == 1 || /^#/ || NF == 0 || $1 != L { next }
{
  d = $2
  if (!(d in n)) deltas[++count] = d
  n[d]++; theta[d, $3] = $5; seeds[$3] = 1; coll[d] += $7; cpu[d] += $8; sum[d] += $5; sum2[d] += $5 * $5
}
function sem(s, s2, k,   v) { v = k > 1 ? (s2 - s * s / k) / (k - 1) / k : 0; return v > 0 ? sqrt(v) : 0 }
END {
  if (count == 0) { print "delta_bias.awk: no runs with L = " L > "/dev/stderr"; exit 2 }
  for (i = 2; i <= count; i++)  # insertion sort, largest delta first
    for (j = i; j > 1 && deltas[j] + 0 > deltas[j - 1] + 0; j--) { t = deltas[j]; deltas[j] = deltas[j - 1]; deltas[j - 1] = t }
  dmin = deltas[count]
  printf "# delta_min: %s\n# bias: theta(delta) - theta(delta_min), mean over the seeds run at both\n", dmin
  for (i = 1; i <= count; i++) {
    d = deltas[i]; k = 0; b = 0; b2 = 0
    for (s in seeds) if (((d, s) in theta) && ((dmin, s) in theta)) { x = theta[d, s] - theta[dmin, s]; k++; b += x; b2 += x * x }
    printf "%s\t%d\t%.4f\t%.4f\t%.4f\t%.4f\t%.0f\t%.3f\t%.2f\n", d, n[d], sum[d] / n[d], sem(sum[d], sum2[d], n[d]),
           k ? b / k : 0, sem(b, b2, k), coll[d] / n[d], (coll[d] / n[d]) / (coll[dmin] / n[dmin]), cpu[d] / n[d]
  }
}
