"""`pip install .` (docs/PYTHON.md, "Set-up"): into a venv with the system's packages, from a wheel
into a second venv, and into a user site, offline with Debian's setuptools, wheel, pybind11 and
NumPy. The module is built in the project's build folder (DGWARP_CMAKE_BUILD_DIR, see setup.py),
where ctest's build already made it: these tests check the packaging, not the compiler."""

import os
import pathlib
import subprocess
import sys

import pytest

from conftest import CLI, SOURCE_DIR

CHECK = (
    "import pickle, dgwarp, numpy as np\n"
    "mesh = dgwarp.Mesh.from_arrays(np.array([[0., 0], [1, 0], [1, 1], [0, 1], [0.5, 0.4]]),\n"
    "    {'triangle': [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]}, {'box': [[0, 1], [1, 2], [2, 3], [3, 0]]})\n"
    "plan = pickle.loads(pickle.dumps(dgwarp.prepare(mesh, [], method='dg-idw')))\n"
    "print(dgwarp.__version__, dgwarp.__file__, plan.deform({'markers': {}})[4].tolist())\n"
)


def project_version():
    text = (SOURCE_DIR / "CMakeLists.txt").read_text()
    return text.split("project(dgwarp VERSION ", 1)[1].split()[0]


@pytest.fixture(scope="module")
def build_env():
    build = CLI.parent
    if not (build / "CMakeCache.txt").exists():
        pytest.skip(f"no CMake build folder beside the CLI ({build})")
    env = dict(os.environ, DGWARP_CMAKE_BUILD_DIR=str(build), DGWARP_BUILD_JOBS="1")
    env.pop("PYTHONPATH", None)  # the installed package, not build/python
    return env


def run(args, env, cwd):
    result = subprocess.run([str(a) for a in args], capture_output=True, text=True, env=env, cwd=cwd)
    assert result.returncode == 0, f"{' '.join(map(str, args))} exited {result.returncode}:\n{result.stdout}\n{result.stderr}"
    return result.stdout


def check_import(python, env, cwd, root):
    version, file, moved = run([python, "-c", CHECK], env, cwd).split(" ", 2)
    assert version == project_version()
    assert pathlib.Path(file).resolve().is_relative_to(pathlib.Path(root).resolve()), file
    assert moved.strip() == "[0.5, 0.4]"


def test_pip_install_into_a_venv_and_a_wheel_into_another(tmp_path, build_env):
    run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", tmp_path / "v"], build_env, tmp_path)
    pip = tmp_path / "v" / "bin" / "pip"
    run([pip, "install", "--no-build-isolation", "--no-index", SOURCE_DIR], build_env, tmp_path)
    check_import(tmp_path / "v" / "bin" / "python", build_env, tmp_path, tmp_path / "v")

    run([pip, "wheel", "--no-build-isolation", "--no-index", "--no-deps", "-w", tmp_path / "dist", SOURCE_DIR],
        build_env, tmp_path)
    wheels = list((tmp_path / "dist").glob("dgwarp-*.whl"))
    assert len(wheels) == 1 and project_version() in wheels[0].name
    run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", tmp_path / "w"], build_env, tmp_path)
    run([tmp_path / "w" / "bin" / "pip", "install", "--no-index", wheels[0]], build_env, tmp_path)
    check_import(tmp_path / "w" / "bin" / "python", build_env, tmp_path, tmp_path / "w")


def test_pip_install_into_the_user_site(tmp_path, build_env):
    # A user base of our own; Debian's Python refuses user installs (PEP 668) without the flag.
    env = dict(build_env, PYTHONUSERBASE=str(tmp_path / "user"))
    run(["/usr/bin/python3", "-m", "pip", "install", "--user", "--break-system-packages", "--no-build-isolation",
         "--no-index", SOURCE_DIR], env, tmp_path)
    check_import("/usr/bin/python3", env, tmp_path, tmp_path / "user")
