#!/usr/bin/env python3
"""Clips a closed triangle mesh (OFF) in half, for disks that are in neither of the bench's
sets (docs/bench_log.md, "Disks from outside the bench").

    python3 docs/clip_half.py IN.off OUT.off [AXIS [FRACTION]]

The plane is z = the middle of the mesh's z range (AXIS 0 or 1: x or y instead; FRACTION 0.3:
at 30% of the range from its low end instead of 50%). Triangles that cross it are split along it
(vertices within a fifth of the mean edge length of it are first moved onto it, so that no
sliver is made), the part below is kept, and of that its largest edge-connected piece. Exits
with 1, writing nothing, unless that piece is a disk (one border loop, Euler characteristic 1).
"""
import math
import sys
from collections import defaultdict


def read_off(path):
    words = open(path).read().split()
    if not words or words[0] != "OFF":
        sys.exit(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    at = 4
    points = [[float(w) for w in words[at + 3 * i:at + 3 * i + 3]] for i in range(nv)]
    at += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(words[at])
        face = [int(w) for w in words[at + 1:at + 1 + n]]
        faces += [[face[0], face[k], face[k + 1]] for k in range(1, n - 1)]
        at += 1 + n
    return points, faces


def clip_below(points, faces, axis=2, fraction=0.5):
    lo, hi = min(p[axis] for p in points), max(p[axis] for p in points)
    level = lo + fraction * (hi - lo)
    mean_edge = sum(math.dist(points[f[0]], points[f[1]]) for f in faces) / len(faces)
    points = [list(p) for p in points]
    for p in points:
        if abs(p[axis] - level) < 0.2 * mean_edge:
            p[axis] = level
    side = [p[axis] - level for p in points]
    crossing = {}  # edge -> index of the point where the plane cuts it

    def cut(a, b):
        key = (min(a, b), max(a, b))
        if key not in crossing:
            t = side[a] / (side[a] - side[b])
            points.append([points[a][q] + t * (points[b][q] - points[a][q]) for q in range(3)])
            crossing[key] = len(points) - 1
        return crossing[key]

    kept = []
    for f in faces:
        if all(side[v] <= 0 for v in f):
            if any(side[v] < 0 for v in f):
                kept.append(f)
            continue
        if not any(side[v] < 0 for v in f):
            continue
        polygon = []
        for k in range(3):
            a, b = f[k], f[(k + 1) % 3]
            if side[a] <= 0:
                polygon.append(a)
            if side[a] * side[b] < 0:
                polygon.append(cut(a, b))
        kept += [[polygon[0], polygon[k], polygon[k + 1]] for k in range(1, len(polygon) - 1)]
    return points, kept


def largest_piece(faces):
    parent = list(range(len(faces)))

    def root(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    by_edge = defaultdict(list)
    for i, f in enumerate(faces):
        for k in range(3):
            by_edge[tuple(sorted((f[k], f[(k + 1) % 3])))].append(i)
    for sharing in by_edge.values():
        for j in sharing[1:]:
            parent[root(j)] = root(sharing[0])
    size = defaultdict(int)
    for i in range(len(faces)):
        size[root(i)] += 1
    biggest = max(size, key=size.get)
    return [f for i, f in enumerate(faces) if root(i) == biggest]


def disk_problem(faces):
    uses = defaultdict(int)
    for f in faces:
        for k in range(3):
            uses[tuple(sorted((f[k], f[(k + 1) % 3])))] += 1
    if any(n > 2 for n in uses.values()):
        return "an edge has more than two triangles"
    border = defaultdict(list)
    for (a, b), n in uses.items():
        if n == 1:
            border[a].append(b)
            border[b].append(a)
    if any(len(ends) != 2 for ends in border.values()):
        return "a border vertex is on more than one border loop"
    seen, loops = set(), 0
    for start in border:
        if start in seen:
            continue
        loops += 1
        stack = [start]
        while stack:
            v = stack.pop()
            if v not in seen:
                seen.add(v)
                stack += border[v]
    vertices = len({v for f in faces for v in f})
    euler = vertices - len(uses) + len(faces)
    if loops != 1 or euler != 1:
        return f"not a disk ({loops} border loops, Euler characteristic {euler})"
    return None


def main():
    if len(sys.argv) not in (3, 4, 5) or (len(sys.argv) >= 4 and sys.argv[3] not in ("0", "1", "2")):
        sys.exit(__doc__)
    source, target = sys.argv[1], sys.argv[2]
    axis = int(sys.argv[3]) if len(sys.argv) >= 4 else 2
    fraction = float(sys.argv[4]) if len(sys.argv) == 5 else 0.5
    if not 0 < fraction < 1:
        sys.exit(f"FRACTION must be between 0 and 1, not {sys.argv[4]}")
    points, faces = read_off(source)
    points, faces = clip_below(points, faces, axis, fraction)
    faces = largest_piece(faces)
    problem = disk_problem(faces)
    if problem:
        sys.exit(f"{source}: its lower half is {problem}")
    used = sorted({v for f in faces for v in f})
    index = {v: i for i, v in enumerate(used)}
    with open(target, "w") as out:
        out.write(f"OFF\n{len(used)} {len(faces)} 0\n")
        out.writelines("%r %r %r\n" % tuple(points[v]) for v in used)
        out.writelines("3 %d %d %d\n" % tuple(index[v] for v in f) for f in faces)
    print(f"{target}: {len(used)} vertices, {len(faces)} triangles, one disk")


if __name__ == "__main__":
    main()
