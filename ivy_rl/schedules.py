"""Schedules of settings over a run (learning rates, PPO's clipping), as the RL zoo writes them.

A schedule maps the run's progress, the fraction of its environment steps done (0 at the start,
1 at the end), to a value. The trainer tells an agent the progress before each of its updates
(``agent.set_progress(progress)``, where the agent defines it); the agent reads its schedules
there and hands the values to its compiled update as array inputs, so a changing value never
retraces. In ``--agent-kwargs`` a schedule is a string:

- ``"linear:3e-4"``: from 3e-4 at the start down to 0 at the end;
- ``"linear:3e-4:1e-5"``: from 3e-4 down to 1e-5;
- a number: constant.

Example:
    >>> lr = as_schedule("linear:3e-4")
    >>> lr(0.0), lr(0.5), lr(1.0)
    (0.0003, 0.00015, 0.0)
    >>> str(lr)                     # how config.json records it
    'linear:0.0003:0.0'
"""

from __future__ import annotations

import math
from typing import Any

__all__ = ["Schedule", "ConstantSchedule", "LinearSchedule", "as_schedule", "is_schedule"]


class Schedule:
    """A value as a function of the run's progress in ``[0, 1]``; see the module's docstring."""

    def __call__(self, progress: float) -> float:
        raise NotImplementedError

    @staticmethod
    def _progress(progress: float) -> float:
        progress = float(progress)
        if not math.isfinite(progress):
            raise ValueError(f"progress must be a finite fraction of the run, got {progress}")
        return min(max(progress, 0.0), 1.0)

    def __eq__(self, other: object) -> bool:
        return type(self) is type(other) and str(self) == str(other)

    def __hash__(self) -> int:
        return hash(str(self))

    def __repr__(self) -> str:
        return f"{type(self).__name__}({str(self)!r})"


class ConstantSchedule(Schedule):
    """The same value throughout.

    Example:
        >>> ConstantSchedule(0.2)(0.7)
        0.2
    """

    def __init__(self, value: float) -> None:
        self.value = _number(value, "value")

    def __call__(self, progress: float) -> float:
        self._progress(progress)
        return self.value

    def __str__(self) -> str:
        return repr(self.value)


class LinearSchedule(Schedule):
    """From ``start`` at progress 0 to ``end`` at progress 1, linearly (clamped outside).

    Args:
        start: the value at the start of the run.
        end: the value at the end of the run.

    Example:
        >>> LinearSchedule(3e-4)(0.25)
        0.000225
    """

    def __init__(self, start: float, end: float = 0.0) -> None:
        self.start = _number(start, "start")
        self.end = _number(end, "end")

    def __call__(self, progress: float) -> float:
        p = self._progress(progress)
        return (1.0 - p) * self.start + p * self.end  # exactly start at 0 and end at 1

    def __str__(self) -> str:
        return f"linear:{self.start!r}:{self.end!r}"


def _number(value: Any, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(f"the schedule's {name} must be a number, got {value!r}")
    value = float(value)
    if not math.isfinite(value):
        raise ValueError(f"the schedule's {name} must be finite, got {value}")
    return value


def is_schedule(value: Any) -> bool:
    """Whether ``value`` is a :class:`Schedule` or a schedule's string (``"linear:..."``)."""
    return isinstance(value, Schedule) or (isinstance(value, str) and value.startswith("linear"))


def as_schedule(value: Any, *, name: str = "value") -> Schedule:
    """A :class:`Schedule` from a number, a string (``"linear:3e-4"``, ``"linear:3e-4:1e-5"``)
    or a schedule.

    Args:
        value: the setting.
        name: the setting's name, for the error message.

    Raises:
        TypeError, ValueError: naming the setting and the forms it accepts.

    Example:
        >>> as_schedule("linear:1e-3:1e-4")(1.0)
        0.0001
    """
    if isinstance(value, Schedule):
        return value
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        try:
            return ConstantSchedule(value)
        except (TypeError, ValueError) as error:
            raise ValueError(f"{name}: {error}") from None
    if isinstance(value, str):
        kind, _, rest = value.partition(":")
        parts = rest.split(":") if rest else []
        if kind == "linear" and 1 <= len(parts) <= 2:
            try:
                return LinearSchedule(*(float(p) for p in parts))
            except ValueError:
                pass
    raise ValueError(
        f"{name} must be a number or a schedule: 'linear:<start>' (down to 0 at the end of the "
        f"run) or 'linear:<start>:<end>'; got {value!r}"
    )
