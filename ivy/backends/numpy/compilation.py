"""numpy backend: numpy has no compiler, so ``compile_native`` warns and returns the function."""

from __future__ import annotations

import warnings


def compile_native(fn, /, *, static_argnums=None, static_argnames=None):
    warnings.warn(
        "numpy has no compiler: ivy.compile_fn returns the function unchanged, and it runs "
        "eagerly. Use jax, tensorflow or torch arrays (or f='jax') to compile.",
        UserWarning,
        stacklevel=3,
    )
    return fn
