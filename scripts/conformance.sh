#!/usr/bin/env bash
# Run the public Array API conformance suite (version 2023.12) against one ivy namespace and print
# the suite's closing line; the numbers in docs/conformance.md come from this script.
#
# Usage, from the project root:
#   scripts/conformance.sh NAMESPACE [MAX_EXAMPLES] [extra pytest args...]
#   scripts/conformance.sh ivy.jax 20 -n 2
#   JAX_ENABLE_X64=1 scripts/conformance.sh ivy.jax 20
#
# SUITE: the suite's checkout (default ../shared/third_party/array-api-tests). PY: the Python to
# run it with (default .venv/bin/python); it needs pytest, hypothesis and ndindex.
#
# The suite is run from a scratch copy (it writes caches next to itself), with one line changed:
# `array_api_tests/dtype_helpers.py` reads `xp.float64` at import even where the rest of the suite
# takes the dtypes a namespace has (`getattr` in a try), so a namespace without float64 (ivy.jax
# while jax's x64 mode is off) could not even be collected. The copy reads it with `getattr(xp,
# "float64", None)`: the value only matters for complex128, which such a namespace does not have.
set -eu
ns=$1; n=${2:-20}; shift $(( $# >= 2 ? 2 : 1 ))
root=$(pwd)
py=${PY:-$root/.venv/bin/python}
suite=${SUITE:-$root/../shared/third_party/array-api-tests}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$suite/." "$work/"
chmod -R u+w "$work"
sed -i 's/"complex128": xp\.float64/"complex128": getattr(xp, "float64", None)/' \
    "$work/array_api_tests/dtype_helpers.py"
# A failing test is reported without hypothesis's shrink and explain phases, which only make
# its message smaller and once took more than 20 minutes on one test (tensorflow's divide): the
# same tests pass and fail, in minutes.
cat > "$work/_conformance_phases.py" <<'PY'
import pytest
from hypothesis import Phase, settings


@pytest.hookimpl(trylast=True)
def pytest_configure(config):
    base = settings.get_profile("array-api-tests")
    phases = [p for p in base.phases if p not in (Phase.shrink, Phase.explain)]
    settings.register_profile("conformance", parent=base, phases=phases)
    settings.load_profile("conformance")
PY
cd "$work"
export PYTHONPATH="$root:$work${PYTHONPATH:+:$PYTHONPATH}"
export ARRAY_API_TESTS_MODULE="exec('import ${ns%%.*}; xp = $ns')"
export ARRAY_API_TESTS_VERSION=2023.12
"$py" -m pytest array_api_tests -q -p no:cacheprovider --max-examples "$n" --disable-warnings \
    -p _conformance_phases -rf "$@" 2>&1 | grep -E '^(FAILED|ERROR)|passed|failed' | tail -n 400
