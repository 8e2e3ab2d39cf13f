#!/usr/bin/env bash
# The pixel inspector (`inspect X Y`: one JSON line) reads what the CLI's views show of the same
# pixel: A's displayed colour is `render --view final`'s pixel, the normal and roughness are the
# normal and roughness views' values, the steps the steps heat map's (shared/colormap.h's heat),
# the reflective flag the mask view's; with B = the reference, the class and the error follow.
# Usage: viewer_inspect.sh SSRLAB_VIEW SSRLAB OUTDIR
set -eu
viewer=$1; ssrlab=$2; outdir=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$outdir"; mkdir -p "$outdir"; cd "$outdir"
command -v xvfb-run >/dev/null || { echo "xvfb-run is missing (apt-get install xvfb)"; exit 1; }
pixels="160 150
60 60
250 120
200 10
100 170"
{
  echo "technique hiz"
  echo "frames 2"
  echo "$pixels" | sed 's/^/inspect /'
  echo "technique-b reference"
  echo "set reference.samples=1"
  echo "compare split"
  echo "frames 1"
  echo "$pixels" | sed 's/^/inspect /'
  echo "inspect 320 10"
} > run.txt
set +e
xvfb-run -a -f "$outdir/Xauthority" -s "-screen 0 800x600x24" "$viewer" --ini "$outdir/imgui.ini" --scene gallery --size 320x180 \
  --script run.txt > log.txt 2>&1
rc=$?
set -e
[ $rc -eq 2 ] || { echo "inspect 320 10 (outside the image) should exit 2, got $rc"; cat log.txt; exit 1; }
grep -q "outside the 320x180 image" log.txt || { echo "no one-sentence error for a pixel outside the image"; cat log.txt; exit 1; }
for v in final normal roughness steps mask; do
  "$ssrlab" render --scene gallery --size 320x180 --technique hiz --view $v --out $v.png > /dev/null 2>&1 ||
    { echo "render --view $v failed"; exit 1; }
done
python3 - "$here" "$pixels" <<'PY'
import json, math, re, sys
sys.path.insert(0, sys.argv[1])
from png import read_png
log = open('log.txt').read()
probes = [json.loads(m) for m in re.findall(r'ssrlab-view: inspect (\{.*\})', log)]
pixels = [tuple(map(int, l.split())) for l in sys.argv[2].splitlines()]
assert len(probes) == 2 * len(pixels), f'{len(probes)} inspect lines:\n' + log
views = {v: read_png(v + '.png') for v in ('final', 'normal', 'roughness', 'steps', 'mask')}
def px(img, x, y):
    w, h, bpp, rows = img
    return rows[y][x * bpp:x * bpp + 3]
def heat(t):
    t = min(max(t, 0.0), 1.0)
    c = (1.6 * t, 1.6 * t * t, 0.5 * math.sin(3.14159 * t) + 0.2 * t ** 3)
    return [round(255 * min(max(v, 0.0), 1.0)) for v in c]
def close(a, b, tol, what):
    assert all(abs(p - q) <= tol for p, q in zip(a, b)), f'{what}: inspector {list(a)} vs CLI {list(b)}'
for (x, y), j in zip(pixels, probes[:len(pixels)]):
    assert j['pixel'] == [x, y]
    close(j['a']['display'], px(views['final'], x, y), 0, f'({x},{y}) final colour')
    if j['depth'] > 0:
        close([round(255 * min(max(n * 0.5 + 0.5, 0), 1)) for n in j['normal']], px(views['normal'], x, y), 1, f'({x},{y}) normal')
        close([round(255 * j['roughness'])] * 3, px(views['roughness'], x, y), 1, f'({x},{y}) roughness')
    reflective = px(views['mask'], x, y)[0] > 128
    assert j['reflective'] == reflective, f'({x},{y}): reflective {j["reflective"]}, the mask view says {reflective}'
    if reflective:
        close(heat(j['a']['steps'] / 256.0), px(views['steps'], x, y), 1, f'({x},{y}) steps {j["a"]["steps"]}')
    print(f'({x:3},{y:3}) depth {j["depth"]:.4f} object {j["object"]} reflector {j["reflector"]} reflective {j["reflective"]} '
          f'steps {j["a"].get("steps")}: matches the CLI views')
for (x, y), j in zip(pixels, probes[len(pixels):]):
    assert j['b']['technique'] == 'reference' and j['b']['current']
    assert j['class'] is not None, 'with the reference current the class is known'
    assert (j['class'] == 'not-reflective') == (not j['reflective']), j
    assert j['b']['error'] == 0 and j['a']['error'] >= 0, j
    print(f'({x:3},{y:3}) class {j["class"]}, |hiz - truth| {j["a"]["error"]:.4f}')
PY
echo "viewer inspect ok"

# A technique without a debug image of its own (stochastic: stage and telemetry views only)
# reports no steps: it reported hiz's, read from the image hiz had left there.
printf 'technique hiz\nframes 2\ninspect 160 150\ntechnique stochastic\nframes 2\ninspect 160 150\n' > stale.txt
xvfb-run -a -f "$outdir/Xauthority" -s "-screen 0 800x600x24" "$viewer" --ini "$outdir/imgui.ini" --scene gallery --size 320x180 \
  --script stale.txt > stale.log 2>&1 || { cat stale.log; exit 1; }
python3 - <<'PY'
import json, re
probes = [json.loads(m) for m in re.findall(r'ssrlab-view: inspect (\{.*\})', open('stale.log').read())]
assert len(probes) == 2 and 'steps' in probes[0]['a'], probes
assert probes[1]['a']['technique'] == 'stochastic' and 'steps' not in probes[1]['a'], probes[1]['a']
print('stochastic after hiz: no stale steps')
PY
echo "viewer inspect stale ok"
