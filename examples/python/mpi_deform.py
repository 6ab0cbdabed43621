"""The NACA0012 case deformed by several MPI processes from Python, each holding its part.

    mpirun -np 2 python3 examples/python/mpi_deform.py [--method dg-idw] [--angle 5] [--check]

Each process cuts its part from the whole case (a solver would have only its part): the cells
whose centroid falls in its share of the x range, their nodes (global_ids: their ids in the whole
mesh) and the boundary elements among them. It prepares with comm=MPI.COMM_WORLD, together with
the others, and deforms a pitch of the airfoil: its own nodes' new coordinates. Rank 0 gathers
them; with --check it also deforms the whole mesh alone and compares: bit for bit (docs/MPI.md).
"""

import argparse

import numpy as np
from mpi4py import MPI

import dgwarp


def my_part(mesh, rank, size):
    """This process's part: (its mesh, the global id of each of its nodes)."""
    cells = mesh.cells["triangle"]
    x = mesh.points[cells].mean(axis=1)[:, 0]
    owner = np.searchsorted(np.quantile(x, np.linspace(0, 1, size + 1))[1:-1], x, side="right")
    mine = cells[owner == rank]
    nodes = np.unique(mine)
    if rank == 0:  # nodes no cell uses (the case has one) go to process 0
        nodes = np.union1d(nodes, np.setdiff1d(np.arange(mesh.num_points), cells))
    local = np.full(mesh.num_points, -1)
    local[nodes] = np.arange(len(nodes))
    markers = {}
    for name in mesh.marker_names:
        lines = mesh.markers[name].elements["line"]
        markers[name] = local[lines[(local[lines] >= 0).all(axis=1)]]  # may be empty on this process
    return dgwarp.Mesh.from_arrays(mesh.points[nodes], {"triangle": local[mine]}, markers), nodes


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--method", default="dg-idw", help="dg-idw, dg-harmonic, idw, rbf or dgm")
    parser.add_argument("--angle", type=float, default=5.0, help="the pitch, degrees")
    parser.add_argument("--check", action="store_true", help="compare with one process on rank 0")
    args = parser.parse_args()
    comm = MPI.COMM_WORLD

    mesh = dgwarp.case("naca0012")
    part, ids = my_part(mesh, comm.rank, comm.size)
    motion = {"markers": {"airfoil": {"rotate": {"angle_deg": args.angle, "center": [0.25, 0]}}}}
    plan = dgwarp.prepare(part, ["airfoil"], method=args.method, comm=comm, global_ids=ids)
    moved = plan.deform(motion)  # collective: every process steps together

    parts = comm.gather((ids, moved), root=0)
    if comm.rank != 0:
        return
    result = np.full_like(mesh.points, np.nan)
    for part_ids, part_points in parts:
        result[part_ids] = part_points  # interface nodes: every holder has the same coordinates
    print(f"{comm.size} processes, {args.method}: {mesh.num_points} nodes, parts of "
          f"{', '.join(str(len(i)) for i, _ in parts)} nodes")
    if args.check:
        # One process, the same method (DG-harmonic without its guard, which a part does not have).
        options = {"harmonic_redo_below": -1} if args.method == "dg-harmonic" else {}
        alone = dgwarp.prepare(mesh, ["airfoil"], method=args.method, **options).deform(motion, untangle=False)
        same = np.array_equal(result, alone)
        print(f"bit-identical to one process: {same}")
        if not same:
            raise SystemExit(1)


if __name__ == "__main__":
    main()
