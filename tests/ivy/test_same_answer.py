"""The same answer on every backend: every public function of the core is called on the same
inputs on every backend, and the answers (dtype, shape and values of every array; or the kind
of error raised) are compared (machinery in ``differential.py``, cases in ``same_answer_cases.py``).

The cases are the edges where frameworks part: 0-d and empty arrays, negative indices, ties and
NaN, integer overflow, every dtype, broadcasting of every argument, Python scalars and arrays as
bounds, and bad input, which raises the same error everywhere. One test per function, running
every case on every backend.
"""

from __future__ import annotations

import pytest

import ivy
from tests.ivy.differential import disagreements
from tests.ivy.same_answer_cases import CASES

# (the opt-in array_api_strict follows the standard where ivy allows more; see conftest.py)
FRAMEWORKS = ("numpy", "torch", "jax", "tensorflow")


@pytest.fixture
def frameworks(request) -> tuple[str, ...]:
    chosen = tuple(b for b in FRAMEWORKS if b in request.config.ivy_backends)
    if len(chosen) < 2:
        pytest.skip("comparing backends needs two or more of them")
    return chosen


def test_every_public_function_has_cases():
    names = {i.name for i in ivy.list_functions() if i.kind != "alias"}
    assert sorted(names - set(CASES)) == []
    assert sorted(set(CASES) - names) == []


@pytest.mark.parametrize("name", sorted(CASES))
def test_same_answer_on_every_backend(name, frameworks):
    report = []
    for case in CASES[name]:
        found = disagreements(name, case, frameworks)
        if found:
            report.append(f"{name}({case.describe()}):\n    " + "\n    ".join(found))
    assert not report, "\n".join(report)
