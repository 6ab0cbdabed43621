"""The examples in examples/python/ run (with small sizes) and write what they say."""

import os
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

EXAMPLES = SOURCE_DIR / "examples" / "python"


def run_example(name, *args, cwd):
    result = subprocess.run([sys.executable, str(EXAMPLES / name), *map(str, args)], cwd=cwd, capture_output=True,
                            text=True, env=dict(os.environ), timeout=300)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_pitching_airfoil_writes_one_vtu_per_frame(tmp_path):
    out = run_example("pitching_airfoil.py", "--frames", 4, "--out", "frames", cwd=tmp_path)
    assert sorted(p.name for p in (tmp_path / "frames").iterdir()) == [f"pitch_{k:04d}.vtu" for k in range(4)]
    assert "4 frames" in out


def test_shape_optimisation_loop_runs_its_steps(tmp_path):
    out = run_example("shape_optimisation_loop.py", "--steps", 20, cwd=tmp_path)
    assert "20 deformations" in out and "best design" in out


@pytest.mark.parametrize("method", ["dg-idw", "dg-harmonic"])
def test_adjoint_gradient_matches_finite_differences_and_descends(tmp_path, method):
    out = run_example("adjoint_gradient.py", "--steps", 3, "--method", method, cwd=tmp_path)
    assert float(out.split("largest relative difference ")[1].split(")")[0]) < 1e-6
    f = [float(line.split("f = ")[1].split(",")[0]) for line in out.splitlines() if line.startswith("step ")]
    assert len(f) == 3 and f[0] > f[1] > f[2]


def test_point_cloud_writes_its_points(tmp_path):
    out = run_example("point_cloud.py", "--angle", 10, "-o", "c.csv", cwd=tmp_path)
    rows = (tmp_path / "c.csv").read_text().splitlines()
    assert rows[0] == "x,y,new_x,new_y" and len(rows) == 1 + 3068
    assert "the box 0.0" in out


def test_quality_histogram_writes_a_png(tmp_path):
    pytest.importorskip("matplotlib")
    run_example("quality_histogram.py", "--methods", "dg-idw", "-o", "q.png", cwd=tmp_path)
    assert (tmp_path / "q.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_readmes_python_block_runs(tmp_path, cli):
    readme = (SOURCE_DIR / "README.md").read_text()
    section = readme[readme.index("\n## Python\n"):]
    block = section[section.index("```python\n") + len("```python\n"):]
    block = block[: block.index("```")]
    cli("case", "naca0012", "-o", tmp_path / "naca0012.su2")
    (tmp_path / "readme.py").write_text(block)
    result = subprocess.run([sys.executable, "readme.py"], cwd=tmp_path, capture_output=True, text=True,
                            env=dict(os.environ), timeout=300)
    assert result.returncode == 0, result.stderr
    assert "dgwarp.Quality(" in result.stdout and (tmp_path / "turned.vtu").exists()
