#!/usr/bin/env python3
"""Markdown tables from `ssrlab bench --json` files, for docs/RESULTS.md.

    scripts/bench_table.py bench.json [more.json ...]

One table per (scene, size): technique, median/min/max ms, time over the floor pass, PSNR,
PSNR traceable, coverage, non-finite count. Device, clock and revision come from each file.
Then, per (scene, size), "speed at equal error": the error linear-binary reaches at its largest
swept budget is the target; for each technique, the fastest variant whose PSNR traceable is
within 0.25 dB of it (or better), and how many times faster than linear-binary's fastest such
variant it is.
"""
import json
import sys


def labels_of(run):
    """Technique + the parameters that vary among its (non-preset) results in this run."""
    varying = {}
    for r in run["results"]:
        if r.get("preset"):
            continue
        for k, v in r["params"].items():
            varying.setdefault((r["technique"], k), set()).add(json.dumps(v))
    out = []
    for r in run["results"]:
        if r.get("preset"):
            out.append(f"{r['technique']} [{r['preset']}]")
            continue
        keys = [k for k in r["params"] if len(varying[(r["technique"], k)]) > 1]
        out.append(" ".join([r["technique"]] + [f"{k.split('.', 1)[1]}={json.dumps(r['params'][k])}" for k in keys]))
    return out


def fmt(v, digits=2):
    return f"{v:.{digits}f}"


def main(paths):
    for path in paths:
        doc = json.load(open(path))
        dev = doc["device"]
        print(f"Device: {dev['renderer']}, {dev['version']}, clock `{dev['clock']}`, "
              f"revision `{doc['revision']}`\n")
        for run in doc["runs"]:
            w, h = run["size"]
            print(f"**{run['scene']} {w}x{h}** (inherent screen-space PSNR "
                  f"{fmt(run['inherent_psnr'])} dB)\n")
            print("| technique | median ms | min | max | x floor | PSNR dB | PSNR traceable dB "
                  "| coverage | non-finite |")
            print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
            for label, r in zip(labels_of(run), run["results"]):
                t = r["time_ms"]
                e = r["error"]
                print(f"| {label} | {fmt(t['median'], 3)} | {fmt(t['min'], 3)} "
                      f"| {fmt(t['max'], 3)} | {fmt(r['time_over_floor'], 1)} | {fmt(e['psnr'])} "
                      f"| {fmt(e['psnr_traceable'])} | {e['coverage'] * 100:.1f}% | {r['nonfinite']} |")
            print()


def equal_error(paths, baseline="linear-binary", slack=0.25):
    print("| scene | size | target PSNR traceable dB | technique | fastest variant at target | ms | speed-up vs "
          f"{baseline} |")
    print("|---|---|---:|---|---|---:|---:|")
    for path in paths:
        for run in json.load(open(path))["runs"]:
            base = [r for r in run["results"] if r["technique"] == baseline and not r.get("preset")]
            if not base:
                continue
            # The target: what the baseline reaches with its largest step budget.
            steps_key = baseline + ".linear_steps"
            target = max(base, key=lambda r: r["params"].get(steps_key, 0))["error"]["psnr_traceable"]
            def fastest(rs):
                ok = [r for r in rs if r["error"]["psnr_traceable"] >= target - slack]
                return min(ok, key=lambda r: r["time_ms"]["median"]) if ok else None
            ref = fastest(base)
            label = dict(zip(map(id, run["results"]), labels_of(run)))
            w, h = run["size"]
            for tech in sorted({r["technique"] for r in run["results"]} - {"none"}):
                best = fastest([r for r in run["results"] if r["technique"] == tech and not r.get("preset")])
                if best is None:
                    print(f"| {run['scene']} | {w}x{h} | {fmt(target)} | {tech} | does not reach it | | |")
                    continue
                ratio = ref["time_ms"]["median"] / best["time_ms"]["median"]
                print(f"| {run['scene']} | {w}x{h} | {fmt(target)} | {tech} | {label[id(best)]} "
                      f"| {fmt(best['time_ms']['median'], 3)} | {fmt(ratio)}x |")
    print()


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: bench_table.py bench.json [more.json ...]")
    main(sys.argv[1:])
    equal_error(sys.argv[1:])
