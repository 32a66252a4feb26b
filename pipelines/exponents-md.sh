#!/bin/sh
# exponents-md.sh EXPONENTS_TSV TABLES SCALE "PARAM_SETS" ["BA_FITS"]
# Writes the measured exponents beside the paper's values as a Markdown table
# (the README's comparison table is a copy of the demo's).
set -e
tsv=$1
tables=$2
scale=$3
sets=$4
ba_fits=${5:-}
here=$(dirname "$0")
v() { sh "$here/tsv-value.sh" "$tsv" "$1"; }
f() { awk "BEGIN { printf \"%.3f\", $1 }"; }
echo "| quantity (SCALE = $scale) | measured | paper |"
echo "|---|---|---|"
echo "| θ, collapse E L^{zθ} vs t/L^z (Fig. 1) | $(f "$(v theta)") ± $(f "$(v theta_err)") | 6/5 |"
echo "| z, same collapse | $(f "$(v z)") ± $(f "$(v z_err)") | 5/2 |"
echo "| η, f(x) ~ x^-η for x ≫ 1 | $(f "$(v eta)") ± $(f "$(v eta_err)") | ≈ 1.83 |"
echo "| θ, power-law fit of E(t) at the largest L | $(f "$(v theta_Lmax)") ± $(f "$(v theta_Lmax_err)") | 6/5 |"
for p in $sets; do
  fit=$tables/fit_param_$p.tsv
  echo "| θ at $(echo "$p" | sed 's/_/, /g; s/^phi/φ = /; s/, r/, r0 = /; s/, d/, δ = /') (Fig. 2) | $(f "$(sh "$here/tsv-value.sh" "$fit" theta)") ± $(f "$(sh "$here/tsv-value.sh" "$fit" theta_err)") | 6/5 |"
done
echo "| τ, N(m) ~ m^-τ below the largest cluster (Fig. 3) | $(f "$(v mass_exponent)") ± $(f "$(v mass_exponent_err)") | 2.7 |"
echo "| fraction of particles in the largest cluster | $(f "$(v largest_fraction)") | ≈ 0.75 |"
echo "| M_max ~ t^a, gas (Fig. 4) | $(f "$(v mmax_exponent)") ± $(f "$(v mmax_exponent_err)") | rapid (gel-like) growth |"
echo "| β, -ln Φ(y) ~ y^β at late times (Fig. 5) | $(f "$(v beta_late)") ± $(f "$(v beta_late_err)") | 5/3 (= 2/θ) |"
echo "| κ at late times | $(f "$(v kappa_late)") | > 0, saturates |"
echo "| M_max ~ t^a, Smoluchowski Eq. 4 | $(f "$(v smol_mmax_exponent)") | 6/5 |"
echo "| M_avg ~ t^a, Smoluchowski Eq. 4 | $(f "$(v smol_mavg_exponent)") | 6/5 |"
if [ -z "$ba_fits" ]; then
  echo "| θ_BA, ballistic aggregation | (run with BA = 1) | 1.283 (φ = 0.005) … 1.206 (φ = 0.208) |"
fi
for fit in $ba_fits; do
  phi=$(basename "$fit" .tsv | sed 's/^fit_energy_ba_phi//; s/_s[0-9]*$//')
  echo "| θ_BA at φ = $phi, ballistic aggregation | $(f "$(sh "$here/tsv-value.sh" "$fit" theta)") ± $(f "$(sh "$here/tsv-value.sh" "$fit" theta_err)") | 1.283 (φ = 0.005) … 1.206 (φ = 0.208) |"
done
