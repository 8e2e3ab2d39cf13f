#!/usr/bin/env python3
"""Markdown tables from `ssrlab bench --json` files, for docs/RESULTS.md.

    scripts/bench_table.py bench.json [more.json ...]

One table per (scene, size): technique, median/min/max ms, time over the floor pass, PSNR,
PSNR traceable, coverage, non-finite count. Device, clock and revision come from each file.
"""
import json
import sys


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
            for r in run["results"]:
                t = r["time_ms"]
                e = r["error"]
                print(f"| {r.get('label', r['technique'])} | {fmt(t['median'], 3)} | {fmt(t['min'], 3)} "
                      f"| {fmt(t['max'], 3)} | {fmt(r['time_over_floor'], 1)} | {fmt(e['psnr'])} "
                      f"| {fmt(e['psnr_traceable'])} | {e['coverage'] * 100:.1f}% | {r['nonfinite']} |")
            print()


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: bench_table.py bench.json [more.json ...]")
    main(sys.argv[1:])
