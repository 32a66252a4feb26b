# %% [markdown]
# # A first look at a freely cooling granular gas, from Python
#
# A small version of the paper's gas (Pathak, Jabeen, Das & Rajesh, PRL 112,
# 038001 (2014): phi = 0.208, r0 = 0.1, delta = 1e-4) and its ballistic-
# aggregation counterpart, simulated with `coolgas.simulate`, read back with
# `coolgas.open`, and analysed with the tools' own kernels: clusters by the
# paper's unit cells, the scaled velocity distribution, E(t).
#
# This file is the plain-script twin of `first_look.ipynb` (the same cells;
# the tests run this script and check that the two agree). Run it with
# `PYTHONPATH=build/python python3 pipelines/notebooks/first_look.py [OUTDIR]`.

# %%
import os
import sys

import matplotlib

if "ipykernel" not in sys.modules:  # a script: draw into files, no display
    matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import coolgas

OUT = sys.argv[1] if len(sys.argv) > 1 and "ipykernel" not in sys.modules else "first-look"
os.makedirs(OUT, exist_ok=True)
print("coolgas", coolgas.__version__)

# %% [markdown]
# ## Simulate the gas and its ballistic-aggregation counterpart
# Same box, density and seed; in the aggregation run touching spheres merge.
# The aggregation run stops (a `SimulationError`, exit code 4) once its
# largest aggregate is half the box wide; its file holds every dump till then.

# %%
L, T_END = 20, 1000.0
gas_scene = {"system": {"L": L, "phi": 0.208, "seed": 1},
             "collision": {"model": "inelastic", "r0": 0.1, "delta": 1e-4},
             "run": {"t_end": T_END}, "output": {"dumps_per_decade": 4}}
ba_scene = {"system": {"L": L, "phi": 0.208, "seed": 1},
            "collision": {"model": "aggregation"},
            "run": {"t_end": 100.0}, "output": {"dumps_per_decade": 4}}
gas = coolgas.simulate(gas_scene, output=os.path.join(OUT, "gas.h5"), force=True)
ba = coolgas.simulate(ba_scene, output=os.path.join(OUT, "ba.h5"), force=True)
print(gas, ba, sep="\n")
print("N =", gas.parameters["N"], " T0 =", gas.parameters["T0"])

# %% [markdown]
# ## E(t): the observables as a DataFrame indexed by t

# %%
fig, ax = plt.subplots()
for run, label in ((gas, "inelastic gas"), (ba, "ballistic aggregation")):
    E = run.observables["kinetic_energy"]
    E = E[E.index > 0]
    ax.loglog(E.index, E / E.iloc[0], label=label)
t = np.logspace(-2, 3, 100)
t0 = 6 / (1 - 0.1**2)  # Haff's law, E0/(1 + t/t0)^2 (tests/physics/README.md)
ax.loglog(t, 1 / (1 + t / t0) ** 2, "k:", label="Haff")
ax.loglog(t, 20 * t ** -1.2, "k--", label=r"$t^{-6/5}$ (paper)")
ax.set_xlabel(r"$t\ [1/\omega_0]$")
ax.set_ylabel(r"$E/E_0$")
ax.legend()
fig.savefig(os.path.join(OUT, "energy.png"), dpi=80)

# %% [markdown]
# ## Clusters of the last frame (the paper's unit cells)

# %%
last = gas.frames[-1]
labels, sizes = coolgas.label_clusters(last)
print(f"t = {last.t}: {len(sizes)} clusters, the largest holds {sizes['mass'].iloc[0]} of {len(labels)} particles")
dist = coolgas.clusters(last)  # the table coolgas-clusters writes for this dump
fig, ax = plt.subplots()
ax.loglog(dist["m"], dist["N"], "o-", label="gas, t = %g" % last.t)
ba_last = ba.frames[-1]
ba_dist = coolgas.clusters(ba_last)  # aggregates are the clusters
ax.loglog(ba_dist["m"], ba_dist["N"], "s-", label="aggregation, t = %g" % ba_last.t)
ax.set_xlabel("cluster mass m")
ax.set_ylabel(r"$N(m)\ [\sigma^{-3}]$")
ax.legend()
fig.savefig(os.path.join(OUT, "cluster_sizes.png"), dpi=80)

# %% [markdown]
# ## The scaled velocity distribution Phi(y), y = v_alpha / v_rms

# %%
fig, ax = plt.subplots()
# the aggregation run at t = 10, while it still holds many aggregates
for fr, label in ((gas.frames[-1], "inelastic gas"), (ba.frames.at(10), "ballistic aggregation")):
    phi = coolgas.velocity(fr, bins=60)
    ax.semilogy(phi["y"], phi["Phi"], ".", label=f"{label}, t = {fr.t:g}, kappa = {phi.attrs['kappa']:.2f}")
y = np.linspace(-5, 5, 200)
ax.semilogy(y, np.exp(-y**2 / 2) / np.sqrt(2 * np.pi), "k:", label="Gaussian")
ax.set_xlabel("y")
ax.set_ylabel(r"$\Phi(y)$")
ax.legend(fontsize=7)
fig.savefig(os.path.join(OUT, "velocity.png"), dpi=80)

# %% [markdown]
# ## One number against the paper
# Before clustering the gas cools by Haff's law, E(t) = E0 / (1 + t/t0)^2
# with t0 = 6/(1 - r0^2) collision times, the regime the paper's Fig. 1
# starts in. At t = 0.5 the run must agree with it within 2 %.

# %%
E = gas.observables["kinetic_energy"]
ratio = E.loc[E.index[np.argmin(abs(E.index - 0.5))]] / E.iloc[0]
t_half = E.index[np.argmin(abs(E.index - 0.5))]
haff = 1 / (1 + t_half / t0) ** 2
print(f"E({t_half:g})/E0 = {ratio:.4f}; Haff's law: {haff:.4f}")
assert abs(ratio / haff - 1) < 0.02, "the early cooling is not Haff's law"
