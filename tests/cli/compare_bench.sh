#!/usr/bin/env bash
# `ssrlab compare` and `ssrlab bench` write valid JSON with every field of ARCHITECTURE §7, a CSV with
# one row per result, and SVG plots; bad input is refused with exit 2 and nothing written.
set -eu
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$SSRLAB" compare --scene gallery --size 96x54 --frames 1 --out "$tmp/grid.png" --json "$tmp/compare.json" \
  --preset thesis-lq --preset stochastic-low --set reference.samples=16 --set hiz.denoise=true --exposure 0.5
"$SSRLAB" bench --scenes gallery,cornell --sizes 64x36,96x54 --techniques none,linear \
  --sweep linear.max_steps=8,32 --preset thesis-hq --set reference.samples=16 --frames 2 --warmup 1 --reflective-f0 0.05 \
  --json "$tmp/bench.json" --csv "$tmp/bench.csv" --plot "$tmp/bench.svg"
"$SSRLAB" compare --scene glass --size 64x36 --frames 1 --out "$tmp/glass.png" --set reference.samples=4
# A scene where nothing reflects: every pooled figure is null (no pixel to score), never 100 dB.
cat > "$tmp/matte.json" <<'JSON'
{"name": "matte", "materials": {"matte": {"albedo": [0.5, 0.5, 0.5], "roughness": 1.0, "reflectance": 0.0}},
 "primitives": [{"type": "plane", "name": "floor", "size": [8, 8], "material": "matte"},
                {"type": "box", "name": "b", "extents": [1, 1, 1], "material": "matte", "translate": [0, 0.5, 0]}],
 "lights": [{"type": "directional", "direction": [-0.4, -1.0, -0.35], "intensity": 2.5}],
 "cameras": [{"name": "default", "position": [2.2, 1.6, 3.2], "target": [0.0, 0.3, 0.0], "fov_y": 50}]}
JSON
"$SSRLAB" compare --scene "$tmp/matte.json" --size 48x27 --frames 1 --techniques hiz,none --out "$tmp/matte.png" \
  --json "$tmp/matte_result.json" > "$tmp/matte.txt"
if grep -q "100.00" "$tmp/matte.txt"; then echo "nothing reflects, yet a figure of 100 dB:"; cat "$tmp/matte.txt"; exit 1; fi
python3 - "$tmp/matte_result.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["inherent_psnr"] is None, j["inherent_psnr"]
assert j["truth_noise"] is None, j["truth_noise"]  # nothing sampled
for r in j["results"]:
    e = r["error"]
    assert e["reflective"] == 0 and all(e[k] is None for k in ("rmse", "psnr", "psnr_traceable", "coverage")), e
PY
# The truth's own noise: a second run of it with another seed. On cornell's glossy floor it is
# the figure's ceiling, and more samples raise it (64x36, llvmpipe: 16 samples 23.68 dB, 1024
# 31.17: fireflies through the tone map, not 1/N, so less than the 18 dB of Gaussian noise).
for n in 16 1024; do
  "$SSRLAB" compare --scene cornell --size 64x36 --techniques none --set reference.samples=$n \
    --json "$tmp/noise$n.json" --out "$tmp/noise.png" > "$tmp/noise$n.txt"
done
grep -q "truth noise floor" "$tmp/noise16.txt" || { echo "the table does not give the truth's noise floor"; exit 1; }
python3 - "$tmp" <<'PY'
import json, sys
n16, n1024 = (json.load(open(f"{sys.argv[1]}/noise{n}.json"))["truth_noise"] for n in (16, 1024))
assert n1024["psnr"] > n16["psnr"] + 4 and n1024["psnr_traceable"] > n16["psnr_traceable"] + 2, (n16, n1024)
PY
# The sweep plot: a value that is not a number (auto, true) is placed by its order and labelled
# (--plot exited 1 on std::stod); two swept keys give a series per value of the second (they
# were drawn as one line).
mkdir "$tmp/sweeps"
"$SSRLAB" bench --scenes cornell --sizes 32x18 --frames 1 --warmup 0 --techniques linear,dda \
  --sweep linear.max_steps=8,16 --sweep linear.thickness=0.1,0.5 --sweep dda.max_steps=auto,64 \
  --set reference.samples=1 --plot "$tmp/sweeps/s.svg" > /dev/null
python3 - "$tmp/sweeps/s-sweep-cornell-32x18.svg" <<'PY'
import re, sys
text = " ".join(re.sub(r"<[^>]*>", " ", t) for t in re.findall(r"<text[^>]*>[^<]*</text>", open(sys.argv[1]).read()))
for want in ("linear.max_steps at linear.thickness=0.1", "linear.max_steps at linear.thickness=0.5", "dda.max_steps", "auto"):
    assert want in text, (want, text)
PY
# Shaders from a directory (another revision's, to time it): the JSON's revision says so.
"$SSRLAB" bench --scenes gallery --sizes 32x18 --techniques linear --set reference.samples=4 --frames 1 --warmup 0 \
  --shaders "$(cd "$(dirname "$0")/../../shaders" && pwd)" --json "$tmp/bench_shaders.json" >/dev/null
# passfloor: one row per size x mode x kind x chain, finite times, the legend of every mode and kind.
"$SSRLAB" passfloor --sizes 16x16,24x8 --modes cs8x8,fs --kinds empty,copy --chains 1,3 --frames 2 \
  --json "$tmp/passfloor.json" >/dev/null
python3 - "$tmp/passfloor.json" <<'PY'
import json, math, sys
j = json.load(open(sys.argv[1]))
assert set(j) >= {"device", "revision", "frames", "legend", "results"}, j.keys()
assert j["device"]["clock"] in ("cpu", "gpu") and "chain of passes" in j["device"]["timing"], j["device"]
assert len(j["results"]) == 2 * 2 * 2 * 2, len(j["results"])
for r in j["results"]:
    assert r["mode"] in j["legend"]["modes"] and r["kind"] in j["legend"]["kinds"], r
    assert math.isfinite(r["ms"]) and r["ms"] > 0 and abs(r["ms_per_pass"] * r["chain"] - r["ms"]) < 1e-9, r
assert {(r["size"], r["chain"]) for r in j["results"]} == {(s, c) for s in ("16x16", "24x8") for c in (1, 3)}
PY

python3 - "$tmp" <<'PY'
import json, math, os, sys
tmp = sys.argv[1]
def check_run(run, where, with_device=True):
    keys = {"size", "scene", "results", "inherent_psnr", "reference", "frame"} | ({"device", "revision"} if with_device else set())
    missing = keys - run.keys()
    assert not missing, f"{where}: missing {missing}"
    if with_device:
        assert set(run["device"]) >= {"renderer", "version", "clock"}, where
        assert run["device"]["clock"] in ("cpu", "gpu"), where
    assert len(run["size"]) == 2 and all(isinstance(v, int) for v in run["size"]), where
    assert math.isfinite(run["inherent_psnr"]), where
    assert run["reference"]["reference.samples"] == 16, f"{where}: the --set reference.samples=16 not recorded"
    # The frame settings move every figure: recorded as given (compare --exposure 0.5, bench
    # --reflective-f0 0.05), the others at their defaults.
    want = {"frame.exposure": 0.5, "frame.reflective_f0": 0.1} if with_device else {"frame.exposure": 0, "frame.reflective_f0": 0.05}
    assert run["frame"] == want, f"{where}: frame settings {run['frame']}"
    assert run["results"], f"{where}: no results"
    for r in run["results"]:
        need = {"technique", "params", "ran_params", "time_ms", "passes", "floor_ms", "error", "nonfinite"}
        assert need <= r.keys(), f"{where}: result lacks {need - r.keys()}"
        # What ran: every key asked, no "auto" left but roughness's (the G-buffer's, per pixel).
        assert r["ran_params"].keys() == r["params"].keys(), where
        left = [k for k, v in r["ran_params"].items() if v == "auto" and not k.endswith(".roughness")]
        assert not left, f"{where}: {r['technique']} ran with {left} auto"
        assert set(r["time_ms"]) >= {"median", "min", "max"}, where
        assert r["time_ms"]["min"] <= r["time_ms"]["median"] <= r["time_ms"]["max"], where
        err = {"rmse", "psnr", "rmse_traceable", "psnr_traceable", "rmse_missing", "coverage"}
        assert err <= r["error"].keys(), f"{where}: error lacks {err - r['error'].keys()}"
        for k in err:
            assert math.isfinite(r["error"][k]), f"{where}: {k} not finite"
        assert 0 <= r["error"]["coverage"] <= 1, where
        assert r["nonfinite"] == 0, f"{where}: {r['technique']} has non-finite values"
        assert all({"name", "ms"} <= p.keys() for p in r["passes"]), where
        # The technique's span (ARCHITECTURE §6): its passes and what lies between them, the
        # frame's own passes apart; the span is the technique's time and not a pass.
        names = [p["name"] for p in r["passes"]]
        assert "between passes" in names and "technique" not in names, f"{where}: {names}"
        assert all(p["ms"] >= 0 for p in r["passes"]), where
        assert r["floor_ms"] > 0, where
    return run

c = check_run(json.load(open(f"{tmp}/compare.json")), "compare")
names = [r["technique"] for r in c["results"]]
assert "linear" in names and "none" in names, names
assert any(r.get("preset") == "thesis-lq" for r in c["results"]), "preset missing"
thesis = next(r for r in c["results"] if r.get("preset") == "thesis-lq")
assert thesis["params"]["linear.max_steps"] == 128 and thesis["params"]["linear.depth_interp"] is False
# A cap that another parameter lowers is recorded as it ran: stochastic-low's glossy rays stop at
# its 64 iterations, though glossy_iterations asks 128.
low = next(r for r in c["results"] if r.get("preset") == "stochastic-low")
# A row's label names what the command line set: "hiz" alone read as hiz at its defaults.
labels = {r["technique"]: r["label"] for r in c["results"] if not r.get("preset")}
assert labels["hiz"] == "hiz denoise=true" and labels["linear"] == "linear", labels
assert low["params"]["stochastic.glossy_iterations"] == 128 and low["ran_params"]["stochastic.glossy_iterations"] == 64, low

b = json.load(open(f"{tmp}/bench.json"))
assert {"device", "revision", "runs"} <= b.keys()
assert b["device"]["timing"].startswith("technique span"), b["device"]
assert "shaders from" not in b["revision"], b["revision"]
bs = json.load(open(f"{tmp}/bench_shaders.json"))
assert "(shaders from " in bs["revision"] and bs["runs"][0]["results"][0]["technique"] == "linear", bs["revision"]
assert len(b["runs"]) == 4, len(b["runs"])          # 2 scenes x 2 sizes
for i, run in enumerate(b["runs"]):
    check_run(run, f"bench run {i}", with_device=False)
    assert len(run["results"]) == 4                  # none, linear x 2 steps, thesis-hq
steps = sorted(r["params"]["linear.max_steps"] for r in b["runs"][0]["results"] if r["technique"] == "linear" and not r.get("preset"))
assert steps == [8, 32], steps

rows = open(f"{tmp}/bench.csv").read().strip().split("\n")
assert rows[0].startswith("scene,width,height,technique"), rows[0]
assert len(rows) == 1 + 16, len(rows)

svgs = sorted(f for f in os.listdir(tmp) if f.endswith(".svg"))
assert "bench.svg" in svgs, svgs
assert any("resolution" in f for f in svgs), svgs
assert any("sweep" in f for f in svgs), svgs
for f in svgs:
    text = open(os.path.join(tmp, f)).read()
    assert text.count("<svg") == 1 and "</svg>" in text, f
    assert "nan" not in text.lower().replace("nanometre", ""), f
print(f"compare/bench outputs ok: {len(svgs)} plots")
PY

# Bad input: exit 2, nothing written.
for args in "bench --json $tmp/x.json --sweep linear.max_steps=0,8" \
            "bench --json $tmp/x.json --techniques linear --sweep dda.max_steps=8" \
            "bench --json $tmp/x.json --sizes 0x0" \
            "bench --json $tmp/x.json --techniques nope" \
            "bench --json $tmp/x.json --preset nope" \
            "bench --plot $tmp/x.png" \
            "bench" \
            "compare --out $tmp/x.png --techniques linear,,none" \
            "compare --out $tmp/x.png --set reference.samples=0" \
            "compare --out $tmp/x.jpg"; do
  set +e; "$SSRLAB" $args >/dev/null 2>"$tmp/err"; rc=$?; set -e
  [ "$rc" = 2 ] || { echo "FAIL: exit $rc for: ssrlab $args"; cat "$tmp/err"; exit 1; }
  [ "$(grep -vc '^ssrlab: GL via' "$tmp/err")" = 1 ] || { echo "FAIL: not one line: ssrlab $args"; cat "$tmp/err"; exit 1; }
  ls "$tmp"/x.* >/dev/null 2>&1 && { echo "FAIL: output left by: ssrlab $args"; exit 1; }
done
echo "1 passed, 0 failed"
