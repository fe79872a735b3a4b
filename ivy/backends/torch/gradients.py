"""torch backend: gradients with ``torch.autograd.grad``, which returns them and never
accumulates into ``.grad``: two calls give the same gradients, and parameters stay untouched.

Each leaf is differentiated through a fresh tensor: ``x.detach().requires_grad_()``, so the graph
of a previous computation is neither reused nor freed, and a tensor that the function captures
from outside is a constant. With ``retain_grads=True`` a leaf that already requires grad is
aliased instead (``x.view_as(x)``, still connected to ``x``) and the graph is kept
(``create_graph=True``), so the results can be differentiated again (second order).
"""

from __future__ import annotations

import torch

from ivy.nest import map_nest, multi_map_nest, nest_leaves


def _input(x, retain_grads):
    """The tensor to differentiate with respect to, in place of the leaf ``x``."""
    if not isinstance(x, torch.Tensor):
        x = torch.as_tensor(x)
    if retain_grads and x.requires_grad:
        return x.view_as(x)
    return x.detach().requires_grad_(True)


def _detach(nest):
    return map_nest(lambda a: a.detach() if isinstance(a, torch.Tensor) else a, nest)


def _grads(y, inputs, retain_grads, keep_graph=False):
    """Gradients of ``y`` with respect to each of ``inputs``; zeros where ``y`` does not depend."""
    if not y.requires_grad:
        return [torch.zeros_like(x) for x in inputs]
    return list(
        torch.autograd.grad(
            y,
            inputs,
            retain_graph=retain_grads or keep_graph,
            create_graph=retain_grads,
            allow_unused=True,
            materialize_grads=True,
        )
    )


def value_and_grad_native(fn, xs, /, *, retain_grads=False):
    inputs = [_input(x, retain_grads) for x in xs]
    with torch.enable_grad():
        loss, aux = fn(inputs)
    if not isinstance(loss, torch.Tensor):
        loss = torch.as_tensor(loss)
    grads = _grads(loss, inputs, retain_grads)
    if not retain_grads:
        loss, aux = loss.detach(), _detach(aux)
    return loss, aux, grads


def jacobian_native(fn, x, /, *, retain_grads=False):
    x = _input(x, retain_grads)
    with torch.enable_grad():
        out, aux = fn(x)
    flat = out.reshape(-1)
    m = flat.numel()
    jac = _batched_rows(flat, x, retain_grads) if m > 1 else None
    if jac is None:  # one backward pass per output component
        rows = [_grads(flat[i], [x], retain_grads, keep_graph=i < m - 1)[0] for i in range(m)]
        jac = torch.stack(rows, 0) if rows else x.new_zeros((0, *x.shape))
    jac = jac.reshape(*out.shape, *x.shape)
    if not retain_grads:
        jac, aux = jac.detach(), _detach(aux)
    return jac, aux


def _batched_rows(flat, x, retain_grads):
    """All the rows of the Jacobian of ``flat`` in one backward pass vectorised over the rows
    (``is_grads_batched``: about 3x faster than a pass per row through a long rollout), or None
    where an operation of the graph has no batching rule (then a pass per row)."""
    if not flat.requires_grad:
        return torch.zeros((flat.numel(), *x.shape), dtype=x.dtype, device=x.device)
    eye = torch.eye(flat.numel(), dtype=flat.dtype, device=flat.device)
    try:
        (jac,) = torch.autograd.grad(
            flat,
            [x],
            grad_outputs=eye,
            retain_graph=True,
            create_graph=retain_grads,
            allow_unused=True,
            materialize_grads=True,
            is_grads_batched=True,
        )
    except RuntimeError:
        return None
    return jac


def stop_gradient(x, /):
    return x.detach()


def with_gradient_of(value, fn, args, /):
    if not _differentiated(nest_leaves(args)):
        return map_nest(lambda v: v.detach() if isinstance(v, torch.Tensor) else v, value)
    out = fn(*args)
    return multi_map_nest(lambda v, o: v.detach() + (o - o.detach()), value, out)


def _differentiated(leaves) -> bool:
    """Whether a derivative may be taken through ``leaves``: grad mode with a leaf that
    requires grad, a forward-mode AD level, or (eagerly: dynamo cannot trace the test, and
    inside torch.compile the tensors' ``requires_grad`` says it) a ``torch.func`` transform's
    wrapped tensor."""
    tensors = [t for t in leaves if isinstance(t, torch.Tensor)]
    if torch.autograd.forward_ad._current_level >= 0:
        return True
    if not torch.compiler.is_compiling() and any(
        torch._C._functorch.is_functorch_wrapped_tensor(t) for t in tensors
    ):
        return True
    return torch.is_grad_enabled() and any(t.requires_grad for t in tensors)


def variable(x, /):
    if not isinstance(x, torch.Tensor):
        x = torch.as_tensor(x)
    return x.detach().requires_grad_(True)
