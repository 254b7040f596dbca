"""Parameter parsing, scene variants and where a point starts from."""
from pathlib import Path

import numpy as np
import pytest

from viscocontact.errors import ValidationError
from viscocontact.scene import Scene
from viscocontact.studies.base import (log_zetas, parse_numbers, parse_seeds, scene_variant,
                                       secant_start, starting_point)

EXAMPLES = Path(__file__).resolve().parents[3] / "examples" / "scenes"


def test_log_zetas_and_lists():
    assert log_zetas(1e-4, 1e3, 8) == (1e-4, 1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0, 1000.0)
    assert parse_numbers("--zetas", "1e-2:1e2:5", log=True) == (0.01, 0.1, 1.0, 10.0, 100.0)
    assert parse_numbers("--loads", "0.1, 0.2") == (0.1, 0.2)
    assert parse_numbers("--loads", "0:1:3") == (0.0, 0.5, 1.0)
    assert parse_seeds("0:3") == (0, 1, 2) and parse_seeds("4,7") == (4, 7)


@pytest.mark.parametrize("call,field", [
    (lambda: parse_numbers("--zetas", "0:10:3", log=True), "--zetas"),
    (lambda: parse_numbers("--zetas", "a,b", log=True), "--zetas"),
    (lambda: parse_seeds("1,1"), "--seeds"),
    (lambda: parse_seeds("-1"), "--seeds"),
])
def test_bad_parameters_name_the_option(call, field):
    with pytest.raises(ValidationError) as info:
        call()
    assert info.value.field == field


def test_scene_variant_drops_contradicting_physical_keys():
    scene = Scene.from_toml(EXAMPLES / "thesis_rough.toml").to_dict()
    scene["physical"].update(velocity=1e-3, tau=1e-2)                  # ζ = q0 V τ
    scene["sliding"]["zeta"] = 2 * 3.141592653589793 / 6.28e-3 * 1e-5
    Scene.from_dict(scene)
    out = scene_variant(scene, zeta=0.5, control="penetration", value=0.3, seed=7,
                        adhesion={"kind": "none"})
    assert out["sliding"] == {"zeta": 0.5} and out["load"] == {"penetration": 0.3}
    assert out["profile"]["seed"] == 7 and out["adhesion"] == {"kind": "none"}
    for key in ("velocity", "tau", "mean_pressure", "penetration", "work_of_adhesion"):
        assert key not in out["physical"]
    assert out["physical"]["E0"] == scene["physical"]["E0"]
    assert scene["profile"].get("seed", 0) != 7          # the base is not modified
    Scene.from_dict(out)                                  # and the variant is a valid scene


def test_starting_point_rules():
    contact = {"converged": True, "n_contacts": 1, "full_contact": False,
               "edges": np.array([-0.5, 0.5])}
    full = dict(contact, n_contacts=1, full_contact=True, edges=np.zeros(0))
    none = dict(contact, n_contacts=0, edges=np.zeros(0))
    origin, edges = starting_point(contact, 0.1)
    assert origin == "neighbour" and edges.tolist() == [-0.5, 0.5]
    assert starting_point(full, -0.1) == ("first touch", None)
    assert starting_point(None, None) == ("first touch", None)
    assert starting_point(none, 0.2) == ("first touch", None)
    origin, edges = starting_point(none, 0.0)
    assert origin == "no contact" and edges.size == 0


def _record(edges, **kw):
    return {"converged": True, "n_contacts": len(edges) // 2, "full_contact": False,
            "edges": np.asarray(edges, dtype=float), **kw}


def test_the_secant_through_the_last_two_contact_sets_predicts_the_next():
    """ζ-continuation: linear in log ζ; a cycle: linear in the penetration, within one phase."""
    records = [_record([-0.50, 0.40], zeta=1e-2), _record([-0.52, 0.41], zeta=1e-1)]
    assert np.allclose(secant_start(records, "zeta", 1.0, log=True), [-0.54, 0.42])
    assert np.allclose(secant_start(records, "zeta", np.sqrt(0.1), log=True), [-0.53, 0.415])
    steps = [_record([-0.30, 0.30], target=0.2, phase="approach"),
             _record([-0.32, 0.31], target=0.25, phase="approach")]
    assert np.allclose(secant_start(steps, "target", 0.3, phase="approach"), [-0.34, 0.32])


def test_the_secant_is_not_used_across_changes():
    base = _record([-0.50, 0.40], zeta=1e-2)
    # a contact born in between, the direction reversed or the step too long, another phase
    assert secant_start([base, _record([-0.5, 0.4, 1.0, 1.1], zeta=0.1)], "zeta", 1.0,
                        log=True) is None
    two = [base, _record([-0.52, 0.41], zeta=1e-1)]
    assert secant_start(two, "zeta", 1e-2, log=True) is None
    assert secant_start(two, "zeta", 1e2, log=True) is None
    steps = [_record([-0.3, 0.3], target=0.2, phase="approach"),
             _record([-0.32, 0.31], target=0.25, phase="approach")]
    assert secant_start(steps, "target", 0.2, phase="retract") is None
    # a failed point last
    failed = dict(two[1], converged=False)
    assert secant_start([base, failed], "zeta", 1.0, log=True) is None


def test_the_secant_moves_no_edge_by_more_than_half_its_half_width():
    """A fast change (an edge running before a jump) is followed only partway."""
    records = [_record([-0.10, 0.10], zeta=1e-2), _record([-0.30, 0.10], zeta=1e-1)]
    out = secant_start(records, "zeta", 1.0, log=True)
    half = 0.5 * (0.10 + 0.30)
    assert np.max(np.abs(out - records[-1]["edges"])) == pytest.approx(0.5 * half)
    assert out[0] < -0.30 and out[1] == pytest.approx(0.10)
