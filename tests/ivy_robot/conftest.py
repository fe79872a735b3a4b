"""MuJoCo's warnings during ivy_robot's tests (a Gymnasium model uses the deprecated
``settotalmass``) go to a list instead of ``MUJOCO_LOG.TXT`` in the working directory."""

from __future__ import annotations

import pytest


@pytest.fixture(autouse=True, scope="session")
def _mujoco_warnings_to_a_list():
    try:
        import mujoco
    except ImportError:
        yield []
        return
    caught: list[str] = []
    previous = mujoco.get_mju_user_warning()
    mujoco.set_mju_user_warning(caught.append)
    yield caught
    mujoco.set_mju_user_warning(previous)
