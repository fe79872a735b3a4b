"""Assemble a backend namespace from its modules, one per core group (same file names)."""

from __future__ import annotations

import importlib
from typing import Any

from ivy import core
from ivy.dtypes import DTYPE_NAMES


def assemble(package: str, namespace: dict[str, Any], native_dtypes: dict[str, Any]) -> None:
    """Fill ``namespace`` (a backend package's globals) with the public names of its modules.

    Each backend package has one module per core group, with the same name; the group's
    dispatched functions must all be defined there. Dtype names map to native dtype objects.
    """
    exported: set[str] = set()
    for group_name, group in zip(core.GROUP_NAMES, core.GROUPS):
        module = importlib.import_module(f"{package}.{group_name}")
        names = getattr(module, "__all__", ())
        namespace.update({name: getattr(module, name) for name in names})
        exported.update(names)
    missing = set(DTYPE_NAMES) - set(native_dtypes)
    if missing:
        raise ImportError(f"{package} defines no native dtype for {sorted(missing)}")
    namespace.update(native_dtypes)
    exported.update(DTYPE_NAMES)
    namespace["__all__"] = sorted(exported)
