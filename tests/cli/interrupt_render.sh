#!/usr/bin/env bash
# Ctrl-C during `femto render`: the render must stop within seconds, write a
# valid partial image and exit with 130.
#   interrupt_render.sh FEMTO SCENE OUTPUT_DIR
set -u
. "$(dirname "$0")/process_wait.sh"
femto=$1 scene=$2 out_dir=$3
image=$out_dir/interrupted.exr
rm -f "$image"
mkdir -p "$out_dir"
# Minutes of work in 64 tiles of seconds each: the render loop stops between
# tiles, so a tile must be short for the stop to be quick.
"$femto" render "$scene" -o "$image" --resolution 256x256 --spp 4096 --no-progress >"$out_dir/interrupt.log" 2>&1 &
pid=$!
# femto installs its Ctrl-C handler once the scene is loaded.
wait_for_handler 2 "$pid" >/dev/null || { kill -KILL "$pid" 2>/dev/null; echo "femto never started rendering"; cat "$out_dir/interrupt.log"; exit 1; }
sleep 1
kill -INT "$pid"
# A cancelled render must not hang: give it 60 s to write the partial image.
wait_for_exit "$pid" 60 || { echo "femto did not stop within 60 s of Ctrl-C"; cat "$out_dir/interrupt.log"; exit 1; }
wait "$pid"; code=$?
cat "$out_dir/interrupt.log"
[ "$code" -eq 130 ] || { echo "expected exit 130 after Ctrl-C, got $code"; exit 1; }
[ -s "$image" ] || { echo "no partial image at $image"; exit 1; }
grep -q "interrupted" "$out_dir/interrupt.log" || { echo "no interruption message"; exit 1; }
echo "partial image written: $image"
