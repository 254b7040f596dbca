"""Classical reference theories of contact mechanics (thesis Chapters 1 and 3), for comparison.

Single contacts (any consistent units, SI in the docstrings):

====================================  =========================================================
:mod:`.hertz`                         :class:`HertzSphere` (eqs. 1.7-1.15), :class:`HertzCylinder`,
                                      :func:`reduced_modulus` (1.13), :func:`combined_radius` (1.4)
:mod:`.jkr`                           :class:`JKRSphere` (1.39-1.47, load- and displacement-
                                      controlled pull-off), :class:`JKRCylinder`, :class:`PullOff`
:mod:`.dmt`                           :class:`DMTSphere` (pull-off ``2πΔγR``)
:mod:`.tabor`                         :func:`tabor_parameter` (1.48, as :mod:`viscocontact.groups`),
                                      :func:`equivalent_crest_radius` (4.55)
:mod:`.lennard_jones`                 :class:`LennardJones` traction law (1.20)
:mod:`.wavy`                          Westergaard and Johnson (re-exported from
                                      :mod:`viscocontact.reference`), inverse forms, pull-off
====================================  =========================================================

Rough contacts, in the package's dimensionless groups (eq. 4.17: lengths × q0, ``p̃ = 2p/(E*Λ̃)``,
``E* = E0/(1-ν²)``, ``γ̃``, ``ζ = q0Vτ``):

====================================  =========================================================
:mod:`.summits`                       :class:`RoughnessMoments` (m0, m2, m4, Λ̃ of a profile) and
                                      Nayak's summit statistics (3.33, 3.48-3.49)
:mod:`.greenwood_williamson`          :class:`GreenwoodWilliamson` (3.20-3.26),
                                      :class:`FullerTabor` (JKR summits, unloading shift 3.28)
:mod:`.bgt`                           :class:`SimplifiedBGT` (Greenwood 2006, 3.29-3.33)
:mod:`.height_curvature`              :class:`HeightCurvatureModel` (Carbone 2009, 3.46-3.49)
:mod:`.spectrum`                      :class:`LineSpectrum` (one-sided spectrum of a profile)
:mod:`.persson`                       :class:`PerssonContact`: area for line roughness (3.34-3.45)
:mod:`.persson_friction`              :class:`PerssonFriction`: mean-field viscoelastic friction
:mod:`.persson_areal`                 :class:`PerssonArealContact`, :class:`PerssonArealFriction`:
                                      area and friction of areal surfaces (:class:`ArealSpectrum`,
                                      pressures as ``p̄/E*``)
====================================  =========================================================

The multi-asperity theories are intrinsically 3D (isotropic surfaces; a profile is read as the
cross-section of one). Persson's area and friction are derived here for 1D roughness on a
half-plane; :mod:`.persson_areal` holds them for areal surfaces. See ``docs/theories.md`` and
``docs/areal.md`` for the formulas, the checks and the thesis's misprints.
"""
from .asperity import AsperityModel, gaussian_tail_moment
from .bgt import SimplifiedBGT
from .dmt import DMTSphere
from .greenwood_williamson import FullerTabor, GreenwoodWilliamson
from .height_curvature import HeightCurvatureModel
from .hertz import HertzCylinder, HertzSphere, combined_radius, reduced_modulus
from .jkr import JKRCylinder, JKRSphere, PullOff
from .lennard_jones import LennardJones
from .persson import PerssonContact
from .persson_areal import ArealSpectrum, PerssonArealContact, PerssonArealFriction
from .persson_friction import PerssonFriction
from .spectrum import LineSpectrum
from .summits import (RoughnessMoments, summit_height_density, summit_joint_density,
                      summit_mean_curvature)
from .tabor import equivalent_crest_radius, tabor_parameter
from .wavy import (JohnsonWavy, johnson_pull_off_load, johnson_pull_off_penetration,
                   westergaard_area, westergaard_area_at_penetration, westergaard_penetration,
                   westergaard_pressure)

__all__ = [
    "ArealSpectrum", "AsperityModel", "DMTSphere", "FullerTabor", "GreenwoodWilliamson",
    "HeightCurvatureModel", "HertzCylinder", "HertzSphere", "JKRCylinder", "JKRSphere", "JohnsonWavy", "LennardJones",
    "LineSpectrum", "PerssonArealContact", "PerssonArealFriction", "PerssonContact",
    "PerssonFriction", "PullOff", "RoughnessMoments",
    "SimplifiedBGT", "combined_radius", "equivalent_crest_radius", "gaussian_tail_moment",
    "johnson_pull_off_load", "johnson_pull_off_penetration", "reduced_modulus",
    "summit_height_density", "summit_joint_density", "summit_mean_curvature", "tabor_parameter",
    "westergaard_area", "westergaard_area_at_penetration", "westergaard_penetration",
    "westergaard_pressure",
]
