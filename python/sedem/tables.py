"""Tidy tables: one row per reading (or curve point), units in the column names, user-facing
units (µm, g) where the files hold SI. pandas DataFrames when pandas is installed, else a dict
of column -> numpy array; fields over time as an xarray Dataset where xarray is installed."""

import numpy as np

TESTS = ("hydrometer", "buoyancy", "pipette")


def pandas():
    try:
        import pandas
        return pandas
    except ImportError:
        return None


def frame(columns):
    """A dict of equal-length columns as a DataFrame (pandas installed) or as it is."""
    pd = pandas()
    return pd.DataFrame(columns) if pd is not None else columns


def _columns(table):
    if isinstance(table, dict):
        return dict(table)
    return {c: table[c].to_numpy() for c in table.columns}


def with_units(table):
    """Diameters in µm and masses in g, named so: diameter_m -> diameter_um (x 1e6),
    apparent_mass_kg -> apparent_mass_g (x 1e3). Other columns as they are."""
    out = {}
    for name, values in _columns(table).items():
        if "diameter" in name and name.endswith("_m"):
            out[name[:-2] + "_um"] = np.asarray(values, dtype=float) * 1e6
        elif name.endswith("_kg"):
            out[name[:-3] + "_g"] = np.asarray(values, dtype=float) * 1e3
        elif "diameter" in name and (name.endswith("_m_low") or name.endswith("_m_high")):
            out[name.replace("_m_", "_um_")] = np.asarray(values, dtype=float) * 1e6
        else:
            out[name] = values
    return out if isinstance(table, dict) else frame(out)


def stack(parts):
    """Tables with the same columns one under the other; constant columns given per part:
    parts is [(dict of constants, table)]. Columns missing from a part are NaN."""
    names = []
    for constants, table in parts:
        for n in list(constants) + list(_columns(table)):
            if n not in names:
                names.append(n)
    out = {n: [] for n in names}
    for constants, table in parts:
        cols = _columns(table)
        rows = len(next(iter(cols.values()))) if cols else 0
        for n in names:
            if n in constants:
                out[n].append(np.full(rows, constants[n], dtype=object))
            elif n in cols:
                out[n].append(np.asarray(cols[n]))
            else:
                out[n].append(np.full(rows, np.nan))
    merged = {}
    for n, chunks in out.items():
        values = np.concatenate(chunks) if chunks else np.array([])
        if values.dtype == object:
            # The constants' own type back (a seed stays an int, a folder a str).
            values = np.array(values.tolist())
            if values.dtype.kind == "U":
                values = values.astype(object)
        merged[n] = values
    return frame(merged)


def readings(tests):
    """Each test's readings, DEM and reference, as one table: test, source, time_s,
    diameter_um, percent_finer and the instrument's own columns. `tests` is a list of
    {"test", "dem": columns, "reference": columns} (the in-process results)."""
    parts = []
    for t in tests:
        for source in ("dem", "reference"):
            parts.append(({"test": t["test"], "source": source}, with_units(t[source])))
    return stack(parts)


def errors(tests):
    """Each test's error and bias (percentage points) and its number of readings."""
    return frame({"test": np.array([t["test"] for t in tests], dtype=object),
                  "error_pp": np.array([t["error_pp"] for t in tests], dtype=float),
                  "bias_pp": np.array([t["bias_pp"] for t in tests], dtype=float),
                  "readings": np.array([len(t["dem"]["time_s"]) for t in tests])})


def split_granulometry(table):
    """granulometry.csv as two tidy tables: the curves (test, source, time_s, diameter_um,
    percent_finer; the true curve as test "true") and each test's error and bias, which the
    file keeps in its percent_finer column as rows of source error_pp and bias_pp."""
    cols = _columns(table)
    source = np.asarray(cols["source"]).astype(str)
    test = np.asarray(cols["test"]).astype(str)
    figure = np.isin(source, ["error_pp", "bias_pp"])
    curves = with_units({n: np.asarray(v)[~figure] for n, v in cols.items()})
    names = [t for t in dict.fromkeys(test[figure])]
    value = np.asarray(cols["percent_finer"], dtype=float)

    def pick(t, s):
        rows = figure & (test == t) & (source == s)
        return value[rows][0] if rows.any() else np.nan

    errs = {"test": np.array(names, dtype=object),
            "error_pp": np.array([pick(t, "error_pp") for t in names], dtype=float),
            "bias_pp": np.array([pick(t, "bias_pp") for t in names], dtype=float)}
    return frame(curves), frame(errs)


def fields_dataset(series):
    """The layer fields over time (a run's fields.pvd) as an xarray Dataset on (time_s,
    depth_m): suspension_density_kg_m3, concentration_kg_m3 and the other layer arrays.
    Without xarray, a dict: "time_s", "depth_m" and each array as time x depth."""
    times = np.asarray(series.times, dtype=float)
    per_time = []
    for i in range(len(series)):
        a = series.arrays(i)
        # Two points per layer, across the section: one of each pair is the layer.
        per_time.append({n: np.asarray(v)[0::2] for n, v in a.items()
                         if n != "points" and np.asarray(v).ndim == 1})
    if not per_time:
        raise ValueError(f"{series.path}: no fields")
    depth = per_time[0]["depth"]
    names = [n for n in per_time[0] if n != "depth"]
    units = {"suspension_density": "suspension_density_kg_m3",
             "concentration": "concentration_kg_m3"}
    data = {units.get(n, n): np.stack([p[n] for p in per_time]) for n in names}
    try:
        import xarray
    except ImportError:
        return dict(data, time_s=times, depth_m=depth)
    return xarray.Dataset({n: (("time_s", "depth_m"), v) for n, v in data.items()},
                          coords={"time_s": times, "depth_m": depth})
