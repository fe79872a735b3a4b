"""The pure, batched core that every environment shares, and its contract.

An environment is a set of physical parameters (a frozen dataclass in ``env.params``) and pure
array functions written once for every backend. Users call the checked functions:

- ``state = env.reset(batch_shape, dtype=..., device=..., f=...)``: a batch of initial states,
  drawn with ivy's random functions (``ivy.seed`` reproduces them, and compiled code draws fresh
  ones at every call), on ``device``;
- ``state, obs, reward, terminated = env.step(state, action)``: one step of the dynamics, pure,
  differentiable and compilable, for any leading batch shape;
- ``obs = env.observe(state)``.

They check their inputs (shapes, one framework: arrays of two frameworks raise ivy's
``MixedFrameworksError``), resolve the backend namespace ``xp`` once and call the kernels.

**The contract** (what an environment defines, and what rollouts, optimisers and facades call;
everything here is public and stable):

- ``Params`` (a frozen dataclass), ``state_names``, ``observation_names``, ``can_terminate``,
  ``max_episode_steps``, ``render_fps``; ``state_dim``, ``observation_dim``, ``action_dim``.
- ``discrete_actions``: None, or the core actions (a tuple of ``action_dim``-tuples) that a
  Gymnasium facade's discrete actions ``0, 1, ...`` stand for (Acrobot's torques -1, 0, 1).
- ``reset_bounds()``, ``action_bounds()``, ``observation_bounds()``: numpy float64 boxes
  ``(low, high)``; ``initial_bounds()`` is the reset box after :meth:`Env.narrowed`.
- ``kernel_step(xp, state, action) -> (state, obs, reward, terminated)`` and
  ``kernel_observe(xp, state) -> obs``: the physics, written against a backend namespace ``xp``
  (``ivy.torch``...), with ``self.params``. No checks, no dispatch, no host transfer: they run
  inside compiled loops. ``state`` is ``(*B, state_dim)``; ``action`` is ``(*B', action_dim)``
  with ``B'`` broadcasting against ``B``, a floating array of ``xp`` whose dtype may differ
  from the state's (Gymnasium's float32 actions on a float64 state): a kernel casts it with
  :func:`cast_like` first, unless it follows Gymnasium's mixed-precision arithmetic. Outputs
  follow the state's device and dtype; ``reward`` and ``terminated`` (bool) are ``(*B,)``.
- ``kernel_initial(xp, state) -> state``: maps a draw from the reset box to an initial state
  (identity unless a task overrides it); :meth:`Env.reset` and the facades both apply it.
- ``kernel_step_info(xp, state, action) -> (state, obs, reward, terminated, info)`` and
  ``kernel_reset_info(xp, state) -> info``: Gymnasium's ``info`` of a step and of a reset as a
  dict of arrays (empty by default); ``reward_type`` and ``info_types`` give the Python or
  numpy types that Gymnasium's own task returns, which the facades convert to.
- ``gymnasium_dtype``, ``gymnasium_action_dtype``, ``gymnasium_observation_dtype``: the
  facades' default dtypes, Gymnasium's: the state's (what Gymnasium computes in), the action
  space's and the observations' (None: the state's). The MuJoCo tasks: float64 states and
  observations, float32 actions; Gymnasium's classic-control tasks: float64 states observed
  in float32.
- ``action_box(xp, dtype=..., device=...) -> (low, high)``: the action space as arrays that
  every compiler traces as constants; ``squash(xp, logits)``: unbounded logits to actions in
  the box, ``mid + half_width * tanh(logits)``.

Helpers for kernels: :func:`cast_like`, :func:`scalar_action`, :func:`unstack_last`; for code
that takes states and actions from users: :func:`check_state`, :func:`check_action`.

Example:
    >>> env = ivy_gym.Pendulum()
    >>> state = env.reset((64,), f="torch")
    >>> state, obs, reward, terminated = env.step(state, torch.zeros(64, 1))
    >>> state, obs, reward, terminated = env.kernel_step(ivy.torch, state, torch.zeros(64, 1))
"""

from __future__ import annotations

import copy
import dataclasses
import operator
from collections.abc import Sequence
from typing import Any, ClassVar

import numpy as np

import ivy
import ivy.checks
from ivy.typing import Array, Dtype, Framework, Shape

__all__ = ["Env", "cast_like", "scalar_action", "unstack_last", "check_state", "check_action"]


class Env:
    """Base class of the environments: parameters, spaces, the kernels and the checked calls.

    Subclasses define ``Params`` (a frozen dataclass), ``state_names``, ``observation_names``,
    :meth:`reset_bounds`, :meth:`action_bounds`, :meth:`kernel_step` and
    :meth:`kernel_observe` (see the module's docstring for the contract), and for rendering
    ``_view`` and ``_draw``.

    Args:
        **params: values of the fields of ``Params`` that differ from the defaults.
    """

    Params: ClassVar[type]
    #: Names of the components of the state's last axis.
    state_names: ClassVar[tuple[str, ...]] = ()
    #: Names of the components of the observation's last axis.
    observation_names: ClassVar[tuple[str, ...]] = ()
    #: Whether ``step`` can report a termination (tasks without one always return False).
    can_terminate: ClassVar[bool] = False
    #: The time limit of the registered Gymnasium task.
    max_episode_steps: ClassVar[int] = 200
    #: Frames per second of renderings.
    render_fps: ClassVar[int] = 30
    #: The core actions of a facade's discrete actions (None: CartPole's push left, right).
    discrete_actions: ClassVar[tuple[tuple[float, ...], ...] | None] = None
    #: The Gymnasium facades' default dtype of the core and the observations, and of the
    #: action space (None: the same).
    gymnasium_dtype: ClassVar[str] = "float32"
    gymnasium_action_dtype: ClassVar[str | None] = None
    gymnasium_observation_dtype: ClassVar[str | None] = None
    #: The type of the reward in the Gymnasium facades (Gymnasium's own task's type).
    reward_type: ClassVar[Any] = float
    #: The types of the values of ``info`` in the Gymnasium facades where they are not
    #: ``np.float64`` (vectors: float64 arrays): ``float``, ``int``, ``np.float64``, or
    #: ``"action"`` (a numpy scalar of the action's dtype).
    info_types: ClassVar[dict[str, Any]] = {}

    def __init__(self, **params: Any) -> None:
        self.params = self.Params(**params)
        #: The reset box's scale about its centre (1: the task's; see :meth:`narrowed`).
        self.reset_scale = 1.0
        self._update_constants()

    def _update_constants(self) -> None:
        """The boxes as numpy float64 arrays, made once (``xp.constant`` brings them into
        kernels, compiled ones included), and the parameters that are arrays."""
        low, high = self.initial_bounds()
        action_low, action_high = self.action_bounds()
        boxes = {
            "reset_low": low,
            "reset_width": high - low,
            "action_low": action_low,
            "action_high": action_high,
            "action_mid": (action_high + action_low) / 2,
            "action_half": (action_high - action_low) / 2,
        }
        self._constants = {k: np.array(v, dtype=np.float64) for k, v in boxes.items()}
        self._array_params = ()

    # ------------------------------------------------------------------------------------------
    # Description
    # ------------------------------------------------------------------------------------------

    @property
    def state_dim(self) -> int:
        """Size of the state's last axis."""
        return len(self.state_names)

    @property
    def observation_dim(self) -> int:
        """Size of the observation's last axis."""
        return len(self.observation_names)

    @property
    def action_dim(self) -> int:
        """Size of the action's last axis."""
        return len(self.action_bounds()[0])

    @property
    def param_arrays(self) -> tuple:
        """The parameters that are arrays (``env.replace(g=g_array)``), empty for numbers: code
        that takes arrays from users checks that they are of one framework with these."""
        return self._array_params

    def reset_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """``(low, high)``: the initial state is uniform in this box (float64, ``(state_dim,)``);
        components with ``low == high`` are that constant."""
        raise NotImplementedError

    def initial_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """``(low, high)`` of the box that :meth:`reset` draws from: :meth:`reset_bounds`,
        shrunk by ``reset_scale`` about its centre (see :meth:`narrowed`)."""
        low, high = self.reset_bounds()
        if self.reset_scale == 1.0:
            return low, high
        centre, half = (high + low) / 2, (high - low) / 2 * self.reset_scale
        return centre - half, centre + half

    def draw_initial(self, rng: np.random.Generator, batch_shape: Shape | int = ()) -> np.ndarray:
        """Initial draws on the host with numpy's generator, as Gymnasium's own environment draws
        them: what the Gymnasium facades' seeded ``reset`` gives to :meth:`kernel_initial`.

        The default draws the random components of :meth:`initial_bounds` with one
        ``rng.random`` call, ``low + width * u``: the values of Gymnasium's
        ``uniform(low, high)``. Tasks whose Gymnasium reset draws otherwise (normal velocities,
        a goal by rejection) override this, and only this.

        Args:
            rng: the generator (the facade's ``np_random``).
            batch_shape: leading shape of the batch, ``()`` for one state.

        Returns:
            float64 ``(*batch_shape, state_dim)``.
        """
        batch = _shape(batch_shape)
        low, high = self.initial_bounds()
        random = low != high
        values = low[random] + (high - low)[random] * rng.random((*batch, int(random.sum())))
        if random.all():
            return values
        states = np.empty((*batch, low.size))
        states[...] = low
        states[..., random] = values
        return states

    def narrowed(self, scale: float) -> Env:
        """A copy whose initial states come from the reset box shrunk by ``scale`` (in (0, 1])
        about its centre: a curriculum of easier starts (for the swing-up tasks, whose boxes
        are centred on upright, near-upright starts). Everything else is unchanged.

        Example:
            >>> ivy_gym.PendulumSmooth().narrowed(0.1).initial_bounds()
            (array([-0.31415927, -0.1       ]), array([0.31415927, 0.1       ]))
        """
        if not 0.0 < float(scale) <= 1.0:
            raise ValueError(f"narrowed: scale must be in (0, 1], got {scale!r}.")
        new = copy.copy(self)
        new.reset_scale = float(scale)
        array_params = self._array_params
        new._update_constants()
        new._array_params = array_params
        return new

    def action_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """``(low, high)`` of the action space (float64, ``(action_dim,)``)."""
        raise NotImplementedError

    def observation_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """``(low, high)`` of the observation space (float64, ``(observation_dim,)``)."""
        inf = np.full(self.observation_dim, np.inf)
        return -inf, inf

    def replace(self, **changes: Any) -> Env:
        """A copy of this environment with some parameters changed (Python numbers or arrays).

        Example:
            >>> heavy = ivy_gym.Pendulum().replace(m=2.0)
            >>> heavy.params.m
            2.0
        """
        new = copy.copy(self)
        new.params = dataclasses.replace(self.params, **changes)
        values = [getattr(new.params, field.name) for field in dataclasses.fields(new.params)]
        arrays = tuple(v for v in values if not _is_number(v))
        if not arrays:
            new._update_constants()
        # array parameters (for gradients) keep the boxes of the numbers they replace
        new._array_params = arrays
        return new

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.params})"

    # ------------------------------------------------------------------------------------------
    # Constants for the kernels
    # ------------------------------------------------------------------------------------------

    def action_box(
        self, xp, *, dtype: Dtype = "float32", device: str | None = None
    ) -> tuple[Array, Array]:
        """``(low, high)`` of the action space as arrays of ``xp`` ``(action_dim,)``: constants
        (``xp.constant``) that every compiler traces, torch.compile included.

        Args:
            xp: the backend namespace (``ivy.torch``...).
            dtype: their dtype.
            device: their device (None: the backend's default).

        Example:
            >>> low, high = ivy_gym.Pendulum().action_box(ivy.numpy, dtype="float64")
            >>> high
            array([2.])
        """
        c = self._constants
        low = xp.constant(c["action_low"], dtype=dtype, device=device)
        return low, xp.constant(c["action_high"], dtype=dtype, device=device)

    def squash(self, xp, logits: Array) -> Array:
        """Actions in the action box from unbounded logits: ``mid + half_width *
        tanh(logits)``, of the logits' dtype and device (a kernel: no checks).

        Example:
            >>> ivy_gym.Pendulum().squash(ivy.numpy, np.zeros((3, 1)))
            array([[0.], [0.], [0.]])
        """
        dtype, device = logits.dtype, xp.dev(logits)
        mid = xp.constant(self._constants["action_mid"], dtype=dtype, device=device)
        half = xp.constant(self._constants["action_half"], dtype=dtype, device=device)
        return mid + half * xp.tanh(logits)

    # ------------------------------------------------------------------------------------------
    # The kernels (see the module's docstring)
    # ------------------------------------------------------------------------------------------

    def kernel_step(self, xp, state: Array, action: Array) -> tuple[Array, Array, Array, Array]:
        """One step of the physics: ``(state, observation, reward, terminated)`` (no checks)."""
        raise NotImplementedError

    def kernel_observe(self, xp, state: Array) -> Array:
        """The observation of ``state`` (no checks)."""
        raise NotImplementedError

    def kernel_initial(self, xp, state: Array) -> Array:
        """The initial state from a draw of the reset box (identity; no checks)."""
        return state

    def kernel_step_info(self, xp, state: Array, action: Array) -> tuple:
        """One step with Gymnasium's ``info``: ``(state, observation, reward, terminated,
        info)``, ``info`` a dict of arrays ``(*B,)`` or ``(*B, k)`` (empty unless the task has
        one; no checks)."""
        return (*self.kernel_step(xp, state, action), {})

    def kernel_reset_info(self, xp, state: Array) -> dict:
        """Gymnasium's ``info`` of a reset to ``state`` (a dict of arrays; empty unless the task
        has one; no checks)."""
        return {}

    # ------------------------------------------------------------------------------------------
    # The checked calls
    # ------------------------------------------------------------------------------------------

    def reset(
        self,
        batch_shape: Shape | int = (),
        *,
        dtype: Dtype = "float32",
        device: str | None = None,
        f: Framework = None,
    ) -> Array:
        """A batch of initial states drawn with ivy's random functions.

        Args:
            batch_shape: leading shape of the batch, ``()`` for one state.
            dtype: floating dtype of the state.
            device: where to create it (``'cpu'``, ``'gpu:0'``; None: the backend's default).
            f: framework name or namespace; by default the global framework.

        Returns:
            An array ``(*batch_shape, state_dim)``.

        Example:
            >>> ivy.seed(0)
            >>> ivy_gym.CartPole().reset((64,), f="jax").shape
            (64, 4)
        """
        xp = ivy.get_framework(f=f)
        ivy.checks.check_floating_dtype(dtype, f"{type(self).__name__}.reset's dtype")
        batch_shape = _shape(batch_shape)
        low = xp.constant(self._constants["reset_low"], dtype=dtype, device=device)
        width = xp.constant(self._constants["reset_width"], dtype=dtype, device=device)
        u = xp.random_uniform(shape=(*batch_shape, self.state_dim), dtype=dtype, device=device)
        return self.kernel_initial(xp, low + width * u)

    def step(self, state: Array, action: Array, *, f: Framework = None) -> tuple:
        """One step of the dynamics for a batch of states.

        Args:
            state: ``(*batch, state_dim)``.
            action: ``(*batch, action_dim)`` (its batch broadcast against the state's), of the
                state's framework; a float32 or float64 action keeps its dtype (Gymnasium's
                tasks compute with it as Gymnasium does), other values are converted to the
                state's dtype.
            f: framework name or namespace; by default inferred from ``state`` and ``action``
                (arrays of two frameworks raise ``ivy.errors.MixedFrameworksError``); when
                given, the state and action are converted to it.

        Returns:
            ``(state, observation, reward, terminated)``: the next state ``(*batch,
            state_dim)``, its observation ``(*batch, observation_dim)``, the reward
            ``(*batch,)`` and whether the episode terminated ``(*batch,)`` (bool).

        Example:
            >>> env = ivy_gym.CartPoleSwingUp()
            >>> s = env.reset((8,), f="numpy")
            >>> s, obs, r, done = env.step(s, np.zeros((8, 1), np.float32))
        """
        xp = ivy.get_framework(state, action, self.param_arrays, f=f)
        name = f"{type(self).__name__}.step"
        check_state(self, state, name)
        if f is not None:  # the chosen framework: convert, as the core's functions do
            state = xp.asarray(state)
        action = check_action(self, xp, action, state, name)
        return self.kernel_step(xp, state, action)

    def observe(self, state: Array, *, f: Framework = None) -> Array:
        """The observation of ``state`` (``(*batch, observation_dim)``).

        Example:
            >>> ivy_gym.Pendulum().observe(np.zeros((2, 2))).shape
            (2, 3)
        """
        xp = ivy.get_framework(state, self.param_arrays, f=f)
        check_state(self, state, f"{type(self).__name__}.observe")
        if f is not None:
            state = xp.asarray(state)
        return self.kernel_observe(xp, state)

    # ------------------------------------------------------------------------------------------
    # Rendering (numpy, no display)
    # ------------------------------------------------------------------------------------------

    def render(self, state: Array, *, width: int = 400, height: int = 400) -> np.ndarray:
        """An RGB picture of one state, drawn with numpy (no display needed).

        Args:
            state: ``(state_dim,)``, of any backend.
            width, height: size of the picture in pixels.

        Returns:
            ``(height, width, 3)`` uint8.

        Example:
            >>> frame = ivy_gym.Pendulum().render(np.zeros(2))
        """
        from ivy_gym.rendering import Canvas

        s = np.asarray(ivy.to_numpy(state), dtype=np.float64)
        if s.shape != (self.state_dim,):
            raise ValueError(
                f"{type(self).__name__}.render draws one state of shape ({self.state_dim},); "
                f"got shape {s.shape}. Index the batch first, e.g. state[0]."
            )
        canvas = Canvas(width, height, self._view(s))
        self._draw(canvas, s)
        return canvas.image

    def _view(self, s: np.ndarray) -> tuple[float, float, float, float]:
        """World box ``(x_min, x_max, y_min, y_max)`` that the picture shows."""
        raise NotImplementedError

    def _draw(self, canvas, s: np.ndarray) -> None:
        raise NotImplementedError


def _is_number(value) -> bool:
    return isinstance(value, (int, float, bool))


def _shape(batch_shape: Shape | int) -> tuple[int, ...]:
    if isinstance(batch_shape, Sequence):
        return tuple(operator.index(n) for n in batch_shape)
    return (operator.index(batch_shape),)


# ----------------------------------------------------------------------------------------------
# Checks of user input (outside the kernels)
# ----------------------------------------------------------------------------------------------


def check_state(env: Env, state: Any, caller: str, *, argument: str = "state") -> None:
    """Raise a ``ValueError`` naming ``argument``, the expected shape and the fix unless
    ``state`` is an array ``(*batch, env.state_dim)``."""
    shape = getattr(state, "shape", None)
    if shape is None:
        raise TypeError(
            f"{caller}: {argument} must be an array (*batch, {env.state_dim}) of "
            f"{list(env.state_names)}; got {type(state).__name__}. Create it with "
            f"env.reset(batch_shape, f=...) or an array of your framework."
        )
    shape = tuple(shape)
    if len(shape) == 0 or shape[-1] != env.state_dim:
        raise ValueError(
            f"{caller}: {argument} must have shape (*batch, {env.state_dim}), its last axis "
            f"{list(env.state_names)}; got shape {shape}. A {type(env).__name__} state has "
            f"{env.state_dim} components (env.state_names)."
        )


def check_action(
    env: Env,
    xp,
    action: Any,
    state: Array,
    caller: str,
    *,
    argument: str = "action",
    time_axis: bool = False,
) -> Array:
    """``action`` as an array of ``xp`` ``(*batch, action_dim)`` whose batch broadcasts against
    the state's (``(T, *batch, action_dim)`` with ``time_axis``): a floating array keeps its
    dtype, anything else becomes the state's dtype on the state's device. Raises a
    ``ValueError`` that names ``argument``, the expected shape and the fix otherwise."""
    if isinstance(action, (int, float, list, tuple)):
        action = xp.asarray(action, dtype=state.dtype, device=xp.dev(state))
    elif type(action) is not type(state):  # another array type of xp (a tracer), or f= given
        action = xp.asarray(action, device=xp.dev(state))
    if not xp.isdtype(action.dtype, "real floating"):
        action = xp.astype(action, state.dtype)
    batch = tuple(state.shape[:-1])
    shape = tuple(action.shape)
    lead, time = ("T, ", ("T",)) if time_axis else ("", ())
    expected = (*time, *batch, env.action_dim)
    expected = "(" + ", ".join(map(str, expected)) + ")"
    if len(shape) < 1 + time_axis or shape[-1] != env.action_dim:
        hint = ""
        if env.action_dim == 1 and shape and shape[time_axis:] == batch:
            hint = f" Add the last axis: {argument}[..., None]."
        raise ValueError(
            f"{caller}: {argument} must have shape ({lead}*batch, {env.action_dim}), e.g. "
            f"{expected} for the state's batch {batch}; got shape {shape}.{hint}"
        )
    try:
        np.broadcast_shapes(batch, shape[time_axis:-1])
    except ValueError:
        raise ValueError(
            f"{caller}: the batch {shape[time_axis:-1]} of {argument} does not broadcast "
            f"against the state's batch {batch}; give {argument} the shape {expected}."
        ) from None
    return action


# ----------------------------------------------------------------------------------------------
# Helpers for kernels
# ----------------------------------------------------------------------------------------------


def cast_like(xp, x: Array, like: Array) -> Array:
    """``x`` in ``like``'s dtype (itself when it already is): a kernel's first line for actions,
    whose dtype may differ from the state's."""
    return x if x.dtype == like.dtype else xp.astype(x, like.dtype)


def scalar_action(xp, action: Array) -> Array:
    """The action of a task with one action component, without its last axis."""
    return xp.squeeze(action, axis=-1)


def unstack_last(xp, x: Array) -> tuple:
    """The components of the last axis of ``x`` (one ``unstack``: slicing component by component
    costs ~40 us a slice on eager jax and ~100 us on eager tensorflow)."""
    return xp.unstack(x, axis=-1)
