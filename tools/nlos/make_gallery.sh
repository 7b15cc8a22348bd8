#!/bin/sh
# The NLOS gallery figure (docs/GALLERY.md, "Non-line-of-sight: a hidden
# letter"): renders tools/nlos/hidden_letter.xml confocally at 64 x 64 wall
# points, 512 bins, SPP samples per point (default 256), and draws its streak
# image and both reconstructions into OUT (default out/nlos/nlos_letter.png).
#   tools/nlos/make_gallery.sh [build-dir]        DOCS=docs/images also copies it there
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-build}
spp=${SPP:-256}
cd "$root"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target femto transient_nlos_path nlos_capture_meter projector diffuse rectangle \
  independent transient_hdr_film box >/dev/null
mkdir -p out/nlos
"$build/bin/femto" render tools/nlos/hidden_letter.xml --strict -D spp="$spp" -t 2 --no-progress \
  -p "$build/bin/plugins" -o out/nlos/letter.exr
/usr/bin/python3 tools/nlos/gallery_figure.py out/nlos/letter.npy out/nlos/nlos_letter.png \
  --box=-0.4,-0.4,0.4,0.4,0.4,0.8
echo "wrote out/nlos/nlos_letter.png"
if [ -n "${DOCS:-}" ]; then cp out/nlos/nlos_letter.png "$DOCS/nlos_letter.png"; echo "copied to $DOCS"; fi
