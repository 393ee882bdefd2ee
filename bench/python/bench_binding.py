"""What the Python binding costs over the library: same-run ratios, Python and C++ taking turns.

    PYTHONPATH=build/release/bindings/python/package /usr/bin/python3 bench/python/bench_binding.py \
        build/release/bindings/python/build_reference

(the second argument: the build_reference program, built with -DHEDGE_BUILD_PYTHON=ON). Prints:
 - Mesh.from_arrays on a 1,002,528-triangle grid beside C++ build_triangles on the same arrays;
 - Mesh.ray_cast of 100,000 rays on that mesh beside FaceBvh::first_hit on the same rays;
 - Mesh.one_rings() of every vertex of that mesh beside the same gathering in C++;
 - the per-call time of a scalar query (mesh.next(h));
 - a one-ring circulation over every vertex through the array views in numpy, beside the same in a
   Python loop over mesh.next / mesh.twin.
"""

import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import hedge


def plate(n):
    """An n x n grid of squares cut into triangles: 2 n^2 triangles."""
    xs, ys = np.meshgrid(np.arange(n + 1, dtype=np.float32), np.arange(n + 1, dtype=np.float32))
    V = np.column_stack([xs.ravel(), ys.ravel(), np.zeros(xs.size, dtype=np.float32)])
    j, i = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    a = (j * (n + 1) + i).ravel()
    b, c, d = a + 1, a + n + 2, a + n + 1
    F = np.empty((2 * a.size, 3), dtype=np.uint32)
    F[0::2] = np.column_stack([a, b, c])
    F[1::2] = np.column_stack([a, c, d])
    return V, F


def median_seconds(fn, runs):
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main():
    reference = sys.argv[1] if len(sys.argv) > 1 else None
    V, F = plate(708)
    rounds = 7
    rng = np.random.default_rng(1)
    n_rays = 100_000
    origins = np.column_stack([rng.uniform(0, 708, (n_rays, 2)), np.full(n_rays, 10.0)]).astype(np.float32)
    directions = np.column_stack([rng.uniform(-0.3, 0.3, (n_rays, 2)), -np.ones(n_rays)]).astype(np.float32)
    big = hedge.Mesh.from_arrays(V, F)
    big.ray_cast(origins[:1], directions[:1])  # builds the picking tree

    per_round = 3  # timings of each measure a round, on each side; a round reports their median

    def python_round():
        """The median of per_round timings of each measure through the binding, in ms."""
        return (
            1e3 * median_seconds(lambda: hedge.Mesh.from_arrays(V, F), per_round),
            1e3 * median_seconds(big.one_rings, per_round),
            1e3 * median_seconds(lambda: big.ray_cast(origins, directions), per_round),
        )

    names = [
        f"build {len(F):,} triangles (`from_arrays` / `build_triangles`, repair on)",
        f"one-rings of all {big.n_vertices:,} vertices (`one_rings()` / the same gathering in C++)",
        f"{n_rays:,} rays on that mesh (`ray_cast` / `FaceBvh::first_hit`)",
    ]
    py_rounds, cpp_rounds = [], []
    with tempfile.TemporaryDirectory() as tmp:
        vp, fp, rp = (os.path.join(tmp, name) for name in ("v.f32", "f.u32", "r.f32"))
        V.tofile(vp)
        F.tofile(fp)
        np.column_stack([origins, directions]).astype(np.float32).tofile(rp)
        # Python and C++ take turns, one timing each a round, so that a change of load on a shared
        # machine reaches both sides of a ratio; the ratio reported is the median of the rounds'.
        for _ in range(rounds):
            py_rounds.append(python_round())
            if reference:
                out = subprocess.run([reference, vp, fp, str(per_round), rp], capture_output=True, text=True, check=True)
                cpp_rounds.append(tuple(float(x) for x in out.stdout.split()))
    print(f"median of {rounds} rounds, Python and C++ in turn:")
    for k, name in enumerate(names):
        py_ms = statistics.median(r[k] for r in py_rounds)
        if cpp_rounds:
            cpp_ms = statistics.median(r[k] for r in cpp_rounds)
            ratio = statistics.median(p[k] / c[k] for p, c in zip(py_rounds, cpp_rounds))
            print(f"| {name} | {py_ms:.1f} ms | {cpp_ms:.1f} ms | {ratio:.2f}x |")
        else:
            print(f"| {name} | {py_ms:.1f} ms | | |")

    mesh = hedge.Mesh.from_arrays(*plate(100))
    n = 200_000
    nxt = mesh.next

    def calls():
        h = 0
        for _ in range(n):
            h = nxt(h)

    def empty_loop():
        h = 0
        for _ in range(n):
            h = h

    per_call = (median_seconds(calls, 5) - median_seconds(empty_loop, 5)) / n
    print(f"mesh.next(h): {1e9 * per_call:.0f} ns a call (loop overhead subtracted)")

    def rings_numpy():
        # The fast path without a native call: every vertex circulated at once, one numpy step per
        # ring position; a stable sort by vertex keeps each ring in its clockwise order.
        to, nxt = mesh.halfedge_vertex_array, mesh.halfedge_next_array
        start = mesh.vertex_halfedge_array.astype(np.int64)
        vertices = np.flatnonzero(start >= 0)
        h, first = start[vertices], start[vertices]
        owners, neighbours = [], []
        while vertices.size:
            owners.append(vertices)
            neighbours.append(to[h])
            h = nxt[h ^ 1]
            going = h != first
            vertices, h, first = vertices[going], h[going], first[going]
        owners, neighbours = np.concatenate(owners), np.concatenate(neighbours)
        order = np.argsort(owners, kind="stable")
        offsets = np.zeros(mesh.vertex_slots + 1, dtype=np.int64)
        np.cumsum(np.bincount(owners, minlength=mesh.vertex_slots), out=offsets[1:])
        return offsets, neighbours[order]

    def rings_loop():
        offsets, neighbours = [0], []
        for v in range(mesh.vertex_slots):
            h0 = h = mesh.vertex_halfedge(v)
            while True:
                neighbours.append(mesh.to_vertex(h))
                h = mesh.next(h ^ 1)
                if h == h0:
                    break
            offsets.append(len(neighbours))
        return offsets, neighbours

    native = mesh.one_rings()
    for offsets, neighbours in (rings_numpy(), rings_loop()):
        assert list(offsets) == list(native[0]) and list(neighbours) == list(native[1])
    t_native = median_seconds(mesh.one_rings, 7)
    t_np = median_seconds(rings_numpy, 5)
    t_loop = median_seconds(rings_loop, 3)
    print(
        f"one-rings of all {mesh.vertex_slots:,} vertices: mesh.one_rings() {1e3 * t_native:.2f} ms, "
        f"numpy over the views {1e3 * t_np:.2f} ms, Python loop over next/twin {1e3 * t_loop:.1f} ms "
        f"({t_loop / t_np:.0f}x numpy)"
    )

if __name__ == "__main__":
    main()
