#!/usr/bin/env bash
# Installs the Debian 12 packages sedem needs to build, test and render with no display, and
# unpacks ParaView 5.11 into .paraview/ for the tests that open sedem's files with pvpython.
# Idempotent: when everything is present it makes no apt call at all. Run as root (or with
# sudo available).
#
# Debian's paraview package cannot be installed beside libvtk9-dev (installing it removes the
# build's VTK), so its two .debs are downloaded and unpacked with dpkg -x into a private
# folder (SEDEM_PARAVIEW_DIR, default .paraview/ at the repository's root): the installed
# packages are never changed by that step. tests/render/pvpython.sh runs that pvpython.
#
# scripts/setup.sh --build-only installs only what building and running sedem needs (the demo's
# set-up: CMake's configure also wants GoogleTest, clang-format and pybind11), not the Python
# test tools, nor ParaView and its libraries, nor Chromium; a later plain run adds them.
set -euo pipefail

build_only=false
[[ "${1:-}" == "--build-only" ]] && build_only=true

packages=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev libtomlplusplus-dev libcli11-dev nlohmann-json3-dev coinor-libclp-dev
  # .xlsx workbooks of laboratory readings are zip archives.
  libzip-dev
  libvtk9-dev qt6-base-dev libcairo2-dev fonts-dejavu-core
  libegl-dev libegl-mesa0 libgl1-mesa-dri libgl-dev libglew-dev
  libgtest-dev googletest clang-format
  # The Python module sedem._sedem, built with the program.
  python3-dev pybind11-dev
)
$build_only || packages+=(
  python3 python3-numpy python3-vtk9 python3-matplotlib python3-pytest
  # The Python package's tables and its install into a virtual environment with no index
  # (pip install --no-build-isolation ./python: the build backend and wheel from Debian).
  python3-pandas python3-xarray python3-venv python3-pip python3-setuptools python3-wheel
  # The lab-file tests write their .xlsx workbooks with openpyxl.
  python3-openpyxl
  # The figure tests render every SVG and PDF the way readers open them.
  librsvg2-bin poppler-utils
  # ParaView's pvpython (unpacked below): its libraries' dependencies, and an X server for
  # its rendering (Debian's ParaView renders through X only).
  xvfb xauth libqt5help5 libqt5opengl5 libqt5widgets5 libqt5network5 libqt5gui5
  libavcodec59 libavformat59 libswscale6 libdouble-conversion3 libgdal32 libgl2ps1.4
  libglew2.2 libhdf5-openmpi-103-1 libnetcdf19 libopenmpi3 libtheora0 libpython3.11
  libopengl0 libxcursor1  python3-mpi4py python3-six
  # Headless Chromium, in which the tests open a run's report.html.
  chromium
  # `sedem batch --emit`: GNU parallel, and Slurm with munge for the single-node cluster the
  # tests start (as root, from a folder of their own: no system service is set up).
  parallel slurm-wlm munge
)

cd "$(dirname "$0")/.."
paraview_dir=${SEDEM_PARAVIEW_DIR:-$PWD/.paraview}
paraview_debs=(paraview python3-paraview)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

have_paraview=false
[[ -x "$paraview_dir/usr/bin/pvpython" ]] && have_paraview=true
$build_only && have_paraview=true  # not wanted

if ((${#missing[@]} == 0)) && [[ $have_paraview == true ]]; then
  if $build_only; then
    echo "setup: all ${#packages[@]} packages to build and run sedem present"
  else
    echo "setup: all ${#packages[@]} packages present, ParaView in $paraview_dir"
  fi
  exit 0
fi

sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "setup: run as root or install sudo" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
updated=false
if ((${#missing[@]} > 0)); then
  echo "setup: installing ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -q
  updated=true
  "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

if [[ $have_paraview == false ]]; then
  echo "setup: unpacking ParaView (${paraview_debs[*]}) into $paraview_dir"
  download=$(mktemp -d)
  chmod 777 "$download"  # apt's download user writes there
  if ! (cd "$download" && apt-get download -q "${paraview_debs[@]}"); then
    [[ $updated == true ]] || "${sudo_cmd[@]}" apt-get update -q
    (cd "$download" && apt-get download -q "${paraview_debs[@]}")
  fi
  rm -rf "$paraview_dir.tmp"
  mkdir -p "$paraview_dir.tmp"
  for deb in "$download"/*.deb; do dpkg -x "$deb" "$paraview_dir.tmp"; done
  rm -rf "$download" "$paraview_dir"
  mv "$paraview_dir.tmp" "$paraview_dir"
fi
