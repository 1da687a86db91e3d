#!/usr/bin/env python3
"""Writes eight disk meshes unlike the bench's, each a test of one thing a remesher can get
wrong (docs/bench_log.md, "Synthetic disks"):

    python3 docs/synthetic_disks.py DIR

- box.off: five faces of a cube (an open box), 90-degree creases and corners;
- graded.off: a wavy disk meshed 50 times finer at its centre than at its rim;
- bowl.off: most of a hemisphere, a jittered grid;
- ellipse.off: a 20:1 strip that bends and twists;
- ripples.off: a square with ripples a tenth of its size;
- tent.off: a square with a narrow peak, 0.4 high and 0.06 wide;
- fan.off: a dome fanned from its apex, 200 slivers around one vertex of valence 200;
- ribbon.off: a 50:1 strip, a few edge lengths wide at 500 vertices.

Six more, as other tools export surfaces (bench_log.md, "Synthetic disks", the last table):

- hemisphere.off: a UV sphere's upper half, a fan of 64 around its pole, its rim a 64-gon;
- saddle.off: a saddle over a polar grid, a fan of 48 at its centre, its rim a 48-gon that
  rises and falls (coarser than the samples of a result at 500 vertices and more);
- halfcylinder.off: half a cylinder as CAD exports it, 3 rows of 300 slivers (1:127);
- lplate.off: an L-shaped plate, a corner of 270 degrees and five of 90;
- crease.off: a terrain folded along a straight crease, its grid jittered;
- spiral.off: a strip wound one and a half turns, 65 times as long as wide.

The square grids alternate their diagonals (valences 4 and 8), and most are jittered too:
every vertex starts irregular.
"""
import math
import os
import random
import sys


def write_off(path, points, triangles):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(points)} {len(triangles)} 0\n")
        for p in points:
            f.write("%r %r %r\n" % tuple(p))
        for t in triangles:
            f.write("3 %d %d %d\n" % tuple(t))
    print(f"{path}: {len(points)} vertices, {len(triangles)} triangles")


def grid(nu, nv, surface, jitter=0.3, seed=1):
    """An nu x nv grid of (u, v) in [0, 1]^2 on `surface`, inside points jittered by `jitter`
    of a cell, each square split along alternating diagonals."""
    rng = random.Random(seed)
    points = []
    for j in range(nv + 1):
        for i in range(nu + 1):
            u, v = i / nu, j / nv
            if 0 < i < nu and 0 < j < nv:
                u += rng.uniform(-jitter, jitter) / nu
                v += rng.uniform(-jitter, jitter) / nv
            points.append(surface(u, v))
    triangles = []
    for j in range(nv):
        for i in range(nu):
            a = j * (nu + 1) + i
            b, c, d = a + 1, a + nu + 2, a + nu + 1
            triangles += [(a, b, c), (a, c, d)] if (i + j) % 2 else [(a, b, d), (b, c, d)]
    return points, triangles


def box(n=24):
    """Five faces of the unit cube, each an n x n grid, welded along the edges, facing out."""
    index, points, triangles = {}, [], []

    def vertex(p):
        key = tuple(round(c * n) for c in p)
        if key not in index:
            index[key] = len(points)
            points.append([k / n for k in key])
        return index[key]

    def face(origin, du, dv):
        at = lambda a, b: [origin[k] + (a * du[k] + b * dv[k]) / n for k in range(3)]
        for i in range(n):
            for j in range(n):
                a, b, c, d = (vertex(at(i, j)), vertex(at(i + 1, j)), vertex(at(i + 1, j + 1)),
                              vertex(at(i, j + 1)))
                triangles.extend([(a, b, c), (a, c, d)])

    face((0, 0, 0), (0, 1, 0), (1, 0, 0))   # bottom
    face((0, 0, 0), (1, 0, 0), (0, 0, 1))   # y = 0
    face((1, 0, 0), (0, 1, 0), (0, 0, 1))   # x = 1
    face((1, 1, 0), (-1, 0, 0), (0, 0, 1))  # y = 1
    face((0, 1, 0), (0, -1, 0), (0, 0, 1))  # x = 0
    return points, triangles


def graded(rings=40):
    """Rings of radius (k / rings)^2.5 around a centre vertex, each as many vertices as keep its
    triangles near equilateral: fine at the centre, coarse at the rim."""
    height = lambda x, y: 0.15 * math.sin(3 * x) * math.cos(2 * y) + 0.1 * x * x
    points, loops = [[0.0, 0.0, height(0, 0)]], [[0]]
    for k in range(1, rings + 1):
        r = (k / rings) ** 2.5
        spacing = (k / rings) ** 1.5 * 2.5 / rings
        m = max(6, int(2 * math.pi * r / spacing))
        loop = []
        for j in range(m):
            a = 2 * math.pi * j / m + 0.3 * k
            x, y = r * math.cos(a), r * math.sin(a)
            loop.append(len(points))
            points.append([x, y, height(x, y)])
        loops.append(loop)
    angle = lambda i: math.atan2(points[i][1], points[i][0]) % (2 * math.pi)
    triangles = []
    for inner, outer in zip(loops, loops[1:]):
        if len(inner) == 1:
            triangles += [(inner[0], outer[j], outer[(j + 1) % len(outer)]) for j in range(len(outer))]
            continue
        # Both loops walked together by angle from the inner loop's first vertex.
        start = angle(inner[0])
        turn = lambda i: (angle(i) - start) % (2 * math.pi)
        o0 = min(range(len(outer)), key=lambda j: turn(outer[j]))
        i = j = 0
        while i < len(inner) or j < len(outer):
            a, b = inner[i % len(inner)], outer[(o0 + j) % len(outer)]
            next_a, next_b = inner[(i + 1) % len(inner)], outer[(o0 + j + 1) % len(outer)]
            ta = turn(next_a) if i + 1 < len(inner) else 2 * math.pi
            tb = turn(next_b) if j + 1 < len(outer) else 2 * math.pi + turn(outer[o0])
            if j >= len(outer) or (i < len(inner) and ta <= tb):
                triangles.append((a, next_a, b))
                i += 1
            else:
                triangles.append((a, next_b, b))
                j += 1
    area = lambda t: ((points[t[1]][0] - points[t[0]][0]) * (points[t[2]][1] - points[t[0]][1]) -
                      (points[t[2]][0] - points[t[0]][0]) * (points[t[1]][1] - points[t[0]][1]))
    return points, [t if area(t) > 0 else (t[0], t[2], t[1]) for t in triangles]


def bowl(u, v):
    x, y = 2 * u - 1, 2 * v - 1  # the square onto the unit disk, then up onto the sphere
    x, y = x * math.sqrt(1 - y * y / 2), y * math.sqrt(1 - x * x / 2)
    return [x, y, -math.sqrt(max(0.0, 1 - 0.9 * min(x * x + y * y, 1.0)))]


def tent(u, v):
    r = math.hypot(u - 0.5, v - 0.5)
    return [u, v, 0.4 * math.exp(-(r / 0.06) ** 2)]


def polar(rings, around, surface):
    """`rings` rings of `around` vertices at radius k / rings around a centre vertex, on
    surface(r, angle): the centre a fan of `around` triangles, the rim an `around`-gon."""
    points = [surface(0.0, 0.0)]
    for k in range(1, rings + 1):
        points += [surface(k / rings, 2 * math.pi * j / around) for j in range(around)]
    ring = lambda k, j: 1 + (k - 1) * around + j % around
    triangles = [(0, ring(1, j), ring(1, j + 1)) for j in range(around)]
    for k in range(1, rings):
        for j in range(around):
            a, b, c, d = ring(k, j), ring(k, j + 1), ring(k + 1, j + 1), ring(k + 1, j)
            triangles += [(a, d, c), (a, c, b)]
    return points, triangles


def hemisphere(r, a):
    t = r * math.pi / 2
    return [math.sin(t) * math.cos(a), math.sin(t) * math.sin(a), math.cos(t)]


def saddle(r, a):
    x, y = r * math.cos(a), r * math.sin(a)
    return [x, y, 0.5 * (x * x - y * y)]


def lplate(n=60):
    """An n x n grid on the unit square less its top right quarter, gently bumped."""
    points, triangles = grid(n, n, lambda u, v: [u, v, 0.05 * math.sin(3 * u) * math.sin(3 * v)], jitter=0)
    keep = [t for t in triangles
            if not all(points[i][0] >= 0.5 - 1e-9 and points[i][1] >= 0.5 - 1e-9 for i in t)]
    used = sorted({i for t in keep for i in t})
    index = {old: new for new, old in enumerate(used)}
    return [points[i] for i in used], [tuple(index[i] for i in t) for t in keep]


def spiral(u, v):
    radius = 1 + 1.5 * u + 0.3 * v
    return [radius * math.cos(3 * math.pi * u), radius * math.sin(3 * math.pi * u), 0.1 * math.sin(10 * u)]


def fan(n=200):
    """A low dome over the unit disk: its apex joined to each of n rim vertices."""
    rim = [[math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n), 0.0] for i in range(n)]
    return [[0.0, 0.0, 0.5]] + rim, [(0, 1 + i, 1 + (i + 1) % n) for i in range(n)]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    write_off(os.path.join(out, "box.off"), *box())
    write_off(os.path.join(out, "graded.off"), *graded())
    write_off(os.path.join(out, "bowl.off"), *grid(60, 60, bowl))
    write_off(os.path.join(out, "ellipse.off"),
              *grid(200, 12, lambda u, v: [20 * u, v + 0.3 * math.sin(6 * u), 0.5 * math.sin(3 * u) * v]))
    write_off(os.path.join(out, "ripples.off"),
              *grid(90, 90, lambda u, v: [u, v, 0.03 * math.sin(20 * u) * math.sin(17 * v)]))
    write_off(os.path.join(out, "tent.off"), *grid(90, 90, tent))
    write_off(os.path.join(out, "fan.off"), *fan())
    write_off(os.path.join(out, "ribbon.off"),
              *grid(100, 2, lambda u, v: [50 * u, v, 0.1 * math.sin(15 * u)]))
    write_off(os.path.join(out, "hemisphere.off"), *polar(24, 64, hemisphere))
    write_off(os.path.join(out, "saddle.off"), *polar(30, 48, saddle))
    write_off(os.path.join(out, "halfcylinder.off"),
              *grid(300, 3, lambda u, v: [math.cos(math.pi * u), math.sin(math.pi * u), 4 * v], jitter=0))
    write_off(os.path.join(out, "lplate.off"), *lplate())
    write_off(os.path.join(out, "crease.off"),
              *grid(70, 70, lambda u, v: [u, v, 0.3 * abs(u - 0.5) + 0.05 * math.sin(8 * v)], jitter=0.15, seed=3))
    write_off(os.path.join(out, "spiral.off"), *grid(300, 6, spiral, jitter=0))


if __name__ == "__main__":
    main()
