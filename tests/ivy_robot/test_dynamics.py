"""KinematicTree dynamics against MuJoCo: mass matrix (``mj_fullM``), bias, passive and actuator
forces, inverse dynamics (``mj_inverse``), forward dynamics (``mj_forward``'s ``qacc``) and a step
(``mj_step``) on every MJCF model Gymnasium ships, at random states free of contacts and active
joint limits, in float64; gradients against central differences; compiled equals eager; the
contact and limit masks; bad input and unsupported models raise."""

from __future__ import annotations

import os

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
# Gymnasium's point and pusher models touch their floor and table in every state (the point rolls
# on the floor; the pusher's arm sweeps the table): their oracle runs with contacts disabled.
ALWAYS_IN_CONTACT = {"point", "pusher", "pusher_v5"}


def _disable(model, *bits):
    for bit in bits:
        model.opt.disableflags |= int(getattr(mujoco.mjtDisableBit, bit))


def _random_state(model, data, rng):
    """A random (qpos, qvel, ctrl, qfrc_applied) inside the joint ranges, free roots lifted."""
    q = model.qpos0.copy()
    for j in range(model.njnt):
        adr, kind = model.jnt_qposadr[j], model.jnt_type[j]
        if kind == 0:
            q[adr : adr + 3] = rng.normal(size=3) * 0.3 + [0.0, 0.0, 3.0]
            quat = rng.normal(size=4)
            q[adr + 3 : adr + 7] = quat / np.linalg.norm(quat)
        elif model.jnt_limited[j]:
            lo, hi = model.jnt_range[j]
            q[adr] = rng.uniform(lo + 0.1 * (hi - lo), hi - 0.1 * (hi - lo))
        else:
            q[adr] = rng.normal() + (3.0 if kind == 2 and model.jnt_axis[j][2] > 0.5 else 0.0)
    lo, hi = model.actuator_ctrlrange.T if model.nu else (np.zeros(0), np.zeros(0))
    ctrl = rng.uniform(lo - 0.2, hi + 0.2)  # some controls beyond the range: clamped
    return q, rng.normal(size=model.nv), ctrl, rng.normal(size=model.nv)


def _oracle(path, seed):
    """Random constraint-free states and MuJoCo's quantities there."""
    model = mujoco.MjModel.from_xml_path(path)
    name = os.path.basename(path)[:-4]
    if name in ALWAYS_IN_CONTACT:
        _disable(model, "mjDSBL_CONTACT")
    data = mujoco.MjData(model)
    rng = np.random.default_rng(seed)
    out = {k: [] for k in ("qpos", "qvel", "ctrl", "applied", "qacc_in")}
    ref = {k: [] for k in ("M", "bias", "passive", "actuator", "qacc", "inverse", "qpos1", "qvel1")}
    while len(out["qpos"]) < BATCH:
        q, v, u, fa = _random_state(model, data, rng)
        data.qpos[:], data.qvel[:], data.ctrl[:], data.qfrc_applied[:] = q, v, u, fa
        mujoco.mj_forward(model, data)
        if data.ncon or data.nefc:
            continue
        full = np.zeros((model.nv, model.nv))
        mujoco.mj_fullM(model, data, full)
        ref["M"].append(full)
        ref["bias"].append(data.qfrc_bias.copy())
        ref["passive"].append(data.qfrc_passive.copy())
        ref["actuator"].append(data.qfrc_actuator.copy())
        ref["qacc"].append(data.qacc.copy())
        qacc_in = rng.normal(size=model.nv)
        data.qacc[:] = qacc_in
        mujoco.mj_inverse(model, data)
        ref["inverse"].append(data.qfrc_inverse.copy())
        for k, x in zip(out, (q, v, u, fa, qacc_in)):
            out[k].append(x)
    # the step: contacts and limits off, since a step may reach one from a free state
    smooth = mujoco.MjModel.from_xml_path(path)
    _disable(smooth, "mjDSBL_CONTACT", "mjDSBL_LIMIT")
    data = mujoco.MjData(smooth)
    for q, v, u, fa in zip(out["qpos"], out["qvel"], out["ctrl"], out["applied"]):
        data.qpos[:], data.qvel[:], data.ctrl[:], data.qfrc_applied[:] = q, v, u, fa
        mujoco.mj_step(smooth, data)
        ref["qpos1"].append(data.qpos.copy())
        ref["qvel1"].append(data.qvel.copy())
    stack = lambda d: {k: np.stack(v) for k, v in d.items()}  # noqa: E731
    return model, stack(out), stack(ref)


@pytest.fixture(scope="module")
def oracles():
    cache = {}

    def get(name):
        if name not in cache:
            path = GYMNASIUM[name]
            model, states, ref = _oracle(path, seed=len(name))
            cache[name] = (model, ivy_robot.KinematicTree.from_mjcf(path), states, ref)
        return cache[name]

    return get


def _compare(tree, model, states, ref, backend):
    s = {k: native(v, backend) for k, v in states.items()}
    got = {
        "M": tree.mass_matrix(s["qpos"]),
        "bias": tree.bias_forces(s["qpos"], s["qvel"]),
        "passive": tree.passive_forces(s["qpos"], s["qvel"]),
        "actuator": tree.actuator_forces(s["qpos"], s["qvel"], s["ctrl"]),
        "qacc": tree.forward_dynamics(s["qpos"], s["qvel"], s["ctrl"], s["applied"]),
        "inverse": tree.inverse_dynamics(s["qpos"], s["qvel"], s["qacc_in"]),
    }
    got["qpos1"], got["qvel1"] = tree.step(s["qpos"], s["qvel"], s["ctrl"], s["applied"])
    for key, value in got.items():
        value = numpy_of(value)
        assert value.dtype == np.float64, key
        expected = ref[key]
        scale = max(1.0, float(np.abs(expected).max(initial=0.0)))
        np.testing.assert_allclose(value, expected, rtol=1e-10, atol=1e-10 * scale, err_msg=key)


@pytest.mark.parametrize("name", sorted(GYMNASIUM))
def test_every_gymnasium_model_matches_mujoco_numpy(name, oracles):
    model, tree, states, ref = oracles(name)
    _compare(tree, model, states, ref, "numpy")


@pytest.mark.parametrize("name", ["inverted_pendulum"])
def test_dynamics_match_mujoco_on_every_backend(name, backend, oracles):
    model, tree, states, ref = oracles(name)
    _compare(tree, model, states, ref, backend)


def _one_autodiff_backend(config):
    chosen = [b for b in config.ivy_backends if capable(b, "autodiff")]
    if not chosen:
        pytest.skip("no autodiff backend selected")
    return chosen[0]


def test_every_gymnasium_model_matches_mujoco_autodiff_backend(oracles, request):
    """All models on one autodiff backend (the first selected)."""
    backend = _one_autodiff_backend(request.config)
    for name in sorted(GYMNASIUM):
        model, tree, states, ref = oracles(name)
        _compare(tree, model, states, ref, backend)


def _step_state(tree):
    def step(qpos, qvel, ctrl):
        qpos1, qvel1 = tree.step(qpos, qvel, ctrl)
        return ivy.concat([qpos1, qvel1], axis=-1)

    return step


def _inside_ctrl(model, ctrl):
    """Controls strictly inside their range (away from the clamp's kinks)."""
    return 0.9 * np.clip(ctrl, *model.actuator_ctrlrange.T)


def test_forward_dynamics_gradients_match_finite_differences(diff_backend, oracles):
    model, tree, states, _ = oracles("inverted_pendulum")
    q, v, u = states["qpos"][0], states["qvel"][0], _inside_ctrl(model, states["ctrl"][0])
    check_gradients(diff_backend, tree.forward_dynamics, [q, v, u], rtol=1e-6)


@pytest.mark.parametrize("name", ["inverted_double_pendulum", "swimmer", "ant", "half_cheetah"])
def test_step_gradients_match_finite_differences(name, oracles, request):
    """Through RK4 (pendulum, swimmer's fluid drag, the ant's free joint) and Euler with
    implicit damping (half cheetah), on one autodiff backend."""
    model, tree, states, _ = oracles(name)
    backend = _one_autodiff_backend(request.config)
    q, v, u = states["qpos"][0], states["qvel"][0], _inside_ctrl(model, states["ctrl"][0])
    check_gradients(backend, _step_state(tree), [q, v, u], rtol=1e-6)


def _compiled_first_use_equals_eager(backend, oracles):
    """A fresh tree, whose first use is the compiled call: its constants must not be read from
    MuJoCo inside the trace, which torch.compile cannot follow."""
    _, _, states, _ = oracles("inverted_pendulum")
    tree = ivy_robot.KinematicTree.from_mjcf(GYMNASIUM["inverted_pendulum"])
    q, v, u = (native(states[k], backend) for k in ("qpos", "qvel", "ctrl"))
    compiled = ivy.compile_fn(lambda q, v, u: tree.forward_dynamics(q, v, u))(q, v, u)
    eager = tree.forward_dynamics(q, v, u)
    np.testing.assert_allclose(numpy_of(compiled), numpy_of(eager), rtol=1e-12, atol=1e-12)


def test_compiled_equals_eager(graph_backend, oracles):
    _compiled_first_use_equals_eager(graph_backend, oracles)


def test_first_use_inside_torch_compile(oracles):
    """dynamo failed in the MuJoCo calls with a RecursionError when the constants were read on
    first use; torch.compile is slow to start, so torch has this one case."""
    pytest.importorskip("torch")
    _compiled_first_use_equals_eager("torch", oracles)


def test_batch_shape_and_dtype(backend, oracles):
    model, tree, states, ref = oracles("inverted_pendulum")
    q = native(states["qpos"].reshape(1, BATCH, -1).astype(np.float32), backend)
    v = native(states["qvel"].reshape(1, BATCH, -1).astype(np.float32), backend)
    qacc = tree.forward_dynamics(q, v, native(states["ctrl"].reshape(1, BATCH, -1), backend))
    assert numpy_of(qacc).dtype == np.float32 and tuple(qacc.shape) == (1, BATCH, model.nv)
    M = tree.mass_matrix(q)
    np.testing.assert_allclose(numpy_of(M)[0], ref["M"], rtol=1e-4, atol=1e-5)
    unbatched = tree.bias_forces(
        native(states["qpos"][0], backend), native(states["qvel"][0], backend)
    )
    np.testing.assert_allclose(numpy_of(unbatched), ref["bias"][0], **TOL)


def test_active_limits_match_mujoco_limit_constraints():
    model = mujoco.MjModel.from_xml_path(GYMNASIUM["hopper"])
    tree = ivy_robot.KinematicTree.from_mjcf(GYMNASIUM["hopper"])
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


@pytest.mark.parametrize("name", ["hopper", "ant", "walker2d", "humanoid"])
def test_contact_mask_is_conservative(name):
    """Wherever MuJoCo finds a contact, possible_contacts is True; far from everything, False."""
    model = mujoco.MjModel.from_xml_path(GYMNASIUM[name])
    tree = ivy_robot.KinematicTree.from_mjcf(GYMNASIUM[name])
    data = mujoco.MjData(model)
    rng = np.random.default_rng(5)
    qpos = np.stack([_random_state(model, data, rng)[0] for _ in range(60)])
    lift = np.concatenate([[1.5] * 20, [0.0] * 20, [-2.5] * 20])  # above, around, into the floor
    root = model.jnt_qposadr[0] + (2 if model.jnt_type[0] == 0 else 0)
    qpos[:, root] += lift
    flagged = tree.possible_contacts(qpos)
    free = tree.constraint_free(qpos)
    touching = []
    for q in qpos:
        data.qpos[:] = q
        mujoco.mj_forward(model, data)
        touching.append(data.ncon > 0)
    touching = np.asarray(touching)
    assert touching.any()
    assert np.all(flagged[touching]), "a MuJoCo contact that possible_contacts missed"
    assert not np.any(free[touching])
    if name != "humanoid":  # the humanoid's limbs' bounding spheres always overlap
        assert not flagged[:20].all()


def test_bad_input_raises(oracles):
    _, tree, states, _ = oracles("hopper")
    q, v = states["qpos"], states["qvel"]
    with pytest.raises(ValueError, match="qvel has shape"):
        tree.bias_forces(q, v[:, :2])
    with pytest.raises(ValueError, match="ctrl has shape"):
        tree.forward_dynamics(q, v, np.zeros((BATCH, 7)))
    with pytest.raises(TypeError, match="qvel has dtype"):
        tree.bias_forces(q, v.astype(np.float32))
    with pytest.raises(TypeError, match="qpos has dtype"):
        tree.mass_matrix(np.zeros((2, tree.nq), dtype=np.int64))


@pytest.mark.parametrize(
    "option, message",
    [
        ('<option integrator="implicitfast"/>', "integrator"),
        ('<equality><joint joint1="a" joint2="b"/></equality>', "equality"),
    ],
)
def test_unsupported_models_raise(option, message):
    xml = f"""<mujoco>{option if "option" in option else ""}<worldbody><body>
      <joint name="a" type="hinge"/><geom size=".1" mass="1"/>
      <body pos="0 0 .3"><joint name="b" type="hinge"/><geom size=".1"/></body></body>
      </worldbody>{option if "option" not in option else ""}</mujoco>"""
    tree = ivy_robot.KinematicTree.from_mjcf(xml)
    with pytest.raises(NotImplementedError, match=message):
        tree.mass_matrix(np.zeros(tree.nq))


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
        mujoco.mj_forward(model, data)
        np.testing.assert_allclose(tree.actuator_forces(q, v, u), data.qfrc_actuator, **TOL)
        np.testing.assert_allclose(tree.passive_forces(q, v), data.qfrc_passive, **TOL)
        np.testing.assert_allclose(tree.forward_dynamics(q, v, u), data.qacc, **TOL)
        mujoco.mj_step(model, data)
        q1, v1 = tree.step(q, v, u)
        np.testing.assert_allclose(q1, data.qpos, **TOL)
        np.testing.assert_allclose(v1, data.qvel, **TOL)
