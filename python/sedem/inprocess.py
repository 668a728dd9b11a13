"""A run of one scene inside this Python process, through the compiled module sedem._sedem:
the same run as `sedem run` (its folder, files, checkpoint and resume), on a worker thread,
with a progress callback and a stop; the results as tables and the particles as arrays, read
from memory."""

import importlib.machinery
import importlib.util
import json
import math
import os
import sys
import tempfile
from pathlib import Path

from . import tables
from .files import Run
from .version import build_dirs

# sedem's exit statuses (README, "Exit status").
_STATUS = {0: "complete", 130: "interrupted"}


class RunError(RuntimeError):
    """A run that did not start or failed: `status` is sedem's exit status, `message` why."""

    def __init__(self, status, message):
        super().__init__(f"sedem run ended with status {status}: {message}")
        self.status = status
        self.message = message


def _extension():
    """sedem._sedem: installed beside the package, else from a build tree (a checkout's
    build/python, or $SEDEM_BUILD_DIR/python)."""
    # Loaded into the global symbol scope: the module's glewInit (render/glew_shim.cpp) must
    # come before libGLEW's for VTK's offscreen frames, as it does in the sedem program.
    flags = sys.getdlopenflags()
    sys.setdlopenflags(flags | os.RTLD_GLOBAL)
    try:
        try:
            from . import _sedem
            return _sedem
        except ImportError:
            pass
        for build in build_dirs():
            for suffix in importlib.machinery.EXTENSION_SUFFIXES:
                path = build / "python" / ("_sedem" + suffix)
                if path.is_file():
                    spec = importlib.util.spec_from_file_location("sedem._sedem", path)
                    module = importlib.util.module_from_spec(spec)
                    spec.loader.exec_module(module)
                    sys.modules["sedem._sedem"] = module
                    return module
    finally:
        sys.setdlopenflags(flags)
    raise ImportError("sedem._sedem, the in-process module, is not built: install the package "
                      "(pip install --no-build-isolation ./python) or build the target _sedem "
                      "(cmake --build build --target _sedem)")


def _toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return json.dumps(v)  # a TOML basic string
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    if isinstance(v, float) and not math.isfinite(v):
        raise ValueError(f"{v}: not a number a scene can hold")
    return repr(v) if isinstance(v, float) else str(v)


def _flatten(d, prefix=""):
    out = {}
    for k, v in d.items():
        key = f"{prefix}{k}"
        if isinstance(v, dict):
            out.update(_flatten(v, key + "."))
        else:
            out[key] = v
    return out


def scene_toml(scene):
    """A scene given as a dict (nested tables or dotted keys) as TOML text."""
    return "".join(f"{k} = {_toml_value(v)}\n" for k, v in _flatten(scene).items())


def overrides(values):
    """A dict of scene keys as --set assignments."""
    return [f"{k}={_toml_value(v)}" for k, v in _flatten(values or {}).items()]


class Simulation:
    """One run of a scene in this process.

    scene      a scene file (str or Path), a dict of scene keys ({"sample": {"seed": 2}} or
               {"sample.seed": 2}; every other key its default), or None (every default)
    set        overrides, as `sedem run --set`: {"sample.simulated_count": 2000}
    out        the run folder (as `sedem run --out`); None: a new temporary folder (kept)
    overwrite  replace the run the folder holds
    resume     a stopped run's folder to go on with (instead of scene)
    particles  which particles to keep in memory: "last" (the last time the run stops at),
               "output" (every output.interval_s), "all" (every time the run stops at) or a
               list of times in s (each the nearest time the run stops at); "none" keeps none.
               A copy costs 64 bytes a particle.

    start() runs it on a worker thread; wait(progress) waits for its end, calling
    progress(simulated_s, end_s, particle_steps) on the calling thread; stop() (from any
    thread, or the callback) or Ctrl-C during wait() stops it as Ctrl-C stops `sedem run`:
    its folder keeps what was computed and a checkpoint, and resume=folder goes on.
    """

    def __init__(self, scene=None, *, set=None, out=None, overwrite=False, resume=None,
                 particles="last", quiet=True):
        module = _extension()
        scene_file, text = "", ""
        if resume is not None:
            if scene is not None:
                raise ValueError("give a scene or resume, not both")
        elif isinstance(scene, dict):
            text = scene_toml(scene)
        elif scene is not None:
            scene_file = str(scene)
        if resume is not None:
            out = Path(resume)
        elif out is None:
            out = Path(tempfile.mkdtemp(prefix="sedem-run-"))
        self.path = Path(out)
        keep, times = particles, []
        if particles == "none":
            keep = "times"
        elif not isinstance(particles, str):
            keep, times = "times", [float(t) for t in particles]
        self._run = module.Run(scene=scene_file, scene_text=text, overrides=overrides(set),
                               out="" if resume is not None else str(out),
                               overwrite=overwrite,
                               resume=str(resume) if resume is not None else "",
                               keep_times=times, keep=keep, quiet=quiet)
        self.exit_status = None

    def __repr__(self):
        return f"Simulation({str(self.path)!r}, status={self.status!r})"

    def start(self):
        self._run.start()
        return self

    def stop(self):
        """Ask the run to stop at its next step; it then writes its folder and a checkpoint."""
        self._run.stop()

    @property
    def running(self):
        return self._run.running

    def wait(self, progress=None, poll=0.2):
        """Wait for the end. Raises RunError when the run failed (or never started)."""
        self.exit_status = self._run.wait(progress, poll)
        if self.exit_status not in _STATUS:
            raise RunError(self.exit_status, self._message())
        return self

    def _message(self):
        try:
            return Run(self.path).record.get("message") or "its reason is on stderr"
        except (FileNotFoundError, ValueError):
            return "its reason is on stderr"

    @property
    def status(self):
        """"complete", "interrupted" (stopped: resumable), "failed", or None while running."""
        if self.exit_status is None:
            return None
        return _STATUS.get(self.exit_status, "failed")

    @property
    def simulated_time(self):
        """Where the run ended, s."""
        return self._run.simulated_time

    @property
    def folder(self):
        """The run folder as sedem.load_run reads it (run.json, CSVs, series)."""
        return Run(self.path)

    def readings(self):
        """Every test's readings, DEM and reference, one row per reading: test, source,
        time_s, diameter_um, percent_finer and each instrument's own columns."""
        return tables.readings(self._run.results())

    def errors(self):
        """Each test's error and bias (pp) and its number of readings."""
        return tables.errors(self._run.results())

    def true_curve(self):
        """The sample's true grading curve: diameter_um, percent_finer."""
        return tables.frame(tables.with_units(self._run.true_curve()))

    def granulometry(self):
        """The true curve and every test's curve, DEM and reference, as granulometry.csv
        holds them: test ("true" for the true curve), source, time_s, diameter_um,
        percent_finer."""
        import numpy as np
        true = self._run.true_curve()
        curve = tables.with_units({"time_s": np.full(len(true["diameter_m"]), np.nan), **true})
        return tables.stack([({"test": "true", "source": "true"}, curve)] +
                            [({"test": t["test"], "source": s},
                              tables.with_units({k: t[s][k] for k in
                                                 ("time_s", "diameter_m", "percent_finer")}))
                             for t in self._run.results() for s in ("dem", "reference")])

    def results(self):
        """The raw results: per test its error, bias, and DEM and reference readings as
        dicts of numpy arrays in SI."""
        return self._run.results()

    def particles(self):
        """The particles kept (see `particles`): a list of dicts, one per time, of numpy
        arrays in SI (time_s; x_m, y_m, vx_m_per_s, vy_m_per_s, omega_rad_per_s, diameter_m,
        weight, size_class, id), in the sample's order."""
        return self._run.particles()


def simulate(scene=None, *, progress=None, poll=0.2, **options):
    """Run a scene in this process to its end (or a stop) and return the Simulation; see
    Simulation for the options. Ctrl-C stops it cleanly, then raises KeyboardInterrupt."""
    return Simulation(scene, **options).start().wait(progress, poll)


def resume(folder, *, progress=None, poll=0.2, particles="last", quiet=True):
    """Go on with a stopped run in its folder (as `sedem run --resume`)."""
    return simulate(resume=folder, progress=progress, poll=poll, particles=particles,
                    quiet=quiet)
