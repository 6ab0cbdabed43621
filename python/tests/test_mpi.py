"""prepare(comm=...) from Python under mpirun (docs/PYTHON.md, "MPI"): each process's part gives
the one-process result bit for bit, and what a distributed plan cannot do is refused."""

import os
import shutil
import subprocess
import sys

import pytest

import dgwarp
from conftest import SOURCE_DIR

pytest.importorskip("mpi4py")
MPIRUN = shutil.which("mpirun")
if MPIRUN is None or not dgwarp._core._has_mpi:
    pytest.skip("no mpirun, or dgwarp built without MPI and mpi4py", allow_module_level=True)

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMP_NUM_THREADS="1")


def mpirun(np_, *args, cwd):
    result = subprocess.run([MPIRUN, "--oversubscribe", "--bind-to", "none", "-np", str(np_), sys.executable,
                             *map(str, args)], capture_output=True, text=True, env=ENV, cwd=cwd, timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr
    return result.stdout


@pytest.mark.parametrize("method", ["dg-idw", "dg-harmonic"])
def test_processes_give_the_one_process_result_bit_for_bit(tmp_path, method):
    out = mpirun(2, SOURCE_DIR / "examples" / "python" / "mpi_deform.py", "--check", "--method", method, cwd=tmp_path)
    assert "2 processes" in out and "bit-identical to one process: True" in out


REFUSALS = """
import numpy as np, pytest, dgwarp
from mpi4py import MPI
mesh = dgwarp.case("naca0012")
ids = np.arange(mesh.num_points)
with pytest.raises(TypeError, match="mpi4py.MPI.Comm"):
    dgwarp.prepare(mesh, ["airfoil"], comm=object(), global_ids=ids)
with pytest.raises(TypeError, match="global_ids"):
    dgwarp.prepare(mesh, ["airfoil"], comm=MPI.COMM_WORLD)
with pytest.raises(ValueError, match="global_ids is for"):
    dgwarp.prepare(mesh, ["airfoil"], global_ids=ids)
with pytest.raises(ValueError, match="ids for"):
    dgwarp.prepare(mesh, ["airfoil"], comm=MPI.COMM_WORLD, global_ids=ids[:-1])
plan = dgwarp.prepare(mesh, ["airfoil"], method="dg-idw", comm=MPI.COMM_WORLD, global_ids=ids)
motion = {"markers": {"airfoil": {"translate": [0.01, 0]}}}
assert np.array_equal(plan.deform(motion), dgwarp.prepare(mesh, ["airfoil"], method="dg-idw").deform(motion))
for call in (lambda: plan.deform(motion, report=True), lambda: plan.deform(motion, untangle=True),
             lambda: plan.save("x.plan"), lambda: plan.deform_derivative(np.zeros((len(plan.boundary_nodes), 2)))):
    with pytest.raises(ValueError, match="comm="):
        call()
import pickle
with pytest.raises(TypeError, match="does not pickle"):
    pickle.dumps(plan)
print("refusals ok")
"""


def test_what_a_distributed_plan_refuses(tmp_path):
    (tmp_path / "refusals.py").write_text(REFUSALS)
    assert "refusals ok" in mpirun(1, tmp_path / "refusals.py", cwd=tmp_path)
