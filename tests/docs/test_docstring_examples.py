"""Every docstring example of the core, ivy_gym and ivy_rl runs, on the backends it names
(``tests/_doctests.py``; ivy_mechanics', ivy_vision's and ivy_robot's run in their own
``test_api.py`` through the same helper)."""

from __future__ import annotations

import pytest

import ivy_gym
import ivy_rl
from tests._doctests import docstring_examples, run_example

#: ivy_rl's examples known to fail, by docstring (ivy_rl is being rewritten; each entry is a
#: defect to fix in its docstring, then to remove from here).
IVY_RL_XFAIL: dict[str, str] = {}


@pytest.mark.parametrize("example", docstring_examples("ivy"))
def test_ivy(example, request, tmp_path, monkeypatch):
    run_example(example, {}, request.config, tmp_path, monkeypatch)


@pytest.mark.parametrize("example", docstring_examples("ivy_gym"))
def test_ivy_gym(example, request, tmp_path, monkeypatch):
    run_example(example, {"ivy_gym": ivy_gym}, request.config, tmp_path, monkeypatch)


@pytest.mark.parametrize("example", docstring_examples("ivy_rl", xfail=IVY_RL_XFAIL))
def test_ivy_rl(example, request, tmp_path, monkeypatch):
    globs = {"ivy_rl": ivy_rl, **{n: getattr(ivy_rl, n) for n in ivy_rl.__all__}}
    run_example(example, globs, request.config, tmp_path, monkeypatch)
