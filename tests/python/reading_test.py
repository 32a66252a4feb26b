"""Reading: run.parameters, run.observables and run.frames equal what h5py
reads from the same file (the H5MD profile, data-schema/h5md-profile.md),
read_table equals pandas on the same table, another program's H5MD file
reads through the same objects, and a file still being written reads."""
import os
import signal
import subprocess

import h5py
import numpy as np
import pandas as pd
import pytest

import coolgas
from conftest import BIN, HANG_S, tool, wait_for_point, waiting_at


def test_parameters_are_the_files(gas):
    p = coolgas.open(gas).parameters
    with h5py.File(gas, "r") as f:
        attrs = f["parameters"].attrs
        for key in ("seed", "N", "L", "phi", "T0", "r0", "delta"):
            assert p[key] == attrs[key], key
        assert p["model"] == "inelastic" and p["program_version"] == coolgas.__version__
        assert p["scene"] == attrs["scene"]
    assert p["scene_dict"]["collision"]["r0"] == 0.1 and p["scene_dict"]["system"]["seed"] == 7
    assert "time" in p["units"]


def test_a_driven_runs_parameters_hold_its_driving(gas, tmp_path):
    # Present exactly when the run is driven ([driving]; data-schema/h5md-profile.md, version 4).
    from conftest import GAS
    assert "driving_power" not in coolgas.open(gas).parameters
    scene = tmp_path / "driven.toml"
    scene.write_text(GAS.replace("[run]", "[driving]\npower = 0.05\n[run]").replace("t_end = 300", "t_end = 5"))
    out = tmp_path / "driven.h5"
    tool("simulate", "-q", scene, "-o", out)
    p = coolgas.open(out).parameters
    with h5py.File(out, "r") as f:
        assert p["driving_power"] == f["parameters"].attrs["driving_power"] == 0.05
        assert p["driving_period"] == f["parameters"].attrs["driving_period"] == 0.5
        assert p["schema_version"] == 4


def test_a_rough_runs_spins_and_temperatures(gas, tmp_path):
    # Rough particles (collision.beta > -1; data-schema/h5md-profile.md, version 5):
    # beta and inertia, each frame's spins and T_rot exactly as the file has
    # them; a smooth run has none of them.
    from conftest import GAS
    smooth = coolgas.open(gas)
    assert "beta" not in smooth.parameters and smooth.frames[0].angular_velocities is None
    assert list(smooth.temperatures.columns) == ["T_tr"]
    scene = tmp_path / "rough.toml"
    scene.write_text(GAS.replace("delta = 1e-4", "delta = 1e-4\nbeta = 0.5").replace("t_end = 300", "t_end = 5"))
    out = tmp_path / "rough.h5"
    tool("simulate", "-q", scene, "-o", out)
    run = coolgas.open(out)
    p = run.parameters
    with h5py.File(out, "r") as f:
        assert p["beta"] == f["parameters"].attrs["beta"] == 0.5
        assert p["inertia"] == f["parameters"].attrs["inertia"] == 0.4
        assert p["schema_version"] == 5
        frame = run.frames[-1]
        assert np.array_equal(frame.angular_velocities, f["particles/all/angular_velocity/value"][-1])
        E_rot = f["observables/rotational_energy/value"][:]
    T = run.temperatures
    assert np.array_equal(T["T_rot"].to_numpy(), 2.0 * E_rot / 3)
    assert T["T_rot"].iloc[0] == pytest.approx(p["T0"], rel=1e-12)  # spins drawn at T0
    assert T["T_tr"].iloc[0] == pytest.approx(p["T0"], rel=1e-12)


def test_a_mixtures_species_and_temperatures(gas, tmp_path):
    # Mixtures ([[species]]; data-schema/h5md-profile.md, version 6): the
    # species table, each frame's species (and masses and diameters from
    # them), each species' temperature, exactly as the file has them; a run
    # of equal particles has none of them.
    from conftest import GAS
    equal = coolgas.open(gas)
    assert "species_fraction" not in equal.parameters and equal.frames[0].species is None
    assert equal.frames[0].masses is None
    scene = tmp_path / "mixture.toml"
    scene.write_text(GAS.replace("t_end = 300", "t_end = 5") +
                     "\n[[species]]\nfraction = 0.25\ndiameter = 1\n[[species]]\nfraction = 0.75\ndiameter = 0.8\n")
    out = tmp_path / "mixture.h5"
    tool("simulate", "-q", scene, "-o", out)
    run = coolgas.open(out)
    p = run.parameters
    assert p["species_fraction"] == [0.25, 0.75] and p["species_diameter"] == [1.0, 0.8]
    assert p["species_mass"] == pytest.approx([1.0, 0.8 ** 3], rel=1e-15) and p["schema_version"] == 6
    with h5py.File(out, "r") as f:
        frame = run.frames[-1]
        species = f["particles/all/species/value"][-1]
        assert np.array_equal(frame.species, species)
        assert np.array_equal(frame.diameters, np.asarray(p["species_diameter"])[species])
        assert np.array_equal(frame.masses, np.asarray(p["species_mass"])[species])
        E = f["observables/species_kinetic_energy/value"][:]
    T = run.temperatures
    assert list(T.columns) == ["T_tr", "T_species_0", "T_species_1"]
    assert np.array_equal(T["T_species_1"].to_numpy(), 2.0 * E[:, 1] / 3)


def test_observables_are_the_files(gas):
    obs = coolgas.open(gas).observables
    assert obs.index.name == "t"
    with h5py.File(gas, "r") as f:
        for name in ("kinetic_energy", "collisions", "collisions_per_particle", "collisions_below_delta"):
            np.testing.assert_array_equal(obs[name].to_numpy(), f[f"observables/{name}/value"][:])
            np.testing.assert_array_equal(obs.index.to_numpy(), f[f"observables/{name}/time"][:])
        p = f["observables/total_momentum/value"][:]
        np.testing.assert_array_equal(obs[["total_momentum_x", "total_momentum_y", "total_momentum_z"]].to_numpy(), p)


def test_a_2d_run_reads_as_2d(disks, gas):
    run = coolgas.open(disks)
    assert run.dimension == 2 and coolgas.open(gas).dimension == 3
    fr = run.frames[-1]
    assert fr.dimension == 2 and fr.positions.shape == (3000, 2) and fr.velocities.shape == (3000, 2)
    obs = run.observables
    with h5py.File(disks, "r") as f:
        p = f["observables/total_momentum/value"][:]
    assert p.shape[1] == 2 and "total_momentum_z" not in obs
    np.testing.assert_array_equal(obs[["total_momentum_x", "total_momentum_y"]].to_numpy(), p)
    labels, sizes = coolgas.label_clusters(fr)  # squares of the plane: every disk in one cluster
    assert sizes["mass"].sum() == 3000 and (np.bincount(labels) == sizes["mass"].to_numpy()).all()


def test_a_1d_file_reads_as_1d(rods):
    run = coolgas.open(rods)
    assert run.dimension == 1
    fr = run.frames[-1]
    assert fr.dimension == 1 and fr.positions.shape == (3000, 1) and fr.velocities.shape == (3000, 1)
    assert fr.images.shape == (3000, 1) and list(fr.box) == [run.L]
    obs = run.observables
    with h5py.File(rods, "r") as f:
        p = f["observables/total_momentum/value"][:]
    assert p.shape[1] == 1 and "total_momentum_y" not in obs
    np.testing.assert_array_equal(obs[["total_momentum_x"]].to_numpy(), p)
    labels, sizes = coolgas.label_clusters(fr)  # unit segments of the ring
    assert sizes["mass"].sum() == 3000 and (np.bincount(labels) == sizes["mass"].to_numpy()).all()
    assert len(sizes) > 100  # rods at line fraction 0.3 make many clusters
    with pytest.raises(coolgas.InputError, match=r"\(N, 1\) for rods, got 2 dimensions \(N, 4\)"):
        coolgas.label_clusters(np.zeros((5, 4)), L=10)


@pytest.mark.parametrize("run", ["gas", "disks", "rods"])
def test_frames_are_the_files_dumps(run, request):
    path = request.getfixturevalue(run)
    frames = coolgas.open(path).frames
    with h5py.File(path, "r") as f:
        times = f["particles/all/position/time"][:]
        assert len(frames) == len(times)
        np.testing.assert_array_equal(frames.times, times)
        for i in (0, len(times) // 2, -1):
            fr = frames[i]
            assert fr.t == times[i]
            np.testing.assert_array_equal(fr.positions, f["particles/all/position/value"][i])
            np.testing.assert_array_equal(fr.velocities, f["particles/all/velocity/value"][i])
            np.testing.assert_array_equal(fr.images, f["particles/all/image/value"][i])
            np.testing.assert_array_equal(fr.box, np.diag(f["particles/all/box/edges/value"][i]))
            np.testing.assert_array_equal(fr.ids, np.arange(f["parameters"].attrs["N"]))
            assert fr.masses is None and fr.diameters is None
        # nearest time: the earlier dump on a tie, as the tools' --time
        mid = 0.5 * (times[2] + times[3])
        assert frames.at(mid).index == 2 and frames.at(times[3] * 1.01).index == 3
    with pytest.raises(IndexError):
        frames[len(times)]
    with pytest.raises(TypeError):
        frames[1.5]


def test_aggregation_frames_hold_the_live_aggregates_only(aggregates):
    run = coolgas.open(aggregates)
    fr = run.frames[-1]
    with h5py.File(aggregates, "r") as f:
        ids = f["particles/all/id/value"][-1]
        live = ids != -1
        assert live.sum() < len(ids)  # some have merged
        np.testing.assert_array_equal(fr.ids, ids[live])
        np.testing.assert_array_equal(fr.masses, f["particles/all/mass/value"][-1][live])
        np.testing.assert_array_equal(fr.diameters, f["particles/all/diameter/value"][-1][live])
        np.testing.assert_array_equal(fr.positions, f["particles/all/position/value"][-1][live])
    assert fr.masses.sum() == run.parameters["N"]  # mass is conserved
    assert "aggregates" in run.observables.columns


def test_read_table_is_pandas_with_provenance(gas, tmp_path):
    out = tool("energy", gas).stdout
    path = tmp_path / "E.tsv"
    path.write_text(out)
    df = coolgas.read_table(path)
    # round_trip: pandas' default float parser may miss the last bit of the shortest form
    ref = pd.read_csv(path, sep="\t", comment="#", float_precision="round_trip")
    pd.testing.assert_frame_equal(df, ref, check_exact=True, check_dtype=False)  # every column float64 here
    assert df.attrs["tool"] == "coolgas-energy"
    assert df.attrs["version"] == coolgas.__version__
    assert df.attrs["input"] == str(gas)
    assert df.attrs["L"] == "16"


def test_read_table_refuses_a_ragged_table(tmp_path):
    path = tmp_path / "bad.tsv"
    path.write_text("t\tE\n1\t2\n3\n")
    with pytest.raises(coolgas.InputError, match=r"bad\.tsv:3: 1 fields, expected 2"):
        coolgas.read_table(path)


def test_another_programs_h5md_file(tmp_path):
    """An H5MD 1.1 file as another program writes it (group 'atoms', ids with
    a hole, a time-dependent box, one observable), read through the same objects."""
    path = tmp_path / "other.h5"
    rng = np.random.default_rng(1)
    pos = rng.uniform(0, 10, (3, 5, 3))
    vel = rng.normal(size=(3, 5, 3))
    with h5py.File(path, "w") as f:
        f.create_group("h5md").attrs["version"] = [1, 1]
        g = f.create_group("particles/atoms")
        box = g.create_group("box")
        box.attrs["dimension"] = 3
        box.attrs["boundary"] = ["periodic"] * 3
        box.create_dataset("edges/value", data=np.tile(np.eye(3) * 10, (3, 1, 1)))
        box.create_dataset("edges/time", data=[0.0, 1.0, 2.0])
        box.create_dataset("edges/step", data=[0, 1, 2])
        for name, data in (("position", pos), ("velocity", vel), ("id", np.tile([4, 3, -1, 1, 0], (3, 1)))):
            g.create_dataset(f"{name}/value", data=data)
            g.create_dataset(f"{name}/time", data=[0.0, 1.0, 2.0])
            g.create_dataset(f"{name}/step", data=[0, 1, 2])
        f.create_dataset("observables/energy/value", data=[3.0, 2.0, 1.0])
        f.create_dataset("observables/energy/time", data=[0.0, 1.0, 2.0])
        f.create_dataset("observables/energy/step", data=[0, 1, 2])
    run = coolgas.open(path)
    assert not run.is_coolgas and run.parameters["group"] == "atoms" and run.parameters["L"] == 10
    assert len(run.frames) == 3
    fr = run.frames.at(1.2)
    present = [0, 1, 3, 4]
    assert fr.index == 1 and fr.t == 1.0 and fr.L == 10
    np.testing.assert_array_equal(fr.positions, pos[1][present])
    np.testing.assert_array_equal(fr.velocities, vel[1][present])
    np.testing.assert_array_equal(fr.ids, [4, 3, 1, 0])
    np.testing.assert_array_equal(run.observables["energy"].to_numpy(), [3.0, 2.0, 1.0])


def test_another_programs_2d_h5md_file(tmp_path):
    """Disks from another program (box/dimension 2, rows of two numbers):
    (n, 2) arrays exactly as written, and run.dimension 2."""
    path = tmp_path / "disks.h5"
    pos = np.random.default_rng(2).uniform(0, 8, (4, 2))
    with h5py.File(path, "w") as f:
        f.create_group("h5md").attrs["version"] = [1, 1]
        box = f.create_group("particles/all/box")
        box.attrs["dimension"] = 2
        box.attrs["boundary"] = ["periodic"] * 2
        box.create_dataset("edges", data=[8.0, 8.0])
        f.create_dataset("particles/all/position", data=pos)
    run = coolgas.open(path)
    assert run.dimension == 2 and run.parameters["L"] == 8
    np.testing.assert_array_equal(run.frames[0].positions, pos)


def test_a_file_being_written_reads_its_complete_dumps(tmp_path):
    """coolgas.open while coolgas-simulate writes: the writer waits with its
    6th dump's rows written but not flushed (the named point dump-frame,
    common/fault_point.h); the reader sees the 5 complete dumps, each equal
    to the same dump of the finished file, and observables up to the last."""
    scene = tmp_path / "live.toml"
    scene.write_text("[system]\nN = 20000\nphi = 0.2\nseed = 5\n[collision]\nmodel = \"inelastic\"\nr0 = 0.5\n"
                     "delta = 1e-4\n[run]\nt_end = 60\n[output]\ndumps_per_decade = 20\nt_min = 0.1\n")
    out, ready = tmp_path / "live.h5", tmp_path / "ready"
    proc = subprocess.Popen([os.path.join(BIN, "coolgas-simulate"), "-q", scene, "-o", out],
                            env=waiting_at("dump-frame:6", ready))
    try:
        wait_for_point(ready, proc)
        run = coolgas.open(out)
        obs = run.observables
        seen = [(frame.t, frame.velocities.copy()) for frame in run.frames]
        proc.send_signal(signal.SIGCONT)  # the writer goes on to the end
        assert proc.wait(timeout=HANG_S) == 0
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert len(seen) == 5
    assert obs.index[-1] <= seen[-1][0]  # observables up to the last complete dump
    done = coolgas.open(out).frames
    for i, (t, v) in enumerate(seen):
        assert done[i].t == t
        np.testing.assert_array_equal(done[i].velocities, v)
