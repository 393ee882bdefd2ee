"""Index and mask arguments (py_args.cpp): one converter for every call that takes element indices.

Integers only, as numpy users give them (arrays of any integer dtype, lists of ints); a bool array
of one entry per slot is a mask, read as np.flatnonzero(mask). Anything else is refused with an
InvalidArgumentError that names the call and the argument, before the mesh is touched.
"""

import numpy as np
import pytest

import hedge
from conftest import assert_valid, grid_arrays


def live_faces_of(mesh):
    return sorted(f for f in range(mesh.face_slots) if mesh.can_split_face(f))


def test_remove_faces_takes_a_bool_mask_as_flatnonzero(grid):
    mask = np.zeros(grid.face_slots, dtype=bool)
    mask[[5, 9, 20]] = True
    assert grid.remove_faces(mask) == 3
    assert live_faces_of(grid) == [f for f in range(32) if f not in (5, 9, 20)]
    assert_valid(grid)


@pytest.mark.parametrize(
    "faces, message",
    [
        (np.array([1.5, 2.5]), "remove_faces: faces must hold integers, not float64"),
        ([1, 2.0], "remove_faces: faces must hold integers, not float64"),
        (np.array([True, False]), "remove_faces: faces as a bool mask must have one entry per slot (32), not 2"),
        (np.array([[1, 2]]), "remove_faces: faces must be a 1-D array of integer indices, not of 2 dimensions"),
        ("12", "remove_faces: faces must be a 1-D array of integer indices, not a string"),
        (3, "remove_faces: faces must be a 1-D array of integer indices, not of 0 dimensions"),
    ],
)
def test_remove_faces_refuses_what_is_not_indices(grid, faces, message):
    with pytest.raises(hedge.InvalidArgumentError) as caught:
        grid.remove_faces(faces)
    assert str(caught.value) == message
    assert grid.n_faces == 32
    assert_valid(grid)


def test_integer_dtypes_and_lists_and_empty_ones_are_indices(grid):
    assert grid.remove_faces(np.array([3], dtype=np.uint16)) == 1
    assert grid.remove_faces([4, 4]) == 1
    assert grid.remove_faces([]) == 0
    assert grid.remove_faces(np.array([], dtype=np.int32)) == 0
    with pytest.raises(hedge.BadHandleError):  # past int64's range stays out of range
        grid.remove_faces(np.array([2**64 - 1], dtype=np.uint64))
    assert grid.n_faces == 30
    assert_valid(grid)


def test_positions_changed_takes_indices_or_a_mask(grid):
    mask = np.zeros(grid.vertex_slots, dtype=bool)
    mask[2] = True
    grid.positions[2] = np.nan
    with pytest.raises(hedge.InvalidArgumentError, match="vertex 2 has a position that is not finite"):
        grid.positions_changed(mask)
    grid.positions[2] = (2, 0, 0.5)
    grid.positions_changed(mask)
    for bad, message in [
        (np.array([0.5]), "positions_changed: vertices must hold integers, not float64"),
        (np.ones(3, dtype=bool), "positions_changed: vertices as a bool mask must have one entry per slot (25)"),
    ]:
        with pytest.raises(hedge.InvalidArgumentError) as caught:
            grid.positions_changed(bad)
        assert message in str(caught.value)
    assert_valid(grid)


def test_one_rings_take_the_same_arguments(grid):
    mask = np.zeros(grid.vertex_slots, dtype=bool)
    mask[[6, 12]] = True
    offsets, rings = grid.one_rings(mask)
    ref_offsets, ref_rings = grid.one_rings(np.flatnonzero(mask))
    assert np.array_equal(offsets, ref_offsets) and np.array_equal(rings, ref_rings)
    assert sorted(rings[offsets[1] : offsets[2]]) == sorted(grid.one_ring(12))
    with pytest.raises(hedge.InvalidArgumentError, match="one_rings: vertices must hold integers, not float64"):
        grid.one_rings(np.array([6.0]))


def test_from_arrays_refuses_float_corners_in_a_list():
    with pytest.raises(hedge.InvalidArgumentError, match="from_arrays: F must hold integers, not float64"):
        hedge.Mesh.from_arrays(np.eye(3), [[0, 1, 2.7]])
    with pytest.raises(hedge.InvalidArgumentError, match="from_arrays: F must hold integers, not bool"):
        hedge.Mesh.from_arrays(np.eye(3), np.ones((1, 3), dtype=bool))
    mesh = hedge.Mesh.from_arrays(np.eye(3), [np.array([0, 1, 2], dtype=np.uint8)])
    assert mesh.n_faces == 1
    assert_valid(mesh)


def test_smooth_mask_moves_the_nonzero_vertices():
    V, F = grid_arrays()
    V[12, 2] = 1.0  # a bump at the centre
    before = hedge.Mesh.from_arrays(V, F)
    for mask_value in (0.5, True, 3):
        mesh = before.clone()
        mask = np.zeros(mesh.vertex_slots, dtype=type(mask_value))
        mask[12] = mask_value
        mesh.smooth(iterations=1, mask=mask)
        moved = np.flatnonzero(np.any(mesh.positions != before.positions, axis=1))
        assert moved.tolist() == [12], mask_value
        assert_valid(mesh)
    for bad, message in [
        (np.zeros(3), "smooth: mask must have one entry per slot (25), not shape (3,)"),
        (np.array(["a"] * 25), "smooth: mask must be a 1-D array of numbers or bools"),
    ]:
        with pytest.raises(hedge.InvalidArgumentError) as caught:
            before.smooth(mask=bad)
        assert message in str(caught.value)


def test_refusal_takes_its_elements_through_the_same_converter(grid):
    assert grid.refusal("flip", np.array([5], dtype=np.uint8)) == grid.refusal("flip", [5])
    with pytest.raises(hedge.InvalidArgumentError) as caught:
        grid.refusal("flip", [1.5])
    assert str(caught.value) == "refusal: elements must hold integers, not float64"
