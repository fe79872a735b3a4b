"""Argument check shared by every backend's ``constant_pad`` (pure Python, no framework)."""

from __future__ import annotations

import operator


def pad_pairs(pad_width, ndim: int) -> list[tuple[int, int]]:
    """``pad_width`` as one ``(before, after)`` pair of non-negative ints per axis."""
    try:
        pairs = [(operator.index(b), operator.index(a)) for b, a in pad_width]
    except (TypeError, ValueError):
        raise ValueError(
            f"constant_pad: pad_width must be one (before, after) pair of ints per axis; "
            f"got {pad_width!r}."
        ) from None
    if len(pairs) != ndim:
        raise ValueError(
            f"constant_pad: pad_width has {len(pairs)} (before, after) pairs for an array of "
            f"{ndim} dimensions; give one pair per axis."
        )
    if any(b < 0 or a < 0 for b, a in pairs):
        raise ValueError(f"constant_pad: pad widths must be non-negative; got {pairs}.")
    return pairs
