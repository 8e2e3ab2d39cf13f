#!/usr/bin/env bash
# `ssrlab sequence`: the JSON's fields, determinism run to run, zero flicker for a deterministic
# technique on a still camera, a cut on the `cut` path, PNG frames, the video (when ffmpeg is
# present), and bad input: exit 2, one sentence, nothing written.
set -eu
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
seq() { "$SSRLAB" sequence --size 96x54 --set reference.samples=8 "$@"; }

seq --scene gallery --path cut --frames 8 --fps 2 --techniques linear,hiz,ppr --json "$tmp/a.json" \
  --plot "$tmp/a.svg" --out "$tmp/frames" > "$tmp/a.txt"
seq --scene gallery --path cut --frames 8 --fps 2 --techniques linear,hiz,ppr --json "$tmp/b.json" > /dev/null
seq --scene corridor --path still --frames 3 --techniques linear,dda --second-truth --json "$tmp/still.json" > "$tmp/still.txt"
seq --scene cornell --frames 4 --truth-every 2 --techniques linear --json "$tmp/every.json" > "$tmp/every.txt"
seq --scene cornell --frames 4 --truth-every 2 --techniques linear,hiz --second-truth --json "$tmp/second.json" > "$tmp/second.txt"
# --shaders: the checkout's own shaders give the embedded ones' figures, and the JSON says whose.
seq --scene cornell --frames 3 --techniques stochastic --json "$tmp/embedded.json" > /dev/null
seq --scene cornell --frames 3 --techniques stochastic --shaders "$(cd "$(dirname "$0")/../../shaders" && pwd)" \
  --json "$tmp/own_shaders.json" > /dev/null
seq --scene cornell --frames 5 --truth-every 3 --techniques linear --second-truth --json "$tmp/every3.json" > /dev/null
seq --scene cornell --path still --frames 2 --techniques stochastic,hiz --sweep stochastic.temporal=false,true \
  --sweep hiz.denoise=false,true --json "$tmp/sweep.json" > /dev/null
# A reflection moving over a floor that stays (gallery's sliding sphere): a history that lags
# leaves a trail there, which the disocclusion figure does not see.
"$SSRLAB" sequence --size 160x90 --set reference.samples=16 --scene gallery --path slide --frames 16 --techniques hiz \
  --sweep hiz.denoise=false,true --json "$tmp/slide.json" > /dev/null

python3 - "$tmp" <<'PY'
import json, math, os, sys
tmp = sys.argv[1]
a = json.load(open(f"{tmp}/a.json"))
assert {"device", "revision", "scene", "path", "width", "height", "fps", "truth_every", "reference", "frame", "frames", "summary"} <= a.keys()
assert a["frame"] == {"frame.exposure": 0, "frame.reflective_f0": 0.1}, a["frame"]
assert a["reference"]["reference.samples"] > 0 and set(a["reference"]) >= {"reference.seed", "reference.bounces"}, a["reference"]
assert a["path"] == "cut" and len(a["frames"]) == 8
assert any(f["cut"] for f in a["frames"]), "the cut path has no cut"
for f in a["frames"]:
    assert {"index", "time", "cut", "truth", "results"} <= f.keys()
    for r in f["results"]:
        assert {"technique", "label", "error", "regions", "nonfinite"} <= r.keys()
        assert r["nonfinite"] == 0, (f["index"], r["technique"])
        assert math.isfinite(r["error"]["psnr"]) and "all" in r["regions"]
for s in a["summary"]:
    assert {"technique", "label", "instability", "ghosting", "convergence", "ran_params"} <= s.keys()
    assert s["ran_params"].keys() == s["params"].keys(), s["ran_params"]
    # Every parameter's value, defaults and "auto" included (a result names its parameters).
    assert s["params"] and all(k.startswith(s["technique"] + ".") for k in s["params"]), s["params"]
    assert set(s["instability"]) >= {"mean", "p95", "change_mean", "truth_change_mean", "change_ratio"}
    assert set(s["ghosting"]) >= {"disoccluded_psnr", "elsewhere_psnr", "moving_psnr", "moving_pixels"}
    assert s["instability"]["change_mean"] >= 0 and s["instability"]["truth_change_mean"] >= 0
    assert len(s["convergence"]) == 8 and s["convergence_frames"] == list(range(8))
    assert s["instability"]["mean"] >= 0 and s["instability"]["p95"] >= s["instability"]["mean"] * 0.5
    # The camera moves: some flicker is measured (0.0127-0.0133, 96x54, llvmpipe; a summary that
    # wrote 0 passed every other check here).
    assert s["instability"]["mean"] > 0.005, s["instability"]
    assert s["instability"]["mean"] == s["instability"]["regions"]["all"]["mean"], s["instability"]
# Run to run: the same numbers (the device and revision are the same too).
b = json.load(open(f"{tmp}/b.json"))
assert a["frames"] == b["frames"] and a["summary"] == b["summary"], "the sequence is not deterministic"
# A still camera on a scene where nothing moves, deterministic techniques: no flicker at all.
still = json.load(open(f"{tmp}/still.json"))
for s in still["summary"]:
    assert s["instability"]["mean"] == 0 and s["instability"]["p95"] == 0, s
# --truth-every 2: truth at frames 0, 1 (a pair), 2, 3.
every = json.load(open(f"{tmp}/every.json"))
assert [f["truth"] for f in every["frames"]] == [True, True, True, True]
# The truth's own noise on the first pair (96x54, 8 samples, llvmpipe): cornell's dolly changes
# the truth by 0.00337 a pixel, 0.00276 of it noise (the noise is fixed to the screen; the pixels
# that reproject to another pixel draw new samples); gallery's cut path 0.02874 and 0.00022 (its
# rough pixels are few); a still camera on corridor, where nothing moves, 0 and 0.
def noise_of(j):
    n = j["truth_noise"]
    assert set(n) == {"psnr", "psnr_traceable", "first_pair_change_mean", "first_pair_noise_change_mean"}, n
    return n["first_pair_noise_change_mean"], n["first_pair_change_mean"]
noise, change = noise_of(every)
assert 0.5 * change < noise < 2 * change and change > 0.001, (noise, change)
noise, change = noise_of(a)
assert noise < 0.05 * change, (noise, change)
assert noise_of(still) == (0, 0), still["truth_noise"]
for name, flagged in (("every", True), ("a", False), ("still", False)):
    text = open(f"{tmp}/{name}.txt").read()
    assert "truth noise: from frame 0 to 1" in text, text
    assert ("the truth's change is mostly noise" in text) == flagged, (name, text)
# --second-truth: "x truth" without the truth's noise (root-mean-square). On cornell's dolly
# (96x54, 8 samples, llvmpipe), mean absolute -> root-mean-square against the noisy truth -> the
# same without its noise: linear 2.71 -> 3.11 -> 4.23, hiz 2.03 -> 2.63 -> 3.58; with truth
# every 3rd frame and the one after (pairs 0-1 and 3-4), linear 2.99 -> 3.49 -> 5.72. A second
# truth paired with the wrong frame's first read 3.89 / 3.29 (a review's mutation): pinned.
second = json.load(open(f"{tmp}/second.json"))
assert second["second_truth"] and not every["second_truth"], (second["second_truth"], every["second_truth"])
assert all(s["instability"]["noise_free_change_ratio"] is None for s in every["summary"]), every["summary"]
want = {"linear": (3.11, 4.23), "hiz": (2.63, 3.58)}
for s in second["summary"] + [dict(json.load(open(f"{tmp}/every3.json"))["summary"][0], label="linear every 3")]:
    i = s["instability"]
    rms, noise_free = want.get(s["label"], (3.49, 5.72))
    assert abs(i["rms_change_ratio"] - rms) < 0.05 and abs(i["noise_free_change_ratio"] - noise_free) < 0.05, (s["label"], i)
assert "x truth, no noise" in open(f"{tmp}/second.txt").read() and "x truth, no noise" not in open(f"{tmp}/every.txt").read()
# A truth that does not move has no ratio to give (and the techniques do not move either).
assert all(s["instability"]["noise_free_change_ratio"] is None for s in still["summary"]), still["summary"]
embedded, own = (json.load(open(f"{tmp}/{n}.json")) for n in ("embedded", "own_shaders"))
assert embedded["summary"] == own["summary"] and embedded["frames"] == own["frames"], "--shaders changed the figures"
assert "(shaders from " in own["revision"] and "(shaders from " not in embedded["revision"], own["revision"]
# --truth-every 3: truth at frames 0, 1, 3, 4; convergence has one entry each and names its frame.
every3 = json.load(open(f"{tmp}/every3.json"))
assert [f["index"] for f in every3["frames"] if f["truth"]] == [0, 1, 3, 4]
s3 = every3["summary"][0]
assert s3["convergence_frames"] == [0, 1, 3, 4] and len(s3["convergence"]) == 4, s3
# --sweep: each value its own technique, labelled by it.
sweep = json.load(open(f"{tmp}/sweep.json"))
assert [s["label"] for s in sweep["summary"]] == ["stochastic temporal=false", "stochastic temporal=true",
                                                   "hiz denoise=false", "hiz denoise=true"], sweep["summary"]
# 160x90, llvmpipe: moving reflections 11.99 dB raw, 11.52 with the denoiser's history (1012
# pixels), while elsewhere the denoiser is ahead (16.47 against 16.42).
raw, den = (s["ghosting"] for s in json.load(open(f"{tmp}/slide.json"))["summary"])
assert raw["moving_pixels"] > 500 and raw["moving_pixels"] == den["moving_pixels"], (raw, den)
assert den["moving_psnr"] < raw["moving_psnr"] - 0.2 and den["elsewhere_psnr"] > raw["elsewhere_psnr"], (raw, den)
assert os.path.getsize(f"{tmp}/a.svg") > 1000 and open(f"{tmp}/a.svg").read().count("<svg") == 3
assert sorted(os.listdir(f"{tmp}/frames")) == [f"frame_{i:05d}.png" for i in range(8)]
PY
grep -q "flicker mean" "$tmp/a.txt"

if command -v ffmpeg > /dev/null && command -v ffprobe > /dev/null; then
  seq --scene gallery --path pan --frames 5 --techniques linear --json "$tmp/v.json" --video "$tmp/v.mp4" > /dev/null
  n=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$tmp/v.mp4")
  [ "$n" = 5 ] || { echo "video has $n frames, not 5"; exit 1; }
else
  echo "sequence.sh: ffmpeg missing, video check skipped"
fi

# Bad input: exit 2, one line on stderr, nothing written.
bad() {  # bad WORDS ARGS...: exit 2, one line holding WORDS, nothing written
  local want=$1; shift
  local out="$tmp/bad"
  rm -rf "$out"; mkdir "$out"
  set +e
  env ${NO_FFMPEG:+PATH=/nonexistent} "$SSRLAB" sequence --size 64x36 --json "$out/r.json" "$@" 2> "$out/err.txt" > /dev/null
  local rc=$?
  set -e
  [ $rc -eq 2 ] || { echo "expected exit 2, got $rc for: $*"; cat "$out/err.txt"; exit 1; }
  [ "$(wc -l < "$out/err.txt")" -eq 1 ] || { echo "expected one line for: $*"; cat "$out/err.txt"; exit 1; }
  [ "$(ls "$out")" = "err.txt" ] || { echo "files left behind for: $*"; ls "$out"; exit 1; }
  grep -qF -- "$want" "$out/err.txt" || { echo "refused, but not for '$want': $*"; cat "$out/err.txt"; exit 1; }
}
bad "no camera path 'nowhere'" --scene gallery --path nowhere --frames 2
grep -q "paths: dolly, orbit, pan, slide, enter, cut, still" "$tmp/bad/err.txt" || { echo "the paths listed lack 'still':"; cat "$tmp/bad/err.txt"; exit 1; }
bad '--frames must be in' --scene gallery --frames 0
bad '--truth-every must be in' --scene gallery --frames 2 --truth-every 0
bad '--fps must be in' --scene gallery --frames 2 --fps 0
bad '--fps must be in' --scene gallery --frames 3 --fps 1e-40  # frame times would overflow a float
bad 'given more than once' --scene gallery --frames 2 --frames 3
bad 'of --video does not exist' --scene gallery --frames 2 --video "$tmp/missing-dir/v.mp4"
bad 'must end in .mp4 or .mkv' --scene gallery --frames 2 --video "$tmp/bad/v.gif"
bad 'must be a new or empty directory' --scene gallery --frames 2 --out "$tmp"
bad "unknown technique 'nothing'" --scene gallery --frames 2 --techniques nothing
bad 'needs a value, not an empty string' --scene gallery --frames 2 --techniques ""
bad 'name the same path' --scene gallery --frames 2 --out "$tmp/bad/r.json"  # the --json file of bad()
bad 'name the same path' --scene gallery --frames 2 --out "$tmp/bad/r.json/"
# "frames/" (a shell's completion) is the directory frames: its temporary lands beside it.
mkdir "$tmp/slash"
seq --scene gallery --path still --frames 2 --techniques none --json "$tmp/slash.json" --out "$tmp/slash/" > /dev/null
[ "$(ls "$tmp/slash")" = "$(printf 'frame_00000.png\nframe_00001.png')" ] || { echo "--out DIR/ holds:"; ls -a "$tmp/slash"; exit 1; }
NO_FFMPEG=1 bad 'needs ffmpeg' --scene gallery --frames 2 --video "$tmp/bad/v.mp4"

# A signal while frames and a video are written: they are removed, not left as temporaries.
stopped="$tmp/stopped"
mkdir "$stopped"
"$SSRLAB" sequence --size 64x36 --frames 100000 --techniques none --json "$stopped/s.json" \
  --out "$stopped/frames" 2> "$stopped/err.txt" > /dev/null &
pid=$!
waited=0
until ls "$stopped"/frames.tmp*/frame_* > /dev/null 2>&1 || [ $waited -ge 600 ]; do  # the first frame (a minute at most)
  sleep 0.1
  waited=$((waited + 1))
done
kill -INT $pid
set +e
wait $pid
rc=$?
set -e
[ $rc -eq 1 ] || { echo "a stopped sequence exited $rc, not 1"; cat "$stopped/err.txt"; exit 1; }
grep -q "stopped by signal 2" "$stopped/err.txt" || { echo "no stop message"; cat "$stopped/err.txt"; exit 1; }
[ "$(ls "$stopped")" = "err.txt" ] || { echo "files left behind by a stopped sequence:"; ls "$stopped"; exit 1; }
echo "sequence: ok"
