"""hedge's exceptions: one family under HedgeError, each also a matching built-in exception.

Every error of the native module is raised as one of these classes. ``kind`` names the error as the
JS API's ``HedgeError.kind`` does ("invalid-argument", "bad-handle", "io", ...), and ``refusal`` holds
the library's reason when an edit was refused (``None`` otherwise). A refused edit called through
``Mesh.split_edge`` and the other edits does not raise: it returns ``None`` (or ``False``) and its
reason is in ``Mesh.last_refusal``.
"""


class HedgeError(Exception):
    """Base class of every error hedge raises.

    Attributes:
        kind: the error's kind, as the JS API names it ("io", "topology", ...).
        refusal: the library's reason for a refused edit, or None.
    """

    kind = "internal"

    def __init__(self, message="", refusal=None):
        super().__init__(message)
        self.refusal = refusal


class InvalidArgumentError(HedgeError, ValueError):
    """Invalid input: a malformed array, a non-finite position, an unknown name."""

    kind = "invalid-argument"


class BadHandleError(HedgeError, IndexError, ValueError):
    """An element index that is out of range or names a deleted element."""

    kind = "bad-handle"


class RefusedError(HedgeError, ValueError):
    """An edit the library refuses (the reason is in ``refusal``); the mesh is unchanged."""

    kind = "refused"


class TopologyError(HedgeError, ValueError):
    """Input a half-edge mesh cannot hold (build without repair)."""

    kind = "topology"


class IoError(HedgeError, OSError):
    """A file that cannot be read, parsed or written."""

    kind = "io"


class OutOfMemoryError(HedgeError, MemoryError):
    """Memory ran out; the mesh is unchanged."""

    kind = "out-of-memory"


class BufferTooSmallError(HedgeError, ValueError):
    """An output buffer too small for the result."""

    kind = "buffer-too-small"


class BusyError(HedgeError, RuntimeError):
    """The mesh is in a call on another thread: a mesh takes calls from one thread at a time."""

    kind = "busy"


class ViewsExportedError(HedgeError, BufferError):
    """An edit that adds elements while numpy views of the mesh's arrays are alive.

    Adding elements may move the arrays, which would leave the views pointing at freed memory, so
    such an edit is refused (as ``bytearray`` refuses to resize while a ``memoryview`` exists).
    Delete the views (``del``) first; the mesh is unchanged.
    """

    kind = "views-exported"


class InternalError(HedgeError, RuntimeError):
    """A bug in hedge: please report it."""

    kind = "internal"


#: Error class by kind, as the native module raises them.
BY_KIND = {
    cls.kind: cls
    for cls in (
        InvalidArgumentError,
        BadHandleError,
        RefusedError,
        TopologyError,
        IoError,
        OutOfMemoryError,
        BufferTooSmallError,
        BusyError,
        ViewsExportedError,
        InternalError,
    )
}

# The classes are hedge's public names (hedge.IoError, ...): so they show in tracebacks.
for _cls in (HedgeError, *BY_KIND.values()):
    _cls.__module__ = "hedge"
del _cls
