#!/bin/sh
# verdicts.sh EXPONENTS_TSV
# The paper's conclusions (Pathak et al. 2014) judged on the exponent table
# (pipelines/exponents.sh), as a TSV table with columns
#   claim  evidence  verdict
# A claim rests on rows of the table and on their verdict words, which
# pipelines/row-verdict.sh gives by its rules; nothing here judges a number
# again, so a claim cannot say what its rows do not. Each part of a claim
# names its rows by the start of their quantity (a part may have several,
# one per gas, say, and several starts, one per cluster definition). The
# rule, the same for every claim, is RULES below, which `verdicts.sh --rules`
# prints (exponents.md quotes it).
set -e
RULES='A claim rests on rows of the table above and on their verdicts; rows outside the paper'"'"'s regime decide nothing and are left out. A claim is not supported when a row of it differs, supported when each of its parts has a row in the regime and every such row agrees, and not decided at this scale otherwise (the first part that decides nothing is named, and why). That theta_BA falls with phi also needs its dilutest row above its densest by more than 3 combined errors.'
[ "${1:-}" = --rules ] && { echo "$RULES"; exit 0; }
tsv=$1
awk -F '\t' '
  function num(v) { return v ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
  FNR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
  /^#/ || NF == 0 { next }
  { n++; q[n] = $col["quantity"]; m[n] = $col["measured"]; e[n] = $col["error"]; p[n] = $col["paper"]
    reg[n] = $col["regime"]; w[n] = $col["verdict"] }
  function shown(i) { return num(e[i]) && e[i] > 0 ? sprintf("%.3f ± %.3f", m[i], e[i]) : (num(m[i]) ? sprintf("%.3g", m[i]) : m[i]) }
  function in_regime(i) { return reg[i] !~ /^no/ }
  # A claim is built part by part: start(text), part(prefix, what), end().
  function start(text) { claim = text; evidence = ""; differs = ""; undecided = "" }
  # A part'"'"'s prefixes are separated by "|" (one quantity by two cluster definitions, say).
  function starts(s, prefixes,   k, np, pre) {
    np = split(prefixes, pre, "|")
    for (k = 1; k <= np; k++) if (index(s, pre[k]) == 1) return 1
    return 0
  }
  function part(prefix, what,   i, rows, kept, agree, why) {
    for (i = 1; i <= n; i++) {
      if (!starts(q[i], prefix)) continue
      rows++
      evidence = evidence (evidence == "" ? "" : "; ") q[i] " " shown(i) " (" (in_regime(i) ? w[i] : "outside the regime") ")"
      if (!in_regime(i)) { if (why == "") why = q[i] " is outside the paper'"'"'s regime (" substr(reg[i], 5) ")"; continue }
      kept++
      if (w[i] == "agrees") agree++
      else if (w[i] == "differs") differs = differs (differs == "" ? "" : "; ") q[i] " differs (" shown(i) " against " p[i] ")"
      else if (why == "" || why ~ /outside/) why = q[i] " neither agrees nor differs (" shown(i) " against " p[i] ")"
    }
    if (undecided != "") return
    if (!rows) undecided = "no row " what " in the table"
    else if (!kept) undecided = why
    else if (agree < kept) undecided = why
  }
  # end(why): the claim'"'"'s line; why says what supports it (default: every row agrees).
  function end(why) {
    if (evidence == "") evidence = "-"
    if (differs != "") v = "not supported: " differs
    else if (undecided != "") v = "not decided at this scale: " undecided
    else v = "supported: " (why == "" ? "every row agrees" : why)
    printf "%s\t%s\t%s\n", claim, evidence, v
  }
  END {
    start("theta agrees with theta_BA^mf = 6/5 and rules out theta_BE = 3/2")
    part("theta, collapse", "theta, collapse"); part("theta, power-law fit", "theta, power-law fit"); end()
    # The paper measured z by its method (z theta = d held); the free fit
    # tests the form itself, and the product z theta the relation.
    start("E(t) obeys E = L^(-z theta) f(t/L^z) with z = z_BA^mf = 5/2 and z theta = d = 3")
    part("z, collapse with z theta = 3", "z, collapse with z theta = 3"); part("z, free collapse", "z, free collapse")
    part("z theta, free collapse", "z theta, free collapse"); end()
    start("beyond the crossover f(x) ~ x^-eta with eta = 1.83")
    part("eta, f(x)", "eta, f(x)"); end()
    start("the gas'"'"'s cluster sizes follow N(m) ~ m^-2.7, with one macroscopic cluster")
    part("tau, N(m)", "tau, N(m)"); part("largest cluster'"'"'s share", "largest cluster'"'"'s share"); end()
    start("BA'"'"'s cluster sizes follow N(m) ~ m^-0.2, then an exponential tail")
    part("tau_BA", "tau_BA"); end()
    start("the gas'"'"'s M_max jumps when clustering sets in, BA'"'"'s grows as a power law")
    # by the unit cells and by contact clusters (pipelines/contact-clusters.mk): where
    # the unit cells percolate from t = 0, their rows are outside the regime
    part("M_max'"'"'s steepest rise, gas|M_max rise, contact", "M_max'"'"'s steepest rise of a gas")
    part("log10(t_jump/t_inhom)|lg(t_jump/t_inhom), contact", "log10(t_jump/t_inhom)")
    part("M_max'"'"'s steepest rise, BA", "M_max'"'"'s steepest rise of BA"); end()
    start("-ln Phi(y) ~ y^beta with beta = 5/3 (= 2/theta) for the gas and 0.70 for BA")
    part("beta, -ln Phi", "beta"); part("beta_BA", "beta_BA"); end()
    start("the kurtosis kappa saturates above 0 (Phi(y) stays non-Gaussian)")
    part("kappa", "kappa"); end()
    # theta_BA: the first and last rows (the table lists them by phi).
    start("theta_BA falls with phi toward 6/5 (paper 1.283 at phi = 0.005, 1.206 at 0.208)")
    lo = 0; hi = 0
    for (i = 1; i <= n; i++) if (index(q[i], "theta_BA at phi") == 1) { if (!lo) lo = i; hi = i }
    if (!hi || lo == hi) { undecided = "no row theta_BA at two phi in the table"; end() }
    else {
      evidence = q[lo] " " shown(lo) "; " q[hi] " " shown(hi) " (" w[hi] ")"
      d = m[lo] - m[hi]; s = sqrt(e[lo] ^ 2 + e[hi] ^ 2)
      falls = sprintf("it falls by %.3f (%s 3 combined errors)", d, d > 3 * s ? "more than" : "not more than")
      if (d < -3 * s) differs = sprintf("it rises by %.3f", -d)
      else if (w[hi] == "differs") differs = q[hi] " differs (" shown(hi) " against " p[hi] ")"
      else if (d <= 3 * s) undecided = falls
      else if (w[hi] != "agrees") undecided = q[hi] " " (w[hi] == "-" ? "has no value of the paper" : "neither agrees nor differs")
      end(falls " and " q[hi] " agrees")
    }
  }' "$tsv"
