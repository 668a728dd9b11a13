"""Shared by the package's tests: where the scenes are, where runs go (SEDEM_TEST_OUTPUT
under ctest), and a small demo scene that runs in a second."""

import os
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
DEMO = str(ROOT / "scenes" / "demo.toml")
OUT = Path(os.environ.get("SEDEM_TEST_OUTPUT", "/tmp")) / "python"
SMALL = {"sample.simulated_count": 300, "output.frames": False, "run.end_time_s": 60,
         "instruments.hydrometer.times_min": [0.25, 0.5, 1]}
