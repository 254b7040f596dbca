"""The areal tests use the fixture ``surface_registry`` of ``tests/conftest.py``; its
``declared_surfaces`` is imported here too for the tests that list the declared kinds."""
from ...conftest import declared_surfaces  # noqa: F401
