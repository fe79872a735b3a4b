"""Compilation: ``ivy.compile_fn(fn)`` compiles with the backend's own compiler.

- jax: ``jax.jit``, with ``static_argnums`` / ``static_argnames``; the backend's PRNG key is
  threaded through as an extra input, so random draws differ from call to call;
- tensorflow: ``tf.function`` (Python arguments are static by nature);
- torch: ``torch.compile``; where it cannot run, the function runs eagerly, with a warning;
- numpy: no compiler; the function is returned unchanged, with a warning.

Compiled results equal eager results. With no ``f``, the framework is resolved from the arguments
of the first call (or the global framework at that time) and kept for later calls.
"""

from __future__ import annotations

import functools
import threading
from collections.abc import Callable, Sequence

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition, dispatch
from ivy.typing import Framework

__all__ = ["compile_fn", "compile_native"]


@dispatch()
def compile_native(
    fn: Callable,
    /,
    *,
    static_argnums: int | Sequence[int] | None = None,
    static_argnames: str | Sequence[str] | None = None,
    f: Framework = None,
) -> Callable:
    """Compile ``fn`` now with the backend of ``f`` (or the global framework); prefer
    :func:`compile_fn`, which can also choose the framework at the first call.

    Example:
        >>> step = ivy.compile_native(step, f='jax')
    """


@composition
def compile_fn(
    fn: Callable,
    /,
    *,
    static_argnums: int | Sequence[int] | None = None,
    static_argnames: str | Sequence[str] | None = None,
    f: Framework = None,
) -> Callable:
    """Compile ``fn`` with the framework's compiler (``jax.jit``, ``tf.function``,
    ``torch.compile``; numpy warns and returns ``fn``).

    Args:
        fn: a function of arrays (and nests of arrays) written with ivy functions.
        static_argnums: positions of arguments that are compile-time constants (jax; tf and
            torch treat Python values as static by themselves).
        static_argnames: names of such arguments.
        f: framework name or namespace; by default resolved from the first call's arguments.

    Returns:
        The compiled function, called like ``fn``.

    Example:
        >>> step = ivy.compile_fn(train_step)
        >>> v = step(v, batch)  # traced and compiled on this first call, for v's framework
    """
    if f is not None:
        xp = _fh.get_framework(f=f)
        return xp.compile_native(fn, static_argnums=static_argnums, static_argnames=static_argnames)
    return _CompiledOnFirstCall(fn, static_argnums, static_argnames)


class _CompiledOnFirstCall:
    """``fn`` compiled for the framework of the arguments of its first call."""

    def __init__(self, fn, static_argnums, static_argnames):
        self._fn = fn
        self._static = dict(static_argnums=static_argnums, static_argnames=static_argnames)
        self._compiled = None
        self._lock = threading.Lock()
        functools.update_wrapper(self, fn)

    def __call__(self, *args, **kwargs):
        compiled = self._compiled
        if compiled is None:
            with self._lock:
                if self._compiled is None:
                    xp = _fh.get_framework(args, kwargs)
                    self._compiled = xp.compile_native(self._fn, **self._static)
                compiled = self._compiled
        return compiled(*args, **kwargs)

    def __get__(self, obj, objtype=None):
        """Bind as a method when used as a decorator inside a class."""
        return self if obj is None else functools.partial(self, obj)

    def __repr__(self) -> str:
        return f"<ivy.compile_fn of {self._fn!r}>"
