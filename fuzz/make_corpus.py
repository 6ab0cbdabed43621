#!/usr/bin/python3
"""Writes the fuzzers' seed corpora, fuzz/corpus/<target>/, from the project's
own small test inputs: the SU2 and Gmsh texts of the reader tests, the example
motion files, and plans made by `dgwarp prepare` on small SU2 meshes.

    fuzz/make_corpus.py build/dgwarp

The corpora are committed; rerun this only when a format changes.
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
CORPUS = ROOT / "fuzz" / "corpus"
FOAM_SEPARATOR = b"\n//dgwarp-next-file\n"  # fuzz_checks.hpp: openfoam_file_separator


def write(target, name, text):
    path = CORPUS / target / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(text.encode() if isinstance(text, str) else text)
    return path


# The valid 2D mesh of tests/io/su2/su2_read_damage_test.cpp.
BASE_2D = """NDIME= 2
NELEM= 2
5 0 1 2 0
5 0 2 3 1
NPOIN= 4
0 0 0
1 0 1
1 1 2
0 1 3
NMARK= 2
MARKER_TAG= lower
MARKER_ELEMS= 1
3 0 1
MARKER_TAG= upper
MARKER_ELEMS= 2
3 1 2
3 2 3
"""


def quad_grid_2d(nx, ny):
    """An nx × ny grid of quadrilaterals on [0, 1]², markers on its four sides,
    with the forms real files have: comments, tabs, index columns."""
    def node(i, j):
        return j * (nx + 1) + i
    lines = ["% a structured grid", "NDIME=\t2", f"NELEM= {nx * ny}"]
    k = 0
    for j in range(ny):
        for i in range(nx):
            lines.append(f"9\t{node(i, j)}\t{node(i + 1, j)}\t{node(i + 1, j + 1)}\t{node(i, j + 1)}\t{k}")
            k += 1
    lines.append(f"NPOIN= {(nx + 1) * (ny + 1)} {(nx + 1) * (ny + 1)}")
    k = 0
    for j in range(ny + 1):
        for i in range(nx + 1):
            lines.append(f"{i / nx!r} {j / ny!r} {k}")
            k += 1
    sides = {
        "lower": [(node(i, 0), node(i + 1, 0)) for i in range(nx)],
        "right": [(node(nx, j), node(nx, j + 1)) for j in range(ny)],
        "upper": [(node(i + 1, ny), node(i, ny)) for i in range(nx)],
        "left": [(node(0, j + 1), node(0, j)) for j in range(ny)],
    }
    lines.append(f"NMARK= {len(sides)}")
    for name, edges in sides.items():
        lines += [f"MARKER_TAG= {name}", f"MARKER_ELEMS= {len(edges)}"]
        lines += [f"3 {a} {b}" for a, b in edges]
    return "\n".join(lines) + "\n"


# One cell of each 3D type around a unit cube: a hexahedron, a wedge beside it,
# a pyramid on top and a tetrahedron; boundary triangles and quadrilaterals.
MIXED_3D = """NDIME= 3
NELEM= 4
12 0 1 2 3 4 5 6 7
13 1 8 2 5 9 6
14 4 5 6 7 10
10 0 3 11 4
NPOIN= 12
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
2 0 0
2 0 1
0.5 0.5 1.5
-1 0.5 0
NMARK= 2
MARKER_TAG= bottom
MARKER_ELEMS= 2
9 0 3 2 1
5 1 2 8
MARKER_TAG= top
MARKER_ELEMS= 4
5 4 5 10
5 5 6 10
5 6 7 10
5 7 4 10
"""

TWO_ZONES = "NZONE= 2\nIZONE= 1\n" + BASE_2D + "IZONE= 2\n" + BASE_2D.replace("lower", "bottom")

WITH_FFD = BASE_2D + "FFD_NBOX= 1\nFFD_NLEVEL= 1\nFFD_TAG= box\nFFD_LEVEL= 0\nFFD_DEGREE_I= 1\n"

# The texts of tests/io/gmsh/gmsh_test_support.hpp.
TET_22 = """$MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
4
1 0 0 0
2 1 0 0
3 0 1 0
4 0 0 1
$EndNodes
$Elements
2
1 4 2 1 1 1 2 3 4
2 2 2 5 2 1 3 2
$EndElements
"""

TET_41 = """$MeshFormat
4.1 0 8
$EndMeshFormat
$Entities
0 0 1 1
1 0 0 0 1 1 0 1 5 0
1 0 0 0 1 1 1 1 1 0
$EndEntities
$Nodes
1 4 1 4
3 1 0 4
1
2
3
4
0 0 0
1 0 0
0 1 0
0 0 1
$EndNodes
$Elements
2 2 1 2
2 1 2 1
1 1 3 2
3 1 4 1
2 1 2 3 4
$EndElements
"""

TET_22_NAMED = TET_22.replace(
    "$EndMeshFormat\n",
    '$EndMeshFormat\n$PhysicalNames\n2\n2 5 "wall"\n3 1 "domain"\n$EndPhysicalNames\n'
    "$Comments\nskipped\n$EndComments\n",
)

MOTIONS = {
    "periodic.json": """{"markers": {"lower": {"periodic": {"pitch": {"amplitude_deg": 5, "mean_deg": 1, "frequency": 2,
                                                  "phase_deg": 90, "axis": [0, 0, 1], "center": [0.25, 0]},
                                        "plunge": {"amplitude": [0, 0.1], "frequency": 2, "phase_deg": 0}}},
             "upper": "fixed"},
 "time": {"time_step": 0.05, "steps": 20}}
""",
    "default_rules.json": """{"markers": {"lower": {"translate": [0.1, 0, 0]}},
 "default": {"rotate": {"angle_deg": -3, "center": [0, 0, 0]}},
 "shared_nodes": "static_wins", "shared_tolerance": 1e-6, "comment": "seed"}
""",
    "frames_files.json": """{"frames": [{"markers": {"lower": {"displacement_file": "d.csv"}}},
            {"markers": {"lower": {"surface_file": "s.dat"}, "upper": {"node_motion_file": "m.csv"}}}],
 "default": "fixed"}
""",
}


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    cli = pathlib.Path(sys.argv[1]).resolve()
    shutil.rmtree(CORPUS, ignore_errors=True)

    su2 = {
        "base_2d.su2": BASE_2D,
        "base_2d_crlf.su2": BASE_2D.replace("\n", "\r\n"),
        "quad_grid_2d.su2": quad_grid_2d(3, 2),
        "mixed_3d.su2": MIXED_3D,
        "two_zones.su2": TWO_ZONES,
        "with_ffd.su2": WITH_FFD,
    }
    for name, text in su2.items():
        write("su2", name, text)

    for name, text in {"tet_22.msh": TET_22, "tet_41.msh": TET_41, "tet_22_named.msh": TET_22_NAMED}.items():
        write("gmsh", name, text)

    for example in sorted((ROOT / "examples" / "motions").glob("*.json")):
        write("motion", example.name, example.read_text())
    for name, text in MOTIONS.items():
        write("motion", name, text)

    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        for stem in ("quad_grid_2d", "mixed_3d"):
            mesh = CORPUS / "su2" / f"{stem}.su2"
            for version in ("41", "22"):
                out = tmp / f"{stem}_{version}.msh"
                subprocess.run([cli, "convert", mesh, out, "--gmsh-version", version], check=True, stdout=subprocess.DEVNULL)
                write("gmsh", out.name, out.read_bytes())
        plans = {
            "quad_grid_2d": '{"markers": {"lower": {"translate": [0, 0.05]}}}',
            "mixed_3d": '{"markers": {"top": {"rotate": {"angle_deg": 2, "axis": [1, 0, 0], "center": [0, 0, 1]}}}}',
        }
        for stem, motion in plans.items():
            motion_file = tmp / f"{stem}.json"
            motion_file.write_text(motion)
            big = tmp / f"{stem}.su2"
            big.write_text(quad_grid_2d(6, 5) if stem == "quad_grid_2d" else MIXED_3D)
            for method in ("dg-idw", "dg-harmonic"):
                suffix = "" if method == "dg-idw" else "_harmonic"
                out = tmp / f"{stem}{suffix}.plan"
                # A dense coarse level, so that these small meshes have coarse points and a factor.
                extra = [] if method == "dg-idw" else ["--harmonic-wall-spacing", "1", "--harmonic-growth", "0.5"]
                subprocess.run([cli, "prepare", big, "-m", motion_file, "-o", out, "-q", "--method", method, *extra],
                               check=True)
                write("plan", out.name, out.read_bytes())

    # OpenFOAM: the five polyMesh files of a case joined by the separator of
    # fuzz_checks.hpp; the committed cases and the mixed SU2 mesh written by dgwarp.
    def foam_seed(poly_mesh):
        names = ("points", "faces", "owner", "neighbour", "boundary")
        return FOAM_SEPARATOR.join((poly_mesh / n).read_bytes() for n in names)

    for case in ("cavity", "cavity-binary", "mixed-binary"):
        write("openfoam", f"{case}.foam", foam_seed(ROOT / "tests" / "data" / "openfoam" / case / "constant" / "polyMesh"))
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        # MIXED_3D's prism turns its first triangle toward the second (mirrored in
        # VTK's order): OpenFOAM's faces cannot hold it beside the hexahedron.
        (tmp / "mixed_3d.su2").write_text(MIXED_3D.replace("13 1 8 2 5 9 6", "13 1 2 8 5 6 9"))
        for fmt in ("ascii", "binary"):
            subprocess.run([cli, "convert", "-q", tmp / "mixed_3d.su2", tmp / fmt, "--foam-format", fmt], check=True)
            write("openfoam", f"mixed_3d_{fmt}.foam", foam_seed(tmp / fmt / "constant" / "polyMesh"))

    # CGNS: the small files the CGNS project's converters made (tests/data/cgns),
    # HDF5 and ADF, and a 2D one of dgwarp's writer.
    for name in ("tet.cgns", "tet-adf.cgns", "mixed-adf.cgns"):
        write("cgns", name, (ROOT / "tests" / "data" / "cgns" / name).read_bytes())
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        (tmp / "base_2d.su2").write_text(BASE_2D)
        subprocess.run([cli, "convert", "-q", tmp / "base_2d.su2", tmp / "base_2d.cgns"], check=True)
        write("cgns", "base_2d.cgns", (tmp / "base_2d.cgns").read_bytes())

    # VTU: dgwarp's writer (binary, markers in FieldData) and meshio's (ascii,
    # and binary with zlib; markers as gmsh:physical cell data).
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        for stem in ("quad_grid_2d", "mixed_3d"):
            out = tmp / f"{stem}.vtu"
            subprocess.run([cli, "convert", "-q", CORPUS / "su2" / f"{stem}.su2", out], check=True)
            write("vtu", out.name, out.read_bytes())
        import meshio  # Debian's python3-meshio
        import numpy as np

        tet = meshio.Mesh(
            np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]]),
            [("tetra", np.array([[0, 1, 2, 3], [1, 2, 3, 4]])), ("triangle", np.array([[0, 1, 2]]))],
            cell_data={"gmsh:physical": [np.array([1, 1]), np.array([7])]},
            field_data={"bottom": np.array([7, 2])},
        )
        for name, options in {"tet_ascii.vtu": {"binary": False},
                              "tet_zlib.vtu": {"binary": True, "compression": "zlib"}}.items():
            meshio.write(tmp / name, tet, file_format="vtu", **options)
            write("vtu", name, (tmp / name).read_bytes())

    total = sum(p.stat().st_size for p in CORPUS.rglob("*") if p.is_file())
    print(f"wrote {sum(1 for p in CORPUS.rglob('*') if p.is_file())} seeds, {total} bytes, in {CORPUS}")


if __name__ == "__main__":
    main()
