"""The whole-mesh algorithms (src/py_algorithms.cpp), checked against numpy over to_arrays(), known
formulas and, when CTest passes its path in HEDGE_CLI, the CLI's own results."""

import json
import os
import subprocess
import threading

import numpy as np
import pytest
from conftest import assert_valid, grid_arrays

import hedge


def icosahedron_arrays():
    """A closed icosahedron with outward (counter-clockwise) faces."""
    t = (1 + 5**0.5) / 2
    V = np.array(
        [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t],
         [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]],
        dtype=np.float64,
    )
    F = np.array(
        [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4],
         [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8],
         [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]],
    )
    return V, F


def box_arrays(size=(1.0, 2.0, 3.0)):
    """A closed axis-aligned box [0, size] of 12 outward triangles."""
    sx, sy, sz = size
    V = np.array([[x, y, z] for z in (0, sz) for y in (0, sy) for x in (0, sx)], dtype=np.float64)
    quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    F = np.array([[q[0], q[1], q[2]] for q in quads] + [[q[0], q[2], q[3]] for q in quads])
    return V, F


@pytest.fixture
def ico():
    return hedge.Mesh.from_arrays(*icosahedron_arrays())


def numpy_area(mesh):
    V, F = mesh.to_arrays()
    V = V.astype(np.float64)
    return 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1).sum()


def numpy_volume(mesh):
    V, F = mesh.to_arrays()
    V = V.astype(np.float64)
    return np.einsum("ij,ij->i", V[F[:, 0]], np.cross(V[F[:, 1]], V[F[:, 2]])).sum() / 6


def cli(*args):
    out = subprocess.run([os.environ["HEDGE_CLI"], *args], capture_output=True, text=True, check=True)
    return out.stdout


needs_cli = pytest.mark.skipif(not os.environ.get("HEDGE_CLI"), reason="the CLI is not built (HEDGE_CLI unset)")


# ---- subdivide, smooth ----


def test_loop_subdivision_counts_follow_the_formulas(ico):
    for _ in range(2):
        v, e, f = ico.n_vertices, ico.n_edges, ico.n_faces
        ico.subdivide("loop", 1)
        assert (ico.n_vertices, ico.n_edges, ico.n_faces) == (v + e, 2 * e + 3 * f, 4 * f)
    assert ico.is_triangle_mesh()
    assert_valid(ico)


@needs_cli
def test_subdivide_matches_the_cli(ico, tmp_path):
    path, out = str(tmp_path / "ico.ply"), str(tmp_path / "ico2.ply")
    ico.write(path)
    cli("subdivide", "--scheme", "catmull-clark", "--steps", "2", path, out)
    info = json.loads(cli("info", "--json", out))
    ico.subdivide("catmull-clark", steps=2)
    assert (info["vertices"], info["edges"], info["faces"]) == (ico.n_vertices, ico.n_edges, ico.n_faces)
    assert info["area"] == pytest.approx(ico.area(), rel=1e-5)
    assert_valid(ico)


def test_subdivide_refuses_bad_input_and_views(ico):
    with pytest.raises(hedge.InvalidArgumentError, match="unknown subdivision scheme 'butterfly'"):
        ico.subdivide("butterfly")
    quads = hedge.Mesh.from_arrays(np.eye(4, 3), [[0, 1, 2, 3]])
    with pytest.raises(hedge.InvalidArgumentError):
        quads.subdivide("loop")
    assert quads.n_faces == 1
    P = ico.positions
    with pytest.raises(hedge.ViewsExportedError):
        ico.subdivide()
    del P
    assert ico.n_faces == 20
    assert_valid(ico)
    assert_valid(quads)


def test_smooth_moves_interior_vertices_only_and_views_see_it():
    V, F = grid_arrays(4)
    V[12, 2] = 1.0  # a spike in the middle of the grid
    mesh = hedge.Mesh.from_arrays(V, F)
    P = mesh.positions
    mesh.smooth("taubin", iterations=5, lambda_=0.5, mu=-0.53)
    assert abs(P[12, 2]) < 0.5  # the view sees the smoothed positions
    boundary = mesh.boundary_vertices()
    np.testing.assert_array_equal(P[boundary], V[boundary].astype(np.float32))
    mask = np.zeros(mesh.vertex_slots, dtype=bool)
    mask[6] = True
    before = P.copy()
    mesh.smooth("uniform", iterations=1, mask=mask)
    moved = np.flatnonzero(np.any(P != before, axis=1))
    assert set(moved) <= {6}
    with pytest.raises(hedge.InvalidArgumentError):
        mesh.smooth("uniform", lambda_=2.0)
    with pytest.raises(hedge.InvalidArgumentError):
        mesh.smooth("gaussian")
    assert_valid(mesh)


# ---- decimate, garbage collection, reorder ----


def test_decimate_reaches_the_target_and_says_so(ico):
    ico.subdivide("loop", 3)  # 1280 faces
    result = ico.decimate(target_faces=300)
    assert result["faces"] == ico.n_faces <= 300
    assert result["vertices"] == ico.n_vertices
    assert result["removed_faces"] == 1280 - ico.n_faces
    assert result["collapses"] > 0 and result["max_error"] > 0
    assert result["target_reached"] and result["stop"] == "target_reached"
    assert set(result["refused"]) == {"topology", "normal", "shape"}
    assert ico.face_slots == ico.n_faces  # compacted
    assert_valid(ico)


def test_decimate_stops_at_max_error(ico):
    ico.subdivide("loop", 2)
    result = ico.decimate(max_error=1e-9)
    assert result["collapses"] == 0 and result["faces"] == 320
    assert not result["target_reached"] and result["stop"] == "error_bound"
    result = ico.decimate(ratio=0.5)
    assert result["faces"] <= 160 and result["target_reached"]
    assert_valid(ico)


def test_decimate_holds_the_normal_limit_when_asked_and_says_why_it_stopped(ico):
    ico.subdivide("loop", 2)
    held = ico.clone()
    strict = held.decimate(target_vertices=4, max_normal_change_degrees=1, relax_normal_change=False)
    assert strict["stop"] == "no_legal_collapse" and not strict["target_reached"]
    assert strict["refused"]["normal"] > 0 and strict["vertices"] > 4
    assert_valid(held)
    relaxed = ico.decimate(target_vertices=4, max_normal_change_degrees=1)
    assert relaxed["collapses"] > strict["collapses"]
    assert_valid(ico)


def test_decimate_errors_leave_the_mesh_unchanged(ico):
    before = ico.to_arrays()
    with pytest.raises(hedge.InvalidArgumentError):
        ico.decimate(target_faces=-1)
    with pytest.raises(hedge.InvalidArgumentError):
        ico.decimate(ratio=1.5)
    with pytest.raises(hedge.InvalidArgumentError):
        ico.decimate(max_error=-1.0)
    view = ico.halfedge_next_array
    with pytest.raises(hedge.ViewsExportedError):
        ico.decimate(target_faces=10)
    del view
    np.testing.assert_array_equal(ico.to_arrays()[1], before[1])
    assert_valid(ico)


def test_decimate_wants_one_target_and_not_two_face_counts(ico):
    faces = ico.n_faces
    with pytest.raises(hedge.InvalidArgumentError) as caught:
        ico.decimate()
    assert str(caught.value) == "decimate: give a target: target_faces, target_vertices, ratio or max_error"
    with pytest.raises(hedge.InvalidArgumentError, match="ratio and target_faces"):
        ico.decimate(ratio=0.5, target_faces=100)
    assert ico.n_faces == faces
    assert ico.decimate(target_vertices=8)["vertices"] == 8
    assert_valid(ico)


def test_garbage_collection_returns_the_maps(grid):
    V0, _ = grid.to_arrays()
    assert grid.remove_faces([0, 1]) == 2  # the two faces of corner vertex 0, which goes with them
    maps = grid.garbage_collection()
    assert set(maps) == {"vertices", "halfedges", "edges", "faces"}
    assert list(maps["faces"][:3]) == [-1, -1, 0]
    assert np.array_equal(np.sort(maps["faces"][maps["faces"] >= 0]), np.arange(grid.n_faces))
    assert len(maps["vertices"]) == 25 and grid.vertex_slots == grid.n_vertices == 24
    assert maps["vertices"][0] == -1
    assert len(maps["halfedges"]) == 2 * len(maps["edges"])
    # Each surviving vertex kept its position under its new index.
    live = np.flatnonzero(maps["vertices"] >= 0)
    np.testing.assert_array_equal(grid.positions[maps["vertices"][live]], V0[live])
    assert_valid(grid)


def test_reorder_renumbers_and_keeps_the_surface(ico):
    ico.subdivide("loop", 2)
    area = ico.area()
    V0 = ico.positions.copy()
    maps = ico.reorder("vertex-cache", cache_size=16)
    assert sorted(maps["vertices"]) == list(range(ico.n_vertices))
    np.testing.assert_array_equal(ico.positions[maps["vertices"]], V0)
    assert ico.area() == pytest.approx(area, rel=1e-12)
    ico.reorder()
    with pytest.raises(hedge.InvalidArgumentError, match="unknown ordering"):
        ico.reorder("random")
    assert_valid(ico)


def fifo_cache_misses(mesh, cache_size):
    """Vertex loads per triangle of drawing the mesh's triangles in face order, each from the
    target of its face's half-edge on, through a FIFO cache; the corners come from the views."""
    to, nxt = mesh.halfedge_vertex_array, mesh.halfedge_next_array
    first = mesh.face_halfedge_array
    F = np.column_stack([to[first], to[nxt[first]], to[nxt[nxt[first]]]])
    cache, misses = [], 0
    for tri in F:
        for v in tri:
            if v not in cache:
                misses += 1
                cache.append(v)
                if len(cache) > cache_size:
                    cache.pop(0)
    return misses / len(F)


def test_vertex_cache_order_lowers_the_cache_miss_ratio():
    rng = np.random.default_rng(5)
    V, F = grid_arrays(12)
    mesh = hedge.Mesh.from_arrays(V, F[rng.permutation(len(F))])  # faces in a shuffled order
    shuffled = mesh.cache_miss_ratio(16)
    assert shuffled == pytest.approx(fifo_cache_misses(mesh, 16))
    mesh.reorder("vertex-cache", cache_size=16)
    ordered = mesh.cache_miss_ratio(16)
    assert ordered == pytest.approx(fifo_cache_misses(mesh, 16))
    assert ordered < 0.6 * shuffled
    with pytest.raises(hedge.InvalidArgumentError):
        mesh.cache_miss_ratio(0)
    assert_valid(mesh)


# ---- normals and geometry ----


def test_normals_against_numpy(ico):
    V, F = ico.to_arrays()
    cross = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    expected = cross / np.linalg.norm(cross, axis=1, keepdims=True)
    np.testing.assert_allclose(ico.face_normals(), expected, atol=1e-6)
    # On a sphere-like solid, vertex normals point away from the centre.
    N = ico.vertex_normals("angle")
    radial = V / np.linalg.norm(V, axis=1, keepdims=True)
    np.testing.assert_allclose(N, radial, atol=1e-6)
    np.testing.assert_allclose(ico.property("v:normal"), N)  # stored for write()
    C = ico.corner_normals(crease_degrees=0)  # flat: every corner has its face's normal
    faces = ico.halfedge_face_array
    np.testing.assert_allclose(C[faces >= 0], expected[faces[faces >= 0]], atol=1e-6)
    with pytest.raises(hedge.InvalidArgumentError):
        ico.vertex_normals("cotangent")
    with pytest.raises(hedge.InvalidArgumentError):
        ico.corner_normals(crease_degrees=200)


def test_normals_have_nan_rows_for_deleted_slots(grid):
    assert grid.remove_face(0)
    N = grid.face_normals()
    assert N.shape == (grid.face_slots, 3)
    assert np.isnan(N[0]).all()
    np.testing.assert_allclose(np.delete(N, 0, axis=0), np.tile([0, 0, 1], (grid.n_faces, 1)), atol=1e-6)
    assert_valid(grid)


def test_area_volume_and_box_against_numpy(ico):
    assert ico.area() == pytest.approx(numpy_area(ico), rel=1e-6)
    assert ico.volume() == pytest.approx(numpy_volume(ico), rel=1e-6)
    V, _ = ico.to_arrays()
    np.testing.assert_allclose(ico.bounding_box(), [V.min(axis=0), V.max(axis=0)])
    assert np.isnan(hedge.Mesh().bounding_box()).all()


def test_volume_of_an_open_surface_raises(grid):
    with pytest.raises(hedge.InvalidArgumentError, match="boundary"):
        grid.volume()
    assert grid.area() == pytest.approx(16.0)


def test_mass_properties_of_a_box():
    a, b, c = 1.0, 2.0, 3.0
    box = hedge.Mesh.from_arrays(*box_arrays((a, b, c)))
    mp = box.mass_properties(density=2.0)
    mass = 2.0 * a * b * c
    assert mp["volume"] == pytest.approx(a * b * c)
    assert mp["mass"] == pytest.approx(mass)
    np.testing.assert_allclose(mp["centre_of_mass"], [a / 2, b / 2, c / 2], atol=1e-9)
    # A solid box's inertia about its centre: m/12 (b^2 + c^2), ... on the diagonal, 0 elsewhere.
    expected = mass / 12 * np.diag([b * b + c * c, a * a + c * c, a * a + b * b])
    np.testing.assert_allclose(mp["inertia"], expected, atol=1e-9)
    np.testing.assert_allclose(mp["principal_moments"], np.sort(np.diag(expected)), rtol=1e-9)
    axes = mp["principal_axes"]
    np.testing.assert_allclose(np.abs(axes), np.eye(3)[[2, 1, 0]], atol=1e-9)  # ascending moments: z, y, x
    with pytest.raises(hedge.InvalidArgumentError):
        box.mass_properties(density=0)
    with pytest.raises(hedge.InvalidArgumentError):
        hedge.Mesh.from_arrays(*grid_arrays()).mass_properties()


def test_convex_hull_is_a_new_closed_mesh(ico):
    V, F = icosahedron_arrays()
    # The icosahedron's vertices and its centre: the hull is the icosahedron again.
    mesh = hedge.Mesh.from_arrays(np.vstack([V, [[0, 0, 0]]]), F)
    hull = mesh.convex_hull()
    assert (hull.n_vertices, hull.n_faces) == (12, 20)
    assert hull.volume() == pytest.approx(ico.volume(), rel=1e-6)
    assert mesh.n_vertices == 13  # the input is untouched
    flat = hedge.Mesh.from_arrays(*grid_arrays()).convex_hull(flat_thickness=1e-2)
    assert flat.n_faces > 0 and flat.validate() == []
    assert hedge.Mesh().convex_hull().n_faces == 0
    with pytest.raises(hedge.InvalidArgumentError):
        mesh.convex_hull(max_vertices=2)
    assert_valid(hull)


# ---- Hausdorff distance ----


def test_hausdorff_of_a_mesh_with_itself_and_a_shifted_copy(ico):
    same = hedge.hausdorff_distance(ico, ico, samples=1000)
    assert same["distance"] == pytest.approx(0, abs=1e-6)
    V, F = icosahedron_arrays()
    shifted = hedge.Mesh.from_arrays(V + [0, 0, 0.25], F)
    d = hedge.hausdorff_distance(ico, shifted, samples=2000, seed=7)
    # The farthest points lie on faces facing along the shift: at most the shift, nearly all of it.
    assert 0.2 < d["distance"] <= 0.25 + 1e-6
    assert d["a_to_b"]["points"] == 12 + 2000 and d["b_to_a"]["points"] == 12 + 2000
    assert d["distance"] == max(d["a_to_b"]["max"], d["b_to_a"]["max"])
    with pytest.raises(hedge.InvalidArgumentError):
        hedge.hausdorff_distance(ico, hedge.Mesh())
    # threads as render takes them: 0 is every core, and gives the same distances.
    every_core = hedge.hausdorff_distance(ico, shifted, samples=2000, seed=7, threads=0)
    assert (every_core["distance"], every_core["mean"]) == (d["distance"], d["mean"])
    for threads in (-1, 10**6):
        with pytest.raises(hedge.InvalidArgumentError) as caught:
            hedge.hausdorff_distance(ico, shifted, threads=threads)
        assert str(caught.value) == f"hausdorff_distance: threads must be 0 (every core) to 1024, got {threads}"
    with pytest.raises(hedge.InvalidArgumentError) as caught:
        hedge.hausdorff_distance(ico, shifted, samples=10**9)
    assert str(caught.value) == "hausdorff_distance: samples must be at most 100000000, got 1000000000; draw fewer"


@needs_cli
def test_hausdorff_matches_the_cli(ico, tmp_path):
    V, F = icosahedron_arrays()
    shifted = hedge.Mesh.from_arrays(V * 1.1, F)
    a, b = str(tmp_path / "a.ply"), str(tmp_path / "b.ply")
    ico.write(a)
    shifted.write(b)
    info = json.loads(cli("distance", "--json", "--samples", "500", "--seed", "3", a, b))
    d = hedge.hausdorff_distance(ico, shifted, samples=500, seed=3)
    assert d["distance"] == pytest.approx(info["hausdorff"], rel=1e-6)


# ---- the GIL ----


@pytest.mark.parametrize("call", [lambda m: m.subdivide("loop", 2), lambda m: m.decimate(ratio=0.2)])
def test_long_algorithms_release_the_gil(call):
    mesh = hedge.Mesh.from_arrays(*grid_arrays(120))  # 28,800 triangles
    done = threading.Event()
    busy = []

    def work():
        try:
            call(mesh)
        finally:
            done.set()

    thread = threading.Thread(target=work)
    thread.start()
    while not done.is_set() and not busy:
        try:
            mesh.n_faces
        except hedge.BusyError as e:
            busy.append(e)
    thread.join()
    assert busy, "the main thread never ran while the algorithm held the mesh: is the GIL released?"
    assert_valid(mesh)
