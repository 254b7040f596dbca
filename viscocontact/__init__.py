"""viscocontact: adhesive, rough, viscoelastic contact in steady sliding.

A rigid periodic profile slides at speed V over a linear viscoelastic half-plane or layer; the
steady-state contact problem (Mastropasqua's thesis, Chapter 4) is solved with a boundary-element
method on edge-clustered meshes and a viscoelastic Griffith energy balance at every contact edge.
All numerics run in the dimensionless groups of the thesis's eq. 4.17.

>>> import viscocontact as vc
>>> scene = vc.Scene.from_dict({"profile": {"kind": "sinusoid", "amplitude": 0.1},
...                             "rheology": {"kind": "standard-linear-solid", "beta": 10.0},
...                             "load": {"mean_pressure": 0.1}, "sliding": {"zeta": 1.0}})
>>> result = vc.solve(scene)             # or vc.solve("scene.toml")
>>> result.converged, result.n_contacts
(True, 1)

The names below are imported on first use, so ``import viscocontact`` loads neither numpy,
scipy, matplotlib nor h5py:

* scenes and solves: :class:`Scene` (with its :class:`Load`; ``scene.replace(zeta=...)``
  derives a variant), :class:`ArealScene` (a ``[surface]`` scene), :func:`read_scene` (either
  kind from a file), :func:`solve`, :class:`ContactProblem`,
  :class:`Discretization`, :class:`Tolerances`, :class:`ContactResult` (``result.physical(scene)``:
  the :class:`PhysicalResult` in SI units), :class:`SolveStatus`,
  :func:`dimensionless_groups` (a time limit for any block: ``vc.deadline.deadline``);
* components: profiles :class:`Sinusoid`, :class:`SelfAffineProfile`, :class:`MeasuredProfile`;
  rheologies :class:`Elastic`, :class:`StandardLinearSolid`, :class:`PronySeries`; kernels
  :class:`HalfPlane`, :class:`ConfinedLayer`, :class:`FreeLayer`; adhesion :class:`NoAdhesion`,
  :class:`EnergyBalance`, :class:`MaugisDugdale`; solvers :class:`Newton`, :class:`Broyden`, :class:`Bisection`,
  :class:`NonlinearCG`;
* studies: :class:`Sweep`, :class:`Cycle`, :func:`run_study` and :func:`resume_study`
  (``viscocontact.studies.run`` and ``resume``), :func:`load_study`, :class:`StudyData`,
  :func:`confidence_band`, :func:`log_zetas`, :func:`plot_study`, :class:`WavyStudy` (the default
  study);
* errors and warnings: :class:`ViscoContactError` and its subclasses :class:`ValidationError`,
  :class:`PluginError`, :class:`ConvergenceError`, :class:`TimeLimitExceeded`,
  :class:`StudyFileError`; :class:`ViscoContactWarning`, :class:`PluginWarning`,
  :class:`ModelValidityWarning`, :class:`CertificationWarning`, :class:`AccuracyWarning`.

The subpackages (``vc.profiles``, ``vc.studies``, ``vc.plots``, ...) are reachable as attributes
too, also imported on first use.
"""
from __future__ import annotations

import importlib
import os
from collections.abc import Mapping
from importlib.metadata import PackageNotFoundError, version
from typing import Any

try:
    __version__ = version("viscocontact")
except PackageNotFoundError:  # pragma: no cover - running from a source tree
    __version__ = "0.0.0+unknown"

#: public name -> (module, attribute), imported on first access
_EXPORTS: dict[str, tuple[str, str]] = {
    "Scene": ("scene", "Scene"),
    "Load": ("scene", "Load"),
    "ArealScene": ("areal.scene", "ArealScene"),
    "read_scene": ("read", "read_scene"),
    "ContactProblem": ("problem", "ContactProblem"),
    "Discretization": ("problem", "Discretization"),
    "ContactResult": ("result", "ContactResult"),
    "SolveStatus": ("result", "SolveStatus"),
    "PhysicalResult": ("units", "PhysicalResult"),
    "Tolerances": ("solvers", "Tolerances"),
    "dimensionless_groups": ("groups", "dimensionless_groups"),
    **{name: ("profiles", name) for name in ("Sinusoid", "SelfAffineProfile", "MeasuredProfile")},
    **{name: ("rheology", name) for name in ("Elastic", "StandardLinearSolid", "PronySeries")},
    **{name: ("kernels", name) for name in ("HalfPlane", "ConfinedLayer", "FreeLayer")},
    **{name: ("adhesion", name) for name in ("NoAdhesion", "EnergyBalance", "MaugisDugdale")},
    **{name: ("solvers", name) for name in ("Newton", "Broyden", "Bisection", "NonlinearCG")},
    **{name: ("studies", name) for name in ("Sweep", "Cycle", "StudyData", "load_study",
                                            "confidence_band", "log_zetas", "StudyFileError")},
    "run_study": ("studies", "run"),
    "resume_study": ("studies", "resume"),
    "plot_study": ("plots", "plot_study"),
    "WavyStudy": ("study", "WavyStudy"),
    **{name: ("errors", name) for name in (
        "ViscoContactError", "ValidationError", "PluginError", "ConvergenceError",
        "TimeLimitExceeded", "ViscoContactWarning", "PluginWarning", "ModelValidityWarning",
        "CertificationWarning", "AccuracyWarning")},
}

#: subpackages and modules reachable as attributes (``vc.studies``)
_SUBMODULES = frozenset({
    "adhesion", "contact", "deadline", "errors", "groups", "kernels", "methods", "plan", "plots",
    "problem", "profiles", "reference", "result", "rheology", "scene", "solvers", "studies",
    "study", "testing", "theories", "units", "defaults", "data", "areal", "read"})

__all__ = sorted([*_EXPORTS, "solve", "__version__"])


def solve(scene, *, initial=None, fields: bool = False, raise_on_failure: bool = False,
          time_limit: float | None = None, **options: Any):
    """The equilibrium of one scene, as a :class:`~viscocontact.result.ContactResult`.

    Parameters
    ----------
    scene : Scene, ArealScene, str, path or mapping
        A :class:`~viscocontact.scene.Scene`, an :class:`~viscocontact.areal.scene.ArealScene`,
        a scene file (TOML path or text, with a ``[profile]`` or a ``[surface]``) or a scene
        table (the dict ``to_dict`` writes). An areal scene takes no ``initial`` nor
        ``options`` (its grid and method options are the scene's).
    initial : ContactResult or array of edges, optional
        Contact set to start from; default the approach path from first touch.
    fields : bool
        Also return pressure, displacement and gap on the check grid.
    raise_on_failure : bool
        Raise :class:`~viscocontact.errors.ConvergenceError` (carrying the result) instead of
        returning a result with ``converged = False``.
    time_limit : float or None
        Wall time allowed (s); past it :class:`~viscocontact.errors.TimeLimitExceeded` is raised
        at the next residual evaluation (a :func:`~viscocontact.deadline.deadline`: the
        kernel-table precomputation is not interrupted).
    **options
        Keyword arguments of :class:`~viscocontact.problem.ContactProblem`: ``discretization``,
        ``tolerances``, ``kernel_tolerance``, ``max_restarts``, ``fallback``.
    """
    from pathlib import Path

    from .deadline import deadline
    from .errors import ValidationError
    from .areal.scene import ArealScene
    from .problem import ContactProblem
    from .read import read_scene, scene_from_dict
    from .scene import Scene

    if isinstance(scene, os.PathLike):
        scene = read_scene(Path(scene))
    elif isinstance(scene, str):
        scene = read_scene(scene)
    elif isinstance(scene, Mapping):
        scene = scene_from_dict(scene)
    elif not isinstance(scene, (Scene, ArealScene)):
        raise ValidationError("scene", scene, "a Scene, an ArealScene, a scene file (path or "
                                              "TOML text) or a scene table")
    if isinstance(scene, ArealScene):
        if initial is not None or options:
            raise ValidationError("initial" if initial is not None else next(iter(options)),
                                  "(given)", "no value for an areal scene (its options are its "
                                             "[method]'s)")
        with deadline(time_limit):
            result = scene.solve(fields=fields)
        if raise_on_failure and not result.converged:
            from .errors import ConvergenceError

            raise ConvergenceError(result.message, result)
        return result
    problem = ContactProblem.from_scene(scene, **options)
    with deadline(time_limit):
        return problem.solve(initial=initial, fields=fields, raise_on_failure=raise_on_failure)


def __getattr__(name: str) -> Any:
    if name in _EXPORTS:
        module, attribute = _EXPORTS[name]
        value = getattr(importlib.import_module(f"{__name__}.{module}"), attribute)
        globals()[name] = value        # the next access is a plain attribute look-up
        return value
    if name in _SUBMODULES:
        return importlib.import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__) | _SUBMODULES)
