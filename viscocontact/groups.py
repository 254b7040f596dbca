"""The dimensionless groups of a scene (thesis eq. 4.17) and its Tabor parameter (eq. 1.48).

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

from .scene import DEFAULT_EQUILIBRIUM_DISTANCE, Scene, _param, _plain, kind_of

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


def _tabor(scene: Scene, groups: dict[str, Any]) -> tuple[dict[str, Any], list[str]]:
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
    if kind_of("profile", scene.profile) == "sinusoid":
        radius = 1.0 / (q0 * groups["amplitude"])  # 1/(q0² Λ)
        which = "crest radius 1/(q0² Λ) of the sinusoid"
    else:
        radius = 1.0 / (q0 * groups["rms"])  # 1/(q0² r_rms), eq. 4.55
        which = "R = λ0²/(4π² r_rms) of the equivalent sinusoid (eq. 4.55)"
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


def dimensionless_groups(scene: Scene) -> dict[str, Any]:
    """The dimensionless groups of ``scene`` (JSON-ready).

    Keys: the component kinds (``profile``, ``rheology``, ``kernel``, ``adhesion``, ``solver``);
    ``gamma`` γ̃, ``Gamma`` γ̃/Λ̃², ``amplitude`` Λ̃ = q0·max r, ``rms`` q0·r_rms, ``m2`` <r'²>,
    ``zeta`` ζ, ``beta`` E∞/E0, ``poisson``, ``mean_pressure`` or ``penetration``; ``hurst``,
    ``scales``, ``thickness`` when the components have them; ``tabor``, ``tabor_glassy``
    (``None`` without a physical scale or without adhesion), ``tabor_radius`` (m),
    ``adhesion_length`` (m), ``equilibrium_distance`` (m), ``tabor_note``; ``physical`` (the
    echoed SI table or ``None``) and ``warnings`` (list of strings, e.g. μ_T < 3).
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
    tabor, warnings = _tabor(scene, groups)
    groups.update(tabor)
    groups["physical"] = dict(scene.physical) if scene.physical is not None else None
    groups["warnings"] = warnings
    return groups
