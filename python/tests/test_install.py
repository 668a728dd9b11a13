"""The package installs as the README says, with no Python index: into a fresh virtual
environment made with --system-site-packages (numpy, pandas, setuptools from Debian), with
pip's --no-build-isolation. (`cmake --install`: tests/packaging/test_install.sh.)"""

import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import DEMO, ROOT

BUILD = os.environ.get("SEDEM_BUILD_DIR")

# Run in the installed package, from a folder that is not the checkout.
CHECK = f"""
import sys, sedem
print(sedem.__file__)
print(sedem.__version__)
sim = sedem.simulate({DEMO!r}, set={{"sample.simulated_count": 300, "run.end_time_s": 60,
                                    "output.frames": False}})
r = sim.readings()
print(type(r).__name__, len(r), sim.status)
"""


def clean_env(**extra):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "SEDEM_EXE")}
    env.update(extra)
    return env


def project_version():
    sys.path.insert(0, str(ROOT / "python" / "sedem"))
    try:
        from version import project_version as read
    finally:
        sys.path.pop(0)
    return read(ROOT / "CMakeLists.txt")


@pytest.mark.skipif(not BUILD, reason="SEDEM_BUILD_DIR names the build tree (ctest sets it)")
def test_pip_install_into_a_fresh_venv(tmp_path):
    venv = tmp_path / "v"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)],
                   check=True)
    pip = subprocess.run([str(venv / "bin" / "pip"), "install", "--no-build-isolation",
                          "--no-index", str(ROOT / "python")],
                         env=clean_env(SEDEM_BUILD_DIR=BUILD, PIP_NO_INPUT="1"),
                         capture_output=True, text=True)
    assert pip.returncode == 0, pip.stdout + pip.stderr
    done = subprocess.run([str(venv / "bin" / "python"), "-c", CHECK], cwd=tmp_path,
                          env=clean_env(), capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    path, version, result = done.stdout.splitlines()[-3:]
    assert path.startswith(str(venv)), path  # the installed copy, not the checkout's
    assert version == project_version()
    kind, rows, status = result.split()
    assert kind == "DataFrame" and int(rows) > 0 and status == "complete"
