#!/bin/bash
# Issue 14's 1080p targets against the pipeline's own floor: every stage at its defaults but the
# trace stopped after one cell visit (max_iterations=1, glossy_iterations=1), beside the defaults.
set -u
mkdir -p $OUT/r
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader > $OUT/r/device.txt
S="--scenes cornell,corridor,ramp --scene assets/scenes/pedestal.json --sizes 1080p --techniques stochastic --set reference.samples=1 --frames 30 --warmup 10"
LOW="--set stochastic.half_resolution=true --set stochastic.roughness_threshold=0.5 --set stochastic.spatial_samples=4 --set stochastic.spatial_radius=4 --set stochastic.bilateral_radius=1"
ONE="--set stochastic.max_iterations=1 --set stochastic.glossy_iterations=1"
run() { n=$1; shift; t0=$(date +%s); timeout 150 .gpu/run ssrlab bench $S "$@" --json $OUT/r/$n.json > $OUT/r/$n.txt 2>&1; echo "$n rc $? in $(( $(date +%s) - t0 )) s" >> $OUT/r/log.txt; tar -C $OUT -cf $OUT/results.tar r; }
run defaults --sweep stochastic.half_resolution=false,true
run one-visit $ONE --sweep stochastic.half_resolution=false,true
run low-one-visit $LOW $ONE --preset stochastic-low
run skeleton $ONE --set stochastic.half_resolution=true --set stochastic.spatial=false --set stochastic.temporal=false --set stochastic.bilateral=false
rm -rf $OUT/r
