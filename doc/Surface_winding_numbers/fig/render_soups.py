#!/usr/bin/env python3
"""Renders the manual's figure soups.png: the swn tool on two soups it reads as they are.

Left: a Moebius strip (nonorientable) with a loop given as a dual chain (`c` records) and one pair left out;
right: three flaps on a spine (nonmanifold edge) with a loop across the spine in the sheet of two flaps,
whose edges at the spine are dropped. Faces are coloured by the label W the tool writes in mesh.ply.

usage: render_soups.py SWN_EXECUTABLE [OUT.png]   (needs python3-matplotlib and python3-numpy)
"""
import math, os, struct, subprocess, sys, tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d.art3d import Poly3DCollection


def write_obj(path, verts, faces, extra=""):
    with open(path, "w") as f:
        for v in verts:
            f.write("v %r %r %r\n" % tuple(v))
        for face in faces:
            f.write("f " + " ".join(str(i + 1) for i in face) + "\n")
        f.write(extra)


def moebius():
    n, m = 40, 8
    vid = lambda i, j: i * (m + 1) + j if i < n else m - j
    verts = []
    for i in range(n):
        for j in range(m + 1):
            phi, s = 2 * math.pi * i / n, (j / m - 0.5) * 0.9
            verts.append(((2 + s * math.cos(phi / 2)) * math.cos(phi), (2 + s * math.cos(phi / 2)) * math.sin(phi),
                          s * math.sin(phi / 2)))
    faces = []
    for i in range(n):
        for j in range(m):
            faces += [(vid(i, j), vid(i + 1, j), vid(i + 1, j + 1)), (vid(i, j), vid(i + 1, j + 1), vid(i, j + 1))]
    inside = lambda f: 14 <= (f // 2) // m < 26 and 2 <= (f // 2) % m < 6
    sides = {}
    for f, t in enumerate(faces):
        for k in range(3):
            a, b = t[k], t[(k + 1) % 3]
            sides.setdefault((min(a, b), max(a, b)), []).append(f)
    pairs = [(p[1], p[0]) if inside(p[0]) else (p[0], p[1])
             for e, p in sorted(sides.items()) if len(p) == 2 and inside(p[0]) != inside(p[1])]
    del pairs[len(pairs) // 2]   # a gap
    return verts, faces, "".join("c %d %d\n" % (a + 1, b + 1) for a, b in pairs), ""


def flaps():
    M, N = 8, 8
    vid = lambda flap, i, k: k if i == 0 else (N + 1) + (flap * M + i - 1) * (N + 1) + k
    verts = [(0.0, 0.0, float(k)) for k in range(N + 1)]
    for flap in range(3):
        a = 2 * math.pi * flap / 3 + 0.3
        for i in range(1, M + 1):
            for k in range(N + 1):
                verts.append((i * math.cos(a), i * math.sin(a), float(k)))
    faces = []
    for flap in range(3):
        for i in range(M):
            for k in range(N):
                q = [vid(flap, i, k), vid(flap, i + 1, k), vid(flap, i + 1, k + 1), vid(flap, i, k + 1)]
                faces.append(tuple(reversed(q)) if flap == 1 else tuple(q))
    at = lambda x, k: vid(0, x, k) if x >= 0 else vid(1, -x, k)
    loop = [at(x, 2) for x in range(-3, 4)] + [at(3, k) for k in range(3, 7)] + [at(x, 6) for x in range(2, -4, -1)] + \
           [at(-3, k) for k in range(5, 1, -1)]
    return verts, faces, "", "# swn polylines\n" + " ".join(map(str, loop)) + "\n"


def read_labels_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().split("\n")
    nv = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    nf = int(next(l for l in header if l.startswith("element face")).split()[2])
    pos = end + 24 * nv
    labels = []
    for _ in range(nf):
        k = data[pos]
        pos += 1 + 4 * k
        labels.append(struct.unpack_from("<i", data, pos)[0])
        pos += 4 + 4 + 4
    return labels


def solve(swn, verts, faces, extra, curve, tmp, name):
    mesh = os.path.join(tmp, name + ".obj")
    write_obj(mesh, verts, faces, extra)
    args = [swn, mesh, "--quiet", "--output-dir", os.path.join(tmp, name)]
    if curve:
        with open(os.path.join(tmp, name + ".txt"), "w") as f:
            f.write(curve)
        args += ["--curve", os.path.join(tmp, name + ".txt")]
    subprocess.run(args, check=True)
    return read_labels_ply(os.path.join(tmp, name, "mesh.ply"))


def main():
    swn = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "soups.png")
    colors = {0: "#d9d9d9", 1: "#e15759", -1: "#4e79a7", 2: "#f28e2b"}
    fig = plt.figure(figsize=(10, 4.4))
    with tempfile.TemporaryDirectory() as tmp:
        for col, (name, build, title, view) in enumerate([
                ("moebius", moebius, "Moebius strip, loop as a dual chain with a gap", (48, -60)),
                ("flaps", flaps, "three flaps on a spine, loop across the spine", (35, 75))]):
            verts, faces, extra, curve = build()
            labels = solve(swn, verts, faces, extra, curve, tmp, name)
            ax = fig.add_subplot(1, 2, col + 1, projection="3d")
            polys = [[verts[i] for i in f] for f in faces]
            ax.add_collection3d(Poly3DCollection(polys, facecolors=[colors.get(l, "#76b7b2") for l in labels],
                                                 edgecolors="#555555", linewidths=0.2))
            xs, ys, zs = zip(*verts)
            ax.set_xlim(min(xs), max(xs)); ax.set_ylim(min(ys), max(ys)); ax.set_zlim(min(zs), max(zs))
            ax.set_box_aspect((max(xs) - min(xs), max(ys) - min(ys), max(zs) - min(zs)))
            ax.view_init(*view)
            ax.set_axis_off()
            ax.set_title(title + "\nW = 1 red, W = 0 grey", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main()
