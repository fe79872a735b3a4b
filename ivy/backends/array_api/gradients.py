"""Gradients for backends without automatic differentiation: the gradient functions raise
:class:`ivy.errors.UnsupportedError`; ``stop_gradient`` and ``variable`` return their input (an
array of such a library carries no gradient, and forward passes of models work on it)."""

from __future__ import annotations

from ivy.backends.array_api._unbound import backend_name
from ivy.errors import UnsupportedError


def _no_autodiff(name: str) -> UnsupportedError:
    return UnsupportedError(
        f"ivy.{name} needs automatic differentiation, which the {backend_name} backend does not "
        f"have. Use a differentiable backend: torch, jax or tensorflow (pass f='jax', convert the "
        f"inputs with ivy.asarray(x, f='jax'), or call ivy.set_framework('jax'))."
    )


def value_and_grad_native(fn, xs, /, *, retain_grads=False):
    raise _no_autodiff("execute_with_gradients")


def jacobian_native(fn, x, /, *, retain_grads=False):
    raise _no_autodiff("execute_with_jacobian")


def stop_gradient(x, /):
    return x


def with_gradient_of(value, fn, args, /):
    return value  # no derivatives are taken: fn is never needed


def variable(x, /):
    return x
