#!/usr/bin/env bash
# The viewer's layout, read from what the user sees (window-shot: the whole window as presented):
#   - the image is never under the panel or the status bar: the window's image area equals the
#     image alone (screenshot), pixel for pixel, and --size is the image's size;
#   - hiding the panel (F2's command) gives its room to the image;
#   - the legend of a heat-map view is drawn (the panel's top holds the view's heat colours);
#   - a truth left stale (the camera moved, truth manual) shows no figure: the status says
#     "stale" with no PSNR, and the image carries the red "STALE" banner;
#   - the grid has four cells, each labelled (the labels are drawn over the window, never into
#     the image), and the inspector maps a pixel to its cell's frame.
# Usage: viewer_layout.sh SSRLAB_VIEW OUTDIR
set -eu
viewer=$1; outdir=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$outdir"; mkdir -p "$outdir"; cd "$outdir"
command -v xvfb-run >/dev/null || { echo "xvfb-run is missing (apt-get install xvfb)"; exit 1; }
cat > run.txt <<'SCRIPT'
technique hiz
frames 2
screenshot image.png
window-shot window.png
view steps
frames 1
window-shot legend.png
panel off
frames 1
screenshot wide.png
window-shot nopanel.png
panel on
view final
technique-b reference
set reference.samples=1
compare split
frames 1
status
truth manual
camera high
frames 1
status
window-shot stale.png
truth now
frames 2
status
truth live
frames 1
screenshot split-image.png
window-shot split.png
compare diff
frames 1
screenshot diff-image.png
window-shot diff.png
compare grid
frames 1
screenshot grid-image.png
window-shot grid.png
inspect 200 120
preset thesis-hq
status
preset-load /nonexistent/preset.json
SCRIPT
set +e
xvfb-run -a -f "$outdir/Xauthority" -s "-screen 0 1024x600x24" "$viewer" --ini "$outdir/imgui.ini" --scene gallery --size 320x180 \
  --script run.txt > log.txt 2>&1
rc=$?
set -e
# The last line fails on purpose (a missing preset): exit 2 and one sentence.
[ $rc -eq 2 ] || { echo "expected exit 2 from the missing preset, got $rc"; cat log.txt; exit 1; }
grep -q "run.txt:.*preset" log.txt || { echo "the error does not name the script line"; cat log.txt; exit 1; }
python3 - "$here" <<'PY'
import json, re, sys
sys.path.insert(0, sys.argv[1])
from png import read_png
log = open('log.txt').read()
status = [json.loads(m) for m in re.findall(r'ssrlab-view: status (\{.*\})', log)]
assert len(status) == 4, log
image, window, legend, wide, nopanel, stale = (read_png(n + '.png') for n in
    ('image', 'window', 'legend', 'wide', 'nopanel', 'stale'))
def px(img, x, y):
    w, h, bpp, rows = img
    return tuple(rows[y][x * bpp:x * bpp + 3])
W, H = window[0], window[1]
assert (image[0], image[1]) == (320, 180), f'--size names the image: got {image[0]}x{image[1]}'
assert W > 320 and H > 180, f'the window {W}x{H} has no room for the panel and status bar'
# The image area of the window is the image itself: nothing covers it.
diff = sum(1 for y in range(180) for x in range(320) if px(window, x, y) != px(image, x, y))
print(f'window {W}x{H}; image area pixels that differ from the image: {diff}')
assert diff == 0, 'something is drawn over the image'
# The panel is there (right of the image) and is not the image.
panel = {px(window, x, y) for y in range(0, 180, 3) for x in range(330, W, 3)}
assert len(panel) > 8, 'the side panel looks empty'
# Panel hidden: the image takes the window's width.
assert (wide[0], wide[1]) == (W, 180), f'with the panel hidden the image is {wide[0]}x{wide[1]}, not {W}x180'
assert (nopanel[0], nopanel[1]) == (W, H)
# The steps view's legend: the heat ramp (shared/colormap.h's heat) at the top of the panel.
import math
def heat(t):
    t = min(max(t, 0.0), 1.0)
    c = (1.6 * t, 1.6 * t * t, 0.5 * math.sin(3.14159 * t) + 0.2 * t ** 3)
    return tuple(round(255 * min(max(v, 0.0), 1.0)) for v in c)
ramp = [heat((i + 0.5) / 64) for i in range(64)]
top = {px(legend, x, y) for y in range(0, 70) for x in range(320, W)}
found = sum(1 for c in ramp if any(sum(abs(a - b) for a, b in zip(c, t)) <= 6 for t in top))
print(f'legend: {found} of 64 heat-ramp colours in the panel top')
assert found >= 48, 'no heat-map legend drawn for the steps view'
# Truth: current after the scripted frame; stale (no figure) after the camera moved with truth manual;
# current again after 'truth now'.
print('truth states:', [s['truth'] for s in status], 'psnr:', [s['psnr'] for s in status])
assert status[0]['truth'] == 'current' and status[0]['psnr'] is not None
assert status[1]['truth'] == 'stale' and status[1]['psnr'] is None, 'a stale truth still shows a figure'
assert status[2]['truth'] == 'current' and status[2]['psnr'] is not None
assert status[0]['image'] == [320, 180] and status[0]['clock'] in ('cpu', 'gpu') and status[0]['device']
# The banner on the stale side (B: right of the divider at 160): a dark red box with light text.
red = sum(1 for y in range(4, 40) for x in range(165, 320)
          if px(stale, x, y)[0] > 100 and px(stale, x, y)[1] < 60 and px(stale, x, y)[2] < 50)
print(f'stale banner pixels: {red}')
assert red > 200, 'the stale truth is not marked on the image'
# Split and difference: the panel covers nothing either (split: away from the divider at x=160
# and the A/B labels at the bottom, which are the mode's own overlays: two lines for 'B:
# reference samples=1' in a 160-pixel half).
for name, skip in (('split', lambda x, y: abs(x - 160) <= 3 or y >= 135), ('diff', lambda x, y: False)):
    win, img = read_png(name + '.png'), read_png(name + '-image.png')
    bad = sum(1 for y in range(180) for x in range(320) if not skip(x, y) and px(win, x, y) != px(img, x, y))
    print(f'{name}: image area pixels that differ from the image: {bad}')
    assert bad == 0, f'something is drawn over the {name} image'
# The grid: four cells of 160x90, a label in each cell's bottom-left corner (window only).
grid, grid_image = read_png('grid.png'), read_png('grid-image.png')
assert (grid_image[0], grid_image[1]) == (320, 180)
for c in range(4):
    x0, y0 = 160 * (c % 2), 90 * (c // 2 + 1) - 24
    drawn = sum(1 for y in range(y0, y0 + 16) for x in range(x0 + 4, x0 + 60)
                if px(grid, x, y) != px(grid_image, x, y))
    print(f'grid cell {c}: {drawn} label pixels')
    assert drawn > 150, f'grid cell {c} has no label'
# The cells differ (A, B = the reference, the truth, the difference): not one image four times.
cells = [[px(grid_image, 160 * (c % 2) + x, 90 * (c // 2) + y) for y in range(10, 60, 5) for x in range(20, 140, 5)] for c in range(4)]
assert cells[3] != cells[0] and cells[2] != cells[3], 'the grid cells look alike'
probe = json.loads(re.findall(r'ssrlab-view: inspect (\{.*\})', log)[0])
assert probe['pixel'] == [200 - 160, 120 - 90] and 'truth' in probe, probe
# A named preset of the CLI: technique A becomes the preset's, the status names its source.
assert status[3]['message'].startswith('preset thesis-hq: '), status[3]
PY
echo "viewer layout ok"
