#!/usr/bin/env python3
"""Markdown tables from `ssrlab bench --json` files, for docs/RESULTS.md.

    scripts/bench_table.py bench.json [more.json ...]
    scripts/bench_table.py --regions [--defaults] bench.json [more.json ...]
    scripts/bench_table.py --summary bench.json   (ms / PSNR vs ideal / correct coverage per technique)

One table per (scene, size): technique, median/min/max ms, time over the floor pass, PSNR,
PSNR traceable, coverage, non-finite count. Device, clock and revision come from each file.
Then, per (scene, size), "speed at equal error": the error linear-binary reaches at its largest
swept budget is the target; for each technique, the fastest variant whose PSNR traceable is
within 0.25 dB of it (or better), and how many times faster than linear-binary's fastest such
variant it is. With --regions: per (scene, size), each technique's verdict per region (traceable
PSNR against the ideal, correct coverage, false-hit rate on missing and sky pixels, noise floor),
"n/a" where the technique does not handle the region, "-" for an empty set.
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
    """A figure, or '-' where it is null (an empty pixel set has none)."""
    return "-" if v is None else f"{v:.{digits}f}"


def load(path, need_regions=False):
    """A bench JSON (its dict, 'runs' checked); one clear sentence (not a traceback) for any other file."""
    try:
        doc = json.load(open(path))
    except (OSError, ValueError) as e:
        sys.exit(f"bench_table.py: {path}: {e}")
    if not isinstance(doc, dict) or "runs" not in doc:
        sys.exit(f"bench_table.py: {path} is not a bench JSON (no 'runs'; compare's JSON is one run, not a list)")
    if need_regions and any("regions" not in r for run in doc["runs"] for r in run["results"]):
        sys.exit(f"bench_table.py: {path} has results without 'regions' (a bench JSON from before the "
                 "per-region verdicts): this table needs them")
    return doc


def main(paths):
    for path in paths:
        doc = load(path)
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
                      f"| {fmt(e['psnr_traceable'])} | {pct(e['coverage'])} | {r['nonfinite']} |")
            print()


def pct(v):
    return "-" if v is None else f"{v * 100:.1f}%"


def db(v):
    return "-" if v is None else fmt(v)


REGION_COLUMNS = ["planar", "other", "mirror", "glossy", "rough", "refractive"]


def region_cell(r, name):
    f = r.get("regions", {}).get(name)
    if f is None or f["pixels"] == 0:
        return "-"
    if f["handled_pixels"] == 0:
        return "n/a"
    t = f["traceable"]
    claimed = [(c["false_hit_rate"], c["pixels"]) for c in (f["missing"], f["sky"]) if c["pixels"]]
    false_rate = sum(rate * n for rate, n in claimed) / sum(n for _, n in claimed) if claimed else None
    cell = f"{db(t['psnr_ideal'])} / {pct(t['correct_coverage'])} / {pct(false_rate)}"
    if t.get("noise_floor_psnr") is not None:
        cell += f" (floor {db(t['noise_floor_psnr'])})"
    return cell


def regions(paths, only_defaults=False):
    """Per run: technique x region, 'PSNR vs ideal / correct coverage / false hits (noise floor)'."""
    for path in paths:
        for run in load(path, need_regions=True)["runs"]:
            present = [n for n in REGION_COLUMNS
                       if any(r.get("regions", {}).get(n, {}).get("pixels", 0) for r in run["results"])]
            w, h = run["size"]
            inh = run.get("inherent", {})
            print(f"**{run['scene']} {w}x{h}**: inherent PSNR traceable {db(inh.get('traceable'))} dB, "
                  f"missing {db(inh.get('missing'))} dB, sky {db(inh.get('sky'))} dB"
                  + (f"; oracles {db(run['oracles']['psnr'])} dB, {pct(run['oracles']['within_1_255'])} "
                     f"within 1/255, {db(run['oracles']['psnr_off_edges'])} dB off edges"
                     if run.get("oracles", {}).get("pixels") else "") + "\n")
            print("| technique | " + " | ".join(present) + " |")
            print("|---|" + "---|" * len(present))
            for label, r in zip(labels_of(run), run["results"]):
                if only_defaults and (r.get("preset") or label != r["technique"]):
                    continue
                print(f"| {label} | " + " | ".join(region_cell(r, n) for n in present) + " |")
            print()


def summary(paths):
    """One row per (scene, size), one column per technique: median ms, traceable PSNR against the
    ideal over what the technique handles, correct coverage."""
    for path in paths:
        runs = load(path, need_regions=True)["runs"]
        names = []
        for run in runs:
            for r in run["results"]:
                if r["technique"] not in names:
                    names.append(r["technique"])
        print("| scene | size | " + " | ".join(names) + " |")
        print("|---|---|" + "---:|" * len(names))
        for run in runs:
            w, h = run["size"]
            cells = []
            for name in names:
                r = next((r for r in run["results"] if r["technique"] == name), None)
                if r is None:
                    cells.append("")
                    continue
                f = r["regions"]["planar" if name in ("ppr", "planar") else "all"]
                t = f["traceable"]
                cells.append(f"{fmt(r['time_ms']['median'], 3)} ms / {db(t['psnr_ideal'])} / {pct(t['correct_coverage'])}")
            print(f"| {run['scene']} | {w}x{h} | " + " | ".join(cells) + " |")
        print()


def equal_error(paths, baseline="linear-binary", slack=0.25):
    print("| scene | size | target PSNR traceable dB | technique | fastest variant at target | ms | speed-up vs "
          f"{baseline} |")
    print("|---|---|---:|---|---|---:|---:|")
    for path in paths:
        for run in load(path)["runs"]:
            base = [r for r in run["results"] if r["technique"] == baseline and not r.get("preset")]
            if not base:
                continue
            # The target: what the baseline reaches with its largest step budget.
            steps_key = baseline + ".linear_steps"
            target = max(base, key=lambda r: r["params"].get(steps_key, 0))["error"]["psnr_traceable"]
            def fastest(rs):
                ok = [r for r in rs if (r["error"]["psnr_traceable"] or float("-inf")) >= target - slack]
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
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if "--summary" in sys.argv:
        summary(args)
    elif "--regions" in sys.argv:
        regions(args, only_defaults="--defaults" in sys.argv)
    else:
        main(args)
        equal_error(args)
