r"""Edge-clustered meshes of contact regions (thesis eqs. 4.21-4.29).

For a contact ``[X_{2j-1}, X_{2j}]`` with centre μ and half-width α, a uniform grid
``ζ_l = -α + 2αl/N`` is mapped by

.. math:: z_l = \mathcal M(\zeta_l) = \frac{\alpha\, I(\zeta_l)}{I(\alpha)},\qquad
          I(\zeta) = \int_0^\zeta [\cos\xi - \cos\alpha]^n\, d\xi ,

so the node density ``1/M'`` diverges at both edges (``n >= 1/2``; eq. 4.27). ``I`` is computed
with the substitution ``ξ = α sin θ`` (which removes the endpoint behaviour) and 8-point
Gauss-Legendre panels between consecutive nodes; ``cos ξ - cos α`` is evaluated as
``2 sin((α+ξ)/2) sin((α-ξ)/2)`` so that small contacts lose nothing. Collocation points are the
element midpoints (eq. 4.23).
"""
from __future__ import annotations

import attrs
import numpy as np

_GL_X, _GL_W = np.polynomial.legendre.leggauss(8)


def clustered_nodes(alpha: float, n_elements: int, exponent: float) -> np.ndarray:
    """Nodes ``z_0 = -α < ... < z_N = α`` of eq. 4.22 for one contact of half-width α (<= π)."""
    theta = np.arcsin(np.clip(-1.0 + 2.0 * np.arange(n_elements + 1) / n_elements, -1.0, 1.0))
    lo, hi = theta[:-1], theta[1:]
    half = 0.5 * (hi - lo)
    t = 0.5 * (hi + lo)[:, None] + half[:, None] * _GL_X[None, :]
    xi = alpha * np.sin(t)
    base = 2.0 * np.sin(0.5 * (alpha + xi)) * np.sin(0.5 * (alpha - xi))
    integrand = np.maximum(base, 0.0) ** exponent * np.cos(t)
    panels = half * (integrand @ _GL_W)
    cum = np.concatenate([[0.0], np.cumsum(panels)])
    z = -alpha + 2.0 * alpha * cum / cum[-1]
    z[0], z[-1] = -alpha, alpha
    return z


@attrs.frozen(kw_only=True, eq=False)
class Mesh:
    """Elements of all contacts, concatenated contact by contact (left to right).

    Attributes
    ----------
    left, right, mid, width : (N,) arrays
        Element ends, collocation points (midpoints) and lengths.
    contact : (N,) int array
        Index of the contact each element belongs to.
    edges : (2 Nc,) array
        Contact edges ``[X_1, X_2, X_3, ...]``.
    """

    left: np.ndarray
    right: np.ndarray
    contact: np.ndarray
    edges: np.ndarray

    @property
    def mid(self) -> np.ndarray:
        return 0.5 * (self.left + self.right)

    @property
    def width(self) -> np.ndarray:
        return self.right - self.left

    @property
    def n_contacts(self) -> int:
        return len(self.edges) // 2

    def slice(self, j: int) -> slice:
        idx = np.flatnonzero(self.contact == j)
        return slice(int(idx[0]), int(idx[-1]) + 1)


def build_mesh(edges: np.ndarray, n_elements: int, exponent: float) -> Mesh:
    """Mesh every contact ``[edges[2j], edges[2j+1]]`` with ``n_elements`` clustered elements."""
    edges = np.asarray(edges, dtype=float)
    lefts, rights, ids = [], [], []
    for j in range(len(edges) // 2):
        a, b = edges[2 * j], edges[2 * j + 1]
        alpha = 0.5 * (b - a)
        z = 0.5 * (a + b) + clustered_nodes(alpha, n_elements, exponent)
        z[0], z[-1] = a, b
        lefts.append(z[:-1])
        rights.append(z[1:])
        ids.append(np.full(n_elements, j))
    return Mesh(left=np.concatenate(lefts), right=np.concatenate(rights),
                contact=np.concatenate(ids), edges=edges.copy())
