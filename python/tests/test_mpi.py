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
             lambda: plan.deform_derivative(np.zeros((len(plan.boundary_nodes), 2)))):
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


SAVE_AND_LOAD = """
import sys, numpy as np, pytest, dgwarp
from mpi4py import MPI
sys.path.insert(0, sys.argv[1])
from mpi_deform import my_part
comm = MPI.COMM_WORLD
mode, method, path = sys.argv[2], sys.argv[3], sys.argv[4]
mesh = dgwarp.case("naca0012")
part, ids = my_part(mesh, comm.rank, comm.size)
motion = {"markers": {"airfoil": {"rotate": {"angle_deg": 4, "center": [0.25, 0]}}}}
if mode == "save":
    plan = dgwarp.prepare(part, ["airfoil"], method=method, comm=comm, global_ids=ids)
    plan.save(path)
    np.save(f"{path}.{comm.rank}.npy", plan.deform(motion))
elif mode == "load":
    plan = dgwarp.load_plan(path, part, ["airfoil"], comm=comm, global_ids=ids)
    assert plan.method == method
    assert np.array_equal(plan.deform(motion), np.load(f"{path}.{comm.rank}.npy"))
elif mode == "other-parts":  # the parts of the processes swapped: every process refuses
    part, ids = my_part(mesh, comm.size - 1 - comm.rank, comm.size)
    with pytest.raises(dgwarp.Error, match="other points|failed to load"):
        dgwarp.load_plan(path, part, ["airfoil"], comm=comm, global_ids=ids)
elif mode == "refused":  # another number of processes, or a damaged file: every process raises
    with pytest.raises(dgwarp.Error, match=sys.argv[5]):
        dgwarp.load_plan(path, part, ["airfoil"], comm=comm, global_ids=ids)
print("ok", comm.rank)
"""


@pytest.mark.parametrize("method", ["dg-idw", "dg-harmonic"])
def test_a_distributed_plan_saves_and_loads(tmp_path, method):
    (tmp_path / "save_load.py").write_text(SAVE_AND_LOAD)
    examples = SOURCE_DIR / "examples" / "python"
    plan = tmp_path / "parts.plan"
    run = lambda np_, *args: mpirun(np_, tmp_path / "save_load.py", examples, *args, cwd=tmp_path)
    assert run(2, "save", method, plan).count("ok") == 2
    assert run(2, "load", method, plan).count("ok") == 2  # the same bits as the plan that was saved
    assert run(2, "other-parts", method, plan).count("ok") == 2
    assert run(3, "refused", method, plan, "for 3 processes").count("ok") == 3
    damaged = bytearray(plan.read_bytes())
    damaged[len(damaged) // 2] ^= 0xFF
    plan.write_bytes(bytes(damaged))
    assert run(2, "refused", method, plan, "checksum").count("ok") == 2
