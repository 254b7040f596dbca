r"""What one grid solve of the spectral method gives: its contacts, their sub-cell edges, the
area, the friction and the dissipated power's friction (:class:`GridMeasures`,
:func:`measure`)."""
from __future__ import annotations

import attrs
import numpy as np

from ...kernels.clausen import TWO_PI
from .cohesive import GridLaw
from .edges import contact_edges
from .grid import UniformGrid
from .operator import convolve, power
from .solvers import GridSolution


@attrs.frozen(kw_only=True, eq=False)
class GridMeasures:
    """What one grid solve gives: the solution, its contacts and the integral measures.

    Attributes
    ----------
    grid : UniformGrid
    solution : GridSolution
    edges : ndarray, shape (n, 2)
        The contacts' sub-cell edges (``x̃``; empty when closed or without contact).
    area : float
        ``Ã``, the contacts' total length.
    friction : float
        ``μ`` (eq. 4.16; NaN without load).
    contact : ndarray of bool
        Cells in contact (the loaded ones, ``p > 0``; a cohesive law's contact cells).
    weights : ndarray or None
        Share of each cell under a cohesive law's stress (None: no law).
    dissipation : float
        ``μ`` from the power fed into the solid (:func:`~.operator.power`; NaN without load or
        without the loss weights), the power balance's side of the friction.
    """

    grid: UniformGrid
    solution: GridSolution
    edges: np.ndarray
    area: float
    friction: float
    contact: np.ndarray
    weights: np.ndarray | None = None
    dissipation: float = float("nan")

    @property
    def closed(self) -> bool:
        """Whether every cell is in contact."""
        return bool(np.all(self.contact))


def measure(grid: UniformGrid, solution: GridSolution, eigenvalues, workers: int = 1,
            law: GridLaw | None = None, contact=None, weights=None, loss=None,
            amplitude: float = 1.0) -> GridMeasures:
    """Contacts, area (sub-cell edges) and friction (eq. 4.16) of a grid solution.

    With a cohesive ``law`` the contacts are the cells ``contact`` and their edges are located
    from the shifted pressure ``p + σ̃0``, which has the adhesionless square-root field at a
    Maugis–Dugdale edge (the gap outside rises as ``s^{3/2}`` there too); the friction counts the
    cohesive stress with the contact stress, and the load may be tensile.

    Parameters
    ----------
    grid : UniformGrid
    solution : GridSolution
    eigenvalues : ndarray
        The grid's circulant eigenvalues (for the gaps).
    workers : int
        Threads of ``scipy.fft``.
    law : GridLaw, optional
        A cohesive law; then ``contact`` and ``weights`` are its solution's
        (:class:`~.cohesive.CohesiveSolution`).
    loss : ndarray, optional
        The grid's loss weights (:func:`~.operator.dissipation_weights`) for the dissipated
        power's friction, with the profile's ``amplitude``.
    """
    p = solution.pressure
    pm = float(p.mean())
    if law is None:
        contact = p > 0
    # a cohesive law's load may be tensile
    defined = pm > 0 if law is None else pm != 0
    mu = float(-(p @ grid.rise) / (TWO_PI * pm)) if defined else float("nan")
    dissipated = (amplitude * power(p, loss, workers) / pm if defined and loss is not None
                  else float("nan"))
    extra = dict(contact=contact, weights=weights, dissipation=dissipated)
    if np.all(contact):
        return GridMeasures(grid=grid, solution=solution, edges=np.zeros((0, 2)), area=TWO_PI,
                            friction=mu, **extra)
    gap = convolve(p, eigenvalues, workers) - (grid.heights - 1.0 + solution.penetration)
    shifted = p if law is None else np.where(contact, p + law.strength * weights, 0.0)
    edges = contact_edges(grid.start, grid.cell, shifted, gap)
    area = float(min(np.sum(edges[:, 1] - edges[:, 0]), TWO_PI)) if edges.size else 0.0
    return GridMeasures(grid=grid, solution=solution, edges=edges, area=area, friction=mu,
                        **extra)
