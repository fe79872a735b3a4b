"""Assemble a backend namespace from its modules, one per core group (same file names).

Array API extension groups (``linalg``, ``fft``) are also exposed as sub-namespaces of the backend
namespace (``ivy.torch.linalg.svd is ivy.torch.svd``); see ``ivy/core/_extensions.py``.
"""

from __future__ import annotations

import importlib
import importlib.util
from typing import Any

from ivy import core
from ivy.core._extensions import ExtensionNamespace, extension_groups
from ivy.dtypes import DTYPE_NAMES

ARRAY_API_VERSION = "2023.12"
ARRAY_API_CONSTANTS = {
    "e": 2.718281828459045,
    "pi": 3.141592653589793,
    "inf": float("inf"),
    "nan": float("nan"),
    "newaxis": None,
}


def assemble(package: str, namespace: dict[str, Any], native_dtypes: dict[str, Any]) -> None:
    """Fill ``namespace`` (a backend package's globals) with the public names of its modules.

    Each backend package has one module per core group that has dispatched functions, with the
    same name as the group; those functions must all be defined there. Dtype names map to
    native dtype objects. Each Array API extension becomes a sub-namespace (``ivy.torch.fft``).
    """
    exported: set[str] = set()
    for group_name, group in zip(core.GROUP_NAMES, core.GROUPS):
        if (
            not _has_dispatched(group)
            and importlib.util.find_spec(f"{package}.{group_name}") is None
        ):
            continue  # a group of compositions only needs no backend module
        module = importlib.import_module(f"{package}.{group_name}")
        names = getattr(module, "__all__", ())
        namespace.update({name: getattr(module, name) for name in names})
        exported.update(names)
    missing = set(DTYPE_NAMES) - set(native_dtypes)
    if missing:
        raise ImportError(f"{package} defines no native dtype for {sorted(missing)}")
    namespace.update(native_dtypes)
    exported.update(DTYPE_NAMES)
    # What makes a backend namespace usable as an Array API namespace.
    namespace.update(ARRAY_API_CONSTANTS)
    exported.update(ARRAY_API_CONSTANTS)
    namespace["__array_api_version__"] = ARRAY_API_VERSION
    backend = package.rpartition(".")[2]
    for ext, group in extension_groups(core.GROUPS):
        call = namespace[ext] if ext in group.__all__ else None  # fft: callable namespace
        namespace[ext] = ExtensionNamespace(
            f"ivy.{backend}.{ext}", group.__all__, namespace.__getitem__, call
        )
        exported.add(ext)
    namespace["__all__"] = sorted(exported)


def _has_dispatched(group) -> bool:
    return any(
        getattr(getattr(group, name), "__ivy_kind__", None) == "dispatch" for name in group.__all__
    )
