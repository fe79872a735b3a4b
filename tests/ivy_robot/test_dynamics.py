"""KinematicTree dynamics (ivy_robot.physics) against MuJoCo 4.0.1.

- The smooth dynamics on every MJCF model Gymnasium ships, at random states without
  constraints: mass matrix (``mj_fullM``), bias, passive and actuator forces, inverse dynamics
  (``mj_inverse``).
- The constrained dynamics at states where the robots touch the floor and their joint limits:
  ``mj_forward``'s ``qacc`` and ``mj_step``'s state and warm start (contacts, limits, Newton
  and PGS), on every backend (jax and tensorflow compiled: their eager mode compiles each
  operation on first use).
- Gradients through steps with contacts against central differences; compiled equals eager.
- Every MuJoCo feature that ``mj_forward`` would honour is modelled (and compared) or refused
  by name; the contact and limit masks are MuJoCo's exactly; bad input raises.
"""

from __future__ import annotations

import os
import warnings

import numpy as np
import pytest

import ivy
import ivy_robot
from tests.conftest import capable
from tests.helpers import check_gradients, native, numpy_of
from tests.ivy_robot._models import gymnasium_models

mujoco = pytest.importorskip("mujoco")

GYMNASIUM = {os.path.basename(p)[:-4]: p for p in gymnasium_models()}
BATCH = 3
TOL = dict(rtol=1e-10, atol=1e-10)
#: models whose geoms collide in pair kinds the pipeline refuses (capsule-cylinder)
REFUSED = {"pusher", "pusher_v5"}
#: models that touch their floor in most states: lowered into it for the constrained oracle.
#: (Gymnasium's point.xml rests its sphere exactly on its floor, at distance 0: whether MuJoCo
#: counts the contact is decided by the rounding of its quaternions, -5.6e-17 or 0; it is left
#: out of the constrained comparison.)
FLOORED = {"hopper", "walker2d", "walker2d_v5", "half_cheetah", "ant", "humanoid",
           "humanoidstandup"}  # fmt: skip


def _disable(model, *bits):
    for bit in bits:
        model.opt.disableflags |= int(getattr(mujoco.mjtDisableBit, bit))


def _random_state(model, rng, lift=3.0):
    """A random (qpos, qvel, ctrl, qfrc_applied) about the joint ranges (10% beyond them on
    both sides: limits), free and sliding roots at height ``lift``."""
    q = model.qpos0.copy()
    for j in range(model.njnt):
        adr, kind = model.jnt_qposadr[j], model.jnt_type[j]
        if kind == 0:
            q[adr : adr + 3] = rng.normal(size=3) * 0.3 + [0.0, 0.0, lift]
            quat = rng.normal(size=4)
            q[adr + 3 : adr + 7] = quat / np.linalg.norm(quat)
        elif model.jnt_limited[j]:
            lo, hi = model.jnt_range[j]
            q[adr] = rng.uniform(lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo))
        elif kind == 2 and model.jnt_axis[j][2] > 0.5:
            q[adr] += lift + rng.normal() * 0.1
        else:
            q[adr] = rng.normal()
    lo, hi = model.actuator_ctrlrange.T if model.nu else (np.zeros(0), np.zeros(0))
    ctrl = rng.uniform(lo - 0.2, hi + 0.2)  # some controls beyond the range: clamped
    return q, rng.normal(size=model.nv), ctrl, rng.normal(size=model.nv)


def _smooth_oracle(path, seed):
    """Random states without constraints and MuJoCo's smooth quantities there."""
    model = mujoco.MjModel.from_xml_path(path)
    _disable(model, "mjDSBL_CONTACT")  # the point and the pusher touch their floor and table
    data = mujoco.MjData(model)
    rng = np.random.default_rng(seed)
    states = {k: [] for k in ("qpos", "qvel", "ctrl", "qacc_in")}
    ref = {k: [] for k in ("M", "bias", "passive", "actuator", "inverse")}
    while len(states["qpos"]) < BATCH:
        q, v, u, _ = _random_state(model, rng)
        data.qpos[:], data.qvel[:], data.ctrl[:] = q, v, u
        mujoco.mj_forward(model, data)
        if data.nefc:
            continue
        full = np.zeros((model.nv, model.nv))
        mujoco.mj_fullM(model, data, full)
        ref["M"].append(full)
        ref["bias"].append(data.qfrc_bias.copy())
        ref["passive"].append(data.qfrc_passive.copy())
        ref["actuator"].append(data.qfrc_actuator.copy())
        qacc_in = rng.normal(size=model.nv)
        data.qacc[:] = qacc_in
        mujoco.mj_inverse(model, data)
        ref["inverse"].append(data.qfrc_inverse.copy())
        for k, x in zip(states, (q, v, u, qacc_in)):
            states[k].append(x)
    return {k: np.stack(v) for k, v in states.items()}, {k: np.stack(v) for k, v in ref.items()}


def _constrained_oracle(path, seed, n=BATCH):
    """Random states with contacts and active limits (the robots lowered into their floor) and
    MuJoCo's ``mj_forward`` and ``mj_step`` there, from a random warm start."""
    model = mujoco.MjModel.from_xml_path(path)
    name = os.path.basename(path)[:-4]
    data = mujoco.MjData(model)
    rng = np.random.default_rng(seed)
    out = {k: [] for k in ("qpos", "qvel", "ctrl", "applied", "warm")}
    ref = {k: [] for k in ("qacc", "nefc", "ncon", "qpos1", "qvel1", "warm1")}
    while len(out["qpos"]) < n:
        lift = rng.uniform(-0.1, 0.3) if name in FLOORED else 3.0
        q, v, u, fa = _random_state(model, rng, lift)
        warm = rng.normal(size=model.nv)
        data.qpos[:], data.qvel[:], data.ctrl[:], data.qfrc_applied[:] = q, v, u, fa
        data.qacc_warmstart[:] = warm
        mujoco.mj_forward(model, data)
        if not data.nefc or (name in FLOORED and not data.ncon):
            continue  # a state with constraints (and contacts where the robot has a floor)
        ref["qacc"].append(data.qacc.copy())
        ref["nefc"].append(data.nefc)
        ref["ncon"].append(int(np.sum(data.contact.exclude == 0)) if data.ncon else 0)
        data.qacc_warmstart[:] = warm
        mujoco.mj_step(model, data)
        ref["qpos1"].append(data.qpos.copy())
        ref["qvel1"].append(data.qvel.copy())
        ref["warm1"].append(data.qacc_warmstart.copy())
        for k, x in zip(out, (q, v, u, fa, warm)):
            out[k].append(x)
    return model, {k: np.stack(v) for k, v in out.items()}, {k: np.stack(v) for k, v in ref.items()}


@pytest.fixture(scope="module")
def trees():
    cache = {}

    def get(name):
        if name not in cache:
            cache[name] = ivy_robot.KinematicTree.from_mjcf(GYMNASIUM[name])
        return cache[name]

    return get


def _close(got, expected, key, tol=1e-10):
    got = numpy_of(got)
    scale = max(1.0, float(np.abs(expected).max(initial=0.0)))
    np.testing.assert_allclose(got, expected, rtol=tol, atol=tol * scale, err_msg=key)


# ----------------------------------------------------------------------------------------------
# The smooth dynamics
# ----------------------------------------------------------------------------------------------


def _compare_smooth(tree, states, ref, backend):
    s = {k: native(v, backend) for k, v in states.items()}
    got = {
        "M": tree.mass_matrix(s["qpos"]),
        "bias": tree.bias_forces(s["qpos"], s["qvel"]),
        "passive": tree.passive_forces(s["qpos"], s["qvel"]),
        "actuator": tree.actuator_forces(s["qpos"], s["qvel"], s["ctrl"]),
        "inverse": tree.inverse_dynamics(s["qpos"], s["qvel"], s["qacc_in"]),
    }
    for key, value in got.items():
        assert numpy_of(value).dtype == np.float64, key
        _close(value, ref[key], key)


@pytest.mark.parametrize("name", sorted(set(GYMNASIUM) - REFUSED))
def test_smooth_dynamics_match_mujoco_numpy(name, trees):
    states, ref = _smooth_oracle(GYMNASIUM[name], seed=len(name))
    _compare_smooth(trees(name), states, ref, "numpy")


def test_smooth_dynamics_match_mujoco_on_every_backend(backend, trees):
    states, ref = _smooth_oracle(GYMNASIUM["hopper"], seed=1)
    _compare_smooth(trees("hopper"), states, ref, backend)


# ----------------------------------------------------------------------------------------------
# The constrained dynamics: mj_forward and mj_step
# ----------------------------------------------------------------------------------------------


def _forward_and_step(tree, backend):
    """``(qacc, qpos1, qvel1, warm1)`` of the tree's forward and step, compiled on the
    backends whose eager mode compiles op by op (jax) or is slow to trace (tensorflow)."""

    def run(q, v, u, fa, w):
        data = tree.make_data(q, v, u, fa, w)
        after = tree.step_data(data)
        return tree.forward_data(data).qacc, after.qpos, after.qvel, after.qacc_warmstart

    return ivy.compile_fn(run) if capable(backend, "fast_graph") else run


def _compare_constrained(tree, states, ref, backend, tol=1e-9):
    args = [native(states[k], backend) for k in ("qpos", "qvel", "ctrl", "applied", "warm")]
    qacc, qpos1, qvel1, warm1 = _forward_and_step(tree, backend)(*args)
    _close(qacc, ref["qacc"], "qacc", tol)
    _close(qpos1, ref["qpos1"], "qpos after a step", tol)
    _close(qvel1, ref["qvel1"], "qvel after a step", tol)
    _close(warm1, ref["warm1"], "qacc_warmstart after a step", tol)


@pytest.mark.parametrize(
    "name",
    ["hopper", "walker2d_v5", "half_cheetah", "ant", "swimmer", "reacher",
     "inverted_pendulum", "inverted_double_pendulum"],
)  # fmt: skip
def test_constrained_dynamics_match_mujoco_numpy(name, trees):
    model, states, ref = _constrained_oracle(GYMNASIUM[name], seed=len(name) + 10)
    _compare_constrained(trees(name), states, ref, "numpy")


def test_humanoid_pgs_matches_mujoco(trees):
    """Humanoid-v5's model solves with PGS (50 iterations), reproduced iterate for iterate."""
    model, states, ref = _constrained_oracle(GYMNASIUM["humanoid"], seed=3)
    assert model.opt.solver == mujoco.mjtSolver.mjSOL_PGS
    _compare_constrained(trees("humanoid"), states, ref, "numpy", tol=1e-6)


@pytest.mark.parametrize("name", ["hopper", "ant"])
def test_constrained_dynamics_match_mujoco_on_every_backend(name, backend, trees):
    model, states, ref = _constrained_oracle(GYMNASIUM[name], seed=7)
    _compare_constrained(trees(name), states, ref, backend)


def test_free_running_with_contacts_follows_mujoco(trees):
    """150 steps of the Hopper falling onto its floor and resting there: the trajectory stays
    within 1e-8 of mj_step's (warm start carried as MuJoCo carries it)."""
    model = mujoco.MjModel.from_xml_path(GYMNASIUM["hopper"])
    data = mujoco.MjData(model)
    rng = np.random.default_rng(11)
    data.qpos[:] = model.qpos0 + 0.05 * rng.normal(size=model.nq)
    data.qpos[1] += 0.05  # dropped from 5 cm
    tree = trees("hopper")
    state = tree.make_data(data.qpos.copy(), data.qvel.copy(), np.zeros(model.nu))
    touched = 0
    for _ in range(150):
        mujoco.mj_step(model, data)
        state = tree.step_data(state)
        touched += int(np.any(numpy_of(state.contact_active)))
        np.testing.assert_allclose(numpy_of(state.qpos), data.qpos, rtol=0, atol=1e-8)
        np.testing.assert_allclose(numpy_of(state.qvel), data.qvel, rtol=1e-8, atol=1e-8)
    assert touched > 10, "the hopper never reached its floor"


# ----------------------------------------------------------------------------------------------
# Gradients and compilation
# ----------------------------------------------------------------------------------------------


def _one_autodiff_backend(config):
    chosen = [b for b in config.ivy_backends if capable(b, "autodiff")]
    if not chosen:
        pytest.skip("no autodiff backend selected")
    return chosen[0]


def _steps(tree, n):
    def run(qpos, qvel, ctrl):
        data = tree.make_data(qpos, qvel, ctrl)
        for _ in range(n):
            data = tree.step_data(data)
        return ivy.concat([data.qpos, data.qvel], axis=-1)

    return run


def _standing(name, rng):
    """A state at rest on the floor, pressed 5 mm further in (at rest the soft contacts sit at
    their margin, where they switch on), with controls inside their range: the set of contacts
    and limits stays the same under small perturbations for a few steps."""
    model = mujoco.MjModel.from_xml_path(GYMNASIUM[name])
    data = mujoco.MjData(model)
    data.qpos[:] = model.qpos0
    for _ in range(300):  # settle on the floor
        mujoco.mj_step(model, data)
    data.qpos[model.jnt_qposadr[0] + (2 if model.jnt_type[0] == 0 else 1)] -= 0.005
    ctrl = 0.3 * rng.uniform(-1, 1, size=model.nu)
    return data.qpos.copy(), data.qvel.copy() + 0.01 * rng.normal(size=model.nv), ctrl


#: (model, steps) per backend: tensorflow takes minutes to build the gradient of Ant steps
#: and of several Hopper steps, jax a minute to compile three Ant steps' (the same code runs on
#: every backend; each checks one case, the Ant on torch)
GRADIENT_CASES = {"torch": ("ant", 3), "jax": ("hopper", 2), "tensorflow": ("hopper", 1)}


def test_gradients_through_steps_with_contacts(diff_backend, trees):
    """Gradients of steps resting on the floor (contacts active throughout) w.r.t. position,
    velocity and control equal central differences (of step 1e-7: stiff contacts leave a
    truncation error of 2e-5 at the usual 1e-5)."""
    name, steps = GRADIENT_CASES.get(diff_backend, ("hopper", 3))
    q, v, u = _standing(name, np.random.default_rng(2))
    tree = trees(name)
    data = tree.forward_data(tree.make_data(q, v, u))
    assert numpy_of(data.contact_active).any()
    run = _steps(tree, steps)
    if capable(diff_backend, "fast_graph"):
        run = ivy.compile_fn(run)
    check_gradients(diff_backend, run, [q, v, u], rtol=1e-5, step=1e-7)


def test_gradients_of_forward_dynamics_at_a_limit(diff_backend, trees):
    model, states, _ = _constrained_oracle(GYMNASIUM["inverted_pendulum"], seed=5, n=1)
    tree = trees("inverted_pendulum")
    q, v, u = states["qpos"][0], states["qvel"][0], 0.9 * np.clip(states["ctrl"][0], -3, 3)
    check_gradients(diff_backend, tree.forward_dynamics, [q, v, u], rtol=1e-6)


def test_compiled_equals_eager(graph_backend, trees):
    _, states, _ = _constrained_oracle(GYMNASIUM["hopper"], seed=4)
    tree = trees("hopper")
    args = [native(states[k], graph_backend) for k in ("qpos", "qvel", "ctrl")]
    compiled = ivy.compile_fn(_steps(tree, 2))(*args)
    eager = _steps(tree, 2)(*args)
    np.testing.assert_allclose(numpy_of(compiled), numpy_of(eager), rtol=1e-11, atol=1e-11)


def test_first_use_inside_torch_compile():
    """A fresh tree whose first use is torch.compile's trace, compiling a step as users do
    (``ivy.compile_fn``: no graph break may fall back to eager mode): its RK4 stages and the
    solver's loops inside them stay torch's loop operators. The positions and velocities are
    slices of one state vector, as ivy_gym's tasks carry them (torch's loop operators refuse
    captured tensors that share memory). One case: compiling is slow."""
    torch = pytest.importorskip("torch")
    tree = ivy_robot.KinematicTree.from_mjcf(GYMNASIUM["inverted_pendulum"])
    _, states, _ = _constrained_oracle(GYMNASIUM["inverted_pendulum"], seed=2)
    q, v, u = (native(states[k], "torch") for k in ("qpos", "qvel", "ctrl"))
    nq = q.shape[-1]

    def step(state, ctrl):
        return _steps(tree, 1)(state[..., :nq], state[..., nq:], ctrl)

    with warnings.catch_warnings():
        warnings.filterwarnings("error", message="torch.compile cannot run")
        compiled = ivy.compile_fn(step)(torch.cat([q, v], -1), u)
    eager = _steps(tree, 1)(q, v, u)
    np.testing.assert_allclose(numpy_of(compiled), numpy_of(eager), rtol=1e-12, atol=1e-12)


def test_batch_shape_and_dtype(backend, trees):
    tree = trees("hopper")
    model, states, ref = _constrained_oracle(GYMNASIUM["hopper"], seed=8)
    q = native(states["qpos"].reshape(1, BATCH, -1).astype(np.float32), backend)
    v = native(states["qvel"].reshape(1, BATCH, -1).astype(np.float32), backend)
    qacc = tree.forward_dynamics(q, v, native(states["ctrl"].reshape(1, BATCH, -1), backend))
    assert numpy_of(qacc).dtype == np.float32 and tuple(qacc.shape) == (1, BATCH, model.nv)
    assert np.isfinite(numpy_of(qacc)).all()
    unbatched = tree.forward_dynamics(
        native(states["qpos"][0], backend),
        native(states["qvel"][0], backend),
        native(states["ctrl"][0], backend),
        native(states["applied"][0] * 0.0, backend),
        native(states["warm"][0], backend),
    )
    assert tuple(unbatched.shape) == (model.nv,)


# ----------------------------------------------------------------------------------------------
# Where constraints act
# ----------------------------------------------------------------------------------------------


def test_active_limits_match_mujoco_limit_constraints(trees):
    model = mujoco.MjModel.from_xml_path(GYMNASIUM["hopper"])
    tree = trees("hopper")
    data = mujoco.MjData(model)
    rng = np.random.default_rng(3)
    qpos = np.tile(model.qpos0, (200, 1)) + rng.normal(scale=1.0, size=(200, model.nq))
    qpos[:, 1] += 3.0  # lifted: no contacts
    mask = tree.active_limits(qpos)
    assert mask.shape == (200, model.njnt) and mask.any() and not mask.all()
    for q, row in zip(qpos, mask):
        data.qpos[:] = q
        mujoco.mj_forward(model, data)
        limited = {
            int(data.efc_id[i])
            for i in range(data.nefc)
            if data.efc_type[i] == mujoco.mjtConstraint.mjCNSTR_LIMIT_JOINT
        }
        assert set(np.flatnonzero(row).tolist()) == limited


@pytest.mark.parametrize("name", ["hopper", "ant", "humanoid"])
def test_contacts_are_mujocos(name, trees):
    """possible_contacts is True exactly where MuJoCo has a contact in its constraints, and
    constraint_free where it has no constraint row at all."""
    model = mujoco.MjModel.from_xml_path(GYMNASIUM[name])
    tree = trees(name)
    data = mujoco.MjData(model)
    rng = np.random.default_rng(5)
    lifts = np.concatenate([[1.5] * 10, rng.uniform(-0.2, 0.3, 20)])
    qpos = np.stack([_random_state(model, rng, lift)[0] for lift in lifts])
    flagged, free = tree.possible_contacts(qpos), tree.constraint_free(qpos)
    contact, constrained = [], []
    for q in qpos:
        data.qpos[:] = q
        mujoco.mj_forward(model, data)
        contact.append(bool(data.ncon) and bool(np.any(data.contact.exclude == 0)))
        constrained.append(data.nefc > 0)
    assert any(contact) and not all(contact)
    np.testing.assert_array_equal(flagged, contact)
    np.testing.assert_array_equal(free, np.logical_not(constrained))


# ----------------------------------------------------------------------------------------------
# Every feature: modelled (against MuJoCo) or refused by name
# ----------------------------------------------------------------------------------------------

_ARM = """<mujoco>{option}<worldbody><geom type="plane" size="5 5 .1"/>
  <body pos="0 0 .2"><joint name="a" type="hinge" axis="0 1 0" {joint}/>
    <geom type="capsule" fromto="0 0 0 .3 0 0" size=".05" {geom}/>
    <body pos=".3 0 0"><joint name="b" type="hinge" axis="0 1 0" range="-30 30" limited="true"/>
      <geom type="capsule" fromto="0 0 0 .3 0 0" size=".04"/></body></body>
  </worldbody>{extra}</mujoco>"""

MODELLED = {
    "joint friction loss": dict(joint='frictionloss="0.8"'),
    "joint limits with margin and solimp": dict(
        joint='range="-20 20" limited="true" margin="0.05" solimplimit="0.5 0.9 0.2 0.3 3"'
    ),
    "contacts with condim 1": dict(geom='condim="1"'),
    "contact priority and solmix": dict(geom='priority="1" solref="0.03 0.8" friction="0.6"'),
    "disabled warm start": dict(option='<option><flag warmstart="disable"/></option>'),
    "PGS": dict(option='<option solver="PGS" iterations="30"/>'),
    "Euler with damping": dict(option='<option integrator="Euler"/>', joint='damping="0.4"'),
    "impratio": dict(option='<option impratio="3"/>'),
}
REFUSED_FEATURES = {
    "tendon friction loss": (
        dict(extra='<tendon><fixed frictionloss="1"><joint joint="a" coef="1"/></fixed></tendon>'),
        "tendon friction loss",
    ),
    "tendon armature": (
        dict(extra='<tendon><fixed armature="1"><joint joint="a" coef="1"/></fixed></tendon>'),
        "tendon armature",
    ),
    "polynomial damping": (dict(joint='damping="1 0.5 0.1"'), "polynomial joint damping"),
    "polynomial stiffness": (dict(joint='stiffness="1 0.5 0.1"'), "polynomial joint stiffness"),
    "actuator damping": (
        dict(extra='<actuator><motor joint="a" damping="0.3"/></actuator>'),
        "with damping",
    ),
    "actuator armature": (
        dict(extra='<actuator><motor joint="a" armature="0.3"/></actuator>'),
        "with armature",
    ),
    "actuator delay": (
        dict(extra='<actuator><motor joint="a" delay="0.01" nsample="2"/></actuator>'),
        "delay",
    ),
    "actuatorgroupdisable": (
        dict(
            option='<option actuatorgroupdisable="1"/>',
            extra='<actuator><motor joint="a" group="1"/></actuator>',
        ),
        "actuatorgroupdisable",
    ),
    "elliptic cones": (dict(option='<option cone="elliptic"/>'), "elliptic"),
    "condim 4": (dict(geom='condim="4"'), "condim"),
    "condim 6": (dict(geom='condim="6"'), "condim"),
    "equality constraints": (
        dict(extra='<equality><joint joint1="a" joint2="b"/></equality>'),
        "equality",
    ),
    "noslip": (dict(option='<option noslip_iterations="3"/>'), "noslip"),
    "implicit integrator": (dict(option='<option integrator="implicitfast"/>'), "integrator"),
    "CG solver": (dict(option='<option solver="CG"/>'), "CG"),
}


def _arm(**parts):
    return _ARM.format(**{k: parts.get(k, "") for k in ("option", "joint", "geom", "extra")})


@pytest.mark.parametrize("feature", sorted(MODELLED))
def test_modelled_features_match_mujoco(feature):
    xml = _arm(**MODELLED[feature])
    model = mujoco.MjModel.from_xml_string(xml)
    tree = ivy_robot.KinematicTree.from_mjcf(model)
    data = mujoco.MjData(model)
    state = tree.make_data(model.qpos0.copy(), np.zeros(model.nv))
    rows = 0
    for _ in range(150):  # falls onto its floor, its joints against their limits
        data.ctrl[:] = 0.0
        mujoco.mj_step(model, data)
        state = tree.step_data(state)
        rows += data.nefc
        np.testing.assert_allclose(numpy_of(state.qpos), data.qpos, rtol=0, atol=1e-9)
        np.testing.assert_allclose(numpy_of(state.qvel), data.qvel, rtol=1e-8, atol=1e-8)
    assert rows > 0


@pytest.mark.parametrize("feature", sorted(REFUSED_FEATURES))
def test_unmodelled_features_are_refused_by_name(feature):
    parts, message = REFUSED_FEATURES[feature]
    tree = ivy_robot.KinematicTree.from_mjcf(_arm(**parts))
    tree.forward_kinematics(np.zeros(tree.nq))  # kinematics work on every model
    with pytest.raises(NotImplementedError, match=message):
        tree.forward_dynamics(np.zeros(tree.nq), np.zeros(tree.nv))
    with pytest.raises(NotImplementedError, match=message):
        tree.step(np.zeros(tree.nq), np.zeros(tree.nv))


def test_gravity_compensation_and_unmodelled_pairs_are_refused():
    xml = _ARM.format(option="", joint="", geom="", extra="").replace(
        '<body pos="0 0 .2">', '<body pos="0 0 .2" gravcomp="1">'
    )
    with pytest.raises(NotImplementedError, match="gravity compensation"):
        ivy_robot.KinematicTree.from_mjcf(xml).mass_matrix(np.zeros(2))
    pusher = ivy_robot.KinematicTree.from_mjcf(GYMNASIUM["pusher"])
    with pytest.raises(NotImplementedError, match="capsule.*cylinder"):
        pusher.forward_dynamics(np.zeros(pusher.nq), np.zeros(pusher.nv))


# ----------------------------------------------------------------------------------------------
# Input
# ----------------------------------------------------------------------------------------------


def test_bad_input_raises(trees):
    tree = trees("hopper")
    q, v = np.zeros((BATCH, tree.nq)), np.zeros((BATCH, tree.nv))
    with pytest.raises(ValueError, match="qvel has shape"):
        tree.bias_forces(q, v[:, :2])
    with pytest.raises(ValueError, match="ctrl has shape"):
        tree.forward_dynamics(q, v, np.zeros((BATCH, 7)))
    with pytest.raises(ValueError, match="qacc_warmstart has shape"):
        tree.step(q, v, None, None, np.zeros((BATCH, 2)))
    with pytest.raises(TypeError, match="qvel has dtype"):
        tree.bias_forces(q, v.astype(np.float32))
    with pytest.raises(TypeError, match="qpos has dtype"):
        tree.mass_matrix(np.zeros((2, tree.nq), dtype=np.int64))


def test_position_actuator_matches_mujoco():
    xml = """<mujoco><option integrator="Euler" timestep="0.005"/><worldbody><body>
      <joint name="a" type="hinge" axis="0 1 0" damping="0.3" stiffness="2" springref="0.4"
             armature="0.05"/>
      <geom type="capsule" fromto="0 0 0 .3 0 0" size=".03"/>
      <body pos=".3 0 0"><joint name="b" type="slide" axis="1 0 0"/><geom size=".05"/></body>
      </body></worldbody>
      <actuator><position joint="a" kp="20" kv="1.5" ctrlrange="-1 1" forcerange="-3 3"/>
      <motor joint="b" gear="2"/></actuator></mujoco>"""
    model = mujoco.MjModel.from_xml_string(xml)
    tree = ivy_robot.KinematicTree.from_mjcf(model)
    data = mujoco.MjData(model)
    rng = np.random.default_rng(0)
    for _ in range(5):
        q, v, u = rng.normal(size=2), rng.normal(size=2), rng.normal(size=2)
        data.qpos[:], data.qvel[:], data.ctrl[:] = q, v, u
        data.qacc_warmstart[:] = 0.0
        mujoco.mj_forward(model, data)
        np.testing.assert_allclose(tree.actuator_forces(q, v, u), data.qfrc_actuator, **TOL)
        np.testing.assert_allclose(tree.passive_forces(q, v), data.qfrc_passive, **TOL)
        np.testing.assert_allclose(tree.forward_dynamics(q, v, u), data.qacc, **TOL)
        mujoco.mj_step(model, data)
        q1, v1 = tree.step(q, v, u)
        np.testing.assert_allclose(q1, data.qpos, **TOL)
        np.testing.assert_allclose(v1, data.qvel, **TOL)
