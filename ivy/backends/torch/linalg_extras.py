"""torch backend: linear algebra beyond the Array API extension (``einsum`` promotes mixed
dtypes, which torch.einsum refuses)."""

from __future__ import annotations

from functools import reduce

import torch

from ivy.backends.torch._unsigned import WIDE_UNSIGNED


def einsum(equation, /, *operands):
    dtypes = {o.dtype for o in operands}
    if len(dtypes) > 1:
        common = reduce(torch.promote_types, dtypes)
        operands = [o.to(common) for o in operands]
    dtype = operands[0].dtype if operands else None
    if dtype is torch.bool:  # no kernel: numpy's product of booleans is any of the ands
        return torch.einsum(equation, *(o.to(torch.float32) for o in operands)) > 0
    if dtype in WIDE_UNSIGNED:  # no kernel: through int64, whose wrap-around is the same
        return torch.einsum(equation, *(o.to(torch.int64) for o in operands)).to(dtype)
    return torch.einsum(equation, *operands)
