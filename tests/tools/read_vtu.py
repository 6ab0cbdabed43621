#!/usr/bin/python3
"""Independent checker of VTK XML unstructured grid (.vtu) files.

Usage: read_vtu.py FILE.vtu

Reads the file with the Python standard library only (no VTK, no numpy), so
that it shares no code with dgwarp's writer. Supports what dgwarp writes and
the common variants: inline DataArrays with format="binary" (base64 of
[byte count][data], uncompressed), byte_order LittleEndian or BigEndian,
header_type UInt32 or UInt64, one Piece.

Checks: the XML parses; every DataArray decodes and its declared byte count
equals the decoded size; NumberOfPoints / NumberOfCells match the array
lengths; every PointData / CellData array has count x NumberOfComponents
values; offsets increase by each cell type's node count and end at the
length of connectivity; connectivity ids lie in [0, NumberOfPoints); types
are VTK ids of linear cells (vertex 1, line 3, triangle 5, quad 9, tetra 10,
hexahedron 12, wedge 13, pyramid 14).

Prints a JSON summary to stdout:
  {"points": N, "cells": M, "cell_types": {"<vtk id>": count, ...},
   "coordinate_sums": [sx, sy, sz],
   "arrays": [{"section": "Points|Cells|PointData|CellData", "name", "type",
               "components", "tuples", "min", "max", "component_min",
               "component_max", "non_finite"}, ...]}
(min/max over finite values; null when there are none). Exits 1 with a
message on stderr at the first inconsistency, 2 on bad usage.
"""
import array
import base64
import binascii
import json
import math
import sys
import xml.etree.ElementTree as ET

# VTK type name -> (array typecode, item size in bytes)
VTK_TYPES = {
    "Int8": ("b", 1), "UInt8": ("B", 1), "Int16": ("h", 2), "UInt16": ("H", 2),
    "Int32": ("i", 4), "UInt32": ("I", 4), "Int64": ("q", 8), "UInt64": ("Q", 8),
    "Float32": ("f", 4), "Float64": ("d", 8),
}
INTEGER_TYPES = {"Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32", "Int64", "UInt64"}
# VTK cell id -> number of nodes (linear cells only)
VTK_CELL_NODES = {1: 1, 3: 2, 5: 3, 9: 4, 10: 4, 12: 8, 13: 6, 14: 5}


class VtuError(Exception):
    pass


def unpack(raw, type_name, big_endian):
    code, size = VTK_TYPES[type_name]
    values = array.array(code)
    if values.itemsize != size:
        raise VtuError(f"this Python's array('{code}') has {values.itemsize}-byte items, "
                       f"expected {size} for {type_name}")
    values.frombytes(raw)
    if big_endian != (sys.byteorder == "big"):
        values.byteswap()
    return values


def decode_data_array(da, header_type, big_endian):
    """The values of an inline binary DataArray, after checking its byte count."""
    name = da.get("Name", "<unnamed>")
    type_name = da.get("type")
    if type_name not in VTK_TYPES:
        raise VtuError(f"DataArray '{name}': unknown type {type_name!r}")
    if da.get("format") != "binary":
        raise VtuError(f"DataArray '{name}': format {da.get('format')!r} is not supported "
                       "(only inline format=\"binary\")")
    text = "".join((da.text or "").split())
    try:
        raw = base64.b64decode(text, validate=True)
    except (binascii.Error, ValueError) as e:
        raise VtuError(f"DataArray '{name}': invalid base64 ({e})")
    header_size = VTK_TYPES[header_type][1]
    if len(raw) < header_size:
        raise VtuError(f"DataArray '{name}': {len(raw)} bytes decoded, "
                       f"fewer than its {header_size}-byte header")
    declared = unpack(raw[:header_size], header_type, big_endian)[0]
    body = raw[header_size:]
    if declared != len(body):
        raise VtuError(f"DataArray '{name}': header declares {declared} bytes, "
                       f"{len(body)} decoded")
    item_size = VTK_TYPES[type_name][1]
    if len(body) % item_size:
        raise VtuError(f"DataArray '{name}': {len(body)} bytes is not a whole number of "
                       f"{type_name} values")
    return unpack(body, type_name, big_endian)


def components_of(da):
    text = da.get("NumberOfComponents", "1")
    try:
        n = int(text)
    except ValueError:
        n = 0
    if n < 1:
        raise VtuError(f"DataArray '{da.get('Name')}': NumberOfComponents {text!r} is not a "
                       "positive integer")
    return n


def finite_min_max(values):
    """(min, max, number of non-finite values) of an array; min/max None when none is finite."""
    non_finite = 0
    if values.typecode in "fd":
        non_finite = sum(1 for v in values if not math.isfinite(v))
        if non_finite:
            values = [v for v in values if math.isfinite(v)]
    if len(values) == 0:
        return None, None, non_finite
    return min(values), max(values), non_finite


def summary_of(section, da, values, components):
    low, high, non_finite = finite_min_max(values)
    columns = [finite_min_max(values[c::components]) for c in range(components)]
    return {
        "section": section,
        "name": da.get("Name"),
        "type": da.get("type"),
        "components": components,
        "tuples": len(values) // components,
        "min": low,
        "max": high,
        "component_min": [c[0] for c in columns],
        "component_max": [c[1] for c in columns],
        "non_finite": non_finite,
    }


def count_attribute(piece, name):
    text = piece.get(name)
    try:
        n = int(text)
    except (TypeError, ValueError):
        n = -1
    if n < 0:
        raise VtuError(f"Piece: {name} {text!r} is not a non-negative integer")
    return n


def only_data_arrays(element):
    children = list(element)
    for c in children:
        if c.tag != "DataArray":
            raise VtuError(f"{element.tag}: unexpected element <{c.tag}>")
    return children


def check_cells(arrays, num_points, num_cells):
    for name in ("connectivity", "offsets", "types"):
        if name not in arrays:
            raise VtuError(f"Cells: no DataArray named '{name}'")
        if arrays[name][0].get("type") not in INTEGER_TYPES:
            raise VtuError(f"Cells/{name}: type {arrays[name][0].get('type')} is not an integer type")
        if arrays[name][1] != 1:
            raise VtuError(f"Cells/{name}: NumberOfComponents must be 1")
    conn = arrays["connectivity"][2]
    offsets = arrays["offsets"][2]
    types = arrays["types"][2]
    if len(offsets) != num_cells:
        raise VtuError(f"Cells/offsets has {len(offsets)} values, NumberOfCells is {num_cells}")
    if len(types) != num_cells:
        raise VtuError(f"Cells/types has {len(types)} values, NumberOfCells is {num_cells}")
    type_counts = {}
    start = 0
    for i, (end, t) in enumerate(zip(offsets, types)):
        if t not in VTK_CELL_NODES:
            raise VtuError(f"cell {i}: type {t} is not a supported VTK cell id")
        if end - start != VTK_CELL_NODES[t]:
            raise VtuError(f"cell {i}: offsets give {end - start} nodes (from {start} to {end}), "
                           f"VTK type {t} has {VTK_CELL_NODES[t]}")
        type_counts[t] = type_counts.get(t, 0) + 1
        start = end
    if start != len(conn):
        raise VtuError(f"Cells: last offset is {start}, connectivity has {len(conn)} values")
    if len(conn) and not (0 <= min(conn) and max(conn) < num_points):
        for k, node in enumerate(conn):
            if not 0 <= node < num_points:
                raise VtuError(f"connectivity[{k}] = {node} is not a node id in [0, {num_points})")
    return {str(t): n for t, n in sorted(type_counts.items())}


def read_vtu(path):
    try:
        root = ET.parse(path).getroot()
    except (ET.ParseError, OSError) as e:
        raise VtuError(f"cannot parse XML: {e}")
    if root.tag != "VTKFile" or root.get("type") != "UnstructuredGrid":
        raise VtuError(f"root is <{root.tag} type={root.get('type')!r}>, "
                       "expected <VTKFile type=\"UnstructuredGrid\">")
    byte_order = root.get("byte_order")
    if byte_order not in ("LittleEndian", "BigEndian"):
        raise VtuError(f"byte_order {byte_order!r} is neither LittleEndian nor BigEndian")
    header_type = root.get("header_type", "UInt32")
    if header_type not in ("UInt32", "UInt64"):
        raise VtuError(f"header_type {header_type!r} is neither UInt32 nor UInt64")
    if root.get("compressor"):
        raise VtuError(f"compressed files are not supported ({root.get('compressor')})")
    big_endian = byte_order == "BigEndian"

    grids = root.findall("UnstructuredGrid")
    if len(grids) != 1:
        raise VtuError(f"{len(grids)} <UnstructuredGrid> elements, expected 1")
    pieces = grids[0].findall("Piece")
    if len(pieces) != 1:
        raise VtuError(f"{len(pieces)} <Piece> elements, expected 1")
    piece = pieces[0]
    num_points = count_attribute(piece, "NumberOfPoints")
    num_cells = count_attribute(piece, "NumberOfCells")

    summaries = []
    coordinate_sums = None
    cell_types = None
    seen = set()
    for section in piece:
        if section.tag in seen:
            raise VtuError(f"Piece: more than one <{section.tag}>")
        seen.add(section.tag)
        if section.tag not in ("Points", "Cells", "PointData", "CellData"):
            raise VtuError(f"Piece: unexpected element <{section.tag}>")
        decoded = {}
        for da in only_data_arrays(section):
            name = da.get("Name")
            if section.tag != "Points" and not name:
                raise VtuError(f"{section.tag}: a DataArray has no Name")
            if name in decoded:
                raise VtuError(f"{section.tag}: two DataArrays named '{name}'")
            values = decode_data_array(da, header_type, big_endian)
            components = components_of(da)
            if len(values) % components:
                raise VtuError(f"{section.tag}/{name}: {len(values)} values is not a whole number "
                               f"of {components}-component tuples")
            decoded[name] = (da, components, values)
            summaries.append(summary_of(section.tag, da, values, components))

        if section.tag == "Points":
            if len(decoded) != 1:
                raise VtuError(f"Points: {len(decoded)} DataArrays, expected 1")
            da, components, values = next(iter(decoded.values()))
            if components != 3:
                raise VtuError(f"Points: NumberOfComponents is {components}, expected 3")
            if da.get("type") not in ("Float32", "Float64"):
                raise VtuError(f"Points: type {da.get('type')} is not Float32 or Float64")
            if len(values) != 3 * num_points:
                raise VtuError(f"Points has {len(values) // 3} points, "
                               f"NumberOfPoints is {num_points}")
            if not all(math.isfinite(v) for v in values):
                raise VtuError("Points: a coordinate is not finite")
            coordinate_sums = [math.fsum(values[c::3]) for c in range(3)]
        elif section.tag == "Cells":
            cell_types = check_cells(decoded, num_points, num_cells)
        else:
            count = num_points if section.tag == "PointData" else num_cells
            for name, (da, components, values) in decoded.items():
                if len(values) != count * components:
                    raise VtuError(f"{section.tag}/{name}: {len(values) // components} tuples, "
                                   f"expected {count}")

    if coordinate_sums is None:
        raise VtuError("Piece: no <Points>")
    if cell_types is None:
        raise VtuError("Piece: no <Cells>")
    return {
        "points": num_points,
        "cells": num_cells,
        "cell_types": cell_types,
        "coordinate_sums": coordinate_sums,
        "arrays": summaries,
    }


def main(argv):
    if len(argv) != 2:
        print("usage: read_vtu.py FILE.vtu", file=sys.stderr)
        return 2
    try:
        summary = read_vtu(argv[1])
    except VtuError as e:
        print(f"read_vtu.py: {argv[1]}: {e}", file=sys.stderr)
        return 1
    json.dump(summary, sys.stdout, indent=1, allow_nan=False)
    print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
