"""Argument checks and window geometry of convolutions and pools, pure Python (no framework).

The core's compositions (``ivy/core/convolutions.py``, ``ivy/core/pooling.py``) parse ``strides``,
``dilations`` and ``padding`` and resolve the padding here, once, so that every backend accepts
the same arguments and raises the same errors; the backends' primitives (``conv_general``,
``pool_general``) use the geometry helpers (``same_pads``, ``window_counts``) where their
library needs them. Layout is channel-last: ``x`` is ``[N, W, C]``, ``[N, H, W, C]`` or
``[N, D, H, W, C]`` (more leading batch axes allowed).
"""

from __future__ import annotations

import operator
from collections.abc import Sequence

LAYOUTS = {1: "[N, W, C]", 2: "[N, H, W, C]", 3: "[N, D, H, W, C]"}
FILTER_LAYOUTS = {1: "[fw, in, out]", 2: "[fh, fw, in, out]", 3: "[fd, fh, fw, in, out]"}
TRANSPOSE_FILTER_LAYOUTS = {
    1: "[fw, out, in]",
    2: "[fh, fw, out, in]",
    3: "[fd, fh, fw, out, in]",
}

Pads = tuple[tuple[int, int], ...]


def as_tuple(value, nd: int, name: str, fn: str) -> tuple[int, ...]:
    """``value`` (an int or ``nd`` ints, each >= 1) as a tuple of ``nd`` ints."""
    try:
        if isinstance(value, Sequence):
            out = tuple(operator.index(v) for v in value)
        else:
            out = (operator.index(value),) * nd
    except TypeError:
        out = ()
    if len(out) != nd or any(v < 1 for v in out) or isinstance(value, bool):
        raise ValueError(
            f"{fn}: {name} must be a positive int or {nd} positive ints, got {value!r}."
        )
    return out


def parse_padding(padding, nd: int, fn: str) -> str | Pads:
    """``'SAME'``, ``'VALID'`` (any case) or ``nd`` explicit ``(low, high)`` pairs.

    An int pads every side by that amount; a sequence of ``nd`` entries gives, per spatial axis,
    an int (both sides) or a ``(low, high)`` pair.
    """
    if isinstance(padding, str):
        upper = padding.upper()
        if upper in ("SAME", "VALID"):
            return upper
    else:
        try:
            if isinstance(padding, Sequence):
                if len(padding) != nd:
                    raise TypeError
                pads = []
                for p in padding:
                    if isinstance(p, Sequence):
                        lo, hi = (operator.index(v) for v in p)
                    else:
                        lo = hi = operator.index(p)
                    pads.append((lo, hi))
                pads = tuple(pads)
            else:
                p = operator.index(padding)
                pads = ((p, p),) * nd
            if all(lo >= 0 and hi >= 0 for lo, hi in pads) and not isinstance(padding, bool):
                return pads
        except (TypeError, ValueError):
            pass
    raise ValueError(
        f"{fn}: unknown padding {padding!r}; use 'SAME', 'VALID', an int, or {nd} "
        f"non-negative (low, high) pairs, one per spatial axis."
    )


def same_pads(sizes, windows, strides) -> Pads:
    """tf's 'SAME' padding: output size ``ceil(size / stride)``, the extra pad at the end."""
    pads = []
    for size, window, stride in zip(sizes, windows, strides):
        out = -(-size // stride)
        total = max((out - 1) * stride + window - size, 0)
        pads.append((total // 2, total - total // 2))
    return tuple(pads)


def effective_windows(kernel, dilations) -> tuple[int, ...]:
    """Extent of a dilated window: ``d * (k - 1) + 1`` per axis."""
    return tuple(d * (k - 1) + 1 for k, d in zip(kernel, dilations))


def explicit_pads(padding: str | Pads, sizes, windows, strides) -> Pads:
    """``(low, high)`` pairs for a padding parsed by :func:`parse_padding`."""
    if padding == "VALID":
        return ((0, 0),) * len(sizes)
    if padding == "SAME":
        return same_pads(sizes, windows, strides)
    return padding


def resolve_pads(parsed: str | Pads, sizes, windows, strides, fn: str) -> str | Pads:
    """The ``(low, high)`` pairs of a padding parsed by :func:`parse_padding`, with the output
    checked non-empty; where a spatial size is unknown (None, in a tensorflow graph), the parsed
    padding as it is ('SAME' and 'VALID' stay strings)."""
    if None in sizes:
        return parsed
    pads = explicit_pads(parsed, sizes, windows, strides)
    output_sizes(sizes, windows, strides, pads, fn)
    return pads


def output_sizes(sizes, windows, strides, pads, fn: str) -> tuple[int, ...]:
    """Spatial output sizes of a window sliding over the padded input; raises when empty."""
    out = tuple(
        (size + lo + hi - window) // stride + 1
        for size, window, stride, (lo, hi) in zip(sizes, windows, strides, pads)
    )
    if any(size + lo + hi < window for size, window, (lo, hi) in zip(sizes, windows, pads)):
        raise ValueError(
            f"{fn}: the window {tuple(windows)} is larger than the padded input "
            f"{tuple(s + lo + hi for s, (lo, hi) in zip(sizes, pads))}; pad more or use a "
            f"smaller kernel."
        )
    return out


def check_conv(x_shape, f_shape, nd: int, fn: str, *, transpose: bool = False) -> None:
    """Ranks and channel counts of a convolution's input and filters."""
    if len(x_shape) < nd + 2:
        raise ValueError(
            f"{fn} expects x of rank >= {nd + 2}, channel-last {LAYOUTS[nd]}; got shape "
            f"{tuple(x_shape)}."
        )
    layout = (TRANSPOSE_FILTER_LAYOUTS if transpose else FILTER_LAYOUTS)[nd]
    if len(f_shape) != nd + 2:
        raise ValueError(
            f"{fn} expects filters of rank {nd + 2}, {layout}; got shape {tuple(f_shape)}."
        )
    in_axis = -1 if transpose else -2
    channels, expected = x_shape[-1], f_shape[in_axis]
    if channels is not None and expected is not None and channels != expected:
        raise ValueError(
            f"{fn}: x has {channels} channels (last axis) but filters {layout} of shape "
            f"{tuple(f_shape)} expect {expected}."
        )


def check_depthwise(x_shape, f_shape, fn: str) -> None:
    if len(x_shape) < 4:
        raise ValueError(
            f"{fn} expects x of rank >= 4, channel-last {LAYOUTS[2]}; got shape {tuple(x_shape)}."
        )
    if len(f_shape) != 3:
        raise ValueError(
            f"{fn} expects filters of rank 3, [fh, fw, C]; got shape {tuple(f_shape)}."
        )
    if x_shape[-1] is not None and f_shape[-1] is not None and x_shape[-1] != f_shape[-1]:
        raise ValueError(
            f"{fn}: x has {x_shape[-1]} channels (last axis) but filters [fh, fw, C] of shape "
            f"{tuple(f_shape)} have {f_shape[-1]}."
        )


def check_pool_input(x_shape, nd: int, fn: str) -> None:
    if len(x_shape) < nd + 2:
        raise ValueError(
            f"{fn} expects x of rank >= {nd + 2}, channel-last {LAYOUTS[nd]}; got shape "
            f"{tuple(x_shape)}."
        )


def pool_pads(padding, sizes, kernel, strides, fn: str) -> str | Pads:
    """Explicit pads of a pool (see :func:`resolve_pads`); explicit pads must be smaller than
    the window."""
    parsed = parse_padding(padding, len(kernel), fn)
    if not isinstance(parsed, str) and any(
        lo >= k or hi >= k for (lo, hi), k in zip(parsed, kernel)
    ):
        raise ValueError(
            f"{fn}: explicit padding {parsed} must be smaller than the window {tuple(kernel)} on "
            f"each side (a window of padding only has no value)."
        )
    return resolve_pads(parsed, sizes, kernel, strides, fn)


def transpose_geometry(sizes, windows, strides, padding, output_shape, fn: str, channels=None):
    """Output sizes and low crops of a transposed convolution.

    The transposed convolution is the gradient of the forward convolution whose input has the
    output's sizes. Its full (unpadded) result has ``(size - 1) * stride + window`` entries per
    axis; the output is that, cropped by the forward convolution's low pads and cut (or extended
    with zeros) to the output size.

    Args:
        channels: the output's channel count, checked against a full ``output_shape``.

    Returns:
        ``(out_sizes, lows, full_sizes)``.
    """
    nd = len(sizes)
    parsed = parse_padding(padding, nd, fn)
    full = tuple((size - 1) * s + w for size, s, w in zip(sizes, strides, windows))
    if output_shape is not None:
        try:
            given = tuple(operator.index(v) for v in output_shape)
        except TypeError:
            given = ()
        if len(given) == nd + 2:
            if channels is not None and given[-1] != channels:
                raise ValueError(
                    f"{fn}: output_shape {tuple(given)} has {given[-1]} channels but the "
                    f"filters give {channels} (their second last axis)."
                )
            given = given[1:-1]
        if len(given) != nd:
            raise ValueError(
                f"{fn}: output_shape must give the {nd} spatial sizes (or the full shape "
                f"{LAYOUTS[nd]}), got {output_shape!r}."
            )
    if parsed == "SAME":
        out = given if output_shape is not None else tuple(n * s for n, s in zip(sizes, strides))
    elif parsed == "VALID":
        out = given if output_shape is not None else full
    else:
        out = (
            given
            if output_shape is not None
            else tuple(f - lo - hi for f, (lo, hi) in zip(full, parsed))
        )
    if any(n < 1 for n in out):
        raise ValueError(f"{fn}: the padding {padding!r} leaves an empty output {out}.")
    pads = explicit_pads(parsed, out, windows, strides)
    back = tuple(
        (n + lo + hi - w) // s + 1 if n + lo + hi >= w else 0
        for n, (lo, hi), w, s in zip(out, pads, windows, strides)
    )
    if back != tuple(sizes):
        raise ValueError(
            f"{fn}: output_shape {tuple(out)} does not fit: a forward convolution of that size "
            f"with these strides and padding gives {back}, not the input's {tuple(sizes)}."
        )
    return out, tuple(lo for lo, _ in pads), full


def transpose_crops(lows, out_sizes, full_sizes) -> tuple[Pads, tuple[int, ...]]:
    """What a transposed convolution crops from its full result, and the zeros it appends.

    The output is ``full[lo : lo + n]`` per axis, extended with zeros past the full result's
    end (an ``output_shape`` larger than the full result, or a low crop beyond it).

    Returns:
        ``(crops, extend)``: ``(low, high)`` crops with ``low + high <= full`` per axis, and the
        zeros to append after the cropped result.
    """
    crops, extend = [], []
    for lo, n, full in zip(lows, out_sizes, full_sizes):
        low = min(lo, full)
        kept = max(min(n, full - lo), 0)
        crops.append((low, full - low - kept))
        extend.append(n - kept)
    return tuple(crops), tuple(extend)


def window_counts(sizes, kernel, strides, pads):
    """Number of real (unpadded) entries in each window of a pool, a numpy array of the
    output's spatial shape: the divisor of an average pool that does not count padding."""
    import numpy as np

    counts = np.ones((), np.int64)
    for n, k, s, (lo, hi) in zip(sizes, kernel, strides, pads):
        starts = np.arange((n + lo + hi - k) // s + 1) * s - lo
        per_axis = np.minimum(starts + k, n) - np.maximum(starts, 0)
        counts = np.multiply.outer(counts, per_axis)
    return counts


def averages(reduction: str) -> bool:
    """True for a mean pool (``reduction='mean'``), False for a max pool (``'max'``)."""
    if reduction not in ("max", "mean"):
        raise ValueError(f"pool_general: reduction must be 'max' or 'mean', got {reduction!r}.")
    return reduction == "mean"
