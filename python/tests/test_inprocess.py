"""The in-process run (sedem.simulate, through sedem._sedem) against the program's: the same
readings bit for bit, a stop that leaves a folder `sedem run --resume` and sedem.resume go on
with, tables with their units in the column names."""

import json
import os
import shutil
import signal
import subprocess

import numpy as np
import pytest

import sedem
from conftest import DEMO, OUT, SMALL

pandas = pytest.importorskip("pandas")

# Long enough (a few seconds of computing) that a stop lands in the middle.
LONG = dict(SMALL, **{"sample.simulated_count": 3000, "run.end_time_s": 1200,
                      "instruments.hydrometer.times_min": [0.5, 2, 5, 10, 20]})


def cli_run(out, values):
    shutil.rmtree(out, ignore_errors=True)
    args = [sedem.executable(), "run", DEMO, "--out", str(out), "--quiet"]
    for k, v in values.items():
        args += ["--set", sedem.inprocess.overrides({k: v})[0]]
    subprocess.run(args, check=True)
    return sedem.load_run(out)


def dem_readings(sim):
    return {t["test"]: t["dem"] for t in sim.results()}


def assert_same_readings(sim, folder):
    """Every DEM reading of the in-process run equals the program's CSV (written with the
    shortest text that reads back as the same double), and so do the files themselves."""
    readings = dem_readings(sim)
    assert readings
    for test, columns in readings.items():
        csv = folder.table(f"readings_{test}", frame=False)
        assert len(csv["time_s"]) == len(columns["time_s"])
        for name, values in columns.items():
            np.testing.assert_array_equal(values, csv[name], err_msg=f"{test} {name}")
        assert (sim.path / f"readings_{test}.csv").read_bytes() == \
            (folder.path / f"readings_{test}.csv").read_bytes()
    assert (sim.path / "granulometry.csv").read_bytes() == \
        (folder.path / "granulometry.csv").read_bytes()


@pytest.fixture(scope="module")
def small_sim():
    out = OUT / "inprocess_small"
    shutil.rmtree(out, ignore_errors=True)
    return sedem.simulate(DEMO, set=SMALL, out=out, particles="all")


def test_an_in_process_run_equals_the_programs_bit_for_bit(small_sim):
    cli = cli_run(OUT / "cli_small", SMALL)
    assert small_sim.status == "complete" and cli.status == "complete"
    assert_same_readings(small_sim, cli)
    # The folder is the program's: run.json says so.
    assert small_sim.folder.status == "complete"
    assert small_sim.folder.record["particle_count"] == 300


def test_readings_are_tidy_with_units_in_the_column_names(small_sim):
    r = small_sim.readings()
    assert isinstance(r, pandas.DataFrame)
    assert list(r.columns[:5]) == ["test", "source", "time_s", "diameter_um", "percent_finer"]
    hydrometer = r[(r.test == "hydrometer") & (r.source == "dem")]
    np.testing.assert_array_equal(hydrometer.time_s, [15, 30, 60])
    # µm, not m: the demo's grains are 10 and 60 µm, the readings' diameters between.
    assert hydrometer.diameter_um.between(1, 100).all()
    assert "diameter_m" not in r.columns
    assert set(r.source) == {"dem", "reference"}
    # The buoyancy sphere's apparent mass in g (its column names its unit).
    assert any(c.endswith("_g") for c in r.columns if "mass" in c)


def test_errors_true_curve_and_granulometry(small_sim):
    e = small_sim.errors()
    assert list(e.columns) == ["test", "error_pp", "bias_pp", "readings"]
    record = small_sim.folder.results
    for row in e.itertuples():
        if np.isfinite(row.error_pp):
            assert row.error_pp == pytest.approx(record[row.test]["error_pp"], rel=1e-12)
    true = small_sim.true_curve()
    assert list(true.columns) == ["diameter_um", "percent_finer"]
    np.testing.assert_allclose(true.diameter_um, [10, 60])
    assert true.percent_finer.iloc[-1] == pytest.approx(100)
    g = small_sim.granulometry()
    # The same table as load_run's from granulometry.csv.
    f = small_sim.folder.granulometry()
    assert list(g.columns) == list(f.columns)
    np.testing.assert_array_equal(g.percent_finer.to_numpy(float),
                                  f.percent_finer.to_numpy(float))


def test_particles_as_arrays_at_the_runs_times(small_sim):
    kept = small_sim.particles()
    times = [p["time_s"] for p in kept]
    assert times[0] == 0 and times[-1] == 60 and times == sorted(times)
    series = small_sim.folder.series("particles")
    assert set(series.times) <= set(times)  # every time the run stopped at
    last = kept[-1]
    assert last["y_m"].shape == (300,) and last["y_m"].dtype == np.float64
    # The particles the program wrote at that time, in the same order.
    from_file = series.arrays(len(series) - 1)
    np.testing.assert_allclose(last["diameter_m"], from_file["diameter"])
    np.testing.assert_allclose(last["y_m"], from_file["points"][:, 1], rtol=1e-6)
    assert (last["y_m"] < kept[0]["y_m"]).mean() > 0.9  # they settled


def test_a_scene_from_a_dict_with_progress(tmp_path):
    seen = []
    sim = sedem.simulate({"name": "dict scene", "sample": {"simulated_count": 500},
                          "run.end_time_s": 30, "output.frames": False},
                         set={"sample.seed": 3}, out=tmp_path / "run", particles="none",
                         progress=lambda t, end, steps: seen.append((t, end)))
    assert sim.status == "complete"
    scene = sim.folder.scene
    assert scene["name"] == "dict scene" and scene["sample.seed"] == 3
    assert scene["sample.simulated_count"] == 500
    assert sim.particles() == []
    assert all(end == 30 for _, end in seen)


def test_a_bad_scene_raises_with_the_reason(tmp_path):
    with pytest.raises(sedem.RunError) as e:
        sedem.simulate(DEMO, set={"fluid.viscosity": -2}, out=tmp_path / "bad")
    assert e.value.status == 2


def stopped_run(out, how):
    """A long run stopped from Python once it is under way: `how` is "stop" (Simulation.stop
    from the callback) or "sigint" (Ctrl-C: SIGINT to this process)."""
    shutil.rmtree(out, ignore_errors=True)
    sim = sedem.Simulation(DEMO, set=LONG, out=out).start()

    def progress(t, end, steps):
        if t > 60 and not sim._run.stop_asked:
            if how == "stop":
                sim.stop()
            else:
                os.kill(os.getpid(), signal.SIGINT)

    if how == "sigint":
        with pytest.raises(KeyboardInterrupt):
            sim.wait(progress, poll=0.05)
    else:
        sim.wait(progress, poll=0.05)
    return sim


@pytest.mark.parametrize("how", ["stop", "sigint"])
def test_a_stop_leaves_a_folder_that_resumes_to_the_uninterrupted_result(how):
    out = OUT / f"inprocess_stopped_{how}"
    sim = stopped_run(out, how)
    record = json.loads((out / "run.json").read_text())
    assert record["status"] == "interrupted"
    assert 0 < record["simulated_time_s"] < 1200, "the stop did not land mid-run"
    assert (out / "checkpoint.bin").is_file()
    if how == "stop":
        assert sim.status == "interrupted"
    # The program goes on with it, to exactly an uninterrupted run's readings.
    resumed = sedem.resume(out)
    assert resumed.status == "complete" and resumed.folder.record["legs"] == 2
    assert_same_readings(resumed, cli_run(OUT / "cli_long", LONG))


def test_the_program_resumes_a_run_stopped_from_python():
    out = OUT / "inprocess_stopped_cli_resume"
    stopped_run(out, "stop")
    subprocess.run([sedem.executable(), "run", "--resume", str(out), "--quiet"], check=True)
    assert sedem.load_run(out).status == "complete"
