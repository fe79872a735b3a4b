"""A device that a backend does not have is refused in the same words on every backend, naming
the device asked for and the devices the backend has (torch's own error on a machine without
CUDA was a long assertion from its CUDA initialisation; tensorflow, jax and numpy each had their
own words). The devices a backend has come from its Array API inspection namespace."""

from __future__ import annotations

import pytest

import ivy
from ivy.errors import UnavailableDeviceError, unavailable_device


def _missing_gpu(xp) -> str:
    """A GPU this backend does not have here."""
    have = {xp.dev(xp.zeros((), device=d)) for d in xp.__array_namespace_info__().devices()}
    return next(f"gpu:{i}" for i in range(64) if f"gpu:{i}" not in have)


@pytest.mark.parametrize("make", ["asarray", "zeros", "arange", "random_normal"])
def test_a_missing_gpu_is_refused_naming_it_and_the_devices_there_are(backend, xp, make):
    device = _missing_gpu(xp)
    calls = {
        "asarray": lambda: ivy.asarray([1.0], device=device, f=backend),
        "zeros": lambda: ivy.zeros((2,), device=device, f=backend),
        "arange": lambda: ivy.arange(3, device=device, f=backend),
        "random_normal": lambda: ivy.random_normal(shape=(2,), device=device, f=backend),
    }
    with pytest.raises(UnavailableDeviceError) as caught:
        calls[make]()
    message = str(caught.value)
    assert f"{backend} has no device {device!r} on this machine" in message
    assert "its devices here: 'cpu'" in message
    assert len(message.splitlines()) == 1


@pytest.mark.parametrize("device", ["tpu:0", "cuda:0", "gpu:x", "cpu:1", "foo", 3])
def test_names_that_are_no_device_are_refused_alike(backend, xp, device):
    with pytest.raises(UnavailableDeviceError, match=f"has no device {device!r}") as caught:
        ivy.asarray([1.0], device=device, f=backend)
    assert isinstance(caught.value, ValueError)  # existing except clauses keep working
    assert str(caught.value) == str(unavailable_device(device, xp))  # the one helper's words


def test_cpu_names_are_accepted_everywhere(backend):
    for device in ("cpu", "cpu:0"):
        assert ivy.dev(ivy.asarray([1.0], device=device, f=backend)) == "cpu"


def test_the_helper_is_reusable_by_libraries_taking_device():
    error = unavailable_device("gpu:3", ivy.numpy, function="KinematicTree.from_mjcf")
    assert isinstance(error, UnavailableDeviceError)
    assert str(error).startswith("ivy.KinematicTree.from_mjcf (numpy backend), argument 'device'")
