"""Compilation: ``ivy.compile_fn(fn)`` compiles with the backend's own compiler.

- jax: ``jax.jit``, with ``static_argnums`` / ``static_argnames`` and ``donate_argnums``; the
  backend's PRNG key is threaded through as an extra input, so random draws differ from call to
  call;
- tensorflow: ``tf.function`` (Python arguments are static by nature);
- torch: ``torch.compile``; where it cannot run, the function runs eagerly, with a warning;
- numpy: no compiler; the function is returned unchanged, with a warning.

Donation (``donate_argnums``) lets the compiled function reuse the buffers of those arguments
for its results (an array updated by ``ivy.put_rows`` is then written in place). Only jax's
compiler does it; the donated arrays are deleted by the call there, so the caller must hold no
other reference to them. Elsewhere it is accepted and changes nothing: the arguments stay valid.

Compiled results equal eager results. With no ``f``, the framework is resolved from the arguments
of the first call (or the global framework at that time) and kept for later calls.
"""

from __future__ import annotations

import functools
import threading
from collections.abc import Callable, Sequence

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition, dispatch
from ivy.nest import flatten_nest, unflatten_nest
from ivy.typing import Framework, Nest

__all__ = ["compile_fn", "compile_native", "compiled_scan"]


@dispatch()
def compile_native(
    fn: Callable,
    /,
    *,
    static_argnums: int | Sequence[int] | None = None,
    static_argnames: str | Sequence[str] | None = None,
    donate_argnums: int | Sequence[int] | None = None,
    f: Framework = None,
) -> Callable:
    """Compile ``fn`` now with the backend of ``f`` (or the global framework); prefer
    :func:`compile_fn`, which can also choose the framework at the first call.

    Example:
        >>> step = lambda x: jnp.sin(x) * 2
        >>> step = ivy.compile_native(step, f='jax')
    """


@composition
def compile_fn(
    fn: Callable,
    /,
    *,
    static_argnums: int | Sequence[int] | None = None,
    static_argnames: str | Sequence[str] | None = None,
    donate_argnums: int | Sequence[int] | None = None,
    f: Framework = None,
) -> Callable:
    """Compile ``fn`` with the framework's compiler (``jax.jit``, ``tf.function``,
    ``torch.compile``; numpy warns and returns ``fn``).

    Args:
        fn: a function of arrays (and nests of arrays) written with ivy functions.
        static_argnums: positions of arguments that are compile-time constants (jax; tf and
            torch treat Python values as static by themselves).
        static_argnames: names of such arguments.
        donate_argnums: positions of arguments (arrays, or nests of arrays) whose buffers the
            compiled function may reuse for its results (jax: ``jax.jit``'s ``donate_argnums``;
            the arrays passed there are deleted by the call, so pass only arrays nothing else
            refers to, and use the results instead). tensorflow, torch and numpy have no
            donation: accepted, with no effect.
        f: framework name or namespace; by default resolved from the first call's arguments.

    Returns:
        The compiled function, called like ``fn``.

    Example:
        >>> train_step = lambda v, batch: {"w": v["w"] - 0.1 * ivy.mean(batch) * v["w"]}
        >>> v, batch = {"w": jnp.ones(3)}, jnp.arange(4.0)
        >>> step = ivy.compile_fn(train_step)
        >>> v = step(v, batch)  # traced and compiled on this first call, for v's framework
        >>> write = ivy.compile_fn(lambda x, i, u: ivy.put_rows(x, i, u), donate_argnums=0)
        >>> x, indices, rows = jnp.zeros((4, 2)), jnp.array([0, 2]), jnp.ones((2, 2))
        >>> x = write(x, indices, rows)  # on jax, in place: the x passed in is deleted
    """
    options = dict(
        static_argnums=static_argnums,
        static_argnames=static_argnames,
        donate_argnums=donate_argnums,
    )
    if f is not None:
        return _fh.get_framework(f=f).compile_native(fn, **options)
    return _CompiledOnFirstCall(fn, options)


class _CompiledOnFirstCall:
    """``fn`` compiled for the framework of the arguments of its first call."""

    def __init__(self, fn, options):
        self._fn = fn
        self._options = options  # of compile_native
        self._compiled = None
        self._lock = threading.Lock()
        functools.update_wrapper(self, fn)

    def __call__(self, *args, **kwargs):
        compiled = self._compiled
        if compiled is None:
            with self._lock:
                if self._compiled is None:
                    xp = _fh.get_framework(args, kwargs)
                    self._compiled = xp.compile_native(self._fn, **self._options)
                compiled = self._compiled
        return compiled(*args, **kwargs)

    def __get__(self, obj, objtype=None):
        """Bind as a method when used as a decorator inside a class."""
        return self if obj is None else functools.partial(self, obj)

    def __repr__(self) -> str:
        return f"<ivy.compile_fn of {self._fn!r}>"


@composition
def compiled_scan(
    fn: Callable[[Nest, Nest], tuple[Nest, Nest]],
    /,
    *,
    length: int | None = None,
    f: Framework = None,
) -> Callable[..., tuple[Nest, Nest]]:
    """``ivy.scan(fn, init, xs, length=length)``, compiled where the framework's compiler can.

    Where to put the compile boundary follows the backend's capability ``compiled_loops``:

    - the compiler keeps loops (jax, tensorflow): the whole scan is one :func:`compile_fn`
      function, so a long loop compiles as fast as a short one;
    - the compiler unrolls loops (``torch.compile``): ``fn`` is compiled on its own and a
      Python loop on the host calls it once per step (compiled once, whatever the length);
    - no compiler (numpy): the scan runs eagerly.

    The results equal ``ivy.scan``'s on every backend.

    Args:
        fn: ``fn(carry, x) -> (carry, y)``, as for :func:`ivy.scan`.
        length: the number of steps; required when ``xs`` is None.
        f: framework name or namespace; by default resolved from the first call's arguments.

    Returns:
        ``run(init, xs=None) -> (carry, ys)``.

    Example:
        >>> run = ivy.compiled_scan(lambda c, x: (c + x, c * x), f="jax")
        >>> carry, ys = run(jnp.zeros(()), jnp.arange(4.0))
    """
    return _CompiledScan(fn, length, f)


class _CompiledScan:
    """The scan of ``fn``, with its compiled function made per framework at the first call."""

    def __init__(self, fn, length, f):
        self._fn = fn
        self._length = length
        self._f = f
        self._runs = {}
        functools.update_wrapper(self, fn)

    def __call__(self, init, xs=None):
        xp = _fh.get_framework(init, xs, f=self._f)
        run = self._runs.get(xp.backend)
        if run is None:
            run = self._runs[xp.backend] = self._plan(xp)
        return run(init, xs)

    def _plan(self, xp):
        fn, length = self._fn, self._length
        caps = xp.capabilities
        if not caps.compilation:
            return lambda init, xs: xp.scan(fn, init, xs, length=length)
        if caps.compiled_loops:
            return xp.compile_fn(lambda init, xs: xp.scan(fn, init, xs, length=length))
        step = xp.compile_fn(fn)
        return lambda init, xs: _host_scan(xp, fn, step, init, xs, length)

    def __repr__(self) -> str:
        return f"<ivy.compiled_scan of {self._fn!r}>"


def _host_scan(xp, fn, step, init, xs, length):
    """``xp.scan(fn, init, xs, length=length)`` as a host loop over ``step``, ``fn`` compiled."""
    leaves, spec = flatten_nest(xs)
    steps = int(leaves[0].shape[0]) if leaves else length
    if steps is None or (length is not None and steps != length) or steps == 0:
        return xp.scan(fn, init, xs, length=length)  # its errors, and the shapes of no step
    carry, outputs = init, []
    for i in range(steps):
        x = unflatten_nest(spec, [leaf[i] for leaf in leaves]) if leaves else xs
        carry, y = step(carry, x)
        outputs.append(flatten_nest(y))
    y_spec = outputs[0][1]
    columns = zip(*(ys for ys, _ in outputs)) if outputs[0][0] else ()
    return carry, unflatten_nest(y_spec, [xp.stack(list(col)) for col in columns])
