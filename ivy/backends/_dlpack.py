"""DLPack export shared by the backends' ``from_dlpack``.

Some producers cannot be handed to a consumer's ``from_dlpack`` as they are: a torch tensor that
requires gradients, or has its lazy conjugate or negative bit set, refuses to export; a tf tensor
exports only without ``copy``, ``dl_device`` or ``stream``. :func:`exportable` prepares them.
"""

from __future__ import annotations

import sys


class _TFExport:
    """A tf tensor or variable whose ``__dlpack__`` ignores the arguments tf refuses (the consumer
    then copies, if asked to, after importing)."""

    def __init__(self, x):
        self._x = sys.modules["tensorflow"].convert_to_tensor(x)

    def __dlpack__(self, *, stream=None, max_version=None, dl_device=None, copy=None):
        return self._x.__dlpack__()

    def __dlpack_device__(self):
        return self._x.__dlpack_device__()


def exportable(x):
    """``(producer, copy_after)``: ``x`` ready for a consumer's ``from_dlpack``, and whether the
    consumer must import it without ``copy`` and copy afterwards (the producer cannot honour
    ``copy``)."""
    root = type(x).__module__.partition(".")[0]
    if root == "torch":
        if x.requires_grad:
            x = x.detach()
        if x.is_conj():
            x = x.resolve_conj()
        if x.is_neg():
            x = x.resolve_neg()
        return x, False
    if root == "tensorflow":
        return _TFExport(x), True
    return x, False
