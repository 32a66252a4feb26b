#!/bin/sh
# table.sh TABLES D T_RELAX T_ROUGH T_MIXTURE
# The effects pipeline's table (pipelines/effects/Makefile): each effect's
# measured quantities against kinetic theory, one row each, judged by the
# exponent table's rule (pipelines/row-verdict.sh). TSV columns
#   effect quantity measured error theory theory_error tolerance deviation verdict source
# deviation = (measured - theory) / sqrt(error^2 + theory_error^2). The
# tolerance is what the theory itself is expected to miss by (its row's
# source says why), so a row agrees when the two meet within it and the
# measurement is that precise.
# TABLES holds velocity_driven_P1.tsv and velocity_driven_P8.tsv
# (coolgas-velocity --series, one row per dump), sampled from T_RELAX on,
# and energy_rough_bBETA.tsv (coolgas-energy of rough spheres at each beta),
# their cooling state's T_rot/T_tr averaged from T_ROUGH on, and
# energy_mixture.tsv (coolgas-energy of a binary mixture), its T_1/T_2
# averaged from T_MIXTURE on; D is the dimension (3: the mixture's contact
# values are BMCSL's).
set -e
tables=$1 d=$2 relax=$3 rough_from=$4 mixture_from=$5
here=$(dirname "$0")
value() { sh "$here/../tsv-value.sh" "$@"; }
calc() { awk "BEGIN { printf \"%.6g\", $1 }"; }
steady() { sh "$here/steady.sh" "$@"; }
row() {  # effect quantity measured error theory theory_error tolerance source
  dev=$(awk "BEGIN { s = sqrt($4 * $4 + $6 * $6); if (s > 0) printf \"%.2f\", ($3 - $5) / s; else print \"-\" }")
  verdict=$(sh "$here/../row-verdict.sh" "$3" "$4" "$5" "$6" "$7" yes)
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4" "$5" "$6" "$7" "$dev" "$verdict" "$8"
}

printf 'effect\tquantity\tmeasured\terror\ttheory\ttheory_error\ttolerance\tdeviation\tverdict\tsource\n'
printf '# format: coolgas-table 2\n'
printf '# tool: pipelines/effects/table.sh\n'
printf '# version: %s\n' "$(value "$tables/velocity_driven_P1.tsv" version '#')"
printf '# simulator_version: %s\n' "$(sed -n 's/^# simulator_version: //p' "$tables"/velocity_*.tsv "$tables"/energy_*.tsv | sort -u | paste -sd ';' -)"
printf '# date: %s\n' "$(date -u +%Y-%m-%d)"

# The driven gas: the white-noise thermostat's steady state. The knobs come
# from the runs' own provenance, so the theory is that of the runs made.
v1=$tables/velocity_driven_P1.tsv v8=$tables/velocity_driven_P8.tsv
r=$(value "$v1" r0 '#') power=$(value "$v1" driving_power '#') T0=$(value "$v1" T0 '#')
# a2 of the white-noise state, first Sonine approximation (van Noije & Ernst,
# Granular Matter 1, 57 (1998)).
a2=$(calc "16 * (1 - $r) * (1 - 2 * $r ^ 2) / (73 + 56 * $d - 24 * $d * $r - 105 * $r + 30 * (1 - $r) * $r ^ 2)")
# Enskog's energy balance: P = (1 - r^2) omega_E(T) T (1 + 3 a2/16) / 2 with
# omega_E(T) = sqrt(T/T0) in these units, so T/T0 = (2P / ((1 - r^2)(1 + 3 a2/16)))^(2/3).
theory_T=$(calc "(2 * $power / ((1 - $r ^ 2) * (1 + 3 * $a2 / 16))) ^ (2 / 3)")
# T = v_rms^2 (per component, unit mass) over the scene's T0 (not over the
# energy at t = 0, whose sample of N Maxwellian velocities is off by ~ 1/sqrt(N)).
set -- $(steady "$v1" v_rms "$relax" "$(calc "1 / $T0")" 2)
T1=$1 T1_err=$2
row "driving" "T/T0, steady" "$T1" "$T1_err" "$theory_T" 0 0.04 \
  "Enskog's energy balance with the first Sonine a2; the tolerance is the velocity correlations molecular chaos leaves out (tests/physics/driven_gas_test.cc: 2.5 % at r0 = 0.5, phi = 0.05)"
set -- $(steady "$v8" v_rms "$relax" "$(calc "1 / $T0")" 2)
T8=$1 T8_err=$2
ratio=$(calc "$T8 / $T1") ratio_err=$(calc "$T8 / $T1 * sqrt(($T1_err / $T1) ^ 2 + ($T8_err / $T8) ^ 2)")
row "driving" "T(8P)/T(P)" "$ratio" "$ratio_err" 4 0 0.04 \
  "exact at delta = 0: velocities x2, times /2, power x8 is the same dynamics (simulate/engine/driving.h)"
# a2 = d kappa / (d + 2) from each dump's kappa (coolgas-velocity --series).
set -- $(steady "$v1" kappa "$relax" "$(calc "$d / ($d + 2)")")
row "driving" "a2, steady" "$1" "$2" "$a2" 0 "$(calc "0.1 * $a2")" \
  "van Noije & Ernst's first Sonine approximation (the formula derived again in docs/effects.md); tolerance 10 % of it for the Sonine terms it leaves out"

# Rough spheres: the cooling state's T_rot/T_tr against the two-temperature
# theory (Huthmann & Zippelius, PRE 56, R6275 (1997); Luding et al., PRE 58,
# 3416 (1998); its d-dimensional form, tests/physics/rough_spheres_test.cc):
# with eta = q (1 + beta) / (2 (1 + q)), a = (1 - r^2) + 2 (d-1) eta (1 - eta),
# b = 2 (d-1) eta^2 / q, c = 2 (d-1) (eta/q) (1 - eta/q) and d_r spinning axes
# (3 for spheres, 1 for disks), R solves (b/d) R^2 + (c/d_r - a/d) R - b/d_r = 0.
rough_ratio() {  # r beta q d
  awk -v r="$1" -v beta="$2" -v q="$3" -v d="$4" 'BEGIN {
    dr = d == 3 ? 3 : 1
    eta = q * (1 + beta) / (2 * (1 + q))
    a = (1 - r * r) + 2 * (d - 1) * eta * (1 - eta); b = 2 * (d - 1) * eta * eta / q
    c = 2 * (d - 1) * (eta / q) * (1 - eta / q)
    A = b / d; B = c / dr - a / d; C = b / dr
    printf "%.6g", (-B + sqrt(B * B + 4 * A * C)) / (2 * A) }'
}
for b in $(ls "$tables" | sed -n 's/^energy_rough_b\(.*\)\.tsv$/\1/p' | sort -g); do
  e=$tables/energy_rough_b$b.tsv
  r=$(value "$e" r0 '#') beta=$(value "$e" beta '#') q=$(value "$e" inertia '#')
  theory=$(rough_ratio "$r" "$beta" "$q" "$d")
  set -- $(steady "$e" T_rot/T_tr "$rough_from")
  row "rough spheres" "T_rot/T_tr, r0 = $r, beta = $beta" "$1" "$2" "$theory" 0 "$(calc "0.05 * $theory")" \
    "two-temperature theory with Maxwellian velocities and spins; tolerance 5 % for the Sonine corrections (Santos, Kremer & dos Santos, Phys. Fluids 23, 030604 (2011))"
done

# A binary mixture: the cooling state's T_1/T_2 against Garzo & Dufty's
# Maxwellian approximation (PRE 60, 5706 (1999)), as
# tests/physics/mixture_test.cc derives it: per particle of species i,
# dE_i/dt = -sum_j nu_ij (1 + r) mu_ji m_i [2 (T_i - T_j)/M + mu_ji (1 - r) w_ij]
# (M = m_i + m_j, mu_ji = m_j/M, w_ij = T_i/m_i + T_j/m_j), with Enskog's
# pair rates nu_ij ~ n_j chi_ij sigma_ij^2 sqrt(w_ij) (the common factor
# cancels) and BMCSL's contact values chi_ij; T_1/T_2 is where the cooling
# rates -dE_i/dt / T_i agree (bisection between 0.1 and 10).
mixture_ratio() {  # r phi "x1,x2" "s1,s2" "m1,m2"
  awk -v r="$1" -v phi="$2" -v xs="$3" -v ss="$4" -v ms="$5" '
    function rate_gap(g,    i, j, dE, w, M, mu, zeta) {
      T[1] = g; T[2] = 1
      for (i = 1; i <= 2; i++) {
        dE = 0
        for (j = 1; j <= 2; j++) {
          w = T[i] / m[i] + T[j] / m[j]; M = m[i] + m[j]; mu = m[j] / M
          dE -= x[j] * chi[i, j] * sij[i, j] ^ 2 * sqrt(w) * (1 + r) * mu * m[i] * (2 * (T[i] - T[j]) / M + mu * (1 - r) * w)
        }
        zeta[i] = -dE / T[i]
      }
      return zeta[1] - zeta[2]
    }
    BEGIN {
      split(xs, x, ","); split(ss, s, ","); split(ms, m, ",")
      # xi_k = (pi/6) n <sigma^k>, with n from phi = xi_3
      s3 = x[1] * s[1] ^ 3 + x[2] * s[2] ^ 3; s2 = x[1] * s[1] ^ 2 + x[2] * s[2] ^ 2
      xi3 = phi; xi2 = phi * s2 / s3
      for (i = 1; i <= 2; i++) for (j = 1; j <= 2; j++) {
        sij[i, j] = (s[i] + s[j]) / 2; h = s[i] * s[j] / (s[i] + s[j])
        chi[i, j] = 1 / (1 - xi3) + 3 * xi2 * h / (1 - xi3) ^ 2 + 2 * xi2 ^ 2 * h ^ 2 / (1 - xi3) ^ 3
      }
      lo = 0.1; hi = 10
      for (k = 0; k < 100; k++) { mid = (lo + hi) / 2; if ((rate_gap(mid) > 0) == (rate_gap(lo) > 0)) lo = mid; else hi = mid }
      printf "%.6g", (lo + hi) / 2
    }'
}
e=$tables/energy_mixture.tsv
r=$(value "$e" r0 '#') phi=$(value "$e" phi '#')
theory=$(mixture_ratio "$r" "$phi" "$(value "$e" species_fraction '#')" "$(value "$e" species_diameter '#')" \
  "$(value "$e" species_mass '#')")
set -- $(steady "$e" T_species_0/T_species_1 "$mixture_from")
row "mixture" "T_1/T_2, r0 = $r, diameters $(value "$e" species_diameter '#')" "$1" "$2" "$theory" 0 "$(calc "0.03 * $theory")" \
  "Garzo & Dufty's Maxwellian approximation with BMCSL contact values; tolerance 3 % for the Sonine corrections it leaves out (small for T_1/T_2: Montanero & Garzo, Granular Matter 4, 17 (2002))"
