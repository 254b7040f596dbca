"""The areal tests use the fixture ``surface_registry`` of ``tests/conftest.py``."""
