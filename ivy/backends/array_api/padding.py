"""Padding, written once: ``xp.pad`` (numpy, jax; not in the standard, so other libraries take
it from the host bridge)."""

from __future__ import annotations

from ivy.backends._pad_args import pad_pairs
from ivy.backends.array_api._unbound import xp

NEEDS = {"constant_pad": ("pad",)}  # what a function needs of xp beyond the standard


def constant_pad(x, /, pad_width, *, value=0):
    x = xp.asarray(x)
    pairs = pad_pairs(pad_width, x.ndim)
    return xp.pad(x, pairs, constant_values=value) if pairs else x  # 0-d: nothing to pad
