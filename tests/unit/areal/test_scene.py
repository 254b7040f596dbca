"""Areal scene files: the ``[surface]`` table, the shared tables, round trips and errors that
name ``section.key``."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from viscocontact.areal.method import ArealSpectral
from viscocontact.areal.problem import ArealProblem
from viscocontact.areal.scene import ArealScene
from viscocontact.areal.surfaces import SelfAffineSurface
from viscocontact.errors import ValidationError
from viscocontact.rheology import StandardLinearSolid
from viscocontact.read import read_scene
from viscocontact.scene import Scene

pytestmark = pytest.mark.usefixtures("surface_registry")

SCENES = Path(__file__).resolve().parents[3] / "examples" / "scenes"

SMALL = """
[surface]
kind = "self-affine"
hurst = 0.8
scales = 12
rms = 0.01
seed = 3
grid = 32

[rheology]
kind = "standard-linear-solid"
beta = 10.0

[load]
mean_pressure = 0.3

[sliding]
zeta = 1.0
"""


def table(**changes):
    import tomllib

    data = tomllib.loads(SMALL)
    for key, value in changes.items():
        section, _, name = key.partition("__")
        if value is None:
            data.get(section, {}).pop(name, None) if name else data.pop(section, None)
        elif name:
            data.setdefault(section, {})[name] = value
        else:
            data[section] = value
    return data


@pytest.mark.parametrize("name", ["areal_self_affine", "areal_maugis_dugdale"])
def test_the_example_scenes_read_and_write_back(name):
    scene = read_scene(SCENES / f"{name}.toml")
    assert isinstance(scene, ArealScene) and scene.grid == (256, 256)
    assert ArealScene.from_toml(scene.to_toml()) == scene
    assert read_scene(scene.to_toml()) == scene


def test_read_scene_tells_profiles_from_surfaces():
    assert isinstance(read_scene(SCENES / "sinusoid.toml"), Scene)
    with pytest.raises(ValidationError, match=r"^surface .*ArealScene"):
        Scene.from_dict(table())


def test_the_scene_is_the_problem_it_names():
    """The scene's solve is the method's solve of the problem built by hand: the same numbers."""
    scene = ArealScene.from_toml(SMALL)
    by_hand = ArealSpectral(points=32).solve(ArealProblem(
        surface=SelfAffineSurface(hurst=0.8, scales=12, rms=0.01, seed=3),
        rheology=StandardLinearSolid(beta=10.0), zeta=1.0, mean_pressure=0.3))
    result = scene.solve()
    assert result.converged
    assert result.to_dict() | {"extras": None} == by_hand.to_dict() | {"extras": None}
    assert result.extras["area_fraction"] == by_hand.extras["area_fraction"]


@pytest.mark.parametrize("grid, points", [(32, (32, 32)), ([64, 32], (64, 32))])
def test_the_grid_is_a_side_or_a_pair(grid, points):
    scene = ArealScene.from_dict(table(surface__grid=grid))
    assert scene.method.points == points and scene.grid == points
    assert ArealScene.from_toml(scene.to_toml()) == scene


def test_without_a_grid_the_method_chooses():
    scene = ArealScene.from_dict(table(surface__grid=None))
    assert scene.method.points is None and scene.grid == (256, 256)
    assert "grid" not in scene.to_dict()["surface"]


def test_sliding_direction_and_method_options_round_trip():
    scene = ArealScene.from_dict(table(sliding__direction=0.5,
                                       method={"kind": "areal-spectral", "tolerance": 0.01}))
    assert scene.direction == 0.5 and scene.problem().direction == 0.5
    assert scene.method.tolerance == 0.01
    assert scene.to_dict()["method"] == {"kind": "areal-spectral", "tolerance": 0.01}
    assert ArealScene.from_toml(scene.to_toml()) == scene


@pytest.mark.parametrize("changes, field, allowed", [
    ({"surface__kind": "self-afine"}, "surface.kind", "did you mean 'self-affine'"),
    ({"surface__hurts": 0.8}, "surface.hurts", "did you mean 'hurst'"),
    ({"surface__hurst": 1.5}, "surface.hurst", ""),
    ({"surface__grid": 33}, "surface.grid", "even"),
    ({"surface": None}, "surface", "a [surface] table"),
    ({"rheology": None}, "rheology", "a [rheology] table"),
    ({"profile": {"kind": "sinusoid", "amplitude": 0.1}}, "profile", "no [profile]"),
    ({"solver": {"kind": "newton"}}, "solver", "no [solver]"),
    ({"method": {"kind": "spectral"}}, "method.kind", "areal-spectral"),
    ({"method": {"kind": "areal-spectral", "points": 64}}, "method.points", "surface.grid"),
    ({"method": {"kind": "areal-spectral", "tolerance": 1.0}}, "method.tolerance", ""),
    ({"adhesion": {"kind": "energy-balance", "gamma": 1e-4}}, "adhesion.kind",
     "maugis-dugdale"),
    ({"adhesion": {"kind": "maugis-dugdale", "gamma": 1e-6, "range": 20.0}}, "adhesion.range",
     ""),
    ({"sliding__direction": 4.0}, "sliding.direction", ""),
    ({"sliding__speed": 1.0}, "sliding.speed", "'zeta', 'direction'"),
    ({"sliding__zeta": None}, "sliding.zeta", "required for a viscoelastic rheology"),
    ({"load": None}, "load", "exactly one of"),
    ({"load__penetration": 0.5}, "load", "exactly one of"),
    ({"kernel": {"kind": "half-plane", "poisson": 0.3}}, "kernel", ""),
    ({"shape": {"x": 1}}, "shape", "one of the sections"),
])
def test_errors_name_the_key(changes, field, allowed):
    with pytest.raises(ValidationError) as info:
        ArealScene.from_dict(table(**changes))
    assert info.value.field.startswith(field), info.value
    assert allowed in str(info.value)


def test_physical_values_fill_the_groups():
    """``physical.rms`` fills ``surface.rms`` (q0·r_rms) and ``physical.mean_pressure`` the load
    ``p̃∞ = 2(1-ν²) p∞/(E0 Λ̃)`` with Λ̃ the surface's highest point on the scene's grid."""
    data = table(surface__rms=None, load=None, sliding__zeta=None)
    data["physical"] = {"E0": 1e7, "poisson": 0.5, "wavelength": 6.28e-3, "rms": 1e-5,
                        "mean_pressure": 1e5, "velocity": 1e-3, "tau": 1.0}
    scene = ArealScene.from_dict(data)
    q0 = 2 * math.pi / 6.28e-3
    assert scene.surface.rms == pytest.approx(q0 * 1e-5, rel=1e-12)
    heights = SelfAffineSurface(hurst=0.8, scales=12, rms=q0 * 1e-5, seed=3).heights(32, 32)
    amplitude = float(np.max(heights - heights.mean()))
    assert scene.load.mean_pressure == pytest.approx(2 * 0.75 * 1e5 / (1e7 * amplitude),
                                                     rel=1e-12)
    assert scene.zeta == pytest.approx(q0 * 1e-3, rel=1e-12)
    assert ArealScene.from_toml(scene.to_toml()) == scene
    with pytest.raises(ValidationError, match="surface.rms"):
        ArealScene.from_dict({**data, "surface": {**data["surface"], "rms": 0.02}})


def test_the_plan_says_grid_memory_time_and_the_cohesive_zone():
    adhesive = table(adhesion={"kind": "maugis-dugdale", "gamma": 2e-6, "range": 0.006})
    plan = {s.stage: s for s in ArealScene.from_dict(adhesive).plan().steps}
    assert "64×64" not in plan["grid"].choice and "16×16 → 32×32" in plan["grid"].choice
    assert plan["memory check"].choice == "fits" and "time" in plan
    assert "cells per quasi-static zone" in plan["adhesion"].choice
    # 4.5/(2π/32) = 22.9 cells per zone: fewer than 32, said
    assert "UNDER-RESOLVED" in plan["adhesion"].reason and "45 cells a side" in \
        plan["adhesion"].reason
    refused = table(method={"kind": "areal-spectral", "max_memory": 1e6}, surface__grid=256)
    plan = {s.stage: s for s in ArealScene.from_dict(refused).plan().steps}
    assert plan["memory check"].choice.startswith("REFUSED: 29 MB")
    # 64² plans 4096·(200 + 2·60·8/4) B = 1.8 MB, 32² 0.45 MB
    assert "32×32 cells fit" in plan["memory check"].reason
    with pytest.raises(ValidationError, match="max_memory"):
        ArealScene.from_dict(refused).solve()


def test_vc_solve_takes_an_areal_scene():
    import viscocontact as vc

    result = vc.solve(SMALL)
    assert result.method == "areal-spectral"
    assert result.extras["area_fraction"] == ArealScene.from_toml(SMALL).solve().extras[
        "area_fraction"]
    with pytest.raises(ValidationError, match="discretization"):
        vc.solve(SMALL, discretization=None)
