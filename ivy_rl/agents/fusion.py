"""Fusion levels of an agent's update: what one ``ivy.compile_fn`` function holds.

``'update'``: the whole update (returns, every optimisation step) is one compiled function;
``'steps'``: the critic's values and each optimisation step are compiled on their own, and the
loops (the returns' scan, the mini-batches) run on the host; ``'auto'``: ``'update'`` where the framework's compiler compiles ``ivy.scan`` as a loop
(jax, tensorflow), ``'steps'`` where it unrolls it (``torch.compile``), as found by
:func:`compiled_scan_unrolls`.

Example:
    >>> compiled_scan_unrolls(f="jax")
    False
"""

from __future__ import annotations

import ivy
from ivy.typing import Framework

__all__ = ["FUSION_LEVELS", "compiled_scan_unrolls"]

FUSION_LEVELS = ("auto", "update", "steps")
_UNROLLS: dict[str, bool] = {}


def compiled_scan_unrolls(*, f: Framework = None) -> bool:
    """Whether ``ivy.compile_fn`` on the framework ``f`` unrolls ``ivy.scan`` (traces
    its body once per step, as ``torch.compile`` does) rather than compiling it as a loop (jax,
    tensorflow). Found once per backend by compiling a scan of 8 steps and counting the
    traces of its body; agents choose their fusion level from it (``fusion='auto'``).

    Args:
        f: framework name or namespace (default: the global framework).

    Returns:
        True where the compiled scan is unrolled.

    Example:
        >>> compiled_scan_unrolls(f="jax"), compiled_scan_unrolls(f="torch")
        (False, True)
    """
    xp = ivy.get_framework(f=f)
    if xp.backend not in _UNROLLS:
        traces = []

        def body(total, x):
            traces.append(None)
            return total + x, x

        def run(xs):
            return xp.scan(body, xs[0], xs)[0]

        ivy.compile_fn(run, f=xp)(xp.zeros((8,), dtype="float32"))
        _UNROLLS[xp.backend] = len(traces) >= 8
    return _UNROLLS[xp.backend]
