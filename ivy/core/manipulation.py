"""Shape manipulation."""

from __future__ import annotations

from collections.abc import Sequence

from ivy import framework_handler as _fh
from ivy.core._by_hand import by_hand
from ivy.core._dispatch import alias, dispatch
from ivy.typing import Array, Framework, Shape

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
def reshape(x: Array, /, shape: Shape, *, copy: bool | None = None, f: Framework = None) -> Array:
    """``x`` with a new ``shape`` (one entry may be -1)."""


@dispatch
def permute_dims(x: Array, /, axes: tuple[int, ...], *, f: Framework = None) -> Array:
    """``x`` with its axes reordered: output axis i is input axis ``axes[i]``."""


@dispatch
def transpose(x: Array, /, axes: tuple[int, ...] | None = None, *, f: Framework = None) -> Array:
    """Paper spelling of :func:`permute_dims`; ``axes=None`` reverses the axes."""


@dispatch
def concat(arrays: Sequence[Array], /, *, axis: int | None = 0, f: Framework = None) -> Array:
    """Join a sequence of arrays along an existing ``axis`` (None: flatten first)."""


concatenate = alias("concatenate", concat)


@dispatch
def stack(arrays: Sequence[Array], /, *, axis: int = 0, f: Framework = None) -> Array:
    """Join a sequence of same-shaped arrays along a new ``axis``."""


@dispatch
def unstack(x: Array, /, *, axis: int = 0, f: Framework = None) -> tuple[Array, ...]:
    """Tuple of the slices of ``x`` along ``axis`` (the inverse of :func:`stack`)."""


@dispatch
def split(
    x: Array,
    /,
    num_or_size_splits: int | Sequence[int] | None = None,
    *,
    axis: int = 0,
    f: Framework = None,
) -> list[Array]:
    """List of pieces of ``x`` along ``axis``.

    ``num_or_size_splits`` is a number of equal pieces (must divide the axis), a sequence of piece
    sizes, or None for pieces of size 1.
    """


@dispatch
def squeeze(
    x: Array, /, axis: int | tuple[int, ...] | None = None, *, f: Framework = None
) -> Array:
    """Remove size-1 ``axis`` (an int or tuple; None removes every size-1 axis)."""


@dispatch
def expand_dims(x: Array, /, axis: int | tuple[int, ...] = 0, *, f: Framework = None) -> Array:
    """Insert size-1 axes at the positions ``axis`` (an int or a tuple of ints) of the result.

    ``axis`` may be passed by position or by keyword (the Array API 2023.12 makes it
    keyword-only, 2024.12 positional as well). Example: the shape of
    ``ivy.expand_dims(np.ones((2, 3)), axis=(0, 3))`` is ``(1, 2, 3, 1)``.
    """


@dispatch
def flip(x: Array, /, *, axis: int | tuple[int, ...] | None = None, f: Framework = None) -> Array:
    """Reverse the order of elements along ``axis`` (None: every axis)."""


@dispatch
def tile(x: Array, repetitions: tuple[int, ...], /, *, f: Framework = None) -> Array:
    """Repeat the whole of ``x`` ``repetitions[i]`` times along axis i."""


@dispatch
def repeat(
    x: Array, repeats: int | Array, /, *, axis: int | None = None, f: Framework = None
) -> Array:
    """Repeat each element ``repeats`` times along ``axis`` (None: flatten first)."""


@dispatch
def roll(
    x: Array,
    /,
    shift: int | tuple[int, ...],
    *,
    axis: int | tuple[int, ...] | None = None,
    f: Framework = None,
) -> Array:
    """Shift elements cyclically by ``shift`` along ``axis`` (None: flattened)."""


@dispatch
def swapaxes(x: Array, axis0: int, axis1: int, /, *, f: Framework = None) -> Array:
    """Exchange two axes of ``x``."""


@dispatch
def broadcast_to(x: Array, /, shape: Shape, *, f: Framework = None) -> Array:
    """Broadcast ``x`` to ``shape``."""


@by_hand
def broadcast_arrays(*arrays: Array, f: Framework = None) -> list[Array]:
    """List of ``arrays`` broadcast against each other to one shape.

    Example: ``[a.shape for a in ivy.broadcast_arrays(np.ones((2, 1)), np.ones(3))]`` ->
    ``[(2, 3), (2, 3)]``.
    """
    ns = _fh.get_framework(*arrays, f=f)
    if f is not None:
        arrays = _fh.to_namespace(ns, arrays)
    try:
        return ns.broadcast_arrays(*arrays)
    except Exception as err:  # noqa: BLE001 - raised again, typed (ivy/core/_diagnose.py)
        return _fh._recover(ns, "broadcast_arrays", err, tuple(arrays), {})


@dispatch
def moveaxis(
    x: Array,
    source: int | tuple[int, ...],
    destination: int | tuple[int, ...],
    /,
    *,
    f: Framework = None,
) -> Array:
    """``x`` with axes ``source`` (an int or tuple) moved to positions ``destination``, the other
    axes keeping their order."""
