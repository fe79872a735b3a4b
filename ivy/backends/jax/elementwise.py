"""jax backend: elementwise functions that differ from the shared layer's.

jax's complex functions give NaN, or the wrong sign of a zero, for many inputs with an infinite
or NaN part (``exp(-inf + inf j)`` is NaN, not ``0 + 0j``; ``sign(0j)`` is NaN): these are jax's
own functions with the Array API's special values put back for complex results
(``ivy/backends/_complex_special.py``). Real inputs take the path of every function of real
numbers (``ivy/backends/_reals.py``), with one dtype test more.
"""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np

from ivy.backends import _complex_special, _reals

_XP = _complex_special.namespace(jnp, complex=jax.lax.complex)


def _fixed(name: str):
    return _reals.unary(getattr(jnp, name), name, _complex_special.fixer(name, _XP))


acos = _fixed("acos")
acosh = _fixed("acosh")
asinh = _fixed("asinh")
atanh = _fixed("atanh")
cosh = _fixed("cosh")
exp = _fixed("exp")
expm1 = _fixed("expm1")
log = _fixed("log")
log1p = _fixed("log1p")
sinh = _fixed("sinh")
sqrt = _fixed("sqrt")
tanh = _fixed("tanh")
# not a function of real numbers (integers keep their dtype): only the complex test
sign = _complex_special.wrap(
    jnp.sign, "sign", _XP, (np.dtype(np.complex64), np.dtype(np.complex128))
)
