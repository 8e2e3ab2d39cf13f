#!/usr/bin/env bash
# The figures of docs/RESULTS.md's "Speed" section (issue 15), in one run on the GPU machine
# (ssrlab on PATH, e.g. .gpu/run's):
#   scripts/speed_results.sh OUTDIR [part ...]     (default: every part)
# equal:    gallery and corridor at 1080p and 4K: linear-binary at 300 (default) and 500 steps
#           (its "auto" ray is the scene's diagonal: long enough), hiz at iteration caps 64..auto
#           and thicknesses 0.15 (its default), 0.3, 0.5 (corridor needs more than the default),
#           dda at strides 1..8, linear; telemetry per result: the equal-error table.
# compact:  every tracer with and without the ray list (compact), gallery and corridor, 1080p.
# pedestal: hiz and stochastic at their defaults on pedestal and cornell, 1080p (telemetry).
# ppr:      ppr (thesis technique: no fallback; and the default hiz fallback) against its floor
#           pass at 1080p and 4K, one and 16 reflectors, and thesis-hq.
# scaling:  every technique at its defaults on gallery at 1080p, 4K and 8K.
set -eu
out=$1; shift
parts=${*:-equal compact pedestal ppr scaling}
mkdir -p "$out"
common="--frames 30 --warmup 10"
for part in $parts; do
  case "$part" in
    equal)
      ssrlab bench --scenes gallery,corridor --sizes 1080p,4k --techniques linear-binary,hiz,dda,linear \
        --sweep linear-binary.linear_steps=300,500 --sweep hiz.max_iterations=64,96,128,192,auto \
        --sweep hiz.thickness=0.15,0.3,0.5 \
        --sweep dda.stride=1,2,4,8 --set reference.samples=64 $common \
        --json "$out/equal.json" > "$out/equal.txt" ;;
    compact)
      ssrlab bench --scenes gallery,corridor --sizes 1080p --techniques linear-binary,hiz,dda,linear \
        --sweep linear-binary.compact=false,true --sweep hiz.compact=false,true \
        --sweep dda.compact=false,true --sweep linear.compact=false,true \
        --set reference.samples=64 $common --json "$out/compact.json" > "$out/compact.txt" ;;
    pedestal)
      ssrlab bench --scenes assets/scenes/pedestal.json,cornell --sizes 1080p --techniques hiz,stochastic \
        --sweep stochastic.half_resolution=false,true \
        --set reference.samples=64 $common --json "$out/pedestal.json" > "$out/pedestal.txt" ;;
    ppr)
      ssrlab bench --scenes gallery --sizes 1080p,4k --techniques ppr --sweep ppr.fallback=none,hiz \
        --preset thesis-hq --set reference.samples=64 $common --json "$out/ppr.json" > "$out/ppr.txt"
      ssrlab bench --scene gallery:reflectors=16 --sizes 1080p --techniques ppr --set ppr.fallback=none \
        --set reference.samples=64 $common --json "$out/ppr16.json" > "$out/ppr16.txt" ;;
    scaling)
      ssrlab bench --scenes gallery --sizes 1080p,4k,8k \
        --techniques none,linear,linear-binary,dda,hiz,ppr,stochastic \
        --set reference.samples=1 $common --json "$out/scaling.json" > "$out/scaling.txt" ;;
    *) echo "usage: $0 OUTDIR [equal|compact|pedestal|ppr|scaling ...]" >&2; exit 2 ;;
  esac
done
