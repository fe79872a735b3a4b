"""Fusion levels of an agent's update: what one ``ivy.compile_fn`` function holds.

``'update'``: the whole update (returns, every optimisation step) is one compiled function;
``'steps'``: the critic's values and each optimisation step are compiled on their own, and the
loop over the mini-batches is an ``ivy.compiled_scan`` (a host loop over the compiled step where
the compiler unrolls loops, one compiled scan where it keeps them); ``'auto'``: ``'update'``
where the framework's compiler compiles ``ivy.scan`` as a loop (jax, tensorflow), ``'steps'``
where it unrolls it (``torch.compile``), as the backend's capability ``compiled_loops`` says
(:func:`compiled_scan_unrolls`).

Example:
    >>> compiled_scan_unrolls(f="jax")
    False
"""

from __future__ import annotations

import ivy
from ivy.typing import Framework
from ivy_rl.settings import Setting

__all__ = ["FUSION_LEVELS", "compiled_scan_unrolls", "check_fusion", "fusion_level"]

FUSION_LEVELS = ("auto", "update", "steps")


def compiled_scan_unrolls(*, f: Framework = None) -> bool:
    """Whether ``ivy.compile_fn`` on the framework ``f`` unrolls ``ivy.scan`` (traces
    its body once per step, as ``torch.compile`` does) rather than compiling it as a loop (jax,
    tensorflow): the negation of the backend's capability ``compiled_loops``
    (:class:`ivy.framework_handler.Capabilities`). Agents choose their fusion level from it
    (``fusion='auto'``).

    Args:
        f: framework name or namespace (default: the global framework).

    Returns:
        True where the compiled scan is unrolled.

    Example:
        >>> compiled_scan_unrolls(f="jax"), compiled_scan_unrolls(f="torch")
        (False, True)
    """
    return not ivy.get_framework(f=f).capabilities.compiled_loops


def check_fusion(who: str, fusion: str) -> str:
    """``fusion`` if it is one of :data:`FUSION_LEVELS`, else a ValueError naming ``who``.

    Example:
        >>> check_fusion("SAC", "steps")
        'steps'
    """
    if fusion not in FUSION_LEVELS:
        raise ValueError(
            f"{who}: unknown fusion {fusion!r}; choose one of {', '.join(map(repr, FUSION_LEVELS))}"
        )
    return fusion


def fusion_level(fusion: str, *, compiled: bool, f: Framework = None) -> str:
    """The fusion level an agent runs at (the one rule of every agent): ``fusion`` itself
    when it is ``'update'`` or ``'steps'``; for ``'auto'``, ``'steps'`` where the agent
    compiles and the compiler of ``f`` unrolls ``ivy.scan`` (:func:`compiled_scan_unrolls`),
    else ``'update'``.

    Example:
        >>> fusion_level("auto", compiled=True, f="torch"), fusion_level("auto", compiled=True, f="jax")
        ('steps', 'update')
    """
    if fusion != "auto":
        return check_fusion("fusion_level", fusion)
    return "steps" if compiled and compiled_scan_unrolls(f=f) else "update"


#: the setting ``fusion`` of the agents that compile their updates
FUSION = Setting(
    "str",
    choices=FUSION_LEVELS,
    meaning="what one compiled function holds ('auto': by the framework's compiled_loops)",
)
