"""A ``viscocontact.surfaces`` registry over the entry points declared in pyproject.toml.

The tests run against the package installed elsewhere (its metadata may predate the surfaces
group), so the group's entry points are read from this checkout's pyproject.toml and faked.
"""
from __future__ import annotations

import tomllib
from importlib.metadata import EntryPoint
from pathlib import Path

import pytest

from viscocontact import _registry

PYPROJECT = Path(__file__).resolve().parents[3] / "pyproject.toml"


def declared_surfaces() -> dict[str, str]:
    """``{name: "module:Class"}`` of the ``viscocontact.surfaces`` entry points."""
    data = tomllib.loads(PYPROJECT.read_text())
    return dict(data["project"]["entry-points"]["viscocontact.surfaces"])


@pytest.fixture
def surface_registry(monkeypatch):
    """The surfaces registry of this checkout, installed in place of the module's one."""
    eps = [EntryPoint(name, value, "viscocontact.surfaces")
           for name, value in declared_surfaces().items()]
    registry = _registry.Registry("viscocontact.surfaces", _registry._base("surfaces"),
                                  entry_points=lambda: eps)
    monkeypatch.setitem(_registry.REGISTRIES, "surfaces", registry)
    monkeypatch.setattr(_registry, "surfaces", registry)
    return registry
