#!/usr/bin/env bash
# The sequences of docs/RESULTS.md ("Time"): the built-in paths of gallery, corridor, cornell and
# glass, every technique at its defaults and hiz with the denoiser, 640x360 at 30 fps, truth on
# every frame.
#   scripts/sequence_results.sh OUTDIR [FRAMES]      (ssrlab on PATH; on the GPU machine: .gpu/run)
# FRAMES (default 64) per path; gallery's cut path runs at least 75, so that its cut (2 s) is inside.
#   scripts/sequence_table.py OUTDIR/*.json           the Markdown tables
set -eu
out=$1; frames=${2:-64}
mkdir -p "$out"
for spec in gallery:dolly gallery:orbit gallery:pan gallery:slide gallery:enter gallery:cut \
            corridor:dolly corridor:pan cornell:dolly glass:orbit; do
  scene=${spec%%:*}; path=${spec##*:}; n=$frames
  [ "$path" = cut ] && [ "$n" -lt 75 ] && n=75
  ssrlab sequence --scene "$scene" --path "$path" --frames "$n" --size 640x360 --sweep hiz.denoise=false,true \
    --json "$out/seq-$scene-$path.json" --plot "$out/seq-$scene-$path.svg" > "$out/seq-$scene-$path.txt"
done
