"""Reading a scene of either kind: a 1D :class:`~viscocontact.scene.Scene` (a ``[profile]``
table) or an :class:`~viscocontact.areal.scene.ArealScene` (a ``[surface]`` table)."""
from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any, Mapping

__all__ = ["read_scene", "scene_from_dict"]


def scene_from_dict(data: Mapping[str, Any]):
    """A :class:`Scene` from a table with ``[profile]``, or an
    :class:`~viscocontact.areal.scene.ArealScene` from one with ``[surface]``."""
    if isinstance(data, Mapping) and "surface" in data:
        from .areal.scene import ArealScene

        return ArealScene.from_dict(data)
    from .scene import Scene

    return Scene.from_dict(data)


def read_scene(source: str | Path):
    """The scene of a TOML file or text: a :class:`Scene` (``[profile]``) or an
    :class:`~viscocontact.areal.scene.ArealScene` (``[surface]``).

    Examples
    --------
    >>> type(read_scene("examples/scenes/sinusoid.toml")).__name__
    'Scene'
    """
    from .scene import scene_text

    return scene_from_dict(tomllib.loads(scene_text(source)))
