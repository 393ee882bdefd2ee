"""The numpy views: zero-copy, writable positions, read-only connectivity, the view guard
(src/py_views.cpp)."""

import gc
import os

import numpy as np
import pytest
from conftest import assert_valid, grid_arrays

import hedge

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "data")

def test_positions_is_a_writable_view_of_the_mesh(grid):
    P = grid.positions
    assert P.shape == (grid.vertex_slots, 3) and P.dtype == np.float32
    assert not P.flags.owndata and P.flags.writeable
    assert np.shares_memory(P, grid.positions)
    P[3] = (7, 8, 9)
    grid.positions_changed([3])
    del P
    np.testing.assert_array_equal(grid.to_arrays()[0][3], [7, 8, 9])
    assert_valid(grid)


def test_connectivity_views_share_memory_and_are_read_only(grid):
    for name in ("halfedge_vertex_array", "halfedge_next_array", "halfedge_face_array", "vertex_halfedge_array", "face_halfedge_array"):
        view = getattr(grid, name)
        assert view.dtype == np.int32 and not view.flags.owndata, name
        assert np.shares_memory(view, getattr(grid, name)), name
        with pytest.raises(ValueError):
            view[0] = 1
    assert len(grid.halfedge_vertex_array) == grid.halfedge_slots
    assert len(grid.vertex_halfedge_array) == grid.vertex_slots
    assert len(grid.face_halfedge_array) == grid.face_slots


def test_connectivity_views_agree_with_the_faces(grid):
    V, F = grid.to_arrays()
    to, nxt, face = grid.halfedge_vertex_array, grid.halfedge_next_array, grid.halfedge_face_array
    fh = grid.face_halfedge_array
    for f in range(grid.n_faces):
        # A face's corners start at the target of its half-edge.
        h, corners = fh[f], []
        for _ in range(3):
            assert face[h] == f
            corners.append(to[h])
            h = nxt[h]
        assert h == fh[f]
        assert corners == list(F[f])
    # Twin is h ^ 1: a half-edge's origin is its twin's target.
    h = np.arange(grid.halfedge_slots)
    origin = to[h ^ 1]
    assert np.all(to[nxt[h]] != origin[nxt[h]])
    assert np.all(origin[nxt[h]] == to[h])
    # Boundary half-edges have no face.
    assert np.count_nonzero(face == -1) == 16


def test_one_ring_through_the_views(grid):
    # The numpy fast path of the docs: the outgoing half-edges of v are found by rotating through
    # next(twin(h)); here compared with the edges of the face list.
    to, nxt, vh = grid.halfedge_vertex_array, grid.halfedge_next_array, grid.vertex_halfedge_array
    center = 12  # the middle vertex of the 4 x 4 grid
    ring, h = [], vh[center]
    while True:
        ring.append(int(to[h]))
        h = nxt[h ^ 1]
        if h == vh[center]:
            break
    _, F = grid.to_arrays()
    expected = {int(x) for f in F if center in f for x in f} - {center}
    assert sorted(ring) == sorted(expected) and len(ring) == len(expected)


def test_a_view_keeps_the_mesh_alive():
    V, F = grid_arrays(2)
    mesh = hedge.Mesh.from_arrays(V, F)
    P, nxt = mesh.positions, mesh.halfedge_next_array
    expected = P.copy()
    del mesh
    gc.collect()
    np.testing.assert_array_equal(P, expected)
    assert len(nxt) > 0 and nxt[0] >= 0


def test_views_block_edits_that_add_elements(grid):
    P = grid.positions
    before = grid.to_arrays()
    with pytest.raises(hedge.ViewsExportedError) as caught:
        grid.split_edge(0)
    assert isinstance(caught.value, BufferError)
    assert "REPL's `_` or a notebook's Out[]" in str(caught.value) and "gc.collect()" in str(caught.value)
    with pytest.raises(hedge.ViewsExportedError):
        grid.split_face(0)
    # A slice keeps the view alive through its base.
    row = P[1:2]
    del P
    with pytest.raises(hedge.ViewsExportedError):
        grid.split_face(0)
    del row
    np.testing.assert_array_equal(grid.to_arrays()[1], before[1])
    # Edits that add nothing move nothing: they are allowed with views alive.
    nxt = grid.halfedge_next_array
    interior = next(e for e in range(grid.n_edges) if grid.can_flip(e))
    assert grid.flip(interior) == interior
    del nxt
    assert grid.split_face(0) is not None
    assert_valid(grid)


def test_positions_changed_checks_before_marking(grid):
    P = grid.positions
    P[2, 0] = np.inf
    with pytest.raises(hedge.InvalidArgumentError) as caught:
        grid.positions_changed()
    assert "vertex 2" in str(caught.value)
    P[2, 0] = 2.0
    grid.positions_changed()
    with pytest.raises(hedge.BadHandleError):
        grid.positions_changed([grid.vertex_slots])
    with pytest.raises(hedge.BadHandleError):
        grid.positions_changed([-1])
    with pytest.raises(hedge.InvalidArgumentError):
        grid.positions_changed(np.zeros((2, 2), dtype=np.int64))
    assert_valid(grid)


def test_to_arrays_adopts_its_buffers(grid):
    V, F = grid.to_arrays()
    # The exported vectors are the arrays' memory (a capsule owns them): no copy after the export.
    assert not V.flags.owndata and not F.flags.owndata
    assert not np.shares_memory(V, grid.positions)


def test_properties_by_name_are_views(grid):
    names = grid.property_names()
    assert set(names) == {"vertex", "halfedge", "edge", "face"}
    assert "v:position" in names["vertex"]
    P = grid.property("v:position")
    assert P.shape == (grid.vertex_slots, 3) and P.dtype == np.float32
    assert np.shares_memory(P, grid.positions)
    view = grid.property("v:position", kind="vertex")
    view[0] = (1, 2, 3)  # writable, and the mesh's own memory
    np.testing.assert_array_equal(grid.positions[0], [1, 2, 3])
    # A property view counts as a view: edits that add elements wait for it.
    with pytest.raises(hedge.ViewsExportedError):
        grid.split_face(0)
    del P, view
    assert grid.split_face(0) is not None
    assert_valid(grid)


def test_face_and_corner_properties_of_a_file():
    mesh = hedge.read(os.path.join(DATA, "two_quads.gltf"))
    names = mesh.property_names()
    assert "h:texcoord" in names["halfedge"], names
    uv = mesh.property("h:texcoord")
    assert uv.shape == (mesh.halfedge_slots, 2) and uv.dtype == np.float32
    if "f:submesh" in names["face"]:
        sub = mesh.property("f:submesh")
        assert sub.shape == (mesh.face_slots,) and sub.dtype == np.int32
    assert mesh.validate() == []


def test_unknown_property_names_raise(grid):
    with pytest.raises(hedge.InvalidArgumentError, match="no property named 'v:colour'"):
        grid.property("v:colour")
    with pytest.raises(hedge.InvalidArgumentError, match="kind must be"):
        grid.property("v:position", kind="corner")
    with pytest.raises(hedge.InvalidArgumentError, match="no face property"):
        grid.property("v:position", kind="face")


def test_live_masks_leave_out_the_slots_edits_deleted(grid):
    for h in (grid.vertex_halfedge(6), grid.vertex_halfedge(18)):
        assert grid.collapse(h) is not None
    live_v, live_h = grid.live_vertices(), grid.live_halfedges()
    live_e, live_f = grid.live_edges(), grid.live_faces()
    assert live_v.dtype == bool and live_v.shape == (grid.vertex_slots,)
    assert (live_v.sum(), live_h.sum(), live_e.sum(), live_f.sum()) == (
        grid.n_vertices, grid.n_halfedges, grid.n_edges, grid.n_faces)
    assert np.array_equal(live_h, np.repeat(live_e, 2))
    # The valence of every vertex through the views and the masks, against the one-rings.
    to = grid.halfedge_vertex_array
    valence = np.bincount(to[live_h], minlength=grid.vertex_slots)
    offsets, _ = grid.one_rings()
    assert np.array_equal(valence, np.diff(offsets))
    assert not np.array_equal(np.bincount(to[to >= 0], minlength=grid.vertex_slots), np.diff(offsets))
    assert not live_v[6] and not live_v[18]
    dead_faces = {f for f in range(grid.face_slots) if grid.refusal("split_face", [f]) == "the face is not live"}
    assert set(np.flatnonzero(~live_f)) == dead_faces
    del to
    assert_valid(grid)
