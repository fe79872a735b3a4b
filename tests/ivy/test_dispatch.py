"""The generated dispatchers are code that tools can read: source, tracebacks, type hints, and
tensorflow's AutoGraph, which prints nothing for ivy functions inside a user's ``tf.function``."""

from __future__ import annotations

import inspect
import logging
import os
import traceback
import typing

import numpy as np
import pytest

import ivy


def test_the_source_of_a_dispatcher_is_code():
    source = inspect.getsource(ivy.clip)
    assert source.startswith("def clip(x: Array, /, min: Array | Scalar | None = None")
    assert "return ns.clip(x, min, max)" in source
    assert inspect.getsourcefile(ivy.clip).endswith(os.path.join("_dispatchers", "clip.py"))


def test_a_dispatcher_has_the_stubs_type_hints():
    hints = typing.get_type_hints(ivy.clip)
    assert hints["x"] is ivy.typing.Array and hints["return"] is ivy.typing.Array
    assert inspect.signature(ivy.clip).parameters["min"].default is None


def test_a_traceback_shows_the_dispatchers_lines():
    with pytest.raises(ivy.errors.UnknownFrameworkError) as info:
        ivy.sin(np.ones(2), f="no-such-framework")
    frames = traceback.extract_tb(info.value.__traceback__)
    mine = [fr for fr in frames if fr.filename.endswith(os.path.join("_dispatchers", "sin.py"))]
    assert mine and mine[0].line == "ns = _resolve_f(f)"


def test_every_dispatcher_has_source():
    for info in ivy.list_functions(kind="dispatched"):
        fn = getattr(ivy.core, info.name)
        fn = getattr(fn, "_call", None) or fn  # ivy.core.fft is the callable namespace
        assert f"return ns.{info.name}(" in inspect.getsource(fn), info.name


def test_ivy_functions_inside_tf_function_print_nothing(request, capfd):
    if "tensorflow" not in request.config.ivy_backends:
        pytest.skip("tensorflow is not among the backends under test")
    import tensorflow as tf

    records: list[logging.LogRecord] = []
    handler = logging.Handler()
    handler.emit = records.append
    logger = logging.getLogger("tensorflow")
    logger.addHandler(handler)

    @tf.function
    def step(x, w):
        y = ivy.clip(x, 0.0, 1.0)  # dispatched, Python scalars beside an array
        z = ivy.matmul(ivy.expand_dims(y, axis=0), w)  # dispatched, two arrays
        n = ivy.safe_norm(z, axis=-1)  # a composition
        c = ivy.isclose(y, ivy.zeros_like(y))  # composition over dispatched functions
        s = ivy.softmax(ivy.sin(y), axis=-1)  # reals rule
        return ivy.sum(n) + ivy.mean(s) + ivy.sum(ivy.astype(c, "float32"))

    capfd.readouterr()
    try:
        out = step(tf.constant([0.5, 2.0, -1.0]), tf.ones((3, 2)))
    finally:
        logger.removeHandler(handler)
    printed = capfd.readouterr()
    assert np.isfinite(out.numpy())
    assert printed.out == "" and printed.err == "", printed
    assert [r.getMessage() for r in records] == []
