"""Builds the package's compiled module, sedem._sedem, with CMake, from the checkout this
folder is in: the extension links the same libraries as the sedem program, so it is one of
the project's CMake targets, not a list of sources here.

Which build tree: $SEDEM_BUILD_DIR if set, else the checkout's build/ (scripts/build.sh's).
A tree that is not configured yet is configured (Release, Ninja); then the targets _sedem and
sedem are built in it (an up-to-date tree builds nothing). The installed package records that
tree, where it finds the sedem program for batches and the laboratory commands.
"""

import os
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE / "sedem"))
from version import project_version  # noqa: E402  (the package's own, not yet installed)

VERSION = project_version(ROOT / "CMakeLists.txt")


def build_dir():
    return Path(os.environ.get("SEDEM_BUILD_DIR") or ROOT / "build").resolve()


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = build_dir()
        if not (build / "CMakeCache.txt").is_file():
            subprocess.check_call(["cmake", "-S", str(ROOT), "-B", str(build), "-G", "Ninja",
                                   "-DCMAKE_BUILD_TYPE=Release"])
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.check_call(["cmake", "--build", str(build), "--parallel", jobs,
                               "--target", "_sedem", "sedem"])
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = build / "python" / ("_sedem" + suffix)
        if not built.is_file():
            found = sorted(p.name for p in (build / "python").glob("_sedem*"))
            raise RuntimeError(f"{built} not built (found {found}): the build tree's Python "
                               f"is not this one ({sys.executable}); configure it with "
                               f"-DPython3_EXECUTABLE={sys.executable}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


class BuildInfo(build_py):
    """Writes sedem/_build_info.py: the version and the build tree."""

    def run(self):
        super().run()
        info = Path(self.build_lib) / "sedem" / "_build_info.py"
        info.write_text(f"version = {VERSION!r}\nbuild_dir = {str(build_dir())!r}\n")


setup(version=VERSION,
      ext_modules=[Extension("sedem._sedem", sources=[])],
      cmdclass={"build_ext": CMakeBuild, "build_py": BuildInfo})
