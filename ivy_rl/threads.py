"""Intra-op threads of a framework, set by what the framework offers.

Small models (the agents' networks) run fastest on one thread, above all on a shared machine,
where more threads wait on each other. Each framework sets its threads its own way, and some
only before their first computation; :func:`set_threads` hides that behind one call.

This belongs with ivy's backends (beside ``ivy.framework_handler.capabilities``); until ivy's
backend layer offers it, ivy_rl keeps it here, on its own.

Example:
    >>> set_threads("torch", 1)
    'torch.set_num_threads(1)'
"""

from __future__ import annotations

import importlib
import os
import warnings
from typing import Any

import numpy as np

import ivy

__all__ = ["set_threads"]


def set_threads(xp: Any, threads: int) -> str:
    """Set the intra-op threads of the framework behind ``xp`` (a backend namespace, or a
    framework's name: a name does not load ivy's backend, and tensorflow's threads can only be
    set before anything, ivy's backend included, runs on it) to ``threads``.

    The setter is found by what the framework offers, not by its name: a
    ``set_num_threads`` function (torch; its inter-op pool is left alone, it can be sized only
    before its first use), ``config.threading``'s intra- and inter-op setters (tensorflow; they
    are settable only before its first operation, afterwards a value that differs is reported in
    a warning), or XLA's ``XLA_FLAGS`` (jax: ``--xla_cpu_multi_thread_eigen=false`` and
    ``intra_op_parallelism_threads=N`` for one thread, read when XLA starts, so they act only if
    set before jax's first computation; afterwards a warning says so). Frameworks with none of
    these (numpy, whose element-wise functions use one thread) are left as they are.

    Args:
        xp: a backend namespace (``ivy.get_framework(f="torch")``) or a framework's name.
        threads: intra-op threads, an integer >= 1 (1: small models run fastest on a shared
            machine).

    Returns:
        What was done, in words (``'torch.set_num_threads(1)'``, ``'not settable'``...).

    Example:
        >>> set_threads(ivy.get_framework(f="torch"), 1)
        'torch.set_num_threads(1)'
    """
    _check_count("threads", threads, 1)
    threads = int(threads)
    name = xp if isinstance(xp, str) else str(getattr(xp, "backend", ""))
    try:
        native = importlib.import_module(ivy.framework_handler.native_package(name))
    except (ImportError, ivy.framework_handler.UnknownFrameworkError):
        return "not settable"
    name = native.__name__
    if callable(getattr(native, "set_num_threads", None)):
        native.set_num_threads(threads)
        return f"{name}.set_num_threads({threads})"
    threading = getattr(getattr(native, "config", None), "threading", None)
    if threading is not None and hasattr(threading, "set_intra_op_parallelism_threads"):
        pairs = (
            (
                threading.get_intra_op_parallelism_threads,
                threading.set_intra_op_parallelism_threads,
            ),
            (
                threading.get_inter_op_parallelism_threads,
                threading.set_inter_op_parallelism_threads,
            ),
        )
        for get, put in pairs:
            if get() == threads:
                continue
            try:
                put(threads)
            except RuntimeError:
                _warn(
                    f"{name} already ran operations with {get() or 'its default'} threads; its "
                    f"threads can be set only before: set them ({put.__name__}) first in the "
                    "process, or run the command in a new process"
                )
                return f"{name}: not changed (already started)"
        return f"{name}.config.threading: intra/inter-op {threads}"
    try:
        bridge = importlib.import_module(f"{name}._src.xla_bridge")
    except ImportError:
        bridge = None
    if bridge is not None and hasattr(bridge, "backends_are_initialized"):
        if threads != 1:
            return f"{name}: XLA's default threads (only one thread can be asked for)"
        flags = "--xla_cpu_multi_thread_eigen=false intra_op_parallelism_threads=1"
        current = os.environ.get("XLA_FLAGS", "")
        if flags in current:
            return f"{name}: XLA_FLAGS {flags}"
        if bridge.backends_are_initialized():
            _warn(
                f"{name} has started XLA, which reads its threads from XLA_FLAGS only when it "
                f"starts: set XLA_FLAGS='{flags}' before the process's first {name} computation"
            )
            return f"{name}: not changed (already started)"
        os.environ["XLA_FLAGS"] = f"{current} {flags}".strip()
        return f"{name}: XLA_FLAGS {flags}"
    return "not settable"


def _check_count(name: str, value: Any, minimum: int) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {value!r}")


def _warn(message: str) -> None:
    warnings.warn(message, RuntimeWarning, stacklevel=3)
