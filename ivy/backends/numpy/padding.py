"""numpy backend: padding."""

from __future__ import annotations

import numpy as np

from ivy.backends._pad_args import pad_pairs

__all__ = ["constant_pad"]


def constant_pad(x, /, pad_width, *, value=0):
    x = np.asarray(x)
    pairs = pad_pairs(pad_width, x.ndim)
    return np.pad(x, pairs, constant_values=value) if pairs else x  # 0-d: nothing to pad
