"""Surfaces as scene tables: ``{"kind": registered name, **parameters}`` and back.

The same format as the scene's component sections (:func:`viscocontact.scene.build_component`):
the kind is looked up in the ``viscocontact.surfaces`` registry, errors name ``surface.key``, a
nested profile (:class:`~viscocontact.areal.surfaces.ExtrudedProfile`) is its own table with a
``kind`` from ``viscocontact.profiles``.
"""
from __future__ import annotations

import difflib
from typing import Any, Mapping

from ... import _registry
from ...errors import ValidationError
from .base import Surface

__all__ = ["build_surface", "surface_parameters", "surface_table"]

SECTION = "surface"


def build_surface(table: Mapping[str, Any]) -> Surface:
    """The surface of a table ``{"kind": ..., **parameters}``.

    Raises
    ------
    ValidationError
        Naming ``surface.kind`` (unknown kind, with the registered ones) or ``surface.<key>``.
    """
    from ...components import _instantiate

    registry = _registry.REGISTRIES["surfaces"]
    params = dict(table)
    kind = params.pop("kind", None)
    if not isinstance(kind, str) or kind not in registry:
        names = registry.names()
        close = difflib.get_close_matches(kind, names, n=1) if isinstance(kind, str) else []
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise ValidationError(f"{SECTION}.kind", kind,
                              f"one of the registered {registry.group} names {names}{hint}")
    cls = registry.get(kind)
    return _instantiate(SECTION, kind, cls, params)


def surface_table(surface: Surface) -> dict[str, Any]:
    """``{"kind": registered name, **parameters}`` of a surface (None parameters left out)."""
    kind = _registry.REGISTRIES["surfaces"].name_of(surface)  # PluginError if not registered
    return {"kind": kind, **surface_parameters(surface)}


def surface_parameters(surface: Surface) -> dict[str, Any]:
    """The constructor's parameters as plain data: arrays as lists, a nested profile as its own
    table with its ``kind``, None parameters left out (TOML has no null)."""
    from ...profiles.base import Profile
    from ...components import _init_fields, _plain, dump_component

    out: dict[str, Any] = {}
    for key, f in _init_fields(type(surface)).items():
        value = getattr(surface, f.name)
        if value is None:
            continue
        out[key] = dump_component("profile", value) if isinstance(value, Profile) else _plain(value)
    return out
