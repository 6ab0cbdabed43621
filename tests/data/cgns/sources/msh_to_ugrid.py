#!/usr/bin/python3
"""Writes a Gmsh mesh as an ASCII AFLR3 .ugrid file (aflr3_to_cgns -f reads it).

usage: msh_to_ugrid.py MESH.msh OUT.ugrid

The boundary faces' surface ids are their Gmsh physical tags. Node orders:
meshio's (VTK's, the same as CGNS's but for the prism, which aflr3_to_cgns
turns as it needs), with the pyramid permuted ([0, 3, 4, 1, 2]) so that
aflr3_to_cgns writes the Gmsh pyramid back node for node (meshio's own
ugrid writer's [1, 0, 4, 2, 3] gives the same pyramid with its base starting
at another node). meshio's writer itself is not used: it fails on a mesh with
several boundary blocks (meshio 5.3).
"""
import sys

import meshio
import numpy as np

mesh = meshio.read(sys.argv[1])
blocks = {}
tags = {}
for block, tag in zip(mesh.cells, mesh.cell_data["gmsh:physical"]):
    blocks.setdefault(block.type, []).append(block.data)
    tags.setdefault(block.type, []).append(np.asarray(tag))
def cells(kind):
    return np.concatenate(blocks[kind]) if kind in blocks else np.zeros((0, 1), dtype=int)
def ids(kind):
    return np.concatenate(tags[kind]) if kind in tags else np.zeros(0, dtype=int)
kinds = ["triangle", "quad", "tetra", "pyramid", "wedge", "hexahedron"]
counts = [len(mesh.points)] + [len(cells(k)) for k in kinds]
with open(sys.argv[2], "w") as f:
    f.write(" ".join(str(c) for c in counts) + "\n")
    for p in mesh.points:
        f.write(" ".join(repr(float(x)) for x in p) + "\n")
    for k in ["triangle", "quad"]:
        for c in cells(k):
            f.write(" ".join(str(i + 1) for i in c) + "\n")
    for k in ["triangle", "quad"]:
        for t in ids(k):
            f.write(f"{t}\n")
    for k in ["tetra", "pyramid", "wedge", "hexahedron"]:
        c = cells(k)
        if k == "pyramid" and len(c):
            c = c[:, [0, 3, 4, 1, 2]]
        for e in c:
            f.write(" ".join(str(i + 1) for i in e) + "\n")
