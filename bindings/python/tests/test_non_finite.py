"""A NaN written through the positions view: validate() names it, and the writers and the
whole-mesh algorithms refuse it by name, leaving the mesh and the file as they were (the checks
are the library's, so every binding has them)."""

import numpy as np
import pytest
from conftest import assert_valid

import hedge


def poisoned(mesh, v=7):
    before = mesh.positions.copy()
    mesh.positions[v, 1] = np.nan
    with pytest.raises(hedge.InvalidArgumentError):
        mesh.positions_changed()
    return before


def test_validate_names_the_vertex(grid):
    poisoned(grid)
    problems = grid.validate()
    assert len(problems) == 1 and problems[0].startswith("vertex 7 has a non-finite position (")
    assert "nan" in problems[0]


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda m: m.smooth(), "smooth"),
        (lambda m: m.subdivide(), "subdivide"),
        (lambda m: m.bounding_box(), "bounding_box"),
        (lambda m: m.area(), "surface_area"),
    ],
)
def test_algorithms_refuse_and_change_nothing(grid, call, name):
    before = poisoned(grid)
    V, F = grid.to_arrays()
    with pytest.raises(hedge.InvalidArgumentError) as caught:
        call(grid)
    assert str(caught.value).startswith(name + ": vertex 7 has a non-finite position (")
    V2, F2 = grid.to_arrays()
    np.testing.assert_array_equal(V2, V)  # NaN compares equal here
    np.testing.assert_array_equal(F2, F)
    grid.positions[7] = before[7]
    grid.positions_changed()
    assert_valid(grid)


@pytest.mark.parametrize("ext", ["obj", "off", "ply", "stl", "gltf", "glb"])
def test_write_refuses_and_keeps_the_old_file(grid, tmp_path, ext):
    path = tmp_path / ("mesh." + ext)
    path.write_bytes(b"old")
    poisoned(grid)
    with pytest.raises(hedge.HedgeError) as caught:
        grid.write(str(path))
    assert "vertex 7 has a non-finite position" in str(caught.value)
    assert path.read_bytes() == b"old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mesh." + ext]
