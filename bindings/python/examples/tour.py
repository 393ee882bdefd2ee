"""hedge in Python, stage by stage: load, inspect, edit, subdivide, decimate, fracture, render.

    python tour.py [MESH] [--out DIR]      (MESH: data/spot_control_mesh.obj by default)

Each `# %%` starts a cell: the file opens as a notebook in editors that read such cells, and runs
as a plain script. Pictures go to DIR (out/ by default) as python_tour_<stage>.png; in a notebook a
mesh on the last line of a cell shows itself (Mesh._repr_png_).
"""

# %% Load
import argparse
import os
import time

import numpy as np

import hedge

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("mesh", nargs="?", default="data/spot_control_mesh.obj")
parser.add_argument("--out", default="out")
args, _ = parser.parse_known_args()
os.makedirs(args.out, exist_ok=True)


def stage(name, mesh, seconds):
    """Prints a stage's counts and time, checks the mesh and draws it."""
    problems = mesh.validate()
    print(
        f"{name:<12} {mesh.n_vertices:>8,} vertices {mesh.n_faces:>8,} faces  "
        f"{1e3 * seconds:8.2f} ms  {'valid' if not problems else problems[0]}"
    )
    hedge.render(mesh, width=480, height=360, path=os.path.join(args.out, f"python_tour_{name}.png"))


t0 = time.perf_counter()
mesh = hedge.read(args.mesh)
stage("loaded", mesh, time.perf_counter() - t0)
print("  repairs and warnings:", {k: v for k, v in mesh.build_report.items() if v} or "none")

# %% Inspect: numpy over the mesh's own arrays, no copies
to = mesh.halfedge_vertex_array
valence = np.bincount(to[to >= 0], minlength=mesh.vertex_slots)
print("  valence histogram:", dict(zip(*np.unique(valence, return_counts=True))))
lo, hi = mesh.bounding_box()
print(f"  box {np.round(lo, 3)} .. {np.round(hi, 3)}, area {mesh.area():.4f}, volume {mesh.volume():.4f}")
offsets, ring = mesh.one_rings([0])
print(f"  vertex 0's one-ring, clockwise: {ring.tolist()}")

# %% Edit: every edit says why when it is refused
t0 = time.perf_counter()
boundary = [e for e in range(mesh.n_edges) if not mesh.can_flip(e)]
if boundary:
    assert mesh.flip(boundary[0]) is None
    print(f"  flip({boundary[0]}) refused: {mesh.last_refusal}")
v = mesh.split_edge(0)
f = mesh.split_face(mesh.face(mesh.vertex_halfedge(v)))
stage("edited", mesh, time.perf_counter() - t0)

# %% Subdivide: Catmull-Clark, then Loop on the quads cut in two
t0 = time.perf_counter()
mesh.subdivide("catmull-clark", 2)
stage("subdivided", mesh, time.perf_counter() - t0)

# %% Decimate to a quarter of the faces
t0 = time.perf_counter()
mesh.subdivide("triangulate") if not mesh.is_triangle_mesh() else None
result = mesh.decimate(target_faces=mesh.n_faces // 4)
stage("decimated", mesh, time.perf_counter() - t0)
print("  ", result)

# %% Fracture: strike the surface where a ray from the camera hits it
t0 = time.perf_counter()
lo, hi = mesh.bounding_box()
centre = (lo + hi) / 2
faces, _, points = mesh.ray_cast([centre + [0, 0, 2 * (hi[2] - lo[2])]], [[0, 0, -1]])
shards = mesh.fracture(points[0], material="glass", seed=7)
stage("broken", mesh, time.perf_counter() - t0)
print(f"  {len(shards)} shards; the first weighs {shards[0].mass['mass']:.3g} at unit density")

# %% Render: an array for numpy, a PNG for people
picture = hedge.render(mesh, width=320, height=240)
print("  picture", picture.shape, picture.dtype, "; pictures in", args.out)
mesh
