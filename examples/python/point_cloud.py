"""A point cloud deformed as a mesh's volume nodes: no cells, markers by node ids.

    PYTHONPATH=build/python python3 examples/python/point_cloud.py [--angle 20] [-o cloud.csv]

An ellipse of 60 points turns about its centre inside the eight points of a fixed box; 3,000
random points between them follow, as the volume nodes of a mesh would (the ellipse's nodes
exactly, the box's not at all). Writes x, y, new x, new y per point.
"""

import argparse

import numpy as np

import dgwarp


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--angle", type=float, default=20.0, help="the ellipse's turn, degrees")
    parser.add_argument("--method", default="dg-idw", help="any method but laplacian")
    parser.add_argument("-o", "--output", default="cloud.csv", help="CSV output")
    args = parser.parse_args()

    t = np.linspace(0, 2 * np.pi, 60, endpoint=False)
    ellipse = np.c_[0.3 * np.cos(t), 0.1 * np.sin(t)]
    box = np.array([[-1, -1], [0, -1], [1, -1], [1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0]], dtype=float)
    rng = np.random.default_rng(1)
    cloud = rng.uniform(-0.98, 0.98, (4000, 2))
    cloud = cloud[(cloud[:, 0] / 0.33) ** 2 + (cloud[:, 1] / 0.13) ** 2 > 1][:3000]  # outside the ellipse
    points = np.r_[ellipse, box, cloud]
    mesh = dgwarp.Mesh.point_cloud(points, {"ellipse": np.arange(60), "box": 60 + np.arange(8)})

    plan = dgwarp.prepare(mesh, ["ellipse"], method=args.method)
    moved = plan.deform({"markers": {"ellipse": {"rotate": {"angle_deg": args.angle, "center": [0, 0]}}}})
    np.savetxt(args.output, np.c_[points, moved], delimiter=",", header="x,y,new_x,new_y", comments="")
    shift = np.hypot(*(moved - points).T)
    print(f"{mesh.num_points} points, {plan.method}: the ellipse turned {args.angle} degrees; "
          f"the cloud moved up to {shift[68:].max():.4f}, the box {shift[60:68].max():.1f}; wrote {args.output}")


if __name__ == "__main__":
    main()
