#!/usr/bin/env python3
"""Independent computation of dgwarp's mesh quality figures for an SU2 mesh.

Reads an SU2 ASCII mesh with its own parser and computes Knupp's shape metric
per cell with its own implementation (formulas: docs/QUALITY.md), judged
against the dominant orientation of each cell type, as
`dgwarp quality MESH --json` does. Prints JSON {cells, min, mean, inverted}.

Written separately from the C++ code so the two can check each other: the
simplices use the edge-length forms, the corner-based elements the weighted
Jacobian T = A W^-1 with a numerically inverted W. Python 3 standard library only.

Usage: knupp_quality.py MESH.su2 [--zone N]
"""
import argparse
import json
import math
import sys

# VTK/SU2 element id -> (name, node count)
ELEMENTS = {
    5: ("triangle", 3),
    9: ("quadrilateral", 4),
    10: ("tetrahedron", 4),
    12: ("hexahedron", 8),
    13: ("prism", 6),
    14: ("pyramid", 5),
}


# ----------------------------------------------------------------- SU2 input

def read_su2(path, zone=1):
    """Returns (dim, points, cells) of one zone: points a list of coordinate
    tuples (dim values), cells a list of (vtk_id, node tuple) in file order."""
    with open(path, "r") as f:
        lines = f.read().splitlines()

    def content(line):
        cut = line.find("%")
        return (line if cut < 0 else line[:cut]).strip()

    pos = 0

    def data_lines(count):
        nonlocal pos
        out = []
        while len(out) < count:
            if pos >= len(lines):
                raise ValueError(f"{path}: file ends inside a block of {count} lines")
            text = content(lines[pos])
            pos += 1
            if text:
                out.append(text)
        return out

    dim = None
    points = None
    cells = None
    current_zone = 1
    while pos < len(lines) and (points is None or cells is None):
        text = content(lines[pos])
        pos += 1
        if "=" not in text:
            continue
        key, value = (s.strip() for s in text.split("=", 1))
        key = key.upper()
        if key == "IZONE":
            current_zone = int(value.split()[0])
            continue
        if current_zone != zone:
            continue
        if key == "NDIME":
            dim = int(value.split()[0])
        elif key == "NELEM":
            cells = []
            for row in data_lines(int(value.split()[0])):
                tokens = row.split()
                vtk = int(tokens[0])
                if vtk not in ELEMENTS:
                    raise ValueError(f"{path}: unsupported element type {vtk}")
                n = ELEMENTS[vtk][1]
                cells.append((vtk, tuple(int(t) for t in tokens[1:1 + n])))
        elif key == "NPOIN":
            if dim is None:
                raise ValueError(f"{path}: NPOIN before NDIME")
            points = [tuple(float(t) for t in row.split()[:dim])
                      for row in data_lines(int(value.split()[0]))]
    if dim is None or points is None or cells is None:
        raise ValueError(f"{path}: zone {zone} lacks NDIME, NELEM or NPOIN")
    return dim, points, cells


# ------------------------------------------------------------ linear algebra

def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def det3(c1, c2, c3):
    """Determinant of the 3x3 matrix with columns c1, c2, c3 (cofactor expansion)."""
    return (c1[0] * (c2[1] * c3[2] - c3[1] * c2[2])
            - c2[0] * (c1[1] * c3[2] - c3[1] * c1[2])
            + c3[0] * (c1[1] * c2[2] - c2[1] * c1[2]))


def inverse3(m):
    """Inverse of a row-major 3x3 matrix given as a list of rows."""
    (a, b, c), (d, e, f), (g, h, i) = m
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    adj = [[e * i - f * h, c * h - b * i, b * f - c * e],
           [f * g - d * i, a * i - c * g, c * d - a * f],
           [d * h - e * g, b * g - a * h, a * e - b * d]]
    return [[adj[r][s] / det for s in range(3)] for r in range(3)]


def columns_to_rows(c1, c2, c3):
    return [[c1[0], c2[0], c3[0]], [c1[1], c2[1], c3[1]], [c1[2], c2[2], c3[2]]]


def two_thirds(v):
    return abs(v) ** (2.0 / 3.0)


# --------------------------------------------------- ideal corners (W) and corners

SQ3 = math.sqrt(3.0)
SQ2 = math.sqrt(2.0)
# Columns of the ideal corner of each corner-based solid (docs/QUALITY.md).
W_HEX = columns_to_rows((1, 0, 0), (0, 1, 0), (0, 0, 1))
W_PRISM = columns_to_rows((1, 0, 0), (0.5, SQ3 / 2, 0), (0, 0, 1))
W_PYRAMID = columns_to_rows((1, 0, 0), (0, 1, 0), (0.5, 0.5, 1 / SQ2))
W_INVERSE = {12: inverse3(W_HEX), 13: inverse3(W_PRISM), 14: inverse3(W_PYRAMID)}


def hex_corners():
    out = []
    for k in range(4):  # bottom face 0..3, counter-clockwise seen from the top face
        out.append((k, (k + 1) % 4, (k + 3) % 4, k + 4))
    for k in range(4):  # top face 4..7: previous, next, below
        out.append((k + 4, 4 + (k + 3) % 4, 4 + (k + 1) % 4, k))
    return out


def prism_corners():
    # VTK wedge: seen from the top triangle, the base runs 0, 2, 1 counter-clockwise.
    ccw = (0, 2, 1)
    out = []
    for i, k in enumerate(ccw):
        nxt, prv = ccw[(i + 1) % 3], ccw[(i + 2) % 3]
        out.append((k, nxt, prv, k + 3))
    for i, k in enumerate(ccw):
        nxt, prv = ccw[(i + 1) % 3], ccw[(i + 2) % 3]
        out.append((k + 3, prv + 3, nxt + 3, k))
    return out


def pyramid_corners():
    out = [(k, (k + 1) % 4, (k + 3) % 4, 4) for k in range(4)]
    # apex: one tetrahedral sub-corner per base node m, leaving out the edge to m+2
    out += [(4, (m + 3) % 4, (m + 1) % 4, m) for m in range(4)]
    return out


CORNERS = {12: hex_corners(), 13: prism_corners(), 14: pyramid_corners()}


# ------------------------------------------------------------ element metrics

def triangle(x, dim, sigma):
    e01, e12, e20 = sub(x[1], x[0]), sub(x[2], x[1]), sub(x[0], x[2])
    edges2 = sum(c * c for e in (e01, e12, e20) for c in e)
    a, b = e01, sub(x[2], x[0])
    if dim == 2:
        area = 0.5 * (a[0] * b[1] - a[1] * b[0]) * sigma
    else:
        cr = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
        area = 0.5 * math.sqrt(cr[0] ** 2 + cr[1] ** 2 + cr[2] ** 2)
    return 4.0 * SQ3 * area / edges2 if edges2 > 0 else 0.0


def quadrilateral(x, dim, sigma):
    alphas, norms = [], []
    crosses = []
    for k in range(4):
        e1, e2 = sub(x[(k + 1) % 4], x[k]), sub(x[(k + 3) % 4], x[k])
        crosses.append((e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                        e1[0] * e2[1] - e1[1] * e2[0]))
        norms.append(sum(c * c for c in e1) + sum(c * c for c in e2))
    if dim == 2:
        alphas = [sigma * c[2] for c in crosses]
    else:
        n = [sum(c[i] for c in crosses) for i in range(3)]
        length = math.sqrt(sum(v * v for v in n))
        alphas = [sum(c[i] * n[i] for i in range(3)) / length if length > 0 else 0.0 for c in crosses]
    if min(alphas) <= 0:
        return min(2 * a / s if s > 0 else 0.0 for a, s in zip(alphas, norms))
    return 8.0 / sum(s / a for a, s in zip(alphas, norms))


def tetrahedron(x, sigma):
    volume = sigma * det3(sub(x[1], x[0]), sub(x[2], x[0]), sub(x[3], x[0])) / 6.0
    edges2 = 0.0
    for i in range(4):
        for j in range(i + 1, 4):
            edges2 += sum(c * c for c in sub(x[j], x[i]))
    if edges2 <= 0:
        return 0.0
    q = 12.0 * two_thirds(3.0 * volume) / edges2
    return -q if volume < 0 else q


def corner_solid(vtk, x, sigma):
    winv = W_INVERSE[vtk]
    signed, inverse_sum, any_bad = [], 0.0, False
    for c, p1, p2, p3 in CORNERS[vtk]:
        a = columns_to_rows(sub(x[p1], x[c]), sub(x[p2], x[c]), sub(x[p3], x[c]))
        t = [[sum(a[r][m] * winv[m][s] for m in range(3)) for s in range(3)] for r in range(3)]
        det = sigma * det3((t[0][0], t[1][0], t[2][0]), (t[0][1], t[1][1], t[2][1]),
                           (t[0][2], t[1][2], t[2][2]))
        frob = sum(v * v for row in t for v in row)
        q = 3.0 * two_thirds(det) / frob if frob > 0 else 0.0
        q = -q if det < 0 else q
        signed.append(q)
        if not q > 0:
            any_bad = True
        else:
            inverse_sum += 1.0 / q
    if any_bad:
        return min(signed)
    return len(signed) / inverse_sum


def cell_quality(vtk, x, dim, sigma):
    if vtk == 5:
        return triangle(x, dim, sigma)
    if vtk == 9:
        return quadrilateral(x, dim, sigma)
    if vtk == 10:
        return tetrahedron(x, sigma)
    return corner_solid(vtk, x, sigma)


def signed_measure(vtk, x, dim):
    """Area, volume, or sum of corner determinants (0 for faces in 3D space)."""
    if vtk in (5, 9) and dim == 3:
        return 0.0
    if vtk == 5:
        a, b = sub(x[1], x[0]), sub(x[2], x[0])
        return a[0] * b[1] - a[1] * b[0]
    if vtk == 9:
        total = 0.0
        for k in range(4):
            e1, e2 = sub(x[(k + 1) % 4], x[k]), sub(x[(k + 3) % 4], x[k])
            total += e1[0] * e2[1] - e1[1] * e2[0]
        return total
    if vtk == 10:
        return det3(sub(x[1], x[0]), sub(x[2], x[0]), sub(x[3], x[0]))
    return sum(det3(sub(x[p1], x[c]), sub(x[p2], x[c]), sub(x[p3], x[c]))
               for c, p1, p2, p3 in CORNERS[vtk])


# ---------------------------------------------------------------------- main

def mesh_quality(dim, points, cells):
    pts = [p + (0.0,) * (3 - len(p)) for p in points]
    elements = [(vtk, [pts[n] for n in nodes]) for vtk, nodes in cells]
    # dominant orientation per cell type (+1 on ties)
    balance = {}
    for vtk, x in elements:
        balance[vtk] = balance.get(vtk, 0) + (-1 if signed_measure(vtk, x, dim) < 0 else 1)
    qualities = [cell_quality(vtk, x, dim, -1 if balance[vtk] < 0 else 1) for vtk, x in elements]
    return {
        "cells": len(qualities),
        "min": min(qualities) if qualities else 0.0,
        "mean": math.fsum(qualities) / len(qualities) if qualities else 0.0,
        "inverted": sum(1 for q in qualities if not q > 0),
    }


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh")
    parser.add_argument("--zone", type=int, default=1)
    args = parser.parse_args(argv)
    dim, points, cells = read_su2(args.mesh, args.zone)
    print(json.dumps(mesh_quality(dim, points, cells)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
