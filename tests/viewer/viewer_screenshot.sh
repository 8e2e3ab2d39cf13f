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
  # A PNG with content: count distinct colours with python's zlib (no extra packages).
  python3 - "$shot" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], 'rb').read()
assert data[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
pos, idat, w, h = 8, b'', 0, 0
while pos < len(data):
    n, kind = struct.unpack('>I4s', data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b'IHDR': w, h, depth, ctype = struct.unpack('>IIBB', body[:10])
    if kind == b'IDAT': idat += body
    pos += 12 + n
raw = zlib.decompress(idat)
stride = w * 4 + 1
# Filter bytes aside, unfiltering is not needed to tell "one flat colour" from "a picture":
# a flat image compresses to nearly nothing and has a handful of distinct byte values.
distinct = len(set(raw[i * stride + 1:(i + 1) * stride] for i in range(h)))
print(f'{sys.argv[1]}: {w}x{h}, {distinct} distinct rows, {len(set(raw))} distinct bytes')
assert w == 320 and h == 180, 'wrong size'
assert distinct > 20 and len(set(raw)) > 64, 'the screenshot looks blank'
PY
done
echo "viewer screenshots ok"
