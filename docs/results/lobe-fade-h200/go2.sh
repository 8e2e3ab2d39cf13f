#!/bin/bash
# The lobe fade's before/after (73bdcf4's shaders against HEAD's): ramp's dolly, glass's and gallery's orbits.
set -u
start=$(date +%s)
W=/tmp/work2; mkdir -p $W
left() { echo $(( 540 - ($(date +%s) - start) )); }
for sp in ramp:dolly glass:orbit gallery:orbit; do
  s=${sp%%:*}; p=${sp##*:}
  for v in new old; do
    [ $sp = glass:orbit -o $sp = gallery:orbit ] && [ $v = new ] && continue  # came back from go1
    sh=""; [ $v = old ] && sh="--shaders .gpu/old/shaders"
    t=$(left); [ $t -lt 30 ] && { echo "skip $sp $v" >> $W/log2.txt; continue; }
    t0=$(date +%s)
    timeout $t .gpu/run ssrlab sequence --scene $s --path $p --frames 64 --size 640x360 --truth-every 4 \
      --techniques stochastic,hiz --set hiz.denoise=true --second-truth $sh \
      --json $W/paths-$v-$s-$p.json > $W/paths-$v-$s-$p.txt 2>&1
    echo "$sp $v rc $? in $(( $(date +%s) - t0 )) s" >> $W/log2.txt
    (cd $W && tar czf $OUT/paths2.tgz *)
  done
done
