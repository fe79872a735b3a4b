"""This package's tests also run on the opt-in backends (see ``tests/conftest.py``)."""

IVY_OPT_IN_BACKENDS = ("array_api_strict",)
