#!/usr/bin/env bash
# Installs the Debian 12 packages sedem needs to build, test and render with no display.
# Idempotent: when everything is present it makes no apt call at all. Run as root (or with
# sudo available).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
  libvtk9-dev qt6-base-dev
  libegl-dev libegl-mesa0 libgl1-mesa-dri libgl-dev libglew-dev
  libgtest-dev googletest clang-format
  python3 python3-numpy python3-vtk9 python3-matplotlib python3-pytest
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "setup: run as root or install sudo" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
