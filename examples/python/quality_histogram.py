"""The cell quality before and after a deformation, as histograms (matplotlib), saved as PNG.

    PYTHONPATH=build/python python3 examples/python/quality_histogram.py [--angle 30] [-o quality.png]

The NACA0012 case turned about its quarter chord with each method; the histogram bins are
dgwarp's (docs/QUALITY.md): (-inf, 0] (inverted), (0, 0.1], ..., (0.9, 1].
"""

import argparse

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt
import numpy as np

import dgwarp


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--angle", type=float, default=30.0, help="rotation of the airfoil, degrees")
    parser.add_argument("--methods", default="dg-idw,idw,dg-harmonic", help="comma-separated methods")
    parser.add_argument("-o", "--output", default="quality.png", help="PNG file")
    args = parser.parse_args()

    mesh = dgwarp.case("naca0012")
    turn = {"markers": {"airfoil": {"rotate": {"angle_deg": args.angle, "center": [0.25, 0]}}}}
    before = dgwarp.quality(mesh)
    edges, counts = before.histogram
    labels = ["<= 0"] + [f"{lo:.1f}-{hi:.1f}" for lo, hi in zip(edges[1:-1], edges[2:])]
    series = [("original", counts, before.min)]
    for method in args.methods.split(","):
        points = dgwarp.prepare(mesh, moving=["airfoil"], method=method).deform(turn)
        after = dgwarp.quality(mesh, points=points)
        series.append((f"{method} (ratio min {after.ratio_min:.3f})", after.histogram[1], after.min))

    fig, ax = plt.subplots(figsize=(9, 4.5))
    width = 0.8 / len(series)
    for i, (name, c, q_min) in enumerate(series):
        ax.bar(np.arange(len(labels)) + (i - (len(series) - 1) / 2) * width, c, width,
               label=f"{name}: min {q_min:.3f}")
    ax.set_xticks(np.arange(len(labels)), labels, rotation=45)
    ax.set_yscale("log")
    ax.set_xlabel("Knupp shape quality")
    ax.set_ylabel("cells")
    ax.set_title(f"NACA0012 ({mesh.num_cells} cells) turned {args.angle:g} degrees about the quarter chord")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=100)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
