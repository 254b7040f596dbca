"""Scene format: round trips, the physical boundary, the thesis's figures and every bad input."""
from __future__ import annotations

import math
import tomllib
import warnings
from importlib.metadata import EntryPoint
from pathlib import Path

import attrs
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from viscocontact import _registry
from viscocontact._toml import dumps
from viscocontact.errors import ModelValidityWarning, PluginError, ValidationError
from viscocontact.groups import dimensionless_groups, tabor_parameter
from viscocontact.kernels.half_plane import HalfPlane
from viscocontact.kernels.layers import ConfinedLayer
from viscocontact.profiles import SelfAffineProfile, Sinusoid
from viscocontact.rheology.elastic import Elastic
from viscocontact.rheology.sls import StandardLinearSolid
from viscocontact.scene import ComponentSpec, Load, Scene, build_component, kind_of

EXAMPLES = Path(__file__).resolve().parents[3] / "examples" / "scenes"

BASE = {
    "profile": {"kind": "sinusoid", "amplitude": 0.05},
    "rheology": {"kind": "standard-linear-solid", "beta": 10.0},
    "kernel": {"kind": "half-plane"},
    "adhesion": {"kind": "energy-balance", "gamma": 1e-5},
    "solver": {"kind": "broyden"},
    "load": {"mean_pressure": 0.3},
    "sliding": {"zeta": 0.01},
}

THESIS = {"E0": 1e7, "poisson": 0.5, "wavelength": 6.28e-3, "work_of_adhesion": 0.01,
          "rms": 1e-5, "equilibrium_distance": 1e-9}


def scene_dict(**sections):
    d = {k: dict(v) for k, v in BASE.items()}
    for key, value in sections.items():
        if value is None:
            d.pop(key, None)
        else:
            d[key] = value
    return d


def rough_dict(physical, **sections):
    d = scene_dict(profile={"kind": "self-affine", "hurst": 0.8, "scales": 50, "seed": 0},
                   adhesion={"kind": "energy-balance"}, physical=dict(physical))
    d.update(sections)
    return d


# ---- examples and round trips ---------------------------------------------------------------
@pytest.mark.parametrize("name", ["sinusoid.toml", "thesis_rough.toml"])
def test_examples_round_trip(name):
    scene = Scene.from_toml(EXAMPLES / name)
    text = scene.to_toml()
    again = Scene.from_toml(text)
    assert again == scene
    assert again.to_dict() == scene.to_dict()
    assert tomllib.loads(text) == scene.to_dict()


def test_sinusoid_example_values():
    scene = Scene.from_toml(str(EXAMPLES / "sinusoid.toml"))
    assert scene.profile == Sinusoid(amplitude=0.05)
    assert scene.rheology == StandardLinearSolid(beta=10.0)
    assert scene.kernel == HalfPlane()
    assert kind_of("adhesion", scene.adhesion) == "energy-balance"
    assert kind_of("solver", scene.solver) == "broyden"
    assert scene.load == Load(mean_pressure=0.3)
    assert scene.zeta == 0.01 and scene.poisson == 0.5 and scene.physical is None
    assert scene.adhesive


def test_thesis_example_is_the_thesis_case():
    scene = Scene.from_toml(EXAMPLES / "thesis_rough.toml")
    q0 = 2 * math.pi / 6.28e-3
    assert scene.profile == SelfAffineProfile(hurst=0.8, scales=50, rms=q0 * 1e-5, seed=0)
    assert scene.rheology.modulus_ratio == 10.0
    assert scene.load.mean_pressure == 0.3 and scene.zeta == 0.01
    assert dict(scene.physical) == THESIS


component_tables = st.one_of(
    st.builds(lambda a: {"kind": "sinusoid", "amplitude": a}, st.floats(1e-4, 10.0)),
    st.builds(lambda h, n, r, s: {"kind": "self-affine", "hurst": h, "scales": n, "rms": r,
                                  "seed": s},
              st.floats(0.1, 1.0), st.integers(1, 16), st.floats(1e-3, 1.0),
              st.integers(0, 2**31)))
rheology_tables = st.one_of(
    st.builds(lambda b, t: {"kind": "standard-linear-solid", "beta": b, "tau": t},
              st.floats(1.001, 1e4), st.floats(1e-3, 1e3)),
    st.builds(lambda e: {"kind": "elastic", "modulus": e}, st.floats(1e-3, 1e3)),
    st.builds(lambda m, t: {"kind": "prony", "moduli": m, "times": t},
              st.lists(st.floats(0.0, 100.0), min_size=2, max_size=2),
              st.lists(st.floats(1e-3, 1e3), min_size=2, max_size=2, unique=True)))
kernel_tables = st.one_of(
    st.just({"kind": "half-plane"}),
    st.builds(lambda k, d: {"kind": k, "thickness": d, "poisson": 0.5},
              st.sampled_from(["confined-layer", "free-layer"]), st.floats(0.01, 100.0)))
loads = st.one_of(st.builds(lambda p: {"mean_pressure": p}, st.floats(-10.0, 10.0)),
                  st.builds(lambda d: {"penetration": d}, st.floats(-5.0, 5.0)))


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(profile=component_tables, rheology=rheology_tables, kernel=kernel_tables, load=loads,
       gamma=st.one_of(st.none(), st.floats(0.0, 1.0)), zeta=st.floats(0.0, 1e6),
       solver=st.sampled_from(["broyden", "newton", "nonlinear-cg", "bisection"]))
def test_round_trip_over_parameters(profile, rheology, kernel, load, gamma, zeta, solver):
    adhesion = {"kind": "none"} if gamma is None else {"kind": "energy-balance", "gamma": gamma}
    d = scene_dict(profile=profile, rheology=rheology, kernel=kernel, load=load,
                   adhesion=adhesion, solver={"kind": solver}, sliding={"zeta": zeta})
    scene = Scene.from_dict(d)
    assert Scene.from_toml(scene.to_toml()) == scene
    assert Scene.from_dict(scene.to_dict()) == scene
    assert scene.to_dict()["load"] == load


@pytest.mark.filterwarnings("ignore::viscocontact.errors.ModelValidityWarning")  # any μ_T here
@settings(max_examples=25, deadline=None)
@given(e0=st.floats(1e5, 1e10), lam=st.floats(1e-5, 1e-1), rms_ratio=st.floats(1e-4, 1e-1),
       dgamma=st.floats(1e-4, 1.0), p=st.floats(-1e5, 1e6), v=st.floats(0.0, 10.0),
       tau=st.floats(1e-6, 1e2), nu=st.floats(0.0, 0.5))
def test_physical_round_trip(e0, lam, rms_ratio, dgamma, p, v, tau, nu):
    phys = {"E0": e0, "wavelength": lam, "rms": rms_ratio * lam, "work_of_adhesion": dgamma,
            "mean_pressure": p, "velocity": v, "tau": tau, "poisson": nu}
    d = rough_dict(phys, load={}, sliding={})
    d["profile"]["scales"] = 8
    scene = Scene.from_dict(d)
    assert Scene.from_toml(scene.to_toml()) == scene
    assert scene.poisson == nu


# ---- the physical boundary ------------------------------------------------------------------
def test_thesis_gamma_tilde():
    scene = Scene.from_dict(rough_dict(THESIS))
    gamma = scene.adhesion.params["gamma"] if isinstance(scene.adhesion, ComponentSpec) \
        else scene.adhesion.gamma
    assert gamma == pytest.approx(2.387e-7, rel=1e-3)  # the thesis's figure (§4.6)
    assert gamma == pytest.approx(2.38854e-7, rel=1e-5)  # exact for λ0 = 6.28 mm
    q1000 = Scene.from_dict(rough_dict({**THESIS, "wavelength": 2 * math.pi * 1e-3}))
    assert dimensionless_groups(q1000)["gamma"] == pytest.approx(2.3873241e-7, rel=1e-7)
    assert dimensionless_groups(scene)["gamma"] == gamma


def test_thesis_tabor_parameter():
    groups = dimensionless_groups(Scene.from_dict(rough_dict(THESIS)))
    assert groups["tabor_radius"] == pytest.approx(0.1, rel=2e-3)  # eq. 4.55: R ≈ 0.1 m
    assert groups["tabor"] == pytest.approx(383.0, rel=1e-3)        # E* = E0/(1-ν²)
    assert groups["tabor_glassy"] == pytest.approx(383.0 / 10 ** (2 / 3), rel=1e-3)
    assert groups["adhesion_length"] == pytest.approx(7.5e-10)
    assert groups["warnings"] == []
    # the thesis's "μ_T ≈ 460" is reproduced with E0 in place of E*:
    with_e0 = tabor_parameter(radius=groups["tabor_radius"], work_of_adhesion=0.01,
                              reduced_modulus=1e7)
    assert with_e0 == pytest.approx(464.0, rel=1e-3)
    assert abs(with_e0 - 460) / 460 < 0.01 < abs(groups["tabor"] - 460) / 460
    exact = tabor_parameter(radius=0.1, work_of_adhesion=0.01, reduced_modulus=1e7 / 0.75)
    assert exact == pytest.approx((0.1 * 1e-4 / ((1e7 / 0.75) ** 2 * 1e-27)) ** (1 / 3))


def test_tabor_of_a_sinusoid_uses_crest_radius():
    phys = {"E0": 1e7, "wavelength": 2 * math.pi * 1e-3, "amplitude": 2e-5,
            "work_of_adhesion": 0.01}
    d = scene_dict(adhesion={"kind": "energy-balance"}, physical=phys)
    d["profile"] = {"kind": "sinusoid"}
    scene = Scene.from_dict(d)
    assert scene.profile.amplitude == pytest.approx(0.02)
    groups = dimensionless_groups(scene)
    assert groups["tabor_radius"] == pytest.approx(1 / (1e6 * 2e-5))
    assert groups["equilibrium_distance"] == 1e-9  # default Z0


def test_tabor_needs_a_physical_scale():
    groups = dimensionless_groups(Scene.from_dict(scene_dict()))
    assert groups["tabor"] is None and groups["tabor_glassy"] is None
    assert "physical.E0" in groups["tabor_note"]
    assert groups["physical"] is None
    assert groups["Gamma"] == pytest.approx(1e-5 / 0.05**2)
    assert groups["m2"] == pytest.approx(0.05**2 / 2)
    groups = dimensionless_groups(Scene.from_dict(scene_dict(adhesion={"kind": "none"})))
    assert groups["tabor"] is None and groups["gamma"] == 0.0
    assert "no adhesion" in groups["tabor_note"]


def test_tabor_from_dimensionless_gamma_and_warning():
    # hard solid: E0 = 100 GPa, γ̃ given dimensionless, Δγ derived from it
    phys = {"E0": 1e11, "wavelength": 1e-3, "rms": 1e-6}
    d = rough_dict(phys, adhesion={"kind": "energy-balance", "gamma": 1e-9})
    with pytest.warns(ModelValidityWarning, match="Tabor parameter"):
        groups = dimensionless_groups(Scene.from_dict(d))
    q0 = 2 * math.pi / 1e-3
    dgamma = 1e-9 * math.pi * 1e11 / (0.75 * q0)
    expected = tabor_parameter(radius=1 / (q0**2 * 1e-6), work_of_adhesion=dgamma,
                               reduced_modulus=1e11 / 0.75)
    assert groups["tabor"] == pytest.approx(expected, rel=1e-6)
    assert groups["tabor"] < 3
    assert any("< 3" in w for w in groups["warnings"])


LOW_TABOR = {"profile": {"kind": "sinusoid"}, "rheology": {"kind": "elastic"},
             "load": {"penetration": 0.5},
             "physical": {"E0": 2e11, "wavelength": 1e-4, "amplitude": 1e-6,
                          "work_of_adhesion": 0.01}}


def test_low_tabor_parameter_warns_when_the_scene_is_built():
    """A stiff solid with weak adhesion on a short wavelength: μ_T well below 3, where the
    infinitely short-range (JKR-like) adhesion of the edge energy balance does not hold. The
    warning names the user's line, not the library's."""
    with pytest.warns(ModelValidityWarning) as record:
        scene = Scene.from_dict(LOW_TABOR)
    assert len(record) == 1
    tabor = dimensionless_groups(scene)["tabor"]
    expected = tabor_parameter(radius=1 / ((2 * math.pi / 1e-4) ** 2 * 1e-6),
                               work_of_adhesion=0.01, reduced_modulus=2e11 / 0.75)
    assert tabor == pytest.approx(expected, rel=1e-12) and tabor < 3
    message = str(record[0].message)
    assert f"μ_T = {tabor:.3g} < 3" in message and "JKR" in message
    assert record[0].filename == __file__
    with pytest.warns(ModelValidityWarning) as record:       # every way a scene is built
        Scene.from_toml(scene.to_toml())
        attrs.evolve(scene, zeta=0.0)
    assert len(record) == 2 and {r.filename for r in record} == {__file__}


@pytest.mark.parametrize("data", [
    pytest.param(lambda: rough_dict(THESIS), id="thesis case, μ_T = 383"),
    pytest.param(lambda: scene_dict(), id="adhesive, dimensionless only"),
    pytest.param(lambda: {**LOW_TABOR, "adhesion": {"kind": "none"},
                          "physical": {k: v for k, v in LOW_TABOR["physical"].items()
                                       if k != "work_of_adhesion"}},
                 id="the stiff case without adhesion"),
])
def test_no_tabor_warning_where_it_does_not_apply(data):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        Scene.from_dict(data())


def test_physical_conversions():
    lam, amp, e0, nu = 5e-3, 3e-5, 2e6, 0.4
    q0 = 2 * math.pi / lam
    phys = {"E0": e0, "poisson": nu, "wavelength": lam, "amplitude": amp, "thickness": 1e-3,
            "work_of_adhesion": 0.05, "velocity": 0.02, "tau": 0.5, "mean_pressure": 1e4}
    d = {"profile": {"kind": "sinusoid"},
         "rheology": {"kind": "standard-linear-solid", "beta": 5.0},
         "kernel": {"kind": "confined-layer"}, "physical": phys}
    scene = Scene.from_dict(d)
    assert scene.profile.amplitude == pytest.approx(q0 * amp, rel=1e-15)
    assert scene.kernel == ConfinedLayer(thickness=q0 * 1e-3, poisson=nu)
    assert scene.poisson == nu
    assert scene.zeta == pytest.approx(q0 * 0.02 * 0.5, rel=1e-15)
    assert kind_of("adhesion", scene.adhesion) == "energy-balance"  # implied by Δγ
    assert kind_of("solver", scene.solver) == "broyden"
    assert dimensionless_groups(scene)["gamma"] == pytest.approx(
        (1 - nu**2) * q0 * 0.05 / (math.pi * e0), rel=1e-15)
    assert scene.load.mean_pressure == pytest.approx(2 * (1 - nu**2) * 1e4 / (e0 * q0 * amp),
                                                     rel=1e-12)
    by_penetration = {k: v for k, v in phys.items() if k != "mean_pressure"} | {"penetration": 1e-5}
    pen = Scene.from_dict({**d, "physical": by_penetration})
    assert pen.load.controlled == "penetration"
    assert pen.load.penetration == pytest.approx(1e-5 / amp, rel=1e-12)
    assert Scene.from_toml(pen.to_toml()) == pen


def test_physical_agreeing_within_tolerance_is_accepted():
    q0 = 2 * math.pi / 6.28e-3
    d = rough_dict(THESIS)
    d["profile"]["rms"] = q0 * 1e-5 * (1 + 1e-11)
    assert Scene.from_dict(d).profile.rms == d["profile"]["rms"]


def test_elastic_scene_defaults():
    d = scene_dict(rheology={"kind": "elastic"}, adhesion=None, solver=None, kernel=None,
                   sliding=None)
    scene = Scene.from_dict(d)
    assert scene.zeta == 0.0
    assert scene.kernel == HalfPlane()
    assert kind_of("adhesion", scene.adhesion) == "none" and not scene.adhesive
    assert kind_of("solver", scene.solver) == "bisection"
    assert Scene.from_dict(scene.to_dict()) == scene


def test_python_construction_defaults_and_tensile_load():
    scene = Scene(profile=Sinusoid(amplitude=0.1), rheology=Elastic(),
                  load=Load(mean_pressure=-0.2), zeta=0)
    assert scene.zeta == 0.0 and scene.load.controlled == "mean_pressure"
    assert scene.load.value == -0.2
    assert kind_of("solver", scene.solver) == "bisection"
    layer = Scene(profile=Sinusoid(amplitude=0.1), rheology=Elastic(), load=Load(penetration=0.5),
                  zeta=0.0, kernel=ConfinedLayer(thickness=2.0, poisson=0.3))
    assert layer.poisson == 0.3
    assert Scene.from_toml(layer.to_toml()) == layer
    assert attrs.evolve(scene, zeta=1.0).zeta == 1.0


def test_component_spec_resolves_and_lazy_fallback(monkeypatch):
    spec = ComponentSpec(kind="sinusoid", params={"amplitude": 0.1})
    assert spec.resolve("profile") == Sinusoid(amplitude=0.1)
    missing = _registry.Registry(
        "viscocontact.solvers", lambda: object,
        entry_points=lambda: [EntryPoint(name="later", value="no_such_solver_module:Later",
                                         group="viscocontact.solvers")])
    monkeypatch.setitem(_registry.REGISTRIES, "solvers", missing)
    spec = build_component("solver", {"kind": "later", "tol": 1e-9}, lazy=True)
    assert spec == ComponentSpec(kind="later", params={"tol": 1e-9})
    with pytest.raises(PluginError) as info:
        build_component("solver", {"kind": "later"})
    assert isinstance(info.value.__cause__, ImportError)
    with pytest.raises(PluginError):
        spec.resolve("solver")


def test_toml_writer():
    data = {"a": 1, "t": {"x": 0.1, "s": 'q"uote\\', "b": True, "l": [1.0, 2.5e-300],
                          "n": None, "inf": math.inf, "sub": {"k": -3}}, "odd key": {"v": 1e22}}
    back = tomllib.loads(dumps(data))
    assert back == {"a": 1, "t": {"x": 0.1, "s": 'q"uote\\', "b": True, "l": [1.0, 2.5e-300],
                                  "inf": math.inf, "sub": {"k": -3}}, "odd key": {"v": 1e22}}
    with pytest.raises(TypeError):
        dumps({"t": {"x": object()}})


def test_toml_writer_escapes_every_control_character():
    """TOML forbids U+0000-U+001F and U+007F raw in a basic string (keys too): every one is
    written as an escape and read back as itself."""
    text = "".join(map(chr, [*range(0x20), 0x7F])) + "é\u2028"
    written = dumps({"t": {"s": text, text: 1}})
    assert all(ord(c) >= 0x20 and c != "\x7f" for c in written.replace("\n", ""))
    assert tomllib.loads(written) == {"t": {"s": text, text: 1}}


# ---- bad input: every case names the key ----------------------------------------------------
BAD = [
    # (label, modifier, expected field, text that must appear in the message)
    ("unknown section", lambda d: d.update(extra={"x": 1}), "extra", "'profile'"),
    ("unknown top-level key", lambda d: d.update(title="x"), "title", "poisson"),
    ("section not a table", lambda d: d.update(profile=3), "profile", "sections"),
    ("missing profile", lambda d: d.pop("profile"), "profile", "kind"),
    ("missing rheology", lambda d: d.pop("rheology"), "rheology", "kind"),
    ("missing kind", lambda d: d["profile"].pop("kind"), "profile.kind", "sinusoid"),
    ("unknown kind", lambda d: d["rheology"].update(kind="standard-linear-sollid"),
     "rheology.kind", "did you mean 'standard-linear-solid'"),
    ("unknown kernel", lambda d: d["kernel"].update(kind="quarter-plane"), "kernel.kind",
     "half-plane"),
    ("unknown solver", lambda d: d["solver"].update(kind="brodyen"), "solver.kind", "broyden"),
    ("unknown adhesion", lambda d: d["adhesion"].update(kind="glue"), "adhesion.kind",
     "energy-balance"),
    ("unknown key", lambda d: d["rheology"].update(betta=3.0), "rheology.betta", "'beta'"),
    ("bad value", lambda d: d["rheology"].update(beta=0.5), "rheology.beta", "> 1"),
    ("bad type", lambda d: d["profile"].update(amplitude="big"), "profile.amplitude", ""),
    ("missing required", lambda d: d["profile"].pop("amplitude"), "profile.amplitude",
     "requires"),
    ("bad layer", lambda d: d.update(kernel={"kind": "free-layer", "thickness": -1.0}),
     "kernel.thickness", ""),
    ("both loads", lambda d: d["load"].update(penetration=0.5), "load", "exactly one"),
    ("no load", lambda d: d.pop("load"), "load", "exactly one"),
    ("empty load", lambda d: d.update(load={}), "load", "exactly one"),
    ("unknown load key", lambda d: d["load"].update(force=1.0), "load.force", "mean_pressure"),
    ("nan load", lambda d: d["load"].update(mean_pressure=math.nan), "load.mean_pressure",
     "finite"),
    ("inf penetration", lambda d: d.update(load={"penetration": math.inf}), "load.penetration",
     "finite"),
    ("string load", lambda d: d["load"].update(mean_pressure="0.3"), "load.mean_pressure", ""),
    ("negative zeta", lambda d: d["sliding"].update(zeta=-1.0), "sliding.zeta", "[0.0, inf]"),
    ("inf zeta", lambda d: d["sliding"].update(zeta=math.inf), "sliding.zeta", "finite"),
    ("bool zeta", lambda d: d["sliding"].update(zeta=True), "sliding.zeta", "finite"),
    ("missing zeta", lambda d: d.pop("sliding"), "sliding.zeta", "required"),
    ("unknown sliding key", lambda d: d["sliding"].update(speed=1.0), "sliding.speed", "zeta"),
    ("poisson too big", lambda d: d.update(poisson=0.6), "poisson", "(-1.0, 0.5]"),
    ("poisson -1", lambda d: d.update(poisson=-1.0), "poisson", "(-1.0, 0.5]"),
    ("poisson vs kernel",
     lambda d: d.update(poisson=0.3, kernel={"kind": "confined-layer", "thickness": 1.0,
                                             "poisson": 0.5}), "kernel.poisson", "poisson"),
    ("unknown physical key", lambda d: d.update(physical={"youngs": 1e7}), "physical.youngs",
     "E0"),
    ("negative E0", lambda d: d.update(physical={"E0": -1.0}), "physical.E0", "(0.0, inf]"),
    ("nan wavelength", lambda d: d.update(physical={"wavelength": math.nan}),
     "physical.wavelength", "finite"),
    ("physical poisson", lambda d: d.update(physical={"poisson": 0.7}), "physical.poisson", ""),
    ("physical poisson disagrees", lambda d: d.update(poisson=0.5, physical={"poisson": 0.3}),
     "physical.poisson", "poisson = 0.5"),
    ("gamma needs E0", lambda d: d.update(physical={"work_of_adhesion": 0.01, "wavelength": 1e-3}),
     "physical.E0", "physical.work_of_adhesion"),
    ("gamma needs wavelength", lambda d: d.update(physical={"work_of_adhesion": 0.01, "E0": 1e7}),
     "physical.wavelength", "adhesion.gamma"),
    ("velocity needs tau", lambda d: (d.pop("sliding"),
                                      d.update(physical={"velocity": 1.0, "wavelength": 1e-3})),
     "physical.tau", "sliding.zeta"),
    ("pressure needs E0", lambda d: (d.pop("load"), d.update(physical={"mean_pressure": 1e5})),
     "physical.E0", "load.mean_pressure"),
    ("rms for a sinusoid", lambda d: d.update(physical={"rms": 1e-5, "wavelength": 1e-3}),
     "physical.rms", "'amplitude'"),
    ("thickness for a half-plane",
     lambda d: d.update(physical={"thickness": 1e-3, "wavelength": 1e-3}), "physical.thickness",
     "half-plane"),
    ("adhesion none with Δγ",
     lambda d: d.update(adhesion={"kind": "none"},
                        physical={"work_of_adhesion": 0.01, "E0": 1e7, "wavelength": 1e-3}),
     "physical.work_of_adhesion", "energy-balance"),
    ("gamma disagrees", lambda d: d.update(physical={"work_of_adhesion": 0.01, "E0": 1e7,
                                                     "wavelength": 6.28e-3}),
     "adhesion.gamma", "physical.work_of_adhesion"),
    ("zeta disagrees", lambda d: d.update(physical={"velocity": 1.0, "tau": 1.0,
                                                    "wavelength": 1e-3}),
     "sliding.zeta", "physical.velocity"),
    ("load disagrees", lambda d: d.update(physical={"mean_pressure": 2e5, "E0": 1e7}),
     "load.mean_pressure", "physical.mean_pressure"),
    ("both loads via physical",
     lambda d: d.update(load={"penetration": 0.5}, physical={"mean_pressure": 1e5, "E0": 1e7}),
     "load", "exactly one"),
    ("wavelength vs measured length",
     lambda d: d.update(profile={"kind": "measured", "amplitudes": [0.1], "phases": [0.0],
                                 "length": 1e-3}, physical={"wavelength": 2e-3}),
     "physical.wavelength", "length"),
    ("amplitude disagrees", lambda d: d.update(physical={"amplitude": 1e-5, "wavelength": 1e-3}),
     "profile.amplitude", "physical.amplitude"),
]


@pytest.mark.parametrize("label,modify,field,text", BAD, ids=[b[0] for b in BAD])
def test_bad_input_names_the_key(label, modify, field, text):
    d = scene_dict()
    modify(d)
    with pytest.raises(ValidationError) as info:
        Scene.from_dict(d)
    assert info.value.field == field, str(info.value)
    assert text in str(info.value)


def test_rms_disagreement_names_both():
    d = rough_dict(THESIS)
    d["profile"]["rms"] = 0.02
    with pytest.raises(ValidationError) as info:
        Scene.from_dict(d)
    assert info.value.field == "profile.rms"
    assert "physical.rms" in str(info.value) and "physical.wavelength" not in info.value.field


def test_unknown_kind_lists_registered_names():
    d = scene_dict()
    d["profile"]["kind"] = "fractal"
    with pytest.raises(ValidationError) as info:
        Scene.from_dict(d)
    for name in ("sinusoid", "self-affine"):
        assert name in str(info.value)


def test_unknown_key_lists_fields():
    d = scene_dict()
    d["profile"] = {"kind": "self-affine", "hurst": 0.8, "scales": 4, "rms": 0.1, "sead": 1}
    with pytest.raises(ValidationError) as info:
        Scene.from_dict(d)
    assert info.value.field == "profile.sead"
    for name in ("hurst", "scales", "rms", "seed", "rolloff"):
        assert name in str(info.value)


def test_constructor_checks():
    with pytest.raises(ValidationError, match="exactly one"):
        Load()
    with pytest.raises(ValidationError, match="exactly one"):
        Load(mean_pressure=0.1, penetration=0.2)
    with pytest.raises(ValidationError) as info:
        Scene(profile=Elastic(), rheology=Elastic(), load=Load(penetration=1.0), zeta=0.0)
    assert info.value.field == "Scene.profile"
    with pytest.raises(ValidationError) as info:  # physical table must agree with the values
        Scene(profile=Sinusoid(amplitude=0.1), rheology=Elastic(), load=Load(penetration=1.0),
              zeta=0.0, physical={"velocity": 1.0, "tau": 1.0, "wavelength": 1.0})
    assert info.value.field == "sliding.zeta"
    with pytest.raises(ValidationError) as info:
        Scene(profile=Sinusoid(amplitude=0.1), rheology=Elastic(), load=Load(penetration=1.0),
              zeta=0.0, physical={"rms": 1e-3, "wavelength": 1.0})
    assert info.value.field == "physical.rms"
    with pytest.raises(ValidationError) as info:
        Scene(profile=Sinusoid(amplitude=0.1), rheology=Elastic(), load=Load(penetration=1.0),
              zeta=0.0, physical={"E0": 0.0})
    assert info.value.field == "physical.E0"


def test_from_toml_text_path_and_errors(tmp_path):
    text = (EXAMPLES / "sinusoid.toml").read_text()
    path = tmp_path / "s.toml"
    path.write_text(text)
    assert Scene.from_toml(text) == Scene.from_toml(path) == Scene.from_toml(str(path))
    with pytest.raises(FileNotFoundError):
        Scene.from_toml(str(tmp_path / "missing.toml"))
    with pytest.raises(tomllib.TOMLDecodeError):
        Scene.from_toml("[profile\nkind = 1\n")


def test_nested_option_tables_round_trip(tmp_path, monkeypatch):
    """A component option that is itself an attrs class is written as a sub-table and rebuilt."""
    (tmp_path / "vc_fake_solver_mod.py").write_text(
        "import attrs\n"
        "class Base:\n    pass\n"
        "@attrs.frozen(kw_only=True)\nclass Options:\n    damping: float = 1.0\n"
        "@attrs.frozen(kw_only=True)\nclass Fake(Base):\n"
        "    options: Options = attrs.field(factory=Options)\n    memory: int = 5\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    import importlib

    fake = _registry.Registry(
        "viscocontact.solvers", lambda: importlib.import_module("vc_fake_solver_mod").Base,
        entry_points=lambda: [EntryPoint(name="fake", value="vc_fake_solver_mod:Fake",
                                         group="viscocontact.solvers")])
    monkeypatch.setitem(_registry.REGISTRIES, "solvers", fake)
    table = {"kind": "fake", "options": {"damping": 0.5}, "memory": 3}
    solver = build_component("solver", table)
    assert solver.options.damping == 0.5 and solver.memory == 3
    text = dumps({"solver": {"kind": "fake", "options": {"damping": 0.5}, "memory": 3}})
    assert "[solver.options]" in text
    assert build_component("solver", tomllib.loads(text)["solver"]) == solver
    with pytest.raises(ValidationError) as info:
        build_component("solver", {"kind": "fake", "options": {"dampng": 0.5}})
    assert info.value.field == "solver.options.dampng"
