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

from ivy import framework_handler as _fh
from ivy.backends import _complex_special, _int_pow, _reals
from ivy.backends._clip_args import clip_bounds

_XP = _complex_special.namespace(jnp, complex=jax.lax.complex)


def _fixed(name: str):
    # jitted: eager, its hundred small operations would each compile for every new shape
    fix = jax.jit(_complex_special.fixer(name, _XP))
    return _reals.unary(getattr(jnp, name), name, fix)


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
_fix_sign = _complex_special.fixer("sign", _XP)


@jax.jit
def sign(x, /):
    """jax's sign, with the Array API's special values: ``sign(0j)`` is ``0 + 0j`` (jax's is
    NaN) and ``sign(-0.0)`` is ``+0.0`` as on the other backends (jax's is -0.0). Jitted as jax's
    own is: the dtype tests happen at trace time, so a call costs what ``jax.numpy.sign``'s
    does."""
    out = jnp.sign(x)
    if jnp.iscomplexobj(out):
        return _fix_sign(x, out)
    if jnp.issubdtype(out.dtype, jnp.floating):
        return jnp.where(out == 0, jnp.zeros_like(out), out)
    return out


_HALF = (jnp.float16, jnp.bfloat16)


def _floor_divide(x1, x2, /):
    """jax's, with half-precision floats computed in float32 as numpy and torch do (jax's own
    float16 result rounds the quotient: 2.5 // 0.001 is 2496 there, 2498 elsewhere)."""
    out = jnp.floor_divide(x1, x2)
    if out.dtype in _HALF:
        wide = jnp.floor_divide(jnp.asarray(x1, jnp.float32), jnp.asarray(x2, jnp.float32))
        return wide.astype(out.dtype)
    return out


floor_divide = _reals.scalar_operands(_floor_divide, "floor_divide")


@jax.jit
def abs(x, /):  # noqa: A001 - the Array API name
    """jax's abs; of a complex number with an infinite part it is +inf, as the standard says
    (jax's is NaN where the other part is NaN). Jitted as jax's own is: a real input costs what
    ``jax.numpy.abs`` does."""
    out = jnp.abs(x)
    if jnp.iscomplexobj(x):
        infinite = jnp.isinf(jnp.real(x)) | jnp.isinf(jnp.imag(x))
        return jnp.where(infinite, jnp.asarray(jnp.inf, out.dtype), out)
    return out


def clip(x, /, min=None, max=None):  # noqa: A002 - the Array API names
    """``jnp.clip``'s values with torch's and tensorflow's gradient: 1 where ``x`` equals a bound
    (``jnp.clip`` is ``minimum(maximum(x, min), max)``, whose gradient is 1/2 there, so that a
    bilinear sample clamped to the image's edge got half the gradient of the other backends).
    The result has ``x``'s dtype whatever the bounds' (``ivy/backends/_clip_args.py``)."""
    x = jnp.asarray(x)
    if min is None and max is None:
        return jnp.array(x, copy=True)
    low, high = clip_bounds(_fh.load_backend("jax"), x, min, max)
    if x.dtype == jnp.bool_:
        if low is not None:
            x = jnp.logical_or(x, low)
        return x if high is None else jnp.logical_and(x, high)
    return _clamped(x, low, high)


@jax.jit
def _clamped(x, low, high):
    """One compiled call (eager, the ``where`` of each bound would be dispatched one by one);
    None bounds are static (a pytree without leaves)."""
    if low is not None:
        x = jnp.where(x < low, jnp.asarray(low, dtype=x.dtype), x)
    if high is not None:
        x = jnp.where(x > high, jnp.asarray(high, dtype=x.dtype), x)
    return x


# jax's own minimum and maximum order -0 below +0 already (``ivy/backends/_signed_zeros.py``)
maximum = _reals.scalar_operands(jnp.maximum, "maximum")
minimum = _reals.scalar_operands(jnp.minimum, "minimum")


_scalar_pow = _reals.scalar_operands(jnp.power, "pow")


def _integral(x) -> bool:
    dtype = getattr(x, "dtype", None)
    if dtype is None:
        return type(x) is int
    return jnp.issubdtype(dtype, jnp.integer)


def pow(x1, x2, /):
    """``x1 ** x2``; integers to negative integer powers as ``ivy/backends/_int_pow.py`` says
    (jax would wrap around: ``2 ** -1`` is ``-2**63``)."""
    if not (_integral(x2) and _integral(x1)):  # the common case, first
        return _scalar_pow(x1, x2)
    return _int_pow.integer_pow(
        _scalar_pow,
        x1,
        x2,
        integral=_integral,
        values_known=lambda x: not isinstance(x, jax.core.Tracer),
        any_negative=lambda x: bool(jnp.any(jnp.asarray(x) < 0)),
        where=jnp.where,
        backend="jax",
    )
