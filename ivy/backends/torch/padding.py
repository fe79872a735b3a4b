"""torch backend: padding (``torch.nn.functional.pad``, whose widths run from the last axis)."""

from __future__ import annotations

import torch

from ivy.backends._pad_args import pad_pairs


def constant_pad(x, /, pad_width, *, value=0):
    pairs = pad_pairs(pad_width, x.ndim)
    flat = [w for pair in reversed(pairs) for w in pair]
    return torch.nn.functional.pad(x, flat, mode="constant", value=value)
