#!/bin/bash
# The lobe fade's before/after (73bdcf4's shaders against HEAD's) on gallery's paths not yet run.
set -u
start=$(date +%s)
W=/tmp/work2; mkdir -p $W
left() { echo $(( 560 - ($(date +%s) - start) )); }
for p in dolly pan slide enter cut; do
  for v in new old; do
    sh=""; [ $v = old ] && sh="--shaders .gpu/old/shaders"
    t=$(left); [ $t -lt 30 ] && { echo "skip $p $v" >> $W/log2.txt; continue; }
    t0=$(date +%s)
    timeout $t .gpu/run ssrlab sequence --scene gallery --path $p --frames 64 --size 640x360 --truth-every 4 \
      --techniques stochastic,hiz --set hiz.denoise=true --second-truth $sh \
      --json $W/paths-$v-gallery-$p.json > $W/paths-$v-gallery-$p.txt 2>&1
    echo "gallery:$p $v rc $? in $(( $(date +%s) - t0 )) s" >> $W/log2.txt
    (cd $W && tar czf $OUT/paths2.tgz *)
  done
done
