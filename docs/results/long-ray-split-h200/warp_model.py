#!/usr/bin/env python3
"""Lockstep-warp model of a trace split at C cell visits (docs/RESULTS.md, "Long rays in a pass
of their own").

Input: one file per image, two int32 (width, height) then width*height float32 cell visits per
pixel (0: no ray), e.g. `ssrlab render --technique stochastic --size 1080p --view iterations`
with display_views.glsl writing vec3(float(telemetry_iterations(word))) instead of the heat map,
the EXR's red channel dumped. A warp is 32 consecutive invocations of an 8x8 group (8x4
pixels) and costs its busiest lane's visits; the split's first pass costs min(that, C) per warp,
the second the visits left beyond C, packed 32 rays to a warp in tile order."""
import sys

import numpy as np

for path in sys.argv[1:]:
    w, h = np.fromfile(path, dtype=np.int32, count=2)
    visits = np.fromfile(path, dtype=np.float32, offset=8).reshape(h, w)
    H, W = -(-h // 8) * 8, -(-w // 8) * 8
    padded = np.zeros((H, W))
    padded[:h, :w] = visits
    warps = padded.reshape(H // 4, 4, W // 8, 8).transpose(0, 2, 1, 3).reshape(-1, 32)
    warps = warps[warps.max(1) > 0]
    base = warps.max(1).sum()
    print(f"{path}: {int((padded > 0).sum())} rays, idle lanes {1 - warps.sum() / (32 * base):.3f}")
    tiles = padded.reshape(H // 8, 8, W // 8, 8).transpose(0, 2, 1, 3).reshape(-1)
    for c in (16, 24, 32, 48, 64, 96):
        left = tiles[tiles > c] - c
        left = np.concatenate([left, np.zeros((-len(left)) % 32)]).reshape(-1, 32)
        cost = np.minimum(warps.max(1), c).sum() + (left.max(1).sum() if left.size else 0)
        print(f"  split at {c}: {cost / base:.3f}x the warp-visits of one pass")
