#!/usr/bin/python3
"""Writes the per-node files of the example motions (stdlib only).

    make_node_files.py SU2_MESHES [OUTPUT_FOLDER]

SU2_MESHES is a folder with SU2's test meshes under the names of ../shared/meshes/su2:
deformation_naca0012_mesh_NACA0012_inv.su2 (SU2's deformation/naca0012/mesh_NACA0012_inv.su2,
markers airfoil, farfield) and deformation_brick_KIND_mesh_brick_KIND_ffd.su2 for KIND in
hex, prism, pyra, tets (SU2's deformation/brick_KIND/mesh_brick_KIND_ffd.su2: the box
[0,2]x[0,1]x[0,1], markers x_m x_p y_m y_p z_m z_p, meshed with hexahedra, prisms,
pyramids + tetrahedra, tetrahedra). Node ids are the points' 0-based positions in the
.su2 file, which is what dgwarp and SU2 use; each brick mesh numbers its nodes
differently, so each gets its own bump file (brick_top_bump.csv is the hex one).
"""
import math
import os
import sys


def read_su2(path):
    """Returns (dim, points, {marker: sorted node ids})."""
    with open(path) as f:
        lines = f.read().split("\n")
    dim, points, markers, i = None, [], {}, 0
    while i < len(lines):
        line = lines[i].split("%")[0].strip()
        if line.startswith("NDIME"):
            dim = int(line.split("=")[1])
        elif line.startswith("NPOIN"):
            n = int(line.split("=")[1].split()[0])
            points = [[float(v) for v in lines[i + 1 + k].split()[:dim]] for k in range(n)]
            i += n
        elif line.startswith("MARKER_TAG"):
            name = line.split("=")[1].strip()
            count = int(lines[i + 1].split("=")[1])
            nodes = set()
            for k in range(count):
                nodes.update(int(v) for v in lines[i + 2 + k].split()[1:])
            markers[name] = sorted(nodes)
            i += count + 1
        i += 1
    return dim, points, markers


def write(path, header, rows):
    with open(path, "w") as f:
        if header:
            f.write(header + "\n")
        for row in rows:
            f.write(row + "\n")


def num(v):
    return repr(round(v, 15) + 0.0)


def airfoil_files(mesh, out):
    _, points, markers = read_su2(mesh)
    nodes = markers["airfoil"]
    # A bump on the upper surface: dy = 0.01 sin²(πx), zero at both ends.
    write(os.path.join(out, "airfoil_bump.csv"), "node,dx,dy",
          ["%d,0,%s" % (n, num(0.01 * math.sin(math.pi * points[n][0]) ** 2 if points[n][1] > 0 else 0.0))
           for n in nodes])
    # SU2 surface file (new coordinates by global index): the airfoil 20 % thicker.
    write(os.path.join(out, "airfoil_thicker.dat"), None,
          ["%d\t%.15e\t%.15e" % (n, points[n][0], 1.2 * points[n][1]) for n in nodes])
    # A smooth flap: each node behind x = 0.7 turns about the hinge (0.7, 0) by an angle that
    # grows from 0 at the hinge to -10° at the trailing edge (2D form: node,tx,ty,wz,cx,cy).
    rows = []
    for n in nodes:
        x = points[n][0]
        wz = -math.radians(10.0) * max(0.0, (x - 0.7) / 0.3)
        rows.append("%d,0,0,%s,0.7,0" % (n, num(wz)))
    write(os.path.join(out, "airfoil_flap.csv"), "node,tx,ty,wz,cx,cy", rows)


def brick_bump(mesh, out, name):
    _, points, markers = read_su2(mesh)
    # A bump on the top face, zero on its edges: dz = 0.1 sin(πx/2) sin(πy).
    write(os.path.join(out, name), "node,dx,dy,dz",
          ["%d,0,0,%s" % (n, num(0.1 * math.sin(math.pi * points[n][0] / 2) * math.sin(math.pi * points[n][1])))
           for n in markers["z_p"]])


def brick_twist(mesh, out):
    _, points, markers = read_su2(mesh)
    # A twist of the top face about the brick's long axis (y = z = 0.5): the angle grows from 0
    # at x = 0 to 5° at x = 2 (3D form: node,tx,ty,tz,wx,wy,wz,cx,cy,cz). At 10° the top
    # face's edges would drop below the side faces' next row of nodes (0.053 lower).
    rows = []
    for n in markers["z_p"]:
        x = points[n][0]
        rows.append("%d,0,0,0,%s,0,0,%s,0.5,0.5" % (n, num(math.radians(5.0) * x / 2), num(x)))
    write(os.path.join(out, "brick_top_twist.csv"), "node,tx,ty,tz,wx,wy,wz,cx,cy,cz", rows)


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    meshes = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) == 3 else os.path.dirname(os.path.abspath(__file__))
    brick = lambda kind: os.path.join(meshes, "deformation_brick_%s_mesh_brick_%s_ffd.su2" % (kind, kind))
    airfoil_files(os.path.join(meshes, "deformation_naca0012_mesh_NACA0012_inv.su2"), out)
    brick_bump(brick("hex"), out, "brick_top_bump.csv")
    for kind in ("prism", "pyra", "tets"):
        brick_bump(brick(kind), out, "brick_%s_top_bump.csv" % kind)
    brick_twist(brick("hex"), out)


if __name__ == "__main__":
    main()
