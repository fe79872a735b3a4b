"""The Array API's inspection namespace of an ivy backend: ``ivy.torch.__array_namespace_info__()``.

What it reports is what the backend can do now: dtypes are the backend namespace's own dtype
objects, the Array API's only (not float16, which ivy has beyond the standard), and only those
the backend can hold at the time of the call (jax's 64-bit types exist only while
``jax_enable_x64`` is on, which may change after import); devices are the framework's own device
objects, which arrays report as ``x.device`` and every ivy function takes as ``device=`` (as do
ivy's names, ``'cpu'`` and ``'gpu:0'``).

Example:
    >>> info = ivy.torch.__array_namespace_info__()
    >>> info.default_dtypes()["real floating"]
    torch.float32
    >>> info.default_device()
    device(type='cpu')
    >>> sorted(info.dtypes(kind="unsigned integer"))
    ['uint16', 'uint32', 'uint64', 'uint8']
"""

from __future__ import annotations

import types
from collections.abc import Callable
from typing import Any

from ivy.core._dtype_rules import KINDS
from ivy.dtypes import DTYPE_NAMES

ARRAY_API_DTYPES = tuple(n for n in DTYPE_NAMES if n != "float16")  # float16 is ivy's extra


class NamespaceInfo:
    """What ``xp.__array_namespace_info__()`` returns for the ivy namespace ``xp``.

    Args:
        ns: the backend namespace (``ivy.torch``...).
        devices: a callable giving ivy's names of the devices the backend sees now.
        capabilities: the Array API's capability flags of the backend.
    """

    __slots__ = ("_ns", "_devices", "_capabilities")

    def __init__(
        self, ns: types.ModuleType, devices: Callable[[], list[str]], capabilities: dict
    ) -> None:
        self._ns, self._devices, self._capabilities = ns, devices, capabilities

    def __repr__(self) -> str:
        return f"<ivy.{self._ns.backend} namespace info>"

    def capabilities(self) -> dict[str, Any]:
        """``{'boolean indexing': bool, 'data-dependent shapes': bool, 'max dimensions': ...}``:
        what the backend supports in eager code (inside a compiled function, jax and tensorflow
        need static shapes)."""
        return dict(self._capabilities)

    def default_device(self) -> Any:
        """The device new arrays go to (the framework's own object, as ``x.device``)."""
        return self._ns.zeros(()).device

    def devices(self) -> list:
        """The devices the backend can place arrays on (the framework's own objects)."""
        found = list(self._devices())
        default = self.default_device()
        return found if default in found else [default, *found]

    def default_dtypes(self, *, device: Any = None) -> dict[str, Any]:
        """The default dtypes: float32, complex64, and the default integer (int64; int32 on jax
        while 64-bit types are off), which is also the dtype of indices."""
        ns = self._ns

        def of(value: Any) -> Any:  # the namespace's own dtype object
            return getattr(ns, ns.dtype(ns.asarray(value), as_str=True))

        integral = of(0)
        return {
            "real floating": of(0.0),
            "complex floating": of(0j),
            "integral": integral,
            "indexing": integral,
        }

    def dtypes(self, *, device: Any = None, kind: str | tuple | None = None) -> dict[str, Any]:
        """The dtypes the backend can hold now, by name, of ``kind`` (a kind name such as
        ``'real floating'``, a dtype, or a tuple of these; None: every dtype)."""
        out = {}
        for name in ARRAY_API_DTYPES:
            native = getattr(self._ns, name, None)
            if native is not None and (kind is None or self._is_of(name, native, kind)):
                out[name] = native
        return out

    def _is_of(self, name: str, native: Any, kind: Any) -> bool:
        if isinstance(kind, tuple):
            return any(self._is_of(name, native, k) for k in kind)
        if isinstance(kind, str):
            if kind in KINDS:
                return name in KINDS[kind]
            if kind not in DTYPE_NAMES:
                raise ValueError(
                    f"Unknown dtype kind {kind!r}; use one of {', '.join(map(repr, KINDS))}, a "
                    f"dtype, or a tuple of these."
                )
            return kind == name
        return kind == native


def info_function(
    ns: types.ModuleType, devices: Callable[[], list[str]] | None, capabilities: dict
) -> Callable[[], NamespaceInfo]:
    """``ns.__array_namespace_info__``: a function returning the namespace's :class:`NamespaceInfo`."""
    info = NamespaceInfo(ns, devices or (lambda: []), capabilities)

    def __array_namespace_info__() -> NamespaceInfo:
        """The Array API inspection namespace of this backend (dtypes, devices, capabilities)."""
        return info

    return __array_namespace_info__
