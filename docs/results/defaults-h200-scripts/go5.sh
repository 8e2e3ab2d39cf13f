#!/bin/bash
# go4.sh's last group, which ran past that call's limit.
set -u
mkdir -p $OUT/d
T="--techniques none,linear,linear-binary,dda,hiz,stochastic,ppr,planar --set reference.samples=64 --frames 30 --warmup 10 --sizes 1080p,4k"
t0=$(date +%s); timeout 380 .gpu/run ssrlab bench --scene gallery:normal_map=ripples --scenes ramp $T --json $OUT/d/d.json > $OUT/d/d.txt 2>&1
echo "d rc $? in $(( $(date +%s) - t0 )) s" >> $OUT/d/log.txt; tar -C $OUT -cf $OUT/defaults2.tar d; rm -rf $OUT/d
