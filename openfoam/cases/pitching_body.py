#!/usr/bin/python3
"""A pitching and plunging body in a channel: an OpenFOAM case for dgwarp's
motion solver (docs/OPENFOAM.md, "dgwarp as OpenFOAM's motion solver").

The channel x in [-3, 5], y and z in [-1.5, 1.5] holds a thick plate
x in [-0.5, 0.5], y in [-0.1, 0.1], z in [-0.5, 0.5]; blockMesh makes the 26
blocks around it, hexahedra graded towards the plate (about 50,400 cells at
--resolution 1, times resolution^3). The plate pitches about the z axis
through its centre, amplitude_deg * sin(2 pi f t), and plunges along y,
plunge * sin(2 pi f t) (pointDisplacement: solidBodyMotionDisplacement with a
multiMotion of oscillatingRotatingMotion and oscillatingLinearMotion); the
channel's patches (inlet, outlet, walls) stay.

    pitching_body.py CASE [--resolution R] [--solver dgwarp|displacementLaplacian]
                          [--method M] [--option NAME=VALUE ...] [--steps N] [--dt DT]
                          [--amplitude-deg A] [--plunge P] [--frequency F]
                          [--application moveDynamicMesh|pimpleFoam] [--processors P]

It writes the case's dictionaries (blockMesh is the caller's: `blockMesh -case CASE`).
Decompose with `decomposePar -copyZero` (v1912 cannot map multiMotion's
dictionary onto the processors: "Entry 'solidBodyMotionFunction' not found").
--solver displacementLaplacian sets up OpenFOAM's own solver as
bench/peers/openfoam.sh's "converged" set-up (inverseDistance to the plate,
GAMG, 20 V-cycles per solve). Standard library only.
"""
import argparse
import os

HEADER = "FoamFile {{ version 2.0; format ascii; class {cls}; object {obj}; }}\n"

X = (-3.0, -0.5, 0.5, 5.0)
Y = (-1.5, -0.1, 0.1, 1.5)
Z = (-1.5, -0.5, 0.5, 1.5)
CELLS = ((10, 20, 14), (12, 6, 12), (10, 20, 10))  # per interval of X, Y, Z at resolution 1
GRADING = (0.25, 1.0, 4.0)  # per interval: the cells grow away from the plate


def write(case, path, text):
    full = os.path.join(case, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, "w") as f:
        f.write(text)


def block_mesh_dict(resolution):
    def v(i, j, k):
        return i + 4 * j + 16 * k

    vertices = [f"    ({X[i]} {Y[j]} {Z[k]})" for k in range(4) for j in range(4) for i in range(4)]
    counts = [[max(1, round(n * resolution)) for n in axis] for axis in CELLS]
    blocks, patches = [], {"inlet": [], "outlet": [], "walls": [], "body": []}
    hex_faces = {  # blockMesh's outward faces of a hex (local vertex numbers)
        "x-": (0, 4, 7, 3), "x+": (1, 2, 6, 5), "y-": (0, 1, 5, 4),
        "y+": (3, 7, 6, 2), "z-": (0, 3, 2, 1), "z+": (4, 5, 6, 7)}
    for k in range(3):
        for j in range(3):
            for i in range(3):
                if (i, j, k) == (1, 1, 1):
                    continue  # the plate
                corners = [v(i, j, k), v(i + 1, j, k), v(i + 1, j + 1, k), v(i, j + 1, k),
                           v(i, j, k + 1), v(i + 1, j, k + 1), v(i + 1, j + 1, k + 1), v(i, j + 1, k + 1)]
                blocks.append("    hex ({}) ({} {} {}) simpleGrading ({} {} {})".format(
                    " ".join(map(str, corners)), counts[0][i], counts[1][j], counts[2][k],
                    GRADING[i], GRADING[j], GRADING[k]))

                def face(name):
                    return "({})".format(" ".join(str(corners[c]) for c in hex_faces[name]))

                if i == 0: patches["inlet"].append(face("x-"))
                if i == 2: patches["outlet"].append(face("x+"))
                if j == 0: patches["walls"].append(face("y-"))
                if j == 2: patches["walls"].append(face("y+"))
                if k == 0: patches["walls"].append(face("z-"))
                if k == 2: patches["walls"].append(face("z+"))
                # The faces towards the plate.
                if (j, k) == (1, 1) and i == 0: patches["body"].append(face("x+"))
                if (j, k) == (1, 1) and i == 2: patches["body"].append(face("x-"))
                if (i, k) == (1, 1) and j == 0: patches["body"].append(face("y+"))
                if (i, k) == (1, 1) and j == 2: patches["body"].append(face("y-"))
                if (i, j) == (1, 1) and k == 0: patches["body"].append(face("z+"))
                if (i, j) == (1, 1) and k == 2: patches["body"].append(face("z-"))
    types = {"inlet": "patch", "outlet": "patch", "walls": "wall", "body": "wall"}
    boundary = "\n".join(
        f"    {name}\n    {{\n        type {types[name]};\n        faces\n        (\n" +
        "\n".join("            " + f for f in faces) + "\n        );\n    }"
        for name, faces in patches.items())
    return (HEADER.format(cls="dictionary", obj="blockMeshDict") + "scale 1;\nvertices\n(\n" +
            "\n".join(vertices) + "\n);\nblocks\n(\n" + "\n".join(blocks) +
            "\n);\nedges ();\nboundary\n(\n" + boundary + "\n);\nmergePatchPairs ();\n")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("case")
    p.add_argument("--resolution", type=float, default=1.0)
    p.add_argument("--solver", choices=["dgwarp", "displacementLaplacian"], default="dgwarp")
    p.add_argument("--method", default=None, help="dgwarpCoeffs' method (default: dgwarp's, dg-harmonic)")
    p.add_argument("--option", action="append", default=[], metavar="NAME=VALUE",
                   help="a dgwarpCoeffs entry, e.g. harmonic-wall-spacing=4 or allowInverted=true")
    p.add_argument("--steps", type=int, default=50)
    p.add_argument("--dt", type=float, default=0.01)
    p.add_argument("--write-interval", type=int, default=None, help="time steps between writes (default: every 10th, and the last)")
    p.add_argument("--amplitude-deg", type=float, default=10.0)
    p.add_argument("--plunge", type=float, default=0.25)
    p.add_argument("--frequency", type=float, default=1.0)
    p.add_argument("--application", choices=["moveDynamicMesh", "pimpleFoam"], default="moveDynamicMesh")
    p.add_argument("--processors", type=int, default=2)
    a = p.parse_args()

    case = a.case
    omega = 2 * 3.141592653589793 * a.frequency
    end = a.steps * a.dt
    interval = a.write_interval or max(1, min(10, a.steps))
    write(case, "system/blockMeshDict", block_mesh_dict(a.resolution))
    fluid = a.application == "pimpleFoam"
    write(case, "system/controlDict", HEADER.format(cls="dictionary", obj="controlDict") + f"""
application     {a.application};
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         {end!r};
deltaT          {a.dt!r};
writeControl    timeStep;
writeInterval   {interval};
purgeWrite      0;
writeFormat     ascii;
writePrecision  17;
writeCompression off;
timeFormat      general;
timePrecision   8;
runTimeModifiable false;
""")
    solvers = """
    "cellDisplacement.*" { solver GAMG; smoother GaussSeidel; tolerance 0; relTol 0; minIter 20; maxIter 20; }"""
    if fluid:
        solvers += """
    p { solver GAMG; smoother GaussSeidel; tolerance 1e-6; relTol 0.05; }
    pFinal { $p; relTol 0; }
    "(U|UFinal)" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-6; relTol 0; }
    pcorr { solver GAMG; smoother GaussSeidel; tolerance 1e-6; relTol 0; }
    pcorrFinal { $pcorr; }"""
    write(case, "system/fvSolution", HEADER.format(cls="dictionary", obj="fvSolution") +
          "solvers\n{" + solvers + "\n}\n" +
          ("PIMPLE { nOuterCorrectors 1; nCorrectors 2; nNonOrthogonalCorrectors 0; correctPhi yes; }\n" if fluid else ""))
    write(case, "system/fvSchemes", HEADER.format(cls="dictionary", obj="fvSchemes") + """
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; div(phi,U) Gauss linearUpwind grad(U); div((nuEff*dev2(T(grad(U))))) Gauss linear; }
laplacianSchemes { default Gauss linear uncorrected; }
interpolationSchemes { default linear; }
snGradSchemes { default uncorrected; }
""")
    write(case, "system/decomposeParDict", HEADER.format(cls="dictionary", obj="decomposeParDict") +
          f"numberOfSubdomains {a.processors};\nmethod simple;\nsimpleCoeffs {{ n ({a.processors} 1 1); delta 0.001; }}\n")
    if a.solver == "dgwarp":
        entries = [f"    method {a.method};"] if a.method else []
        for o in a.option:
            name, _, value = o.partition("=")
            entries.append(f"    {name} {value};")
        solver = ('motionSolverLibs ("libdgwarpFoam.so");\nmotionSolver dgwarp;\ndgwarpCoeffs\n{\n' +
                  "\n".join(entries) + "\n}\n")
    else:
        solver = ('motionSolverLibs ("libfvMotionSolvers.so");\nmotionSolver displacementLaplacian;\n'
                  "displacementLaplacianCoeffs { diffusivity inverseDistance (body); }\n")
    write(case, "constant/dynamicMeshDict", HEADER.format(cls="dictionary", obj="dynamicMeshDict") +
          "dynamicFvMesh dynamicMotionSolverFvMesh;\n" + solver)
    write(case, "0/pointDisplacement", HEADER.format(cls="pointVectorField", obj="pointDisplacement") + f"""
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{{
    body
    {{
        type solidBodyMotionDisplacement;
        solidBodyMotionFunction multiMotion;
        multiMotionCoeffs
        {{
            pitch
            {{
                solidBodyMotionFunction oscillatingRotatingMotion;
                oscillatingRotatingMotionCoeffs {{ origin (0 0 0); amplitude (0 0 {a.amplitude_deg!r}); omega {omega!r}; }}
            }}
            plunge
            {{
                solidBodyMotionFunction oscillatingLinearMotion;
                oscillatingLinearMotionCoeffs {{ amplitude (0 {a.plunge!r} 0); omega {omega!r}; }}
            }}
        }}
        value uniform (0 0 0);
    }}
    "(inlet|outlet|walls)" {{ type fixedValue; value uniform (0 0 0); }}
    #includeEtc "caseDicts/setConstraintTypes"
}}
""")
    if fluid:
        write(case, "constant/transportProperties", HEADER.format(cls="dictionary", obj="transportProperties") +
              "transportModel Newtonian;\nnu 0.01;\n")
        write(case, "constant/turbulenceProperties", HEADER.format(cls="dictionary", obj="turbulenceProperties") +
              "simulationType laminar;\n")
        write(case, "0/U", HEADER.format(cls="volVectorField", obj="U") + """
dimensions [0 1 -1 0 0 0 0];
internalField uniform (1 0 0);
boundaryField
{
    inlet { type fixedValue; value uniform (1 0 0); }
    outlet { type zeroGradient; }
    walls { type slip; }
    body { type movingWallVelocity; value uniform (0 0 0); }
    #includeEtc "caseDicts/setConstraintTypes"
}
""")
        write(case, "0/p", HEADER.format(cls="volScalarField", obj="p") + """
dimensions [0 2 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    inlet { type zeroGradient; }
    outlet { type fixedValue; value uniform 0; }
    walls { type zeroGradient; }
    body { type zeroGradient; }
    #includeEtc "caseDicts/setConstraintTypes"
}
""")


if __name__ == "__main__":
    main()
