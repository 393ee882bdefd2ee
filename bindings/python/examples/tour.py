"""hedge in Python, stage by stage: load, inspect, edit, subdivide, decimate, fracture, render.

    python tour.py [MESH] [--out DIR]      (MESH: the repository's data/spot_control_mesh.obj)

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
SAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "data", "spot_control_mesh.obj")
parser.add_argument("mesh", nargs="?", default=os.path.normpath(SAMPLE))
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
# Deleted elements keep stale entries until garbage_collection(): the live masks leave them out.
valence = np.bincount(to[mesh.live_halfedges()], minlength=mesh.vertex_slots)[mesh.live_vertices()]
print("  valence histogram:", dict(zip(*np.unique(valence, return_counts=True))))
lo, hi = mesh.bounding_box()
print(f"  box {np.round(lo, 3)} .. {np.round(hi, 3)}, area {mesh.area():.4f}, volume {mesh.volume():.4f}")
offsets, ring = mesh.one_rings([0])
print(f"  vertex 0's one-ring, clockwise: {ring.tolist()}")
del to  # a live view blocks the edits that add elements (ViewsExportedError says so)

# %% Edit: every edit says why when it is refused
t0 = time.perf_counter()
refused = [e for e in range(mesh.n_edges) if not mesh.can_flip(e)]
if refused:
    assert mesh.flip(refused[0]) is None
    print(f"  flip({refused[0]}) refused, nothing changed: {mesh.last_refusal}")
v = mesh.split_edge(0)
f = mesh.split_face(mesh.face(mesh.vertex_halfedge(v)))
stage("edited", mesh, time.perf_counter() - t0)

# %% Subdivide: Catmull-Clark, then every face split at its centre (triangles), then Loop
t0 = time.perf_counter()
mesh.subdivide("catmull-clark")
mesh.subdivide("split-faces")
mesh.subdivide("loop")
stage("subdivided", mesh, time.perf_counter() - t0)

# %% Decimate to a quarter of the faces
t0 = time.perf_counter()
result = mesh.decimate(target_faces=mesh.n_faces // 4)
stage("decimated", mesh, time.perf_counter() - t0)
print(f"  {result['collapses']:,} collapses, largest quadric error {result['max_error']:.3g}")

# %% Fracture: strike where a ray from above the box's centre hits the surface
lo, hi = mesh.bounding_box()
top = (lo + hi) / 2
top[1] = hi[1] + (hi[1] - lo[1])
faces, _, points = mesh.ray_cast([top], [[0, -1, 0]])
if faces[0] >= 0:
    t0 = time.perf_counter()
    shards = mesh.fracture(points[0], "glass", seed=7, break_radius=0.15 * np.linalg.norm(hi - lo))
    stage("broken", mesh, time.perf_counter() - t0)
    heaviest = max(shards, key=lambda s: s.front_area)
    print(f"  {len(shards)} shards; the largest has {heaviest.n_faces} faces, {heaviest.front_area:.4g} area")

# %% Render: an array for numpy, a PNG for people
picture = hedge.render(mesh, width=320, height=240)
print("  picture", picture.shape, picture.dtype, "; pictures in", args.out)
mesh
