"""Shape manipulation."""

from __future__ import annotations

from ivy import framework_handler as _fh
from ivy.core._by_hand import by_hand
from ivy.core._dispatch import alias, dispatch

__all__ = [
    "reshape",
    "permute_dims",
    "transpose",
    "concat",
    "concatenate",
    "stack",
    "unstack",
    "split",
    "squeeze",
    "expand_dims",
    "flip",
    "tile",
    "repeat",
    "roll",
    "swapaxes",
    "broadcast_to",
    "broadcast_arrays",
    "moveaxis",
]


@dispatch
def reshape(x, /, shape, *, copy=None, f=None):
    """``x`` with a new ``shape`` (one entry may be -1)."""


@dispatch
def permute_dims(x, /, axes, *, f=None):
    """``x`` with its axes reordered: output axis i is input axis ``axes[i]``."""


@dispatch
def transpose(x, /, axes=None, *, f=None):
    """Paper spelling of :func:`permute_dims`; ``axes=None`` reverses the axes."""


@dispatch
def concat(arrays, /, *, axis=0, f=None):
    """Join a sequence of arrays along an existing ``axis`` (None: flatten first)."""


concatenate = alias("concatenate", concat)


@dispatch
def stack(arrays, /, *, axis=0, f=None):
    """Join a sequence of same-shaped arrays along a new ``axis``."""


@dispatch
def unstack(x, /, *, axis=0, f=None):
    """Tuple of the slices of ``x`` along ``axis`` (the inverse of :func:`stack`)."""


@dispatch
def split(x, /, num_or_size_splits=None, *, axis=0, f=None):
    """List of pieces of ``x`` along ``axis``.

    ``num_or_size_splits`` is a number of equal pieces (must divide the axis), a sequence of piece
    sizes, or None for pieces of size 1.
    """


@dispatch
def squeeze(x, /, axis=None, *, f=None):
    """Remove size-1 ``axis`` (an int or tuple; None removes every size-1 axis)."""


@dispatch
def expand_dims(x, /, *, axis=0, f=None):
    """Insert a size-1 axis at position ``axis``."""


@dispatch
def flip(x, /, *, axis=None, f=None):
    """Reverse the order of elements along ``axis`` (None: every axis)."""


@dispatch
def tile(x, repetitions, /, *, f=None):
    """Repeat the whole of ``x`` ``repetitions[i]`` times along axis i."""


@dispatch
def repeat(x, repeats, /, *, axis=None, f=None):
    """Repeat each element ``repeats`` times along ``axis`` (None: flatten first)."""


@dispatch
def roll(x, /, shift, *, axis=None, f=None):
    """Shift elements cyclically by ``shift`` along ``axis`` (None: flattened)."""


@dispatch
def swapaxes(x, axis0, axis1, /, *, f=None):
    """Exchange two axes of ``x``."""


@dispatch
def broadcast_to(x, /, shape, *, f=None):
    """Broadcast ``x`` to ``shape``."""


@by_hand
def broadcast_arrays(*arrays, f=None):
    """List of ``arrays`` broadcast against each other to one shape.

    Example: ``[a.shape for a in ivy.broadcast_arrays(np.ones((2, 1)), np.ones(3))]`` ->
    ``[(2, 3), (2, 3)]``.
    """
    return _fh.get_framework(*arrays, f=f).broadcast_arrays(*arrays)


@dispatch
def moveaxis(x, source, destination, /, *, f=None):
    """``x`` with axes ``source`` (an int or tuple) moved to positions ``destination``, the other
    axes keeping their order."""
