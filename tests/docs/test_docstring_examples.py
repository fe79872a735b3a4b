"""Every docstring example of the core, ivy_gym and ivy_rl runs, on the backends it names
(``tests/_doctests.py``; ivy_mechanics', ivy_vision's and ivy_robot's run in their own
``test_api.py`` through the same helper)."""

from __future__ import annotations

import pytest

import ivy_gym
import ivy_rl
from tests._doctests import docstring_examples, run_example


@pytest.mark.parametrize("example", docstring_examples("ivy"))
def test_ivy(example, request, tmp_path, monkeypatch):
    run_example(example, {}, request.config, tmp_path, monkeypatch)


@pytest.mark.parametrize("example", docstring_examples("ivy_gym"))
def test_ivy_gym(example, request, tmp_path, monkeypatch):
    run_example(example, {"ivy_gym": ivy_gym}, request.config, tmp_path, monkeypatch)


#: ivy_rl's examples all run (none known to fail, none slow): a training example runs a short
#: run (2,000 steps on jax), and the lines that start a Ray cluster (``ivy_rl.distributed``),
#: which forks the process under jax's threads, are marked ``+SKIP`` in their docstrings.
@pytest.mark.parametrize("example", docstring_examples("ivy_rl"))
def test_ivy_rl(example, request, tmp_path, monkeypatch):
    # the package's names, where the example's module has no name of its own (the function
    # ivy_rl.checkpoints.checkpoints, not the module)
    names = {n: getattr(ivy_rl, n) for n in ivy_rl.__all__ if n not in example.globs}
    globs = {"ivy_rl": ivy_rl, **names}
    run_example(example, globs, request.config, tmp_path, monkeypatch)
