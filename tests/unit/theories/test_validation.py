"""Bad input raises ValidationError naming the field and the allowed range."""
from __future__ import annotations

import math

import numpy as np
import pytest

from viscocontact import ValidationError
from viscocontact.profiles import Sinusoid
from viscocontact.rheology import StandardLinearSolid
from viscocontact.theories import (DMTSphere, FullerTabor, GreenwoodWilliamson, HertzCylinder,
                                   HertzSphere, JKRCylinder, JKRSphere, LennardJones, LineSpectrum,
                                   PerssonContact, PerssonFriction, RoughnessMoments, reduced_modulus,
                                   tabor_parameter, westergaard_area_at_penetration)

SPEC = LineSpectrum.from_profile(Sinusoid(amplitude=0.1))


@pytest.mark.parametrize("build,field,allowed", [
    (lambda: HertzSphere(radius=-1.0, reduced_modulus=1.0), "HertzSphere.radius", "(0.0, inf]"),
    (lambda: HertzCylinder(radius=1.0, reduced_modulus=math.nan), "HertzCylinder.reduced_modulus",
     "(0.0, inf]"),
    (lambda: JKRSphere(radius=1.0, reduced_modulus=1.0, work_of_adhesion=-0.1),
     "JKRSphere.work_of_adhesion", "[0.0, inf]"),
    (lambda: DMTSphere(radius=0.0, reduced_modulus=1.0, work_of_adhesion=0.1), "DMTSphere.radius",
     "(0.0, inf]"),
    (lambda: LennardJones(work_of_adhesion=1.0, equilibrium_distance=0.0),
     "LennardJones.equilibrium_distance", "(0.0, inf]"),
    (lambda: RoughnessMoments(m0=1.0, m2=-1.0, m4=1.0), "RoughnessMoments.m2", "(0.0, inf]"),
    (lambda: RoughnessMoments(m0="x", m2=1.0, m4=1.0), "RoughnessMoments.m0", "(0.0, inf]"),
    (lambda: GreenwoodWilliamson(summit_density=1.0, summit_radius=1.0, summit_std=0.0),
     "GreenwoodWilliamson.summit_std", "(0.0, inf]"),
    (lambda: FullerTabor(summit_density=1.0, summit_radius=1.0, summit_std=1.0, gamma=-1e-3),
     "FullerTabor.gamma", "[0.0, inf]"),
    (lambda: LineSpectrum(wavenumbers=[1.0, 1.0], weights=[1.0, 1.0], amplitude=1.0),
     "LineSpectrum.wavenumbers", "strictly increasing"),
    (lambda: LineSpectrum(wavenumbers=[1.0], weights=[-1.0], amplitude=1.0),
     "LineSpectrum.weights", ">= 0"),
    (lambda: LineSpectrum(wavenumbers=[1.0], weights=[1.0], amplitude=0.0),
     "LineSpectrum.amplitude", "(0.0, inf]"),
    (lambda: PerssonFriction(spectrum=SPEC, rheology=StandardLinearSolid(beta=2.0),
                             contact_correction=1.5),
     "PerssonFriction.contact_correction", "[0.0, 1.0]"),
])
def test_bad_fields(build, field, allowed):
    with pytest.raises(ValidationError) as err:
        build()
    assert err.value.field == field
    assert allowed in err.value.allowed


@pytest.mark.parametrize("call,field,allowed", [
    (lambda: HertzSphere(radius=1.0, reduced_modulus=1.0).contact_radius(-1.0), "load", "[0.0, inf]"),
    (lambda: HertzSphere(radius=1.0, reduced_modulus=1.0).displacement(2.0, 1.0), "r", "contact_radius"),
    (lambda: JKRSphere(radius=1.0, reduced_modulus=1.0, work_of_adhesion=0.1).contact_radius(-1.0),
     "load", f"[{-0.15 * math.pi}"),
    (lambda: JKRSphere(radius=1.0, reduced_modulus=1.0, work_of_adhesion=0.1)
     .contact_radius_at_penetration(-10.0), "penetration", "[-"),
    (lambda: JKRCylinder(radius=1.0, reduced_modulus=1.0, work_of_adhesion=0.1).half_width(-5.0),
     "load", "[-"),
    (lambda: DMTSphere(radius=1.0, reduced_modulus=1.0, work_of_adhesion=0.1).contact_radius(-1.0),
     "load", "[-"),
    (lambda: LennardJones(work_of_adhesion=1.0, equilibrium_distance=1.0).traction(
        np.array([1.0, -1.0])), "gap", "(0.0, inf]"),
    (lambda: reduced_modulus(1.0, 0.7), "poisson1", "(-1.0, 0.5]"),
    (lambda: tabor_parameter(radius=0.0, work_of_adhesion=0.01, reduced_modulus=1.0), "radius",
     "(0.0, inf]"),
    (lambda: westergaard_area_at_penetration(1.5), "penetration", "[0.0, 1.0]"),
    (lambda: PerssonContact(spectrum=SPEC).area_fraction(-0.1), "mean_pressure", "[0.0, inf]"),
    (lambda: PerssonContact(spectrum=SPEC).area_fraction(0.1, 0.5), "magnification", "[1.0, inf]"),
    (lambda: PerssonContact(spectrum=SPEC).mean_pressure_at_area(1.0), "area_fraction", "[0.0, 1.0)"),
    (lambda: PerssonFriction(spectrum=SPEC, rheology=StandardLinearSolid(beta=2.0))
     .coefficient(-1.0, 0.1), "zeta", "[0.0, inf]"),
    (lambda: PerssonFriction(spectrum=SPEC, rheology=StandardLinearSolid(beta=2.0))
     .coefficient(1.0, 0.0), "mean_pressure", "(0.0, inf]"),
    (lambda: GreenwoodWilliamson(summit_density=1.0, summit_radius=1.0, summit_std=1.0)
     .mean_pressure(0.0), "GreenwoodWilliamson.amplitude", "(0.0, inf]"),
    (lambda: GreenwoodWilliamson(summit_density=1.0, summit_radius=1.0, summit_std=1.0,
                                 amplitude=1.0).separation_at_pressure(0.0), "mean_pressure",
     "(0.0, inf]"),
])
def test_bad_arguments(call, field, allowed):
    with pytest.raises(ValidationError) as err:
        call()
    assert err.value.field == field
    assert allowed in err.value.allowed
