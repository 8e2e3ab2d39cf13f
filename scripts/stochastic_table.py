#!/usr/bin/env python3
"""Markdown tables for docs/RESULTS.md's stochastic section, from scripts/stochastic_results.sh's
JSON: stages-*.json (each denoiser stage, per roughness band and class, with the pixels each
figure rests on), paths-*.json (instability and ghosting), bench JSON (time per pass).
  scripts/stochastic_table.py stages DIR | paths DIR | bench FILE.json..."""
import glob
import json
import os
import sys


def fmt(v, digits=2):
    return "-" if v is None else f"{v:.{digits}f}"


def short(label):
    """'stochastic spatial=true temporal=false bilateral=true' -> 'S . B'; others unchanged."""
    if not label.startswith("stochastic "):
        return label + " (16 rays)" if label == "hiz" else label
    on = {k: v == "true" for k, v in (kv.split("=") for kv in label.split()[1:])}
    return " ".join(n if on[k] else "." for k, n in (("spatial", "S"), ("temporal", "T"), ("bilateral", "B")))


def reflection_psnr(result, region):
    """From ssrlab's JSON, or the stripped copies in docs/results/stochastic."""
    r = result["regions"].get(region)
    if not r or not r["pixels"]:
        return None
    return r["traceable"]["psnr_reflection"] if "traceable" in r else r["psnr_reflection"]


def stages(directory):
    for path in sorted(glob.glob(os.path.join(directory, "stages-*.json"))):
        d = json.load(open(path))
        last = len(d["frames"]) - 1
        first_regions = d["frames"][0]["results"][0]["regions"]
        regions = [k for k in ("mirror", "glossy", "rough") if first_regions.get(k, {}).get("pixels")]
        bands = sorted((k for k in d["frames"][0]["results"][0]["regions"] if k.startswith("reflector:")),
                       key=lambda k: int(k.split(":")[1]))
        if len(bands) > 2:  # the ramp: one column per band (roughness (N-1)/10), then its classes
            regions = bands + regions
        names = [f"r {(int(k.split(':')[1]) - 1) / 10:.1f}" if k.startswith("reflector:") else k for k in regions]
        print(f"\n{d['scene']} ({d['width']}x{d['height']}, still camera): reflection PSNR (dB) on traceable "
              f"pixels, frame 0 -> frame {last}; flicker = mean excess change per frame\n")
        print("| stages | " + " | ".join(names) + " | flicker |")
        print("|---|" + "---|" * (len(regions) + 1))
        for i, s in enumerate(d["summary"]):
            first = d["frames"][0]["results"][i]
            end = d["frames"][last]["results"][i]
            cells = [f"{fmt(reflection_psnr(first, k), 1)} -> {fmt(reflection_psnr(end, k), 1)}" for k in regions]
            print(f"| {short(s['label'])} | " + " | ".join(cells) + f" | {fmt(s['instability']['mean'], 4)} |")
        # What each column's figure rests on (absent from the stripped copies in docs/results).
        counts = [first_regions[k].get("traceable", {}).get("pixels") for k in regions]
        if all(c is not None for c in counts):
            print("| traceable pixels (of all) | " + " | ".join(
                f"{c} ({first_regions[k]['pixels']})" for c, k in zip(counts, regions)) + " | |")


def paths(directory):
    files = sorted(glob.glob(os.path.join(directory, "paths-*.json")))
    runs = [json.load(open(path)) for path in files]
    # With `sequence --second-truth`: x truth without the truth's noise, and each path's first
    # pair's truth change with its noise part.
    second = any(d.get("second_truth") for d in runs)
    print("\n| scene:path | technique | PSNR (final) | flicker mean | flicker p95 | change x truth | " +
          ("x truth, no noise | " if second else "") + "disoccluded PSNR | elsewhere |")
    print("|---|---|---|---|---|---|---|---|" + ("---|" if second else ""))
    for d in runs:
        for s in d["summary"]:
            conv = [c for c in s["convergence"] if c is not None]
            mean = sum(conv) / len(conv) if conv else None
            g = s["ghosting"]
            ratio = s["instability"].get("change_ratio")  # absent before revision 2026-11-27 (third session)
            noise_free = f"{fmt(s['instability'].get('noise_free_change_ratio'))} | " if second else ""
            print(f"| {d['scene']}:{d['path']} | {s['label']} | {fmt(mean)} | {fmt(s['instability']['mean'], 4)} | "
                  f"{fmt(s['instability']['p95'], 4)} | {fmt(ratio)} | {noise_free}{fmt(g['disoccluded_psnr'])} | "
                  f"{fmt(g['elsewhere_psnr'])} |")
    noisy = [d for d in runs if d.get("truth_noise") and d["truth_noise"].get("first_pair_change_mean") is not None]
    if noisy:
        print("\n| scene:path | truth change, frames 0 to 1 | its noise's part | truth noise floor dB |")
        print("|---|---|---|---|")
        for d in noisy:
            n = d["truth_noise"]
            print(f"| {d['scene']}:{d['path']} | {fmt(n['first_pair_change_mean'], 4)} | "
                  f"{fmt(n['first_pair_noise_change_mean'], 4)} | {fmt(n['psnr'])} |")


def bench(files):
    skip = {"gbuffer", "lighting", "composite", "display"}
    rows, passes = [], []
    for f in files:
        d = json.load(open(f))
        for run in d["runs"]:
            for r in run["results"]:
                p = {x["name"]: x["ms"] for x in r["passes"] if x["name"] not in skip}
                passes += [n for n in p if n not in passes]
                rows.append((run["scene"], "x".join(map(str, run["size"])), r.get("label", r["technique"]),
                             r["time_ms"]["median"], r["error"]["psnr"], p))
    print("\n| scene | size | variant | ms | PSNR dB | " + " | ".join(passes) + " |")
    print("|---|---|---|---|---|" + "---|" * len(passes))
    for scene, size, label, ms, psnr, p in rows:
        print(f"| {scene} | {size} | {label} | {ms:.3f} | {psnr:.2f} | " +
              " | ".join(fmt(p.get(n), 3) for n in passes) + " |")


if __name__ == "__main__":
    what = sys.argv[1]
    {"stages": lambda: stages(sys.argv[2]), "paths": lambda: paths(sys.argv[2]),
     "bench": lambda: bench(sys.argv[2:])}[what]()
