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
    if root == "numpy" and hasattr(x, "flags") and not x.flags.writeable:
        # (numpy refuses to export read-only memory, such as a view of a jax array, through
        # the DLPack version the consumers ask for: a copy, which is writable, carries it)
        return x.copy(), False
    return x, False


# DLPack device types whose memory the host reads: kDLCPU, kDLCUDAHost (pinned), kDLROCMHost.
_HOST_DEVICE_TYPES = (1, 3, 11)


def on_host(x) -> bool:
    """Whether the DLPack producer ``x`` (as :func:`exportable` returns it) holds host memory."""
    device = getattr(x, "__dlpack_device__", None)
    return device is None or int(device()[0]) in _HOST_DEVICE_TYPES


def refuse_copy_between_devices(copy, where: str) -> None:
    """``copy=False`` across the host and an accelerator cannot be honoured: say so."""
    if copy is False:
        raise ValueError(
            f"from_dlpack: copy=False, but the array must move {where}, which copies it. Pass "
            f"copy=None (or True), or give a device= where the array already is."
        )
