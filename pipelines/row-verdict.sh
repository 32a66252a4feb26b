#!/bin/sh
# row-verdict.sh MEASURED ERROR PAPER PAPER_ERROR TOLERANCE REGIME
# The verdict of one row of the exponent table (pipelines/exponents.sh): the
# word of its 'verdict' column. exponents.sh writes every row through this
# script, pipelines/verdicts.sh builds the paper's claims on the words, and
# tests/cli/pipeline_scripts_cli_test.cc checks them; the rules are stated
# once, in RULES below, which `row-verdict.sh --rules` prints (exponents.md
# quotes it).
set -e
RULES='A row agrees with the paper when its value lies within the tolerance of the paper'"'"'s and is known to within it (its error, combined with the paper'"'"'s, is no larger than the tolerance); it differs when it lies beyond the tolerance by more than 3 combined errors (by any amount when it has no error); it is not decided otherwise, or when it is outside the paper'"'"'s regime or has no number. Where the paper says only which side of a bound b a value lies ("> b", "< b"), a row agrees when it lies on that side by more than 3 errors, differs when it lies on the other side by more than 3 errors, and is not decided otherwise. A row whose quantity the paper gives no value for has no verdict ("-").'
[ "${1:-}" = --rules ] && { echo "$RULES"; exit 0; }
[ $# -eq 6 ] || { echo "usage: row-verdict.sh MEASURED ERROR PAPER PAPER_ERROR TOLERANCE REGIME" >&2; exit 2; }
awk -v m="$1" -v e="$2" -v p="$3" -v pe="$4" -v tol="$5" -v regime="$6" '
  function num(v) { return v ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
  function bad(what, v, allowed) { printf "row-verdict.sh: %s is \"%s\"; allowed: %s\n", what, v, allowed > "/dev/stderr"; exit 2 }
  BEGIN {
    if (regime != "yes" && regime !~ /^no/) bad("REGIME", regime, "yes, or no and why")
    if (!num(m) && m != "nan") bad("MEASURED", m, "a number or nan")
    if (!num(e) && e != "-" && e != "nan") bad("ERROR", e, "a number, - or nan")
    if (!num(pe) && pe != "-") bad("PAPER_ERROR", pe, "a number or -")
    bound = (p ~ /^[<>] /) ? substr(p, 1, 1) : ""
    b = bound == "" ? p : substr(p, 3)
    if (p != "-" && !num(b)) bad("PAPER", p, "a number, \"> b\", \"< b\" or -")
    if (p != "-" && bound == "" && !(num(tol) && tol >= 0)) bad("TOLERANCE", tol, "a number >= 0")
    if (regime ~ /^no/ || m == "nan") { print "not decided"; exit }
    if (p == "-") { print "-"; exit }
    s = sqrt((num(e) ? e * e : 0) + (num(pe) ? pe * pe : 0))
    if (bound != "") {
      d = bound == ">" ? m - b : b - m  # how far on the side the paper names
      print (d > 3 * s ? "agrees" : -d > 3 * s ? "differs" : "not decided")
      exit
    }
    d = m - p; if (d < 0) d = -d
    print (d <= tol + 0 && s <= tol + 0 ? "agrees" : d - tol > 3 * s ? "differs" : "not decided")
  }'
