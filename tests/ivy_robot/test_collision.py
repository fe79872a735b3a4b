"""Collision detection (``ivy_robot.physics.collision``) against MuJoCo's ``mj_forward``: every
pair kind on small scenes (touching, penetrating, within margin, out of range, degenerate), the
contact table's filters, parameters and order on small scenes and on Gymnasium's models, the
refusals, gradients against central differences, and compiled equals eager."""

from __future__ import annotations

import functools
import os

import numpy as np
import pytest

import ivy
from ivy_robot.physics import collision as C
from tests.conftest import capable
from tests.helpers import native, native_value_and_grads, numpy_of
from tests.ivy_robot._models import gymnasium_models

mujoco = pytest.importorskip("mujoco")

GYMNASIUM = {os.path.basename(p)[:-4]: p for p in gymnasium_models()}
TOL = 1e-10
STEP = 1e-6  # central differences

# ----------------------------------------------------------------------------------------------
# The oracle
# ----------------------------------------------------------------------------------------------


def _poses(model, qpos):
    """MuJoCo's geom poses and contacts at each state of ``qpos [n, nq]``."""
    data = mujoco.MjData(model)
    xpos, xmat, contacts = [], [], []
    for q in qpos:
        data.qpos[:] = q
        mujoco.mj_forward(model, data)
        xpos.append(np.array(data.geom_xpos))
        xmat.append(np.array(data.geom_xmat).reshape(-1, 3, 3))
        contacts.append([_contact_record(c) for c in data.contact[: data.ncon]])
    return np.array(xpos), np.array(xmat), contacts


@functools.cache
def _collider(backend, table):
    """``collide`` on ``backend``, compiled where the backend compiles quickly (one compilation
    costs less there than running the kernels' many primitives eagerly for the first time;
    eager equals compiled: ``test_compiled_equals_eager``)."""
    xp = getattr(ivy, backend)

    def contacts(geom_xpos, geom_xmat):
        return tuple(C.collide(xp, table, geom_xpos, geom_xmat))

    return ivy.compile_fn(contacts) if capable(backend, "fast_graph") else contacts


def _contact_record(c) -> dict:
    return dict(
        geom=tuple(int(g) for g in c.geom),
        dist=c.dist,
        pos=np.array(c.pos),
        frame=np.array(c.frame).reshape(3, 3),
        condim=int(c.dim),
        friction=np.array(c.friction),
        solref=np.array(c.solref),
        solreffriction=np.array(c.solreffriction),
        solimp=np.array(c.solimp),
        includemargin=c.includemargin,
        active=c.efc_address >= 0,
    )


def _check(backend, model, qpos, table=None):
    """The table's candidates at MuJoCo's geom poses (one batched call): the found ones are
    ``d.contact`` in order, with its values; the active ones are its constraint contacts.
    Returns the number of MuJoCo contacts seen."""
    table = table or C.read_contact_table(model)
    xpos, xmat, reference = _poses(model, qpos)
    got = _collider(backend, table)(native(xpos, backend), native(xmat, backend))
    dist, pos, frame, found, active = (numpy_of(a) for a in got)
    assert dist.shape == (len(qpos), table.ncon) and frame.shape == (len(qpos), table.ncon, 3, 3)
    for i, contacts in enumerate(reference):
        rows = np.flatnonzero(found[i])
        listed = [(table.geom1[r], table.geom2[r]) for r in rows]
        assert listed == [c["geom"] for c in contacts], f"state {i}: found geoms"
        for r, c in zip(rows, contacts):
            ours = dict(
                dist=dist[i, r],
                pos=pos[i, r],
                frame=frame[i, r],
                condim=table.condim[r],
                friction=table.friction[r],
                solref=table.solref[r],
                solreffriction=table.solreffriction[r],
                solimp=table.solimp[r],
                includemargin=table.includemargin[r],
            )
            for key, value in ours.items():
                np.testing.assert_allclose(value, c[key], rtol=0, atol=TOL, err_msg=key)
        want = [k for k, c in enumerate(contacts) if c["active"]]
        assert [list(rows).index(r) for r in np.flatnonzero(active[i])] == want, f"state {i}"
    return sum(len(c) for c in reference)


def _quat(axis, angle) -> np.ndarray:
    q = np.zeros(4)
    axis = np.asarray(axis, np.float64)
    mujoco.mju_axisAngle2Quat(q, axis / np.linalg.norm(axis), angle)
    return q


def _mul(q1, q2) -> np.ndarray:
    q = np.zeros(4)
    mujoco.mju_mulQuat(q, np.asarray(q1, np.float64), np.asarray(q2, np.float64))
    return q


def _random_quats(rng, n) -> np.ndarray:
    q = rng.normal(size=(n, 4))
    return q / np.linalg.norm(q, axis=1, keepdims=True)


# ----------------------------------------------------------------------------------------------
# Pair kinds: one scene with every kind, each pair kept to itself by contype/conaffinity bits
# ----------------------------------------------------------------------------------------------

PLANE_QUAT = _quat([1.0, 0.5, 0.2], 0.4)
PLANE_ORIGIN = np.array([0.1, -0.2, 0.3])
#: name -> (type, size, contype = conaffinity bits); plane kinds first, then pairs of bodies
ZOO = {
    "sphere": ("sphere", "0.1", 1),
    "capsule": ("capsule", "0.1 0.3", 2),
    "box": ("box", "0.1 0.2 0.3", 4),
    "cylinder": ("cylinder", "0.1 0.3", 8),
    "ss1": ("sphere", "0.1", 16),
    "ss2": ("sphere", "0.2", 16),
    "sc1": ("sphere", "0.1", 32),
    "sc2": ("capsule", "0.15 0.3", 32),
    "cc1": ("capsule", "0.1 0.3", 64),
    "cc2": ("capsule", "0.15 0.2", 64),
}
PLANE_BODIES = ("sphere", "capsule", "box", "cylinder")
PAIR_BODIES = (("ss1", "ss2"), ("sc1", "sc2"), ("cc1", "cc2"))


@functools.cache
def _zoo_model():
    bodies = "".join(
        f'<body name="{name}" pos="0 0 3"><freejoint/><geom name="{name}" type="{kind}" '
        f'size="{size}" contype="{bits}" conaffinity="{bits}" margin="{0.02 if i % 2 else 0.01}"'
        f' gap="{0.0 if i % 3 else 0.01}"/></body>'
        for i, (name, (kind, size, bits)) in enumerate(ZOO.items())
    )
    quat = " ".join(map(str, PLANE_QUAT))
    xml = (
        f'<mujoco><worldbody><geom name="plane" type="plane" size="5 5 .1" pos="0.1 -0.2 0.3" '
        f'quat="{quat}" contype="15" conaffinity="15" margin="0.01" gap="0.005"/>{bodies}'
        "</worldbody></mujoco>"
    )
    return mujoco.MjModel.from_xml_string(xml)


def _rotation_of(quat) -> np.ndarray:
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, np.asarray(quat, np.float64))
    return mat.reshape(3, 3)


def _lowest(kind: int, size, centre, rot, normal) -> float:
    """A geom's lowest point along ``normal``."""
    along = rot.T @ normal
    height = centre @ normal
    if kind == C.SPHERE:
        return height - size[0]
    if kind == C.CAPSULE:
        return height - size[0] - size[1] * abs(along[2])
    if kind == C.CYLINDER:
        return height - size[0] * np.sqrt(max(0.0, 1 - along[2] ** 2)) - size[1] * abs(along[2])
    return height - np.abs(along) @ size[:3]


def _sizes(name) -> np.ndarray:
    return np.array([float(s) for s in ZOO[name][1].split()] + [0.0, 0.0])[:3]


def _plane_states(rng, n, name) -> np.ndarray:
    """One body about the plane: random orientations and heights from penetrating to out of
    range, then the degenerate orientations (aligned with the plane: a flat box face or cylinder
    cap, an upright capsule; upside down; on an edge; on the side; on a corner; tilted) 1 cm
    into the plane."""
    kind, size = getattr(C, ZOO[name][0].upper()), _sizes(name)
    frame = _rotation_of(PLANE_QUAT)
    normal = frame[:, 2]
    special = [
        PLANE_QUAT,
        _mul(PLANE_QUAT, [0.0, 1.0, 0.0, 0.0]),
        _mul(PLANE_QUAT, _quat([1, 0, 0], np.pi / 4)),
        _mul(PLANE_QUAT, _quat([1, 0, 0], np.pi / 2)),
        _mul(PLANE_QUAT, _quat([1, 1, 0], np.arccos(1 / np.sqrt(3)))),
        _mul(PLANE_QUAT, _quat([0, 1, 0], 0.3)),
    ]
    quats = list(_random_quats(rng, n - len(special))) + special
    reach = float(np.linalg.norm(size))
    q = np.zeros((n, 7))
    for i, quat in enumerate(quats):
        centre = PLANE_ORIGIN + frame[:, :2] @ rng.normal(size=2)
        if i < n - len(special):
            height = rng.uniform(-0.3 * reach, 1.3 * reach)
        else:
            height = -0.01 - (
                _lowest(kind, size, centre, _rotation_of(quat), normal) - centre @ normal
            )
        q[i] = np.concatenate([centre + normal * height, quat])
    return q


def _pair_states(rng, n) -> np.ndarray:
    """Two bodies: degenerate poses (coincident centres with parallel or crossing z axes, a
    sphere centre on the capsule axis; parallel and near-parallel axes: overlapping, end to
    end, coaxial, flipped), then random poses from penetrating to out of range."""
    special = []
    for quat in _random_quats(rng, 2):
        x, _, z = _rotation_of(quat).T
        base = np.concatenate([[0, 0, 0], quat, [0, 0, 0], quat])
        twisted = base.copy()
        twisted[10:14] = _mul(quat, _quat([1, 0, 0], 0.7))
        on_axis = base.copy()
        on_axis[7:10] = z * 0.1
        on_axis[10:14] = _mul(quat, _quat([1, 0, 0], 0.3))
        special += [base, twisted, on_axis]
        for offset, lateral in ((0.1, 0.2), (0.45, 0.1), (0.7, 0.0), (0.3, 0.24), (0.2, 0.0)):
            for flip, tilt in ((False, 0.0), (True, 0.0), (False, 3e-5), (True, 1e-3)):
                par = base.copy()  # geom 2 beside geom 1, moved along the axis
                par[7:10] = lateral * x + offset * z
                turn = _mul(_quat([0, 1, 0], tilt), [0, 1, 0, 0] if flip else [1, 0, 0, 0])
                par[10:14] = _mul(quat, turn)
                special.append(par)
    q = np.zeros((n - len(special), 14))
    q[:, 3:7], q[:, 10:14] = _random_quats(rng, len(q)), _random_quats(rng, len(q))
    q[:, 7:10] = rng.normal(size=(len(q), 3)) * 0.3
    return np.concatenate([np.array(special), q])


def _zoo_states(rng, n=60) -> np.ndarray:
    """States of the whole zoo: each plane body about the plane, each pair on its own island."""
    parts = [_plane_states(rng, n, name) for name in PLANE_BODIES]
    for k, _ in enumerate(PAIR_BODIES):
        pair = _pair_states(rng, n)
        island = np.array([3.0 * k - 3.0, 4.0, 3.0])
        pair[:, 0:3] += island
        pair[:, 7:10] += island
        parts.append(pair)
    return np.concatenate(parts, axis=1)


@functools.cache
def _zoo_table():
    return C.read_contact_table(_zoo_model())


def test_pair_kinds(backend):
    model, table = _zoo_model(), _zoo_table()
    assert sorted(k.types for k in table.kinds) == sorted(C.PAIR_KINDS)
    assert table.ncon == 1 + 2 + 4 + 4 + 1 + 1 + 2
    assert _check(backend, model, _zoo_states(np.random.default_rng(0)), table) > 100


def test_pair_kind_functions_alone():
    """A kind's function on one pair, unbatched, with a Python margin."""
    xp = ivy.numpy
    size = np.array([0.1, 0.2, 0.05])
    dist, pos, frame, found = C.plane_box(
        xp, np.zeros(3), np.eye(3), np.zeros(3), np.array([0, 0, 0.04]), np.eye(3), size, 0.0
    )
    np.testing.assert_allclose(dist, [-0.01] * 4, atol=1e-15)
    np.testing.assert_allclose(pos[:, 2], [-0.005] * 4, atol=1e-15)
    assert found.tolist() == [True] * 4 and frame.shape == (4, 3, 3)
    np.testing.assert_allclose(frame[0], [[0, 0, 1], [0, 1, 0], [-1, 0, 0]], atol=1e-15)


# ----------------------------------------------------------------------------------------------
# The table: filters, parameters, explicit pairs, options
# ----------------------------------------------------------------------------------------------

SCENE = """
<mujoco>
  <option {option}>{flags}</option>
  <default><geom solref="{solref}"/></default>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 .1" conaffinity="5" friction="0.7 0.01 0.002"
          priority="{priority}" solmix="2" solimp="0.8 0.9 0.002 0.4 3" margin="0.02" gap="0.01"/>
    <geom name="stone" type="sphere" size="0.1" pos="3 0 0.05" contype="0" conaffinity="0"/>
    <body name="a" pos="0 0 0.3"><freejoint/>
      <geom name="a_cap" type="capsule" size="0.05 0.2" euler="0 90 0" friction="0.3 0.02 0.001"
            solmix="0.5" condim="1"/>
      <geom name="a_sph" type="sphere" size="0.08" pos="0.1 0 0.05" contype="2" conaffinity="2"
            margin="0.03"/>
      <body name="a_child" pos="0 0 0.15"><joint type="hinge" axis="0 1 0"/>
        <geom name="c_sph" type="sphere" size="0.07" solref="-1000 -10"/>
        <geom name="c_cap" type="capsule" size="0.04 0.1" pos="0 0.05 0.05" gap="0.02"
              contype="3"/>
      </body>
    </body>
    <body name="b" pos="0.05 0.05 0.4"><freejoint/>
      <geom name="b_cyl" type="cylinder" size="0.06 0.05" contype="4" conaffinity="0"/>
      <geom name="b_sph" type="sphere" size="0.06" pos="0 0 0.1" solref="0.03 0.8" solmix="0"/>
    </body>
    <body name="c" pos="0 -0.1 0.35"><freejoint/>
      <geom name="c_box" type="box" size="0.05 0.04 0.03" contype="0" conaffinity="0"/>
      <geom name="c_capsule" type="capsule" size="0.05 0.1"/>
    </body>
  </worldbody>
  <contact>{contact}</contact>
</mujoco>
"""
PAIRS = (
    '<pair geom1="b_cyl" geom2="floor" condim="1" friction="0.5 0.5 0.1 0.01 0.02" '
    'solref="0.05 0.5" solreffriction="0.1 0.3" margin="0.05" gap="0.02"/>'
    '<pair geom1="a_cap" geom2="c_capsule"/><pair geom1="stone" geom2="floor"/>'
    '<pair geom1="c_sph" geom2="b_sph" solimp="0.7 0.8 0.01 0.5 2"/>'
    '<pair geom1="a_cap" geom2="a_sph"/><pair geom1="a_sph" geom2="c_sph"/>'
)
VARIANTS = {
    "plain": {},
    "priority": dict(priority="1"),
    "direct_solref": dict(solref="-2000 -30"),
    "filterparent": dict(flags='<flag filterparent="disable"/>'),
    "midphase": dict(flags='<flag midphase="disable"/>'),
    "exclude": dict(contact='<exclude body1="a" body2="b"/><exclude body1="world" body2="c"/>'),
    "pairs": dict(contact=PAIRS),
    "pairs_sparse": dict(contact=PAIRS, option='jacobian="sparse"'),
    "override": dict(
        option='o_margin="0.04" o_solref="0.03 0.7" o_solimp="0.8 0.85 0.01 0.4 2" '
        'o_friction="0.6 0.6 0.01 0.001 0.001"',
        flags='<flag override="enable"/>',
        contact='<pair geom1="b_cyl" geom2="floor" margin="0.05"/>',
    ),
}


def _scene(**kwargs):
    values = {**dict(option="", flags="", solref="0.02 1", priority="0", contact=""), **kwargs}
    return mujoco.MjModel.from_xml_string(SCENE.format(**values))


def _random_states(model, rng, n, height=0.2, spread=0.1) -> np.ndarray:
    q = np.tile(model.qpos0, (n, 1))
    for j in range(model.njnt):
        adr = model.jnt_qposadr[j]
        if model.jnt_type[j] == 0:
            q[:, adr : adr + 3] = rng.normal(size=(n, 3)) * spread + [0, 0, height]
            q[:, adr + 3 : adr + 7] = _random_quats(rng, n)
        elif model.jnt_type[j] == 3:
            q[:, adr] = rng.uniform(-3, 3, n)
    return q


@pytest.mark.parametrize("variant", sorted(VARIANTS))
def test_filters_parameters_and_order(variant):
    model = _scene(**VARIANTS[variant])
    rng = np.random.default_rng(3)
    assert _check("numpy", model, _random_states(model, rng, 30)) > 0


def test_what_the_table_holds():
    table = C.read_contact_table(_scene(contact=PAIRS))
    names = {(C.GEOM_TYPE_NAMES[k.types[0]], C.GEOM_TYPE_NAMES[k.types[1]]) for k in table.kinds}
    assert ("plane", "cylinder") in names and ("capsule", "capsule") in names
    assert sorted(table.order.tolist()) == list(range(table.ncon))
    # explicit static and same-body pairs never enter the constraints; the rest can
    static = [i for i in range(table.ncon) if table.pair[i] >= 0 and not table.acts[i]]
    assert len(static) == 2 and table.acts[table.pair < 0].all()


@pytest.mark.parametrize("flag", ["contact", "constraint"])
def test_disabled_contacts_give_an_empty_table(backend, flag):
    table = C.read_contact_table(_scene(flags=f'<flag {flag}="disable"/>'))
    assert table.ncon == 0 and table.kinds == ()
    xp = getattr(ivy, backend)
    got = C.collide(
        xp, table, native(np.zeros((2, 9, 3)), backend), native(np.zeros((2, 9, 3, 3)), backend)
    )
    assert numpy_of(got.frame).shape == (2, 0, 3, 3) and numpy_of(got.active).shape == (2, 0)


# ----------------------------------------------------------------------------------------------
# Refusals
# ----------------------------------------------------------------------------------------------


@pytest.mark.skipif("pusher" not in GYMNASIUM, reason="needs gymnasium's models")
def test_unsupported_pair_kinds_are_refused_by_name():
    model = mujoco.MjModel.from_xml_path(GYMNASIUM["pusher"])
    with pytest.raises(
        NotImplementedError, match=r"geom #\d+ \(capsule.*\) and geom #\d+ \(cylinder"
    ):
        C.read_contact_table(model)


@pytest.mark.parametrize(
    "old, new, match",
    [
        ('type="capsule" size="0.05 0.1"', 'type="box" size="0.05 0.1 0.1"', r"'c_capsule' \(box"),
        ('name="c_capsule"', 'name="c_capsule" adhesion="0.5"', "adhesion"),
        ("<option >", '<option ><flag sleep="enable"/>', "sleep"),
    ],
)
def test_unmodelled_features_are_refused(old, new, match):
    xml = SCENE.format(option="", flags="", solref="0.02 1", priority="0", contact="")
    assert old in xml
    model = mujoco.MjModel.from_xml_string(xml.replace(old, new))
    with pytest.raises(NotImplementedError, match=match):
        C.read_contact_table(model)


# ----------------------------------------------------------------------------------------------
# Gymnasium's models: the table's filters and order at states where the robots touch
# ----------------------------------------------------------------------------------------------


def _root_height_index(model) -> int | None:
    for j in range(model.njnt):
        if model.jnt_type[j] == 0:
            return int(model.jnt_qposadr[j]) + 2
        if model.jnt_type[j] == 2 and model.jnt_axis[j][2] > 0.99:
            return int(model.jnt_qposadr[j])
    return None


def _touching_states(model, rng, n, lying=False) -> np.ndarray:
    """Random joint angles in range, the root turned at random (lying: on its side), lowered so
    that its lowest geom sinks a few centimetres into the floor."""
    q = np.tile(model.qpos0, (n, 1))
    for j in range(model.njnt):
        adr, kind = model.jnt_qposadr[j], model.jnt_type[j]
        if kind == 0:
            quats = _random_quats(rng, n)
            if lying:
                quats = [
                    _mul(_quat([0, 0, 1], rng.uniform(0, 6)), _quat([0, 1, 0], 1.5)) for _ in q
                ]
            q[:, adr + 3 : adr + 7] = quats
        elif kind in (2, 3) and model.jnt_limited[j]:
            q[:, adr] = rng.uniform(*model.jnt_range[j], n)
        elif kind == 3:
            q[:, adr] = rng.uniform(-np.pi, np.pi, n)
    height = _root_height_index(model)
    if height is None:
        return q
    data = mujoco.MjData(model)
    up = np.array([0.0, 0.0, 1.0])
    movers = [g for g in range(model.ngeom) if model.geom_bodyid[g] and model.geom_type[g] != 0]
    for i in range(n):
        data.qpos[:] = q[i]
        mujoco.mj_kinematics(model, data)
        lowest = min(
            _lowest(
                model.geom_type[g],
                model.geom_size[g],
                data.geom_xpos[g],
                data.geom_xmat[g].reshape(3, 3),
                up,
            )
            for g in movers
        )
        q[i, height] += rng.uniform(-0.06, 0.01) - lowest
    return q


ROBOTS = [
    "hopper", "walker2d_v5", "half_cheetah", "ant", "humanoid", "humanoidstandup", "swimmer",
    "inverted_pendulum", "inverted_double_pendulum", "reacher", "point",
]  # fmt: skip


@pytest.mark.parametrize("name", ROBOTS)
def test_gymnasium_models(name):
    if name not in GYMNASIUM:
        pytest.skip("needs gymnasium's models")
    model = mujoco.MjModel.from_xml_path(GYMNASIUM[name])
    rng = np.random.default_rng(11)
    lying = name.startswith("humanoid")
    qpos = _touching_states(model, rng, 8, lying=lying)
    seen = _check("numpy", model, qpos)
    if _root_height_index(model) is not None:
        assert seen > 0


@pytest.mark.parametrize("name", ["ant", "humanoid"])
def test_gymnasium_models_on_every_backend(backend, name):
    if name not in GYMNASIUM:
        pytest.skip("needs gymnasium's models")
    model = mujoco.MjModel.from_xml_path(GYMNASIUM[name])
    qpos = _touching_states(model, np.random.default_rng(12), 3, lying=name == "humanoid")
    assert _check(backend, model, qpos) > 0


# ----------------------------------------------------------------------------------------------
# Gradients and compilation
# ----------------------------------------------------------------------------------------------


def _geom_poses(xp, model, qpos):
    """Geom poses ``[..., ngeom, 3]``, ``[..., ngeom, 3, 3]`` of the zoo (the world plane and
    free bodies with one geom each at the body origin): a differentiable stand-in for the
    kinematics."""
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    batch = tuple(qpos.shape[:-1])
    plane_pos = xp.broadcast_to(
        xp.asarray(np.array(data.geom_xpos[0]), dtype=qpos.dtype), batch + (3,)
    )
    plane_mat = xp.asarray(np.array(data.geom_xmat[0]).reshape(3, 3), dtype=qpos.dtype)
    positions, rotations = [plane_pos], [xp.broadcast_to(plane_mat, batch + (3, 3))]
    for body in range(1, model.nbody):
        adr = model.jnt_qposadr[model.body_jntadr[body]]
        positions.append(qpos[..., adr : adr + 3])
        rotations.append(_rotation(xp, qpos[..., adr + 3 : adr + 7]))
    return xp.stack(positions, axis=-2), xp.stack(rotations, axis=-3)


def _rotation(xp, quat):
    quat = quat / xp.sqrt(xp.sum(quat * quat, axis=-1, keepdims=True))
    w, x, y, z = (quat[..., i] for i in range(4))
    rows = [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]
    return xp.stack([xp.stack(r, axis=-1) for r in rows], axis=-2)


def _contact_function(model, table, keep):
    """qpos ``[..., nq]`` -> the kept contacts' distances, positions and frames
    ``[..., ncon, 13]`` (the others zero)."""

    def fn(qpos):
        xp = ivy.get_framework(qpos)
        got = C.collide(xp, table, *_geom_poses(xp, model, qpos))
        flat = xp.concat(
            [got.dist[..., None], got.pos, xp.reshape(got.frame, got.frame.shape[:-2] + (9,))],
            axis=-1,
        )
        return xp.where(xp.asarray(keep)[..., None], flat, xp.zeros_like(flat))

    return fn


def _touching_zoo_state(rng, parallel: bool) -> np.ndarray:
    """A zoo state where every pair touches (1 to 4 cm deep), away from the degenerate poses;
    the capsules side by side with parallel axes where ``parallel``."""
    frame = _rotation_of(PLANE_QUAT)
    normal = frame[:, 2]
    q = []
    for name in PLANE_BODIES:
        kind, size = getattr(C, ZOO[name][0].upper()), _sizes(name)
        quat = _mul(PLANE_QUAT, _quat(rng.normal(size=3), rng.uniform(0.3, 1.2)))
        centre = PLANE_ORIGIN + frame[:, :2] @ rng.normal(size=2) * 2
        lowest = _lowest(kind, size, centre, _rotation_of(quat), normal) - centre @ normal
        q.append(np.concatenate([centre - normal * (lowest + rng.uniform(0.01, 0.04)), quat]))
    for k, (first, second) in enumerate(PAIR_BODIES):
        island = np.array([3.0 * k - 3.0, 4.0, 3.0])
        quat1, quat2 = _random_quats(rng, 2)
        x, y, z = _rotation_of(quat1).T
        reach = _sizes(first)[0] + _sizes(second)[0] - rng.uniform(0.01, 0.04)
        if second == "cc2" and parallel:
            quat2, offset = quat1, reach * x + 0.15 * z
        elif second == "cc2":
            quat2 = _mul(quat1, _quat([1, 0, 0], 1.2))
            offset = reach * x + 0.05 * z
        else:
            offset = reach * (0.6 * x + 0.8 * y) + (0.1 * z if second == "sc2" else 0)
        q.append(np.concatenate([island, quat1]))
        q.append(np.concatenate([island + offset, quat2]))
    return np.concatenate(q)


def test_gradients(diff_backend):
    """Distances, positions and frames of every kind (capsules general and parallel) against
    central differences, through a free-body wrapper of the geom poses; and finite gradients
    at degenerate poses (in the same batch, left out of the finite differences)."""
    model, table = _zoo_model(), _zoo_table()
    rng = np.random.default_rng(1)
    touching = np.stack([_touching_zoo_state(rng, parallel) for parallel in (False, True)])
    qpos = np.concatenate([touching, _degenerate_zoo_states()])
    xpos, xmat, reference = _poses(model, qpos)
    found = numpy_of(C.collide(ivy.numpy, table, xpos, xmat).found)
    assert found.sum() == sum(len(c) for c in reference)
    for state, contacts in enumerate(reference[:2]):  # every pair; parallel capsules twice
        pairs = [c["geom"] for c in contacts]
        assert len(set(pairs)) == 7 and pairs.count((9, 10)) == 1 + state, pairs
    assert [len(c) for c in reference[2:]] == [13, 13]
    keep = np.concatenate([found[:2], np.ones_like(found[2:])])  # degenerate: all, unfound too
    fn = _contact_function(model, table, keep)
    weights = rng.standard_normal(keep.shape + (13,))
    value, (grad,) = native_value_and_grads(diff_backend, fn, [qpos], weights)
    assert np.isfinite(value) and np.all(np.isfinite(grad))
    # central differences along random directions of the touching states
    forward = ivy.compile_fn(fn) if capable(diff_backend, "fast_graph") else fn

    def loss(q):
        return np.sum(numpy_of(forward(native(q, diff_backend))) * weights)

    for _ in range(2):
        # small steps: parallel capsules stay parallel (axes within 1e-4 rad)
        direction = np.concatenate([rng.standard_normal(touching.shape), np.zeros((2, 70))])
        step = STEP * direction
        numeric = (loss(qpos + step) - loss(qpos - step)) / (2 * STEP)
        np.testing.assert_allclose(np.sum(grad * direction), numeric, rtol=1e-6, atol=1e-8)


def _degenerate_zoo_states() -> np.ndarray:
    """Two zoo states with every degenerate pose: the plane bodies aligned with the plane
    (upright capsule, flat box, flat cylinder cap), coincident sphere centres (parallel z axes,
    then crossing), a sphere centre on the capsule axis, coaxial then parallel capsules."""
    frame = _rotation_of(PLANE_QUAT)
    normal = frame[:, 2]
    states = []
    for variant in range(2):
        q = []
        for i, name in enumerate(PLANE_BODIES):
            kind, size = getattr(C, ZOO[name][0].upper()), _sizes(name)
            centre = PLANE_ORIGIN + frame[:, 0] * i * 0.7 + frame[:, 1] * 0.1 * variant
            lowest = _lowest(kind, size, centre, _rotation_of(PLANE_QUAT), normal) - centre @ normal
            q.append(np.concatenate([centre - normal * (lowest + 0.01), PLANE_QUAT]))
        quat = _quat([0.3, 0.2, 1.0], 0.8)
        x, _, z = _rotation_of(quat).T
        turned = _mul(quat, _quat([1, 0, 0], 0.7)) if variant else quat
        for k, (_, second) in enumerate(PAIR_BODIES):
            island = np.array([3.0 * k - 3.0, 4.0, 3.0])
            offset = {"ss2": 0 * z, "sc2": 0.1 * z, "cc2": 0.2 * z + 0.2 * x * variant}[second]
            second_quat = quat if second == "cc2" else turned
            q += [np.concatenate([island, quat]), np.concatenate([island + offset, second_quat])]
        states.append(np.concatenate(q))
    return np.array(states)


def _zoo_batch():
    return _poses(_zoo_model(), _zoo_states(np.random.default_rng(2), 60)[47:53])  # no degeneracy


def test_float32(backend):
    """float32 poses give float32 contacts close to float64's."""
    table = _zoo_table()
    xpos, xmat, _ = _zoo_batch()
    contacts = _collider(backend, table)
    wide = contacts(native(xpos, backend), native(xmat, backend))
    narrow = contacts(
        native(xpos.astype(np.float32), backend), native(xmat.astype(np.float32), backend)
    )
    assert numpy_of(narrow[0]).dtype == np.float32
    both = numpy_of(wide[3]) & numpy_of(narrow[3])
    assert both.sum() > 10
    for k in (0, 1, 2):
        np.testing.assert_allclose(numpy_of(narrow[k])[both], numpy_of(wide[k])[both], atol=2e-5)


def test_compiled_equals_eager(graph_backend):
    table = _zoo_table()
    xpos, xmat, _ = _zoo_batch()
    xp = getattr(ivy, graph_backend)
    pos, mat = native(xpos, graph_backend), native(xmat, graph_backend)
    eager = C.collide(xp, table, pos, mat)
    compiled = _collider(graph_backend, table)(pos, mat)
    for a, b in zip(eager, compiled):
        np.testing.assert_allclose(numpy_of(b), numpy_of(a), rtol=1e-12, atol=1e-12)


def test_near_parallel_capsules_in_float32_have_finite_gradients(diff_backend):
    """A float32 Hopper pose met in training (the thigh and leg angles cancel to 1e-9, so the
    torso, thigh and leg capsules are parallel to within float32's resolution): the contacts'
    gradients are finite. The parallel test used to read MuJoCo's determinant while dividing
    by the cross product's square, which float32 rounded to 0 where the determinant was not."""
    from ivy_robot.physics import kinematics, read_model

    model = read_model(mujoco.MjModel.from_xml_path(GYMNASIUM["hopper"]))
    qpos = np.array(
        [-1.3134272e-03, 1.2449507e00, 1.0505068e-03, 1.1393814e-03, -1.1393793e-03, 1.6544214e-03],
        np.float32,
    )[None]
    xp = getattr(ivy, diff_backend)

    def fn(q):
        kin = kinematics(xp, model, q)
        found = C.collide(xp, model.contacts, kin["geom_xpos"], kin["geom_xmat"])
        return xp.concat([found.dist, xp.reshape(found.pos, (1, -1))], axis=-1)

    weights = np.random.default_rng(0).standard_normal((1, 14 * 4)).astype(np.float32)
    value, (grad,) = native_value_and_grads(diff_backend, fn, [qpos], weights)
    assert grad.dtype == np.float32 and np.isfinite(value) and np.all(np.isfinite(grad))
