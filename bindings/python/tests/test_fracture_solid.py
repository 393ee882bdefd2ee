"""Mesh.fracture_solid: closed pieces with their volumes, mass properties, hulls and bonds, checked
against numpy; refusals of open meshes and bad arguments."""

import os

import numpy as np
import pytest
from conftest import assert_valid, grid_arrays
from test_fracture import solid_properties, surface_area

import hedge

DATA = os.path.join(os.path.dirname(__file__), "..", "..", "..", "data")


def spot():
    return hedge.read(os.path.join(DATA, "spot_triangulated.obj"))


def impact_on(mesh):
    """A point of spot's back: where a ray down the y axis meets it."""
    faces, _, points = mesh.ray_cast([[0, 2, 0.1]], [[0, -1, 0]])
    assert faces[0] >= 0
    return points[0]


def volume(mesh):
    return solid_properties(mesh, 1.0)[0]


def boundary_halfedges(mesh):
    """Half-edges without a face: none on a closed mesh."""
    live = mesh.live_halfedges()
    return int(np.count_nonzero(live & (np.asarray(mesh.halfedge_face_array) < 0)))


def test_pieces_are_closed_and_their_volumes_and_the_rest_add_up_to_the_mesh():
    mesh = spot()
    before = volume(mesh)
    at = impact_on(mesh)
    assert mesh.solid_fracture_refusal(at) is None
    pieces, bonds = mesh.fracture_solid(at, "stone", seed=3, radius_fraction=0.2)
    assert len(pieces) >= 2
    total = 0.0
    for p in pieces:
        assert isinstance(p, hedge.Piece) and isinstance(p, hedge.Mesh)
        assert_valid(p)
        assert boundary_halfedges(p) == 0
        assert p.volume > 0 and p.volume == pytest.approx(volume(p), rel=1e-5)
        assert p.cap_area > 0
        total += p.volume
    assert boundary_halfedges(mesh) == 0, "the remaining object is closed"
    assert total + volume(mesh) == pytest.approx(before, rel=1e-6)
    assert_valid(mesh)


def test_a_piece_has_the_mass_properties_numpy_computes_and_a_hull():
    mesh = spot()
    pieces, _ = mesh.fracture_solid(impact_on(mesh), seed=4, density=2.5)
    for p in pieces:
        v, centre, inertia = solid_properties(p, 2.5)
        m = p.mass
        assert m["volume"] == pytest.approx(v, rel=1e-5)
        assert m["mass"] == pytest.approx(2.5 * v, rel=1e-5)
        assert np.allclose(m["centre_of_mass"], centre, atol=1e-5)
        assert np.allclose(m["inertia"], inertia, rtol=1e-4, atol=1e-9)
        assert p.hull_dimension == "solid"
        hull = p.hull
        assert hull is not None and hull.n_faces == 2 * hull.n_vertices - 4
        assert_valid(hull)
    assert_valid(mesh)
    fresh = spot()
    no_hulls, _ = fresh.fracture_solid(impact_on(fresh), seed=4, hulls=False)
    assert no_hulls and all(p.hull is None for p in no_hulls)
    assert_valid(fresh)


def test_caps_are_marked_inner_with_their_submesh():
    mesh = spot()
    pieces, _ = mesh.fracture_solid(impact_on(mesh), seed=5, inner_submesh=3)
    for p in pieces:
        inner = np.asarray(p.property("f:inner"))
        submesh = np.asarray(p.property("f:submesh"))
        live = p.live_faces()
        assert inner[live].any() and not inner[live].all()
        assert (submesh[live][inner[live] == 1] == 3).all()
        assert (submesh[live][inner[live] == 0] == 0).all()
        # The caps' area is the area of the faces marked inner.
        V, F = p.to_arrays()
        t = V.astype(np.float64)[np.asarray(F)]
        areas = 0.5 * np.linalg.norm(np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]), axis=1)
        marked = inner[np.flatnonzero(live)] == 1
        assert areas[marked].sum() == pytest.approx(p.cap_area, rel=1e-5)
        assert p.cap_area < surface_area(p)
        del inner, submesh
        assert_valid(p)


def test_bonds_pair_touching_pieces_and_the_remaining_object():
    mesh = spot()
    pieces, bonds = mesh.fracture_solid(impact_on(mesh), seed=6, radius_fraction=0.2)
    assert bonds == sorted(bonds, key=lambda b: (b[0], float("inf") if b[1] is None else b[1]))
    assert any(b is None for _, b, _ in bonds), "some piece touches the remaining object"
    for a, b, area in bonds:
        assert 0 <= a < len(pieces) and area > 0
        assert b is None or a < b < len(pieces)
    for i, p in enumerate(pieces):
        assert sum(area for a, _, area in bonds if a == i) <= p.cap_area * (1 + 1e-6)
    assert_valid(mesh)


def test_the_same_strike_gives_the_same_pieces():
    def run():
        mesh = spot()
        pieces, bonds = mesh.fracture_solid(impact_on(mesh), seed=9, radius_fraction=0.15)
        return [p.to_arrays() for p in pieces], bonds, mesh.to_arrays()

    (a, bonds_a, rest_a), (b, bonds_b, rest_b) = run(), run()
    assert bonds_a == bonds_b and len(a) == len(b)
    for (va, fa), (vb, fb) in zip(a + [rest_a], b + [rest_b]):
        assert np.array_equal(va, vb) and np.array_equal(np.asarray(fa), np.asarray(fb))


def test_an_open_mesh_is_refused_with_its_reason_and_left_unchanged():
    V, F = grid_arrays(10)
    plate = hedge.Mesh.from_arrays(V, F)
    why = plate.solid_fracture_refusal((5.2, 4.7, 0))
    assert why is not None and ("open" in why or "boundary" in why)
    before = plate.to_arrays()
    with pytest.raises(hedge.InvalidArgumentError) as e:
        plate.fracture_solid((5.2, 4.7, 0))
    assert why in str(e.value) or "open" in str(e.value)
    after = plate.to_arrays()
    assert np.array_equal(before[0], after[0]) and np.array_equal(before[1], after[1])
    # Surface fracture breaks it instead.
    assert plate.fracture((5.2, 4.7, 0), "glass", seed=1)
    assert_valid(plate)


def test_kind_auto_breaks_an_open_mesh_by_surface_fracture_and_a_closed_one_as_a_solid():
    V, F = grid_arrays(10)
    plate = hedge.Mesh.from_arrays(V, F)
    shards, why = plate.fracture_solid(
        (5.2, 4.7, 0), "glass", kind="auto", seed=1, surface={"thickness": 0.1}
    )
    assert isinstance(why, str) and why.startswith("the mesh is open")
    assert shards and all(isinstance(s, hedge.Shard) for s in shards)
    assert all(s.closed for s in shards)  # the surface option reached fracture()
    assert_valid(plate)
    # A closed mesh breaks as a solid, as with kind 'solid'.
    mesh = spot()
    pieces, bonds = mesh.fracture_solid(impact_on(mesh), kind="auto", seed=3)
    assert pieces and all(isinstance(p, hedge.Piece) for p in pieces)
    assert isinstance(bonds, list)
    assert_valid(mesh)
    # A bad option is an error with 'auto' too, and an unknown kind is named.
    before = plate.to_arrays()
    with pytest.raises(hedge.InvalidArgumentError, match="density"):
        plate.fracture_solid((5.2, 4.7, 0), kind="auto", density=0)
    with pytest.raises(hedge.InvalidArgumentError, match="unknown kind 'surface' \\(solid, auto\\)"):
        plate.fracture_solid((5.2, 4.7, 0), kind="surface")
    after = plate.to_arrays()
    assert np.array_equal(before[0], after[0]) and np.array_equal(before[1], after[1])


def test_kind_auto_falls_back_by_the_refusal_code_alone():
    V, F = grid_arrays(10)
    plate = hedge.Mesh.from_arrays(V, F)
    assert plate.solid_fracture_refusal_code((5.2, 4.7, 0)) == "open"
    # Off the surface of the open plate: not about its shape, so 'auto' raises the solid
    # fracture's error instead of trying surface fracture.
    assert plate.solid_fracture_refusal_code((5.2, 4.7, 3)) == "off_surface"
    with pytest.raises(hedge.InvalidArgumentError, match="^fracture_solid: the impact"):
        plate.fracture_solid((5.2, 4.7, 3), kind="auto")
    assert plate.solid_fracture_refusal_code((5.2, 4.7, 0), density=0) == "bad_option"
    mesh = spot()
    assert mesh.solid_fracture_refusal_code(impact_on(mesh)) == "none"
    assert_valid(plate)
    assert_valid(mesh)


@pytest.mark.parametrize(
    "point, options, message",
    [
        ((0, 0), {}, "fracture_solid: point must be 3 numbers"),
        ((float("nan"), 0, 0), {}, "not finite"),
        ((0, 5, 0), {}, "from the nearest face"),
        (None, {"material": "rubber"}, "unknown material 'rubber'"),
        (None, {"material": 3}, "fracture_solid: material must be a preset name"),
        (None, {"material": {"rings": [], "colour": 1}}, "'colour' is unknown"),
        (None, {"seed": -1}, "fracture_solid: seed must be a whole number"),
        (None, {"seed": 1.5}, "fracture_solid: seed must be a whole number"),
        (None, {"radius": -2}, "radius"),
        (None, {"radius_fraction": 0}, "radius_fraction"),
        (None, {"density": 0}, "density"),
        (None, {"inner_submesh": -5}, "inner_submesh"),
    ],
)
def test_bad_input_is_a_clear_error_and_leaves_the_mesh_unchanged(point, options, message):
    mesh = spot()
    at = impact_on(mesh) if point is None else point
    before = mesh.to_arrays()
    with pytest.raises(hedge.InvalidArgumentError) as e:
        mesh.fracture_solid(at, **options)
    assert message in str(e.value)
    after = mesh.to_arrays()
    assert np.array_equal(before[0], after[0]) and np.array_equal(before[1], after[1])
    assert_valid(mesh)


def test_views_alive_block_a_solid_fracture_but_not_its_refusal():
    mesh = spot()
    at = impact_on(mesh)
    P = mesh.positions
    assert mesh.solid_fracture_refusal(at) is None
    with pytest.raises(hedge.ViewsExportedError, match="fracture_solid"):
        mesh.fracture_solid(at)
    del P
    pieces, _ = mesh.fracture_solid(at)
    assert pieces
    assert_valid(mesh)
