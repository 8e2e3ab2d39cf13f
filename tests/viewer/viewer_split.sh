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
  xvfb-run -a -s "-screen 0 800x600x24" "$viewer" --scene gallery --size 320x180 --frames 3 \
    --screenshot "$shot" "$@"
  [ -s "$shot" ] || { echo "no screenshot $shot"; exit 1; }
}
shoot base --technique none
shoot split --technique none --technique-b linear --split 0.5
shoot diff --technique none --technique-b linear --diff
shoot same --technique linear --technique-b linear --diff
python3 - "$outdir" <<'PY'
import struct, sys, zlib
def read_png(path):
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
    pos, idat = 8, b''
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR': w, h, depth, ctype = struct.unpack('>IIBB', body[:10])
        if kind == b'IDAT': idat += body
        pos += 12 + n
    assert depth == 8 and ctype in (2, 6), 'expected 8-bit RGB(A)'
    bpp = 4 if ctype == 6 else 3
    raw, stride = zlib.decompress(idat), w * bpp
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line); prev = line
    return w, h, bpp, rows
def mad(img1, img2, x0, x1, y0, y1):  # mean absolute difference over RGB of a region
    w, h, bpp, r1 = img1; _, _, bpp2, r2 = img2
    s = n = 0
    for y in range(y0, y1):
        for x in range(x0, x1):
            for c in range(3):
                s += abs(r1[y][x * bpp + c] - r2[y][x * bpp2 + c]); n += 1
    return s / n
d = sys.argv[1]
base, split, diff, same = (read_png(f'{d}/{n}.png') for n in ('base', 'split', 'diff', 'same'))
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
PY
echo "viewer split/diff ok"
