"""Shared fixtures of the Python package's tests.

ctest runs them with PYTHONPATH=build/python and DGWARP_CLI, DGWARP_SOURCE_DIR and
DGWARP_SHARED_MESHES set (python/CMakeLists.txt); by hand, from the repository's folder:
    PYTHONPATH=build/python /usr/bin/python3 -m pytest python/tests
"""

import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("DGWARP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
CLI = pathlib.Path(os.environ.get("DGWARP_CLI", SOURCE_DIR / "build" / "dgwarp"))
SHARED_MESHES = pathlib.Path(os.environ.get("DGWARP_SHARED_MESHES", SOURCE_DIR.parent / "shared" / "meshes"))
MOTIONS = SOURCE_DIR / "examples" / "motions"


def run_cli(*args, check=True):
    """Runs the dgwarp CLI; returns the completed process (text output)."""
    result = subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True)
    if check and result.returncode != 0:
        raise AssertionError(f"dgwarp {' '.join(map(str, args))} exited {result.returncode}:\n{result.stderr}")
    return result


def cli_json(*args):
    return json.loads(run_cli(*args, "--json").stdout)


@pytest.fixture(scope="session")
def cli():
    if not CLI.exists():
        pytest.skip(f"the CLI is not built ({CLI})")
    return run_cli


@pytest.fixture(scope="session")
def naca_file(tmp_path_factory, cli):
    """The naca0012 case written by `dgwarp case` (1,656 nodes, markers airfoil and farfield)."""
    path = tmp_path_factory.mktemp("naca") / "naca0012.su2"
    cli("case", "naca0012", "-o", path)
    return path


@pytest.fixture(scope="session")
def su2_meshes():
    folder = SHARED_MESHES / "su2"
    if not folder.is_dir():
        pytest.skip(f"the shared SU2 meshes are not here ({folder})")
    return folder


def grid_with_hole(n):
    """A square [0, 1]^2 of n x n squares, two triangles each, without the squares inside
    [0.4, 0.6]^2; markers "box" (the outer sides) and "body" (the hole's sides). Nodes inside the
    hole belong to no cell: they move as volume nodes. (n + 1)^2 nodes."""
    import numpy as np

    import dgwarp

    xs = np.linspace(0.0, 1.0, n + 1)
    points = np.stack(np.meshgrid(xs, xs, indexing="xy"), axis=-1).reshape(-1, 2)
    node = np.arange((n + 1) ** 2).reshape(n + 1, n + 1)  # node[j, i] at (xs[i], xs[j])
    lo, hi = round(0.4 * n), round(0.6 * n)
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="xy")
    keep = ~((i >= lo) & (i < hi) & (j >= lo) & (j < hi))
    i, j = i[keep], j[keep]
    a, b, c, d = node[j, i], node[j, i + 1], node[j + 1, i + 1], node[j + 1, i]
    triangles = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])

    def ring(i0, i1):
        # The square [i0, i1]^2's sides, counter-clockwise.
        path = ([node[i0, k] for k in range(i0, i1)] + [node[k, i1] for k in range(i0, i1)]
                + [node[i1, k] for k in range(i1, i0, -1)] + [node[k, i0] for k in range(i1, i0, -1)])
        return np.stack([path, np.roll(path, -1)], 1)

    return dgwarp.Mesh.from_arrays(points, {"triangle": triangles}, {"box": ring(0, n), "body": ring(lo, hi)})
