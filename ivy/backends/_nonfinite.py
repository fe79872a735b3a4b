"""Matrices holding NaN or infinity, the same on every backend (written once, against any array
library's ``where``).

LAPACK's decompositions fail on them in different ways: numpy and torch raise ("SVD did not
converge"), jax and tensorflow answer with NaN, some only in part of the result (a QR factor, an
eigenvector), and tensorflow's ``eigh`` raises a framework error. ivy takes one rule for the
decompositions (``cholesky``, ``eigh``, ``eigvalsh``, ``pinv``, ``qr``, ``slogdet``, ``svd`` and
``svdvals``): **a matrix that is not finite gives NaN in every floating result**, and the other
matrices of the batch their usual results. A NaN from a sensor then flows through a compiled
program (which cannot raise on values) as it flows through ``det``, ``inv`` and ``solve``,
whose answers the backends already share. ``matrix_rank`` counts singular values, and its
integer result has no NaN: where the values are known it refuses such a matrix
(``LinAlgError``); inside a compiled program its count is 0 (no NaN is above the tolerance).

Each non-finite matrix is replaced by the identity before the native call, so that the native
never sees it and the gradient of the finite matrices is unchanged.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

_NAN = float("nan")


def nan_where_not_finite(
    compute: Callable[[Any], Any],
    x: Any,
    ok: Any,
    eye: Any,
    where: Callable[[Any, Any, Any], Any],
    floating: Callable[[Any], bool],
) -> Any:
    """``compute(x)`` with NaN in every floating result of the matrices where ``ok`` (one bool
    per matrix, ``x``'s batch shape) is False, those matrices replaced by ``eye`` (the identity
    of ``x``'s last two axes) for the native call."""
    out = compute(where(ok[..., None, None], x, eye))

    def fill(y):
        if not floating(y):
            return y
        mask = ok[(..., *([None] * (len(y.shape) - len(ok.shape))))]
        return where(mask, y, _NAN)

    if isinstance(out, tuple):
        values = [fill(y) for y in out]
        return type(out)(*values) if hasattr(out, "_fields") else type(out)(values)
    return fill(out)


def refuse_not_finite(all_finite: bool, backend: str) -> None:
    """``matrix_rank``'s refusal where the values are known (``all_finite`` False)."""
    if not all_finite:
        from ivy.errors import LinAlgError

        raise LinAlgError(
            "the matrix holds NaN or infinity: its rank is undefined. Replace them first "
            "(ivy.nan_to_num), or mask those matrices out.",
            function="matrix_rank",
            argument="x",
            backend=backend,
        )
