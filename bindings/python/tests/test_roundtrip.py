"""Build from arrays, edit, write, read back (with hedge.read, and with `hedge info --json` when the
CLI is built: CTest passes its path in HEDGE_CLI)."""

import json
import os
import subprocess

import numpy as np
import pytest
from conftest import assert_valid, grid_arrays

import hedge


def edited_grid():
    V, F = grid_arrays(5)
    mesh = hedge.Mesh.from_arrays(V, F)
    P = mesh.positions
    P[:, 2] = 0.1 * P[:, 0] * P[:, 1]
    mesh.positions_changed()
    del P
    interior = [e for e in range(mesh.n_edges) if mesh.can_flip(e)]
    assert mesh.flip(interior[0]) is not None
    assert mesh.split_edge(interior[1]) is not None
    assert mesh.split_face(3) is not None
    assert_valid(mesh)
    return mesh


@pytest.mark.parametrize("ext", ["obj", "off", "ply"])
def test_build_edit_write_read_back(tmp_path, ext):
    mesh = edited_grid()
    path = str(tmp_path / ("edited." + ext))
    mesh.write(path)
    back = hedge.read(path)
    assert (back.n_vertices, back.n_edges, back.n_faces) == (mesh.n_vertices, mesh.n_edges, mesh.n_faces)
    V, F = mesh.to_arrays()
    V2, F2 = back.to_arrays()
    np.testing.assert_allclose(V2, V, rtol=1e-6, atol=1e-6)
    np.testing.assert_array_equal(F2, F)
    assert back.build_report["repairs"] == 0
    assert_valid(back)


@pytest.mark.skipif(not os.environ.get("HEDGE_CLI"), reason="the CLI is not built (HEDGE_CLI unset)")
def test_cli_reads_what_python_wrote(tmp_path):
    mesh = edited_grid()
    path = str(tmp_path / "edited.ply")
    mesh.write(path)
    out = subprocess.run([os.environ["HEDGE_CLI"], "info", "--json", path], capture_output=True, text=True, check=True)
    info = json.loads(out.stdout)
    assert (info["vertices"], info["edges"], info["faces"]) == (mesh.n_vertices, mesh.n_edges, mesh.n_faces)
    assert info["valid"] and info["problems"] == []
    assert info["is_triangle_mesh"] and info["boundary_loops"] == 1
    V, _ = mesh.to_arrays()
    np.testing.assert_allclose(info["bounding_box"]["min"], V.min(axis=0), atol=1e-6)
    np.testing.assert_allclose(info["bounding_box"]["max"], V.max(axis=0), atol=1e-6)
