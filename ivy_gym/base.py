"""The pure, batched core that every environment shares.

An environment is a set of physical parameters (a frozen dataclass in ``env.params``) and two
array functions written once for every backend:

- ``state = env.reset(batch_shape, f=...)``: a batch of initial states, drawn with ivy's random
  functions (``ivy.seed`` reproduces them, and compiled code draws fresh ones at every call);
- ``state, obs, reward, terminated = env.step(state, action)``: one step of the dynamics, pure,
  differentiable and compilable, for any leading batch shape.

A state is one array ``(*batch, state_dim)`` whose components are named in
``env.state_names``; the faithful Gymnasium tasks use Gymnasium's layout. Actions are arrays
``(*batch, action_dim)``; the core clips them only where Gymnasium clips. Parameters may be Python
numbers or arrays (``env.replace(g=g_array)``), so gradients flow to them too.

Example:
    >>> env = ivy_gym.Pendulum()
    >>> state = env.reset((64,), f="torch")
    >>> state, obs, reward, terminated = env.step(state, torch.zeros(64, 1))
"""

from __future__ import annotations

import copy
import dataclasses
import operator
from collections.abc import Sequence
from typing import Any, ClassVar

import numpy as np

import ivy
from ivy.typing import Array, Dtype, Framework, Shape

__all__ = ["Env"]


class Env:
    """Base class of the environments: parameters, spaces and the pure step.

    Subclasses define ``Params`` (a frozen dataclass), ``state_names``, the bounds of the reset
    distribution, of the actions and of the observations, and the kernels ``_step(xp, p, state,
    action)`` and ``_observe(xp, p, state)``, written against a backend namespace ``xp``.

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

    def __init__(self, **params: Any) -> None:
        self.params = self.Params(**params)
        #: The reset box's scale about its centre (1: the task's; see :meth:`narrowed`).
        self.reset_scale = 1.0
        self._boxes = self._python_boxes()

    def _python_boxes(self) -> dict[str, tuple[float, ...]]:
        """The reset and action boxes as tuples of Python floats, made once, outside any trace:
        constants that every compiler takes as they are (numpy arrays inside a function that
        torch.compile traces become traced tensors)."""
        low, high = self.initial_bounds()
        action_low, action_high = self.action_bounds()
        return {
            "reset_low": tuple(float(v) for v in low),
            "reset_width": tuple(float(v) for v in high - low),
            "action_low": tuple(float(v) for v in action_low),
            "action_mid": tuple(float(v) for v in (action_high + action_low) / 2),
            "action_half": tuple(float(v) for v in (action_high - action_low) / 2),
            "action_width": tuple(float(v) for v in action_high - action_low),
        }

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

    def narrowed(self, scale: float) -> Env:
        """A copy whose initial states come from the reset box shrunk by ``scale`` (in (0, 1])
        about its centre: a curriculum of easier starts (for the swing-up tasks, whose boxes
        are centred on upright, near-upright starts). Everything else is unchanged.

        Example:
            >>> ivy_gym.PendulumSmooth().narrowed(0.1).initial_bounds()
            (array([-0.31415927, -0.1]), array([0.31415927, 0.1]))
        """
        if not 0.0 < float(scale) <= 1.0:
            raise ValueError(f"narrowed: scale must be in (0, 1], got {scale!r}.")
        new = copy.copy(self)
        new.reset_scale = float(scale)
        new._boxes = new._python_boxes()
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
        if not all(_is_number(v) for v in values):
            return new  # array parameters (for gradients) keep the boxes of the numbers
        new._boxes = new._python_boxes()
        return new

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.params})"

    # ------------------------------------------------------------------------------------------
    # The pure functions
    # ------------------------------------------------------------------------------------------

    def reset(
        self, batch_shape: Shape | int = (), *, dtype: Dtype = "float32", f: Framework = None
    ) -> Array:
        """A batch of initial states drawn with ivy's random functions.

        Args:
            batch_shape: leading shape of the batch, ``()`` for one state.
            dtype: floating dtype of the state.
            f: framework name or namespace; by default the global framework.

        Returns:
            An array ``(*batch_shape, state_dim)``.

        Example:
            >>> ivy.seed(0)
            >>> ivy_gym.CartPole().reset((64,), f="jax").shape
            (64, 4)
        """
        xp = ivy.get_framework(f=f)
        batch_shape = _shape(batch_shape)
        low = xp.asarray(self._boxes["reset_low"], dtype=dtype)
        width = xp.asarray(self._boxes["reset_width"], dtype=dtype)
        u = xp.random_uniform(shape=(*batch_shape, self.state_dim), dtype=dtype)
        return self._initial(xp, low + width * u)

    def _initial(self, xp, state):
        """A hook on freshly drawn states (e.g. rounding); identity by default."""
        return state

    def step(self, state: Array, action: Array, *, f: Framework = None) -> tuple:
        """One step of the dynamics for a batch of states.

        Args:
            state: ``(*batch, state_dim)``.
            action: ``(*batch, action_dim)`` (broadcast against the batch); converted to the
                state's dtype.
            f: framework name or namespace; by default inferred from ``state``.

        Returns:
            ``(state, observation, reward, terminated)``: the next state ``(*batch,
            state_dim)``, its observation ``(*batch, observation_dim)``, the reward
            ``(*batch,)`` and whether the episode terminated ``(*batch,)`` (bool).

        Example:
            >>> env = ivy_gym.CartPoleSwingUp()
            >>> s = env.reset((8,), f="numpy")
            >>> s, obs, r, done = env.step(s, np.zeros((8, 1), np.float32))
        """
        xp = ivy.get_framework(state, f=f)
        return self._step(xp, self.params, state, as_action(xp, action, state))

    def observe(self, state: Array, *, f: Framework = None) -> Array:
        """The observation of ``state`` (``(*batch, observation_dim)``).

        Example:
            >>> ivy_gym.Pendulum().observe(np.zeros((2, 2))).shape
            (2, 3)
        """
        xp = ivy.get_framework(state, f=f)
        return self._observe(xp, self.params, state)

    def _step(self, xp, p, state, action):
        raise NotImplementedError

    def _observe(self, xp, p, state):
        raise NotImplementedError

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


def as_action(xp, action, state):
    """``action`` as an array of ``state``'s framework and dtype (a no-op when it is one)."""
    dtype = state.dtype
    if type(action) is type(state):
        return action if action.dtype == dtype else xp.astype(action, dtype)
    return xp.asarray(action, dtype=dtype)


def scalar_action(xp, action):
    """The action of a task with one action component, without its last axis."""
    return xp.squeeze(action, axis=-1)


def unstack_last(xp, x) -> tuple:
    """The components of the last axis of ``x`` (one ``unstack``: slicing component by component
    costs ~40 us a slice on eager jax and ~100 us on eager tensorflow)."""
    return xp.unstack(x, axis=-1)
