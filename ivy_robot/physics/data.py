"""The data record: the named arrays that the pipeline's stages fill in, as MuJoCo's ``mjData``.

:class:`Data` is a named tuple (every framework's tree utilities and loops take it as it is),
with MuJoCo's field names and shapes over any leading batch shape ``[...]``. Matrices are
``[..., 3, 3]`` rather than MuJoCo's rows of 9, the mass matrix is dense, and constraint rows and
contacts are laid out for every candidate (a fixed number, so that the pipeline compiles and
batches): ``efc_active`` and ``contact_active`` say which MuJoCo would have. A field a stage has
not reached yet is None.
"""

from __future__ import annotations

from typing import Any, NamedTuple

__all__ = ["Data"]


class Data(NamedTuple):
    """MuJoCo's ``mjData`` as named arrays (see the module docstring).

    State and inputs: ``qpos [..., nq]``, ``qvel [..., nv]``, ``ctrl [..., nu]``,
    ``qfrc_applied [..., nv]``, ``qacc_warmstart [..., nv]``.

    Kinematics: ``xpos [..., nbody, 3]``, ``xmat [..., nbody, 3, 3]``, ``xanchor``,
    ``xaxis [..., njnt, 3]``, ``xipos``, ``ximat`` (inertial frames), ``geom_xpos``,
    ``geom_xmat``, ``site_xpos``, ``site_xmat``; about each tree's centre of mass:
    ``subtree_com [..., nbody, 3]``, ``cinert [..., nbody, 10]``, ``cdof [..., nv, 6]``.

    Inertia: ``qM [..., nv, nv]`` (dense, with armature), ``qLD`` and ``qLDiag`` (its
    ``L diag(D) L^T`` factor, ``L`` without its unit diagonal).

    Velocities and forces: ``cvel [..., nbody, 6]``, ``cdof_dot [..., nv, 6]``, ``qfrc_bias``,
    ``qfrc_passive``, ``actuator_force [..., nu]``, ``qfrc_actuator``, ``qfrc_smooth``,
    ``qacc_smooth``, ``qfrc_constraint``, ``qacc [..., nv]``.

    Contacts (one per candidate, ``ncon`` of the model's contact table): ``contact_dist
    [..., ncon]``, ``contact_pos [..., ncon, 3]``, ``contact_frame [..., ncon, 3, 3]`` (rows:
    normal, tangents), ``contact_active [..., ncon]`` (bool).

    Constraint rows (``nefc`` candidates, in MuJoCo's order: friction loss, limits, contacts):
    ``efc_J [..., nefc, nv]``, ``efc_pos``, ``efc_vel``, ``efc_imp`` (the impedance),
    ``efc_D``, ``efc_R``, ``efc_aref``,
    ``efc_force [..., nefc]``, ``efc_active [..., nefc]`` (bool).

    After the constraints (``mj_rnePostConstraint``): ``cacc [..., nbody, 6]``, ``cfrc_int``,
    ``cfrc_ext [..., nbody, 6]``.

    Example:
        >>> data = forward(xp, model, make_data(xp, model, model.qpos0, np.zeros(model.nv)))
        >>> data.xpos.shape, data.qM.shape, data.efc_J.shape     # the Hopper
        ((5, 3), (6, 6), (44, 6))
    """

    qpos: Any = None
    qvel: Any = None
    ctrl: Any = None
    qfrc_applied: Any = None
    qacc_warmstart: Any = None
    xpos: Any = None
    xmat: Any = None
    xanchor: Any = None
    xaxis: Any = None
    xipos: Any = None
    ximat: Any = None
    geom_xpos: Any = None
    geom_xmat: Any = None
    site_xpos: Any = None
    site_xmat: Any = None
    subtree_com: Any = None
    cinert: Any = None
    cdof: Any = None
    qM: Any = None
    qLD: Any = None
    qLDiag: Any = None
    cvel: Any = None
    cdof_dot: Any = None
    qfrc_bias: Any = None
    qfrc_passive: Any = None
    actuator_force: Any = None
    qfrc_actuator: Any = None
    qfrc_smooth: Any = None
    qacc_smooth: Any = None
    contact_dist: Any = None
    contact_pos: Any = None
    contact_frame: Any = None
    contact_active: Any = None
    efc_J: Any = None
    efc_pos: Any = None
    efc_vel: Any = None
    efc_imp: Any = None
    efc_D: Any = None
    efc_R: Any = None
    efc_aref: Any = None
    efc_force: Any = None
    efc_active: Any = None
    qfrc_constraint: Any = None
    qacc: Any = None
    cacc: Any = None
    cfrc_int: Any = None
    cfrc_ext: Any = None

    def replace(self, **changes: Any) -> Data:
        """A copy with some fields changed.

        Example:
            >>> data.replace(qvel=np.ones(model.nv)).qvel
            array([1., 1., 1., 1., 1., 1.])
        """
        return self._replace(**changes)

    def fields(self) -> dict[str, Any]:
        """The fields by name, absent ones (None) included.

        Example: what :func:`forward` leaves for :func:`external_forces` to fill in

            >>> sorted(k for k, v in data.fields().items() if v is None)
            ['cacc', 'cfrc_ext', 'cfrc_int']
        """
        return self._asdict()

    @classmethod
    def names(cls) -> tuple[str, ...]:
        """The names of the fields, in order.

        Example:
            >>> Data.names()[:3]
            ('qpos', 'qvel', 'ctrl')
        """
        return cls._fields
