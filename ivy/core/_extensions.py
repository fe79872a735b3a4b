"""Array API extension namespaces: ``ivy.linalg``, ``ivy.fft`` and ``ivy.<backend>.linalg`` ...

A core group that is an Array API extension sets ``__extension__`` to the extension's name; its
``__all__`` lists the extension's functions. Those functions stay reachable flat (``ivy.svd``,
``ivy.torch.svd``) and are also grouped in a namespace of the extension's name (``ivy.linalg.svd``,
``ivy.torch.linalg.svd``) holding the very same objects.

``fft`` is both the name of the extension and of one of its functions, so ``ivy.fft`` is a callable
namespace: ``ivy.fft(x)`` is ``ivy.fft.fft(x)`` (as ``xp.fft.fft`` in Array API code).
"""

from __future__ import annotations

import types
from collections.abc import Callable, Iterable
from typing import Any

__all__ = ["ExtensionNamespace", "agnostic_extensions", "extension_groups"]


class ExtensionNamespace(types.ModuleType):
    """A namespace whose attributes are the functions of one Array API extension.

    Attributes are looked up in ``source`` (the backend namespace, or the core group) on first
    access and then cached, so functions bound into ``source`` after the namespace was made
    (compositions, aliases) are found too, and ``ns.svd is source.svd``.
    """

    def __init__(
        self,
        name: str,
        names: Iterable[str],
        source: Callable[[str], Any],
        call: Callable | None = None,
    ):
        super().__init__(name)
        self.__all__ = sorted(names)
        self.__doc__ = f"The Array API extension {name}: {', '.join(self.__all__)}."
        self._source = source
        self._call = call

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__") or name not in self.__all__:
            raise AttributeError(f"namespace {self.__name__!r} has no attribute {name!r}")
        own = self.__name__.rpartition(".")[2]
        value = self._call if name == own and self._call is not None else self._source(name)
        setattr(self, name, value)
        return value

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        if self._call is None:
            raise TypeError(f"namespace {self.__name__!r} is not callable")
        return self._call(*args, **kwargs)

    def __dir__(self) -> list[str]:
        return list(self.__all__)

    def __repr__(self) -> str:
        return f"<ivy namespace {self.__name__!r}>"


def extension_groups(groups: Iterable[types.ModuleType]) -> list[tuple[str, types.ModuleType]]:
    """``(extension name, group)`` for each core group that is an Array API extension."""
    return [(g.__extension__, g) for g in groups if getattr(g, "__extension__", None)]


def agnostic_extensions() -> dict[str, ExtensionNamespace]:
    """The framework-agnostic extension namespaces (``ivy.linalg``, ``ivy.fft``), keyed by name.

    An extension whose name is also one of its functions (``fft``) replaces that function in
    ``ivy.core`` by its callable namespace, so that ``ivy.core.fft is ivy.fft``.
    """
    from ivy import core

    out = {}
    for name, group in extension_groups(core.GROUPS):
        call = getattr(group, name) if name in group.__all__ else None
        ns = ExtensionNamespace(f"ivy.{name}", group.__all__, group.__dict__.__getitem__, call)
        if call is not None:
            setattr(core, name, ns)
        out[name] = ns
    return out
