"""Framework-agnostic definitions of ivy's functions, one module per group.

Every public module here is a group; each backend package has a module of the same name that
implements the group's dispatched functions.
"""

import importlib
import pkgutil

GROUP_NAMES = tuple(
    sorted(m.name for m in pkgutil.iter_modules(__path__) if not m.name.startswith("_"))
)
GROUPS = tuple(importlib.import_module(f"{__name__}.{name}") for name in GROUP_NAMES)

__all__ = sorted({name for group in GROUPS for name in group.__all__})

for _group in GROUPS:
    globals().update({name: getattr(_group, name) for name in _group.__all__})
del _group
