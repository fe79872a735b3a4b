"""Intra-op threads of a framework, set by what the framework offers.

Each framework sets its threads its own way, and some only before their first computation;
:func:`set_threads` hides that behind one call. Small models run fastest on one thread, above
all on a shared machine, where more threads wait on each other.

``import ivy`` imports no framework, and neither does this module: the framework is imported
when :func:`set_threads` is called, and only the framework (not ivy's backend), so that
tensorflow's and XLA's threads can still be set before their first operation.

Example:
    >>> import ivy
    >>> ivy.set_threads("torch", 1)
    'torch.set_num_threads(1)'
"""

from __future__ import annotations

import importlib
import importlib.util
import operator
import os
import sys
import warnings
from typing import Any

from ivy import framework_handler
from ivy.errors import FrameworkNotInstalledError

__all__ = ["set_threads"]

#: XLA's flags for one intra-op thread, read once, when XLA starts.
_XLA_ONE_THREAD = "--xla_cpu_multi_thread_eigen=false intra_op_parallelism_threads=1"


def set_threads(framework: Any, threads: int) -> str:
    """Set the intra-op threads of a framework to ``threads``.

    The setter is found by what the framework offers, not by its name:

    - a ``set_num_threads`` function (torch; its inter-op pool is left alone, it can be sized
      only before its first use);
    - ``config.threading``'s intra- and inter-op setters (tensorflow; settable only before its
      first operation: afterwards a value that differs is reported in a warning, and nothing
      changes);
    - XLA's ``XLA_FLAGS`` (jax: ``--xla_cpu_multi_thread_eigen=false
      intra_op_parallelism_threads=1`` for one thread, read when XLA starts, so they act only if
      set before jax's first computation; afterwards a warning says so; XLA's default pool is
      the only other choice, so any count above 1 leaves it as it is);
    - none of these (numpy, whose element-wise functions run on one thread; a library registered
      with :func:`ivy.register_framework`): nothing is changed, and ``'not settable'`` says so.

    Args:
        framework: a framework's name (``'torch'``, ``'tf'``, ...; ivy's backend is not loaded,
            so tensorflow and jax can still be set before their first operation) or a backend
            namespace (``ivy.torch``, ``ivy.get_framework(f='jax')``).
        threads: intra-op threads, an integer >= 1.

    Returns:
        What was done, in words (``'torch.set_num_threads(1)'``, ``'not settable'``, ...).

    Raises:
        ValueError: ``threads`` is not an integer >= 1.
        UnknownFrameworkError: ``framework`` names no framework ivy knows.
        FrameworkNotInstalledError: the framework is not installed.

    Example:
        >>> import ivy
        >>> ivy.set_threads(ivy.torch, 1)
        'torch.set_num_threads(1)'
        >>> ivy.set_threads("numpy", 1)
        'not settable'
    """
    try:
        count = None if isinstance(threads, bool) else operator.index(threads)
    except TypeError:
        count = None
    if count is None or count < 1:
        raise ValueError(f"threads must be an integer >= 1, got {threads!r}")
    threads = count
    name = framework if isinstance(framework, str) else getattr(framework, "backend", None)
    if not isinstance(name, str):
        raise TypeError(
            "set_threads takes a framework's name ('torch') or a backend namespace (ivy.torch), "
            f"got {type(framework).__name__}"
        )
    package = framework_handler.native_package(name)
    if package not in sys.modules and importlib.util.find_spec(package) is None:
        raise FrameworkNotInstalledError(
            f"cannot set the threads of {name}: its package '{package}' is not installed"
        )
    native = importlib.import_module(package)
    if callable(getattr(native, "set_num_threads", None)):
        native.set_num_threads(threads)
        return f"{package}.set_num_threads({threads})"
    threading = getattr(getattr(native, "config", None), "threading", None)
    if threading is not None and hasattr(threading, "set_intra_op_parallelism_threads"):
        return _set_config_threading(package, threading, threads)
    try:
        bridge = importlib.import_module(f"{package}._src.xla_bridge")
    except ImportError:
        bridge = None
    if bridge is not None and hasattr(bridge, "backends_are_initialized"):
        return _set_xla_flags(package, bridge, threads)
    return "not settable"


def _set_config_threading(package: str, threading: Any, threads: int) -> str:
    pairs = (
        (threading.get_intra_op_parallelism_threads, threading.set_intra_op_parallelism_threads),
        (threading.get_inter_op_parallelism_threads, threading.set_inter_op_parallelism_threads),
    )
    for get, put in pairs:
        if get() == threads:
            continue
        try:
            put(threads)
        except RuntimeError:
            _warn(
                f"{package} already ran operations with {get() or 'its default'} threads; its "
                f"threads can be set only before: set them ({put.__name__}) first in the "
                "process, or run the command in a new process"
            )
            return f"{package}: not changed (already started)"
    return f"{package}.config.threading: intra/inter-op {threads}"


def _set_xla_flags(package: str, bridge: Any, threads: int) -> str:
    if threads != 1:
        return f"{package}: XLA's default threads (only one thread can be asked for)"
    current = os.environ.get("XLA_FLAGS", "")
    if _XLA_ONE_THREAD in current:
        return f"{package}: XLA_FLAGS {_XLA_ONE_THREAD}"
    if bridge.backends_are_initialized():
        _warn(
            f"{package} has started XLA, which reads its threads from XLA_FLAGS only when it "
            f"starts: set XLA_FLAGS='{_XLA_ONE_THREAD}' before the process's first {package} "
            "computation"
        )
        return f"{package}: not changed (already started)"
    os.environ["XLA_FLAGS"] = f"{current} {_XLA_ONE_THREAD}".strip()
    return f"{package}: XLA_FLAGS {_XLA_ONE_THREAD}"


def _warn(message: str) -> None:
    warnings.warn(message, RuntimeWarning, stacklevel=4)
