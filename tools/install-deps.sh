#!/usr/bin/env bash
# Install the Debian 12 packages femto builds with, skipping what is present.
# Runs apt-get as root (directly, or through sudo when available).
set -euo pipefail
packages=(
  build-essential cmake ninja-build ccache pkg-config
  libembree-dev libopenexr-dev libopenimageio-dev libtinyxml2-dev libtbb-dev
  libgtest-dev libtinyobjloader-dev libcli11-dev zlib1g-dev
  libcpp-httplib-dev  # femto view: the viewer's HTTP server (a maintained library, not a hand-written parser)
  python3-numpy python3-matplotlib
  ffmpeg  # femto frames --gif/--mp4 (run as a program, not linked)
  chromium  # the femto view test drives the viewer page in headless Chromium (skipped without it)
  # The femto Python module (src/python): pybind11 headers and the Python
  # headers to build it for /usr/bin/python3; pytest runs its tests under ctest.
  pybind11-dev python3-dev python3-pytest
  libopenmpi-dev openmpi-bin  # optional: mpirun -n N femto render (tools/femto/mpi/) and its tests
  python3-nbconvert python3-ipykernel  # optional: run examples/python's notebook headless in the tests (skipped without)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "Installing: ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then sudo=""; elif command -v sudo >/dev/null; then sudo="sudo"; else
  echo "error: need root (or sudo) to install: ${missing[*]}" >&2; exit 1
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
