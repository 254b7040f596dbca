"""The result's physical view: a solve of a scene given in SI units, read in SI units.

The numerics run in the groups of the thesis's eq. 4.17; a scene's ``[physical]`` table gives
their scale (:mod:`viscocontact.scene` converts it into the groups). Here the same scale turns a
:class:`~viscocontact.result.ContactResult` back:

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
from typing import Any

import attrs
import numpy as np

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


def physical_result(result: Any, scene: Any) -> PhysicalResult:
    """``result`` (a solve of ``scene``) in SI units, from the scene's ``[physical]`` table.

    Raises :class:`ValidationError` naming the ``physical`` key the conversion needs
    (``physical.wavelength`` for lengths, ``physical.E0`` for pressures) when it is missing.
    """
    phys = scene.physical or {}
    for key, meaning in (("wavelength", "fundamental wavelength λ0, m"),
                         ("E0", "relaxed Young modulus E0, Pa")):
        if key not in phys:
            raise ValidationError(f"physical.{key}", None,
                                  f"a value ({meaning}): needed to read a result in SI units")
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
