#!/usr/bin/env bash
# Install the newest framework releases that pyproject.toml allows into a fresh virtual
# environment, and run the core's and the applied libraries' tests on them.
#
# Usage: scripts/test_versions.sh [--python VERSION] [--frameworks LIST] [--venv DIR]
#                                 [--constraint FILE] [-- PYTEST_ARGS...]
#   --python      the interpreter: a version that pyenv knows (3.12) or a path (default: python3)
#   --frameworks  comma-separated subset of torch,jax,tensorflow to install (default: all three)
#   --venv        where to build the environment (default: .venv-versions-<python>)
#   --constraint  a pip constraints file, to check a release other than the newest
#                 (for example a file holding `jax==0.11.2`)
#   after --, arguments for pytest (default: the test directories, on 2 workers)
#
# Examples:
#   scripts/test_versions.sh --python 3.12                        # jax 0.12, torch 2.15, tf 2.21
#   scripts/test_versions.sh --python 3.12 --frameworks jax,tensorflow -- tests/ivy -x
#   scripts/test_versions.sh --constraint .ci/constraints.txt     # the releases CI pins
set -euo pipefail
cd "$(dirname "$0")/.."

python=python3
frameworks=torch,jax,tensorflow
venv=""
constraint=()
while [[ $# -gt 0 ]]; do
    case "$1" in
        --python) python="$2"; shift 2 ;;
        --frameworks) frameworks="$2"; shift 2 ;;
        --venv) venv="$2"; shift 2 ;;
        --constraint) constraint=(-c "$2"); shift 2 ;;
        --) shift; break ;;
        *) echo "test_versions.sh: unknown argument '$1' (see the usage at the top of the script)" >&2
           exit 2 ;;
    esac
done

if [[ "$python" =~ ^[0-9]+\.[0-9]+$ ]] && command -v pyenv >/dev/null; then
    interpreter="$(pyenv root)/versions/$(pyenv versions --bare | grep -E "^${python//./\\.}(\.|$)" | tail -1)/bin/python"
else
    interpreter="$(command -v "$python" || true)"
fi
if [[ ! -x "$interpreter" ]]; then
    echo "test_versions.sh: no interpreter for '$python'; install it or pass a path" >&2
    exit 2
fi
version="$("$interpreter" -c 'import sys; print(f"{sys.version_info[0]}.{sys.version_info[1]}")')"
venv="${venv:-.venv-versions-$version}"

# The extras: the frameworks asked for, and everything the applied libraries and tests need.
extras="$frameworks,rl,gym,robot,vision,test"
echo "== Python $version in $venv, extras [$extras]"
rm -rf "$venv"
"$interpreter" -m venv "$venv"
"$venv/bin/pip" install --quiet --disable-pip-version-check --upgrade pip
"$venv/bin/pip" install --quiet --disable-pip-version-check --upgrade --upgrade-strategy eager \
    "${constraint[@]}" -e ".[$extras]"

echo "== Installed releases"
"$venv/bin/python" - <<'EOF'
import importlib.metadata as md
for name in ("numpy", "torch", "jax", "jaxlib", "tensorflow-cpu", "gymnasium", "mujoco", "optree"):
    try:
        print(f"  {name:15s} {md.version(name)}")
    except md.PackageNotFoundError:
        print(f"  {name:15s} (not installed)")
EOF

if [[ $# -eq 0 ]]; then
    set -- -n 2 -q tests/ivy tests/ivy_mechanics tests/ivy_vision tests/ivy_robot tests/ivy_gym \
        tests/ivy_rl tests/test_conventions.py
fi
echo "== pytest $*"
IVY_BACKENDS="numpy,array_api_strict,$frameworks" "$venv/bin/python" -m pytest -p no:cacheprovider "$@"
