"""Mesh.fracture: shards as meshes with their mass properties, checked against numpy and the CLI."""

import json
import os
import subprocess
import threading

import numpy as np
import pytest
from conftest import assert_valid, grid_arrays

import hedge

IMPACT = (10.3, 10.4, 0.0)


def plate(n=20):
    V, F = grid_arrays(n)
    return hedge.Mesh.from_arrays(V, F)


def triangles(mesh):
    """The mesh's triangles as an (m, 3, 3) float64 array."""
    V, F = mesh.to_arrays()
    F = np.asarray(F)
    assert F.ndim == 2 and F.shape[1] == 3
    return V.astype(np.float64)[F]


def surface_area(mesh):
    t = triangles(mesh)
    return 0.5 * np.linalg.norm(np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]), axis=1).sum()


def solid_properties(mesh, density):
    """Volume, centre of mass and inertia about it of a closed triangle mesh, from its tetrahedra
    with the origin: the second moment of each is det/120 * A K A^T (A: its corners as columns)."""
    t = triangles(mesh)
    det = np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2]))
    volume = det.sum() / 6
    centre = (det[:, None] * t.sum(axis=1)).sum(axis=0) / 24 / volume
    K = np.array([[2.0, 1, 1], [1, 2, 1], [1, 1, 2]])
    A = np.transpose(t, (0, 2, 1))
    C = (det[:, None, None] * (A @ K @ np.transpose(A, (0, 2, 1)))).sum(axis=0) / 120
    C -= volume * np.outer(centre, centre)
    inertia = density * (np.trace(C) * np.eye(3) - C)
    return volume, centre, inertia


def test_shards_are_meshes_and_the_rest_stays_in_the_mesh():
    mesh = plate()
    before_faces, before_area = mesh.n_faces, surface_area(mesh)
    shards = mesh.fracture(IMPACT, "glass", seed=3)
    assert 1 < len(shards) <= 40  # glass has 40 break points: at most one shard each
    for s in shards:
        assert isinstance(s, hedge.Shard) and isinstance(s, hedge.Mesh)
        assert s.n_faces > 0 and not s.closed
        assert_valid(s)
    # The broken faces left the mesh; refining them only adds faces, and no area is lost or made.
    assert mesh.n_faces < before_faces
    assert mesh.n_faces + sum(s.n_faces for s in shards) >= before_faces
    assert surface_area(mesh) + sum(s.front_area for s in shards) == pytest.approx(before_area, rel=1e-6)
    assert_valid(mesh)


def test_the_same_seed_gives_the_same_shards_and_another_seed_others():
    def arrays(seed):
        shards = plate().fracture(IMPACT, seed=seed)
        return [tuple(np.asarray(a).tobytes() for a in s.to_arrays()) for s in shards]

    assert arrays(7) == arrays(7)
    assert arrays(7) != arrays(8)
    assert arrays(2**64 - 1) == arrays(np.uint64(2**64 - 1))  # any integer, numpy's too


def test_an_open_shard_reports_the_area_and_centroid_of_its_faces():
    for s in plate().fracture(IMPACT, "ice", seed=1):
        t = triangles(s)
        areas = 0.5 * np.linalg.norm(np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]), axis=1)
        assert s.front_area == pytest.approx(areas.sum(), rel=1e-6)
        np.testing.assert_allclose(s.front_centroid, (areas[:, None] * t.mean(axis=1)).sum(axis=0) / areas.sum(), rtol=1e-6)
        # An open shard weighs as a thin shell: a mass and a positive-definite inertia.
        assert not s.closed and s.shell_thickness > 0
        assert s.mass["volume"] == pytest.approx(s.front_area * s.shell_thickness, rel=1e-9)
        assert s.mass["mass"] > 0 and s.mass["principal_moments"][0] > 0


def test_a_solid_shard_has_the_mass_properties_numpy_computes():
    mesh = plate()
    shards = mesh.fracture(IMPACT, "stone", seed=5, thickness=0.25, density=2.5)
    assert shards
    for s in shards:
        assert s.closed
        assert_valid(s)
        volume, centre, inertia = solid_properties(s, 2.5)
        mp = s.mass
        assert mp["volume"] == pytest.approx(volume, rel=1e-6)
        assert mp["mass"] == pytest.approx(2.5 * volume, rel=1e-6)
        np.testing.assert_allclose(mp["centre_of_mass"], centre, rtol=1e-6, atol=1e-6)
        np.testing.assert_allclose(mp["inertia"], inertia, rtol=1e-5, atol=1e-6 * np.abs(inertia).max())
        axes, moments = mp["principal_axes"], mp["principal_moments"]
        np.testing.assert_allclose(moments, np.linalg.eigvalsh(inertia), rtol=1e-6)
        np.testing.assert_allclose(axes @ axes.T, np.eye(3), atol=1e-9)
        assert np.linalg.det(axes) == pytest.approx(1.0)
        for a in range(3):
            np.testing.assert_allclose(mp["inertia"] @ axes[a], moments[a] * axes[a], atol=1e-6 * moments.max())
        # The solid is the front (the broken faces) thickened against its normals: here, down z.
        assert s.front_area == pytest.approx(volume / 0.25, rel=1e-3)
    assert_valid(mesh)


def test_hulls_are_meshes_and_can_be_left_out():
    shards = plate().fracture(IMPACT, "stone", seed=5, thickness=0.25)
    for s in shards:
        assert s.hull_dimension == "solid" and s.hull_tolerance > 0
        hull = s.hull
        assert isinstance(hull, hedge.Mesh) and not isinstance(hull, hedge.Shard)
        assert_valid(hull)
        V, _ = s.to_arrays()
        Vh, _ = hull.to_arrays()
        assert (Vh.min(axis=0) >= V.min(axis=0) - 1e-5).all() and (Vh.max(axis=0) <= V.max(axis=0) + 1e-5).all()
    assert all(s.hull is None and s.hull_dimension == "empty" for s in plate().fracture(IMPACT, hulls=False))


def test_a_break_radius_breaks_that_far_and_a_custom_material_its_rings():
    small = sum(s.front_area for s in plate().fracture(IMPACT, "stone", break_radius=2))
    large = sum(s.front_area for s in plate().fracture(IMPACT, "stone", break_radius=5))
    assert 0 < small < large
    material = {"rings": [{"points": np.int64(3), "spacing": 2.0}, {"points": 5, "spacing": 2, "jitter": 0.5}]}
    mesh = plate()
    shards = mesh.fracture(IMPACT, material, seed=2)
    assert 1 < len(shards) <= 8
    assert_valid(mesh)


def test_the_presets_break_the_same_share_at_every_resolution_units_and_radius_change_it():
    def share(n, **options):
        V, F = grid_arrays(n)
        mesh = hedge.Mesh.from_arrays(V * (20.0 / n), F)
        return sum(s.front_area for s in mesh.fracture(IMPACT, seed=3, **options)) / 400

    coarse, fine = share(20), share(80)
    assert abs(fine - coarse) < 0.1 * coarse
    assert share(80, units="edge_lengths", radius=7) < share(20, units="edge_lengths", radius=7) / 8
    assert share(40, units="model", radius=2) < share(40, units="model", radius=4) / 2.5


def test_the_default_strike_on_spot_gives_the_librarys_shards():
    # The library's FractureMaterial.TheDefaultStrikeOnSpotThatEveryBindingChecks gives these numbers:
    # the binding's defaults are the library's.
    data = os.path.join(os.path.dirname(__file__), "..", "..", "..", "data", "spot_triangulated.obj")
    mesh = hedge.read(data)
    shards = mesh.fracture((0.380073, -0.0641595, 0.195141))
    assert len(shards) == 40
    assert sum(s.front_area for s in shards) == pytest.approx(0.498213, abs=1e-6)
    assert sum(s.mass["mass"] for s in shards) == pytest.approx(0.00838123, abs=1e-8)


def test_a_shard_is_a_mesh_like_any_other():
    mesh = plate()
    shard = mesh.fracture(IMPACT, seed=1)[0]
    e = next(e for e in range(shard.n_edges) if shard.can_split_edge(e))
    assert shard.split_edge(e) is not None
    assert hedge.render(shard, 32, 24).shape == (24, 32, 3)
    assert_valid(shard)
    copy = shard.clone()
    assert copy.n_faces == shard.n_faces
    assert_valid(mesh)


@pytest.mark.skipif(not os.environ.get("HEDGE_CLI"), reason="the CLI is not built (HEDGE_CLI unset)")
@pytest.mark.parametrize(
    "material,thickness",
    [("stone", 0.0), ("glass", 0.2), ({"name": "tile", "rings": [{"points": 5, "spacing": 1.5, "jitter": 0.3}]}, 0.1)],
)
def test_the_same_shards_as_the_cli(tmp_path, material, thickness):
    mesh = plate()
    mesh.write(str(tmp_path / "plate.ply"))
    cli_material = material
    if isinstance(material, dict):
        cli_material = str(tmp_path / "tile.json")
        with open(cli_material, "w", encoding="utf-8") as f:
            json.dump(material, f)
    command = [os.environ["HEDGE_CLI"], "fracture", str(tmp_path / "plate.ply"), "--impact", "10.3,10.4,0"]
    command += ["--material", cli_material, "--seed", "11", "--thickness", str(thickness), "--density", "3"]
    out = subprocess.run(command + ["-o", str(tmp_path / "out"), "--json"], capture_output=True, text=True, check=True)
    summary = json.loads(out.stdout)
    shards = mesh.fracture(IMPACT, material, seed=11, thickness=thickness, density=3)
    assert len(shards) == len(summary["shards"]) > 1
    assert mesh.n_faces == summary["remaining"]["faces"]
    for s, c in zip(shards, summary["shards"]):
        assert (s.n_faces, s.n_vertices, s.closed) == (c["faces"], c["vertices"], c["closed"])
        np.testing.assert_allclose(s.front_centroid, c["centroid"], rtol=1e-12)
        assert s.front_area == pytest.approx(c["area"], rel=1e-12)
        mp = s.mass  # of the solid, or of the thin shell an open shard weighs as
        assert s.shell_thickness == c["shell_thickness"]
        assert mp["volume"] == pytest.approx(c["volume"], rel=1e-12)
        assert mp["mass"] == pytest.approx(c["mass"]["mass"], rel=1e-12)
        np.testing.assert_allclose(mp["principal_moments"], c["mass"]["principal_moments"], rtol=1e-12)
        assert s.hull.n_faces == c["hull"]["faces"]
    assert_valid(mesh)


@pytest.mark.parametrize(
    "point,options,message",
    [
        ((1, 2, float("nan")), {}, "fracture: point (1.000000, 2.000000, nan) is not finite"),
        ((1, 2), {}, "fracture: point must be 3 numbers"),
        ("1,2,0", {}, "fracture: point must be 3 numbers"),
        ((1, 2, 5), {}, "is 5 from the nearest face"),
        ((1, 2, 0), {"material": "rubber"}, "unknown material 'rubber'; valid presets: glass, stone, wood, ice"),
        ((1, 2, 0), {"material": 3}, "material must be a preset name (glass, stone, wood, ice) or a dict, not int"),
        ((1, 2, 0), {"material": {"rings": [{"points": 3, "spacing": -1}]}}, "'rings[0].spacing' must be positive"),
        ((1, 2, 0), {"material": {"rings": [{"points": 3, "spacing": float("inf")}]}}, "must be finite"),
        ((1, 2, 0), {"material": {"rings": [], "colour": 1}}, "'colour' is unknown"),
        ((1, 2, 0), {"seed": -1}, "seed must be a whole number in [0, 2^64), got -1"),
        ((1, 2, 0), {"seed": 1.5}, "seed must be a whole number in [0, 2^64), not float"),
        ((1, 2, 0), {"break_radius": -2}, "radius"),
        ((1, 2, 0), {"units": "metres"}, "units must be 'diagonal_fraction', 'model' or 'edge_lengths'"),
        ((1, 2, 0), {"radius": -1}, "radius (the break radius, in diagonal_fraction) must be finite"),
        ((1, 2, 0), {"shell_thickness": -1}, "shell_thickness must be finite and >= 0"),
        ((1, 2, 0), {"material": {"rings": [{"points": 3, "spacing": 1}], "absolute": True}}, "replaced by units"),
        ((1, 2, 0), {"thickness": -1}, "thickness must be finite and >= 0"),
        ((1, 2, 0), {"thickness": 0.1, "relative_thickness": 0.1}, "thickness"),
        ((1, 2, 0), {"density": 0}, "density"),
    ],
)
def test_bad_input_is_a_clear_error_and_leaves_the_mesh_unchanged(point, options, message):
    mesh = plate(4)
    before = mesh.to_arrays()
    with pytest.raises(hedge.InvalidArgumentError) as e:
        mesh.fracture(point, **options)
    assert isinstance(e.value, ValueError)
    assert message in str(e.value)
    after = mesh.to_arrays()
    assert np.array_equal(before[0], after[0]) and np.array_equal(before[1], after[1])
    assert_valid(mesh)


def test_views_alive_block_a_fracture():
    mesh = plate(4)
    P = mesh.positions
    with pytest.raises(hedge.ViewsExportedError, match="fracture"):
        mesh.fracture((1.3, 1.4, 0))
    del P
    assert mesh.fracture((1.3, 1.4, 0))
    assert_valid(mesh)


def test_the_picking_tree_follows_the_fracture():
    mesh = plate()
    mesh.ray_cast([[10.3, 10.4, 1]], [[0, 0, -1]])  # builds the picking tree
    mesh.fracture(IMPACT, seed=3)
    faces, _, _ = mesh.ray_cast([[10.3, 10.4, 1], [0.5, 0.5, 1]], [[0, 0, -1], [0, 0, -1]])
    assert faces[0] == -1 and faces[1] >= 0  # a hole where it broke, the plate elsewhere
    assert_valid(mesh)


def test_fracture_releases_the_gil():
    n = 300  # the first strike builds the picking tree over 180,000 triangles
    xs, ys = np.meshgrid(np.arange(n + 1.0), np.arange(n + 1.0))
    V = np.column_stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)])
    a = (np.arange(n)[None, :] + (n + 1) * np.arange(n)[:, None]).ravel()
    F = np.concatenate([np.column_stack([a, a + 1, a + n + 2]), np.column_stack([a, a + n + 2, a + n + 1])])
    mesh = hedge.Mesh.from_arrays(V, F)
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(1)
            done.wait(0.0005)

    thread = threading.Thread(target=tick)
    thread.start()
    try:
        shards = mesh.fracture((150.3, 150.4, 0), seed=1)
    finally:
        done.set()
        thread.join()
    assert shards and len(ticks) > 10  # about 2 while the GIL is held
    assert_valid(mesh)


def test_a_shard_keeps_every_mesh_method():
    # Shard's own attributes must not hide Mesh's methods: area() and mass_properties() of a shard
    # agree with what the fracture reported of it.
    mesh = plate()
    shards = mesh.fracture(IMPACT, "stone", seed=3, thickness=0.25, density=2.0)
    for s in shards:
        assert callable(s.area) and callable(s.mass_properties)
        assert s.area() > s.front_area > 0  # the solid adds a back and walls to the front
        again = s.mass_properties(density=2.0)
        assert again["mass"] == pytest.approx(s.mass["mass"], rel=1e-9)
        np.testing.assert_allclose(again["centre_of_mass"], s.mass["centre_of_mass"], rtol=1e-9, atol=1e-12)
        assert_valid(s)
    assert_valid(mesh)
