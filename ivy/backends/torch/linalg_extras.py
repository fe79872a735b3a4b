"""torch backend: linear algebra beyond the Array API extension (``einsum`` promotes mixed
dtypes, which torch.einsum refuses)."""

from __future__ import annotations

from functools import reduce

import torch


def einsum(equation, /, *operands):
    dtypes = {o.dtype for o in operands}
    if len(dtypes) > 1:
        common = reduce(torch.promote_types, dtypes)
        operands = [o.to(common) for o in operands]
    return torch.einsum(equation, *operands)
