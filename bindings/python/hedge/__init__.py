"""hedge: half-edge meshes for Python, with numpy arrays in and out and zero-copy views.

    import hedge
    mesh = hedge.read("bunny.obj")            # or hedge.Mesh.from_arrays(V, F)
    P = mesh.positions                        # (vertex_slots, 3) float32, the mesh's own memory
    P[:, 2] += 0.1; mesh.positions_changed()  # tell the change log about the writes
    del P                                     # views block edits that add elements
    v = mesh.split_edge(0)                    # None if refused; mesh.last_refusal says why
    V, F = mesh.to_arrays()
    mesh.write("out.ply")

Half-edge h's twin is ``h ^ 1`` and its edge ``h >> 1``; the connectivity views
(``halfedge_vertex_array``, ``halfedge_next_array``, ``halfedge_face_array``,
``vertex_halfedge_array``, ``face_halfedge_array``)
are read-only int32 arrays over the mesh's memory, -1 meaning "none".
"""

from ._errors import (
    BadHandleError,
    BufferTooSmallError,
    BusyError,
    HedgeError,
    InternalError,
    InvalidArgumentError,
    IoError,
    OutOfMemoryError,
    RefusedError,
    TopologyError,
    ViewsExportedError,
)
from ._hedge import Mesh, Piece, Shard, __version__, hausdorff_distance, read, render

__all__ = [
    "__version__",
    "Mesh",
    "Shard",
    "Piece",
    "read",
    "render",
    "hausdorff_distance",
    "HedgeError",
    "InvalidArgumentError",
    "BadHandleError",
    "RefusedError",
    "TopologyError",
    "IoError",
    "OutOfMemoryError",
    "BufferTooSmallError",
    "BusyError",
    "ViewsExportedError",
    "InternalError",
]
