"""Framework-agnostic definitions of ivy's functions, one module per group."""

from ivy.core import (
    creation,
    data_type,
    elementwise,
    general,
    indexing,
    linalg,
    manipulation,
    random,
    searching,
    statistical,
)

GROUPS = (
    creation,
    data_type,
    elementwise,
    general,
    indexing,
    linalg,
    manipulation,
    random,
    searching,
    statistical,
)

__all__ = sorted({name for group in GROUPS for name in group.__all__})

for _group in GROUPS:
    globals().update({name: getattr(_group, name) for name in _group.__all__})
del _group
