"""The package's version and where its build is.

One source of truth: the version in the top CMakeLists.txt's project(). An installed package
carries it in _build_info.py, written when it was built (by setup.py, or by cmake --install);
from a checkout (PYTHONPATH=python) it is read from that file directly.
"""

import os
import re
from pathlib import Path

_CHECKOUT = Path(__file__).resolve().parents[2]


def project_version(cmakelists):
    """The version in `project(sedem VERSION x.y.z ...)` of a CMakeLists.txt."""
    text = Path(cmakelists).read_text()
    m = re.search(r"project\(\s*sedem\s+VERSION\s+([0-9][0-9.]*)", text)
    if not m:
        raise ValueError(f"{cmakelists}: no project(sedem VERSION ...)")
    return m.group(1)


try:
    from ._build_info import version, build_dir
except ImportError:
    version = project_version(_CHECKOUT / "CMakeLists.txt")
    build_dir = None


def build_dirs():
    """Build trees to look in for the sedem program and the extension, first found first:
    $SEDEM_BUILD_DIR, the one the package was built from, build/ of this checkout."""
    dirs = [os.environ.get("SEDEM_BUILD_DIR"), build_dir, _CHECKOUT / "build"]
    return [Path(d) for d in dirs if d]
