#!/usr/bin/env python3
"""Markdown tables of docs/RESULTS.md's "Speed" section from docs/results/speed-<device>.json
(the parts of scripts/speed_results.sh merged into one file), or from the run's output folder,
which --write merges into that file first:
    scripts/speed_table.py docs/results/speed-h200.json
    scripts/speed_table.py OUTDIR --write docs/results/speed-h200.json
"""
import json
import os
import sys

PARTS = ("equal", "compact", "pedestal", "ppr", "ppr16", "scaling")


def merged(folder):
    parts = {n: json.load(open(os.path.join(folder, n + ".json"))) for n in PARTS}
    first = parts["equal"]
    return {"device": first["device"], "revision": first["revision"],
            "command": "scripts/speed_results.sh OUT " + " ".join(p for p in PARTS if p != "ppr16") +
                       " (through .gpu/run on the GPU machine)",
            "parts": parts}


def ms(r):
    return r["time_ms"]["median"]


def passes(r, skip=("gbuffer", "lighting", "composite", "display", "history", "motion")):
    return ", ".join(f"{p['name']} {p['ms']:.3f}" for p in r["passes"] if p["name"] not in skip)


def planar(r):
    v = r["regions"].get("planar", {}).get("traceable", {}).get("psnr_ideal")
    return "-" if v is None else f"{v:.2f}"


def tele(r):
    t = r.get("telemetry")
    if not t:
        return "- | - | - | -"
    i = t["iterations"]
    idle = "-" if t["idle_lanes"] is None else f"{100 * t['idle_lanes']:.0f}%"
    return f"{i['mean']:.1f} | {i['p95']} | {i['max']} | {idle}"


def size(run):
    return f"{run['size'][0]}x{run['size'][1]}"


def equal_table(part):
    print("| scene | size | variant | ms | trace dB | planar dB | iter mean | p95 | max | idle lanes |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for run in part["runs"]:
        for r in run["results"]:
            print(f"| {run['scene']} | {size(run)} | {r['label']} | {ms(r):.3f} | {r['error']['psnr_traceable']:.2f} "
                  f"| {planar(r)} | {tele(r)} |")


def equal_error(part):
    """Per scene and size: linear-binary's 500-step figure, then the fastest variant of every
    other technique reaching it."""
    print("| scene | size | linear-binary/500 trace dB | ms | fastest hiz at >= that | ms | speed-up | fastest dda at >= that | ms | speed-up |")
    print("|---|---|---:|---:|---|---:|---:|---|---:|---:|")
    for run in part["runs"]:
        res = run["results"]
        base = next(r for r in res if r["label"] == "linear-binary linear_steps=500")
        goal = base["error"]["psnr_traceable"]
        cells = []
        for tech in ("hiz", "dda"):
            ok = [r for r in res if r["technique"] == tech and r["error"]["psnr_traceable"] >= goal]
            if ok:
                best = min(ok, key=ms)
                cells.append(f"{best['label']} ({best['error']['psnr_traceable']:.2f} dB) | {ms(best):.3f} | {ms(base) / ms(best):.2f}x")
            else:
                cells.append("none reaches it | - | -")
        print(f"| {run['scene']} | {size(run)} | {goal:.2f} | {ms(base):.3f} | " + " | ".join(cells) + " |")


def compact_table(part):
    print("| scene | tracer | full-screen ms | ray list ms (classify + trace) | ratio |")
    print("|---|---|---:|---:|---:|")
    for run in part["runs"]:
        res = run["results"]
        for tech in ("linear-binary", "hiz", "dda", "linear"):
            full = next(r for r in res if r["technique"] == tech and "compact=false" in r["label"])
            lst = next(r for r in res if r["technique"] == tech and "compact=true" in r["label"])
            print(f"| {run['scene']} {size(run)} | {tech} | {ms(full):.3f} | {ms(lst):.3f} ({passes(lst)}) | {ms(lst) / ms(full):.2f} |")


def ppr_table(ppr, ppr16):
    print("| scene | size | variant | ms | passes | floor ms | x floor | trace dB | planar dB |")
    print("|---|---|---|---:|---|---:|---:|---:|---:|")
    for part in (ppr, ppr16):
        for run in part["runs"]:
            for r in run["results"]:
                print(f"| {run['scene']} | {size(run)} | {r['label']} | {ms(r):.3f} | {passes(r)} | {r['floor_ms']:.4f} "
                      f"| {ms(r) / r['floor_ms']:.2f} | {r['error']['psnr_traceable']:.2f} | {planar(r)} |")


def scaling_table(part):
    sizes = [size(run) for run in part["runs"]]
    techs = [r["label"] for r in part["runs"][0]["results"]]
    print("| technique | " + " | ".join(f"{s} ms (ns/pixel)" for s in sizes) + f" | {sizes[-1]} / {sizes[0]} per pixel |")
    print("|---|" + "---:|" * (len(sizes) + 1))
    for t in techs:
        cells, per = [], []
        for run in part["runs"]:
            r = next(x for x in run["results"] if x["label"] == t)
            px = run["size"][0] * run["size"][1]
            per.append(ms(r) * 1e6 / px)
            cells.append(f"{ms(r):.3f} ({per[-1]:.3f})")
        print(f"| {t} | " + " | ".join(cells) + f" | {per[-1] / per[0]:.2f} |")


def pass_table(part):
    print("| scene | variant | ms | trace dB | iter mean | p95 | max | idle lanes | passes |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---|")
    for run in part["runs"]:
        for r in run["results"]:
            print(f"| {run['scene']} {size(run)} | {r['label']} | {ms(r):.3f} | {r['error']['psnr_traceable']:.2f} | {tele(r)} | {passes(r)} |")


def main():
    src = sys.argv[1]
    d = merged(src) if os.path.isdir(src) else json.load(open(src))
    if len(sys.argv) == 4 and sys.argv[2] == "--write":
        json.dump(d, open(sys.argv[3], "w"), indent=1)
    p = d["parts"]
    dev = d["device"]
    print(f"Device: {dev['renderer']}, {dev['version']}, clock `{dev['clock']}`, revision `{d['revision']}`\n")
    for title, fn in (("Equal error", lambda: equal_error(p["equal"])),
                      ("Every variant of the equal-error run", lambda: equal_table(p["equal"])),
                      ("Ray list against full-screen dispatch", lambda: compact_table(p["compact"])),
                      ("hiz and stochastic per pass", lambda: pass_table(p["pedestal"])),
                      ("PPR against its floor", lambda: ppr_table(p["ppr"], p["ppr16"])),
                      ("Time per pixel from 1080p to 8K (gallery)", lambda: scaling_table(p["scaling"]))):
        print(f"#### {title}\n")
        fn()
        print()


if __name__ == "__main__":
    main()
