"""The subprocess path against a real `sedem`: run through ctest (SEDEM_EXE names the build's
program, SEDEM_TEST_OUTPUT where runs go)."""

import shutil
from pathlib import Path

import numpy as np
import pytest

import sedem
from conftest import DEMO, OUT, SMALL


@pytest.fixture(scope="module")
def demo_run():
    out = OUT / "run"
    shutil.rmtree(out, ignore_errors=True)
    return sedem.run(DEMO, out=out, set=SMALL)


def test_run_applies_overrides_and_loads_the_record(demo_run):
    assert demo_run.status == "complete"
    assert demo_run.scene["sample.simulated_count"] == 300
    assert demo_run.scene["output.frames"] is False
    assert demo_run.scene["instruments.hydrometer.times_min"] == [0.25, 0.5, 1]
    assert demo_run.record["particle_count"] == 300
    assert set(demo_run.results) == {"hydrometer", "buoyancy", "pipette"}
    for f in demo_run.files:
        assert (demo_run.path / f).is_file(), f


def test_csv_as_arrays(demo_run):
    readings = demo_run.table("readings_hydrometer", frame=False)
    assert isinstance(readings["time_s"], np.ndarray)
    np.testing.assert_allclose(readings["time_s"], [15, 30, 60])
    g = demo_run.table("granulometry", frame=False)
    assert g["test"].dtype.kind == "U"            # text stays text
    assert np.isnan(g["time_s"][0])               # empty cells are NaN
    assert "figures/fig18_granulometry" in demo_run.tables()


def test_csv_as_a_dataframe_where_pandas_is_installed(demo_run):
    pandas = pytest.importorskip("pandas")
    g = demo_run.table("granulometry")
    assert isinstance(g, pandas.DataFrame)
    assert list(g.columns[:3]) == ["test", "source", "time_s"]


def test_series_through_vtk(demo_run):
    particles = demo_run.series("particles")
    assert particles.times[0] == 0 and particles.times[-1] == 60
    last = particles.arrays(-1)
    assert last["diameter"].shape == (300,)
    assert last["velocity"].shape == (300, 3)
    assert last["points"].shape == (300, 3)
    assert set(np.round(last["diameter"] * 1e6)) == {10, 60}
    fields = demo_run.series("fields")
    assert len(fields) == len(fields.files) > 1


def test_a_failed_run_raises_with_the_message():
    with pytest.raises(sedem.SedemError) as e:
        sedem.run(DEMO, out=OUT / "bad", set={"fluid.viscosity": -2})
    assert e.value.status == 2
    assert "fluid.viscosity = -2 is out of range" in e.value.output


def test_default_output_folder(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    r = sedem.run(DEMO, set=dict(SMALL, **{"run.end_time_s": 10}))
    assert r.path == Path("out/demo") and r.status == "complete"


def test_batch_returns_the_summary():
    out = OUT / "batch"
    shutil.rmtree(out, ignore_errors=True)
    summary = sedem.batch(DEMO, out=out, sweep={"sample.simulated_count": [300, 400]},
                          set=dict(SMALL, **{"run.end_time_s": 20}), jobs=2)
    if not isinstance(summary, dict):
        summary = {c: summary[c].to_numpy() for c in summary.columns}
    np.testing.assert_array_equal(summary["sample.simulated_count"], [300, 400])
    assert list(summary["status"]) == ["complete", "complete"]
    assert (out / "summary_error.png").is_file()
    assert sedem.load_batch(out).stats is None


def test_a_seed_batch_loads_its_statistics():
    out = OUT / "seed_batch"
    shutil.rmtree(out, ignore_errors=True)
    sedem.batch(DEMO, out=out, seeds=3, seed0=4, jobs=2,
                set=dict(SMALL, **{"run.end_time_s": 20,
                                   "instruments.hydrometer.times_min": [0.25]}))
    b = sedem.load_batch(out, frame=False)
    np.testing.assert_array_equal(b.summary["seed"], [4, 5, 6])
    assert [r.record["seed"] for r in b.runs()] == [4, 5, 6]
    assert b.stats["runs"].tolist() == [3]
    errors = b.summary["hydrometer_error_pp"]
    mean, sd = errors.mean(), errors.std(ddof=1)
    # summary.csv holds 6 significant digits, summary_stats.csv every digit.
    np.testing.assert_allclose(b.stats["hydrometer_error_pp_mean"], [mean], rtol=1e-5)
    np.testing.assert_allclose(b.stats["hydrometer_error_pp_sd"], [sd], rtol=1e-5)
    half = 4.302653 * sd / np.sqrt(3)  # t(0.95, 2 dof)
    close = dict(rtol=0, atol=1e-4 * (abs(mean) + sd))
    np.testing.assert_allclose(b.stats["hydrometer_error_pp_ci95_low"], [mean - half], **close)
    np.testing.assert_allclose(b.stats["hydrometer_error_pp_ci95_high"], [mean + half], **close)
    # No buoyancy reading in 20 s: nothing to average, empty cells.
    assert np.isnan(b.stats["buoyancy_error_pp_mean"][0])


def test_reduce(tmp_path):
    lab = tmp_path / "lab.csv"
    lab.write_text("time_min,reading_g_per_l,temperature_c\n2,40,20\n5,30,20\n")
    table = sedem.reduce(str(lab), mass_g=50, frame=False)
    np.testing.assert_allclose(table["percent_finer"], [80, 60])
    # D7928's diameter at 2 min, 20 °C, in µm (the program writes metres).
    assert "diameter_m" not in table
    np.testing.assert_allclose(table["diameter_um"][0], 30.086307934799644, rtol=1e-12)


CLAY_LOAM = """time_min,reading_g_per_l,temperature_c,composite_correction_g_per_l
0.66,39,23,2
2,33,23,2
5,29,23,2
15,23,23,2
30,22,23,2
60,20,23,2
180,18,23,2
"""


def test_invert_returns_tables_in_micrometres(tmp_path):
    """docs/invert.md's clay loam: the inverted curve at 15 min near its 42 %."""
    pytest.importorskip("pandas")
    lab = tmp_path / "clay_loam.csv"
    lab.write_text(CLAY_LOAM)
    out = sedem.invert(lab, test="hydrometer", out=tmp_path / "inv",
                       options={"gs": 2.65, "mass-g": 50})
    curve, fit = out["curve"], out["fit"]
    assert {"diameter_um", "percent_finer", "percent_finer_low",
            "percent_finer_high"} <= set(curve.columns)
    assert "diameter_m" not in curve.columns
    assert curve.diameter_um.between(0.01, 1e4).all()
    assert len(fit) == 7 and "time_s" in fit.columns
    assert out["record"] and (out["path"] / "invert.json").is_file()
    at = np.interp(12.6, curve.diameter_um, curve.percent_finer)
    assert at == pytest.approx(42, abs=3)


def test_design_returns_its_readings(tmp_path):
    pytest.importorskip("pandas")
    out = sedem.design(DEMO, test="hydrometer", out=tmp_path / "design", readings=3,
                       dem_count=0)
    d = out["readings"]
    assert {"schedule", "source", "time_min"} <= set(d.columns)
    assert {"standard"} <= set(d.schedule)
    assert out["record"]["test"] == "hydrometer"


def test_reduce_the_whole_curve(tmp_path):
    """';' and decimal commas, a sieve analysis: the whole curve, its sources, by hand (the
    hydrometer's 80 and 60 % of the fraction passing 75 um, 50 % of the sample)."""
    lab = tmp_path / "lab.csv"
    lab.write_text("time (min);R (g/L);T (\u00b0C)\n2;40;20,0\n5;30;20\n", encoding="utf-8")
    sieves = tmp_path / "sieves.csv"
    sieves.write_text("opening (mm),mass retained (g)\n4.75,12\n2,18\n0.075,70\npan,100\n")
    table = sedem.reduce(str(lab), mass_g=50, sieve=str(sieves), separating_sieve_mm=0.075,
                         report=str(tmp_path / "r.html"), frame=False)
    assert list(table["source"]) == ["sieve", "sieve", "sieve", "hydrometer", "hydrometer"]
    np.testing.assert_allclose(table["percent_finer"], [94, 85, 50, 40, 30])
    assert (tmp_path / "r.html").exists()
