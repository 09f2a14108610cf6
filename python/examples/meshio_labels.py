"""Winding numbers of a mesh file read with meshio, the labels written back as cell data.

The file's polygon cells (triangle, quad and polygon blocks) are the surface, its line cells the curves
(segments along the surface's edges, each from its first vertex to its second). The labels are written
to OUT as the cell data "swn_W" (0 on the line cells), with the same points and cells.

Usage: python3 meshio_labels.py MESH OUT   (formats: any meshio reads and writes, e.g. .vtu, .vtk, .msh;
meshio's OBJ reader leaves out the `l` lines of an OBJ file: swn.load() reads them)
"""
import sys

import meshio
import numpy as np

import swn

mesh = meshio.read(sys.argv[1])
surface = [k for k, block in enumerate(mesh.cells) if block.type in ("triangle", "quad") or block.type.startswith("polygon")]
lines = [mesh.cells[k].data for k, block in enumerate(mesh.cells) if block.type == "line"]
if not surface or not lines:
    sys.exit(f"{sys.argv[1]}: needs polygon cells (the surface) and line cells (the curves)"
             + ("; meshio reads no `l` lines from OBJ files: swn.load() does" if sys.argv[1].lower().endswith(".obj") else ""))

# one block of faces: its array as it is (read in place); several: one list of polygons
F = mesh.cells[surface[0]].data if len(surface) == 1 else [f for k in surface for f in mesh.cells[k].data.tolist()]
r = swn.winding_numbers(mesh.points, F, np.vstack(lines))

labels, start = [], 0
for k, block in enumerate(mesh.cells):
    if k in surface:
        labels.append(r.W[start:start + len(block.data)])
        start += len(block.data)
    else:
        labels.append(np.zeros(len(block.data), np.int32))
meshio.write(sys.argv[2], meshio.Mesh(mesh.points, mesh.cells, cell_data={"swn_W": labels}))

values, counts = np.unique(r.W, return_counts=True)
print(f"{len(r.W)} faces, solved as {'a polygon soup (' + r.polygon_soup + ')' if r.polygon_soup else 'a triangle mesh'}; "
      + ", ".join(f"W={v}: {c} faces" for v, c in zip(values, counts)) + f"; G on {np.count_nonzero(r.G)} edges")
