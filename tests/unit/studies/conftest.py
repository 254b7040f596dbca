"""Cheap scenes for the study tests: a sinusoid (Λ̃ = 0.1) on a standard linear solid (β = 10),
Newton, 32 elements per contact (each solve well under a second, except adhesive first touches)."""
from __future__ import annotations

import numpy as np
import pytest

from viscocontact.scene import Scene
from viscocontact.studies.point import COLUMNS, TIMING_COLUMNS
from viscocontact.testing.scenes import WAVY

ADHESIONLESS = WAVY

ADHESIVE = ADHESIONLESS.replace('[solver]', '[adhesion]\nkind = "energy-balance"\n'
                                            'gamma = 3e-5\n[solver]')

MESH = {"elements": 32}


@pytest.fixture
def adhesionless() -> Scene:
    return Scene.from_toml(ADHESIONLESS)


@pytest.fixture
def adhesive() -> Scene:
    return Scene.from_toml(ADHESIVE)


def ordered(points):
    """Columns sorted by (chain, step): the order of finishing depends on the backend."""
    order = np.lexsort((points["step"], points["chain"]))
    return {k: v[order] for k, v in points.items()}


def assert_identical(a, b):
    """Every column but the timings equal bit for bit (NaN equal to NaN)."""
    a, b = ordered(a), ordered(b)
    assert len(a["chain"]) == len(b["chain"])
    for key in COLUMNS:
        if key in TIMING_COLUMNS or (key not in a and key not in b):
            continue
        if key == "edges":
            assert all(np.array_equal(x, y) for x, y in zip(a[key], b[key])), key
        elif a[key].dtype.kind == "f":
            assert np.array_equal(a[key], b[key], equal_nan=True), (key, a[key], b[key])
        else:
            assert np.array_equal(a[key], b[key]), (key, a[key], b[key])


@pytest.fixture
def identical():
    """``identical(points_a, points_b)`` asserts bit-identical study results."""
    return assert_identical


@pytest.fixture
def mesh() -> dict:
    """Discretization of the test solves (32 elements per contact)."""
    return dict(MESH)
