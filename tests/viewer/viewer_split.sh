#!/usr/bin/env bash
# The viewer's compare modes in a real X window (Xvfb): a split of `none` (A, left) and `linear`
# (B, right) must match a plain `none` frame on the left and differ from it on the right (the
# floor's reflections); the difference mode must show a heat map, not a blank frame.
set -eu
viewer=$1; outdir=$2
mkdir -p "$outdir"
command -v xvfb-run >/dev/null || { echo "xvfb-run is missing (apt-get install xvfb)"; exit 1; }
shoot() {  # shoot NAME ARGS...: one screenshot of 3 frames
  local shot="$outdir/$1.png"; shift
  rm -f "$shot"
  xvfb-run -a -f "$outdir/Xauthority" -s "-screen 0 800x600x24" "$viewer" --scene gallery --size 320x180 --frames 3 \
    --screenshot "$shot" "$@"
  [ -s "$shot" ] || { echo "no screenshot $shot"; exit 1; }
}
shoot base --technique none
shoot split --technique none --technique-b linear --split 0.5
shoot diff --technique none --technique-b linear --diff
shoot same --technique linear --technique-b linear --diff
# A debug view only B fills: A's half is plain grey (it showed the debug image's leftovers, read
# through B's legend as data).
printf 'view steps\n' > "$outdir/steps.txt"
shoot steps --technique reference --technique-b linear --split 0.5 --script "$outdir/steps.txt"
python3 - "$outdir" "$(dirname "$0")" <<'PY'
import sys
sys.path.insert(0, sys.argv[2])
from png import read_png
def mad(img1, img2, x0, x1, y0, y1):  # mean absolute difference over RGB of a region
    w, h, bpp, r1 = img1; _, _, bpp2, r2 = img2
    s = n = 0
    for y in range(y0, y1):
        for x in range(x0, x1):
            for c in range(3):
                s += abs(r1[y][x * bpp + c] - r2[y][x * bpp2 + c]); n += 1
    return s / n
d = sys.argv[1]
base, split, diff, same, steps = (read_png(f'{d}/{n}.png') for n in ('base', 'split', 'diff', 'same', 'steps'))
w, h = base[0], base[1]
assert (w, h) == (320, 180) and (split[0], split[1]) == (w, h), 'wrong size'
left = mad(split, base, 0, w // 2 - 2, 0, h)
right_floor = mad(split, base, w // 2 + 2, w, 2 * h // 3, h)
print(f'split vs none: left half {left:.3f}, right half lower third {right_floor:.3f}')
assert left < 0.5, 'the left half of the split is not technique A'
assert right_floor > 1.0, 'the right half of the split does not differ from technique A'
hot = sum(1 for row in diff[3] for x in range(w) if row[x * diff[2]] != row[x * diff[2] + 2])
distinct = len(set(bytes(row) for row in diff[3]))
print(f'diff none vs linear: {hot} coloured pixels, {distinct} distinct rows')
assert distinct > 20 and hot > 100, 'the difference heat map looks blank'
hot_same = sum(1 for row in same[3] for x in range(w) if row[x * same[2]] != row[x * same[2] + 2])
print(f'diff linear vs linear: {hot_same} coloured pixels')
assert hot_same == 0, 'identical techniques must give no heat'
left = {bytes(steps[3][y][x * steps[2]:x * steps[2] + 3]) for y in range(h) for x in range(w // 2 - 2)}
right = {bytes(steps[3][y][x * steps[2]:x * steps[2] + 3]) for y in range(h) for x in range(w // 2 + 2, w)}
print(f'steps view, reference | linear: {len(left)} colours on the left, {len(right)} on the right')
assert left == {bytes([48, 48, 48])}, f'the half without the view is not plain grey: {sorted(left)[:4]}'
assert len(right) > 20, 'linear shows no steps'
PY
echo "viewer split/diff ok"
