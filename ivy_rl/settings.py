"""How parts and agents declare their settings, and the one check every setting passes.

A part (a model, a replay, an exploration, an updater) declares each of its settings once, in
its class attribute ``settings``: ``{parameter: Setting(kind, bounds, meaning)}``; the default
is the constructor's. An agent's flat settings (``SAC(batch_size=128)``, the command line's
``--agent-kwargs``) are derived from its parts (:meth:`ivy_rl.agents.Agent.settings`), plus the
few the agent reads itself (its ``own_settings``, e.g. ``fusion``), with the agent's defaults
where they differ from its parts' (its ``_defaults``).

Example:
    >>> from ivy_rl.settings import Setting, check
    >>> check("segment_size", Setting("int", 1), 32)
    32
    >>> check("segment_size", Setting("int", 1), "32")
    Traceback (most recent call last):
    TypeError: setting 'segment_size' must be an integer >= 1, got '32' (str)
"""

from __future__ import annotations

import functools
import inspect
import math
from dataclasses import dataclass
from typing import Any

from ivy_rl.schedules import ConstantSchedule, Schedule, as_schedule

__all__ = ["Setting", "check", "describe", "declared"]


@dataclass(frozen=True)
class Setting:
    """What values a setting takes.

    Attributes:
        kind: ``'int'``, ``'float'``, ``'schedule'`` (a number, or a schedule of the run's
            progress: ``'linear:<start>[:<end>]'`` or a :class:`ivy_rl.schedules.Schedule`,
            recorded as its string; its start must lie in the bounds, its end may reach an
            open low bound), ``'bool'``, ``'str'``, ``'sizes'`` (a non-empty list of
            positive integers) or ``'any'`` (a JSON value, not checked).
        low, high: bounds of numbers (inclusive unless ``open_low`` / ``open_high``).
        choices: the values a ``'str'`` setting takes.
        optional: None is allowed.
        meaning: one line for errors and docs.
    """

    kind: str
    low: float | None = None
    high: float | None = None
    open_low: bool = False
    open_high: bool = False
    choices: tuple[Any, ...] | None = None
    optional: bool = False
    meaning: str = ""


def declared(factory: Any) -> dict[str, tuple[Setting, Any]]:
    """``{parameter: (Setting, default)}`` of a part's factory: a class (or function) with a
    ``settings`` attribute, or a ``functools.partial`` of one (its keywords are fixed, not
    settings). The defaults are the factory's signature's.

    Example:
        >>> spec, default = ivy_rl.settings.declared(ivy_rl.replays.Segment)["size"]
        >>> spec.kind, default
        ('int', 2048)
    """
    fixed: dict[str, Any] = {}
    while isinstance(factory, functools.partial):
        fixed = {**factory.keywords, **fixed}
        factory = factory.func
    specs = getattr(factory, "settings", None)
    if specs is None:
        raise TypeError(f"{getattr(factory, '__name__', factory)!r} declares no settings")
    parameters = inspect.signature(factory).parameters
    out = {}
    for name, spec in specs.items():
        if name in fixed:
            continue
        default = parameters[name].default
        out[name] = (spec, None if default is inspect.Parameter.empty else default)
    return out


def describe(spec: Setting) -> str:
    """What ``spec`` takes, in words (for errors and docs)."""
    if spec.kind == "sizes":
        text = "a non-empty list of integers >= 1, e.g. [64, 64]"
    elif spec.kind == "str":
        text = "one of " + ", ".join(repr(c) for c in spec.choices or ())
    elif spec.kind == "bool":
        text = "true or false"
    elif spec.kind == "any":
        text = "any JSON value"
    else:
        text = "an integer" if spec.kind == "int" else "a number"
        if spec.kind == "schedule":
            text = "a number or a schedule 'linear:<start>' / 'linear:<start>:<end>'"
        bounds = []
        if spec.low is not None:
            bounds.append(f"{'>' if spec.open_low else '>='} {spec.low:g}")
        if spec.high is not None:
            bounds.append(f"{'<' if spec.open_high else '<='} {spec.high:g}")
        if bounds:
            text += " " + " and ".join(bounds)
    return text + (" or None (null)" if spec.optional else "")


def check(name: str, spec: Setting | None, value: Any) -> Any:
    """``value`` checked against ``spec`` and normalised (sizes as a tuple, integers as
    ``int``, numbers as ``float``, schedules as their string); a TypeError or ValueError
    naming the setting, what it takes and what it got otherwise. ``spec`` None: unchecked.

    Example:
        >>> ivy_rl.settings.check("hidden_sizes", ivy_rl.settings.Setting("sizes"), [64, 64])
        (64, 64)
    """
    if spec is None or spec.kind == "any" or (value is None and spec.optional):
        return value

    def fail(error: type[Exception]) -> Exception:
        return error(
            f"setting {name!r} must be {describe(spec)}, got {value!r} "
            f"({type(value).__name__})" + (f": {spec.meaning}" if spec.meaning else "")
        )

    if spec.kind == "bool":
        if not isinstance(value, bool):
            raise fail(TypeError)
        return value
    if spec.kind == "str":
        if not isinstance(value, str):
            raise fail(TypeError)
        if spec.choices is not None and value not in spec.choices:
            raise fail(ValueError)
        return value
    if spec.kind == "sizes":
        if not isinstance(value, (list, tuple)) or not value:
            raise fail(TypeError)
        if not all(_is_int(s) for s in value):
            raise fail(TypeError)
        if not all(int(s) >= 1 for s in value):
            raise fail(ValueError)
        return tuple(int(s) for s in value)
    if spec.kind == "schedule" and not _is_number(value) and not isinstance(value, (int, float)):
        return _check_schedule(name, spec, value, fail)
    if spec.kind == "int":
        if not _is_int(value):
            raise fail(TypeError)
        value = int(value)
    else:
        if isinstance(value, bool) or not isinstance(value, (int, float)) and not _is_number(value):
            raise fail(TypeError)
        value = float(value)
        if not math.isfinite(value):
            raise fail(ValueError)
    if spec.low is not None and (value <= spec.low if spec.open_low else value < spec.low):
        raise fail(ValueError)
    if spec.high is not None and (value >= spec.high if spec.open_high else value > spec.high):
        raise fail(ValueError)
    return value


def _check_schedule(name: str, spec: Setting, value: Any, fail: Any) -> Any:
    """A schedule's string (``'linear:...'``) or :class:`Schedule` checked: its start within the
    setting's bounds, its end too (or at an open low bound: down to 0); its string returned."""
    if not isinstance(value, (str, Schedule)):
        raise fail(TypeError)
    try:
        schedule = as_schedule(value, name=f"setting {name!r}")
    except (TypeError, ValueError):
        raise fail(ValueError) from None
    if isinstance(schedule, ConstantSchedule):
        return check(name, spec, schedule.value)
    start, end = schedule(0.0), schedule(1.0)
    low, high = spec.low, spec.high
    if low is not None and ((start <= low if spec.open_low else start < low) or end < low):
        raise fail(ValueError)
    if high is not None and ((start >= high if spec.open_high else start > high) or end > high):
        raise fail(ValueError)
    return str(schedule)


def _is_int(value: Any) -> bool:
    import numpy as np

    return not isinstance(value, bool) and isinstance(value, (int, np.integer))


def _is_number(value: Any) -> bool:
    import numpy as np

    return isinstance(value, (np.integer, np.floating))


# Settings that several parts share, declared once here and named by the parts
SIZES = Setting("sizes", meaning="hidden sizes of the actor's (or the Q-network's) torso")
CRITIC_SIZES = Setting("sizes", optional=True, meaning="of the critic's torso (None: hidden_sizes)")
ACTIVATION = Setting("str", choices=("tanh", "relu", "elu", "gelu", "silu"))
DISCOUNT = Setting("float", 0.0, 1.0, meaning="discount factor gamma")
TRACE_DECAY = Setting("float", 0.0, 1.0, meaning="lambda of the lambda-returns")
LR = Setting("schedule", 0.0, open_low=True, meaning="Adam's learning rate")
CLIP = Setting("float", 0.0, meaning="global norm of the gradients (0: no clipping)")
BETA1 = Setting("float", 0.0, 1.0, meaning="Adam's decay rate of its mean of the gradients")
BETA2 = Setting("float", 0.0, 1.0, meaning="Adam's decay rate of its mean of their squares")
FLAG = Setting("bool")
