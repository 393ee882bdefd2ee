"""Shared meshes of the Python binding's tests."""

import numpy as np
import pytest

import hedge


def grid_arrays(n=4):
    """An n x n grid of unit squares in the z = 0 plane, each cut into two triangles."""
    xs, ys = np.meshgrid(np.arange(n + 1, dtype=np.float64), np.arange(n + 1, dtype=np.float64))
    V = np.column_stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)])
    faces = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            b, c, d = a + 1, a + n + 2, a + n + 1
            faces += [[a, b, c], [a, c, d]]
    return V, np.array(faces, dtype=np.int64)


def assert_valid(mesh):
    """Every test that edits a mesh ends here: the half-edge structure is intact."""
    assert mesh.validate() == []


@pytest.fixture
def grid():
    V, F = grid_arrays()
    return hedge.Mesh.from_arrays(V, F)
