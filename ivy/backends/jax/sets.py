"""jax backend: unique values (jax.numpy's own Array API functions, which return named tuples).
Each NaN is a distinct value; -0.0 and 0.0 are one value.

The number of unique values decides the shape of the result, so inside ``jax.jit`` (or ``vmap``)
these functions raise UnsupportedError: jax needs a static ``size`` there, which the Array API's
signature has no place for (``jax.numpy.unique_values(x, size=N)`` takes one)."""

from __future__ import annotations

import jax
import jax.numpy as jnp

from ivy.errors import UnsupportedError


def _eager(native, name: str):
    def fn(x, /):
        try:
            return native(x)
        except jax.errors.ConcretizationTypeError as err:
            raise UnsupportedError(
                f"{name}: inside jax.jit (or vmap) the number of unique values must be known "
                f"when tracing. Call it outside the compiled function, or call "
                f"jax.numpy.{name}(x, size=N) with a static size N."
            ) from err

    fn.__name__ = fn.__qualname__ = name
    fn.__doc__ = f"``jax.numpy.{name}``, outside ``jax.jit``."
    return fn


unique_all = _eager(jnp.unique_all, "unique_all")
unique_counts = _eager(jnp.unique_counts, "unique_counts")
unique_inverse = _eager(jnp.unique_inverse, "unique_inverse")
unique_values = _eager(jnp.unique_values, "unique_values")
