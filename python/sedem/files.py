"""Run and batch folders as files: run.json, each CSV as a table, the .pvd series through VTK.

Tables are pandas DataFrames when pandas is installed (and ``frame=True``), otherwise a
dict of column name -> numpy array (numbers as float, empty cells as NaN; text columns as
arrays of str). The ParaView series are read with VTK's Python (Debian: python3-vtk9).
"""

import csv
import json
import xml.etree.ElementTree as ET
from pathlib import Path


def _pandas():
    try:
        import pandas
        return pandas
    except ImportError:
        return None


def _column(values):
    import numpy as np
    try:
        return np.array([float(v) if v != "" else np.nan for v in values], dtype=float)
    except ValueError:
        return np.array(values, dtype=str)


def read_csv(path, frame=True):
    """A CSV file as a pandas DataFrame (when pandas is installed and `frame`), otherwise a
    dict of column name -> numpy array."""
    pandas = _pandas() if frame else None
    # Comment lines above the header ("# partial: ..." in the outputs of a partial run).
    with open(path, newline="") as f:
        comments = 0
        for line in f:
            if not line.startswith("#"):
                break
            comments += 1
    if pandas is not None:
        return pandas.read_csv(path, skiprows=comments)
    with open(path, newline="") as f:
        rows = list(csv.reader(f))[comments:]
    if not rows:
        return {}
    header, body = rows[0], rows[1:]
    return {name: _column([r[i] if i < len(r) else "" for r in body])
            for i, name in enumerate(header)}


class Series:
    """A ParaView .pvd series: its times and files, each read with VTK on demand."""

    def __init__(self, pvd):
        self.path = Path(pvd)
        root = ET.parse(self.path).getroot()
        entries = [(float(d.get("timestep")), self.path.parent / d.get("file"))
                   for d in root.iter("DataSet")]
        self.times = [t for t, _ in entries]
        self.files = [f for _, f in entries]

    def __len__(self):
        return len(self.files)

    def read(self, i):
        """The VTK data set at index i (vtkPolyData for .vtp, vtkImageData for .vti)."""
        from vtkmodules.vtkIOXML import vtkXMLGenericDataObjectReader
        reader = vtkXMLGenericDataObjectReader()
        reader.SetFileName(str(self.files[i]))
        reader.Update()
        return reader.GetOutput()

    def arrays(self, i):
        """The point arrays at index i as numpy arrays, by name, and "points" (n x 3, m)."""
        from vtkmodules.util.numpy_support import vtk_to_numpy
        data = self.read(i)
        out = {}
        if hasattr(data, "GetPoints") and data.GetPoints() is not None:
            out["points"] = vtk_to_numpy(data.GetPoints().GetData())
        pd = data.GetPointData()
        for k in range(pd.GetNumberOfArrays()):
            out[pd.GetArrayName(k)] = vtk_to_numpy(pd.GetArray(k))
        return out


class Run:
    """A run folder written by `sedem run`."""

    def __init__(self, path):
        self.path = Path(path)
        record = self.path / "run.json"
        if not record.is_file():
            raise FileNotFoundError(f"{record}: no run.json (is this a sedem run folder?)")
        with open(record) as f:
            self.record = json.load(f)

    def __repr__(self):
        return f"Run({str(self.path)!r}, status={self.status!r})"

    @property
    def status(self):
        return self.record.get("status")

    @property
    def scene(self):
        """The scene as resolved: every key (dotted name) in the scene file's units."""
        return self.record.get("scene", {})

    @property
    def results(self):
        """Each test's error and bias, percentage points: {"hydrometer": {"error_pp": ...}}."""
        return self.record.get("results", {})

    @property
    def files(self):
        """The files the run wrote (run.json lists them), relative to its folder."""
        return list(self.record.get("files", []))

    def tables(self):
        """The names of the run's CSV files (without .csv), e.g. "granulometry",
        "readings_hydrometer", "figures/fig18_granulometry"."""
        return sorted(str(p.relative_to(self.path).with_suffix(""))
                      for p in self.path.rglob("*.csv"))

    def table(self, name, frame=True):
        """One CSV file of the run by name, see tables()."""
        return read_csv(self.path / (name + ".csv"), frame=frame)

    def series(self, name="particles"):
        """A ParaView series of the run: "particles", "fields" or "hydrometer"."""
        return Series(self.path / (name + ".pvd"))

    def granulometry(self):
        """The true curve and each test's curves, DEM and reference, one row per point:
        test ("true" for the true curve), source, time_s, diameter_um, percent_finer."""
        from . import tables
        return tables.split_granulometry(self.table("granulometry", frame=False))[0]

    def errors(self):
        """Each test's error and bias in percentage points: test, error_pp, bias_pp."""
        from . import tables
        return tables.split_granulometry(self.table("granulometry", frame=False))[1]

    def readings(self):
        """Every test's DEM readings, one row per reading: test, time_s, diameter_um,
        percent_finer and the instrument's own columns (masses in g)."""
        from . import tables
        parts = [({"test": t}, tables.with_units(self.table(f"readings_{t}", frame=False)))
                 for t in tables.TESTS if (self.path / f"readings_{t}.csv").is_file()]
        return tables.stack(parts)

    def fields(self):
        """The layer fields over time (fields.pvd) as an xarray Dataset on (time_s,
        depth_m); a dict of arrays without xarray."""
        from . import tables
        return tables.fields_dataset(self.series("fields"))


def load_run(path):
    """The run in folder `path`."""
    return Run(path)


class Batch:
    """A batch folder written by `sedem batch`: its summary.csv (one row per run) and, for a
    batch of two seeds or more, summary_stats.csv (one row per scene and swept value: the
    runs counted and each test's error_pp and bias_pp mean, sd, ci95_low and ci95_high)."""

    def __init__(self, path, frame=True):
        self.path = Path(path)
        summary = self.path / "summary.csv"
        if not summary.is_file():
            raise FileNotFoundError(f"{summary}: no summary.csv (is this a sedem batch folder?)")
        self.summary = read_csv(summary, frame=frame)
        stats = self.path / "summary_stats.csv"
        self.stats = read_csv(stats, frame=frame) if stats.is_file() else None

    def __repr__(self):
        return f"Batch({str(self.path)!r})"

    def runs(self):
        """Each run of the batch, in summary.csv's order (its "run" column names the folder)."""
        return [Run(self.path / name) for name in list(self.summary["run"])]

    def table(self, what="errors"):
        """One table of every run of the batch: "errors", "granulometry" or "readings" (as
        Run has them), with the run's folder, its swept key (a scene key's column) and its
        seed as columns: a seed sweep groups by them directly."""
        from . import tables
        cols = {c: list(self.summary[c]) for c in _keys_of(self.summary)}
        parts = []
        for i, run in enumerate(self.runs()):
            constants = {c: cols[c][i] for c in cols}
            parts.append((constants, getattr(run, what)()))
        return tables.stack(parts)


def _keys_of(summary):
    """The columns of summary.csv that say which run a row is: its folder, scene, swept key
    (a dotted scene key) and seed."""
    names = list(summary.columns) if hasattr(summary, "columns") else list(summary)
    return [n for n in names if n in ("run", "scene", "seed") or "." in n]


def load_batch(path, frame=True):
    """The batch in folder `path`: .summary and .stats (None without seeds) as tables."""
    return Batch(path, frame=frame)


