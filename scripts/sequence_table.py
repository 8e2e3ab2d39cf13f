#!/usr/bin/env python3
"""Markdown tables of `ssrlab sequence` JSON files (docs/RESULTS.md, "Time").

usage: sequence_table.py FILE.json...
One table per file: per technique the mean PSNR over truth frames, flicker (mean and p95 of the
excess change beyond the truth's) and ghosting (PSNR on recently disoccluded pixels vs elsewhere).
"""
import json
import math
import sys


def fmt(v, f):
    return "–" if v is None or (isinstance(v, float) and not math.isfinite(v)) else f % v


for name in sys.argv[1:]:
    r = json.load(open(name))
    cuts = [f["index"] for f in r["frames"] if f["cut"]]
    print(f"**{r['scene']} / {r['path']}**: {len(r['frames'])} frames at {r['fps']:g} fps, "
          f"{r['width']}x{r['height']}, truth every {r['truth_every']}"
          + (f", cut at frame {', '.join(map(str, cuts))}" if cuts else "")
          + f" ({r['device']['renderer']}, {r['revision']})\n")
    print("| technique | mean PSNR | flicker mean | flicker p95 | disoccluded PSNR | elsewhere PSNR |")
    print("|---|---:|---:|---:|---:|---:|")
    for s in r["summary"]:
        conv = [p for p in s["convergence"] if p is not None]
        mean = sum(conv) / len(conv) if conv else None
        g, i = s["ghosting"], s["instability"]
        print(f"| {s['label']} | {fmt(mean, '%.2f')} | {fmt(i['mean'], '%.4f')} | {fmt(i['p95'], '%.4f')} | "
              f"{fmt(g['disoccluded_psnr'], '%.2f')} | {fmt(g['elsewhere_psnr'], '%.2f')} |")
    print()
