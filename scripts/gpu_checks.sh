#!/usr/bin/env bash
# Every GPU check of issue 24 (item 6), in one script, each step under its own timeout, printing
# every figure. Written for the device machine (one GPU, 15 minutes of device time in all; see
# docs/gpu.md), tested on the CPU with --quick.
#
#   bash scripts/gpu_checks.sh [--quick] [--device gpu:0] [--part all|tests|bench]
#   bash scripts/gpu_checks.sh --fetch-wheels     # here, before the GPU session (needs pip)
#
# --quick        small sizes and --device cpu unless --device is given (the CPU test of this script)
# --device D     'gpu:0' (default) or 'cpu'
# --part P       'tests' (the test suite on the device), 'bench' (precision check and
#                benchmarks), or 'all' (default)
# --fetch-wheels download, into .whl/ (ignored by git: add '/.whl/' to .git/info/exclude), the
#                wheels the device machine lacks: gymnasium and its farama-notifications, optree,
#                mujoco (and its glfw), gymnax, kornia (and kornia_rs), pytorch_kinematics (and its
#                arm_pytorch_utilities, pytorch_seed); nothing else is installed there.
# On the device machine, wheels in .whl/ (name '.whl' in the run's carry) are installed with
# 'pip install --no-index --no-deps --target /tmp/site' and put on PYTHONPATH; without them the
# steps that need a missing package print so and go on (tests that need gymnasium or mujoco skip).
set -u
cd "$(dirname "$0")/.."

QUICK=0
DEVICE=""
PART=all
while [ $# -gt 0 ]; do
    case "$1" in
        --quick) QUICK=1 ;;
        --device) DEVICE="$2"; shift ;;
        --part) PART="$2"; shift ;;
        --fetch-wheels)
            py=${PYTHON:-python3}
            plat="--platform manylinux_2_28_x86_64 --platform manylinux_2_27_x86_64
                  --platform manylinux_2_17_x86_64 --platform manylinux2014_x86_64
                  --platform manylinux1_x86_64"
            # shellcheck disable=SC2086
            "$py" -m pip download --no-deps --only-binary=:all: --python-version 3.12 \
                --implementation cp $plat -d .whl \
                gymnasium farama-notifications optree mujoco glfw gymnax kornia kornia_rs \
                pytorch_kinematics arm_pytorch_utilities pytorch_seed
            exit $?
            ;;
        *) echo "unknown argument: $1 (see the head of $0)" >&2; exit 2 ;;
    esac
    shift
done
if [ -z "$DEVICE" ]; then
    if [ "$QUICK" = 1 ]; then DEVICE=cpu; else DEVICE=gpu:0; fi
fi

PY=${PYTHON:-python3}
export PYTHONUNBUFFERED=1
if ls .whl/*.whl >/dev/null 2>&1; then
    "$PY" -m pip install -q --no-index --no-deps --no-compile --no-cache-dir --upgrade \
        --target /tmp/site .whl/*.whl && export PYTHONPATH=$PWD:/tmp/site \
        || echo "WARNING: the wheels in .whl/ did not install"
fi
export PYTHONPATH=${PYTHONPATH:-$PWD}
case ":$PYTHONPATH:" in *":$PWD:"*) ;; *) export PYTHONPATH=$PWD:$PYTHONPATH ;; esac

FAILED=()
step() {  # step NAME SECONDS COMMAND...: run under a timeout, record a failure, go on
    local name=$1 limit=$(($2 * SLOWER))
    shift 2
    echo
    echo "=== $name (timeout ${limit}s): $*"
    local start=$SECONDS
    timeout --kill-after=10 "$limit" "$@"
    local rc=$?
    echo "=== $name: exit $rc after $((SECONDS - start))s"
    [ $rc = 0 ] || FAILED+=("$name (exit $rc)")
}

echo "device $DEVICE, quick $QUICK, part $PART; python $("$PY" -c 'import sys; print(sys.version.split()[0])')"
"$PY" - <<'PYEOF'
import importlib.util as u
for name in ("torch", "jax", "gymnasium", "optree", "mujoco", "gymnax", "kornia", "pytorch_kinematics"):
    spec = u.find_spec(name)
    print(f"  {name:20s} {'yes' if spec else 'MISSING'}")
try:
    import torch
    print("  torch", torch.__version__, "cuda:", torch.cuda.is_available())
    import jax
    print("  jax", jax.__version__, jax.devices())
except Exception as error:  # report and go on
    print("  ", error)
PYEOF

if [ "$QUICK" = 1 ]; then
    TEST_ARGS=(tests/ivy_robot/test_devices.py tests/ivy_vision/test_devices.py
               tests/ivy_gym/test_contract.py -k device -q -x -p no:cacheprovider)
    TEST_LIMIT=300
    GYM=(--steps 20 --device-batches 256,1024 --torch-batches 256 --torch-steps 10 --repeats 3)
    FK=(--batches 1000 --repeats 3 --backends torch,jax)
    WARP=(--batch 1 --sizes 120x160 --repeats 5 --backends torch,jax --no-torch-compile)
    MATMUL=(--size 512 --repeats 5)
    RL=(--workers 64 --steps 16384 --epochs 2 --test-episodes 2)
    BENCH_LIMIT=400
    SLOWER=3  # a shared CPU: compilation alone takes a minute
else
    SLOWER=1
    TEST_ARGS=(tests -q -x -n 8 -p no:cacheprovider)
    TEST_LIMIT=150
    GYM=(--steps 100 --device-batches 65536,1048576 --torch-batches 4096,65536
         --torch-steps 50 --repeats 5)
    FK=(--batches 1000000 --repeats 5 --backends torch,jax)
    WARP=(--batch 4 --sizes 480x640 --repeats 15 --backends torch,jax)
    MATMUL=(--size 8192 --repeats 7)
    RL=(--workers 4096 --steps 1048576 --epochs 8 --test-episodes 3)
    BENCH_LIMIT=120
fi

if [ "$PART" = all ] || [ "$PART" = tests ]; then
    step tests "$TEST_LIMIT" env IVY_TEST_DEVICE="$DEVICE" IVY_BACKENDS=numpy,torch,jax \
        "$PY" -m pytest "${TEST_ARGS[@]}"
fi
if [ "$PART" = all ] || [ "$PART" = bench ]; then
    step matmul_precision 45 "$PY" benchmarks/matmul_precision.py --device "$DEVICE" "${MATMUL[@]}"
    step gym_throughput "$BENCH_LIMIT" "$PY" benchmarks/gym_throughput.py --device "$DEVICE" \
        --device-only "${GYM[@]}"
    step robot_kinematics 90 "$PY" benchmarks/robot_kinematics.py --device "$DEVICE" "${FK[@]}"
    step vision_warping 90 "$PY" benchmarks/vision_warping.py --device "$DEVICE" "${WARP[@]}"
    step rl_gpu 200 "$PY" benchmarks/rl_gpu.py --device "$DEVICE" "${RL[@]}"
fi

echo
if [ ${#FAILED[@]} = 0 ]; then
    echo "gpu_checks: every step passed"
else
    echo "gpu_checks: failed steps: ${FAILED[*]}"
    exit 1
fi
