#!/usr/bin/python3
"""The viscoelastic restitution table against an independent solution.

The engine tabulates eps(x) from a fixed-step Runge-Kutta solution of
    eta'' = -eta^(3/2) - x eta^(1/2) eta',  eta(0) = 0, eta'(0) = 1,
eps = -eta'(end) (simulate/engine/viscoelastic_restitution.h). Here the same
equation is solved another way: SciPy's adaptive DOP853 at rtol 1e-13, and
near eta = 0, where the equation is singular in t, in the variable
s = sqrt(eta), in which it is smooth:
    d(eta')/ds = -2 s^2 (s^2 + x eta') / eta'.
This solution is checked first (eps(0) = 1; the series of Schwager &
Poeschel, PRE 57, 650 (1998), to third order at small x; tolerance 1e-11
changes it by < 1e-10), then the table is held to the bound the README and
the header state: within 2e-7 on x in [0, 8] (measured 1.82e-7 at
x = 0.70 on a grid of 0.00025).

usage: viscoelastic_table_accuracy.py TABLE_VALUES_PROGRAM
"""
import subprocess
import sys

import numpy as np
from scipy.integrate import solve_ivp

BOUND = 2e-7
C1 = 1.1534489
C2 = 0.6 * C1 * C1


def eps(x, rtol=1e-13):
    tol = dict(rtol=rtol, atol=1e-16, method="DOP853")

    def in_s(s, y):
        return [-2 * s * s * (s * s + x * y[0]) / y[0]]

    def in_t(t, y):
        return [y[1], -y[0] ** 1.5 - x * np.sqrt(max(y[0], 0.0)) * y[1]]

    def half_speed(s, y):  # compression, in s, until the rate falls to 1/2
        return y[0] - 0.5
    half_speed.terminal = True
    a = solve_ivp(in_s, [0, 10], [1.0], events=half_speed, **tol)
    s1, r1 = a.t_events[0][0], a.y_events[0][0][0]

    def back(t, y):  # through the turning point, in t, until eta is s1^2 / 4
        return y[0] - s1 * s1 / 4
    back.terminal, back.direction = True, -1
    b = solve_ivp(in_t, [0, 1e4], [s1 * s1, r1], events=back, **tol)
    s2, r2 = np.sqrt(b.y_events[0][0][0]), b.y_events[0][0][1]
    c = solve_ivp(in_s, [s2, 0], [r2], **tol)  # restitution, in s, down to 0
    return -c.y[0][-1]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    failures = []
    if abs(eps(0.0) - 1) > 1e-12:
        failures.append(f"independent eps(0) = {eps(0.0)!r}, not 1")
    for x in (1e-3, 3e-3, 1e-2):
        remainder = eps(x) - (1 - C1 * x + C2 * x * x)
        if not abs(remainder) < x ** 3:
            failures.append(f"independent eps({x}) leaves the series by {remainder:.3g} (third order: < {x ** 3:.3g})")
    for x in (0.05, 0.7, 4.0):
        if abs(eps(x) - eps(x, rtol=1e-11)) > 1e-10:
            failures.append(f"independent eps({x}) not converged in its tolerance")
    # 100 points over [0, 8] and 60 around the largest error (x ~ 0.7).
    xs = np.concatenate([np.linspace(0.0013, 7.99, 100), np.linspace(0.6, 0.8, 60)])
    out = subprocess.run([sys.argv[1]], input="\n".join(repr(float(x)) for x in xs), capture_output=True, text=True,
                         check=True).stdout
    table = np.array([[float(v) for v in line.split()] for line in out.splitlines()])
    errors = np.array([t - eps(x) for x, t in table])
    worst = int(np.argmax(np.abs(errors)))
    print(f"table vs independent solution: largest |error| {abs(errors[worst]):.3g} at x = {table[worst, 0]:.4f} "
          f"over {len(errors)} points (bound {BOUND:g})")
    if not abs(errors[worst]) < BOUND:
        failures.append(f"table off by {errors[worst]:.3g} at x = {table[worst, 0]!r}; the stated bound is {BOUND:g}")
    for f in failures:
        print("FAIL", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
