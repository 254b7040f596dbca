"""The scene: one steady-sliding contact problem, its file format and its unit conversion.

A scene file (TOML) holds one table per component — ``[profile]``, ``[rheology]``, ``[kernel]``,
``[adhesion]``, ``[solver]``, ``[method]`` — each naming a registered ``kind`` and its parameters,
plus ``[load]``
(``mean_pressure`` p̃∞ *or* ``penetration`` Δ̃), ``[sliding]`` (``zeta`` ζ = q0·V·τ) and an optional
top-level ``poisson``. Every value is one of the dimensionless groups of the thesis's eq. 4.17.

An optional ``[physical]`` table gives the same scene in SI units; it is converted here, at this
one boundary, into the dimensionless keys (see :data:`PHYSICAL_KEYS` and ``docs/scene.md``):

* ``q0 = 2π/λ0``, ``γ̃ = (1-ν²) q0 Δγ/(π E0)``, ``ζ = q0 V τ``, ``Λ̃ = q0 Λ``, ``rms → q0 r_rms``,
  ``thickness → q0 d``, ``p̃∞ = 2(1-ν²) p∞/(E0 q0 Λ)``, ``Δ̃ = Δ/Λ`` with ``Λ = max r`` of the
  built profile.

A physical value fills its dimensionless key when that key is absent; when both are present they
must agree to 1e-9 relative. The physical table is kept on the :class:`Scene` so that
``to_dict``/``to_toml`` (which write it together with the resolved dimensionless keys) round-trip.

Components are built generically from the entry-point registries (``registry.get(kind)(**params)``).
Adhesion models and solvers whose module cannot be imported yet are kept as a
:class:`ComponentSpec` (kind + parameters) and resolved by :meth:`Scene.resolve`.
"""
from __future__ import annotations

import difflib
import math
import re
import tomllib
import types
from pathlib import Path
from typing import Any, Mapping, cast

import attrs
import numpy as np

from . import _registry, defaults
from ._toml import dumps
from .errors import PluginError, ValidationError

#: Scene sections and the registry that builds each component section.
COMPONENT_SECTIONS = {"profile": "profiles", "rheology": "rheologies", "kernel": "kernels",
                      "adhesion": "adhesion", "solver": "solvers", "method": "methods"}
SECTIONS = (*COMPONENT_SECTIONS, "load", "sliding", "physical")
TOP_LEVEL_KEYS = ("poisson",)
DEFAULT_KERNEL = defaults.KERNEL
DEFAULT_SOLVER = defaults.SOLVER  # keyed by "is adhesive"
DEFAULT_METHOD = defaults.METHOD
DEFAULT_EQUILIBRIUM_DISTANCE = 1e-9  # m, Z0 of the Tabor parameter

#: ``[physical]`` keys: SI unit, allowed range (lo, hi, lo_open) and meaning.
PHYSICAL_KEYS: dict[str, tuple[str, tuple[float | None, float | None, bool], str]] = {
    "E0": ("Pa", (0.0, None, True), "relaxed (rubbery) Young modulus E0"),
    "poisson": ("1", (-1.0, 0.5, True), "Poisson ratio ν"),
    "wavelength": ("m", (0.0, None, True), "fundamental wavelength λ0 = 2π/q0"),
    "work_of_adhesion": ("J/m^2", (0.0, None, False), "Dupré work of adhesion Δγ"),
    "tau": ("s", (0.0, None, True), "reference (creep) time τ of the rheology"),
    "velocity": ("m/s", (0.0, None, False), "sliding speed V"),
    "rms": ("m", (0.0, None, True), "root-mean-square roughness r_rms"),
    "amplitude": ("m", (0.0, None, True), "profile amplitude Λ = max r"),
    "thickness": ("m", (0.0, None, True), "layer thickness d"),
    "mean_pressure": ("Pa", (None, None, False), "remote mean pressure p∞ (negative = tensile)"),
    "penetration": ("m", (None, None, False), "penetration Δ"),
    "equilibrium_distance": ("m", (0.0, None, True), "equilibrium distance Z0 (Tabor parameter)"),
    "cohesive_range": ("m", (0.0, None, True),
                       "range h0 of the Dugdale cohesive law (adhesion kind 'maugis-dugdale')"),
    "cohesive_strength": ("Pa", (0.0, None, True),
                          "cohesive strength σ0 = Δγ/h0 (adhesion kind 'maugis-dugdale')"),
}
#: The ``[physical]`` keys that give the range of the Maugis–Dugdale law (exclusive).
COHESIVE_KEYS = ("cohesive_range", "cohesive_strength")
COHESIVE_KIND = "maugis-dugdale"
#: Upper bound of ``MaugisDugdale.range`` (h̃0 = q0·h0 in (0, RANGE_MAX]).
RANGE_MAX = 10.0

# (section, key) <- (physical sources, physical keys also needed)
_TARGETS: dict[tuple[str, str], tuple[tuple[str, ...], tuple[str, ...]]] = {
    ("profile", "rms"): (("rms",), ("wavelength",)),
    ("profile", "amplitude"): (("amplitude",), ("wavelength",)),
    ("kernel", "thickness"): (("thickness",), ("wavelength",)),
    ("adhesion", "gamma"): (("work_of_adhesion",), ("E0", "wavelength")),
    ("load", "mean_pressure"): (("mean_pressure",), ("E0",)),
    ("load", "penetration"): (("penetration",), ("wavelength",)),
    ("sliding", "zeta"): (("velocity", "tau"), ("wavelength",)),
}
_REL_TOL = 1e-9


# ---------------------------------------------------------------------------------------------
# small helpers
def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(
        value, (bool, np.bool_))


def _as_float(value: Any) -> Any:
    try:
        return float(value) if _is_number(value) else value
    except OverflowError:  # an integer beyond the float range: the validator rejects it
        return value


def _overflows(value: Any) -> bool:
    """Whether ``value`` (or an item of it) is an integer too large for a float."""
    if isinstance(value, (list, tuple)):
        return any(_overflows(v) for v in value)
    try:
        float(value) if _is_number(value) else None
    except OverflowError:
        return True
    return False


def _check_number(field: str, value: Any, lo=None, hi=None, lo_open=False) -> None:
    interval = (f"{'(' if lo_open else '['}{'-inf' if lo is None else lo}, "
                f"{'inf' if hi is None else hi}]")
    desc = f"a finite real number in {interval}"
    if not _is_number(value) or _overflows(value) or not math.isfinite(float(value)):
        raise ValidationError(field, value, desc)
    v = float(value)
    if lo is not None and (v < lo or (lo_open and v == lo)):
        raise ValidationError(field, value, desc)
    if hi is not None and v > hi:
        raise ValidationError(field, value, desc)


def did_you_mean(word: Any, names) -> str:
    """`` (did you mean 'x'?)`` for the closest of ``names`` to a mistyped ``word``, or ``""``."""
    close = difflib.get_close_matches(word, list(names), n=1) if isinstance(word, str) else []
    return f" (did you mean {close[0]!r}?)" if close else ""


def _freeze(mapping: Mapping | None) -> Mapping | None:
    if mapping is None:
        return None
    if not isinstance(mapping, Mapping):
        raise ValidationError("physical", mapping, "a table of SI values")
    return types.MappingProxyType({k: _as_float(v) for k, v in mapping.items()})


def _agree(a: float, b: float) -> bool:
    return math.isclose(float(a), float(b), rel_tol=_REL_TOL, abs_tol=0.0)


def _registry_for(section: str) -> _registry.Registry:
    return _registry.REGISTRIES[COMPONENT_SECTIONS[section]]


def _init_fields(cls: type) -> dict[str, attrs.Attribute]:
    """``{keyword: attribute}`` of the constructor arguments of an attrs class."""
    if not attrs.has(cls):
        raise PluginError(f"{cls.__module__}.{cls.__qualname__} is not an attrs class; components "
                          "must be frozen attrs classes")
    return {f.alias: f for f in attrs.fields(cls) if f.init}


def _plain(value: Any) -> Any:
    """A component field value as plain data (numpy → lists/floats, attrs → dicts)."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, (np.floating, np.integer, np.bool_)):
        return value.item()
    if attrs.has(type(value)):
        return {k: _plain(getattr(value, f.name)) for k, f in _init_fields(type(value)).items()}
    if isinstance(value, Mapping):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    return value


# ---------------------------------------------------------------------------------------------
@attrs.frozen(kw_only=True)
class ComponentSpec:
    """A component given by its registered name and parameters, built on demand.

    Used for components whose class cannot be imported when the scene is read (and by
    :meth:`Scene.resolve`). ``resolve(section)`` builds it with the same checks as a scene file.
    """

    kind: str = attrs.field(validator=attrs.validators.instance_of(str))
    params: Mapping[str, Any] = attrs.field(
        factory=dict, converter=lambda p: types.MappingProxyType(dict(p)), hash=False)

    def resolve(self, section: str) -> Any:
        """The component object (``section`` is ``"solver"``, ``"adhesion"``, ...)."""
        return build_component(section, {"kind": self.kind, **self.params})


def build_component(section: str, table: Mapping[str, Any], *, lazy: bool = False) -> Any:
    """Build the component of scene section ``section`` from its table (``kind`` + parameters).

    Raises :class:`ValidationError` naming ``section.key`` for an unknown kind, an unknown or
    missing key and a rejected value; a plugin that fails to import raises :class:`PluginError`,
    unless ``lazy`` is set, in which case a :class:`ComponentSpec` is returned instead.
    """
    registry = _registry_for(section)
    params = dict(table)
    kind = params.pop("kind", None)
    try:
        if not isinstance(kind, str):
            raise PluginError(f"{section}.kind must be a string")
        cls = registry.get(kind)  # cached after the first look-up
    except PluginError as exc:
        names = registry.names()
        if isinstance(kind, str) and kind in names:  # registered, but failed to load
            if lazy and isinstance(exc.__cause__, ImportError):
                return ComponentSpec(kind=kind, params=params)
            raise
        hint = did_you_mean(kind, names)
        raise ValidationError(f"{section}.kind", kind, f"one of the registered {registry.group} "
                                                        f"names {names}{hint}") from None
    return _instantiate(section, kind, cls, params)


def _instantiate(section: str, kind: str, cls: type, params: dict[str, Any]) -> Any:
    fields = _init_fields(cls)
    for key in params:
        if key not in fields:
            raise ValidationError(f"{section}.{key}", params[key],
                                  f"a key of {section} kind {kind!r}: one of {sorted(fields)}"
                                  f"{did_you_mean(key, fields)}")
    required = [k for k, f in fields.items() if f.default is attrs.NOTHING]
    for key in required:
        if key not in params:
            raise ValidationError(f"{section}.{key}", None,
                                  f"a value ({section} kind {kind!r} requires {required})")
    params = _nested_options(section, cls, fields, params)
    try:
        return cls(**params)
    except ValidationError as exc:
        attr = exc.field.rsplit(".", 1)[-1]  # "StandardLinearSolid.beta" -> "rheology.beta"
        raise ValidationError(f"{section}.{attr}", exc.value, exc.allowed) from exc
    except (TypeError, ValueError, OverflowError) as exc:
        message = str(exc).replace("\n", " ")
        named = [k for k in fields if re.search(rf"\b{re.escape(k)}\b", message)]
        if isinstance(exc, OverflowError) and len(named) != 1:  # "int too large to convert"
            named = [k for k, v in params.items() if _overflows(v)]
        if len(named) == 1:
            raise ValidationError(f"{section}.{named[0]}", params.get(named[0]), message) from exc
        raise ValidationError(section, params, message) from exc


def _nested_options(section: str, cls: type, fields: dict, params: dict) -> dict:
    """Build attrs-typed fields given as sub-tables (``[solver.options]``) into their class."""
    nested = [k for k, v in params.items() if isinstance(v, Mapping)]
    if not nested:
        return params
    try:
        attrs.resolve_types(cls)
    except Exception:  # unresolvable annotations: pass the tables through unchanged
        return params
    out = dict(params)
    for key in nested:
        ftype = fields[key].type
        if isinstance(ftype, type) and attrs.has(ftype):
            out[key] = _instantiate(f"{section}.{key}", ftype.__name__, ftype, dict(params[key]))
    return out


def dump_component(section: str, component: Any) -> dict[str, Any]:
    """``{"kind": registered name, **parameters}`` of a component or :class:`ComponentSpec`."""
    if isinstance(component, ComponentSpec):
        return {"kind": component.kind,
                **{k: _plain(v) for k, v in component.params.items() if v is not None}}
    out = {"kind": kind_of(section, component)}
    for key, f in _init_fields(type(component)).items():
        value = getattr(component, f.name)
        if value is None and f.default is None:
            continue  # TOML has no null: an omitted key rebuilds the default
        out[key] = _plain(value)
    return out


def kind_of(section: str, component: Any) -> str:
    """The registered name of a component (or of a :class:`ComponentSpec`)."""
    if isinstance(component, ComponentSpec):
        return component.kind
    registry = _registry_for(section)
    cls = type(component)
    for name, cached in registry._cache.items():  # classes already looked up (no metadata scan)
        if cached is cls:
            return name
    return registry.name_of(component)


def _param(component: Any, key: str) -> Any:
    if isinstance(component, ComponentSpec):
        return component.params.get(key)
    return getattr(component, key, None)


def _has_param(component: Any, key: str) -> bool | None:
    """Whether the component takes ``key`` (``None`` if unknown: an unresolved spec)."""
    if isinstance(component, ComponentSpec):
        return None
    return key in _init_fields(type(component))


# ---------------------------------------------------------------------------------------------
def _optional_number(inst, attribute, value):
    if value is not None:
        _check_number(f"load.{attribute.name}", value)


@attrs.frozen(kw_only=True)
class Load:
    """The load control: exactly one of ``mean_pressure`` (p̃∞, eq. 4.17, any finite real;
    negative is a tensile load, legal with adhesion) and ``penetration`` (Δ̃ = Δ/Λ, finite)."""

    mean_pressure: float | None = attrs.field(default=None, converter=_as_float,
                                              validator=_optional_number)
    penetration: float | None = attrs.field(default=None, converter=_as_float,
                                            validator=_optional_number)

    def __attrs_post_init__(self):
        if (self.mean_pressure is None) == (self.penetration is None):
            raise ValidationError("load", {"mean_pressure": self.mean_pressure,
                                           "penetration": self.penetration},
                                  "exactly one of load.mean_pressure and load.penetration")

    @property
    def controlled(self) -> str:
        """``"mean_pressure"`` (load control) or ``"penetration"`` (displacement control)."""
        return "mean_pressure" if self.mean_pressure is not None else "penetration"

    @property
    def value(self) -> float:
        """The controlled value."""
        # exactly one of the two is set (checked at construction)
        return cast(float, self.mean_pressure if self.mean_pressure is not None
                    else self.penetration)


def _as_load(value: Any) -> Any:
    """``Scene(load={"mean_pressure": 0.3})``: a mapping is read as the ``[load]`` table."""
    if not isinstance(value, Mapping):
        return value
    for key in value:
        if key not in ("mean_pressure", "penetration"):
            raise ValidationError(f"load.{key}", value[key],
                                  "a key of [load]: 'mean_pressure' or 'penetration'"
                                  f"{did_you_mean(key, ('mean_pressure', 'penetration'))}")
    return Load(**value)


def _is_load(inst, attribute, value):
    if not isinstance(value, Load):
        raise ValidationError("Scene.load", value, "a Load or a mapping such as "
                                                   "{'mean_pressure': 0.3} or {'penetration': 0.5}")


def _is_instance_of_base(kind: str):
    def check(inst, attribute, value):
        if isinstance(value, ComponentSpec) and attribute.name in ("adhesion", "solver", "method"):
            return
        base = _registry._base(kind)()
        if not isinstance(value, base):
            raise ValidationError(f"Scene.{attribute.name}", value,
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


def _check_physical(inst, attribute, value):
    if value is None:
        return
    for key, v in value.items():
        if key not in PHYSICAL_KEYS:
            raise ValidationError(f"physical.{key}", v, f"one of {list(PHYSICAL_KEYS)}"
                                                        f"{did_you_mean(key, PHYSICAL_KEYS)}")
        lo, hi, lo_open = PHYSICAL_KEYS[key][1]
        _check_number(f"physical.{key}", v, lo=lo, hi=hi, lo_open=lo_open)
    if all(k in value for k in COHESIVE_KEYS):
        raise ValidationError("physical.cohesive_strength", value["cohesive_strength"],
                              "no value when physical.cohesive_range is given (the range h0 and "
                              "the strength σ0 = Δγ/h0 fix the same adhesion.range: give one)")


@attrs.frozen(kw_only=True)
class Scene:
    """One steady-sliding contact problem in the dimensionless groups of eq. 4.17.

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
        knu = getattr(self.kernel, "poisson", None)
        if knu is not None and not _agree(knu, self.poisson):
            raise ValidationError("kernel.poisson", knu, f"the scene's poisson = {self.poisson!r} "
                                                         "(one material, one Poisson ratio)")
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
        from .data import scene_path

        if isinstance(source, Path):
            text = scene_path(source).read_text(encoding="utf-8")
        elif "\n" in source or ("=" in source and not Path(source).is_file()):
            text = source
        else:
            text = scene_path(source).read_text(encoding="utf-8")
        return cls.from_dict(tomllib.loads(text))

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
# the physical boundary
def physical_targets(section: str, physical: Mapping[str, float], poisson: float,
                     amplitude=None, gamma: Any = None) -> dict[str, tuple[float, str]]:
    """Dimensionless values of ``section`` implied by the physical table.

    Returns ``{key: (value, "physical.source")}``. ``amplitude`` is a callable returning the built
    profile's Λ̃ = q0·max r (needed for the load). Raises :class:`ValidationError` naming the
    missing physical key when a conversion lacks an input (e.g. ``physical.E0``). ``gamma`` is
    the adhesion table's γ̃ (used by ``physical.cohesive_strength`` when
    ``physical.work_of_adhesion`` is absent).
    """
    out: dict[str, tuple[float, str]] = {}
    one_minus_nu2 = 1.0 - poisson**2
    for (sec, key), (sources, needs) in _TARGETS.items():
        if sec != section or not any(s in physical for s in sources):
            continue
        present = [s for s in sources if s in physical]
        for req in (*sources, *needs):
            if req not in physical:
                unit, _, meaning = PHYSICAL_KEYS[req]
                raise ValidationError(f"physical.{req}", None,
                                      f"a value ({meaning}, {unit}): needed to convert "
                                      f"physical.{present[0]} into {sec}.{key}")
        P = physical
        # every conversion but the mean pressure's needs physical.wavelength (checked above)
        q0 = 2.0 * math.pi / P["wavelength"] if "wavelength" in P else math.nan
        if key in ("rms", "amplitude", "thickness"):
            value = q0 * P[key]
        elif key == "gamma":
            value = one_minus_nu2 * q0 * P["work_of_adhesion"] / (math.pi * P["E0"])
        elif key == "mean_pressure":
            value = 2.0 * one_minus_nu2 * P["mean_pressure"] / (P["E0"] * amplitude())
        elif key == "penetration":
            value = P["penetration"] * q0 / amplitude()
        else:  # zeta
            value = q0 * P["velocity"] * P["tau"]
        out[key] = (float(value), " and ".join(f"physical.{s}" for s in sources))
    if section == "adhesion" and any(k in physical for k in COHESIVE_KEYS):
        given = out["gamma"][0] if "gamma" in out else gamma
        out["range"] = _cohesive_range(physical, one_minus_nu2, given)
    return out


def _cohesive_range(physical: Mapping[str, float], one_minus_nu2: float,
                    gamma: Any) -> tuple[float, str]:
    """``adhesion.range`` h̃0 from ``physical.cohesive_range`` (``q0·h0``) or
    ``physical.cohesive_strength`` (``h0 = Δγ/σ0``, i.e. ``h̃0 = πγ̃E*/σ0`` from
    ``σ0/E* = πγ̃/h̃0``), checked against ``(0, RANGE_MAX]``."""
    key = "cohesive_range" if "cohesive_range" in physical else "cohesive_strength"
    value = physical[key]
    if key == "cohesive_range":
        if "wavelength" not in physical:
            raise ValidationError("physical.wavelength", None,
                                  "a value (fundamental wavelength λ0, m): needed to convert "
                                  "physical.cohesive_range into adhesion.range")
        q0 = 2.0 * math.pi / physical["wavelength"]
        h0 = q0 * value
        allowed = f"a range h0 in (0, {RANGE_MAX / q0:.6g}] m (h̃0 = q0·h0 in (0, {RANGE_MAX:g}])"
    else:
        if "E0" not in physical:
            raise ValidationError("physical.E0", None,
                                  "a value (relaxed Young modulus E0, Pa): needed to convert "
                                  "physical.cohesive_strength into adhesion.range")
        if not _is_number(gamma) or not float(gamma) > 0.0:
            raise ValidationError("physical.cohesive_strength", value,
                                  "a work of adhesion > 0 with it (physical.work_of_adhesion or "
                                  f"adhesion.gamma; got {gamma!r}): h0 = Δγ/σ0")
        estar = physical["E0"] / one_minus_nu2
        h0 = math.pi * float(gamma) * estar / value
        allowed = (f"a strength σ0 >= {math.pi * float(gamma) * estar / RANGE_MAX:.6g} Pa "
                   f"(h̃0 = πγ̃E*/σ0 in (0, {RANGE_MAX:g}])")
    if not (math.isfinite(h0) and 0.0 < h0 <= RANGE_MAX):
        raise ValidationError(f"physical.{key}", value, allowed)
    return float(h0), f"physical.{key}"


def _disagree(section, key, current, value, source, phys):
    given = ", ".join(f"{s} = {phys[s.split('.')[1]]!r}" for s in source.split(" and "))
    return ValidationError(f"{section}.{key}", current,
                           f"{value!r} (to 1e-9 relative), the value converted from {given}")


def _no_target(section, key, kind, source, phys, component):
    first = source.split(" and ")[0]
    fields = [] if isinstance(component, ComponentSpec) else sorted(_init_fields(type(component)))
    return ValidationError(first, phys[first.split(".")[1]],
                           f"a {section} kind with a {key!r} key ({section} kind {kind!r} has "
                           f"{fields})")


def _none_adhesion(phys):
    key = next((k for k in ("work_of_adhesion", *COHESIVE_KEYS) if k in phys), "work_of_adhesion")
    use = "'maugis-dugdale'" if key in COHESIVE_KEYS else "'energy-balance' or 'maugis-dugdale'"
    return ValidationError(f"physical.{key}", phys.get(key),
                           f"no value when adhesion.kind = 'none' (use kind = {use})")


def _check_cohesive(phys: Mapping[str, float], kind: Any, params: Mapping[str, Any]) -> None:
    """``physical.cohesive_range``/``cohesive_strength`` only with adhesion kind
    'maugis-dugdale', and never together with an explicit ``adhesion.range``."""
    key = next((k for k in COHESIVE_KEYS if k in phys), None)
    if key is None:
        return
    if kind != COHESIVE_KIND:
        raise ValidationError(f"physical.{key}", phys[key],
                              f"adhesion kind {COHESIVE_KIND!r} with it (the Dugdale law's "
                              f"range; adhesion kind {kind!r} has none)")
    if "range" in params:
        raise ValidationError("adhesion.range", params["range"],
                              f"no value when physical.{key} is given (it fixes adhesion.range)")


def _fill(section: str, params: dict[str, Any], targets: dict[str, tuple[float, str]],
          phys: Mapping[str, float], fields: dict | None, kind: str | None) -> None:
    for key, (value, source) in targets.items():
        if fields is not None and key not in fields:
            first = source.split(" and ")[0]
            raise ValidationError(first, phys[first.split(".")[1]],
                                  f"a {section} kind with a {key!r} key ({section} kind {kind!r} "
                                  f"has {sorted(fields)})")
        if key not in params:
            params[key] = value
        elif not _is_number(params[key]) or not _agree(params[key], value):
            raise _disagree(section, key, params[key], value, source, phys)


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


def _from_dict(data: Mapping[str, Any]) -> Scene:
    if not isinstance(data, Mapping):
        raise ValidationError("scene", data, "a table of sections")
    for key, value in data.items():
        if isinstance(value, Mapping):
            if key not in SECTIONS:
                raise ValidationError(key, "[table]", f"one of the sections {list(SECTIONS)}"
                                                      f"{did_you_mean(key, SECTIONS)}")
        elif key not in TOP_LEVEL_KEYS:
            raise ValidationError(key, value, f"one of the sections {list(SECTIONS)} or a "
                                              f"top-level key in {list(TOP_LEVEL_KEYS)}"
                                              f"{did_you_mean(key, (*SECTIONS, *TOP_LEVEL_KEYS))}")
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

    params = kernel_table
    kind, fields = _kind_class("kernel", params)
    _fill("kernel", params, physical_targets("kernel", phys, nu), phys, fields, kind)
    if fields is not None and "poisson" in fields and "poisson" not in params:
        params["poisson"] = nu
    kernel = build_component("kernel", params)

    params = adhesion_table
    kind, fields = _kind_class("adhesion", params)
    if kind == "none" and any(k in phys for k in ("work_of_adhesion", *COHESIVE_KEYS)):
        raise _none_adhesion(phys)
    _check_cohesive(phys, kind, params)
    targets = physical_targets("adhesion", phys, nu, gamma=params.get("gamma"))
    _fill("adhesion", params, targets, phys, fields, kind)
    adhesion = build_component("adhesion", params, lazy=True)

    if solver_table is None:
        solver_table = {"kind": DEFAULT_SOLVER[kind_of("adhesion", adhesion) != "none"]}
    solver = build_component("solver", solver_table, lazy=True)
    method = build_component("method", tables["method"] or {"kind": DEFAULT_METHOD}, lazy=True)

    load_table = _section(data, "load") or {}
    for key in load_table:
        if key not in ("mean_pressure", "penetration"):
            raise ValidationError(f"load.{key}", load_table[key],
                                  "a key of [load]: 'mean_pressure' or 'penetration'"
                                  f"{did_you_mean(key, ('mean_pressure', 'penetration'))}")
    targets = physical_targets("load", phys, nu, amplitude=lambda: _amplitude(profile))
    _fill("load", load_table, targets, phys, None, "load")
    if not load_table:
        raise ValidationError("load", None, "exactly one of load.mean_pressure and "
                                            "load.penetration (or physical.mean_pressure / "
                                            "physical.penetration)")
    load = Load(**load_table)

    sliding = _section(data, "sliding") or {}
    for key in sliding:
        if key != "zeta":
            raise ValidationError(f"sliding.{key}", sliding[key], "a key of [sliding]: 'zeta'"
                                                                  f"{did_you_mean(key, ['zeta'])}")
    _fill("sliding", sliding, physical_targets("sliding", phys, nu), phys, None, "sliding")
    if "zeta" not in sliding:
        if rheology.modulus_ratio != 1.0:
            raise ValidationError("sliding.zeta", None,
                                  "a value >= 0 (ζ = q0·V·τ; or physical.velocity and "
                                  "physical.tau): required for a viscoelastic rheology")
        sliding["zeta"] = 0.0

    return Scene(profile=profile, rheology=rheology, kernel=kernel, adhesion=adhesion,
                 solver=solver, method=method, load=load, zeta=sliding["zeta"], poisson=nu,
                 physical=physical)


# ---------------------------------------------------------------------------------------------
# the dimensionless groups of a scene (``viscocontact describe``; see viscocontact.groups)
TABOR_SHORT_RANGE = 3.0  # Greenwood: JKR (infinitely short-range adhesion) is accurate for μ_T >> 3


def tabor_parameter(*, radius: float, work_of_adhesion: float, reduced_modulus: float,
                    equilibrium_distance: float = DEFAULT_EQUILIBRIUM_DISTANCE) -> float:
    """``μ_T = (R Δγ² / (E*² Z0³))^(1/3)`` (eq. 1.48, second form).

    Parameters
    ----------
    radius : float
        Crest radius of curvature R (m).
    work_of_adhesion : float
        Δγ (J/m²).
    reduced_modulus : float
        E* = E/(1-ν²) (Pa).
    equilibrium_distance : float
        Z0 (m).

    Examples
    --------
    >>> round(tabor_parameter(radius=0.1, work_of_adhesion=0.01, reduced_modulus=1e7 / 0.75), 1)
    383.2
    """
    length = work_of_adhesion / reduced_modulus
    return length ** (2.0 / 3.0) * radius ** (1.0 / 3.0) / equilibrium_distance


def _tabor(scene: "Scene", groups: dict[str, Any]) -> tuple[dict[str, Any], list[str]]:
    phys = scene.physical or {}
    out: dict[str, Any] = {"tabor": None, "tabor_glassy": None, "tabor_radius": None,
                           "adhesion_length": None, "equilibrium_distance": None}
    if not scene.adhesive or groups["gamma"] == 0.0:
        out["tabor_note"] = "no adhesion: the Tabor parameter does not apply"
        return out, []
    missing = [k for k in ("E0", "wavelength") if k not in phys]
    if missing:
        out["tabor_note"] = ("the Tabor parameter needs a physical scale: give "
                             + ", ".join(f"physical.{k}" for k in missing)
                             + " (and physical.equilibrium_distance Z0, default 1 nm)")
        return out, []
    nu2 = 1.0 - scene.poisson**2
    q0 = 2.0 * math.pi / phys["wavelength"]
    e0 = phys["E0"]
    dgamma = phys.get("work_of_adhesion", groups["gamma"] * math.pi * e0 / (nu2 * q0))
    z0 = phys.get("equilibrium_distance", DEFAULT_EQUILIBRIUM_DISTANCE)
    radius = 1.0 / (q0 * scene.profile.crest_length)    # 1/(q0² Λ) or 1/(q0² r_rms), eq. 4.55
    which = ("crest radius 1/(q0² Λ) of the sinusoid" if _is_sinusoid(scene.profile)
             else "R = λ0²/(4π² r_rms) of the equivalent sinusoid (eq. 4.55)")
    estar = e0 / nu2
    out.update(
        tabor=tabor_parameter(radius=radius, work_of_adhesion=dgamma, reduced_modulus=estar,
                              equilibrium_distance=z0),
        tabor_glassy=tabor_parameter(radius=radius, work_of_adhesion=dgamma,
                                     reduced_modulus=estar * groups["beta"],
                                     equilibrium_distance=z0),
        tabor_radius=radius, adhesion_length=dgamma / estar, equilibrium_distance=z0,
        tabor_note=(f"μ_T = (R Δγ²/(E*² Z0³))^(1/3), E* = E0/(1-ν²) (glassy: E∞/(1-ν²)), {which}"))
    warnings = []
    if out["tabor"] < TABOR_SHORT_RANGE:
        warnings.append(f"Tabor parameter μ_T = {out['tabor']:.3g} < 3: infinitely short-range "
                        "(JKR-type) adhesion is doubtful")
    elif out["tabor_glassy"] < TABOR_SHORT_RANGE:
        warnings.append(f"glassy Tabor parameter μ_T,∞ = {out['tabor_glassy']:.3g} < 3: "
                        "short-range adhesion is doubtful at high ζ")
    return out, warnings


def _is_sinusoid(profile) -> bool:
    """Whether the crest length of ``profile`` is a sinusoid's amplitude (the wording of
    ``describe``; :attr:`~viscocontact.profiles.Profile.crest_length` gives the value)."""
    from .profiles import Sinusoid

    return isinstance(profile, Sinusoid)


def _regime(value: float) -> str:
    from .adhesion.maugis_dugdale import DMT_LIKE, JKR_LIKE

    if value >= JKR_LIKE:
        return f"JKR-like (λ >= {JKR_LIKE:g})"
    if value <= DMT_LIKE:
        return f"DMT-like (λ <= {DMT_LIKE:g})"
    return f"Maugis transition ({DMT_LIKE:g} < λ < {JKR_LIKE:g})"


def _cohesive(scene: "Scene", groups: dict[str, Any]) -> dict[str, Any]:
    """The Maugis–Dugdale groups (``docs/cohesive.md``): range, strength, zone, λ, μ_T, regime;
    in SI units too when the physical table gives the scale."""
    adhesion = scene.adhesion
    if isinstance(adhesion, ComponentSpec):
        adhesion = adhesion.resolve("adhesion")
    gamma, h0, amp, beta = adhesion.gamma, adhesion.range, groups["amplitude"], groups["beta"]
    length = scene.profile.crest_length
    which = ("crest radius R = 1/(q0² Λ) of the sinusoid" if _is_sinusoid(scene.profile)
             else "R = 1/(q0² r_rms) of the equivalent sinusoid (eq. 4.55), not the crest of "
                  "the highest asperity")
    lam = adhesion.transition_parameter(length) if gamma > 0 else 0.0
    lam_glassy = adhesion.transition_parameter(length, beta) if gamma > 0 else 0.0
    regime = _regime(lam)
    if _regime(lam_glassy) != regime:
        regime += f"; glassy (high ζ): {_regime(lam_glassy)}"
    out: dict[str, Any] = {
        "range": h0, "range_ratio": h0 / amp,
        "cohesive_stress": adhesion.strength(amp), "strength_ratio": math.pi * gamma / h0,
        "quasi_static_zone": adhesion.quasi_static_zone,
        "transition": lam, "transition_glassy": lam_glassy, "regime": regime,
        "tabor": adhesion.tabor(length) if gamma > 0 else 0.0,
        "tabor_glassy": adhesion.tabor(length, beta) if gamma > 0 else 0.0,
        "tabor_radius": None, "adhesion_length": None, "equilibrium_distance": None,
        "cohesive_range": None, "cohesive_strength": None, "quasi_static_zone_length": None,
        "tabor_note": (f"Maugis–Dugdale: λ = 2σ0 (R/(πE²Δγ))^(1/3), μ_T with Z0 = 16h0/(9√3) "
                       f"(σ0 the Lennard-Jones maximum), E = E* (glassy: βE*), {which}; "
                       f"physical.equilibrium_distance is not used"),
    }
    phys = scene.physical or {}
    if {"E0", "wavelength"} <= set(phys):
        q0 = 2.0 * math.pi / phys["wavelength"]
        estar = phys["E0"] / (1.0 - scene.poisson**2)
        out.update(cohesive_range=h0 / q0, cohesive_strength=estar * math.pi * gamma / h0,
                   quasi_static_zone_length=adhesion.quasi_static_zone / q0,
                   tabor_radius=1.0 / (q0 * length), adhesion_length=math.pi * gamma / q0,
                   equilibrium_distance=16.0 / (9.0 * math.sqrt(3.0)) * h0 / q0)
    return out


def dimensionless_groups(scene: "Scene") -> dict[str, Any]:
    """The dimensionless groups of ``scene`` (JSON-ready).

    Keys: the component kinds (``profile``, ``rheology``, ``kernel``, ``adhesion``, ``solver``);
    ``gamma`` γ̃, ``Gamma`` γ̃/Λ̃², ``amplitude`` Λ̃ = q0·max r, ``rms`` q0·r_rms, ``m2`` <r'²>,
    ``zeta`` ζ, ``beta`` E∞/E0, ``poisson``, ``mean_pressure`` or ``penetration``; ``hurst``,
    ``scales``, ``thickness`` when the components have them; ``tabor``, ``tabor_glassy``
    (``None`` without a physical scale or without adhesion), ``tabor_radius`` (m),
    ``adhesion_length`` (m), ``equilibrium_distance`` (m), ``tabor_note``; ``physical`` (the
    echoed SI table or ``None``) and ``warnings`` (list of strings, e.g. μ_T < 3).

    For adhesion kind ``maugis-dugdale`` (see ``docs/cohesive.md``): ``range`` h̃0,
    ``range_ratio`` η = h̃0/Λ̃, ``cohesive_stress`` σ̃0 = 2πγ̃/(h̃0Λ̃), ``strength_ratio``
    σ0/E* = πγ̃/h̃0, ``quasi_static_zone`` q0a0 = h̃0²/(4γ̃), ``transition`` λ and
    ``transition_glassy`` (E = βE*), ``regime`` (JKR-like for λ >= 5, DMT-like for λ <= 0.1,
    else the transition), ``tabor``/``tabor_glassy`` with Z0 = 16h0/(9√3) (no physical scale
    needed); with ``physical.E0`` and ``physical.wavelength`` also ``cohesive_range`` h0 (m),
    ``cohesive_strength`` σ0 (Pa), ``quasi_static_zone_length`` a0 (m), ``tabor_radius`` (m),
    ``adhesion_length`` Δγ/E* (m) and ``equilibrium_distance`` Z0 (m).
    """
    stats = scene.profile.statistics()
    amplitude = float(scene.profile.amplitude)
    gamma = float(_param(scene.adhesion, "gamma") or 0.0) if scene.adhesive else 0.0
    groups: dict[str, Any] = {s: kind_of(s, getattr(scene, s))
                              for s in ("profile", "rheology", "kernel", "adhesion", "solver")}
    groups.update(gamma=gamma, Gamma=gamma / amplitude**2, amplitude=amplitude,
                  rms=float(stats.rms), m2=float(stats.m2), zeta=scene.zeta,
                  beta=float(scene.rheology.modulus_ratio), poisson=scene.poisson)
    groups[scene.load.controlled] = scene.load.value
    for name in ("hurst", "scales", "rolloff", "seed"):
        if getattr(scene.profile, name, None) is not None:
            groups[name] = _plain(getattr(scene.profile, name))
    if getattr(scene.kernel, "thickness", None) is not None:
        groups["thickness"] = float(scene.kernel.thickness)
    if kind_of("adhesion", scene.adhesion) == COHESIVE_KIND:
        groups.update(_cohesive(scene, groups))  # finite range: no short-range warnings
        warnings: list[str] = []
    else:
        tabor, warnings = _tabor(scene, groups)
        groups.update(tabor)
    groups["physical"] = dict(scene.physical) if scene.physical is not None else None
    groups["warnings"] = warnings
    return groups
