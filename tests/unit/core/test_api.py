"""The Python API without traps: one set of defaults for a Scene and a ContactProblem, clear
errors for a component given by name, a load given as a mapping, ``Scene.replace``, "did you
mean" for mistyped keys, and solve events logged while the solve runs."""
from __future__ import annotations

import logging

import pytest

import viscocontact as vc
from viscocontact.problem import ContactProblem
from viscocontact.scene import Scene

WAVY = dict(profile=vc.Sinusoid(amplitude=0.1), rheology=vc.StandardLinearSolid(beta=10.0),
            zeta=1.0)


@pytest.mark.parametrize("adhesion, solver", [(vc.NoAdhesion(), vc.Bisection()),
                                              (vc.EnergyBalance(gamma=1e-4), vc.Broyden())])
def test_a_problem_and_a_scene_have_the_same_defaults(adhesion, solver):
    scene = Scene(adhesion=adhesion, load={"mean_pressure": 0.3}, **WAVY).resolve()
    problem = ContactProblem(adhesion=adhesion, mean_pressure=0.3, **WAVY)
    assert problem == ContactProblem.from_scene(scene)
    assert problem.solver == scene.solver == solver
    assert problem.method == scene.method and problem.method.name == "auto"
    assert problem.kernel == scene.kernel


def test_an_adhesionless_problem_solves_as_its_scene_does():
    """The same method (the spectral grid, via auto) and the same answer by either path."""
    problem = ContactProblem(mean_pressure=0.3, **WAVY)
    direct, scene = problem.solve(), vc.solve(Scene(load={"mean_pressure": 0.3}, **WAVY))
    assert direct.method == scene.method == "spectral"
    assert direct.area == scene.area and direct.friction == scene.friction


@pytest.mark.parametrize("field, value, text", [
    ("rheology", "elastic", "viscocontact.rheology.elastic.Elastic(...)"),
    ("rheology", "elastc", "'standard-linear-solid'"),
    ("profile", {"kind": "sinusoid"}, "Profile"),
    ("solver", "newton", "Newton(...)"),
])
def test_a_component_given_by_name_fails_at_once_naming_the_field(field, value, text):
    with pytest.raises(vc.ValidationError) as info:
        ContactProblem(**{**WAVY, field: value}, mean_pressure=0.3)
    assert info.value.field == f"ContactProblem.{field}" and text in str(info.value)


def test_a_scene_takes_its_load_as_a_mapping_or_a_load():
    assert vc.Load is vc.scene.Load
    a = Scene(load={"mean_pressure": 0.3}, **WAVY)
    assert a == Scene(load=vc.Load(mean_pressure=0.3), **WAVY)
    with pytest.raises(vc.ValidationError, match="did you mean 'penetration'"):
        Scene(load={"penetraton": 0.3}, **WAVY)
    with pytest.raises(vc.ValidationError) as info:
        Scene(load=0.3, **WAVY)
    assert info.value.field == "Scene.load"


def test_replace_derives_a_checked_variant():
    base = Scene(load={"mean_pressure": 0.3}, **WAVY)
    variant = base.replace(zeta=0.1, load={"penetration": 0.5})
    assert variant.zeta == 0.1 and variant.load.penetration == 0.5 and base.zeta == 1.0
    with pytest.raises(vc.ValidationError, match="did you mean 'zeta'"):
        base.replace(zetta=0.1)
    with pytest.raises(vc.ValidationError) as info:
        base.replace(zeta=-1.0)
    assert info.value.field == "sliding.zeta"


@pytest.mark.parametrize("change, field, hint", [
    (lambda d: d["profile"].update(amplitud=0.1), "profile.amplitud", "amplitude"),
    (lambda d: d["profile"].update(kind="sinusiod"), "profile.kind", "sinusoid"),
    (lambda d: d.update(sliding={"zetta": 1.0}), "sliding.zetta", "zeta"),
    (lambda d: d.update(load={"mean_presure": 0.3}), "load.mean_presure", "mean_pressure"),
    (lambda d: d.update(phyiscal={"E0": 1e7}), "phyiscal", "physical"),
    (lambda d: d.update(physical={"wavelenght": 1e-3}), "physical.wavelenght", "wavelength"),
    (lambda d: d.update(poison=0.5), "poison", "poisson"),
])
def test_a_mistyped_key_gets_a_did_you_mean(change, field, hint):
    table = {"profile": {"kind": "sinusoid", "amplitude": 0.1}, "rheology": {"kind": "elastic"},
             "load": {"mean_pressure": 0.3}}
    change(table)
    with pytest.raises(vc.ValidationError) as info:
        Scene.from_dict(table)
    assert info.value.field == field and f"(did you mean {hint!r}?)" in str(info.value)


class _Records(logging.Handler):
    def __init__(self):
        super().__init__(logging.INFO)
        self.records = []

    def emit(self, record):
        self.records.append(record)


def test_solve_events_are_logged_as_they_happen():
    """Each event is logged by the event list when it is recorded (with the seconds since the
    solve began), not replayed from the result after the solve."""
    log, handler = logging.getLogger("viscocontact.solve"), _Records()
    log.addHandler(handler)
    level = log.level
    log.setLevel(logging.INFO)
    try:
        result = ContactProblem(adhesion=vc.EnergyBalance(gamma=1e-4), mean_pressure=0.1,
                                **WAVY).solve()
    finally:
        log.removeHandler(handler)
        log.setLevel(level)
    bem = [r for r in handler.records if r.getMessage().startswith("bem: [")]
    events = result.extras["events"]
    assert events[0].startswith("method bem") and events[1:]      # auto's choice, then the BEM's
    assert [r.getMessage().split("] ", 1)[1] for r in bem] == events[1:]
    assert all(r.funcName == "append" for r in bem)
    assert handler.records[0].getMessage().startswith("auto: method bem")


def test_the_cli_shows_the_events_with_v(tmp_path, capsys):
    from viscocontact.cli import main
    from viscocontact.testing.scenes import WAVY as TEXT

    scene = tmp_path / "w.toml"
    scene.write_text(TEXT)
    assert main(["solve", "-v", str(scene)]) == 0
    err = capsys.readouterr().err
    assert "viscocontact: auto: method spectral" in err and "viscocontact: spectral: [" in err
    assert main(["solve", str(scene)]) == 0
    assert capsys.readouterr().err == ""


def test_an_areal_solve_logs_its_grids_as_it_goes():
    """The areal method's events (one per grid of its ladder) are logged when they happen too,
    so that ``viscocontact -v solve`` shows a long areal solve's progress."""
    import numpy as np

    from viscocontact.areal.method import ArealSpectral
    from viscocontact.areal.problem import ArealProblem

    x = np.arange(64) * 2 * np.pi / 64
    h = np.cos(x)[None, :] + 0.5 * np.cos(x)[:, None]
    log, handler = logging.getLogger("viscocontact.solve"), _Records()
    log.addHandler(handler)
    level = log.level
    log.setLevel(logging.INFO)
    try:
        result = ArealSpectral().solve(ArealProblem(surface=h, rheology=vc.Elastic(),
                                                    mean_pressure=0.3))
    finally:
        log.removeHandler(handler)
        log.setLevel(level)
    assert result.converged and result.extras["events"]
    logged = [r.getMessage() for r in handler.records if r.funcName == "append"]
    assert [m.split("] ", 1)[1] for m in logged] == result.extras["events"]
    assert all(m.startswith("areal-spectral: [") for m in logged)
