"""Framework-agnostic functions whose dispatcher is written by hand, because ``@dispatch`` cannot
generate it: a variable number of arrays (``meshgrid(*arrays)``), or a framework-independent answer
when no framework is involved (``finfo('float32')``)."""

from __future__ import annotations

import sys
from collections.abc import Callable
from types import ModuleType
from typing import Any

from ivy import framework_handler as _fh
from ivy.core._dispatch import DISPATCHED
from ivy.errors import NoFrameworkError
from ivy.typing import Framework

__all__ = ["by_hand", "framework_or_none"]


def by_hand(fn: Callable) -> Callable:
    """Register ``fn``, a dispatcher written by hand, as a dispatched function: every backend
    must implement a function of the same name."""
    fn.__ivy_kind__ = "dispatch"
    DISPATCHED[fn.__name__] = fn
    return fn


def framework_or_none(*args: Any, f: Framework = None) -> ModuleType | None:
    """The namespace chosen by ``f``, the global framework or the arrays and native dtypes among
    ``args`` (numpy's scalar types such as ``np.float32`` count as numpy's); None when none of
    these chooses one (dtype names and Python scalars only)."""
    try:
        return _fh.get_framework(*args, f=f)
    except NoFrameworkError:
        pass
    numpy = sys.modules.get("numpy")
    if numpy is not None and any(_is_numpy_type(a, numpy) for a in args):
        return _fh.get_framework(f="numpy")  # np.float32 is a class: no instance to infer from
    return None


def _is_numpy_type(obj, numpy) -> bool:
    if isinstance(obj, tuple):
        return any(_is_numpy_type(o, numpy) for o in obj)
    return isinstance(obj, type) and issubclass(obj, numpy.generic)
