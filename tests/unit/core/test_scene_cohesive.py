"""The Maugis–Dugdale keys of a scene: ``physical.cohesive_range`` and ``cohesive_strength``."""
from __future__ import annotations

import math

import pytest

from viscocontact.adhesion.maugis_dugdale import MaugisDugdale
from viscocontact.errors import ValidationError
from viscocontact.scene import Scene

E0, WAVELENGTH, DGAMMA, NU = 1e7, 1e-3, 0.01, 0.5
Q0 = 2 * math.pi / WAVELENGTH
GAMMA = (1 - NU**2) * Q0 * DGAMMA / (math.pi * E0)      # 1.5e-6


def scene_dict(adhesion=None, **physical):
    d = {"profile": {"kind": "sinusoid", "amplitude": 0.1},
         "rheology": {"kind": "standard-linear-solid", "beta": 10.0},
         "load": {"mean_pressure": 0.05}, "sliding": {"zeta": 0.3},
         "physical": {"E0": E0, "wavelength": WAVELENGTH, "work_of_adhesion": DGAMMA,
                      **physical}}
    if adhesion is not None:
        d["adhesion"] = adhesion
    return d


def test_cohesive_range_gives_q0_h0():
    scene = Scene.from_dict(scene_dict({"kind": "maugis-dugdale"}, cohesive_range=1e-6))
    assert isinstance(scene.adhesion, MaugisDugdale)
    assert scene.adhesion.gamma == pytest.approx(GAMMA, rel=1e-12)
    assert scene.adhesion.range == pytest.approx(Q0 * 1e-6, rel=1e-12)


def test_cohesive_strength_gives_the_range_of_dgamma_over_sigma0():
    scene = Scene.from_dict(scene_dict({"kind": "maugis-dugdale"}, cohesive_strength=1e4))
    assert scene.adhesion.range == pytest.approx(Q0 * DGAMMA / 1e4, rel=1e-12)
    # σ0/E* = πγ̃/h̃0 (docs/cohesive.md)
    estar = E0 / (1 - NU**2)
    assert math.pi * scene.adhesion.gamma / scene.adhesion.range == pytest.approx(1e4 / estar)


def test_cohesive_strength_with_a_dimensionless_gamma():
    d = scene_dict({"kind": "maugis-dugdale", "gamma": 1e-4}, cohesive_strength=2e5)
    del d["physical"]["work_of_adhesion"]
    scene = Scene.from_dict(d)
    assert scene.adhesion.range == pytest.approx(math.pi * 1e-4 * E0 / (1 - NU**2) / 2e5)


def test_a_cohesive_key_defaults_the_kind_to_maugis_dugdale():
    scene = Scene.from_dict(scene_dict(cohesive_range=1e-6))
    assert isinstance(scene.adhesion, MaugisDugdale)


@pytest.mark.parametrize("key,value", [("cohesive_range", 1e-6), ("cohesive_strength", 1e4)])
def test_round_trip_keeps_the_range_in_the_physical_table(key, value):
    scene = Scene.from_dict(scene_dict({"kind": "maugis-dugdale"}, **{key: value}))
    text = scene.to_toml()
    assert "range =" not in text.split("[adhesion]")[1].split("[")[0]
    assert Scene.from_toml(text) == scene


def test_a_scene_built_directly_must_agree_with_the_physical_table():
    scene = Scene.from_dict(scene_dict({"kind": "maugis-dugdale"}, cohesive_range=1e-6))
    with pytest.raises(ValidationError) as info:
        Scene(profile=scene.profile, rheology=scene.rheology,
              adhesion=MaugisDugdale(gamma=GAMMA, range=0.01), load=scene.load, zeta=0.3,
              physical=scene.physical)
    assert info.value.field == "adhesion.range"
    assert "physical.cohesive_range" in str(info.value)


def _drop(key):
    def modify(d):
        del d["physical"][key]
    return modify


BAD = [
    # (label, adhesion table, physical additions, modify, field, text in the message)
    ("both keys", {"kind": "maugis-dugdale"}, {"cohesive_range": 1e-6, "cohesive_strength": 1e4},
     None, "physical.cohesive_strength", "physical.cohesive_range"),
    ("range and explicit adhesion.range", {"kind": "maugis-dugdale", "range": 0.01},
     {"cohesive_range": 1e-6}, None, "adhesion.range", "physical.cohesive_range"),
    ("strength and explicit adhesion.range", {"kind": "maugis-dugdale", "range": 0.01},
     {"cohesive_strength": 1e4}, None, "adhesion.range", "physical.cohesive_strength"),
    ("range with energy-balance", {"kind": "energy-balance"}, {"cohesive_range": 1e-6}, None,
     "physical.cohesive_range", "'maugis-dugdale'"),
    ("strength with energy-balance", {"kind": "energy-balance"}, {"cohesive_strength": 1e4},
     None, "physical.cohesive_strength", "'maugis-dugdale'"),
    ("range with none", {"kind": "none"}, {"cohesive_range": 1e-6}, _drop("work_of_adhesion"),
     "physical.cohesive_range", "'maugis-dugdale'"),
    ("negative range", {"kind": "maugis-dugdale"}, {"cohesive_range": -1e-6}, None,
     "physical.cohesive_range", "(0.0, inf]"),
    ("zero strength", {"kind": "maugis-dugdale"}, {"cohesive_strength": 0.0}, None,
     "physical.cohesive_strength", "(0.0, inf]"),
    ("nan range", {"kind": "maugis-dugdale"}, {"cohesive_range": math.nan}, None,
     "physical.cohesive_range", "finite"),
    ("string strength", {"kind": "maugis-dugdale"}, {"cohesive_strength": "1e4"}, None,
     "physical.cohesive_strength", "finite"),
    ("range beyond q0·h0 = 10", {"kind": "maugis-dugdale"}, {"cohesive_range": 1e-2}, None,
     "physical.cohesive_range", f"(0, {10 / Q0:.6g}] m"),
    ("strength too low (range beyond 10)", {"kind": "maugis-dugdale"},
     {"cohesive_strength": 1.0}, None, "physical.cohesive_strength", "σ0 >= 6.28319 Pa"),
    ("range needs wavelength", {"kind": "maugis-dugdale", "gamma": 1e-4}, {"cohesive_range": 1e-6},
     lambda d: (d["physical"].pop("wavelength"), d["physical"].pop("work_of_adhesion")),
     "physical.wavelength", "physical.cohesive_range"),
    ("strength needs E0", {"kind": "maugis-dugdale", "gamma": 1e-4}, {"cohesive_strength": 1e4},
     lambda d: (d["physical"].pop("E0"), d["physical"].pop("work_of_adhesion")),
     "physical.E0", "physical.cohesive_strength"),
    ("strength needs a work of adhesion", {"kind": "maugis-dugdale", "gamma": 0.0},
     {"cohesive_strength": 1e4}, _drop("work_of_adhesion"), "physical.cohesive_strength",
     "work of adhesion > 0"),
    ("strength with zero work of adhesion", {"kind": "maugis-dugdale"},
     {"cohesive_strength": 1e4, "work_of_adhesion": 0.0}, None, "physical.cohesive_strength",
     "work of adhesion > 0"),
]


@pytest.mark.parametrize("label,adhesion,physical,modify,field,text", BAD,
                         ids=[b[0] for b in BAD])
def test_bad_cohesive_input_names_the_key(label, adhesion, physical, modify, field, text):
    d = scene_dict(adhesion, **physical)
    if modify is not None:
        modify(d)
    with pytest.raises(ValidationError) as info:
        Scene.from_dict(d)
    assert info.value.field == field, str(info.value)
    assert text in str(info.value), str(info.value)


# ---- describe ----------------------------------------------------------------------------------
def _dimensionless(gamma, h0, amplitude=0.1, profile=None):
    return {"profile": profile or {"kind": "sinusoid", "amplitude": amplitude},
            "rheology": {"kind": "standard-linear-solid", "beta": 10.0},
            "adhesion": {"kind": "maugis-dugdale", "gamma": gamma, "range": h0},
            "load": {"mean_pressure": 0.05}, "sliding": {"zeta": 0.3}}


@pytest.mark.parametrize("lam,regime", [(10.0, "JKR-like"), (1.0, "transition"),
                                        (0.05, "DMT-like")])
def test_describe_reports_the_reference_transition_parameters(lam, regime):
    from viscocontact.groups import dimensionless_groups
    from viscocontact.reference import MaugisDugdaleWavy

    ref = MaugisDugdaleWavy.from_transition(Gamma=0.05, transition=lam)   # relaxed λ
    amp = 0.1
    groups = dimensionless_groups(Scene.from_dict(_dimensionless(0.05 * amp**2, ref.h0 * amp)))
    assert groups["transition"] == pytest.approx(lam, rel=1e-12)
    glassy = MaugisDugdaleWavy(Gamma=0.05, h0=ref.h0, modulus_ratio=10.0)
    assert groups["transition_glassy"] == pytest.approx(glassy.transition_parameter, rel=1e-12)
    assert groups["tabor"] == pytest.approx(ref.tabor, rel=1e-12)
    assert groups["tabor_glassy"] == pytest.approx(glassy.tabor, rel=1e-12)
    assert groups["cohesive_stress"] == pytest.approx(ref.cohesive_stress, rel=1e-12)
    assert groups["range_ratio"] == pytest.approx(ref.h0, rel=1e-12)
    assert groups["strength_ratio"] == pytest.approx(math.pi * 0.05 * amp / ref.h0, rel=1e-12)
    assert groups["quasi_static_zone"] == pytest.approx((ref.h0 * amp) ** 2 / (4 * 5e-4))
    assert groups["regime"].startswith({"JKR-like": "JKR-like", "transition": "Maugis transition",
                                        "DMT-like": "DMT-like"}[regime])
    assert groups["warnings"] == [] and groups["cohesive_range"] is None
    if lam == 10.0:      # λ∞ = λ/10^(2/3) = 2.15: the glassy limit is in the transition
        assert "glassy (high ζ): Maugis transition" in groups["regime"]


def test_describe_in_physical_units():
    from viscocontact.groups import dimensionless_groups

    groups = dimensionless_groups(Scene.from_dict(scene_dict({"kind": "maugis-dugdale"},
                                                             cohesive_strength=1e4)))
    assert groups["cohesive_strength"] == pytest.approx(1e4, rel=1e-12)
    assert groups["cohesive_range"] == pytest.approx(DGAMMA / 1e4, rel=1e-12)
    assert groups["adhesion_length"] == pytest.approx(DGAMMA * (1 - NU**2) / E0, rel=1e-12)
    assert groups["tabor_radius"] == pytest.approx(1 / (Q0**2 * 0.1 / Q0), rel=1e-12)
    assert groups["equilibrium_distance"] == pytest.approx(16 / (9 * math.sqrt(3)) * 1e-6)
    assert groups["quasi_static_zone_length"] == pytest.approx(
        math.pi * E0 / (1 - NU**2) * DGAMMA / (4 * 1e4**2), rel=1e-12)   # πE*Δγ/(4σ0²)


def test_describe_names_the_radius_of_a_rough_profile():
    from viscocontact.groups import dimensionless_groups

    d = _dimensionless(1e-4, 1e-2, profile={"kind": "self-affine", "hurst": 0.8, "scales": 8,
                                                 "rms": 0.05})
    groups = dimensionless_groups(Scene.from_dict(d))
    assert "eq. 4.55" in groups["tabor_note"]
    lam = 2 * math.pi ** (1 / 3) * 1e-4 ** (2 / 3) / (1e-2 * groups["rms"] ** (1 / 3))
    assert groups["transition"] == pytest.approx(lam, rel=1e-12)


def test_describe_cli_text(capsys, tmp_path):
    from viscocontact.cli import main
    from viscocontact.scene import Scene as _Scene

    path = tmp_path / "md.toml"
    path.write_text(_Scene.from_dict(scene_dict({"kind": "maugis-dugdale"},
                                                cohesive_range=1e-6)).to_toml())
    assert main(["describe", str(path)]) == 0
    out, err = capsys.readouterr()
    assert err == ""
    assert "regime" in out and "Maugis transition" in out and "glassy (high ζ): DMT-like" in out
    assert "cohesive_strength         10000 Pa" in out and "cohesive_range            1e-06 m" in out
