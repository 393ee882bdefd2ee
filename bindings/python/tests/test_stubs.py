"""The type stubs (hedge/_hedge.pyi) name exactly what the native module binds."""

import ast
import os

import hedge
from hedge import _hedge


def stub_names():
    path = os.path.join(os.path.dirname(hedge.__file__), "_hedge.pyi")
    with open(path, encoding="utf-8") as f:
        tree = ast.parse(f.read())
    top = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    mesh = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "Mesh")
    members = {n.name for n in mesh.body if isinstance(n, ast.FunctionDef)}
    return top, members


def test_stubs_match_the_module():
    top, members = stub_names()
    bound_top = {n for n in dir(_hedge) if not n.startswith("__")}
    assert top == bound_top
    # What Mesh binds beyond object's members (its own __init__ and __repr__ included).
    bound = {n for n in dir(hedge.Mesh) if n not in dir(object) or hedge.Mesh.__dict__.get(n) is not None}
    bound -= {"__module__", "__doc__", "__dict__"}
    assert members == bound, (members ^ bound)


def test_every_function_has_a_docstring():
    for name in dir(hedge.Mesh):
        if not name.startswith("_"):
            assert getattr(hedge.Mesh, name).__doc__, name
    assert hedge.read.__doc__
