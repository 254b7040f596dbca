"""The scene: one steady-sliding contact problem as a value, and its file format.

A scene file (TOML) holds one table per component — ``[profile]``, ``[rheology]``, ``[kernel]``,
``[adhesion]``, ``[solver]``, ``[method]`` — each naming a registered ``kind`` and its parameters,
plus ``[load]`` (``mean_pressure`` p̃∞ *or* ``penetration`` Δ̃), ``[sliding]`` (``zeta``
ζ = q0·V·τ) and an optional top-level ``poisson``. Every value is one of the dimensionless groups
of the thesis's eq. 4.17. An optional ``[physical]`` table gives the same scene in SI units; it
is kept on the :class:`Scene` so that ``to_dict``/``to_toml`` (which write it together with the
resolved dimensionless keys) round-trip.

This module reads and writes the format and holds :class:`Scene`; the other jobs have their own
modules, whose names this one re-exports:

* :mod:`viscocontact.components`: building a component from its table (:func:`build_component`,
  :class:`ComponentSpec`, :func:`dump_component`, :func:`kind_of`);
* :mod:`viscocontact.load`: the load control (:class:`Load`);
* :mod:`viscocontact.units`: the SI conversion (:data:`PHYSICAL_KEYS`, :func:`physical_targets`);
* :mod:`viscocontact.groups`: the dimensionless groups and the Tabor parameter
  (:func:`dimensionless_groups`, :func:`tabor_parameter`);
* :mod:`viscocontact.defaults`: the components a scene takes when it names none.
"""
from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any, Mapping

import attrs

from . import _registry, defaults
from ._numbers import _agree, _as_float, _check_number, _freeze, _is_number, check_one_poisson
from ._toml import dumps
from .components import (COMPONENT_SECTIONS, ComponentSpec, _has_param, _init_fields, _param,
                         _plain, _registry_for, build_component, did_you_mean, dump_component,
                         kind_of)  # _plain: re-exported for plugins written against 0.1.0
from .errors import PluginError, ValidationError
from .load import Load, _as_load, _is_load
from .units import (COHESIVE_KEYS, COHESIVE_KIND, PHYSICAL_KEYS, RANGE_MAX, _check_cohesive,
                    _check_physical, _disagree, _fill, _no_target, _none_adhesion,
                    physical_targets)

__all__ = ["Scene", "scene_text", "Load", "ComponentSpec",
           "build_component", "dump_component", "kind_of",
           "physical_targets", "dimensionless_groups", "tabor_parameter", "SECTIONS",
           "COMPONENT_SECTIONS", "TOP_LEVEL_KEYS", "PHYSICAL_KEYS", "COHESIVE_KEYS",
           "COHESIVE_KIND", "RANGE_MAX", "TABOR_SHORT_RANGE", "DEFAULT_EQUILIBRIUM_DISTANCE"]

SECTIONS = (*COMPONENT_SECTIONS, "load", "sliding", "physical")
TOP_LEVEL_KEYS = ("poisson",)
DEFAULT_KERNEL = defaults.KERNEL
DEFAULT_SOLVER = defaults.SOLVER  # keyed by "is adhesive"
DEFAULT_METHOD = defaults.METHOD




def _is_instance_of_base(kind: str, owner: str = "Scene",
                         specs: tuple[str, ...] = ("adhesion", "solver", "method")):
    """An attrs validator: the field holds an instance of the ``kind`` registry's base class
    (a :class:`ComponentSpec` is accepted for the fields named in ``specs``); the error names
    ``owner.field``."""
    def check(inst, attribute, value):
        if isinstance(value, ComponentSpec) and attribute.name in specs:
            return
        base = _registry._base(kind)()
        if not isinstance(value, base):
            raise ValidationError(f"{owner}.{attribute.name}", value,
                                  f"an instance of {base.__module__}.{base.__qualname__}")
    return check


def _default_kernel():
    return build_component("kernel", {"kind": DEFAULT_KERNEL})


def _default_adhesion():
    return build_component("adhesion", {"kind": "none"}, lazy=True)


def _default_solver(scene: "Scene"):
    adhesive = kind_of("adhesion", scene.adhesion) != "none"
    return build_component("solver", {"kind": DEFAULT_SOLVER[adhesive]}, lazy=True)


def _default_method():
    return build_component("method", {"kind": DEFAULT_METHOD}, lazy=True)


def _default_poisson(scene: "Scene"):
    nu = getattr(scene.kernel, "poisson", None)
    return 0.5 if nu is None else float(nu)


def _check_zeta(inst, attribute, value):
    _check_number("sliding.zeta", value, lo=0.0)


def _check_poisson(inst, attribute, value):
    _check_number("poisson", value, lo=-1.0, hi=0.5, lo_open=True)


@attrs.frozen(kw_only=True)
class Scene:
    """One steady-sliding contact problem in the dimensionless groups of equation 4.17.

    Parameters
    ----------
    profile : Profile
        The rigid periodic profile (heights in q0·r units).
    rheology : Rheology
        The viscoelastic solid (dimensionless: E0 = 1, τ = 1).
    kernel : GreenKernel, optional
        Elastic geometry; default the half-plane.
    adhesion : AdhesionModel or ComponentSpec, optional
        Default ``"none"``.
    solver : NonlinearSolver or ComponentSpec, optional
        Default ``"broyden"`` with adhesion, ``"bisection"`` without.
    method : SolutionMethod or ComponentSpec, optional
        How the equilibrium is computed: ``"auto"`` (default: the spectral method for an
        adhesionless scene, the BEM for an adhesive one), ``"spectral"``, ``"bem"`` or a plugin.
    load : Load
        ``mean_pressure`` p̃∞ or ``penetration`` Δ̃.
    zeta : float
        ``ζ = q0·V·τ >= 0``; 0 is the relaxed (rubbery) elastic limit.
    poisson : float, optional
        ν in (-1, 0.5]; default the kernel's ν if it has one, else 0.5. Enters only the unit
        conversion (1-ν²) and must equal the kernel's ν when the kernel has one.
    physical : mapping, optional
        The ``[physical]`` table in SI units (see :data:`PHYSICAL_KEYS`), kept for round trips and
        for :func:`viscocontact.groups.dimensionless_groups`; it must agree with the
        dimensionless values.

    Examples
    --------
    >>> scene = Scene.from_toml('''
    ... [profile]
    ... kind = "sinusoid"
    ... amplitude = 0.05
    ... [rheology]
    ... kind = "standard-linear-solid"
    ... beta = 10.0
    ... [load]
    ... mean_pressure = 0.3
    ... [sliding]
    ... zeta = 0.01
    ... ''')
    >>> scene.load.mean_pressure, scene.zeta
    (0.3, 0.01)
    >>> Scene.from_toml(scene.to_toml()) == scene
    True
    """

    profile: Any = attrs.field(validator=_is_instance_of_base("profiles"))
    rheology: Any = attrs.field(validator=_is_instance_of_base("rheologies"))
    kernel: Any = attrs.field(factory=_default_kernel, validator=_is_instance_of_base("kernels"))
    adhesion: Any = attrs.field(factory=_default_adhesion,
                                validator=_is_instance_of_base("adhesion"))
    solver: Any = attrs.field(default=attrs.Factory(_default_solver, takes_self=True),
                              validator=_is_instance_of_base("solvers"))
    method: Any = attrs.field(factory=_default_method, validator=_is_instance_of_base("methods"))
    load: Load = attrs.field(converter=_as_load, validator=_is_load)
    zeta: float = attrs.field(converter=_as_float, validator=_check_zeta)
    poisson: float = attrs.field(default=attrs.Factory(_default_poisson, takes_self=True),
                                 converter=_as_float, validator=_check_poisson)
    physical: Mapping[str, float] | None = attrs.field(default=None, converter=_freeze,
                                                       validator=_check_physical, hash=False)

    def __attrs_post_init__(self):
        check_one_poisson(self.kernel, self.poisson)
        if self.physical is not None:
            self._check_physical_agrees(self.physical)
            self._warn_outside_model(self.physical)

    def _warn_outside_model(self, phys: Mapping[str, float]) -> None:
        """A :class:`~viscocontact.errors.ModelValidityWarning` for each doubt that
        ``viscocontact describe`` lists: a Tabor parameter below 3 (eq. 1.48; rubbery, or glassy
        at high ζ) for an adhesive scene given in physical units, where the infinitely
        short-range (JKR-like) adhesion of the energy balance does not hold."""
        if not self.adhesive or not {"E0", "wavelength"} <= set(phys):
            return
        from .errors import ModelValidityWarning, warn_user
        from .groups import dimensionless_groups

        for message in dimensionless_groups(self)["warnings"]:
            warn_user(f"{message} (viscocontact describe shows μ_T and its inputs)",
                      ModelValidityWarning)

    # ---- physical consistency --------------------------------------------------------------
    def _section_value(self, section: str, key: str) -> tuple[Any, bool | None]:
        if section == "load":
            return getattr(self.load, key), True
        if section == "sliding":
            return self.zeta, True
        component = getattr(self, section)
        return _param(component, key), _has_param(component, key)

    def _check_physical_agrees(self, phys: Mapping[str, float]) -> None:
        length: Any = getattr(self.profile, "length", None)  # a measured profile's λ0 (m)
        if "wavelength" in phys and _is_number(length) and not _agree(length, phys["wavelength"]):
            raise ValidationError("physical.wavelength", phys["wavelength"],
                                  f"the profile's own length λ0 = {length!r} m")
        if "poisson" in phys and not _agree(phys["poisson"], self.poisson):
            raise ValidationError("poisson", self.poisson,
                                  f"to agree with physical.poisson = {phys['poisson']!r}")
        for section in ("profile", "kernel", "adhesion", "load", "sliding"):
            targets = physical_targets(section, phys, self.poisson,
                                       amplitude=lambda: self.profile.amplitude,
                                       gamma=_param(self.adhesion, "gamma"))
            for key, (value, source) in targets.items():
                if section == "adhesion" and not self.adhesive:
                    raise _none_adhesion(phys)
                current, takes = self._section_value(section, key)
                if takes is False:
                    raise _no_target(section, key, kind_of(section, getattr(self, section)),
                                     source, phys, getattr(self, section))
                if current is None or not _agree(current, value):
                    raise _disagree(section, key, current, value, source, phys)

    # ---- (de)serialisation -----------------------------------------------------------------
    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> "Scene":
        """Build a scene from the parsed scene table; see the module docstring and docs/scene.md."""
        return _from_dict(data)

    @classmethod
    def from_toml(cls, source: str | Path) -> "Scene":
        """Read a scene from a TOML file path or from TOML text.

        A :class:`str` containing a newline or a ``=`` that is not an existing file is read as
        TOML text; anything else is a path (``FileNotFoundError`` if missing). TOML syntax errors
        raise :class:`tomllib.TOMLDecodeError`. The example scenes' paths of the README,
        ``examples/scenes/NAME.toml``, read the copies shipped with the package when no such
        file exists in the working folder.
        """
        return cls.from_dict(tomllib.loads(scene_text(source)))

    def to_dict(self) -> dict[str, Any]:
        """The scene table: resolved dimensionless keys, plus ``physical`` when present."""
        out: dict[str, Any] = {"poisson": self.poisson}
        for section in COMPONENT_SECTIONS:
            out[section] = dump_component(section, getattr(self, section))
        if self.physical is not None and any(k in self.physical for k in COHESIVE_KEYS):
            out["adhesion"].pop("range", None)  # given by the physical table (exclusive)
        out["load"] = {self.load.controlled: self.load.value}
        out["sliding"] = {"zeta": self.zeta}
        if self.physical is not None:
            out["physical"] = dict(self.physical)
        return out

    def to_toml(self) -> str:
        """TOML text of :meth:`to_dict`; ``Scene.from_toml(scene.to_toml()) == scene``."""
        return dumps(self.to_dict())

    def replace(self, **changes: Any) -> "Scene":
        """This scene with some fields replaced, checked like a new one.

        ``changes`` are fields of :class:`Scene` (``zeta``, ``load``, ``adhesion``, ...); a load
        may be a mapping. An unknown name is a :class:`ValidationError` with the closest field.
        A ``physical`` table is kept as it is and must agree with the changed values (pass
        ``physical=None`` to drop it).

        Examples
        --------
        >>> from viscocontact.scene import Scene
        >>> base = Scene.from_dict({"profile": {"kind": "sinusoid", "amplitude": 0.1},
        ...                         "rheology": {"kind": "elastic"},
        ...                         "load": {"mean_pressure": 0.3}})
        >>> base.replace(load={"penetration": 0.5}).load.controlled
        'penetration'
        """
        names = [f.name for f in attrs.fields(Scene)]
        for key in changes:
            if key not in names:
                raise ValidationError(f"Scene.{key}", changes[key],
                                      f"a field of Scene: one of {names}"
                                      f"{did_you_mean(key, names)}")
        return attrs.evolve(self, **changes)

    def resolve(self) -> "Scene":
        """This scene with every :class:`ComponentSpec` built into its component object."""
        changes = {s: getattr(self, s).resolve(s) for s in ("adhesion", "solver", "method")
                   if isinstance(getattr(self, s), ComponentSpec)}
        return attrs.evolve(self, **changes) if changes else self

    @property
    def adhesive(self) -> bool:
        """Whether the adhesion model is anything but ``"none"``."""
        return kind_of("adhesion", self.adhesion) != "none"


# ---------------------------------------------------------------------------------------------


def _amplitude(profile) -> float:
    """Λ̃ of a built profile, for a physical load; a profile too large to evaluate is named."""
    try:
        return profile.amplitude
    except (MemoryError, ValueError, OverflowError) as exc:
        raise ValidationError("profile", kind_of("profile", profile),
                              "a profile whose amplitude Λ̃ can be computed (it converts the "
                              f"physical load): {type(exc).__name__}: {exc}") from exc


def _section(data: Mapping[str, Any], name: str) -> dict[str, Any] | None:
    table = data.get(name)
    if table is None:
        return None
    if not isinstance(table, Mapping):
        raise ValidationError(name, table, f"a table ([{name}])")
    return dict(table)


def _kind_class(section: str, params: dict[str, Any]) -> tuple[str | None, dict | None]:
    """(kind, init fields) if the kind is registered and loadable, else (kind, None)."""
    kind: Any = params.get("kind")  # any TOML value: a kind that is no string is a TypeError
    try:
        return kind, _init_fields(_registry_for(section).get(kind))
    except (PluginError, TypeError):
        return kind, None


def _resolve_poisson(data, physical, kernel_table) -> float:
    candidates = []
    if "poisson" in data:
        candidates.append(("poisson", data["poisson"]))
    if "poisson" in physical:
        candidates.append(("physical.poisson", physical["poisson"]))
    if kernel_table is not None and "poisson" in kernel_table:
        candidates.append(("kernel.poisson", kernel_table["poisson"]))
    for name, value in candidates:
        _check_number(name, value, lo=-1.0, hi=0.5, lo_open=True)
    for name, value in candidates[1:]:
        if not _agree(value, candidates[0][1]):
            raise ValidationError(name, value, f"to agree with {candidates[0][0]} = "
                                               f"{candidates[0][1]!r} (one material, one ν)")
    return float(candidates[0][1]) if candidates else 0.5


def scene_text(source: str | Path) -> str:
    """The TOML text of a scene given as a path or as text (see :meth:`Scene.from_toml`)."""
    from .data import scene_path

    if isinstance(source, Path):
        return scene_path(source).read_text(encoding="utf-8")
    if "\n" in source or ("=" in source and not Path(source).is_file()):
        return source
    return scene_path(source).read_text(encoding="utf-8")


def check_sections(data: Mapping[str, Any], sections) -> None:
    """Every table of a scene's ``data`` is one of ``sections`` and every other key a
    top-level key (:data:`TOP_LEVEL_KEYS`), else a :class:`ValidationError` naming it."""
    for key, value in data.items():
        if isinstance(value, Mapping):
            if key not in sections:
                raise ValidationError(key, "[table]", f"one of the sections {list(sections)}"
                                                      f"{did_you_mean(key, sections)}")
        elif key not in TOP_LEVEL_KEYS:
            raise ValidationError(key, value, f"one of the sections {list(sections)} or a "
                                              f"top-level key in {list(TOP_LEVEL_KEYS)}"
                                              f"{did_you_mean(key, (*sections, *TOP_LEVEL_KEYS))}")


def _from_dict(data: Mapping[str, Any]) -> Scene:
    if not isinstance(data, Mapping):
        raise ValidationError("scene", data, "a table of sections")
    if "surface" in data:
        raise ValidationError("surface", "[table]", "a [profile] table: a scene with a [surface] "
                                                    "is areal (read it with read_scene or "
                                                    "ArealScene.from_dict)")
    check_sections(data, SECTIONS)
    physical = _section(data, "physical")
    _check_physical(None, None, physical)
    phys = physical or {}
    tables = {s: _section(data, s) for s in COMPONENT_SECTIONS}
    profile_table, rheology_table = tables["profile"], tables["rheology"]
    if profile_table is None:
        raise ValidationError("profile", None, "a [profile] table with a 'kind'")
    if rheology_table is None:
        raise ValidationError("rheology", None, "a [rheology] table with a 'kind'")
    kernel_table = tables["kernel"]
    if kernel_table is None:
        kernel_table = {"kind": DEFAULT_KERNEL}
    adhesion_table = tables["adhesion"]
    if adhesion_table is None:
        adhesion_table = {"kind": COHESIVE_KIND if any(k in phys for k in COHESIVE_KEYS)
                          else "energy-balance" if "work_of_adhesion" in phys else "none"}
    solver_table = tables["solver"]
    nu = _resolve_poisson(data, phys, kernel_table)

    # profile (its Λ̃ is needed to convert the load)
    params = profile_table
    kind, fields = _kind_class("profile", params)
    _fill("profile", params, physical_targets("profile", phys, nu), phys, fields, kind)
    profile = build_component("profile", params)
    rheology = build_component("rheology", rheology_table)

    kernel = _build_kernel(kernel_table, phys, nu)
    adhesion = _build_adhesion(adhesion_table, phys, nu, lazy=True)
    if solver_table is None:
        solver_table = {"kind": DEFAULT_SOLVER[kind_of("adhesion", adhesion) != "none"]}
    solver = build_component("solver", solver_table, lazy=True)
    method = build_component("method", tables["method"] or {"kind": DEFAULT_METHOD}, lazy=True)
    load = _build_load(data, phys, nu, lambda: _amplitude(profile))
    sliding = _build_sliding(data, phys, nu, rheology)

    return Scene(profile=profile, rheology=rheology, kernel=kernel, adhesion=adhesion,
                 solver=solver, method=method, load=load, zeta=sliding["zeta"], poisson=nu,
                 physical=physical)


def _build_kernel(table: dict[str, Any], phys: Mapping[str, float], nu: float):
    """The ``[kernel]`` component, its thickness from the physical table and its ν the scene's."""
    kind, fields = _kind_class("kernel", table)
    _fill("kernel", table, physical_targets("kernel", phys, nu), phys, fields, kind)
    if fields is not None and "poisson" in fields and "poisson" not in table:
        table["poisson"] = nu
    return build_component("kernel", table)


def _build_adhesion(table: dict[str, Any], phys: Mapping[str, float], nu: float, *,
                    lazy: bool):
    """The ``[adhesion]`` component, γ̃ and the cohesive range from the physical table."""
    kind, fields = _kind_class("adhesion", table)
    if kind == "none" and any(k in phys for k in ("work_of_adhesion", *COHESIVE_KEYS)):
        raise _none_adhesion(phys)
    _check_cohesive(phys, kind, table)
    targets = physical_targets("adhesion", phys, nu, gamma=table.get("gamma"))
    _fill("adhesion", table, targets, phys, fields, kind)
    return build_component("adhesion", table, lazy=lazy)


def _build_load(data: Mapping[str, Any], phys: Mapping[str, float], nu: float,
                amplitude) -> Load:
    """The ``[load]`` table (or the physical load, converted with the amplitude Λ̃ that the
    callable ``amplitude`` gives)."""
    load_table = _section(data, "load") or {}
    for key in load_table:
        if key not in ("mean_pressure", "penetration"):
            raise ValidationError(f"load.{key}", load_table[key],
                                  "a key of [load]: 'mean_pressure' or 'penetration'"
                                  f"{did_you_mean(key, ('mean_pressure', 'penetration'))}")
    targets = physical_targets("load", phys, nu, amplitude=amplitude)
    _fill("load", load_table, targets, phys, None, "load")
    if not load_table:
        raise ValidationError("load", None, "exactly one of load.mean_pressure and "
                                            "load.penetration (or physical.mean_pressure / "
                                            "physical.penetration)")
    return Load(**load_table)


def _build_sliding(data: Mapping[str, Any], phys: Mapping[str, float], nu: float, rheology,
                   keys: tuple[str, ...] = ("zeta",)) -> dict[str, Any]:
    """The ``[sliding]`` table with its ζ (from the physical table, or 0 for an elastic
    rheology); ``keys`` are the keys it may hold."""
    sliding = _section(data, "sliding") or {}
    for key in sliding:
        if key not in keys:
            raise ValidationError(f"sliding.{key}", sliding[key],
                                  f"a key of [sliding]: {', '.join(repr(k) for k in keys)}"
                                  f"{did_you_mean(key, keys)}")
    _fill("sliding", sliding, physical_targets("sliding", phys, nu), phys, None, "sliding")
    if "zeta" not in sliding:
        if rheology.modulus_ratio != 1.0:
            raise ValidationError("sliding.zeta", None,
                                  "a value >= 0 (ζ = q0·V·τ; or physical.velocity and "
                                  "physical.tau): required for a viscoelastic rheology")
        sliding["zeta"] = 0.0
    return sliding


def __getattr__(name: str) -> Any:
    """The groups' names, imported from :mod:`viscocontact.groups` on first use (they need the
    theories, which a scene alone does not)."""
    if name in ("dimensionless_groups", "tabor_parameter", "TABOR_SHORT_RANGE",
                "DEFAULT_EQUILIBRIUM_DISTANCE"):
        from . import groups

        return getattr(groups, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
