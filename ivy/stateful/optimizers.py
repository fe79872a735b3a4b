"""Optimizers as functional updates of nests: ``v, state = opt.step(v, grads, state)``.

The optimizer state is a nest too (``{'step': count, 'mu': ..., 'nu': ...}``), so a whole
training step (loss, gradients, update) is a pure function of arrays that compiles on jax and
tensorflow. A stateful form keeps the state in the optimizer and the variables in a module::

    opt = ivy.Adam(1e-3)
    loss = opt.minimize(model, lambda v: ivy.mse(model(x, v=v), y))   # updates model.v

The update formulas are torch's (``torch.optim.SGD``, ``Adam``, ``AdamW``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from ivy import framework_handler as _fh
from ivy.core.compilation import compile_fn
from ivy.core.gradients import execute_with_gradients
from ivy.nest import flatten_nest, map_nest, multi_map_nest, unflatten_nest
from ivy.stateful.module import Module
from ivy.typing import Framework, Nest

__all__ = ["Optimizer", "SGD", "Adam", "AdamW"]


class Optimizer:
    """Base class: a functional update rule with optional stateful conveniences.

    Subclasses name their per-variable slots in ``slots`` and implement
    ``_update(xp, lr, t, params, grads, slots) -> (params, slots)`` on flat lists of arrays.

    Args:
        lr: learning rate: a number, or a schedule ``lr(step)`` of the step count (an array
            starting at 1).
        f: the framework; default: that of the variables (or the global framework).
    """

    slots: tuple[str, ...] = ()

    def __init__(self, lr: float | Callable = 1e-3, *, f: Framework = None) -> None:
        self.lr = lr
        self._f = f
        self.state: dict[str, Any] | None = None
        self._owner: Any = None

    def _xp(self, leaves: list) -> Any:
        if not leaves:
            raise ValueError(f"{type(self).__name__}: the variables nest has no arrays")
        return _fh.get_framework(leaves[0], f=self._f)

    # ------------------------------------------------------------------------------------------
    # Functional form
    # ------------------------------------------------------------------------------------------

    def init(self, v: Nest) -> dict[str, Any]:
        """The initial state for the variables ``v``: a step count of 0 and zeroed slots.

        Args:
            v: nest of arrays (e.g. ``module.v``).

        Returns:
            ``{'step': 0-d array, <slot>: nest like v, ...}``.

        Example:
            >>> model = ivy.MLP(4, (8,), 1, f="torch")
            >>> state = ivy.Adam(1e-3).init(model.v)
            >>> sorted(state)
            ['mu', 'nu', 'step']
        """
        leaves, spec = flatten_nest(v)
        xp = self._xp(leaves)
        first = leaves[0]
        count_dtype = "float64" if xp.dtype(first, as_str=True) == "float64" else "float32"
        state = {"step": xp.zeros((), dtype=count_dtype, device=xp.dev(first))}
        for name in self.slots:
            state[name] = unflatten_nest(spec, [xp.zeros_like(p) for p in leaves])
        return state

    def step(self, v: Nest, grads: Nest, state: dict[str, Any]) -> tuple[Nest, dict[str, Any]]:
        """One update: a pure function of arrays (it compiles with ``ivy.compile_fn``).

        Args:
            v: nest of variables.
            grads: nest of gradients with the structure of ``v``.
            state: the optimizer state, from :meth:`init` or the previous step.

        Returns:
            ``(new_v, new_state)``.

        Example:
            >>> from ivy import execute_with_gradients
            >>> v, opt = {"w": torch.ones(3)}, ivy.Adam(1e-3)
            >>> loss_fn, state = (lambda v: ivy.sum(v["w"] ** 2)), opt.init(v)
            >>> loss, grads = execute_with_gradients(loss_fn, v)
            >>> v, state = opt.step(v, grads, state)
        """
        leaves, spec = flatten_nest(v)
        grad_leaves, _ = flatten_nest(grads)
        if len(grad_leaves) != len(leaves):
            raise ValueError(
                f"{type(self).__name__}.step: grads has {len(grad_leaves)} arrays but v has "
                f"{len(leaves)}; grads must have the structure of v"
            )
        xp = self._xp(leaves)
        t = xp.add(state["step"], 1.0)
        lr = self.lr(t) if callable(self.lr) else self.lr
        slots = {name: flatten_nest(state[name])[0] for name in self.slots}
        new_leaves, new_slots = self._update(xp, lr, t, leaves, grad_leaves, slots)
        new_state = {"step": t}
        for name in self.slots:
            new_state[name] = unflatten_nest(spec, new_slots[name])
        return unflatten_nest(spec, new_leaves), new_state

    def _update(self, xp, lr, t, params, grads, slots):
        raise NotImplementedError

    def training_step(self, loss_fn: Callable, *, compile: bool = False) -> Callable:
        """A pure training step ``step(v, state, *args, **kwargs) -> (loss, v, state)``.

        It computes ``loss_fn(v, *args, **kwargs)`` and its gradients with
        ``ivy.execute_with_gradients``, then applies :meth:`step`.

        Args:
            loss_fn: scalar loss of the variables nest and the batch.
            compile: wrap the step with ``ivy.compile_fn`` (jax.jit, tf.function, torch.compile).

        Returns:
            The step function.

        Example:
            >>> model, x, y = ivy.MLP(4, (8,), 1, f="jax"), jnp.ones((2, 4)), jnp.ones((2, 1))
            >>> opt = ivy.Adam(1e-3)
            >>> step = opt.training_step(lambda v, x, y: ivy.mse(model(x, v=v), y), compile=True)
            >>> v, state = model.v, opt.init(model.v)
            >>> loss, v, state = step(v, state, x, y)
        """

        def step(v, state, *args, **kwargs):
            loss, grads = execute_with_gradients(lambda w: loss_fn(w, *args, **kwargs), v)[:2]
            new_v, new_state = self.step(v, grads, state)
            return loss, new_v, new_state

        return compile_fn(step) if compile else step

    # ------------------------------------------------------------------------------------------
    # Stateful form
    # ------------------------------------------------------------------------------------------

    def update(self, module: Module, grads: Nest) -> None:
        """Apply ``grads`` to ``module.v`` in place, keeping the state in ``self.state``.

        The state is created on the first call, and again whenever another module is passed.

        Example:
            >>> from ivy import execute_with_gradients
            >>> model, x, y = ivy.MLP(4, (8,), 1, f="torch"), torch.ones(2, 4), torch.ones(2, 1)
            >>> opt = ivy.SGD(0.1)
            >>> loss_fn = lambda v: ivy.mse(model(x, v=v), y)
            >>> loss, grads = execute_with_gradients(loss_fn, model.v)
            >>> opt.update(model, grads)
        """
        v = module.v
        if self.state is None or self._owner is not module:
            self.state = self.init(v)
            self._owner = module
        module.v, self.state = self.step(v, grads, self.state)

    def minimize(self, module: Module, loss_fn: Callable) -> Any:
        """Compute ``loss_fn(module.v)`` and its gradients, and update ``module.v`` in place.

        Args:
            module: the module to train.
            loss_fn: function of a variables nest returning a scalar loss, or ``(loss, *aux)``.

        Returns:
            The loss before the update (``(loss, *aux)`` when ``loss_fn`` returns aux values).

        Example:
            >>> model, x, y = ivy.MLP(4, (8,), 1, f="torch"), torch.ones(2, 4), torch.ones(2, 1)
            >>> opt = ivy.Adam(1e-3)
            >>> loss = opt.minimize(model, lambda v: ivy.mse(model(x, v=v), y))
        """
        loss, grads, *aux = execute_with_gradients(loss_fn, module.v)
        self.update(module, grads)
        return (loss, *aux) if aux else loss

    def module_step(self, module: Module, loss_fn: Callable, *, compile: bool = False) -> Callable:
        """A training step bound to ``module``: ``train(*args, **kwargs) -> loss``.

        Each call computes ``loss_fn(module.v, *args, **kwargs)`` and its gradients, and updates
        ``module.v`` and ``self.state`` in place (the state is created on the first call, or
        when another module was trained in between). With ``compile=True`` the whole step is
        compiled with ``ivy.compile_fn``.

        On tensorflow the compiled step keeps the variables and the state in ``tf.Variable``
        objects (``ivy.variable``) that the graph reads and assigns, as Keras does: passing each
        array in and out of a ``tf.function`` on every call would cost more than the update.
        ``module.v`` then holds those variables, which every ivy function accepts.

        Args:
            module: the module to train.
            loss_fn: scalar loss of a variables nest and the batch.
            compile: compile the step.

        Returns:
            The step function.

        Example:
            >>> model, opt = ivy.MLP(4, (8,), 1, f="jax"), ivy.Adam(1e-3)
            >>> batches = [(jnp.ones((2, 4)), jnp.ones((2, 1)))] * 3
            >>> train = opt.module_step(model, lambda v, x, y: ivy.mse(model(x, v=v), y),
            ...                         compile=True)
            >>> for x, y in batches:
            ...     loss = train(x, y)
        """
        return _ModuleStep(self, module, loss_fn, compile)

    def __repr__(self) -> str:
        args = ", ".join(f"{k}={v!r}" for k, v in self._hyperparameters().items())
        return f"{type(self).__name__}({args})"

    def _hyperparameters(self) -> dict[str, Any]:
        return {"lr": self.lr}


# Frameworks whose compiled functions assign variables in place (``.assign``) for less than it
# costs to pass the arrays in and out of every call.
_ASSIGN_IN_PLACE = frozenset({"tensorflow"})


class _ModuleStep:
    """``Optimizer.module_step``: a training step that updates a module and an optimizer."""

    def __init__(self, optimizer: Optimizer, module: Any, loss_fn: Callable, compile: bool):
        self._opt = optimizer
        self._module = module
        self._pure = optimizer.training_step(loss_fn)
        self._in_place = compile and module.f.backend in _ASSIGN_IN_PLACE
        if self._in_place:
            self._v_vars = self._state_vars = None
            self._run = compile_fn(self._assigning_step, f=module.f)
        else:
            self._run = compile_fn(self._pure, f=module.f) if compile else self._pure

    def _state_for(self, v: Any) -> Any:
        opt = self._opt
        if opt.state is None or opt._owner is not self._module:
            opt.state = opt.init(v)
            opt._owner = self._module
        return opt.state

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        if self._in_place:
            self._bind_variables()
            return self._run(*args, **kwargs)
        module = self._module
        v = module.v
        loss, module.v, self._opt.state = self._run(v, self._state_for(v), *args, **kwargs)
        return loss

    # tensorflow: variables read and assigned inside the compiled function -------------------

    def _assigning_step(self, *args, **kwargs):
        read = lambda var: var.read_value()  # noqa: E731
        v = map_nest(read, self._v_vars)
        state = map_nest(read, self._state_vars)
        loss, v, state = self._pure(v, state, *args, **kwargs)
        multi_map_nest(lambda var, value: var.assign(value), self._v_vars, v)
        multi_map_nest(lambda var, value: var.assign(value), self._state_vars, state)
        return loss

    def _bind_variables(self) -> None:
        """Make ``module.v`` and the optimizer's state this step's variables (again, when they
        were replaced since the last call, e.g. by an eager update)."""
        module, opt = self._module, self._opt
        v = module.v
        leaves = flatten_nest(v)[0]
        if self._v_vars is not None and all(
            a is b for a, b in zip(leaves, flatten_nest(self._v_vars)[0])
        ):
            if opt.state is self._state_vars and opt._owner is module:
                return
        state = self._state_for(v)
        xp = module.f
        if self._v_vars is None:
            self._v_vars = map_nest(xp.variable, v)
            self._state_vars = map_nest(xp.variable, state)
        else:
            multi_map_nest(lambda var, value: var.assign(value), self._v_vars, v)
            multi_map_nest(lambda var, value: var.assign(value), self._state_vars, state)
        module.v = self._v_vars
        opt.state = self._state_vars


def _scalar_cast(xp, value, like):
    """``value`` (a 0-d array or Python number) in the dtype of ``like`` when it differs."""
    if isinstance(value, (int, float)) or value.dtype == like.dtype:
        return value
    return xp.astype(value, like.dtype)


class SGD(Optimizer):
    """Stochastic gradient descent with optional momentum, Nesterov and L2 weight decay.

    ``g += weight_decay * p``; ``buf = momentum * buf + g``; ``p -= lr * (g + momentum * buf if
    nesterov else buf)`` (torch's rule, with no dampening).

    Args:
        lr: learning rate (number or schedule of the step count).
        momentum: momentum factor (0: plain SGD, no slot).
        nesterov: use Nesterov momentum.
        weight_decay: L2 penalty coefficient added to the gradients.
        f: the framework (default: that of the variables).

    Example:
        >>> opt = ivy.SGD(0.1, momentum=0.9)
        >>> v = {"w": torch.ones(3)}
        >>> loss, grads = ivy.execute_with_gradients(lambda v: ivy.sum(v["w"] ** 2), v)
        >>> v, state = opt.step(v, grads, opt.init(v))
    """

    def __init__(
        self,
        lr: float | Callable = 1e-2,
        *,
        momentum: float = 0.0,
        nesterov: bool = False,
        weight_decay: float = 0.0,
        f: Framework = None,
    ) -> None:
        super().__init__(lr, f=f)
        if nesterov and momentum <= 0:
            raise ValueError("SGD: nesterov=True needs momentum > 0")
        self.momentum = momentum
        self.nesterov = nesterov
        self.weight_decay = weight_decay
        self.slots = ("momentum",) if momentum else ()

    def _hyperparameters(self):
        return {
            "lr": self.lr,
            "momentum": self.momentum,
            "nesterov": self.nesterov,
            "weight_decay": self.weight_decay,
        }

    def _update(self, xp, lr, t, params, grads, slots):
        mom, wd = self.momentum, self.weight_decay
        bufs = slots.get("momentum")
        new_params, new_bufs = [], []
        for i, (p, g) in enumerate(zip(params, grads)):
            if wd:
                g = xp.add(g, xp.multiply(p, wd))
            if mom:
                buf = xp.add(xp.multiply(bufs[i], mom), g)
                new_bufs.append(buf)
                g = xp.add(g, xp.multiply(buf, mom)) if self.nesterov else buf
            new_params.append(xp.subtract(p, xp.multiply(g, _scalar_cast(xp, lr, p))))
        return new_params, ({"momentum": new_bufs} if mom else {})


class Adam(Optimizer):
    """Adam (Kingma and Ba), with optional L2 weight decay added to the gradients.

    ``m = b1 m + (1 - b1) g``; ``n = b2 n + (1 - b2) g^2``;
    ``p -= lr / (1 - b1^t) * m / (sqrt(n / (1 - b2^t)) + eps)``.

    Args:
        lr: learning rate (number or schedule of the step count).
        beta1, beta2: decay rates of the first and second moment estimates.
        eps: added to the denominator.
        weight_decay: L2 penalty coefficient added to the gradients (see :class:`AdamW` for
            decoupled decay).
        f: the framework (default: that of the variables).

    Example:
        >>> opt = ivy.Adam(1e-3)
        >>> model, x, y = ivy.MLP(4, (8,), 1, f="torch"), torch.ones(2, 4), torch.ones(2, 1)
        >>> loss, grads = ivy.execute_with_gradients(lambda v: ivy.mse(model(x, v=v), y), model.v)
        >>> state = opt.init(model.v)
        >>> v, state = opt.step(model.v, grads, state)
    """

    slots = ("mu", "nu")
    _decoupled = False

    def __init__(
        self,
        lr: float | Callable = 1e-3,
        *,
        beta1: float = 0.9,
        beta2: float = 0.999,
        eps: float = 1e-8,
        weight_decay: float = 0.0,
        f: Framework = None,
    ) -> None:
        super().__init__(lr, f=f)
        if not (0.0 <= beta1 < 1.0 and 0.0 <= beta2 < 1.0):
            raise ValueError(f"betas must be in [0, 1), got beta1={beta1}, beta2={beta2}")
        self.beta1 = beta1
        self.beta2 = beta2
        self.eps = eps
        self.weight_decay = weight_decay

    def _hyperparameters(self):
        return {
            "lr": self.lr,
            "beta1": self.beta1,
            "beta2": self.beta2,
            "eps": self.eps,
            "weight_decay": self.weight_decay,
        }

    def _update(self, xp, lr, t, params, grads, slots):
        b1, b2, eps, wd = self.beta1, self.beta2, self.eps, self.weight_decay
        # Per step, as 0-d arrays of the count's dtype: the bias corrections 1 - b^t folded into
        # p -= lr / bc1 * m / (sqrt(n) / sqrt(bc2) + eps)
        #    = (lr * sqrt(bc2) / bc1) * m / (sqrt(n) + eps * sqrt(bc2)),
        # which leaves 12 elementwise operations per variable.
        bc1 = xp.negative(xp.expm1(xp.multiply(t, math.log(b1)))) if b1 else xp.ones_like(t)
        bc2 = xp.negative(xp.expm1(xp.multiply(t, math.log(b2)))) if b2 else xp.ones_like(t)
        sqrt_bc2 = xp.sqrt(bc2)
        step_size = xp.divide(xp.multiply(sqrt_bc2, lr), bc1)
        eps_hat = xp.multiply(sqrt_bc2, eps)
        decay = None
        if wd and self._decoupled:
            plain = isinstance(lr, (int, float))
            decay = 1.0 - lr * wd if plain else xp.subtract(1.0, xp.multiply(lr, wd))
        new_p, new_m, new_n = [], [], []
        for p, g, m, n in zip(params, grads, slots["mu"], slots["nu"]):
            if wd and not self._decoupled:
                g = xp.add(g, xp.multiply(p, wd))
            m = xp.add(xp.multiply(m, b1), xp.multiply(g, 1.0 - b1))
            n = xp.add(xp.multiply(n, b2), xp.multiply(xp.square(g), 1.0 - b2))
            if decay is not None:
                p = xp.multiply(p, _scalar_cast(xp, decay, p))
            denom = xp.add(xp.sqrt(n), _scalar_cast(xp, eps_hat, p))
            update = xp.multiply(xp.divide(m, denom), _scalar_cast(xp, step_size, p))
            new_p.append(xp.subtract(p, update))
            new_m.append(m)
            new_n.append(n)
        return new_p, {"mu": new_m, "nu": new_n}


class AdamW(Adam):
    """Adam with decoupled weight decay (Loshchilov and Hutter): before the Adam update,
    ``p *= 1 - lr * weight_decay``.

    Args:
        lr, beta1, beta2, eps: as for :class:`Adam`.
        weight_decay: decoupled decay coefficient (torch's default 0.01).
        f: the framework (default: that of the variables).

    Example:
        >>> opt = ivy.AdamW(1e-3, weight_decay=0.01)
        >>> model, x, y = ivy.MLP(4, (8,), 1, f="torch"), torch.ones(2, 4), torch.ones(2, 1)
        >>> loss = opt.minimize(model, lambda v: ivy.mse(model(x, v=v), y))
    """

    _decoupled = True

    def __init__(
        self,
        lr: float | Callable = 1e-3,
        *,
        beta1: float = 0.9,
        beta2: float = 0.999,
        eps: float = 1e-8,
        weight_decay: float = 1e-2,
        f: Framework = None,
    ) -> None:
        super().__init__(lr, beta1=beta1, beta2=beta2, eps=eps, weight_decay=weight_decay, f=f)
