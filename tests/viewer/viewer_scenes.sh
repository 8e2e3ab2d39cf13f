#!/usr/bin/env bash
# The real viewer in a real X window (Xvfb), started on every built-in scene: a scripted input
# file switches techniques and the split/difference modes and takes screenshots; the screenshots
# are checked for content. Usage: viewer_scenes.sh SSRLAB_VIEW SSRLAB OUTDIR
set -eu
viewer=$1; ssrlab=$2; outdir=$3
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$outdir"
command -v xvfb-run >/dev/null || { echo "xvfb-run is missing (apt-get install xvfb)"; exit 1; }
# The built-in scenes, as `ssrlab scenes` lists them (so that a new scene is tested too).
scenes=$("$ssrlab" scenes | awk '/^built-in/ {on=1; next} /^[^ ]/ {on=0} on && NF {print $1}')
[ -n "$scenes" ] || { echo "no built-in scenes listed"; exit 1; }
cat > "$outdir/walk.txt" <<'SCRIPT'
# A (left) = none, B (right) = hiz: the right half gains the reflections. (hiz, not linear:
# at its auto step linear finds nothing on hard-depth-range, see docs/ROBUSTNESS.md.)
technique none
frames 2
screenshot none.png
technique-b hiz
split 0.5
frames 2
screenshot split.png
compare diff
frames 2
screenshot diff.png
# Every other technique once, with a debug view, so that each runs on each scene.
compare off
technique linear-binary
view steps
frames 1
technique dda
view hits
frames 1
technique linear
view confidence
frames 1
technique ppr
view offsets
frames 1
technique planar
view reflection
frames 1
view final
frames 1
screenshot last.png
SCRIPT
for scene in $scenes; do
  d="$outdir/$scene"
  rm -rf "$d"; mkdir -p "$d"
  # -a picks a free display number, so parallel ctest runs do not collide.
  (cd "$d" && xvfb-run -a -f "$outdir/Xauthority" -s "-screen 0 800x600x24" "$viewer" --scene "$scene" --size 320x180 \
     --ini "$d/imgui.ini" --script "$outdir/walk.txt" > log.txt 2>&1) ||
    { echo "viewer failed on $scene:"; cat "$d/log.txt"; exit 1; }
done
python3 - "$outdir" "$here" $scenes <<'PY'
import sys
sys.path.insert(0, sys.argv[2])
from png import read_png
out, scenes = sys.argv[1], sys.argv[3:]
def mad(a, b, x0, x1):  # mean absolute difference over RGB of columns [x0, x1)
    s = n = 0
    for ra, rb in zip(a[3], b[3]):
        for x in range(x0, x1):
            for c in range(3):
                s += abs(ra[x * a[2] + c] - rb[x * b[2] + c]); n += 1
    return s / n
def blank(img):
    w, h, bpp, rows = img
    return len(set(bytes(r) for r in rows)) < 10 or len(set(v for r in rows for v in r)) < 32
for scene in scenes:
    none, split, diff, last = (read_png(f'{out}/{scene}/{n}.png') for n in ('none', 'split', 'diff', 'last'))
    w, h = none[0], none[1]
    assert all((i[0], i[1]) == (320, 180) for i in (none, split, diff, last)), f'{scene}: wrong size'
    left, right = mad(split, none, 0, w // 2 - 2), mad(split, none, w // 2 + 2, w)
    heat = sum(1 for row in diff[3] for x in range(w) if row[x * diff[2]] != row[x * diff[2] + 2])
    print(f'{scene:18} split vs none: left {left:.3f}, right {right:.3f}; heat pixels {heat}')
    assert not blank(none) and not blank(last), f'{scene}: a screenshot looks blank'
    assert left < 0.5, f'{scene}: the left half of the split is not technique A'
    assert right > 0.05, f'{scene}: the right half of the split does not differ from technique A'
    assert heat > 0, f'{scene}: the difference heat map is blank though the techniques differ'
PY
echo "viewer scenes ok"
