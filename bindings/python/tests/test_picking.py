"""ray_cast and closest_point over arrays (src/py_picking.cpp), and the picking tree following
edits and positions_changed()."""

import numpy as np
import pytest
from conftest import assert_valid

import hedge


def down_rays(xy):
    xy = np.asarray(xy, dtype=np.float32)
    origins = np.column_stack([xy, np.full(len(xy), 5.0, dtype=np.float32)])
    directions = np.tile(np.array([0, 0, -1], dtype=np.float32), (len(xy), 1))
    return origins, directions


def test_ray_cast_hits_and_misses(grid):
    origins, directions = down_rays([[0.25, 0.75], [3.5, 3.2], [9.0, 9.0]])
    faces, t, points = grid.ray_cast(origins, directions)
    assert faces.dtype == np.int32 and faces[2] == -1 and np.isnan(t[2])
    np.testing.assert_allclose(t[:2], [5.0, 5.0], rtol=1e-6)
    np.testing.assert_allclose(points[:2], [[0.25, 0.75, 0], [3.5, 3.2, 0]], atol=1e-6)
    _, F = grid.to_arrays()
    # Face 1 is the upper triangle of the first square (a, c, d).
    assert faces[0] == 1 and set(F[faces[1]]) <= {18, 19, 23, 24}


def test_the_tree_follows_positions_changed(grid):
    origins, directions = down_rays([[0.25, 0.75]])
    assert grid.ray_cast(origins, directions)[1][0] == pytest.approx(5.0)
    P = grid.positions
    P[:, 0] += 100.0
    # The tree's boxes move when the change log says so: without positions_changed() a ray at the
    # new place would still walk the old boxes.
    grid.positions_changed()
    moved, _ = down_rays([[100.25, 0.75]])
    assert grid.ray_cast(moved, directions)[0][0] == 1
    assert grid.ray_cast(origins, directions)[0][0] == -1
    del P
    # Edits reach the tree by themselves.
    assert grid.remove_face(1)
    assert grid.ray_cast(moved, directions)[0][0] == -1
    assert_valid(grid)


def test_closest_point(grid):
    faces, points, distances = grid.closest_point(np.array([[0.25, 0.75, 2.0], [-1.0, 0.5, 0.0]]))
    assert faces[0] == 1
    np.testing.assert_allclose(points, [[0.25, 0.75, 0], [0, 0.5, 0]], atol=1e-6)
    np.testing.assert_allclose(distances, [2.0, 1.0], rtol=1e-6)
    empty = hedge.Mesh()
    faces, _, distances = empty.closest_point(np.zeros((1, 3)))
    assert faces[0] == -1 and np.isnan(distances[0])


def test_bad_arrays(grid):
    with pytest.raises(hedge.InvalidArgumentError) as caught:
        grid.ray_cast(np.zeros((2, 3)), np.zeros((3, 3)))
    assert "2 origins but 3 directions" in str(caught.value)
    with pytest.raises(ValueError):
        grid.ray_cast(np.zeros((2, 2)), np.zeros((2, 2)))
    with pytest.raises(hedge.InvalidArgumentError):
        grid.closest_point(np.zeros(3))


@pytest.mark.parametrize(
    "row, origin, direction, message",
    [
        (1, (np.nan, 0, 5), (0, 0, -1), "ray_cast: origins[1] (nan, 0, 5) is not finite"),
        (0, (0, 0, 5), (0, np.inf, -1), "ray_cast: directions[0] (0, inf, -1) is not finite"),
        (2, (0, 0, 5), (0, 0, 0), "ray_cast: directions[2] has zero length"),
    ],
)
def test_ray_cast_names_a_bad_row(grid, row, origin, direction, message):
    origins, directions = down_rays([[0.25, 0.75], [0.5, 0.5], [1.5, 1.5]])
    origins[row], directions[row] = origin, direction
    with pytest.raises(hedge.InvalidArgumentError) as caught:
        grid.ray_cast(origins, directions)
    assert str(caught.value) == message
    assert isinstance(caught.value, ValueError)
    # The good rows still work once the bad one is gone.
    keep = [i for i in range(3) if i != row]
    assert (grid.ray_cast(origins[keep], directions[keep])[0] >= 0).all()
    assert_valid(grid)


def test_closest_point_names_a_bad_row(grid):
    points = np.array([[0.25, 0.75, 2.0], [0, 0, 0], [1, -np.inf, 0]])
    with pytest.raises(hedge.InvalidArgumentError) as caught:
        grid.closest_point(points)
    assert str(caught.value) == "closest_point: points[2] (1, -inf, 0) is not finite"
    points[1, 2] = np.nan
    with pytest.raises(hedge.InvalidArgumentError, match=r"points\[1\] \(0, 0, nan\)"):
        grid.closest_point(points)
    assert_valid(grid)
