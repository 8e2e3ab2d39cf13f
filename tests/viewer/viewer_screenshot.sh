#!/usr/bin/env bash
# The real viewer in a real X window (Xvfb): a few frames of each built-in scene, a screenshot,
# and a check that the screenshot has content (not one flat colour).
set -eu
viewer=$1; outdir=$2
mkdir -p "$outdir"
command -v xvfb-run >/dev/null || { echo "xvfb-run is missing (apt-get install xvfb)"; exit 1; }
for scene in gallery cornell corridor; do
  shot="$outdir/$scene.png"
  rm -f "$shot"
  # -a picks a free display number, so parallel ctest runs do not collide.
  xvfb-run -a -s "-screen 0 800x600x24" "$viewer" --scene "$scene" --size 320x180 --frames 3 \
    --screenshot "$shot"
  [ -s "$shot" ] || { echo "no screenshot for $scene"; exit 1; }
  # A picture, not one flat colour: decoded rows and values must vary.
  python3 - "$shot" "$(dirname "$0")" <<'PY'
import sys
sys.path.insert(0, sys.argv[2])
from png import read_png
w, h, bpp, rows = read_png(sys.argv[1])
distinct_rows = len(set(bytes(r) for r in rows))
distinct_values = len(set(v for r in rows for v in r))
print(f'{sys.argv[1]}: {w}x{h}, {distinct_rows} distinct rows, {distinct_values} distinct byte values')
assert w == 320 and h == 180, 'wrong size'
assert distinct_rows > 20 and distinct_values > 64, 'the screenshot looks blank'
PY
done
echo "viewer screenshots ok"
