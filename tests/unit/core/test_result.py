"""ContactResult's JSON (strict: null for non-finite numbers) and its short repr."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

from viscocontact.result import ContactResult, SolveStatus


def result(**changes) -> ContactResult:
    values = dict(area=0.59018, mean_pressure=0.1, penetration=0.2089, friction=0.0283,
                  reduced_friction=np.float64(0.4003), n_contacts=1,
                  edges=np.array([[-0.0667, 0.5235]]), full_contact=False, converged=True,
                  status=SolveStatus.CONVERGED, message="converged", residual=1e-11,
                  iterations=7, function_evaluations=159, zeta=1.0, edge_perturbation=0.0,
                  min_gap=0.0123, fields={"x": np.linspace(0, 1, 4000)})
    values.update(changes)
    return ContactResult(**values)


def _reject(constant):
    raise AssertionError(f"{constant} is not JSON")


def test_no_contact_json_is_strict():
    apart = result(area=0.0, mean_pressure=0.0, penetration=-0.5, friction=math.nan,
                   reduced_friction=np.float64(np.nan), n_contacts=0, edges=np.zeros((0, 2)),
                   status=SolveStatus.NO_CONTACT, min_gap=math.inf, residual=-math.inf)
    data = json.loads(apart.to_json(), parse_constant=_reject)
    assert data["friction"] is None and data["reduced_friction"] is None
    assert data["min_gap"] is None and data["residual"] is None
    assert data["edges"] == [] and data["status"] == "no_contact" and data["area"] == 0.0
    # to_dict keeps the floats (studies store NaN in their float columns)
    assert math.isnan(apart.to_dict()["friction"]) and apart.to_dict()["min_gap"] == math.inf


def test_finite_json_round_trips_exactly():
    r = result(extras={"method": "bem", "error_estimate": 2e-4})
    data = json.loads(r.to_json(), parse_constant=_reject)
    assert data["reduced_friction"] == 0.4003 and type(r.to_dict()["reduced_friction"]) is float
    assert data["edges"] == [[-0.0667, 0.5235]]
    assert data == r.to_dict()
    assert data["method"] == "bem" and data["error_estimate"] == 2e-4
    with_fields = json.loads(r.to_json(with_fields=True), parse_constant=_reject)
    assert len(with_fields["fields"]["x"]) == 4000


def test_repr_is_short_and_says_what_matters():
    r = result(extras={"method": "newton", "residual_history": list(range(500))})
    text = repr(r)
    assert text.count("\n") <= 1 and len(text) < 160
    for fragment in ("converged", "Ã=0.59018", "p̃∞=0.1", "μ=0.0283", "1 contact",
                     "method='newton'"):
        assert fragment in text
    assert "array" not in text and "4000" not in text
    assert "method" not in repr(result())
    assert "3 contacts" in repr(result(n_contacts=3))
    full = repr(result(full_contact=True, area=2 * math.pi, status=SolveStatus.NOT_CONVERGED))
    assert "full contact" in full and "not_converged" in full


@pytest.mark.parametrize("status", list(SolveStatus))
def test_repr_of_every_status(status):
    assert repr(result(status=status)).startswith(f"<ContactResult {status.value}:")
