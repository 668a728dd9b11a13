"""sedem from Python: run a scene in this process, and read runs and batches as tables.

    >>> import sedem
    >>> sim = sedem.simulate("scenes/demo.toml", set={"sample.simulated_count": 2000},
    ...                      progress=lambda t, end, steps: print(f"{t:.0f}/{end:.0f} s"))
    >>> sim.readings()           # one row per reading: test, source, time_s, diameter_um, ...
    >>> sim.errors()             # each test's error_pp and bias_pp
    >>> sim.particles()[-1]["y_m"]   # the particles as numpy arrays, from memory
    >>> run = sedem.load_run("out/demo")    # a run folder: .granulometry(), .readings(),
    >>> run.fields()                        # .errors(), .fields() (xarray), .series(...)
    >>> sedem.load_batch("out/seeds").table("errors")   # every run, swept key and seed as columns

Tables are pandas DataFrames where pandas is installed, else dicts of numpy arrays. The
`sedem` program runs batches and the laboratory commands (batch, reduce, invert, design).
"""

from .cli import SedemError, batch, design, executable, invert, reduce, run
from .files import Batch, Run, Series, load_batch, load_run, read_csv
from .inprocess import RunError, Simulation, resume, scene_toml, simulate
from .version import version as __version__

__all__ = ["Run", "Series", "Batch", "load_run", "load_batch", "read_csv", "run", "batch",
           "reduce", "invert", "design", "executable", "SedemError", "Simulation",
           "simulate", "resume", "RunError", "scene_toml", "__version__"]
