#!/usr/bin/python3
"""Writes the closed triangle meshes that tests and shipped scenes use (no downloads).

Every round shape is a profile polygon in the (r, z) half-plane revolved in n sectors: a sphere
(a half circle from pole to pole), a torus (a circle), a cylinder (a rectangle on the axis) and a
cup (a thick-walled cylinder open at the top, with a bottom). The box obstacle is the one of
Kleefsman et al. (2005): 0.161 x 0.403 x 0.161 m, from the origin. Lengths are in metres.

    scripts/make_meshes.py --out DIR [--shapes sphere,torus,cylinder,cup,obstacle]
                           [--formats stl,stl-ascii,obj,ply] [--sectors N]

writes DIR/<shape>.stl (binary), <shape>_ascii.stl, <shape>.obj, <shape>.ply as asked. The
triangles face outward (counter-clockwise seen from outside).
"""
import argparse
import math
import os
import struct

import numpy as np

# Each shape: (profile points (r, z), whether the profile is a closed loop off the axis) given
# the number of sectors; an open profile starts and ends on the axis (r = 0).


def sphere_profile(sectors, radius=0.1):
    rings = sectors // 2
    a = np.linspace(0, math.pi, rings + 1)
    profile = np.stack([radius * np.sin(a), -radius * np.cos(a)], axis=1)
    profile[[0, -1], 0] = 0  # the poles on the axis exactly
    return profile, False


def torus_profile(sectors, major=0.1, minor=0.04):
    a = np.linspace(0, 2 * math.pi, sectors // 2, endpoint=False)
    return np.stack([major + minor * np.cos(a), minor * np.sin(a)], axis=1), True


def cylinder_profile(sectors, radius=0.05, height=0.1):
    return np.array([[0, 0], [radius, 0], [radius, height], [0, height]], float), False


def cup_profile(sectors, outer=0.04, inner=0.035, height=0.1, bottom=0.005):
    """A cup from its bottom's centre, round its outside, over its rim, down its inside."""
    points = [[0, 0], [outer, 0], [outer, height], [inner, height], [inner, bottom], [0, bottom]]
    return np.array(points, float), False


PROFILES = {"sphere": sphere_profile, "torus": torus_profile, "cylinder": cylinder_profile,
            "cup": cup_profile}


def revolve(profile, closed, sectors):
    """Vertices and triangles of the profile revolved about z in `sectors` sectors; points on
    the axis become single vertices."""
    angles = 2 * math.pi * np.arange(sectors) / sectors
    vertices, index = [], {}

    def vertex(j, s):
        r, z = profile[j]
        key = (j, 0) if r == 0 else (j, s % sectors)
        if key not in index:
            index[key] = len(vertices)
            vertices.append((r * math.cos(angles[s % sectors]), r * math.sin(angles[s % sectors]), z))
        return index[key]

    triangles = []
    count = len(profile) if closed else len(profile) - 1
    for j in range(count):
        k = (j + 1) % len(profile)
        for s in range(sectors):
            a, b, c, d = vertex(j, s), vertex(j, s + 1), vertex(k, s + 1), vertex(k, s)
            for t in ((a, b, c), (a, c, d)):
                if len(set(t)) == 3:
                    triangles.append(t)
    return orient(np.array(vertices), np.array(triangles))


def box(size=(0.161, 0.403, 0.161)):
    corners = np.array([[i & 1, i >> 1 & 1, i >> 2 & 1] for i in range(8)], float) * size
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    triangles = [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]
    return orient(corners, np.array(triangles))


def orient(vertices, triangles):
    """Turns every triangle over when the enclosed volume comes out negative (facing in)."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    if np.einsum("ij,ij->i", a, np.cross(b, c)).sum() < 0:
        triangles = triangles[:, [0, 2, 1]]
    return vertices, triangles


def normals(vertices, triangles):
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    n = np.cross(b - a, c - a)
    return n / np.linalg.norm(n, axis=1)[:, None]


def write_stl(path, vertices, triangles):
    with open(path, "wb") as f:
        f.write(b"numerics make_meshes.py".ljust(80, b" "))
        f.write(struct.pack("<I", len(triangles)))
        for n, t in zip(normals(vertices, triangles), triangles):
            f.write(struct.pack("<12fH", *n, *vertices[t[0]], *vertices[t[1]], *vertices[t[2]], 0))


def write_stl_ascii(path, vertices, triangles):
    with open(path, "w") as f:
        f.write("solid numerics\n")
        for n, t in zip(normals(vertices, triangles), triangles):
            f.write("facet normal %.9g %.9g %.9g\n outer loop\n" % tuple(n))
            for v in t:
                f.write("  vertex %.9g %.9g %.9g\n" % tuple(vertices[v]))
            f.write(" endloop\nendfacet\n")
        f.write("endsolid numerics\n")


def write_obj(path, vertices, triangles):
    with open(path, "w") as f:
        f.writelines("v %.9g %.9g %.9g\n" % tuple(v) for v in vertices)
        f.writelines("f %d %d %d\n" % tuple(t + 1) for t in triangles)


def write_ply(path, vertices, triangles):
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex %d\n" % len(vertices))
        f.write("property float x\nproperty float y\nproperty float z\n")
        f.write("element face %d\nproperty list uchar int vertex_indices\nend_header\n"
                % len(triangles))
        f.writelines("%.9g %.9g %.9g\n" % tuple(v) for v in vertices)
        f.writelines("3 %d %d %d\n" % tuple(t) for t in triangles)


WRITERS = {"stl": (write_stl, ".stl"), "stl-ascii": (write_stl_ascii, "_ascii.stl"),
           "obj": (write_obj, ".obj"), "ply": (write_ply, ".ply")}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", required=True, help="directory to write into")
    parser.add_argument("--shapes", default="sphere,torus,cylinder,cup,obstacle")
    parser.add_argument("--formats", default="stl", help=",".join(WRITERS))
    parser.add_argument("--sectors", type=int, default=48,
                        help="sectors of a round shape (a sphere has half as many rings)")
    parser.add_argument("--suffix", default="", help="added to each file's name")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for shape in args.shapes.split(","):
        if shape == "obstacle":
            vertices, triangles = box()
        elif shape in PROFILES:
            vertices, triangles = revolve(*PROFILES[shape](args.sectors), args.sectors)
        else:
            parser.error("unknown shape '%s' (sphere, torus, cylinder, cup or obstacle)" % shape)
        for fmt in args.formats.split(","):
            if fmt not in WRITERS:
                parser.error("unknown format '%s' (%s)" % (fmt, ", ".join(WRITERS)))
            write, ending = WRITERS[fmt]
            write(os.path.join(args.out, shape + args.suffix + ending), vertices, triangles)


if __name__ == "__main__":
    main()
