"""Compilation for backends without a compiler: ``compile_native`` warns and returns the
function, which then runs eagerly with the same results (static and donated arguments are
accepted and change nothing)."""

from __future__ import annotations

import warnings

from ivy.backends.array_api._unbound import backend_name


def compile_native(fn, /, *, static_argnums=None, static_argnames=None, donate_argnums=None):
    warnings.warn(
        f"{backend_name} has no compiler: ivy.compile_fn returns the function unchanged, and it "
        f"runs eagerly. Use jax, tensorflow or torch arrays (or f='jax') to compile.",
        UserWarning,
        stacklevel=3,
    )
    return fn
