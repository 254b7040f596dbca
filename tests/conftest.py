"""Hypothesis runs the same examples on every machine and in every run (``derandomize``), and
gives no example a deadline: a loaded machine is slower, not wrong. A test's own ``@settings``
override only what they name. ``pytest --hypothesis-profile=explore`` draws new examples, to
look for failures by hand."""
import tomllib
from importlib.metadata import EntryPoint
from pathlib import Path

import pytest
from hypothesis import settings

from viscocontact import _registry

settings.register_profile("ci", derandomize=True, deadline=None)
settings.register_profile("explore", deadline=None)
settings.load_profile("ci")


# ---- the surfaces registry of this checkout -------------------------------------------------
# The tests run against the package installed elsewhere (its metadata may predate the
# ``viscocontact.surfaces`` group), so the group's entry points are read from this checkout's
# pyproject.toml and faked by the fixture ``surface_registry``.
PYPROJECT = Path(__file__).resolve().parents[1] / "pyproject.toml"


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
