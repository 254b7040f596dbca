"""An areal scene: a rigid surface, a solid, a speed, and a load or a penetration.

:class:`ArealProblem` is the 2D counterpart of :class:`~viscocontact.problem.ContactProblem`,
in the same dimensionless groups (thesis eq. 4.17) with the amplitude ``Λ̃`` the highest point of
the surface on the grid: pressures in units of ``E0 q0 Λ/(2(1-ν²))``, heights, gaps and the
penetration ``Δ̃`` in units of ``Λ`` (``Δ̃ = 0``: the highest point touches).
"""
from __future__ import annotations

from typing import Any

import attrs
import numpy as np

from .._validation import in_range, positive
from ..errors import ValidationError
from ..kernels.half_plane import HalfPlane
from .kernels import ArealKernel
from .surfaces.base import Surface


def _heights_field(value):
    if isinstance(value, Surface):
        return value
    try:
        a = np.array(value, dtype=float, copy=True)
    except (TypeError, ValueError):
        raise ValidationError("ArealProblem.surface", type(value).__name__,
                              "a Surface or a 2D array of q0·h") from None
    if a.ndim != 2 or a.shape[0] % 2 or a.shape[1] % 2 or min(a.shape) < 4:
        raise ValidationError("ArealProblem.surface", f"array of shape {a.shape}",
                              "a Surface or a 2D array of q0·h with even sides >= 4")
    if not np.all(np.isfinite(a)):
        raise ValidationError("ArealProblem.surface", "array with non-finite heights",
                              "finite heights")
    a -= a.mean()
    a.setflags(write=False)
    return a


@attrs.frozen(kw_only=True, eq=False)
class ArealProblem:
    """A rigid periodic surface sliding in steady state over a viscoelastic solid.

    Parameters
    ----------
    surface : Surface or ndarray
        A :class:`~viscocontact.areal.surfaces.base.Surface`, or the heights ``q0·h`` sampled on
        the cell as an array of shape ``(ny, nx)`` (even sides; its mean is removed): then the
        grid of the solve is that array's.
    rheology : Rheology
        The solid's material (any registered rheology).
    kernel : GreenKernel
        Geometry: :class:`~viscocontact.kernels.HalfPlane` (the half-space), a confined or free
        layer (its ``thickness`` is ``q0·d``).
    zeta : float
        ``ζ = q0 V τ`` (>= 0).
    mean_pressure, penetration : float
        Exactly one: ``p̃∞`` (load control) or ``Δ̃`` (penetration control).
    direction : float
        Sliding direction, radians from the ``x̃`` axis, in ``[-π, π]``.
    aspect : float
        ``L_y/L_x`` of an array's cell (a Surface has its own; default 1).
    adhesion : AdhesionModel or None
        A traction law applied cell by cell (:meth:`AdhesionModel.cohesive_law`:
        :class:`~viscocontact.adhesion.MaugisDugdale`; :meth:`AdhesionModel.traction`:
        :class:`~viscocontact.adhesion.LennardJones`); None: adhesionless.
    """

    surface: Any = attrs.field(converter=_heights_field)
    rheology: Any
    kernel: Any = attrs.field(factory=HalfPlane)
    zeta: float = attrs.field(default=0.0, validator=in_range(0.0))
    mean_pressure: float | None = attrs.field(
        default=None, validator=attrs.validators.optional(in_range()))
    penetration: float | None = attrs.field(
        default=None, validator=attrs.validators.optional(in_range()))
    direction: float = attrs.field(default=0.0, validator=in_range(-np.pi, np.pi))
    aspect: float = attrs.field(default=1.0, validator=positive)
    adhesion: Any = None

    def __attrs_post_init__(self):
        if self.adhesion is not None and not hasattr(self.adhesion, "cohesive_law"):
            raise ValidationError("ArealProblem.adhesion", self.adhesion,
                                  "None or an AdhesionModel with a cohesive law")
        if (self.mean_pressure is None) == (self.penetration is None):
            raise ValidationError("ArealProblem.mean_pressure", self.mean_pressure,
                                  "exactly one of mean_pressure and penetration")
        if isinstance(self.surface, Surface) and self.aspect != 1.0 \
                and self.aspect != self.surface.aspect:
            raise ValidationError("ArealProblem.aspect", self.aspect,
                                  f"the surface's own aspect {self.surface.aspect} (or 1)")

    @property
    def cell_aspect(self) -> float:
        """``L_y/L_x`` of the cell."""
        return float(self.surface.aspect if isinstance(self.surface, Surface) else self.aspect)

    @property
    def native_points(self) -> tuple[int, int] | None:
        """``(nx, ny)`` of an array surface, None for a :class:`Surface` (any grid)."""
        if isinstance(self.surface, Surface):
            return None
        ny, nx = self.surface.shape
        return int(nx), int(ny)

    def heights(self, nx: int, ny: int) -> np.ndarray:
        """``q0·h`` on the ``(ny, nx)`` grid of the cell (an array surface: its own grid)."""
        if isinstance(self.surface, Surface):
            h = np.asarray(self.surface.heights(nx, ny), dtype=float)
            if h.shape != (ny, nx):
                raise ValidationError(f"{type(self.surface).__name__}.heights", h.shape,
                                      f"an array of shape {(ny, nx)}")
            return h - h.mean()
        if self.native_points != (nx, ny):
            raise ValidationError("grid", (nx, ny), f"the array's own grid {self.native_points}")
        return np.asarray(self.surface)

    def areal_kernel(self) -> ArealKernel:
        """The prepared kernel (rheology, ``ζ``, geometry, direction, aspect)."""
        return ArealKernel.prepare(self.kernel, self.rheology, self.zeta,
                                   direction=self.direction, aspect=self.cell_aspect)
