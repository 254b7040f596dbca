"""The dimensionless groups of a scene (thesis equation 4.17) and its Tabor parameter (equation
1.48).

:func:`dimensionless_groups` is what ``viscocontact describe`` prints.

Tabor parameter
---------------
``μ_T = (R Δγ² / (E*² Z0³))^(1/3) = l^(2/3) R^(1/3) / Z0`` with the adhesion length ``l = Δγ/E*``
and the reduced (rubbery) modulus ``E* = E0/(1-ν²)``; ``tabor_glassy`` uses ``E∞/(1-ν²)``. The
thesis's eq. 1.48 prints ``E*`` to the first power in its first form, which is dimensionally
inconsistent; its second form (used here) is the standard one (Tabor 1977,
doi:10.1016/0021-9797(77)90396-4). The radius R is that of the crest of an equivalent sinusoid
(eq. 4.55): ``R = 1/(q0² Λ)`` for a sinusoid of amplitude Λ, and ``R = 1/(q0² r_rms)``
(= λ0²/(4π² r_rms)) for any other profile.

For the thesis's physical case (E0 = 10 MPa, ν = 0.5, Δγ = 0.01 J/m², λ0 = 6.28 mm,
r_rms = 10 µm, Z0 = 1 nm; R ≈ 0.1 m) this gives μ_T ≈ 383; the thesis's "μ_T ≈ 460" is obtained
with E0 in place of E* (≈ 464).
"""
from __future__ import annotations

import math
from typing import Any

from .components import ComponentSpec, _param, _plain, kind_of
from .theories.tabor import tabor_parameter
from .units import COHESIVE_KIND

__all__ = ["DEFAULT_EQUILIBRIUM_DISTANCE", "TABOR_SHORT_RANGE", "dimensionless_groups",
           "tabor_parameter"]


DEFAULT_EQUILIBRIUM_DISTANCE = 1e-9  # m, Z0 of the Tabor parameter


TABOR_SHORT_RANGE = 3.0  # Greenwood: JKR (infinitely short-range adhesion) is accurate for μ_T >> 3


def _tabor(scene: Any, groups: dict[str, Any]) -> tuple[dict[str, Any], list[str]]:
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


def _cohesive(scene: Any, groups: dict[str, Any]) -> dict[str, Any]:
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


def dimensionless_groups(scene: Any) -> dict[str, Any]:
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
