"""hedge.render and Mesh._repr_png_: the shaded picture of `hedge render`, as an array or a PNG."""

import os
import struct
import subprocess
import threading
import zlib

import numpy as np
import pytest
from conftest import grid_arrays

import hedge

WHITE = np.array([255, 255, 255], dtype=np.uint8)


def decode_png(data):
    """(width, height, pixels) of an 8-bit RGB PNG, decoded here with zlib and numpy."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    at, idat, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at : at + 8])
        body = data[at + 8 : at + 8 + length]
        assert zlib.crc32(kind + body) == struct.unpack(">I", data[at + 8 + length : at + 12 + length])[0]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    width, height, depth, colour, _, _, interlace = header
    assert (depth, colour, interlace) == (8, 2, 0)  # 8-bit RGB, not interlaced
    raw = np.frombuffer(zlib.decompress(idat), dtype=np.uint8).reshape(height, 1 + 3 * width)
    out = np.zeros((height, 3 * width), dtype=np.int32)
    for y in range(height):
        kind, row = raw[y, 0], raw[y, 1:].astype(np.int32)
        up = out[y - 1] if y > 0 else np.zeros(3 * width, dtype=np.int32)
        if kind in (0, 2):
            out[y] = (row + (up if kind == 2 else 0)) % 256
            continue
        for x in range(3 * width):  # left, average and Paeth depend on the pixel just decoded
            left = out[y, x - 3] if x >= 3 else 0
            corner = up[x - 3] if x >= 3 else 0
            if kind == 1:
                guess = left
            elif kind == 3:
                guess = (left + up[x]) // 2
            else:
                p = left + up[x] - corner
                pa, pb, pc = abs(p - left), abs(p - up[x]), abs(p - corner)
                guess = left if pa <= pb and pa <= pc else (up[x] if pb <= pc else corner)
            out[y, x] = (row[x] + guess) % 256
    return width, height, out.astype(np.uint8).reshape(height, width, 3)


def projected_box(points, eye, target, up, fov, width, height):
    """The pixel box of points seen by a perspective camera (picture y down), computed here."""
    eye, target, up = (np.asarray(v, dtype=np.float64) for v in (eye, target, up))
    forward = (target - eye) / np.linalg.norm(target - eye)
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    true_up = np.cross(right, forward)
    d = np.asarray(points, dtype=np.float64) - eye
    scale = 0.5 * height / np.tan(np.radians(fov) / 2) / (d @ forward)
    x = 0.5 * width + (d @ right) * scale
    y = 0.5 * height - (d @ true_up) * scale
    return x.min(), x.max(), y.min(), y.max()


def covered(image):
    return np.any(image != WHITE, axis=2)


def grid_mesh():
    V, F = grid_arrays()
    return hedge.Mesh.from_arrays(V, F)


def test_the_picture_is_an_array_of_the_asked_size():
    image = hedge.render(grid_mesh(), 64, 48)
    assert image.shape == (48, 64, 3) and image.dtype == np.uint8
    assert hedge.render(grid_mesh(), width=30, height=70).shape == (70, 30, 3)


@pytest.mark.parametrize("centre", [(2, 2), (3, 1.5)])
def test_the_mesh_covers_where_it_projects_and_nothing_else(centre):
    mesh = grid_mesh()
    eye, target, up = (centre[0], centre[1], 10), (centre[0], centre[1], 0), (0, 1, 0)
    image = hedge.render(mesh, 80, 60, eye=eye, target=target, up=up, fov=40)
    x0, x1, y0, y1 = projected_box(mesh.positions, eye, target, up, 40, 80, 60)
    xs, ys = np.meshgrid(np.arange(80) + 0.5, np.arange(60) + 0.5)
    inside = (xs > x0 + 2) & (xs < x1 - 2) & (ys > y0 + 2) & (ys < y1 - 2)
    outside = (xs < x0 - 2) | (xs > x1 + 2) | (ys < y0 - 2) | (ys > y1 + 2)
    assert inside.sum() > 100 and outside.sum() > 100
    assert covered(image)[inside].all()
    assert not covered(image)[outside].any()


def test_a_moved_camera_or_other_options_change_the_picture():
    mesh = grid_mesh()
    base = hedge.render(mesh, 64, 48)
    assert np.array_equal(base, hedge.render(mesh, 64, 48))  # deterministic
    assert not np.array_equal(base, hedge.render(mesh, 64, 48, view="top"))
    assert not np.array_equal(base, hedge.render(mesh, 64, 48, eye=(1, 2, 8), target=(2, 2, 0)))
    assert not np.array_equal(base, hedge.render(mesh, 64, 48, wireframe=True))
    assert not np.array_equal(base, hedge.render(mesh, 64, 48, color_by="face"))


def test_positions_written_through_the_view_show_in_the_picture():
    mesh = grid_mesh()
    before = hedge.render(mesh, 64, 48, eye=(2, 2, 10), target=(2, 2, 0))
    P = mesh.positions
    P[:, 0] += 1.0
    mesh.positions_changed()
    del P
    after = hedge.render(mesh, 64, 48, eye=(2, 2, 10), target=(2, 2, 0))
    cols_before = np.nonzero(covered(before).any(axis=0))[0]
    cols_after = np.nonzero(covered(after).any(axis=0))[0]
    assert cols_after.min() > cols_before.min() and cols_after.max() > cols_before.max()


def test_the_png_written_decodes_to_the_array(tmp_path):
    mesh = grid_mesh()
    path = tmp_path / "grid.png"
    assert hedge.render(mesh, 50, 40, color_by="face", path=path) is None  # a pathlib.Path
    data = path.read_bytes()
    assert struct.unpack(">II", data[16:24]) == (50, 40)  # IHDR width, height
    width, height, pixels = decode_png(data)
    assert (width, height) == (50, 40)
    assert np.array_equal(pixels, hedge.render(mesh, 50, 40, color_by="face"))


def test_repr_png_shows_the_mesh_in_a_notebook():
    mesh = grid_mesh()
    data = mesh._repr_png_()
    assert isinstance(data, bytes)
    width, height, pixels = decode_png(data)
    assert (width, height) == (400, 300)
    assert np.array_equal(pixels, hedge.render(mesh, 400, 300))
    assert covered(pixels).any()
    # What IPython does with it: a display bundle keyed by MIME type.
    bundle = {"image/png": mesh._repr_png_(), "text/plain": repr(mesh)}
    assert bundle["image/png"] == data
    empty = hedge.Mesh.from_arrays(np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64))
    assert empty._repr_png_() is None


CLI_CASES = [
    ([], {}),
    (["--view", "top", "--shading", "flat", "--wireframe"], dict(view="top", shading="flat", wireframe=True)),
    (["--color-by", "valence", "--feature-angle", "0", "--supersample", "1"], dict(color_by="valence", feature_angle=0, supersample=1)),
    (
        ["--eye", "0.3,-2.5,7.1", "--target", "2,2,0.1", "--up", "0,0,1", "--fov", "55", "--color-by", "face"],
        dict(eye=(0.3, -2.5, 7.1), target=(2, 2, 0.1), up=(0, 0, 1), fov=55, color_by="face"),
    ),
]


@pytest.mark.skipif(not os.environ.get("HEDGE_CLI"), reason="the CLI is not built (HEDGE_CLI unset)")
@pytest.mark.parametrize("cli_args,options", CLI_CASES)
def test_the_same_picture_as_the_cli(tmp_path, cli_args, options):
    mesh = grid_mesh()
    P = mesh.positions
    P[:, 2] = np.sin(P[:, 0]) * np.cos(P[:, 1])  # a bumpy surface, so that shading shows
    mesh.positions_changed()
    del P
    mesh.write(str(tmp_path / "bumpy.ply"))
    out = tmp_path / "cli.png"
    command = [os.environ["HEDGE_CLI"], "render", str(tmp_path / "bumpy.ply"), "-o", str(out), "--size", "72x54"]
    subprocess.run(command + cli_args, capture_output=True, check=True)
    _, _, cli_pixels = decode_png(out.read_bytes())
    assert np.array_equal(cli_pixels, hedge.render(mesh, 72, 54, **options))


@pytest.mark.parametrize(
    "options,message",
    [
        (dict(view="side"), "render: view 'side' is not one of"),
        (dict(shading="gouraud"), "render: shading 'gouraud' is not one of flat, smooth"),
        (dict(color_by="colour"), "render: color_by 'colour' is not one of"),
        (dict(fov=-1), "render: fov must be in [0, 179] degrees"),  # with the default view too
        (dict(fov=float("nan")), "render: fov must be in [0, 179] degrees"),
        (dict(eye=(0, 0, 5)), "eye and target go together"),
        (dict(eye=(0, 0, 5), target=(0, 0, float("nan"))), "render: target (0.000000, 0.000000, nan) is not finite"),
        (dict(eye=(0, 0), target=(0, 0, 0)), "render: eye must be 3 numbers"),
        (dict(eye=(0, 0, 5), target=(0, 0, 5)), "the eye and the target must differ"),
        (dict(up=(0, 0, 1)), "up is for the camera of eye and target"),
        (dict(supersample=5), "supersample must be from 1 to 4"),
        (dict(feature_angle=-1), "feature_angle must be in [0, 180]"),
        (dict(threads=-1), "render: threads must be 0 (every core) to 1024, got -1"),
        (dict(threads=10**6), "render: threads must be 0 (every core) to 1024, got 1000000"),
        (dict(width=0), "render: the picture"),
        (dict(path="grid.jpg"), "the path must end in .png"),
    ],
)
def test_bad_options_are_invalid_arguments(options, message):
    with pytest.raises(hedge.InvalidArgumentError, match=None) as e:
        hedge.render(grid_mesh(), **{"width": 40, "height": 30, **options})
    assert isinstance(e.value, ValueError)
    assert message in str(e.value)


def test_a_mesh_that_cannot_be_drawn_is_an_error():
    mesh = grid_mesh()
    P = mesh.positions
    P[3, 1] = np.inf
    del P
    with pytest.raises(hedge.InvalidArgumentError, match="not finite"):
        hedge.render(mesh, 40, 30)


def test_a_path_that_cannot_be_written_is_an_io_error_and_leaves_no_file(tmp_path):
    path = tmp_path / "missing" / "grid.png"
    with pytest.raises(hedge.IoError) as e:
        hedge.render(grid_mesh(), 40, 30, path=str(path))
    assert isinstance(e.value, OSError) and "grid.png" in str(e.value)
    assert not path.parent.exists()
    (tmp_path / "dir.png").mkdir()
    with pytest.raises(hedge.IoError):
        hedge.render(grid_mesh(), 40, 30, path=str(tmp_path / "dir.png"))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["dir.png"]  # no temporary file left


def test_rendering_releases_the_gil():
    mesh = grid_mesh()
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(1)
            done.wait(0.0005)

    thread = threading.Thread(target=tick)
    thread.start()
    try:
        hedge.render(mesh, 1200, 900, supersample=4, threads=1)
    finally:
        done.set()
        thread.join()
    assert len(ticks) > 10  # about 2 while the GIL is held
