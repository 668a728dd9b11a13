"""sedem from Python: load a run folder, and run ``sedem`` (run, batch, reduce).

    >>> import sedem
    >>> run = sedem.run("scenes/demo.toml", out="out/demo", set={"run.end_time_s": 60})
    >>> run.record["results"]["hydrometer"]["error_pp"]
    >>> g = run.table("granulometry")          # a pandas DataFrame, or a dict of arrays
    >>> series = run.series("particles")       # the .pvd series, read with VTK
    >>> series.arrays(-1)["diameter"]          # a point array of the last output time
    >>> b = sedem.load_batch("out/batch")      # summary.csv and summary_stats.csv

Tables are pandas DataFrames when pandas is installed (and ``frame=True``), otherwise a
dict of column name -> numpy array (numbers as float, empty cells as NaN; text columns as
arrays of str). The ParaView series are read with VTK's Python (Debian: python3-vtk9).
"""

import csv
import json
import os
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

__all__ = ["Run", "Series", "Batch", "load_run", "load_batch", "read_csv", "run", "batch",
           "reduce", "executable", "SedemError"]


class SedemError(RuntimeError):
    """`sedem` ended with a non-zero status; `status` and `output` say why."""

    def __init__(self, args, status, output):
        super().__init__(f"sedem {' '.join(args)} ended with status {status}:\n{output}")
        self.status = status
        self.output = output


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


def load_batch(path, frame=True):
    """The batch in folder `path`: .summary and .stats (None without seeds) as tables."""
    return Batch(path, frame=frame)


def executable():
    """The sedem program: $SEDEM_EXE, else `sedem` on the PATH, else the build tree's."""
    exe = os.environ.get("SEDEM_EXE") or shutil.which("sedem")
    if exe:
        return exe
    built = Path(__file__).resolve().parents[2] / "build" / "app" / "sedem"
    if built.is_file():
        return str(built)
    raise FileNotFoundError("sedem not found: set SEDEM_EXE, put sedem on the PATH, or build "
                            "it (cmake --build build --target sedem)")


def _value(v):
    """A Python value as a --set value (TOML): True -> true, [1, 2] -> [1,2]."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (list, tuple)):
        return "[" + ",".join(_value(x) for x in v) + "]"
    return str(v)


def _sets(overrides):
    args = []
    for key, value in (overrides or {}).items():
        args += ["--set", f"{key}={_value(value)}"]
    return args


def _sedem(args, check=True, quiet=True):
    cmd = [executable()] + [str(a) for a in args]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if check and done.returncode != 0:
        raise SedemError([str(a) for a in args], done.returncode, done.stdout + done.stderr)
    return done


def run(scene, out=None, set=None, overwrite=False, check=True):
    """`sedem run SCENE [--out OUT] [--set key=value]... [--overwrite]`; returns the Run.
    `set` is a dict of scene keys to values, e.g. {"sample.simulated_count": 2000}.
    Without `out`, the run goes to out/<scene name> (relative to the current folder)."""
    args = ["run", scene, "--quiet"] + _sets(set)
    if out is not None:
        args += ["--out", out]
    if overwrite:
        args.append("--overwrite")
    done = _sedem(args, check=check)
    if out is None:  # where sedem put it: out/<scene name>, made a safe folder name
        out = Path("out") / _scene_name(scene, set)
    result = Run(out)
    result.returncode = done.returncode
    return result


def _scene_name(scene, overrides):
    if overrides and "name" in overrides:
        return _safe_folder(str(overrides["name"]))
    try:
        import tomllib
        with open(scene, "rb") as f:
            return _safe_folder(tomllib.load(f).get("name", "scene"))
    except ImportError:
        import re
        with open(scene) as f:
            m = re.search(r'^\s*name\s*=\s*"([^"]*)"', f.read(), re.M)
        return _safe_folder(m.group(1) if m else "scene")


def _safe_folder(name):
    out = "".join(c if c.isascii() and (c.isalnum() or c in "._-=,+") else "_" for c in name)
    return "_" + out if not out or out.startswith(".") else out


def batch(scenes, out="out/batch", sweep=None, set=None, jobs=1, overwrite=False, check=True,
          seeds=None, seed0=None):
    """`sedem batch`: `scenes` a file or a list, `sweep` a dict {key: [values]} (one key),
    `seeds` runs of each differing only in sample.seed (seed0, seed0 + 1, ...).
    Returns the batch's summary.csv as a table (DataFrame or dict of arrays); load_batch(out)
    also reads the statistics over the seeds."""
    if isinstance(scenes, (str, os.PathLike)):
        scenes = [scenes]
    args = ["batch", *scenes, "--out", out, "--quiet", "--jobs", str(jobs)] + _sets(set)
    if seeds is not None:
        args += ["--seeds", str(seeds)]
    if seed0 is not None:
        args += ["--seed0", str(seed0)]
    if sweep:
        if len(sweep) != 1:
            raise ValueError("sweep: one key, e.g. {'sample.simulated_count': [1000, 2000]}")
        (key, values), = sweep.items()
        args += ["--sweep", f"{key}=" + ",".join(_value(v) for v in values)]
    if overwrite:
        args.append("--overwrite")
    _sedem(args, check=check)
    return read_csv(Path(out) / "summary.csv")


def reduce(readings, method="d7928", gs=2.65, mass_g=50.0, out=None, frame=True,
           volume_ml=1000.0, sheet=None, sieve=None, sieve_sheet=None, sieve_total_g=None,
           separating_sieve_mm=None, report=None):
    """`sedem reduce`: a laboratory's hydrometer readings (CSV with ',' or ';', tab-separated
    text or .xlsx, `sheet` its sheet; time_min, reading_g_per_l, temperature_c or the lab's
    names and units) to diameters and percent finer, ASTM D7928 or, with method="d422", D422.
    With `sieve` (the sieve analysis, docs/lab.md) the whole grading curve, each row marked
    by its `source`; `report` writes the lab report page. Returns the table."""
    args = ["reduce", readings, "--method", method, "--gs", gs, "--mass-g", mass_g,
            "--volume-ml", volume_ml]
    for flag, value in (("--sheet", sheet), ("--sieve", sieve), ("--sieve-sheet", sieve_sheet),
                        ("--sieve-total-g", sieve_total_g),
                        ("--separating-sieve-mm", separating_sieve_mm), ("--report", report)):
        if value is not None:
            args += [flag, value]
    if out is not None:
        _sedem(args + ["--out", out])
        return read_csv(out, frame=frame)
    done = _sedem(args)
    import tempfile
    with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False) as f:
        f.write(done.stdout)
    try:
        return read_csv(f.name, frame=frame)
    finally:
        os.unlink(f.name)
