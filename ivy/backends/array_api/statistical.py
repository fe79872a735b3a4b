"""Reductions, written once against ``xp``, with the Array API's keywords (numpy's and jax's own
``mean``, ``var`` and ``std`` take more, positionally). Integer and boolean inputs compute in
float32 by the rule declared on the core's stubs."""

from __future__ import annotations

from ivy._args.axes import too_few_for_correction
from ivy.backends.array_api._unbound import xp


def mean(x, /, *, axis=None, keepdims=False):
    return xp.mean(x, axis=axis, keepdims=keepdims)


def var(x, /, *, axis=None, correction=0.0, keepdims=False):
    if too_few_for_correction(x.shape, axis, correction):
        return _nan_like(xp.var(x, axis=axis, keepdims=keepdims))
    return xp.var(x, axis=axis, correction=correction, keepdims=keepdims)


def std(x, /, *, axis=None, correction=0.0, keepdims=False):
    if too_few_for_correction(x.shape, axis, correction):
        return _nan_like(xp.std(x, axis=axis, keepdims=keepdims))
    return xp.std(x, axis=axis, correction=correction, keepdims=keepdims)


def _nan_like(out):
    """NaN of ``out``'s shape and dtype: the result where ``N - correction <= 0``, as the
    standard says (numpy gives inf there, with a warning)."""
    return xp.full_like(xp.asarray(out), float("nan"))
