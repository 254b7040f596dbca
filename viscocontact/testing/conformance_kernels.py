"""Conformance checks for :class:`~viscocontact.kernels.base.GreenKernel` implementations.

``check_kernel(kernel)`` raises ``AssertionError`` with a clear message when a kernel breaks the
contract: finite geometry factors tending to 1 (the half-plane) at large modes, a symmetric elastic
kernel whose influence matrix on equal elements is symmetric and negative definite, the relaxed
(E0) and glassy (E∞) limits of the viscoelastic kernel, and non-negative power fed by sliding.
"""
from __future__ import annotations

import numpy as np


def _fail(name: str, message: str):
    raise AssertionError(f"{name}: {message}")


def check_kernel(kernel, *, seed: int = 0) -> None:
    """Run the kernel conformance checks (see the module docstring)."""
    from ..rheology.elastic import Elastic
    from ..rheology.sls import StandardLinearSolid

    name = type(kernel).__name__
    m = np.arange(1, 2001, dtype=float)
    s = np.asarray(kernel.geometry_factors(m), dtype=float)
    if s.shape != m.shape or not np.all(np.isfinite(s)):
        _fail(name, "geometry_factors must return finite values of the shape of m")
    if np.any(s <= 0):
        _fail(name, "geometry_factors must be positive (a positive compliance per mode)")
    if abs(s[-1] - 1.0) > 1e-6:
        _fail(name, f"geometry_factors must tend to 1 (half-plane) at large m; S_2000 = {s[-1]}")
    if not np.isfinite(kernel.mean_compliance()):
        _fail(name, "mean_compliance must be finite")

    rng = np.random.default_rng(seed)
    n = 24
    h = 2 * np.pi / (n + 3)
    a = -np.pi + h * np.sort(rng.choice(n + 3, n, replace=False))
    b = a + h
    xi = 0.5 * (a + b)
    relaxed = kernel.prepare(Elastic(), 0.0).influence(xi, a, b)
    if np.max(np.abs(relaxed - relaxed.T)) > 1e-10 * np.abs(relaxed).max():
        _fail(name, "elastic influence matrix on equal elements must be symmetric")
    if np.linalg.eigvalsh(-0.5 * (relaxed + relaxed.T)).min() <= 0:
        _fail(name, "-B must be positive definite on a union of intervals shorter than the period")

    sls = StandardLinearSolid(beta=10.0)
    c0 = kernel.mean_compliance() * (b - a)[None, :]
    scale = np.abs(relaxed).max()
    if np.max(np.abs(kernel.prepare(sls, 1e-9).influence(xi, a, b) - relaxed)) > 1e-6 * scale:
        _fail(name, "ζ → 0 must give the relaxed (E0) kernel")
    fast = kernel.prepare(sls, 1e9).influence(xi, a, b)
    if np.max(np.abs(fast - ((relaxed - c0) / 10.0 + c0))) > 1e-6 * scale:
        _fail(name, "ζ → ∞ must give the glassy (E∞) kernel (mean part relaxed)")

    for zeta in (0.01, 0.3, 3.0):
        pk = kernel.prepare(sls, zeta)
        F = pk.antiderivative
        Bx = lambda x: F(x[:, None] - a[None, :]) - F(x[:, None] - b[None, :])  # noqa: E731
        P = Bx(b) - Bx(a)
        sym = 0.5 * (P + P.T)
        if np.linalg.eigvalsh(sym).min() < -1e-9 * np.abs(P).max():
            _fail(name, f"sliding must feed non-negative power (ζ = {zeta}): V∫σu' < 0 for some σ")
