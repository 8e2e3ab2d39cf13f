#!/usr/bin/env python3
"""Markdown tables of `ssrlab sequence` JSON files (docs/RESULTS.md, "Time").

usage: sequence_table.py [--regions] FILE.json...
One table per file: per technique the mean PSNR over truth frames, flicker (mean and p95 of the
excess change beyond the truth's, and the technique's change over the truth's: "x truth"; with
`sequence --second-truth` also over the truth's change without its noise: "x truth, no noise")
and ghosting (PSNR on recently disoccluded pixels vs elsewhere).
--regions: the flicker mean per region instead (the summary's instability.regions), one column
per region that holds pixels in the file.
"""
import json
import math
import sys

from bench_table import REGION_COLUMNS  # the classes' column order, declared once


def fmt(v, f):
    return "–" if v is None or (isinstance(v, float) and not math.isfinite(v)) else f % v


def header(r):
    cuts = [f["index"] for f in r["frames"] if f["cut"]]
    return (f"**{r['scene']} / {r['path']}**: {len(r['frames'])} frames at {r['fps']:g} fps, "
            f"{r['width']}x{r['height']}, truth every {r['truth_every']}"
            + (f", cut at frame {', '.join(map(str, cuts))}" if cuts else "")
            + f" ({r['device']['renderer']}, {r['revision']})\n")


def summary_table(r):
    second = r.get("second_truth", False)  # sequence --second-truth: x truth without the truth's noise too
    print("| technique | mean PSNR | flicker mean | flicker p95 | x truth | " + ("x truth, no noise | " if second else "")
          + "disoccluded PSNR | elsewhere PSNR | moving reflections PSNR |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|" + ("---:|" if second else ""))
    for s in r["summary"]:
        conv = [p for p in s["convergence"] if p is not None]
        mean = sum(conv) / len(conv) if conv else None
        g, i = s["ghosting"], s["instability"]
        print(f"| {s['label']} | {fmt(mean, '%.2f')} | {fmt(i['mean'], '%.4f')} | {fmt(i['p95'], '%.4f')} | "
              f"{fmt(i.get('change_ratio'), '%.2f')} | "
              + (f"{fmt(i.get('noise_free_change_ratio'), '%.2f')} | " if second else "") +
              f"{fmt(g['disoccluded_psnr'], '%.2f')} | {fmt(g['elsewhere_psnr'], '%.2f')} | "
              f"{fmt(g.get('moving_psnr'), '%.2f')} |")  # runs before it have none


def region_table(r):
    have = [k for k in ["all"] + REGION_COLUMNS  # per-reflector regions left out
            if any((s["instability"].get("regions", {}).get(k) or {}).get("pixels") for s in r["summary"])]
    if not have:
        sys.exit(f"{r['scene']} / {r['path']}: no per-region flicker in this file (stripped JSON?)")
    print("| technique | " + " | ".join(have) + " |")
    print("|---|" + "---:|" * len(have))
    for s in r["summary"]:
        reg = s["instability"].get("regions", {})
        print(f"| {s['label']} | " + " | ".join(fmt((reg.get(k) or {}).get("mean"), "%.4f") for k in have) + " |")


args = sys.argv[1:]
regions = "--regions" in args
for name in [a for a in args if a != "--regions"]:
    r = json.load(open(name))
    print(header(r))
    (region_table if regions else summary_table)(r)
    print()
