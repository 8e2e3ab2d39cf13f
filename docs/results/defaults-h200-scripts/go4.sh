#!/bin/bash
# Verdicts per region at the defaults (RESULTS), again at this revision: every technique, the
# command of the b8d68d4 run, the scenes in four groups so each group's JSON comes back.
set -u
mkdir -p $OUT/d
start=$(date +%s)
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader > $OUT/d/device.txt
T="--techniques none,linear,linear-binary,dda,hiz,stochastic,ppr,planar --set reference.samples=64 --frames 30 --warmup 10 --sizes 1080p,4k"
run() { n=$1; shift; left=$(( 585 - ($(date +%s) - start) )); [ $left -lt 20 ] && { echo "$n skipped" >> $OUT/d/log.txt; return; }
  t0=$(date +%s); timeout $left .gpu/run ssrlab bench "$@" $T --json $OUT/d/$n.json > $OUT/d/$n.txt 2>&1
  echo "$n rc $? in $(( $(date +%s) - t0 )) s" >> $OUT/d/log.txt; tar -C $OUT -cf $OUT/defaults.tar d; }
run a --scenes gallery,cornell
run b --scenes corridor,glass
run c --scene assets/scenes/pedestal.json --scene gallery:reflectors=8
run d --scene gallery:normal_map=ripples --scenes ramp
rm -rf $OUT/d
