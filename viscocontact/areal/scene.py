"""An areal scene: a ``[surface]`` table where a 1D scene has its ``[profile]``.

A scene file with a ``[surface]`` table describes an :class:`ArealProblem` solved by
:class:`~viscocontact.areal.method.ArealSpectral`, in the same dimensionless groups (thesis
eq. 4.17) and with the same tables as a 1D scene (:mod:`viscocontact.scene`) where they apply:

* ``[surface]``: ``kind`` from the ``viscocontact.surfaces`` registry and its parameters, plus
  ``grid`` (cells a side, or ``[nx, ny]``; default: 256 a side, refined until the estimate meets
  the tolerance);
* ``[rheology]``, ``[kernel]``, ``[load]``, ``[physical]`` as in 1D;
* ``[adhesion]``: ``"none"`` or a finite-range law with a cohesive form (``maugis-dugdale``),
  applied cell by cell;
* ``[sliding]``: ``zeta`` and ``direction`` (radians from ``x̃``, default 0);
* ``[method]``: optional, ``kind = "areal-spectral"`` and its options (``tolerance``,
  ``max_points``, ``max_memory``, ...).

Every table is parsed by the same functions as a 1D scene's, so errors name ``section.key``, the
value and the allowed range. The physical load is converted with the amplitude ``Λ̃`` (highest
point) of the surface on its first grid.
"""
from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any, Mapping

import attrs

from .. import scene as _scene
from .._numbers import _as_float, _check_number, _freeze, check_one_poisson
from .._toml import dumps
from ..components import _instantiate, build_component, did_you_mean, dump_component, kind_of
from ..errors import ValidationError
from ..load import Load, _as_load, _is_load
from ..units import COHESIVE_KEYS, COHESIVE_KIND, _check_physical, _fill, physical_targets
from .method import ArealSpectral
from .problem import ArealProblem
from .surfaces.base import Surface
from .surfaces.tables import build_surface, surface_table

__all__ = ["ArealScene", "SECTIONS", "METHOD_KIND", "GRID_KEY"]

#: The tables of an areal scene.
SECTIONS = ("surface", "rheology", "kernel", "adhesion", "method", "load", "sliding", "physical")
#: The one method of an areal scene.
METHOD_KIND = "areal-spectral"
#: The key of ``[surface]`` that gives the grid (``ArealSpectral.points``).
GRID_KEY = "grid"
SLIDING_KEYS = ("zeta", "direction")


def _component_of(registry: str):
    return _scene._is_instance_of_base(registry, owner="ArealScene", specs=())


def _default_kernel():
    return build_component("kernel", {"kind": _scene.DEFAULT_KERNEL})


def _default_adhesion():
    return build_component("adhesion", {"kind": "none"})


def _default_poisson(scene: "ArealScene") -> float:
    nu = getattr(scene.kernel, "poisson", None)
    return 0.5 if nu is None else float(nu)


def _check_direction(inst, attribute, value):
    import math

    _check_number("sliding.direction", value, lo=-math.pi, hi=math.pi)


def _check_zeta(inst, attribute, value):
    _check_number("sliding.zeta", value, lo=0.0)


def _check_poisson(inst, attribute, value):
    _check_number("poisson", value, lo=-1.0, hi=0.5, lo_open=True)


def _is_surface(inst, attribute, value):
    if not isinstance(value, Surface):
        raise ValidationError("ArealScene.surface", value, "a Surface (viscocontact.surfaces)")


def _check_method(inst, attribute, value):
    if not isinstance(value, ArealSpectral):
        raise ValidationError("ArealScene.method", value, "an ArealSpectral")


@attrs.frozen(kw_only=True)
class ArealScene:
    """One areal steady-sliding contact problem as a value (module docstring).

    Parameters
    ----------
    surface : Surface
        The rigid periodic surface (heights ``q0·h``).
    rheology : Rheology
    kernel : GreenKernel, optional
        Default the half-space.
    adhesion : AdhesionModel, optional
        ``"none"`` (default) or a model with a cohesive law (``maugis-dugdale``).
    method : ArealSpectral, optional
        Its ``points`` are the scene's ``surface.grid``.
    load : Load
    zeta : float
        ``ζ = q0·V·τ >= 0``.
    direction : float
        Sliding direction, radians from ``x̃``, in ``[-π, π]``.
    poisson : float, optional
        ν in (-1, 0.5]; default the kernel's, else 0.5.
    physical : mapping, optional
        The ``[physical]`` table in SI units (checked against the dimensionless values when the
        scene is read from a table).

    Examples
    --------
    One bump per cell on an elastic half-space, on a 32² grid (a scene file says the same with
    ``[surface] kind = "sinusoid"``, ``amplitude = 0.1``, ``grid = 32``):

    >>> from viscocontact.areal.surfaces import SinusoidSurface
    >>> from viscocontact.rheology import Elastic
    >>> scene = ArealScene(surface=SinusoidSurface(amplitude=0.1), rheology=Elastic(),
    ...                    method=ArealSpectral(points=32), load={"mean_pressure": 0.05},
    ...                    zeta=0.0)
    >>> scene.grid, scene.solve().converged
    ((32, 32), True)
    """

    surface: Surface = attrs.field(validator=_is_surface)
    rheology: Any = attrs.field(validator=_component_of("rheologies"))
    kernel: Any = attrs.field(factory=_default_kernel, validator=_component_of("kernels"))
    adhesion: Any = attrs.field(factory=_default_adhesion, validator=_component_of("adhesion"))
    method: ArealSpectral = attrs.field(factory=ArealSpectral, validator=_check_method)
    load: Load = attrs.field(converter=_as_load, validator=_is_load)
    zeta: float = attrs.field(converter=_as_float, validator=_check_zeta)
    direction: float = attrs.field(default=0.0, converter=_as_float, validator=_check_direction)
    poisson: float = attrs.field(default=attrs.Factory(_default_poisson, takes_self=True),
                                 converter=_as_float, validator=_check_poisson)
    physical: Mapping[str, float] | None = attrs.field(default=None, converter=_freeze,
                                                       validator=_check_physical, hash=False)

    def __attrs_post_init__(self):
        check_one_poisson(self.kernel, self.poisson)
        if self.adhesive and self.adhesion.cohesive_law(1.0) is None and \
                float(getattr(self.adhesion, "gamma", 0.0) or 0.0) > 0:
            raise ValidationError("adhesion.kind", kind_of("adhesion", self.adhesion),
                                  "'none' or a finite-range law with a cohesive form "
                                  f"('{COHESIVE_KIND}'): an areal scene applies the law cell "
                                  "by cell")

    # ---- what the scene is -------------------------------------------------------------------
    @property
    def adhesive(self) -> bool:
        """Whether the adhesion model is anything but ``"none"``."""
        return kind_of("adhesion", self.adhesion) != "none"

    @property
    def grid(self) -> tuple[int, int]:
        """``(nx, ny)`` of the finest grid the solve starts from."""
        return self.method.grid_of(self.problem())

    @property
    def amplitude(self) -> float:
        """``Λ̃``, the highest point of the surface on :attr:`grid` (the unit of the load)."""
        nx, ny = self.grid
        return float(self.problem().heights(nx, ny).max())

    def problem(self) -> ArealProblem:
        """The :class:`ArealProblem` of the scene."""
        load = {self.load.controlled: self.load.value}
        return ArealProblem(surface=self.surface, rheology=self.rheology, kernel=self.kernel,
                            zeta=self.zeta, direction=self.direction,
                            adhesion=self.adhesion if self.adhesive else None, **load)

    def plan(self):
        """The :class:`~viscocontact.plan.SolvePlan` of a solve (grids, memory, time estimate,
        cells per cohesive zone); nothing is solved."""
        from .explain import scene_plan

        return scene_plan(self)

    def solve(self, *, fields: bool = False):
        """The equilibrium: :meth:`ArealSpectral.solve` of :meth:`problem`."""
        from ..errors import warn_accuracy

        result = self.method.solve(self.problem(), fields=fields)
        warn_accuracy(result)
        return result

    def replace(self, **changes: Any) -> "ArealScene":
        """This scene with some fields replaced, checked like a new one (as
        :meth:`Scene.replace <viscocontact.scene.Scene.replace>`)."""
        names = [f.name for f in attrs.fields(ArealScene)]
        for key in changes:
            if key not in names:
                raise ValidationError(f"ArealScene.{key}", changes[key],
                                      f"a field of ArealScene: one of {names}"
                                      f"{did_you_mean(key, names)}")
        return attrs.evolve(self, **changes)

    # ---- (de)serialisation -------------------------------------------------------------------
    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> "ArealScene":
        """Build a scene from its parsed table (module docstring, ``docs/scene.md``)."""
        return _from_dict(data)

    @classmethod
    def from_toml(cls, source: str | Path) -> "ArealScene":
        """Read a scene from a TOML file path or TOML text (as :meth:`Scene.from_toml`)."""
        return cls.from_dict(tomllib.loads(_scene.scene_text(source)))

    def to_dict(self) -> dict[str, Any]:
        """The scene table: resolved dimensionless keys, plus ``physical`` when present."""
        surface = surface_table(self.surface)
        if self.method.points is not None:
            nx, ny = self.method.points
            surface[GRID_KEY] = nx if nx == ny else [nx, ny]
        method = _method_table(self.method)
        out: dict[str, Any] = {"poisson": self.poisson, "surface": surface,
                               "rheology": dump_component("rheology", self.rheology),
                               "kernel": dump_component("kernel", self.kernel),
                               "adhesion": dump_component("adhesion", self.adhesion),
                               "method": method,
                               "load": {self.load.controlled: self.load.value},
                               "sliding": {"zeta": self.zeta, "direction": self.direction}}
        if self.physical is not None:
            if any(k in self.physical for k in COHESIVE_KEYS):
                out["adhesion"].pop("range", None)  # given by the physical table (exclusive)
            out["physical"] = dict(self.physical)
        return out

    def to_toml(self) -> str:
        """TOML text of :meth:`to_dict`; ``ArealScene.from_toml(scene.to_toml()) == scene``."""
        return dumps(self.to_dict())


def _method_table(method: ArealSpectral) -> dict[str, Any]:
    """``[method]``: the kind and the options that differ from the defaults (``points`` is the
    surface's ``grid``)."""
    default = ArealSpectral()
    out: dict[str, Any] = {"kind": METHOD_KIND}
    for f in attrs.fields(ArealSpectral):
        value = getattr(method, f.name)
        if f.name != "points" and value is not None and value != getattr(default, f.name):
            out[f.name] = value
    return out


def _build_method(table: dict[str, Any] | None, grid: Any) -> ArealSpectral:
    params = dict(table or {"kind": METHOD_KIND})
    kind = params.pop("kind", METHOD_KIND)
    if kind != METHOD_KIND:
        raise ValidationError("method.kind", kind, f"{METHOD_KIND!r}, the method of an areal "
                                                   "scene")
    if "points" in params:
        raise ValidationError("method.points", params["points"],
                              f"no value: an areal scene's grid is surface.{GRID_KEY}")
    if grid is not None:
        if isinstance(grid, list):
            grid = tuple(grid)
        params["points"] = grid
    try:
        return _instantiate("method", METHOD_KIND, ArealSpectral, params)
    except ValidationError as exc:
        if exc.field == "method.points":
            raise ValidationError(f"surface.{GRID_KEY}", grid, exc.allowed) from exc
        raise


def _check_sections(data: Mapping[str, Any]) -> None:
    if not isinstance(data, Mapping):
        raise ValidationError("scene", data, "a table of sections")
    if "profile" in data:
        raise ValidationError("profile", "[table]", "no [profile] in an areal scene: its "
                                                    "[surface] is the rigid indenter")
    if "solver" in data:
        raise ValidationError("solver", "[table]", "no [solver] in an areal scene: the areal "
                                                   "spectral method has its own grid solvers "
                                                   "(options in [method])")
    _scene.check_sections(data, SECTIONS)


def _from_dict(data: Mapping[str, Any]) -> ArealScene:
    _check_sections(data)
    physical = _scene._section(data, "physical")
    _check_physical(None, None, physical)
    phys = physical or {}
    tables = {s: _scene._section(data, s) for s in SECTIONS}
    if tables["surface"] is None:
        raise ValidationError("surface", None, "a [surface] table with a 'kind'")
    if tables["rheology"] is None:
        raise ValidationError("rheology", None, "a [rheology] table with a 'kind'")
    kernel_table = tables["kernel"] or {"kind": _scene.DEFAULT_KERNEL}
    adhesion_table = tables["adhesion"] or {
        "kind": COHESIVE_KIND if any(k in phys for k in COHESIVE_KEYS) or
        "work_of_adhesion" in phys else "none"}
    nu = _scene._resolve_poisson(data, phys, kernel_table)

    surface_params = dict(tables["surface"])
    grid = surface_params.pop(GRID_KEY, None)
    kind = surface_params.get("kind")
    fields = _surface_fields(kind)
    _fill("surface", surface_params, physical_targets("profile", phys, nu), phys, fields, kind)
    surface = build_surface(surface_params)
    rheology = build_component("rheology", tables["rheology"])
    kernel = _scene._build_kernel(kernel_table, phys, nu)
    adhesion = _scene._build_adhesion(adhesion_table, phys, nu, lazy=False)
    method = _build_method(tables["method"], grid)

    def amplitude() -> float:
        probe = ArealProblem(surface=surface, rheology=rheology, kernel=kernel, mean_pressure=1.0)
        nx, ny = method.grid_of(probe)
        return float(probe.heights(nx, ny).max())

    load = _scene._build_load(data, phys, nu, amplitude)
    sliding = _scene._build_sliding(data, phys, nu, rheology, keys=SLIDING_KEYS)
    return ArealScene(surface=surface, rheology=rheology, kernel=kernel, adhesion=adhesion,
                      method=method, load=load, zeta=sliding["zeta"],
                      direction=sliding.get("direction", 0.0), poisson=nu, physical=physical)


def _surface_fields(kind: Any) -> dict | None:
    """The constructor's fields of a registered, loadable surface kind (else None)."""
    from .. import _registry
    from ..components import _init_fields
    from ..errors import PluginError

    try:
        return _init_fields(_registry.REGISTRIES["surfaces"].get(kind))
    except (PluginError, TypeError):
        return None
