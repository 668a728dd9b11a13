"""The `sedem` program as a subprocess: batches, and the commands that read a laboratory's
readings (reduce, invert, design). A run of one scene is better made in-process
(sedem.simulate); sedem.run stays for scripts written against the program."""

import json
import os
import shutil
import subprocess
import tempfile
from pathlib import Path

from .files import Run, read_csv
from .version import build_dirs as _build_dirs


class SedemError(RuntimeError):
    """`sedem` ended with a non-zero status; `status` and `output` say why."""

    def __init__(self, args, status, output):
        super().__init__(f"sedem {' '.join(args)} ended with status {status}:\n{output}")
        self.status = status
        self.output = output


def executable():
    """The sedem program: $SEDEM_EXE, else `sedem` on the PATH, else the build tree's."""
    exe = os.environ.get("SEDEM_EXE") or shutil.which("sedem")
    if exe:
        return exe
    for build in _build_dirs():
        built = build / "app" / "sedem"
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
    by its `source`; `report` writes the lab report page. Returns the table, one row per
    point, diameters in µm (diameter_um; the file `out`, when given, keeps sedem's
    diameter_m)."""
    from .tables import with_units
    args = ["reduce", readings, "--method", method, "--gs", gs, "--mass-g", mass_g,
            "--volume-ml", volume_ml]
    for flag, value in (("--sheet", sheet), ("--sieve", sieve), ("--sieve-sheet", sieve_sheet),
                        ("--sieve-total-g", sieve_total_g),
                        ("--separating-sieve-mm", separating_sieve_mm), ("--report", report)):
        if value is not None:
            args += [flag, value]
    if out is not None:
        _sedem(args + ["--out", out])
        return with_units(read_csv(out, frame=frame))
    done = _sedem(args)
    with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False) as f:
        f.write(done.stdout)
    try:
        return with_units(read_csv(f.name, frame=frame))
    finally:
        os.unlink(f.name)


def invert(readings=None, test="hydrometer", out=None, run=None, scene=None, partial=False,
           options=None, frame=True):
    """`sedem invert`: a laboratory's readings (CSV) or, with `run`, a simulated run's own,
    back to the grading curve. `options` adds command-line options by name, e.g.
    {"gs": 2.65, "mass-g": 50}. Returns {"curve": inverted_curve.csv, "fit":
    readings_fit.csv, "record": invert.json, "path": the output folder} with tables in µm."""
    from . import tables
    if (readings is None) == (run is None):
        raise ValueError("invert: give readings (a CSV file) or run (a run folder), not both")
    out = Path(out) if out is not None else Path(tempfile.mkdtemp(prefix="sedem-invert-"))
    args = ["invert", readings] if readings is not None else ["invert", "--run", run]
    args += ["--test", test, "--out", out] + _options(options)
    if scene is not None:
        args += ["--scene", scene]
    if partial:
        args.append("--partial")
    _sedem(args)
    with open(out / "invert.json") as f:
        record = json.load(f)
    return {"curve": tables.with_units(read_csv(out / "inverted_curve.csv", frame=frame)),
            "fit": tables.with_units(read_csv(out / "readings_fit.csv", frame=frame)),
            "record": record, "path": out}


def design(scene, test="hydrometer", out=None, readings=None, set=None, dem_count=None,
           frame=True):
    """`sedem design`: the reading schedule that keeps the test's curve closest to the
    scene's true curve. Returns {"readings": design.csv (one row per reading of each
    schedule), "record": design.json, "path": the output folder}."""
    out = Path(out) if out is not None else Path(tempfile.mkdtemp(prefix="sedem-design-"))
    args = ["design", scene, "--test", test, "--out", out] + _sets(set)
    if readings is not None:
        args += ["--readings", readings]
    if dem_count is not None:
        args += ["--dem-count", dem_count]
    _sedem(args)
    with open(out / "design.json") as f:
        record = json.load(f)
    return {"readings": read_csv(out / "design.csv", frame=frame), "record": record,
            "path": out}


def _options(options):
    args = []
    for key, value in (options or {}).items():
        args += [f"--{key}", _value(value)]
    return args
