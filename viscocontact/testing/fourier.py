"""The Fourier series of a piecewise-constant stress on the period, as an independent reference
for tests: :func:`step_coefficients`, and :func:`dissipated_power`, the power
``4π Σ_m |σ̂_m|² Im[m-th kernel multiplier]`` fed into the bulk, against the BEM's real-space
forms.

For a stress ``s_q`` on ``[a_q, b_q]`` the coefficient of ``exp(i m x)`` is
``σ̂_m = Σ_q s_q (exp(-i m a_q) - exp(-i m b_q)) / (2π i m)``. Summed element by element this
takes two complex exponentials of the whole mode range per element; here the modes are cut
into blocks of ``BLOCK`` and ``exp(-i m x) = exp(-i m₀ x) · exp(-i j x)`` (``m = m₀ + j``), so
only ``(modes/BLOCK + BLOCK)`` exponentials per node are taken and the sum over the nodes is a
complex matrix product. Each factor is an exponential of an exact argument, so the product
keeps the exponential's relative accuracy (no recursion over ``m``).
"""
from __future__ import annotations

import numpy as np

#: Modes per block of the factorised exponentials.
BLOCK = 256


def step_coefficients(left, right, stress, modes: int) -> np.ndarray:
    """``σ̂_m`` for ``m = 1 … modes`` of the stress ``stress[q]`` on ``[left[q], right[q]]``
    (zero elsewhere on the period).

    >>> import numpy as np
    >>> c = step_coefficients([0.0], [np.pi], [1.0], 3)       # a square wave: 1/(iπm), m odd
    >>> bool(np.allclose(c, [1 / (1j * np.pi), 0.0, 1 / (3j * np.pi)]))
    True
    """
    left, right, stress = (np.asarray(v, dtype=float).ravel() for v in (left, right, stress))
    if not left.shape == right.shape == stress.shape:
        raise ValueError("left, right and stress must have one entry per element, got "
                         f"{left.size}, {right.size} and {stress.size}")
    if modes < 1:
        raise ValueError(f"modes must be at least 1, got {modes}")
    nodes = np.concatenate([left, right])
    weights = np.concatenate([stress, -stress])
    blocks = -(-modes // BLOCK)
    starts = np.arange(blocks, dtype=float) * BLOCK + 1.0             # m₀ of each block
    offsets = np.arange(BLOCK, dtype=float)                            # j
    outer = np.exp(-1j * starts[:, None] * nodes[None, :]) * weights   # (blocks, nodes)
    inner = np.exp(-1j * offsets[:, None] * nodes[None, :])            # (BLOCK, nodes)
    summed = (outer @ inner.T).ravel()[:modes]                         # Σ_k w_k e^{-i m x_k}
    m = np.arange(1, modes + 1, dtype=float)
    return summed / (2j * np.pi * m)


def dissipated_power(kernel, left, right, stress, modes: int = 200_000) -> float:
    """``4π Σ_{m=1}^{modes} |σ̂_m|² Im[kernel.multiplier(m)]``: the power the stress ``stress[q]``
    on ``[left[q], right[q]]`` feeds into the bulk per unit speed (friction times ``2π p̃∞/Λ̃``).

    ``kernel`` is a prepared kernel (anything with ``multiplier(m)``, the Fourier multiplier
    ``S_m K(m)``). Stress jumps make ``|σ̂_m|²`` fall like ``1/m²``, so the tail after ``modes``
    is of relative order ``1/modes``.
    """
    m = np.arange(1, modes + 1, dtype=float)
    sig_hat = step_coefficients(left, right, stress, modes)
    return float(4 * np.pi * np.sum(np.abs(sig_hat) ** 2 * np.imag(kernel.multiplier(m))))
