"""What the core declares: every public function, its kind and the rules it follows.

Example:
    >>> ivy.function_info("clip").kind
    'dispatched'
    >>> [i.name for i in ivy.list_functions(kind="alias")]
    ['array', 'cast', 'concatenate', 'norm']
"""

from __future__ import annotations

from ivy.core._dispatch import KINDS, REGISTRY, FunctionInfo

__all__ = ["FunctionInfo", "function_info", "list_functions"]


def list_functions(
    *, kind: str | None = None, group: str | None = None
) -> tuple[FunctionInfo, ...]:
    """The core's public functions, sorted by name.

    Args:
        kind: only those of this kind: ``'dispatched'`` (a generated dispatcher), ``'by_hand'``
            (a dispatcher written by hand), ``'composition'`` or ``'alias'``; None: every kind.
        group: only those of this core group (``'elementwise'``, ``'linalg'`` ...).

    Returns:
        One :class:`FunctionInfo` per function (name, kind, group, alias target, rules).

    Example: ``len(ivy.list_functions(kind='composition'))`` counts the compositions.
    """
    if kind is not None and kind not in KINDS:
        raise ValueError(f"kind={kind!r} is not one of {', '.join(KINDS)}")
    return tuple(
        info
        for name, info in sorted(REGISTRY.items())
        if (kind is None or info.kind == kind) and (group is None or info.group == group)
    )


def function_info(name: str) -> FunctionInfo:
    """What the core declares of the public function ``name`` (see :class:`FunctionInfo`).

    Example: ``ivy.function_info('sin').reals`` -> ``'unary'``.
    """
    try:
        return REGISTRY[name]
    except KeyError:
        raise ValueError(f"ivy has no public function {name!r}") from None
