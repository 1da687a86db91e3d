#!/usr/bin/env python3
"""Adds scanner-like noise to a triangle mesh (OFF), for disks that are in neither of the
bench's sets (docs/bench_log.md, "Noisy disks"):

    python3 docs/add_noise.py IN.off OUT.off SIGMA [SEED]

Each vertex moves along its normal (the sum of its triangles' area-weighted normals) by a
Gaussian amount whose standard deviation is SIGMA times the bounding-box diagonal (0.001:
0.1%). The connectivity stays as it is. SEED (default 1) makes the noise repeatable.
"""
import math
import random
import sys

from clip_half import read_off
from synthetic_disks import write_off


def vertex_normals(points, faces):
    normals = [[0.0, 0.0, 0.0] for _ in points]
    for f in faces:
        a, b, c = (points[v] for v in f)
        u = [b[k] - a[k] for k in range(3)]
        w = [c[k] - a[k] for k in range(3)]
        n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
        for v in f:
            for k in range(3):
                normals[v][k] += n[k]
    for n in normals:
        length = math.sqrt(sum(x * x for x in n)) or 1.0
        for k in range(3):
            n[k] /= length
    return normals


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    source, target, sigma = sys.argv[1], sys.argv[2], float(sys.argv[3])
    rng = random.Random(int(sys.argv[4]) if len(sys.argv) == 5 else 1)
    points, faces = read_off(source)
    diagonal = math.dist([min(p[k] for p in points) for k in range(3)],
                         [max(p[k] for p in points) for k in range(3)])
    noisy = []
    for p, n in zip(points, vertex_normals(points, faces)):
        offset = rng.gauss(0.0, sigma * diagonal)
        noisy.append([p[k] + offset * n[k] for k in range(3)])
    write_off(target, noisy, faces)


if __name__ == "__main__":
    main()
