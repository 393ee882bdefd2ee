"""The scalar queries and the one-ring (src/py_queries.cpp), checked against the array views."""

import numpy as np
import pytest

import hedge


def test_halfedge_queries_match_the_views(grid):
    to, nxt, face = grid.halfedge_vertex_array, grid.halfedge_next_array, grid.halfedge_face_array
    for h in range(grid.halfedge_slots):
        assert grid.next(h) == nxt[h]
        assert grid.to_vertex(h) == to[h]
        assert grid.from_vertex(h) == to[h ^ 1]
        assert grid.face(h) == face[h]
        assert grid.twin(h) == h ^ 1 and grid.edge(h) == h >> 1
        assert grid.next(grid.prev(h)) == h


def test_vertex_and_face_halfedges(grid):
    for v in range(grid.vertex_slots):
        assert grid.vertex_halfedge(v) == grid.vertex_halfedge_array[v]
        assert grid.from_vertex(grid.vertex_halfedge(v)) == v
    for f in range(grid.face_slots):
        assert grid.face(grid.face_halfedge(f)) == f


def test_one_ring_and_vertex_faces(grid):
    # Vertex 12 is the centre of the 4 x 4 grid, vertex 0 a corner.
    _, F = grid.to_arrays()
    for v in (12, 0, 2):
        ring = grid.one_ring(v)
        assert ring.dtype == np.int32
        assert sorted(ring) == sorted({int(x) for f in F if v in f for x in f} - {v})
        assert sorted(grid.vertex_faces(v)) == [i for i, f in enumerate(F) if v in f]
    assert len(grid.one_ring(12)) == 6 and len(grid.vertex_faces(0)) == 2


def test_queries_check_their_handles(grid):
    for call in (grid.next, grid.prev, grid.twin, grid.to_vertex, grid.face):
        with pytest.raises(hedge.BadHandleError):
            call(grid.halfedge_slots)
        with pytest.raises(hedge.BadHandleError):
            call(-1)
    with pytest.raises(hedge.BadHandleError):
        grid.one_ring(10**6)
    with pytest.raises(hedge.BadHandleError):
        grid.face_halfedge(grid.face_slots)
    f = next(f for f in range(grid.n_faces) if grid.can_remove_face(f))
    grid.remove_face(f)
    with pytest.raises(hedge.BadHandleError) as caught:
        grid.face_halfedge(f)
    assert "deleted" in str(caught.value)
    assert grid.validate() == []


def test_one_rings_of_many_vertices_match_one_ring(grid):
    offsets, neighbours = grid.one_rings()
    assert offsets.dtype == np.int64 and neighbours.dtype == np.int32
    assert len(offsets) == grid.vertex_slots + 1 and offsets[-1] == len(neighbours)
    for v in range(grid.vertex_slots):
        assert list(neighbours[offsets[v] : offsets[v + 1]]) == list(grid.one_ring(v))
    # A chosen list, in its order, repeats allowed.
    chosen = np.array([12, 0, 12], dtype=np.uint16)
    offsets, neighbours = grid.one_rings(chosen)
    rings = [list(neighbours[offsets[i] : offsets[i + 1]]) for i in range(3)]
    assert rings == [list(grid.one_ring(12)), list(grid.one_ring(0)), list(grid.one_ring(12))]


def test_one_rings_skip_deleted_vertices_and_check_listed_ones(grid):
    # Vertex 4, the corner at (4, 0), is in face 6 only: removing that face deletes it.
    assert sorted(grid.vertex_faces(4)) == [6]
    assert grid.remove_face(6)
    offsets, neighbours = grid.one_rings()
    sizes = np.diff(offsets)
    assert sizes[4] == 0
    for v in range(grid.vertex_slots):
        if v != 4:
            assert list(neighbours[offsets[v] : offsets[v + 1]]) == list(grid.one_ring(v))
    with pytest.raises(hedge.BadHandleError):
        grid.one_rings([4])
    with pytest.raises(hedge.BadHandleError):
        grid.one_rings([grid.vertex_slots])
    with pytest.raises(hedge.InvalidArgumentError):
        grid.one_rings(np.array([0.5]))
    with pytest.raises(hedge.InvalidArgumentError):
        grid.one_rings(np.zeros((2, 2), dtype=np.int32))
def test_is_boundary_and_boundary_vertices(grid):
    # The 4 x 4 grid's boundary is its outer ring of 16 vertices; numpy finds them from the
    # boundary half-edges (no face) of the views.
    to, face = grid.halfedge_vertex_array, grid.halfedge_face_array
    expected = np.zeros(grid.vertex_slots, dtype=bool)
    expected[to[face == -1]] = True
    assert expected.sum() == 16
    np.testing.assert_array_equal(grid.boundary_vertices(), expected)
    assert [grid.is_boundary(v) for v in range(grid.vertex_slots)] == list(expected)
    assert not grid.is_boundary(12) and grid.is_boundary(0)
    with pytest.raises(hedge.BadHandleError):
        grid.is_boundary(25)
    assert grid.remove_face(0)  # the face (0, 1, 6): its edges 1-6 and 6-0 join the boundary
    b = grid.boundary_vertices()
    assert b.dtype == np.bool_ and b.shape == (grid.vertex_slots,)
    assert b[6]  # the removed face opened the hole up to the interior vertex 6
    assert grid.remove_face(1)  # (0, 6, 5), the last face of vertex 0, which goes with it
    assert not grid.boundary_vertices()[0]  # a deleted slot is no boundary vertex
    with pytest.raises(hedge.BadHandleError):
        grid.is_boundary(0)
    assert grid.validate() == []
