#!/usr/bin/env bash
# The viewer's A-vs-B figure is compare's: with B = the reference, the PSNR the viewer prints for
# hiz equals `ssrlab compare`'s PSNR of hiz on the same frame (same metric code, same pixels:
# the final image's display values on the reflective pixels). Usage:
# viewer_figures.sh SSRLAB_VIEW SSRLAB OUTDIR
# With truth-noise on, the truth's noise floor it shows is compare's too (a second truth, the
# same seed offset, the same pixels).
set -eu
viewer=$1; ssrlab=$2; outdir=$3
rm -rf "$outdir"; mkdir -p "$outdir"; cd "$outdir"
command -v xvfb-run >/dev/null || { echo "xvfb-run is missing (apt-get install xvfb)"; exit 1; }
cat > run.txt <<'SCRIPT'
technique hiz
technique-b reference
set reference.samples=4
compare diff
frames 2
SCRIPT
xvfb-run -a -f "$outdir/Xauthority" -s "-screen 0 800x600x24" "$viewer" --ini "$outdir/imgui.ini" --scene gallery --size 320x180 \
  --script run.txt > log.txt 2>&1 || { cat log.txt; exit 1; }
"$ssrlab" compare --scene gallery --size 320x180 --techniques hiz --set reference.samples=4 --frames 1 \
  --out grid.png --json results.json > compare.txt 2>&1 || { cat compare.txt; exit 1; }
python3 - <<'PY'
import json, re
log = open('log.txt').read()
m = re.search(r'PSNR A vs B ([0-9.]+) dB', log)
assert m, 'the viewer printed no PSNR:\n' + log
viewer = float(m.group(1))
cli = json.load(open('results.json'))['results'][0]['error']['psnr']
print(f'hiz vs reference on gallery 320x180: viewer {viewer:.2f} dB, compare {cli:.2f} dB')
assert abs(viewer - cli) <= 0.01, 'the viewer and compare disagree'
PY
echo "viewer figures ok"

# A technique with history (stochastic) changes its image every frame on a still camera: the
# figure follows it (it was computed once per camera and parameters, and stayed at frame 1's).
# The grid also gives A against its truth, the figure of its fourth cell.
cat > settle.txt <<'SCRIPT'
technique stochastic
technique-b hiz
compare split
frames 1
status
frames 6
status
compare grid
set reference.samples=4
frames 2
status
SCRIPT
xvfb-run -a -f "$outdir/Xauthority" -s "-screen 0 800x600x24" "$viewer" --ini "$outdir/imgui.ini" --scene cornell --size 320x180 \
  --script settle.txt > settle.txt.log 2>&1 || { cat settle.txt.log; exit 1; }
python3 - <<'PY'
import json
status = [json.loads(l.split('status ', 1)[1]) for l in open('settle.txt.log') if 'ssrlab-view: status ' in l]
print('stochastic vs hiz after 1 and 7 frames:', [s['psnr'] for s in status[:2]], 'grid A vs truth:', status[2]['psnr_truth'])
assert status[0]['psnr'] is not None and status[1]['psnr'] is not None
assert status[0]['psnr'] != status[1]['psnr'], 'the PSNR did not follow a settling image'
assert status[2]['psnr_truth'] is not None, 'the grid gave no A-vs-truth figure'
PY
echo "viewer settling figure ok"

# The same technique on both sides at two settings: set-b reaches B alone (set reached both, so
# the figure was "identical"), and the labels say what differs.
printf 'technique hiz\ntechnique-b hiz\nset-b hiz.max_iterations=8\ncompare split\nframes 2\nstatus\n' > same.txt
xvfb-run -a -f "$outdir/Xauthority" -s "-screen 0 800x600x24" "$viewer" --ini "$outdir/imgui.ini" --scene gallery --size 320x180 \
  --script same.txt > same.log 2>&1 || { cat same.log; exit 1; }
python3 - <<'PY'
import json
s = [json.loads(l.split('status ', 1)[1]) for l in open('same.log') if 'ssrlab-view: status ' in l][0]
print('hiz against hiz with 8 iterations:', s['psnr'])
assert s['psnr'] is not None and s['psnr'] < 60, 'set-b did not reach B alone'
PY
echo "viewer set-b ok"

# The truth's noise floor: cornell's glossy floor samples the truth (4 rays a pixel here), so two
# seeds differ; the viewer's floor for this frame is compare's `truth_noise`, again after the
# truth changes (16 rays: the viewer's second truth is one reference, set up anew for each
# truth), and it is gone once the estimate is switched off.
printf 'technique hiz\ntechnique-b reference\nset reference.samples=4\ncompare split\ntruth-noise on\nframes 2\nstatus\nset reference.samples=16\nframes 2\nstatus\ntruth-noise off\nframes 1\nstatus\n' > noise.txt
xvfb-run -a -f "$outdir/Xauthority" -s "-screen 0 800x600x24" "$viewer" --ini "$outdir/imgui.ini" --scene cornell --size 320x180 \
  --script noise.txt > noise.log 2>&1 || { cat noise.log; exit 1; }
"$ssrlab" compare --scene cornell --size 320x180 --techniques hiz --set reference.samples=4 --frames 1 \
  --out noise-grid.png --json noise.json > noise-compare.txt 2>&1 || { cat noise-compare.txt; exit 1; }
"$ssrlab" compare --scene cornell --size 320x180 --techniques hiz --set reference.samples=16 --frames 1 \
  --out noise16-grid.png --json noise16.json > noise16-compare.txt 2>&1 || { cat noise16-compare.txt; exit 1; }
python3 - <<'PY'
import json
status = [json.loads(l.split('status ', 1)[1]) for l in open('noise.log') if 'ssrlab-view: status ' in l]
cli = [json.load(open(f))['truth_noise']['psnr'] for f in ('noise.json', 'noise16.json')]
print('cornell 320x180, truth noise floor at 4 and 16 samples: viewer', status[0]['truth_noise'],
      status[1]['truth_noise'], 'compare', cli[0], cli[1], '; off:', status[2]['truth_noise'])
for s, c in zip(status, cli):
    assert isinstance(s['truth_noise'], float), 'the viewer showed no noise floor'
    assert abs(s['truth_noise'] - c) <= 0.01, 'the viewer and compare disagree on the truth noise'
# Measured (llvmpipe): 22.35 and 23.04 dB; the check below tells the two truths' floors apart.
assert abs(cli[1] - cli[0]) > 0.3, 'the two truths should have different floors'
assert status[0]['psnr'] < 60, 'the two sides were not both drawn'
assert status[2]['truth_noise'] is None, 'truth-noise off still shows a floor'
PY
echo "viewer truth noise ok"
