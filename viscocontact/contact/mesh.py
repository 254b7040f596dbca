r"""Edge-clustered meshes of contact regions (thesis equations 4.21-4.29).

For a contact ``[X_{2j-1}, X_{2j}]`` with centre μ and half-width α, a uniform grid
``ζ_l = -α + 2αl/N`` is mapped by

.. math:: z_l = \mathcal M(\zeta_l) = \frac{\alpha\, I(\zeta_l)}{I(\alpha)},\qquad
          I(\zeta) = \int_0^\zeta [\cos\xi - \cos\alpha]^n\, d\xi ,

so the node density ``1/M'`` diverges at both edges (``n >= 1/2``; eq. 4.27). ``I`` is computed
with the substitution ``ξ = α sin θ`` (which removes the endpoint behaviour) and 8-point
Gauss-Legendre panels between consecutive nodes; ``cos ξ - cos α`` is evaluated as
``2 sin((α+ξ)/2) sin((α-ξ)/2)`` so that small contacts lose nothing. Collocation points are the
element midpoints (eq. 4.23).

Edge zones (viscocontact's extension): a viscoelastic contact has structure at lengths the
clustering above cannot reach at any affordable N — the memory length ζ (on scales below it the
solid responds glassy, above it relaxed, so the edge stress intensity changes across a layer of
width ~ζ) and the virtual edge advance δX of a finite energy balance. Near an edge the clustered
spacing grows like √(distance)/N, so a layer of width ℓ is resolved only when N ≳ √(α/ℓ). A
:class:`MeshSpec` with ``smallest = h0`` replaces the clustered nodes closest to each edge by a
zone anchored at the edge: equal elements of size at most h0, then sizes growing by the ratio
``g = grading`` up to the clustered node where the clustered spacing ratio has fallen to g. Every length between h0
and the contact size is then resolved with the same relative accuracy (``h/d ≈ g - 1``), at a cost
logarithmic in ``α/h0``.
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


#: Largest edge element relative to the half-width when a zone is asked for: keeps the elements
#: that the stress-intensity fit sees self-similar, so that one calibration serves every contact.
ZONE_CAP = 1e-3
#: Largest extent of an edge zone, relative to the half-width of its contact.
ZONE_REACH = 0.4
#: Largest δX/h for which the equal edge elements are aligned with the edge advance δX.
ALIGN_MAX = 20


@attrs.frozen(kw_only=True)
class MeshSpec:
    """How a contact is meshed (hashable: calibration tables are cached per spec).

    Parameters
    ----------
    elements : int
        Elements of the clustered mesh (eq. 4.21's N).
    exponent : float
        Clustering exponent n of eq. 4.27.
    grading : float
        Ratio of consecutive element sizes in the edge zones.
    smallest : float or None
        Size h0 of the element at each edge (absolute, dimensionless); ``None``: no edge zones.
        Capped at ``ZONE_CAP`` times the half-width.
    advance : float or None
        A finite virtual edge advance δX to align the zone nodes with (see :func:`zone_pattern`).
    """

    elements: int
    exponent: float = 1.0
    grading: float = 1.25
    smallest: float | None = None
    advance: float | None = None


def tip_elements(spec: MeshSpec) -> int:
    """Equal elements between the edge and the geometric zone: at least ``1/(g - 1)``, so that the
    element at the edge is no larger than its neighbours, and at least 12, so that the
    stress-intensity fit (8 elements) sees only equal elements, whatever the zone."""
    return max(int(np.ceil(1.0 / (spec.grading - 1.0) - 1e-9)), 12)


def _junction(d: np.ndarray, spec: MeshSpec) -> int:
    """First clustered node from which the spacing grows by at most ``grading`` per element (and
    no further than ``ZONE_REACH`` of the half-width from the edge, so that a zone made for a
    contact fits it unscaled and stays aligned with the edge advance)."""
    half = spec.elements // 2
    ok = np.flatnonzero(np.diff(d)[1:half] <= (spec.grading - 1.0) * d[1:half])
    first = int(ok[0]) + 1 if ok.size else half
    return max(min(first, int(np.searchsorted(d, 0.5 * ZONE_REACH * d[-1], side="right")) - 1), 1)


def zone_pattern(alpha: float, spec: MeshSpec) -> tuple | None:
    """``(nodes, J)``: distances from an edge of the edge-zone nodes of a contact of half-width α,
    from 0 to the junction with clustered node J (``None``: no zone).

    The zone starts with equal elements of size ``h <= h0``; with a finite edge advance δX
    (``spec.advance``) ``h = δX/n`` for an integer n and the equal elements cover ``2δX``, so that
    the mesh of the contact with that edge moved out by δX has the same nodes there (the cross
    terms of δL_P then compare the two fields node by node); this only when ``δX <= 20 h0``. Then sizes grow by ``grading``
    up to the junction.
    """
    if spec.smallest is None or not 0.0 < alpha < np.inf:
        return None                 # (a contact that is no interval, e.g. a start whose edges
        #                             crossed: its zone would grow without end)
    g = spec.grading
    d = clustered_nodes(alpha, spec.elements, spec.exponent) + alpha
    junction = _junction(d, spec)
    d_end = d[junction]
    h = min(spec.smallest, ZONE_CAP * alpha)
    u = tip_elements(spec)
    if spec.advance and spec.advance <= ALIGN_MAX * h * (1 + 1e-9):
        h = spec.advance / np.ceil(spec.advance / h - 1e-9)
        u = max(u, int(round(2 * spec.advance / h)))
    if u * h * g >= d_end:
        return None
    nodes = list(h * np.arange(u + 1))
    size = h * g
    while nodes[-1] + size * (1 + 0.5 * g) <= d_end:
        nodes.append(nodes[-1] + size)
        size *= g
    nodes.append(d_end)
    return np.array(nodes), junction


def graded_nodes(alpha: float, spec: MeshSpec, zone=None) -> np.ndarray:
    """Nodes ``-α < ... < α`` of one contact: clustered (eq. 4.22) with edge zones.

    ``zone`` fixes the zone nodes (distances from each edge; default :func:`zone_pattern` of α)
    and the clustered nodes beyond the junction are mapped affinely onto the rest of the
    contact. Within one equilibrium solve the orchestrator keeps the zones fixed, so that the
    nodes, and every quantity computed on them, are smooth functions of the edge positions.
    """
    z = clustered_nodes(alpha, spec.elements, spec.exponent)
    if spec.smallest is None:
        return z
    if zone is False:                                  # fixed: this contact has no zone
        return z
    if zone is None:
        zone = zone_pattern(alpha, spec)
        if zone is None:
            return z
    nodes, j = zone
    if nodes[-1] > ZONE_REACH * alpha:
        # the contact shrank below the one the zone was made for: shrink the zone with it
        # (same nodes, so the count, and the residual, stay continuous in the edges)
        nodes = nodes * (ZONE_REACH * alpha / nodes[-1])
    d = z - z[0]
    half = spec.elements // 2
    body = nodes[-1] + (d[j:half + 1] - d[j]) * (alpha - nodes[-1]) / (alpha - d[j])
    left = np.concatenate([nodes[:-1], body])
    right = 2.0 * alpha - left[::-1]
    if spec.elements % 2 == 0:
        right = right[1:]
    out = np.concatenate([left, right]) - alpha
    out[0], out[-1] = -alpha, alpha
    return out


def element_counts(spec: MeshSpec, counts, n_contacts: int) -> tuple:
    """The elements of each of ``n_contacts`` contacts (``counts = None``: ``spec.elements``
    for all)."""
    return (spec.elements,) * n_contacts if counts is None else tuple(counts)


def contact_spec(spec: MeshSpec, counts, j: int) -> MeshSpec:
    """The spec of contact ``j``: ``spec`` with ``counts[j]`` elements (``counts = None``: all
    contacts have ``spec.elements``)."""
    if counts is None or counts[j] == spec.elements:
        return spec
    return attrs.evolve(spec, elements=int(counts[j]))


def zone_patterns(edges: np.ndarray, spec: MeshSpec, counts=None) -> tuple:
    """:func:`zone_pattern` of every contact ``[edges[2j], edges[2j+1]]`` (``False``: none, and
    none is to be added while these zones are in use); ``counts``: elements of each contact."""
    edges = np.asarray(edges, dtype=float)
    out = []
    for j in range(len(edges) // 2):
        zone = zone_pattern(0.5 * (edges[2 * j + 1] - edges[2 * j]), contact_spec(spec, counts, j))
        out.append(False if zone is None else zone)
    return tuple(out)


def squeezed(zones: tuple, edges: np.ndarray) -> bool:
    """Whether a contact of ``edges`` has shrunk so far that :func:`graded_nodes` compresses
    its zone of ``zones`` (:func:`zone_patterns`) more than twice, so that the zone's equal
    elements are no longer those of the edge advance or of the calibration. A zone reaches at
    most ``ZONE_REACH`` of its contact's half-width (about 0.21 of it on the default mesh, which
    then fits unscaled down to about half its width); a contact that shrinks by orders of
    magnitude on fixed zones (a contact that detaches) has residuals of round-off, hundreds of
    times the work of adhesion where it is a millionth as wide."""
    edges = np.asarray(edges, dtype=float)
    width = edges[1::2] - edges[0::2]          # (ZONE_REACH of twice the half-width)
    return any(zone is not False and zone[0][-1] > ZONE_REACH * w
               for zone, w in zip(zones, width))


def same_zones(first, second) -> bool:
    """Whether two :func:`zone_patterns` results are equal (node for node)."""
    if len(first) != len(second):
        return False
    for a, b in zip(first, second):
        if (a is False) != (b is False):
            return False
        if a is not False and (a[1] != b[1] or not np.array_equal(a[0], b[0])):
            return False
    return True


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


def build_mesh(edges: np.ndarray, spec: MeshSpec, zones=None, counts=None) -> Mesh:
    """Mesh every contact ``[edges[2j], edges[2j+1]]`` as ``spec`` says (``zones``: the edge-zone
    nodes of each contact, default :func:`zone_patterns`; ``counts``: the elements of each
    contact, default ``spec.elements`` for all)."""
    edges = np.asarray(edges, dtype=float)
    lefts, rights, ids = [], [], []
    for j in range(len(edges) // 2):
        a, b = edges[2 * j], edges[2 * j + 1]
        alpha = 0.5 * (b - a)
        z = 0.5 * (a + b) + graded_nodes(alpha, contact_spec(spec, counts, j),
                                         None if zones is None else zones[j])
        z[0], z[-1] = a, b
        lefts.append(z[:-1])
        rights.append(z[1:])
        ids.append(np.full(len(z) - 1, j))
    return Mesh(left=np.concatenate(lefts), right=np.concatenate(rights),
                contact=np.concatenate(ids), edges=edges.copy())
