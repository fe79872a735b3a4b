"""``ivy.set_threads``: a framework's intra-op threads, set by what the framework offers (torch's
``set_num_threads``, tensorflow's ``config.threading``, XLA's flags for jax), on every backend.

jax and tensorflow read their threads once, when they start, so they are tested in a fresh
process, as a user's program would set them: first, before any computation."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest

import ivy

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
XLA_ONE_THREAD = "--xla_cpu_multi_thread_eigen=false intra_op_parallelism_threads=1"

# a fresh process: set before the framework starts, then after, with a warning
_SCRIPT = """
import os, sys, warnings
os.environ.pop("XLA_FLAGS", None)
import ivy
name = sys.argv[1]
print(sorted(m for m in ("torch", "jax", "tensorflow") if m in sys.modules))
print(ivy.set_threads(name, 2 if name == "jax" else 1))
print(ivy.set_threads(name, 1))
if name == "tensorflow":
    import tensorflow as tf
    print(tf.config.threading.get_intra_op_parallelism_threads(),
          tf.config.threading.get_inter_op_parallelism_threads())
else:
    print(os.environ["XLA_FLAGS"])
xp = ivy.get_framework(f=name)
xp.sum(xp.ones(3))  # the framework starts
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    if name == "jax":
        os.environ.pop("XLA_FLAGS")
    print(ivy.set_threads(xp, 2 if name == "tensorflow" else 1))
print(caught[0].message if caught else "no warning")
"""


@pytest.mark.parametrize("bad", [0, -1, 1.5, True, "2", None])
def test_a_count_that_is_not_an_integer_of_one_or_more_is_refused(backend, bad):
    with pytest.raises(ValueError, match=rf"threads must be an integer >= 1, got {bad!r}"):
        ivy.set_threads(backend, bad)


def test_set_threads_on_every_backend(backend):
    assert ivy.set_threads is ivy.threads.set_threads and "set_threads" in ivy.__all__
    if backend == "torch":
        import torch

        before = torch.get_num_threads()
        try:
            assert ivy.set_threads("torch", 2) == "torch.set_num_threads(2)"
            assert torch.get_num_threads() == 2
            assert ivy.set_threads(ivy.torch, np.int64(1)) == "torch.set_num_threads(1)"
            assert torch.get_num_threads() == 1
        finally:
            torch.set_num_threads(before)
        return
    if backend in ("jax", "tensorflow"):
        done = subprocess.run(
            [sys.executable, "-c", _SCRIPT, backend], capture_output=True, text=True, cwd=ROOT,
            timeout=120,
        )  # fmt: skip
        assert done.returncode == 0, done.stderr[-2000:]
        lines = done.stdout.strip().splitlines()[-6:]
        assert lines[0] == "[]"  # import ivy imports no framework
        if backend == "tensorflow":
            assert lines[1:4] == ["tensorflow.config.threading: intra/inter-op 1"] * 2 + ["1 1"]
        else:
            assert lines[1:4] == [
                "jax: XLA's default threads (only one thread can be asked for)",
                f"jax: XLA_FLAGS {XLA_ONE_THREAD}",
                XLA_ONE_THREAD,
            ]
        assert lines[4] == f"{backend}: not changed (already started)"
        assert "only" in lines[5] and "before" in lines[5], lines[5]
        return
    # numpy's element-wise functions run on one thread; a registered library has no setter
    assert ivy.set_threads(backend, 1) == "not settable"
    assert ivy.set_threads(getattr(ivy, backend), 3) == "not settable"


def test_an_unknown_framework_or_object_is_refused():
    with pytest.raises(ivy.UnknownFrameworkError, match="caffe"):
        ivy.set_threads("caffe", 1)
    with pytest.raises(TypeError, match=r"a framework's name \('torch'\) or a backend namespace"):
        ivy.set_threads(42, 1)
