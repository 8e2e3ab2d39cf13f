#!/usr/bin/env bash
# The figures of docs/RESULTS.md's "Stochastic SSR and the denoiser" section (issue 14), run on
# the GPU machine (ssrlab on PATH, e.g. .gpu/run's):
#   scripts/stochastic_results.sh OUTDIR stages|paths|bench [ssrlab options...]
# Options after the part go to every ssrlab call (e.g. --set reference.samples=2048); ONLY=SCENE
# runs the stages and paths of that scene alone (e.g. ONLY=cornell); PATHS="scene:path ..." runs
# other paths than the four.
# stages: each denoiser stage on and off (8 combinations) and hiz with 16 rays, still camera,
#         16 frames with the truth on every one: error per stage, per roughness band, per frame.
# paths:  stochastic, hiz and hiz + denoiser along camera paths: instability and ghosting, with
#         --second-truth (x truth without the truth's noise: cornell's and ramp's truths change
#         mostly by their noise).
# bench:  time per pass at 1080p and 4K, full and half resolution, the quality tiers.
set -eu
out=$1; what=$2; shift 2
only=${ONLY:-}
mkdir -p "$out"
size=640x360
case "$what" in
  stages)
    for scene in cornell corridor assets/scenes/pedestal.json ramp; do
      name=$(basename "$scene" .json)
      [ -z "$only" ] || [ "$name" = "$only" ] || continue
      ssrlab sequence --scene "$scene" --path still --frames 16 --size $size --techniques stochastic,hiz \
        --sweep stochastic.spatial=false,true --sweep stochastic.temporal=false,true \
        --sweep stochastic.bilateral=false,true --set hiz.samples=16 "$@" \
        --json "$out/stages-$name.json" > "$out/stages-$name.txt"
    done ;;
  paths)
    for spec in ${PATHS:-cornell:dolly corridor:dolly gallery:orbit ramp:dolly}; do
      scene=${spec%%:*}; path=${spec##*:}
      [ -z "$only" ] || [ "$scene" = "$only" ] || continue
      ssrlab sequence --scene "$scene" --path "$path" --frames 64 --size $size --truth-every 4 \
        --techniques stochastic,hiz --sweep hiz.denoise=false,true --second-truth "$@" \
        --json "$out/paths-$scene-$path.json" > "$out/paths-$scene-$path.txt"
    done ;;
  bench)
    # The section's table: 1080p with pedestal and ultra, 4K on cornell and ramp without ultra.
    ssrlab bench --scenes cornell,ramp,assets/scenes/pedestal.json --sizes 1080p --frames 30 --warmup 10 \
      --techniques stochastic,hiz --sweep stochastic.half_resolution=false,true --preset stochastic-low \
      --preset stochastic-medium --preset stochastic-ultra "$@" --json "$out/bench-1080p.json" > "$out/bench-1080p.txt"
    ssrlab bench --scenes cornell,ramp --sizes 4k --frames 20 --warmup 10 \
      --techniques stochastic,hiz --sweep stochastic.half_resolution=false,true --preset stochastic-low \
      --preset stochastic-medium "$@" --json "$out/bench-4k.json" > "$out/bench-4k.txt" ;;
  *) echo "usage: $0 OUTDIR stages|paths|bench" >&2; exit 2 ;;
esac
