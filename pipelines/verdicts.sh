#!/bin/sh
# verdicts.sh EXPONENTS_TSV
# The paper's conclusions (Pathak et al. 2014) judged on the exponent table
# (pipelines/exponents.sh), as a TSV table with columns
#   claim  evidence  verdict
# The verdict is "supported", "not supported" or "not decided at this scale",
# each with its reason. The rules, one per claim:
#   - A number "agrees" with the paper's value when it lies within the
#     tolerance the claim names, and "differs" when it lies further away by
#     more than 3 of its errors; between the two it decides nothing.
#   - Evidence whose row says it is not in the paper's regime (its last
#     column starts with "no") decides nothing; the verdict is then "not
#     decided at this scale" and repeats why, which says what is needed.
# A row the table lacks (a scale without BA, say) makes its claim "not
# decided at this scale (no row ...)".
set -e
tsv=$1
awk -F '\t' '
  function num(v) { return v ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
  FNR == 1 || /^#/ || NF == 0 { next }
  { n++; q[n] = $1; m[n] = $3; e[n] = $4; reg[n] = $8 }
  # The first row whose quantity starts with prefix p (and contains s, if given); 0 if none.
  function find(p, s,   i) {
    for (i = 1; i <= n; i++) if (index(q[i], p) == 1 && (s == "" || index(q[i], s) > 0)) return i
    return 0
  }
  function shown(i) { return num(e[i]) && e[i] > 0 ? sprintf("%.3f ± %.3f", m[i], e[i]) : sprintf("%.3g", m[i]) }
  function out_of_regime(i) { return reg[i] ~ /^no/ }
  # agree/differ of row i with value v at tolerance tol: 1 agrees, -1 differs, 0 neither
  function judge(i, v, tol,   d, s) {
    d = m[i] - v; if (d < 0) d = -d
    s = num(e[i]) && e[i] > 0 ? e[i] : 0
    if (d <= tol) return 1
    if (s > 0 ? d - tol > 3 * s : 1) return -1
    return 0
  }
  function claim(c, ev, v) { printf "%s\t%s\t%s\n", c, ev, v }
  function missing(c, what) { claim(c, "-", "not decided at this scale (no row " what " in the table)") }
  function undecided(c, ev, i) { claim(c, ev, "not decided at this scale (" q[i] ": " substr(reg[i], 5) ")") }
  END {
    # 1. theta = 6/5 (mean-field BA), not 3/2 (Burgers equation).
    c = "theta agrees with theta_BA^mf = 6/5 and rules out theta_BE = 3/2"
    a = find("theta, collapse"); b = find("theta, power-law fit")
    if (!a || !b) missing(c, "theta, collapse / theta, power-law fit")
    else {
      ev = "collapse " shown(a) "; power-law fit at the largest L " shown(b)
      if (out_of_regime(b)) undecided(c, ev, b)
      else if (judge(a, 1.2, 0.03) == 1 && judge(b, 1.2, 0.03) == 1 && judge(a, 1.5, 0) == -1 && judge(b, 1.5, 0) == -1)
        claim(c, ev, "supported: both within 0.03 of 6/5 and more than 3 errors from 3/2")
      else if (judge(b, 1.5, 0.03) == 1) claim(c, ev, "not supported: the power law is within 0.03 of 3/2")
      else claim(c, ev, "not decided at this scale: not both within 0.03 of 6/5")
    }
    # 2. Finite-size scaling with the mean-field z = 5/2 (z theta = d = 3).
    c = "E(t) obeys E = L^(-z theta) f(t/L^z) with z = z_BA^mf = 5/2"
    a = find("z, same collapse"); p = find("z theta, same collapse")
    if (!a) missing(c, "z, same collapse")
    else {
      ev = "free collapse z = " shown(a) (p ? "; z theta = " shown(p) " (mean field 3)" : "")
      if (out_of_regime(a)) undecided(c, ev, a)
      else if (!(num(e[a]) && e[a] <= 0.25)) claim(c, ev, "not decided at this scale: z is uncertain by more than 0.25 (needs boxes whose crossovers span more of x = t/L^z, or more runs)")
      else if (judge(a, 2.5, 0.25) == 1) claim(c, ev, "supported: z within 0.25 of 5/2")
      else if (judge(a, 2.5, 0.25) == -1) claim(c, ev, "not supported: z more than 0.25 and 3 errors from 5/2")
      else claim(c, ev, "not decided at this scale: z neither within 0.25 of 5/2 nor 3 errors beyond")
    }
    # 3. f(x) ~ x^-1.83 beyond the crossover.
    c = "beyond the crossover f(x) ~ x^-eta with eta = 1.83"
    a = find("eta, f(x)")
    if (!a) missing(c, "eta, f(x)")
    else {
      ev = "eta = " shown(a)
      if (!num(m[a])) claim(c, ev, "not decided at this scale: no fit (" substr(reg[a], 5) ")")
      else if (out_of_regime(a)) undecided(c, ev, a)
      else if (judge(a, 1.83, 0.1) == 1) claim(c, ev, "supported: within 0.1 of 1.83")
      else if (judge(a, 1.83, 0.1) == -1) claim(c, ev, "not supported: more than 0.1 and 3 errors from 1.83")
      else claim(c, ev, "not decided at this scale: neither within 0.1 of 1.83 nor 3 errors beyond")
    }
    # 4. The gas'"'"'s clusters differ from BA'"'"'s: a power law m^-2.7 and one
    # macroscopic cluster, against BA'"'"'s m^-0.2 and an exponential tail.
    c = "the gas'"'"'s cluster sizes differ from BA'"'"'s: N(m) ~ m^-2.7 with one macroscopic cluster, BA N(m) ~ m^-0.2 then exponential"
    a = find("tau, N(m)"); b = find("tau_BA"); s = find("largest cluster'"'"'s share")
    if (!a || !b) missing(c, "tau, N(m) / tau_BA")
    else {
      ev = "gas tau = " shown(a) "; BA tau = " shown(b) (s ? "; gas largest share " shown(s) : "")
      if (out_of_regime(a)) undecided(c, ev, a)
      else if (m[a] - m[b] > 3 * sqrt((num(e[a]) ? e[a] : 0) ^ 2 + (num(e[b]) ? e[b] : 0) ^ 2) && m[a] - m[b] > 1) {
        v = "supported that they differ: the gas'"'"'s exponent exceeds BA'"'"'s by " sprintf("%.2f", m[a] - m[b])
        v = v (judge(a, 2.7, 0.2) == 1 ? "; gas tau within 0.2 of 2.7" : "; gas tau not within 0.2 of 2.7")
        v = v (judge(b, 0.2, 0.2) == 1 ? ", BA tau within 0.2 of 0.2" : ", BA tau not within 0.2 of 0.2")
        if (s && out_of_regime(s)) v = v "; the macroscopic cluster not decided (" substr(reg[s], 5) ")"
        else if (s) v = v (m[s] > 0.5 ? "; one cluster holds most particles" : "; no cluster holds most particles")
        claim(c, ev, v)
      } else claim(c, ev, "not supported: the two exponents differ by less than 1 or 3 errors")
    }
    # 5. M_max of the gas jumps at the onset of clustering; BA'"'"'s grows as a power law.
    c = "the gas'"'"'s M_max jumps when clustering sets in, BA'"'"'s grows as a power law"
    g = 0; gall = 0; gmax = 0; bmax = 0; nb = 0; jumps = ""; same = 0; later = 0; why = ""
    for (i = 1; i <= n; i++) {
      if (index(q[i], "M_max'"'"'s steepest rise") == 1 && q[i] ~ /gas phi/) { gall++; if (!out_of_regime(i)) { g++; if (m[i] > gmax) gmax = m[i] } else why = q[i] ": " substr(reg[i], 5) }
      if (index(q[i], "M_max'"'"'s steepest rise") == 1 && q[i] ~ /BA phi/) { nb++; if (m[i] > bmax) bmax = m[i] }
      if (index(q[i], "log10(t_jump/t_inhom)") == 1 && !out_of_regime(i)) {
        jumps = jumps sprintf("%s%.2f", jumps == "" ? "" : ", ", m[i])
        if (m[i] <= e[i] && -m[i] <= e[i]) same++; else later++
      }
    }
    if (!gall || !nb) missing(c, "M_max'"'"'s steepest rise of a gas and of BA")
    else if (!g) claim(c, "-", "not decided at this scale (" why ")")
    else {
      ev = sprintf("steepest d ln M_max/d ln t: gas up to %.2f, BA up to %.2f (mean field 6/5); log10(t_jump/t_inhom): %s", gmax, bmax, jumps == "" ? "-" : jumps)
      if (gmax > 2 * 1.2 && bmax < 1.5) {
        v = "supported: the gas'"'"'s M_max rises more than twice as steeply as mean field'"'"'s, BA'"'"'s no steeper than 1.5"
        if (later) v = v sprintf("; the jump comes later than t_inhom (by more than half a dump spacing) in %d of %d gases", later, same + later)
        claim(c, ev, v)
      } else claim(c, ev, "not supported: no gas rises more than twice as steeply as 6/5, or BA rises faster than 1.5")
    }
    # 6. Velocity tails: -ln Phi ~ y^(5/3) for the gas, y^0.70 for BA.
    c = "-ln Phi(y) ~ y^beta with beta = 5/3 (= 2/theta) for the gas and 0.70 for BA"
    a = find("beta, -ln Phi"); b = find("beta_BA")
    if (!a || !b) missing(c, "beta / beta_BA")
    else {
      ev = "gas beta = " shown(a) "; BA beta = " shown(b)
      if (out_of_regime(a)) undecided(c, ev, a)
      else {
        ja = judge(a, 5 / 3, 0.1); jb = judge(b, 0.7, 0.1)
        v = (ja == 1 ? "gas within 0.1 of 5/3" : ja == -1 ? "gas more than 0.1 and 3 errors from 5/3" : "gas undecided")
        v = v (jb == 1 ? ", BA within 0.1 of 0.70" : jb == -1 ? ", BA more than 0.1 and 3 errors from 0.70" : ", BA undecided")
        claim(c, ev, (ja == 1 && jb == 1 ? "supported: " : ja == -1 || jb == -1 ? "not supported: " : "not decided at this scale: ") v)
      }
    }
    # 7. The kurtosis saturates above 0 (a non-Gaussian Phi).
    c = "the kurtosis kappa saturates above 0 (Phi(y) stays non-Gaussian)"
    a = find("kappa at t")
    if (!a) missing(c, "kappa")
    else {
      ev = "kappa = " shown(a) " at the late time"
      if (out_of_regime(a)) undecided(c, ev, a)
      else if (num(e[a]) && e[a] > 0 && m[a] > 3 * e[a]) claim(c, ev, "supported: above 0 by more than 3 errors")
      else if (num(e[a]) && e[a] > 0 && m[a] < 3 * e[a]) claim(c, ev, "not supported: within 3 errors of 0 (Gaussian)")
      else claim(c, ev, "not decided at this scale: no error")
    }
    # 8. theta_BA falls with phi toward the mean field 6/5, 1.206 +- 0.005 at phi = 0.208.
    c = "theta_BA falls with phi toward 6/5 (paper 1.283 at phi = 0.005, 1.206 at 0.208)"
    lo = 0; hi = 0
    for (i = 1; i <= n; i++) if (index(q[i], "theta_BA at phi") == 1) { if (!lo) lo = i; hi = i }
    if (!hi || lo == hi) missing(c, "theta_BA at two phi")
    else {
      ev = q[lo] " " shown(lo) "; " q[hi] " " shown(hi)
      d = m[lo] - m[hi]; s = sqrt(e[lo] ^ 2 + e[hi] ^ 2)
      if (d > 3 * s && judge(hi, 1.206, 0.03) == 1) claim(c, ev, "supported: it falls by " sprintf("%.3f", d) " (more than 3 errors) to within 0.03 of 1.206")
      else if (d > 3 * s) claim(c, ev, "not supported at the densest phi: it falls, but not to within 0.03 of 1.206")
      else claim(c, ev, "not supported: it does not fall with phi by more than 3 errors")
    }
  }' "$tsv"
