"""The top-level API: ``import viscocontact as vc`` is light, and ``vc.<name>`` is the same
object as the one in its module."""
from __future__ import annotations

import importlib
import subprocess
import sys
from pathlib import Path

import pytest

import viscocontact as vc
from viscocontact.testing.scenes import WAVY

EXAMPLES = Path(__file__).resolve().parents[3] / "examples" / "scenes"

SCENE = WAVY

HOMES = {
    "Scene": "viscocontact.scene", "Load": "viscocontact.scene",
    "ArealScene": "viscocontact.areal.scene", "read_scene": "viscocontact.read",
    "PhysicalResult": "viscocontact.units", "ContactProblem": "viscocontact.problem",
    "Discretization": "viscocontact.problem", "ContactResult": "viscocontact.result",
    "SolveStatus": "viscocontact.result", "Tolerances": "viscocontact.solvers",
    "dimensionless_groups": "viscocontact.groups",
    "Sinusoid": "viscocontact.profiles", "SelfAffineProfile": "viscocontact.profiles",
    "MeasuredProfile": "viscocontact.profiles", "Elastic": "viscocontact.rheology",
    "StandardLinearSolid": "viscocontact.rheology", "PronySeries": "viscocontact.rheology",
    "HalfPlane": "viscocontact.kernels", "ConfinedLayer": "viscocontact.kernels",
    "FreeLayer": "viscocontact.kernels", "NoAdhesion": "viscocontact.adhesion",
    "EnergyBalance": "viscocontact.adhesion", "MaugisDugdale": "viscocontact.adhesion",
    "Newton": "viscocontact.solvers",
    "Broyden": "viscocontact.solvers", "Bisection": "viscocontact.solvers",
    "NonlinearCG": "viscocontact.solvers", "Sweep": "viscocontact.studies",
    "Cycle": "viscocontact.studies", "StudyData": "viscocontact.studies",
    "load_study": "viscocontact.studies", "confidence_band": "viscocontact.studies",
    "log_zetas": "viscocontact.studies", "StudyFileError": "viscocontact.studies",
    "plot_study": "viscocontact.plots", "WavyStudy": "viscocontact.study",
    "ViscoContactError": "viscocontact.errors", "ValidationError": "viscocontact.errors",
    "PluginError": "viscocontact.errors", "ConvergenceError": "viscocontact.errors",
    "TimeLimitExceeded": "viscocontact.errors", "ViscoContactWarning": "viscocontact.errors",
    "PluginWarning": "viscocontact.errors", "ModelValidityWarning": "viscocontact.errors",
    "CertificationWarning": "viscocontact.errors",
    "AccuracyWarning": "viscocontact.errors",
}


def test_import_is_light():
    """No numpy, scipy, matplotlib or h5py until a name is used (a CLI's --help, a plugin's
    entry point, a worker's start-up stay fast)."""
    code = ("import sys, viscocontact as vc; vc.__all__; dir(vc);"
            "print(sorted(m for m in ('numpy', 'scipy', 'matplotlib', 'h5py', 'attrs')"
            " if m in sys.modules))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]"


@pytest.mark.parametrize("name", sorted(HOMES))
def test_exports_are_the_modules_objects(name):
    assert getattr(vc, name) is getattr(importlib.import_module(HOMES[name]), name)


def test_study_functions_under_unambiguous_names():
    from viscocontact import studies

    assert vc.run_study is studies.run and vc.resume_study is studies.resume


def test_all_and_dir_list_the_api():
    assert set(vc.__all__) == set(HOMES) | {"run_study", "resume_study", "solve", "__version__"}
    listed = dir(vc)
    assert set(vc.__all__) <= set(listed)
    assert {"studies", "plots", "profiles", "deadline"} <= set(listed)
    assert vc.studies is importlib.import_module("viscocontact.studies")
    namespace: dict = {}
    exec("from viscocontact import *", namespace)
    assert set(vc.__all__) <= set(namespace)


def test_unknown_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'Sinusiod'"):
        vc.Sinusiod
    assert not hasattr(vc, "numpy")


def test_solve_a_scene_file_the_way_the_readme_does(tmp_path):
    """``vc.solve(vc.Scene.from_toml(path))``, and the same from the path, the TOML text and the
    scene table: one equilibrium, the same bits."""
    text = SCENE
    path = tmp_path / "scene.toml"
    path.write_text(text)
    disc = vc.Discretization(elements=32)
    result = vc.solve(vc.Scene.from_toml(path), discretization=disc)
    assert isinstance(result, vc.ContactResult)
    assert result.converged and result.status is vc.SolveStatus.CONVERGED
    assert result.n_contacts == 1 and 0 < result.area < 2 * 3.141592653589793
    assert result.mean_pressure == pytest.approx(0.1, rel=1e-9)
    scene = vc.Scene.from_toml(path)
    for source in (path, str(path), text, scene.to_dict()):
        again = vc.solve(source, discretization=disc)
        assert (again.area, again.friction) == (result.area, result.friction)


def test_solve_rejects_other_things():
    with pytest.raises(vc.ValidationError) as info:
        vc.solve(42)
    assert info.value.field == "scene"


def test_solve_time_limit():
    scene = vc.Scene.from_toml(EXAMPLES / "sinusoid.toml")
    with pytest.raises(vc.TimeLimitExceeded, match="time limit of 1e-06 s"):
        vc.solve(scene, time_limit=1e-6)
