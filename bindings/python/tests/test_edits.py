"""The edits, their can_* predicates and refusals (src/py_edits.cpp)."""

import numpy as np
import pytest
from conftest import assert_valid

import hedge


def interior_edge(mesh):
    return next(e for e in range(mesh.n_edges) if not mesh.refusal("flip", [e]))


def boundary_halfedge(mesh):
    return int(np.flatnonzero(mesh.halfedge_face_array == -1)[0])


def test_split_edge(grid):
    e = interior_edge(grid)
    assert grid.can_split_edge(e)
    v = grid.split_edge(e)
    assert v == 25 and grid.n_vertices == 26 and grid.n_faces == 34
    assert grid.last_refusal is None
    v2 = grid.split_edge(e, point=(0.25, 0.5, 1.0))
    np.testing.assert_array_equal(grid.to_arrays()[0][v2], [0.25, 0.5, 1.0])
    assert_valid(grid)


def test_split_edge_at_a_point_that_is_not_finite(grid):
    with pytest.raises(hedge.InvalidArgumentError):
        grid.split_edge(0, point=(0, float("nan"), 0))
    assert grid.n_vertices == 25
    assert_valid(grid)


def test_flip_refused_on_the_boundary_returns_none(grid):
    h = boundary_halfedge(grid)
    e = h >> 1
    assert not grid.can_flip(e)
    before = grid.to_arrays()
    assert grid.flip(e) is None
    assert "boundary" in grid.last_refusal
    assert grid.refusal("flip", [e]) == grid.last_refusal
    np.testing.assert_array_equal(grid.to_arrays()[1], before[1])
    e = interior_edge(grid)
    assert grid.flip(e) == e and grid.last_refusal is None
    assert_valid(grid)


def test_collapse(grid):
    # An interior half-edge: its origin merges into its target, which can move.
    h = 2 * interior_edge(grid)
    assert grid.can_collapse(h)
    target = int(grid.halfedge_vertex_array[h])
    v = grid.collapse(h, point=(1.5, 1.5, 0.5))
    assert v == target and grid.n_vertices == 24
    np.testing.assert_array_equal(grid.positions[v], [1.5, 1.5, 0.5])
    assert_valid(grid)


def test_split_face_and_cut_face():
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float32)
    mesh = hedge.Mesh.from_arrays(V, [[0, 1, 2, 3]])
    h0 = int(mesh.face_halfedge_array[0])
    h2 = int(mesh.halfedge_next_array[mesh.halfedge_next_array[h0]])
    assert mesh.can_cut_face(h0, h2)
    assert not mesh.can_cut_face(h0, h0)
    assert mesh.cut_face(h0, h0) is None and mesh.last_refusal
    h = mesh.cut_face(h0, h2)
    assert h is not None and mesh.n_faces == 2 and mesh.is_triangle_mesh()
    assert mesh.can_split_face(0)
    v = mesh.split_face(0)
    assert v == 4 and mesh.n_faces == 4
    assert_valid(mesh)


def test_remove_face_then_fill_hole(grid):
    def interior(f):
        h = grid.face_halfedge_array[f]
        hs = [h, grid.halfedge_next_array[h], grid.halfedge_next_array[grid.halfedge_next_array[h]]]
        return all(grid.halfedge_face_array[x ^ 1] != -1 for x in hs)

    f = next(f for f in range(grid.n_faces) if interior(f) and grid.can_remove_face(f))
    h = int(grid.face_halfedge_array[f])
    assert grid.can_remove_face(f)
    assert grid.remove_face(f) is True and grid.last_refusal is None
    assert grid.n_faces == 31 and grid.halfedge_face_array[h] == -1
    assert not grid.can_remove_face(f)
    with pytest.raises(hedge.BadHandleError):
        grid.remove_face(f)
    assert grid.can_fill_hole(h)
    faces = grid.fill_hole(h)
    assert len(faces) == 1 and grid.n_faces == 32
    assert not grid.can_fill_hole(h)
    assert grid.fill_hole(h) is None and grid.last_refusal
    assert_valid(grid)


def test_bad_handles_raise_and_can_says_false(grid):
    assert not grid.can_flip(10**6) and not grid.can_flip(-1)
    assert not grid.can_remove_face(-1) and not grid.can_remove_face(10**6)
    for call in (lambda: grid.flip(10**6), lambda: grid.split_edge(-3), lambda: grid.collapse(10**9)):
        with pytest.raises(hedge.BadHandleError) as caught:
            call()
        assert isinstance(caught.value, IndexError) and isinstance(caught.value, ValueError)
    with pytest.raises(hedge.InvalidArgumentError):
        grid.refusal("teleport", [0])
    with pytest.raises(hedge.InvalidArgumentError):
        grid.refusal("cut_face", [0])
    assert_valid(grid)


def test_refusal_takes_every_python_edit_name(grid):
    # Each refusable edit by its Python name, agreeing with its can_* predicate.
    calls = {
        "split_edge": ([0], grid.can_split_edge),
        "collapse": ([0], grid.can_collapse),
        "flip": ([0], grid.can_flip),
        "split_face": ([0], grid.can_split_face),
        "cut_face": ([0, 1], grid.can_cut_face),
        "fill_hole": ([0], grid.can_fill_hole),
        "remove_face": ([0], grid.can_remove_face),
    }
    for name, (elements, can) in calls.items():
        assert (grid.refusal(name, elements) is None) == can(*elements), name
    assert grid.refusal("remove_face", [0]) is None
    with pytest.raises(hedge.InvalidArgumentError) as caught:
        grid.refusal("splitEdge", [0])
    assert str(caught.value) == (
        "unknown edit 'splitEdge' (split_edge, collapse, flip, split_face, cut_face, fill_hole, remove_face)"
    )
    assert_valid(grid)


def test_refusal_of_an_index_out_of_range_is_not_live_as_in_the_c_abi(grid):
    # The C ABI and the JS API take 32-bit indices: -1 is past every slot, so "not live".
    for e in (-1, 10**6, 2**40):
        assert grid.refusal("flip", [e]) == "the edge is not live"
        assert not grid.can_flip(e)
    assert grid.refusal("remove_face", [-1]) == "the face is not live"
    assert grid.refusal("cut_face", [-1, 0]) == grid.refusal("cut_face", [10**6, 0])
    assert_valid(grid)


def test_remove_faces_removes_several_at_once(grid):
    assert grid.remove_faces([0, 1, 1, 2]) == 3  # a repeat counts once
    assert grid.n_faces == 29
    assert grid.last_refusal is None
    # Faces 8..15 are the grid's second row: removing it leaves two strips, the mesh still manifold.
    assert grid.remove_faces(np.arange(8, 16)) == 8
    assert grid.n_faces == 21
    assert_valid(grid)


def fans(F):
    """How many fans (faces joined through edges at the vertex) each vertex of the faces F has."""
    count = {}
    for v in np.unique(F):
        faces = [set(f) for f in F if v in f]
        groups = []
        for f in faces:
            joined = [g for g in groups if any(len(f & h) == 2 for h in g)]
            merged = [f] + [h for g in joined for h in g]
            groups = [g for g in groups if g not in joined] + [merged]
        count[int(v)] = len(groups)
    return count


def test_remove_faces_splits_pinched_vertices(grid):
    # Keep two opposite faces around vertex 6: they share the vertex and no edge.
    _, F = grid.to_arrays()
    around = grid.vertex_faces(6)
    assert len(around) == 6
    gone = [f for f in around if f not in (around[0], around[3])]
    assert grid.remove_faces(gone) == 4
    expected = fans(np.delete(F, gone, axis=0))
    assert expected[6] == 2
    assert grid.n_vertices == sum(expected.values())  # one vertex per fan: pinched ones were split
    assert all(n == 1 for n in fans(grid.to_arrays()[1]).values())
    assert_valid(grid)


def test_remove_faces_checks_every_face_first(grid):
    with pytest.raises(hedge.BadHandleError):
        grid.remove_faces([0, 1, 99])
    with pytest.raises(hedge.BadHandleError):
        grid.remove_faces([-1])
    assert grid.n_faces == 32  # nothing removed
    assert grid.remove_face(0)
    with pytest.raises(hedge.BadHandleError):
        grid.remove_faces([1, 0])
    assert grid.n_faces == 31
    P = grid.positions
    with pytest.raises(hedge.ViewsExportedError):
        grid.remove_faces([4])
    del P
    with pytest.raises(hedge.InvalidArgumentError):
        grid.remove_faces([[1, 2]])
    assert grid.n_faces == 31
    assert_valid(grid)
