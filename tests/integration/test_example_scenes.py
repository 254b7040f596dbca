"""The example scenes of ``examples/scenes/`` read, and the Maugis–Dugdale one solves to a state
between its two limits (the adhesionless contact and the JKR-like energy balance with the same
work of adhesion)."""
from pathlib import Path

import pytest

import viscocontact as vc

SCENES = Path(__file__).resolve().parents[2] / "examples" / "scenes"


@pytest.mark.parametrize("path", sorted(SCENES.glob("*.toml")), ids=lambda p: p.name)
def test_every_example_scene_reads_and_writes_back(path, surface_registry):
    scene = vc.read_scene(path)
    assert type(scene).from_toml(scene.to_toml()) == scene
    assert isinstance(scene, vc.ArealScene) == path.name.startswith("areal_")


def test_the_maugis_dugdale_example_lies_between_its_limits():
    """At fixed load a finite-range law gives an area between the adhesionless one (range → ∞
    at fixed strength: no adhesion) and the JKR-like one (range → 0 at fixed work of adhesion);
    the scene sits in Maugis's transition, so the area is strictly between them."""
    scene = vc.Scene.from_toml(SCENES / "maugis_dugdale.toml")
    groups = vc.dimensionless_groups(scene)
    assert 0.1 < groups["transition"] < 5 and groups["regime"].startswith("Maugis transition")
    table = scene.to_dict()
    result = vc.solve(scene)
    assert result.converged and result.method == "bem"
    assert result.n_contacts == 1 and result.min_gap >= 0 and result.friction > 0
    gamma = table["adhesion"]["gamma"]
    dry = vc.solve({**table, "adhesion": {"kind": "none"}})
    jkr = vc.solve({**table, "adhesion": {"kind": "energy-balance", "gamma": gamma}})
    assert dry.converged and jkr.converged
    # The three differ by far more than their discretisation errors (about 1e-4 relative).
    assert dry.area * 1.1 < result.area < jkr.area / 1.1
