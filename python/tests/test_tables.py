"""Run and batch folders as tidy tables: granulometry without its error and bias rows mixed
into percent_finer, readings in µm and g, the fields over time as an xarray Dataset, a seed
batch as one table with the seed and swept key as columns."""

import shutil

import numpy as np
import pytest

import sedem
from conftest import DEMO, OUT, SMALL

pandas = pytest.importorskip("pandas")


@pytest.fixture(scope="module")
def folder():
    out = OUT / "tables_run"
    shutil.rmtree(out, ignore_errors=True)
    sedem.run(DEMO, out=out, set=SMALL)
    return sedem.load_run(out)


def test_granulometry_keeps_curves_and_figures_apart(folder):
    g = folder.granulometry()
    assert list(g.columns) == ["test", "source", "time_s", "diameter_um", "percent_finer"]
    assert set(g.source) <= {"true", "dem", "reference"}
    assert g.percent_finer.between(-50, 150).all()
    true = g[g.test == "true"]
    np.testing.assert_allclose(true.diameter_um, [10, 60])
    raw = folder.table("granulometry")
    assert (raw.source == "error_pp").sum() == 3  # the file's own layout, unchanged
    e = folder.errors()
    assert list(e.columns) == ["test", "error_pp", "bias_pp"]
    assert list(e.test) == ["hydrometer", "buoyancy", "pipette"]
    h = e.set_index("test").loc["hydrometer"]
    assert h.error_pp == pytest.approx(folder.results["hydrometer"]["error_pp"], rel=1e-12)


def test_readings_in_micrometres_and_grams(folder):
    r = folder.readings()
    assert {"test", "time_s", "diameter_um", "percent_finer"} <= set(r.columns)
    assert not any(c.endswith("_kg") or c == "diameter_m" for c in r.columns)
    raw = folder.table("readings_hydrometer")
    h = r[r.test == "hydrometer"]
    np.testing.assert_allclose(h.diameter_um, raw.diameter_m * 1e6)
    b = folder.table("readings_buoyancy")
    kg = [c for c in b.columns if c.endswith("_kg")]
    assert kg, "the sphere's readings name a mass in kg"
    np.testing.assert_allclose(r[r.test == "buoyancy"][kg[0][:-3] + "_g"], b[kg[0]] * 1e3)


def test_fields_over_time_as_an_xarray_dataset(folder):
    xarray = pytest.importorskip("xarray")
    ds = folder.fields()
    assert isinstance(ds, xarray.Dataset)
    assert ds.suspension_density_kg_m3.dims == ("time_s", "depth_m")
    assert float(ds.time_s[0]) == 0 and float(ds.time_s[-1]) == 60
    assert float(ds.depth_m[0]) < float(ds.depth_m[-1])  # from the surface down
    # The suspension clears from the top: the 60 µm grains leave the upper 10 cm in a minute.
    top = ds.concentration_kg_m3.sel(depth_m=slice(0, 0.1)).mean("depth_m")
    assert float(top.isel(time_s=0)) > 1.5 * float(top.isel(time_s=-1)) > 0


def test_a_seed_batch_as_one_table():
    out = OUT / "tables_seeds"
    shutil.rmtree(out, ignore_errors=True)
    sedem.batch(DEMO, out=out, seeds=2, jobs=2,
                sweep={"sample.simulated_count": [200, 300]},
                set=dict(SMALL, **{"run.end_time_s": 20,
                                   "instruments.hydrometer.times_min": [0.25]}))
    b = sedem.load_batch(out)
    errors = b.table("errors")
    assert {"run", "seed", "sample.simulated_count", "test", "error_pp"} <= set(errors.columns)
    assert len(errors) == 4 * 3  # four runs, three tests each
    per_run = errors.groupby(["sample.simulated_count", "seed"]).size()
    assert sorted(per_run.index) == [(200, 1), (200, 2), (300, 1), (300, 2)]
    g = b.table("granulometry")
    dem = g[(g.test == "hydrometer") & (g.source == "dem")]
    assert sorted(set(dem.seed)) == [1, 2] and dem.time_s.eq(15).all()
