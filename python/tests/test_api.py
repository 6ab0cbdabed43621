"""The public API: every name has a docstring and a type hint in the stub, and nothing else is public."""

import ast
import os
import pathlib
import re

import dgwarp


def stub_names():
    tree = ast.parse((pathlib.Path(dgwarp.__file__).parent / "__init__.pyi").read_text())
    return {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}


def test_every_public_name_has_a_docstring_and_a_stub():
    names = stub_names()
    for name in dgwarp.__all__:
        obj = getattr(dgwarp, name)
        assert obj.__doc__ and len(obj.__doc__) > 20, name
        assert name in names, f"{name} is not in __init__.pyi"
    assert names - set(dgwarp.__all__) == set()


def test_methods_and_properties_are_documented():
    for cls in (dgwarp.Mesh, dgwarp.Plan, dgwarp.Motion):
        for name, member in vars(cls).items():
            if not name.startswith("_"):
                assert member.__doc__, f"{cls.__name__}.{name}"


def test_exceptions_derive_from_what_python_callers_expect():
    assert issubclass(dgwarp.IoError, OSError)
    for e in (dgwarp.ParseError, dgwarp.MeshError, dgwarp.FormatError, dgwarp.InvalidResultError, dgwarp.InputError):
        assert issubclass(e, ValueError) and issubclass(e, dgwarp.Error)
    assert issubclass(dgwarp.DgwarpWarning, UserWarning)


def test_version_is_the_projects(cli):
    # The version of CMakeLists.txt's project(), as the CLI prints it.
    source = pathlib.Path(os.environ.get("DGWARP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
    cmake = (source / "CMakeLists.txt").read_text()
    declared = re.search(r"project\(dgwarp VERSION ([0-9.]+)", cmake).group(1)
    assert dgwarp.__version__ == declared
    assert cli("--version").stdout.split() == ["dgwarp", declared]
