#!/bin/bash
# 1: hiz's fixed cost (one cell visit) against linear-binary/500 and hiz at cap 192, one binary.
# 2: the lobe fade's before/after (73bdcf4's shaders against HEAD's) on ramp's dolly and more paths.
set -u
start=$(date +%s)
left() { echo $(( 560 - ($(date +%s) - start) )); }
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader > $OUT/device.txt
timeout 200 .gpu/run ssrlab bench --scenes gallery,corridor --sizes 1080p,4k --techniques linear-binary,hiz \
  --sweep linear-binary.linear_steps=500 --sweep hiz.max_iterations=1,192 --sweep hiz.thickness=0.15,0.5 \
  --set reference.samples=64 --frames 30 --warmup 10 --json $OUT/bound.json > $OUT/bound.txt 2>&1
echo "bench done at $(( $(date +%s) - start )) s" >> $OUT/log.txt
for sp in ramp:dolly glass:orbit gallery:orbit gallery:enter; do
  s=${sp%%:*}; p=${sp##*:}
  for v in new old; do
    sh=""; [ $v = old ] && sh="--shaders .gpu/old/shaders"
    t=$(left); [ $t -lt 30 ] && { echo "skip $sp $v" >> $OUT/log.txt; continue; }
    t0=$(date +%s)
    timeout $t .gpu/run ssrlab sequence --scene $s --path $p --frames 64 --size 640x360 --truth-every 4 \
      --techniques stochastic,hiz --set hiz.denoise=true --second-truth $sh \
      --json $OUT/paths-$v-$s-$p.json > $OUT/paths-$v-$s-$p.txt 2>&1
    echo "$sp $v rc $? in $(( $(date +%s) - t0 )) s" >> $OUT/log.txt
  done
done
