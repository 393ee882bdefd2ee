"""The error family: every class is a HedgeError and the matching built-in (src/py_errors.cpp)."""

import pytest

import hedge


@pytest.mark.parametrize(
    "cls, builtin, kind",
    [
        (hedge.InvalidArgumentError, ValueError, "invalid-argument"),
        (hedge.BadHandleError, IndexError, "bad-handle"),
        (hedge.RefusedError, ValueError, "refused"),
        (hedge.TopologyError, ValueError, "topology"),
        (hedge.IoError, OSError, "io"),
        (hedge.OutOfMemoryError, MemoryError, "out-of-memory"),
        (hedge.BusyError, RuntimeError, "busy"),
        (hedge.ViewsExportedError, BufferError, "views-exported"),
        (hedge.InternalError, RuntimeError, "internal"),
    ],
)
def test_classes(cls, builtin, kind):
    assert issubclass(cls, hedge.HedgeError) and issubclass(cls, builtin)
    assert cls.kind == kind
    assert cls.__module__ == "hedge"


def test_raised_errors_carry_kind_message_and_no_refusal(tmp_path):
    with pytest.raises(hedge.HedgeError) as caught:
        hedge.read(str(tmp_path / "none.off"))
    e = caught.value
    assert type(e) is hedge.IoError and e.kind == "io" and e.refusal is None
    assert "none.off" in str(e)
