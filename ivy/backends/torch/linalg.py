"""torch backend: linear algebra (torch.linalg, whose defaults are the Array API's: ``pinv``'s
rtol defaults to ``max(M, N) * eps``)."""

from __future__ import annotations

import torch

from ivy.backends.torch._helpers import reduction_args

__all__ = ["matmul", "cross", "svd", "inv", "pinv", "vector_norm"]

matmul = torch.matmul
svd = torch.linalg.svd
inv = torch.linalg.inv
pinv = torch.linalg.pinv


def cross(x1, x2, /, *, axis=-1):
    if x1.ndim != x2.ndim:  # torch.linalg.cross broadcasts only between equal ranks
        x1, x2 = torch.broadcast_tensors(x1, x2)
    return torch.linalg.cross(x1, x2, dim=axis)


def vector_norm(x, /, *, axis=None, keepdims=False, ord=2):
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    return torch.linalg.vector_norm(x, ord=ord, dim=dim, keepdim=keepdim)
