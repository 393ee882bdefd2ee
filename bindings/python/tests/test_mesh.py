"""Building from arrays, files, to_arrays, counts and validate (src/py_mesh.cpp)."""

import os
import re

import numpy as np
import pytest
from conftest import assert_valid, grid_arrays

import hedge


def test_from_arrays_counts_and_report():
    V, F = grid_arrays(4)
    mesh = hedge.Mesh.from_arrays(V, F)
    assert (mesh.n_vertices, mesh.n_faces, mesh.n_edges) == (25, 32, 56)
    assert mesh.n_halfedges == 112
    assert mesh.is_triangle_mesh()
    assert mesh.build_report["repairs"] == 0
    assert_valid(mesh)


def test_to_arrays_gives_back_the_input():
    V, F = grid_arrays(3)
    V2, F2 = hedge.Mesh.from_arrays(V, F).to_arrays()
    assert V2.dtype == np.float32 and V2.shape == V.shape
    assert F2.dtype == np.int32
    np.testing.assert_array_equal(V2, V.astype(np.float32))
    np.testing.assert_array_equal(F2, F)
    # The arrays own their memory through the moved-in vectors: writable, independent of the mesh.
    assert V2.flags.writeable


def test_polygons_as_a_list():
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0]], dtype=np.float32)
    mesh = hedge.Mesh.from_arrays(V, [[0, 1, 2, 3], [1, 4, 2]])
    assert (mesh.n_faces, mesh.n_vertices) == (2, 5)
    assert not mesh.is_triangle_mesh()
    V2, F2 = mesh.to_arrays()
    assert [list(f) for f in F2] == [[0, 1, 2, 3], [1, 4, 2]]
    assert_valid(mesh)


def test_quads_as_an_array():
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float64)
    mesh = hedge.Mesh.from_arrays(V, np.array([[0, 1, 2, 3]], dtype=np.uint32))
    assert mesh.n_faces == 1 and mesh.n_edges == 4


@pytest.mark.parametrize(
    "V, F, message",
    [
        (np.zeros((3, 2)), [[0, 1, 2]], "(n, 3)"),
        (np.zeros((3, 3)), [[0, 1, 3]], "F[0, 2] = 3 is not a vertex index"),
        (np.zeros((3, 3)), [[0, -1, 2]], "F[0, 1] = -1"),
        (np.zeros((3, 3)), np.array([[0.0, 1.0, 2.0]]), "integers"),
        (np.zeros((3, 3)), [[0, 1, 2], [[0], 1, 2]], "F[1] must be a 1-D array of integer indices"),
        (np.zeros((3, 3)), [[0, 1, 2], 5], "F[1] is not a sequence"),
        (np.zeros((3, 3)), np.array([[0, 1], [1, 2]]), "at least 3 columns"),
        (np.zeros((3, 3)), [[0, 1, 2], [0, 1, "x"]], "from_arrays: F must hold integers, not <U"),
        (np.zeros((3, 3)), [[0, 1, 2], [0, 1, 2, 2.5]], "F[1] must hold integers, not float64"),
        (np.zeros((3, 3)), "abc", "F must be an array of integers, not a string"),
    ],
)
def test_malformed_arrays_raise_value_errors(V, F, message):
    with pytest.raises(hedge.InvalidArgumentError) as caught:
        hedge.Mesh.from_arrays(V, F)
    assert message in str(caught.value)
    assert isinstance(caught.value, ValueError)


def test_a_polygon_of_two_corners_is_a_degenerate_face():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=np.float32)
    mesh = hedge.Mesh.from_arrays(V, [[0, 1], [0, 1, 2]])
    assert mesh.n_faces == 1 and mesh.build_report["degenerate_faces"] == 1
    assert_valid(mesh)
    with pytest.raises(hedge.TopologyError):
        hedge.Mesh.from_arrays(V, [[0, 1], [0, 1, 2]], repair=False)


def test_non_finite_position_is_refused():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, np.nan, 0]])
    with pytest.raises(hedge.InvalidArgumentError):
        hedge.Mesh.from_arrays(V, [[0, 1, 2]])


def test_repair_false_raises_topology_error():
    # Three triangles on one edge: not a 2-manifold.
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], dtype=np.float32)
    F = [[0, 1, 2], [1, 0, 3], [0, 1, 4]]
    with pytest.raises(hedge.TopologyError) as caught:
        hedge.Mesh.from_arrays(V, F, repair=False)
    assert isinstance(caught.value, ValueError)
    repaired = hedge.Mesh.from_arrays(V, F)
    assert repaired.build_report["repairs"] > 0
    assert_valid(repaired)


def test_write_and_read(tmp_path, grid):
    path = str(tmp_path / "grid.ply")
    grid.write(path)
    back = hedge.read(path)
    assert (back.n_vertices, back.n_faces) == (grid.n_vertices, grid.n_faces)
    np.testing.assert_array_equal(back.to_arrays()[1], grid.to_arrays()[1])
    assert_valid(back)


def test_paths_may_be_path_objects(tmp_path, grid):
    path = tmp_path / "grid.off"
    grid.write(path)
    assert hedge.read(path).n_faces == grid.n_faces
    with pytest.raises(hedge.InvalidArgumentError):
        hedge.read(b"/bytes/path.obj")
    with pytest.raises(TypeError):
        hedge.read(3)


def test_file_errors_are_os_errors(tmp_path, grid):
    with pytest.raises(hedge.IoError) as caught:
        hedge.read(str(tmp_path / "missing.obj"))
    assert isinstance(caught.value, OSError)
    assert "missing.obj" in str(caught.value)
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nf 1 2 x\n")
    with pytest.raises(OSError):
        hedge.read(str(bad))
    with pytest.raises(hedge.IoError):
        grid.write(str(tmp_path / "no" / "such" / "folder.obj"))
    with pytest.raises(hedge.HedgeError):
        grid.write(str(tmp_path / "unknown.format"))


def test_clone_is_independent(grid):
    import copy

    for twin in (grid.clone(), copy.copy(grid), copy.deepcopy(grid)):
        assert not np.shares_memory(twin.positions, grid.positions)
        assert twin.build_report == grid.build_report
        P = twin.positions
        P[0] = (5, 5, 5)
        twin.positions_changed([0])
        del P
        assert twin.split_face(0) is not None
        assert (twin.n_faces, grid.n_faces) == (34, 32)
        assert grid.positions[0].tolist() == [0, 0, 0]
        assert_valid(twin)
    assert_valid(grid)


def test_empty_mesh():
    mesh = hedge.Mesh()
    assert (mesh.n_vertices, mesh.n_faces) == (0, 0)
    assert mesh.positions.shape == (0, 3)
    assert repr(mesh) == "<hedge.Mesh: 0 vertices, 0 faces>"


def test_to_arrays_gives_an_array_for_faces_of_one_degree():
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0], [2, 1, 0]], dtype=np.float64)
    quads = hedge.Mesh.from_arrays(V, [[0, 1, 2, 3], [1, 4, 5, 2]])
    _, F = quads.to_arrays()
    assert isinstance(F, np.ndarray) and F.shape == (2, 4) and F.dtype == np.int32
    assert sorted(map(sorted, F.tolist())) == [[0, 1, 2, 3], [1, 2, 4, 5]]
    mixed = hedge.Mesh.from_arrays(V, [[0, 1, 2, 3], [1, 4, 5], [1, 5, 2]])
    _, F = mixed.to_arrays()
    assert isinstance(F, list) and sorted(len(f) for f in F) == [3, 3, 4]
    assert_valid(quads)
    assert_valid(mixed)


def test_version_is_the_projects():
    root = os.path.join(os.path.dirname(__file__), "..", "..", "..")
    with open(os.path.join(root, "CMakeLists.txt"), encoding="utf-8") as f:
        version = re.search(r"project\(hedge VERSION ([0-9.]+)", f.read()).group(1)
    assert hedge.__version__ == version
