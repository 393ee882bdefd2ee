"""One mesh, one thread at a time: long calls release the GIL, and a call on a mesh that another
thread is using raises BusyError instead of racing (binding::MeshUse)."""

import threading

from conftest import assert_valid, grid_arrays

import hedge


def test_a_second_thread_gets_busy_error_during_a_write(tmp_path):
    mesh = hedge.Mesh.from_arrays(*grid_arrays(300))  # 180,000 triangles: a write takes a while
    path = str(tmp_path / "big.obj")
    done = threading.Event()
    failures = []

    def writer():
        try:
            for _ in range(20):
                mesh.write(path)
                if busy:
                    break
        except Exception as e:  # noqa: BLE001 - reported below
            failures.append(e)
        finally:
            done.set()

    busy = []
    thread = threading.Thread(target=writer)
    thread.start()
    while not done.is_set() and not busy:
        try:
            mesh.n_faces
        except hedge.BusyError as e:
            busy.append(e)
    thread.join()
    assert not failures
    assert busy, "the main thread never ran while the writer held the mesh: is the GIL released?"
    assert isinstance(busy[0], RuntimeError) and busy[0].kind == "busy"
    assert "another thread" in str(busy[0])
    assert "render objects" not in str(busy[0])  # the binding core speaks of no language's objects
    assert mesh.n_faces == 180000
    assert_valid(mesh)


def test_different_meshes_build_in_parallel_threads():
    results = [None, None]

    def build(i):
        results[i] = hedge.Mesh.from_arrays(*grid_arrays(60))

    threads = [threading.Thread(target=build, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for mesh in results:
        assert mesh.n_faces == 7200
        assert_valid(mesh)


def test_repr_of_a_busy_mesh_says_so_instead_of_raising(tmp_path):
    mesh = hedge.Mesh.from_arrays(*grid_arrays(300))
    path = str(tmp_path / "big.obj")
    done = threading.Event()
    seen = set()

    def writer():
        try:
            for _ in range(20):
                mesh.write(path)
                if "busy" in " ".join(seen):
                    break
        finally:
            done.set()

    thread = threading.Thread(target=writer)
    thread.start()
    while not done.is_set():
        seen.add(repr(mesh))  # never raises
    thread.join()
    assert "<hedge.Mesh: busy, another thread is in a call on it>" in seen, seen
    assert repr(mesh) == "<hedge.Mesh: 90601 vertices, 180000 faces>"
    assert_valid(mesh)
