#!/usr/bin/env python3
"""Renders a labelled mesh written by the swn tool (mesh.ply, faces coloured by label) to a PNG, with the
curves of OBJ `l` files (bounding.obj, or the input polylines) drawn on top in black.

Plain Python (no numpy, no matplotlib): an orthographic view along --direction, flat Lambert shading, a
z-buffer. The manual's pictures of the curve workflows were made with it (see make_figures.sh).

usage: render_ply.py MESH.ply OUT.png [--direction X,Y,Z] [--size N] [--curves FILE.obj ...]
"""
import argparse
import math
import struct
import zlib

PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
             "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
             "float": "f", "float32": "f", "double": "d", "float64": "d"}


def read_ply(path):
    """vertices [(x, y, z)], faces [[i, j, k]], face colours [(r, g, b)] or None"""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii").split("\n")
    fmt, elements = "ascii", []
    for line in header:
        w = line.split()
        if not w:
            continue
        if w[0] == "format":
            fmt = w[1]
        elif w[0] == "element":
            elements.append((w[1], int(w[2]), []))
        elif w[0] == "property":
            elements[-1][2].append((w[-1], w[1:-1]))
    body = data[end:]
    pos = 0
    if fmt == "ascii":
        tokens = body.split()

        def scalar(_type):
            nonlocal pos
            pos += 1
            return float(tokens[pos - 1])
    else:
        order = "<" if fmt == "binary_little_endian" else ">"

        def scalar(type_name):
            nonlocal pos
            t = order + PLY_TYPES[type_name]
            pos += struct.calcsize(t)
            return struct.unpack_from(t, body, pos - struct.calcsize(t))[0]
    values = {}
    for name, count, props in elements:
        rows = []
        for _ in range(count):
            row = {}
            for pname, ptype in props:
                if ptype[0] == "list":
                    n = int(scalar(ptype[1]))
                    row[pname] = [scalar(ptype[2]) for _ in range(n)]
                else:
                    row[pname] = scalar(ptype[0])
            rows.append(row)
        values[name] = rows
    verts = [(r["x"], r["y"], r["z"]) for r in values["vertex"]]
    faces, colours = [], []
    for r in values["face"]:
        idx = r.get("vertex_indices", r.get("vertex_index"))
        faces.append([int(i) for i in idx])
        colours.append((int(r["red"]), int(r["green"]), int(r["blue"])) if "red" in r else (200, 200, 200))
    return verts, faces, colours


def read_obj_lines(path):
    pts, lines = [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                pts.append(tuple(float(x) for x in w[1:4]))
            elif w[0] == "l":
                lines.append([int(x.split("/")[0]) - 1 for x in w[1:]])
    return [[pts[i] for i in l] for l in lines]


def frame(d):
    n = math.sqrt(sum(x * x for x in d))
    d = [x / n for x in d]
    up = (0, 1, 0) if abs(d[2]) > math.cos(math.radians(25)) else (0, 0, 1)
    right = cross(d, up)
    n = math.sqrt(sum(x * x for x in right))
    right = [x / n for x in right]
    down = cross(d, right)
    return d, right, down


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def write_png(path, width, height, rgb):
    raw = b"".join(b"\x00" + bytes(rgb[y * width * 3:(y + 1) * width * 3]) for y in range(height))

    def chunk(kind, payload):
        c = struct.pack(">I", len(payload)) + kind + payload
        return c + struct.pack(">I", zlib.crc32(kind + payload) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def render(mesh, out, direction, size, curves):
    verts, faces, colours = read_ply(mesh)
    d, right, down = frame(direction)
    proj = [(dot(p, right), dot(p, down), dot(p, d)) for p in verts]
    xs, ys = [p[0] for p in proj], [p[1] for p in proj]
    span = max(max(xs) - min(xs), max(ys) - min(ys))
    scale = 0.92 * size / span
    ox, oy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2

    def screen(p):
        return ((p[0] - ox) * scale + size / 2, (p[1] - oy) * scale + size / 2, p[2])
    scr = [screen(p) for p in proj]
    depth = [float("inf")] * (size * size)
    rgb = [255] * (size * size * 3)
    for face, colour in zip(faces, colours):
        for k in range(1, len(face) - 1):   # a fan of triangles
            ia, ib, ic = face[0], face[k], face[k + 1]
            a, b, c = scr[ia], scr[ib], scr[ic]
            n = cross([verts[ib][i] - verts[ia][i] for i in range(3)], [verts[ic][i] - verts[ia][i] for i in range(3)])
            ln = math.sqrt(dot(n, n)) or 1.0
            shade = 0.3 + 0.7 * abs(dot(n, d)) / ln
            area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
            if area == 0:
                continue
            x0, x1 = max(0, int(min(a[0], b[0], c[0]))), min(size - 1, int(max(a[0], b[0], c[0])) + 1)
            y0, y1 = max(0, int(min(a[1], b[1], c[1]))), min(size - 1, int(max(a[1], b[1], c[1])) + 1)
            col = [int(min(255, ch * shade)) for ch in colour]
            for y in range(y0, y1 + 1):
                py = y + 0.5
                for x in range(x0, x1 + 1):
                    px = x + 0.5
                    w0 = ((b[0] - px) * (c[1] - py) - (c[0] - px) * (b[1] - py)) / area
                    w1 = ((c[0] - px) * (a[1] - py) - (a[0] - px) * (c[1] - py)) / area
                    w2 = 1 - w0 - w1
                    if w0 < 0 or w1 < 0 or w2 < 0:
                        continue
                    z = w0 * a[2] + w1 * b[2] + w2 * c[2]
                    i = y * size + x
                    if z < depth[i]:
                        depth[i] = z
                        rgb[3 * i:3 * i + 3] = col
    eps = 0.01 * span
    for path in curves:
        for line in read_obj_lines(path):
            for p, q in zip(line, line[1:]):
                a, b = screen((dot(p, right), dot(p, down), dot(p, d))), screen((dot(q, right), dot(q, down), dot(q, d)))
                steps = int(max(abs(b[0] - a[0]), abs(b[1] - a[1])) * 2) + 1
                for s in range(steps + 1):
                    t = s / steps
                    x, y, z = a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])
                    for dx, dy in ((0, 0), (1, 0), (0, 1), (1, 1)):
                        xi, yi = int(x) + dx - 1, int(y) + dy - 1
                        if 0 <= xi < size and 0 <= yi < size and z - eps <= depth[yi * size + xi]:
                            rgb[3 * (yi * size + xi):3 * (yi * size + xi) + 3] = [0, 0, 0]
    write_png(out, size, size, rgb)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("mesh")
    ap.add_argument("out")
    ap.add_argument("--direction", default="0,0,-1")
    ap.add_argument("--size", type=int, default=360)
    ap.add_argument("--curves", nargs="*", default=[])
    a = ap.parse_args()
    render(a.mesh, a.out, [float(x) for x in a.direction.split(",")], a.size, a.curves)


if __name__ == "__main__":
    main()
