"""Finite-difference Jacobians (thesis eqs. 4.49-4.50) and the shared solver machinery."""
import numpy as np
import pytest
from hypothesis import given, settings

from viscocontact.errors import ValidationError
from viscocontact.solvers._fd import (BudgetExhausted, CountedResidual, FiniteDifference,
                                      fd_jacobian, limit_step)
from viscocontact.testing.strategies_solvers import FunctionProblem, tanh_systems

FAST = settings(max_examples=30, deadline=None)


def f(x):
    return np.array([np.sin(x[0]) * x[1], x[0] ** 3 + np.exp(x[1]), x[2] * x[0]])


def jac(x):
    return np.array([[np.cos(x[0]) * x[1], np.sin(x[0]), 0.0],
                     [3 * x[0] ** 2, np.exp(x[1]), 0.0],
                     [x[2], 0.0, x[0]]])


X = np.array([0.7, -0.3, 2.0])


def test_forward_is_first_order_and_central_second_order():
    errors = {}
    for scheme in ("forward", "central"):
        errors[scheme] = [np.max(np.abs(fd_jacobian(f, X, scheme=scheme, rel_step=h)[0] - jac(X)))
                          for h in (1e-2, 1e-3)]
    fwd, cen = errors["forward"], errors["central"]
    assert 7 < fwd[0] / fwd[1] < 13           # O(h)
    assert 70 < cen[0] / cen[1] < 130         # O(h²)
    assert cen[1] < fwd[1] / 100


@pytest.mark.parametrize("scheme, given_f0, evaluations", [
    ("forward", True, 3), ("forward", False, 4), ("central", True, 6), ("central", False, 6)])
def test_evaluation_counts(scheme, given_f0, evaluations):
    calls = []

    def counted(x):
        calls.append(x.copy())
        return f(x)

    J, n = FiniteDifference(scheme=scheme).jacobian(counted, X, f(X) if given_f0 else None)
    assert n == len(calls) == evaluations
    np.testing.assert_allclose(J, jac(X), rtol=1e-4, atol=1e-6)


def test_steps_are_relative_with_a_floor_and_exact():
    fd = FiniteDifference(rel_step=1e-6, typical_scale=0.5)
    x = np.array([0.0, 0.1, 3.0, -2000.0])
    h = fd.steps(x)
    np.testing.assert_allclose(h, 1e-6 * np.array([0.5, 0.5, 3.0, 2000.0]), rtol=1e-9)
    assert np.all((x + h) - x == h)          # representable: no rounding in the difference


def test_perturbs_one_component_at_a_time_and_never_mutates_x():
    seen = []
    x = X.copy()
    FiniteDifference(scheme="central").jacobian(lambda y: seen.append(y.copy()) or f(y), x)
    np.testing.assert_array_equal(x, X)
    for y in seen:
        assert np.count_nonzero(y != X) == 1


def test_exceptions_propagate():
    class Stop(Exception):
        pass

    def bad(x):
        raise Stop

    with pytest.raises(Stop):
        fd_jacobian(bad, X)


@FAST
@given(system=tanh_systems(width_decades=(-1.0, 1.0), scale_decades=(-1.0, 1.0),
                           negative_scales=True))
def test_central_differences_match_the_analytic_jacobian(system):
    x = system.root + 0.3 * system.width
    J, _ = fd_jacobian(system.residual, x, scheme="central", rel_step=1e-6,
                       typical_scale=float(np.min(system.width)))
    scale = np.max(np.abs(system.jacobian(x)))
    np.testing.assert_allclose(J, system.jacobian(x), atol=1e-5 * scale)


@pytest.mark.parametrize("kwargs, field", [({"scheme": "backward"}, "FiniteDifference.scheme"),
                                           ({"rel_step": 0.0}, "FiniteDifference.rel_step"),
                                           ({"rel_step": -1e-7}, "FiniteDifference.rel_step"),
                                           ({"typical_scale": 0.0},
                                            "FiniteDifference.typical_scale")])
def test_bad_options(kwargs, field):
    with pytest.raises(ValidationError, match=field):
        FiniteDifference(**kwargs)


def test_counted_residual_enforces_the_budget_before_calling():
    calls = []
    counted = CountedResidual(FunctionProblem(lambda x: calls.append(1) or x), budget=2)
    counted(np.zeros(2))
    counted(np.zeros(2))
    with pytest.raises(BudgetExhausted):
        counted(np.zeros(2))
    assert counted.count == len(calls) == 2


def test_limit_step_uses_one_common_factor():
    problem = FunctionProblem(lambda x: x, max_step=np.array([0.1, 1.0]))
    step, t = limit_step(problem, np.zeros(2), np.array([0.4, -0.2]))
    assert t == pytest.approx(0.25)
    np.testing.assert_allclose(step, [0.1, -0.05])
    free, t = limit_step(FunctionProblem(lambda x: x), np.zeros(2), np.array([5.0, 1.0]))
    assert t == 1.0 and np.array_equal(free, [5.0, 1.0])
