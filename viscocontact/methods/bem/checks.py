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


def tensile_split(fields, widen: bool = False, strength: float = 0.0):
    """Split contacts that carry more tension inside than the interface holds (an adhesionless
    solid none, a finite-range law its cohesive stress ``strength``): the new edges, for each
    contact split its index and the middle of its overloaded stretch, and the largest tension
    beyond ``strength`` as a fraction of the largest stress (``None, [], 0.0`` without).

    The new inner edges are the ends of the stretch; ``widen`` moves each out by half the
    stretch's width (at most halfway to the contact's edges), for a split whose parts merged
    again."""
    mesh = fields.mesh
    sig = fields.sigma
    scale = np.max(np.abs(sig)) if sig.size else 0.0
    out, where, tension = [], [], 0.0
    for j in range(mesh.n_contacts):
        sl = mesh.slice(j)
        s = sig[sl] - strength
        inner = np.zeros(s.shape, bool)
        inner[3:-3] = s[3:-3] > 1e-6 * scale
        if inner.any():
            tension = max(tension, float(np.max(s[3:-3])) / scale)
            idx = np.flatnonzero(inner)
            lo, hi = mesh.left[sl][idx[0]], mesh.right[sl][idx[-1]]
            if widen:
                a, b = mesh.edges[2 * j], mesh.edges[2 * j + 1]
                w = 0.5 * (hi - lo)
                lo, hi = max(lo - w, 0.5 * (a + lo)), min(hi + w, 0.5 * (hi + b))
            out += [mesh.edges[2 * j], lo, hi, mesh.edges[2 * j + 1]]
            where.append((j, 0.5 * (lo + hi)))
        else:
            out += [mesh.edges[2 * j], mesh.edges[2 * j + 1]]
    return (np.array(out), where, tension) if where else (None, [], 0.0)
