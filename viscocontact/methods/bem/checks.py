"""What is checked on a uniform grid once the edges are in equilibrium: interpenetration outside
the contacts (contacts are born there), tension inside adhesionless contacts (they split there),
and how closely the discrete solid follows the profile between collocation points."""
from __future__ import annotations

import functools

import numpy as np

from ...contact.topology import TWO_PI, negative_regions
from .sets import Control, first_touch, inside


#: The depth of interpenetration outside the contacts at which a contact is born.
BIRTH_DEPTH = 1e-9


class Checks:
    """The check grid of one solve.

    Parameters
    ----------
    prep : Prepared
    check_points : int
        Points of the uniform grid (:attr:`Discretization.check_points`).
    """

    def __init__(self, prep, check_points: int):
        self.prep = prep
        self.points = check_points
        #: left end of the period window: half a period before the highest peak
        self.origin = prep.shape.peak_position - np.pi

    def grid(self):
        return self.origin + TWO_PI * (np.arange(self.points) + 0.5) / self.points

    @functools.cached_property
    def check_x(self):
        """Where interpenetration is checked: the uniform grid and every local maximum of the
        profile, so that a contact narrower than the grid spacing is still born."""
        peaks = self.origin + np.mod(self.prep.shape.maxima - self.origin, TWO_PI)
        return np.unique(np.concatenate([self.grid(), peaks]))

    def gap_outside(self, fields):
        """Gap ``ũ - w`` at the check points outside the contacts (edges excluded by 1% width)."""
        return self.gap_at(fields, self.check_x)

    def gap_at(self, fields, x):
        """The points of ``x`` outside the contacts (edges excluded by 1% width) and the gap
        ``ũ - w`` there."""
        x = np.asarray(x, dtype=float)
        mesh = fields.mesh
        keep = np.ones(x.shape, bool)
        for j in range(mesh.n_contacts):
            a, b = mesh.edges[2 * j], mesh.edges[2 * j + 1]
            pad = 0.01 * (b - a) + 1e-9
            for shift in (-TWO_PI, 0.0, TWO_PI):
                keep &= ~((x + shift > a - pad) & (x + shift < b + pad))
        xs = x[keep]
        if mesh.n_contacts:
            u = fields.displacement(self.prep.kernel, xs)
        else:
            u = np.zeros_like(xs)
        w = self.prep.shape.heights(xs) - 1.0 + fields.penetration
        return xs, u - w

    def closing(self, before, after) -> float | None:
        """The fraction of a step at which the gap outside the contacts first closes: linear
        between the fields ``before`` (the step's start, where it is open) and ``after`` (its
        predicted end), at the check points outside the contacts of both, the earliest where
        the profile penetrates at the end (:meth:`births`' depth); None where it stays open."""
        xs0, g0 = self.gap_outside(before)
        xs1, g1 = self.gap_outside(after)
        _, i0, i1 = np.intersect1d(xs0, xs1, assume_unique=True, return_indices=True)
        g0, g1 = g0[i0], g1[i1]
        closes = (g0 > 0.0) & (g1 < -BIRTH_DEPTH)
        if not np.any(closes):
            return None
        return float(np.min(g0[closes] / (g0[closes] - g1[closes])))

    def births(self, fields, outside=None):
        """Regions ``(a, b, depth)`` outside the contacts where the profile penetrates
        (``outside``: :meth:`gap_outside` of ``fields`` when at hand)."""
        xs, gap = self.gap_outside(fields) if outside is None else outside
        return negative_regions(xs, gap, BIRTH_DEPTH)

    def births_without_contact(self, control: Control):
        """Contacts of a state without any: where the profile penetrates the undeformed solid
        (penetration control), the first touch (a compressive load) or none."""
        if control.is_load:
            return None if control.value <= 0 else first_touch(self.prep.shape)[1]
        x = self.check_x
        w = self.prep.shape.heights(x) - 1.0 + control.value
        regions = negative_regions(x, -w, 0.0)
        if not regions:
            return None
        return np.array([v for (a, b, _) in regions for v in (a, b)])

    def conformity(self, fields, grid_displacement=None) -> float:
        """Largest ``|ũ - w|`` at the check grid's points inside the contacts: how far the
        discrete solid departs from the profile between collocation points (zero at them), in
        units of the profile amplitude. A discretisation error; see
        :attr:`Discretization.interior_resolution`. ``grid_displacement``: ``ũ`` on the whole
        check grid when it is at hand (:meth:`fields_on_grid`)."""
        x = self.grid()
        mesh = fields.mesh
        within = inside(x, mesh.edges, closed=False)
        if not within.any():
            return 0.0
        xs = x[within]
        u = (fields.displacement(self.prep.kernel, xs) if grid_displacement is None
             else grid_displacement[within])
        w = self.prep.shape.heights(xs) - 1.0 + fields.penetration
        return float(np.max(np.abs(u - w)))

    def fields_on_grid(self, fields):
        """Pressure, displacement and gap on the check grid."""
        x = self.grid()
        mesh = fields.mesh
        u = fields.displacement(self.prep.kernel, x)
        pres = np.zeros_like(x)
        loads = fields.loads
        if loads is not None:            # known stresses outside the contacts (cohesive zones)
            for lo, hi, s in zip(loads.left, loads.right, loads.stress):
                for shift in (-TWO_PI, 0.0, TWO_PI):
                    pres = np.where((x + shift >= lo) & (x + shift <= hi), -s, pres)
        for shift in (-TWO_PI, 0.0, TWO_PI):
            idx = np.searchsorted(mesh.right, x + shift)
            ok = idx < len(mesh.right)
            idx = np.minimum(idx, len(mesh.right) - 1)
            within = ok & (x + shift >= mesh.left[idx])
            pres = np.where(within, -fields.sigma[idx], pres)
        w = self.prep.shape.heights(x) - 1.0 + fields.penetration
        # inside the contacts the gap is zero by the contact condition (the discrete displacement
        # between collocation points differs from the profile by discretisation error only: the
        # result's extras["conformity"])
        within = inside(x, mesh.edges, closed=True)
        return {"x": x, "pressure": pres, "displacement": u, "gap": np.where(within, 0.0, u - w)}


#: Elements at each end of a contact that :func:`tensile_split` does not judge, and fewest
#: between two overloaded stretches that it keeps in contact.
KEPT = 3


def tensile_split(fields, widen: bool = False, strength: float = 0.0):
    """Split contacts that carry more tension inside than the interface holds (an adhesionless
    solid none, a finite-range law its cohesive stress ``strength``): the new edges, for each
    overloaded stretch its contact's index and its middle, and the largest tension beyond
    ``strength`` as a fraction of the largest stress (``None, [], 0.0`` without).

    Each stretch of elements whose tension exceeds ``strength`` opens between its ends, and the
    compressed parts between stretches stay in contact: a compressed hump between two tensile
    shoulders opened with them penetrated the profile, and the parts merged again (campaign
    seed 40). A contact's :data:`KEPT` elements at each end are not judged (their stresses are
    the bounded-stress fit's), and stretches fewer than :data:`KEPT` elements apart open
    together. ``widen`` moves each stretch's ends out by half its width (:func:`_widened`), for
    a split whose parts merged again."""
    mesh = fields.mesh
    sig = fields.sigma
    scale = np.max(np.abs(sig)) if sig.size else 0.0
    out, where, tension = [], [], 0.0
    for j in range(mesh.n_contacts):
        sl = mesh.slice(j)
        s = sig[sl] - strength
        a, b = mesh.edges[2 * j], mesh.edges[2 * j + 1]
        inner = np.zeros(s.shape, bool)
        inner[KEPT:-KEPT] = s[KEPT:-KEPT] > 1e-6 * scale
        if not inner.any():
            out += [a, b]
            continue
        tension = max(tension, float(np.max(s[KEPT:-KEPT])) / scale)
        cuts = [(mesh.left[sl][i], mesh.right[sl][k]) for i, k in _stretches(inner)]
        if widen:
            cuts = _widened(cuts, a, b)
        out += [a, *[v for cut in cuts for v in cut], b]
        where += [(j, 0.5 * (lo + hi)) for lo, hi in cuts]
    return (np.array(out), where, tension) if where else (None, [], 0.0)


def _stretches(inner: np.ndarray) -> list[tuple[int, int]]:
    """``(first, last)`` element of each stretch of ``inner``, stretches fewer than
    :data:`KEPT` elements apart joined."""
    idx = np.flatnonzero(inner)
    breaks = np.flatnonzero(np.diff(idx) > KEPT)
    return list(zip(np.r_[idx[0], idx[breaks + 1]], np.r_[idx[breaks], idx[-1]]))


def _widened(cuts: list, a: float, b: float) -> list:
    """``cuts`` of the contact ``(a, b)``, each moved out by half its width, at most halfway to
    the contact's edges and a quarter of the way to the cut beside it (whose own move takes
    another quarter: the compressed part between them keeps half its width)."""
    out = []
    for k, (lo, hi) in enumerate(cuts):
        w = 0.5 * (hi - lo)
        low = 0.5 * (a + lo) if k == 0 else lo - 0.25 * (lo - cuts[k - 1][1])
        high = 0.5 * (hi + b) if k == len(cuts) - 1 else hi + 0.25 * (cuts[k + 1][0] - hi)
        out.append((max(lo - w, low), min(hi + w, high)))
    return out
