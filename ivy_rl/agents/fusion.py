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

__all__ = ["FUSION_LEVELS", "compiled_scan_unrolls"]

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
