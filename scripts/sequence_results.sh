#!/usr/bin/env bash
# The sequences of docs/RESULTS.md ("Time"): the built-in paths of gallery, corridor, cornell,
# glass and ramp, every technique at its defaults and hiz with the denoiser, 640x360 at 30 fps, truth on
# every frame.
#   scripts/sequence_results.sh OUTDIR [FRAMES [SEQUENCE OPTIONS...]]   (ssrlab on PATH; on the GPU: .gpu/run)
# FRAMES (default 64) per path; gallery's cut path runs at least 75, so that its cut (2 s) is inside.
# Further options go to every `ssrlab sequence`, e.g. --second-truth: "x truth" also without the
# truth's own noise (a second reference with another seed on every truth frame: twice its time).
#   scripts/sequence_table.py OUTDIR/*.json           the Markdown tables
set -eu
out=$1; frames=${2:-64}
shift $(( $# < 2 ? $# : 2 ))
mkdir -p "$out"
for spec in gallery:dolly gallery:orbit gallery:pan gallery:slide gallery:enter gallery:cut \
            corridor:dolly corridor:pan cornell:dolly glass:orbit ramp:dolly; do
  scene=${spec%%:*}; path=${spec##*:}; n=$frames
  [ "$path" = cut ] && [ "$n" -lt 75 ] && n=75
  ssrlab sequence --scene "$scene" --path "$path" --frames "$n" --size 640x360 --sweep hiz.denoise=false,true "$@" \
    --json "$out/seq-$scene-$path.json" --plot "$out/seq-$scene-$path.svg" > "$out/seq-$scene-$path.txt"
done
