"""Units: a scene's ``[physical]`` table into the groups of equation 4.17, and a result back.

The numerics run on dimensionless arrays in the thesis's groups (eq. 4.17); SI units are
converted at this one boundary, both ways.

**Into the groups** (:func:`physical_targets`, used when a scene is read; see
:data:`PHYSICAL_KEYS` and ``docs/scene.md``): ``q0 = 2π/λ0``, ``γ̃ = (1-ν²) q0 Δγ/(π E0)``,
``ζ = q0 V τ``, ``Λ̃ = q0 Λ``, ``rms → q0 r_rms``, ``thickness → q0 d``,
``p̃∞ = 2(1-ν²) p∞/(E0 q0 Λ)``, ``Δ̃ = Δ/Λ`` with ``Λ = max r`` of the built profile, and the
Maugis–Dugdale range ``h̃0 = q0 h0`` (or ``πγ̃E*/σ0`` from a cohesive strength). A physical value
fills its dimensionless key when that key is absent; when both are present they must agree to
1e-9 relative.

**Back** (the result's physical view, :func:`physical_result`):

* lengths along the interface: ``x = x̃/q0`` with ``q0 = 2π/λ0``, so the contact length is
  ``Ã/q0`` per period (``λ0`` in full contact, where ``Ã = 2π``);
* the penetration: ``Δ = Δ̃·Λ`` with ``Λ = Λ̃/q0`` the profile's amplitude;
* pressures: ``p = p̃·E0·Λ̃/(2(1-ν²))`` (eq. 4.17's ``p̃∞ = 2(1-ν²)p∞/(E0 q0 Λ)``).

>>> import viscocontact as vc
>>> scene = vc.Scene.from_toml("examples/scenes/thesis_wavy.toml")
>>> si = vc.solve(scene).physical(scene)
>>> round(si.mean_pressure)                   # Pa: p̃∞ = 0.3 with E0 = 10 MPa, Λ̃ = 0.0503
100531
"""
from __future__ import annotations

import math
from typing import Any, Mapping

import attrs
import numpy as np

from ._numbers import _agree, _check_number, _is_number
from .components import ComponentSpec, _init_fields, did_you_mean
from .errors import ValidationError


@attrs.frozen(kw_only=True)
class PhysicalResult:
    """A :class:`~viscocontact.result.ContactResult` in SI units (one period of the profile).

    Parameters
    ----------
    contact_length : float
        Length in contact per period, ``Ã/q0`` (m); the wavelength λ0 in full contact.
    contact_fraction : float
        The fraction of the period in contact, ``Ã/(2π)`` (1).
    edges : ndarray, shape (n_contacts, 2)
        Leading and trailing edge of each contact, ``x̃/q0`` (m).
    penetration : float
        Penetration Δ (m).
    mean_pressure : float
        Remote mean pressure p∞ (Pa; negative: tensile).
    tangential_stress : float
        Mean tangential (friction) stress ``μ·p∞`` (Pa).
    friction : float
        Friction coefficient μ (1).
    wavelength, amplitude : float
        The scale: λ0 = 2π/q0 and the profile's amplitude Λ (m).
    """

    contact_length: float
    contact_fraction: float
    edges: np.ndarray = attrs.field(eq=attrs.cmp_using(eq=np.array_equal))
    penetration: float
    mean_pressure: float
    tangential_stress: float
    friction: float
    wavelength: float
    amplitude: float


def require_scale(scene: Any) -> Mapping[str, float]:
    """The scene's ``[physical]`` table if it gives the SI scale of a result (``wavelength``
    and ``E0``); else a :class:`ValidationError` naming the missing key."""
    phys = scene.physical or {}
    for key, meaning in (("wavelength", "fundamental wavelength λ0, m"),
                         ("E0", "relaxed Young modulus E0, Pa")):
        if key not in phys:
            raise ValidationError(f"physical.{key}", None,
                                  f"a value ({meaning}): needed to read a result in SI units")
    return phys


def physical_result(result: Any, scene: Any) -> PhysicalResult:
    """``result`` (a solve of ``scene``) in SI units, from the scene's ``[physical]`` table.

    Raises :class:`ValidationError` naming the ``physical`` key the conversion needs
    (``physical.wavelength`` for lengths, ``physical.E0`` for pressures) when it is missing.
    """
    phys = require_scale(scene)
    q0 = 2.0 * math.pi / phys["wavelength"]
    amplitude = float(scene.profile.amplitude)          # Λ̃ = q0·Λ
    pressure_scale = phys["E0"] * amplitude / (2.0 * (1.0 - scene.poisson**2))
    edges = np.array(result.edges, dtype=float).reshape(-1, 2) / q0
    edges.setflags(write=False)
    return PhysicalResult(
        contact_length=float(result.area) / q0,
        contact_fraction=float(result.area) / (2.0 * math.pi),
        edges=edges,
        penetration=float(result.penetration) * amplitude / q0,
        mean_pressure=float(result.mean_pressure) * pressure_scale,
        tangential_stress=float(result.friction * result.mean_pressure) * pressure_scale,
        friction=float(result.friction),
        wavelength=float(phys["wavelength"]),
        amplitude=amplitude / q0)


# ---- into the groups -------------------------------------------------------------------------
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
