"""A 1D profile extruded along y: ``h(x̃, ỹ) = r(x̃)``."""
from __future__ import annotations

from collections.abc import Mapping

import attrs
import numpy as np

from ..._validation import positive
from ...errors import ValidationError
from ...profiles.base import Profile
from ...profiles.spectral import as_float
from .base import Surface
from .spectral import check_grid

__all__ = ["ExtrudedProfile"]


def _as_profile(value):
    """A :class:`Profile`, or a scene table ``{"kind": ..., **parameters}`` built into one."""
    if isinstance(value, Mapping):
        from ...scene import build_component

        return build_component("profile", value)
    return value


def _check_profile(inst, attribute, value):
    if not isinstance(value, Profile):
        raise ValidationError("ExtrudedProfile.profile", type(value).__name__,
                              "a viscocontact Profile (or its scene table with a 'kind')")


@attrs.frozen(kw_only=True)
class ExtrudedProfile(Surface):
    """Any 1D :class:`~viscocontact.profiles.base.Profile` extruded along y (ridges along y).

    Parameters
    ----------
    profile : Profile or mapping
        The profile ``q0·r(x̃)``, or its scene table (``{"kind": "sinusoid", "amplitude": 0.1}``).
    aspect : float
        Cell side ratio ``L_y/L_x > 0``; the heights do not depend on it.

    Notes
    -----
    Every row of :meth:`heights` is the profile sampled exactly as the 1D spectral method samples
    it (:func:`viscocontact.methods.spectral.grid.uniform_heights`: one inverse FFT for a
    spectral profile resolved by the grid, else :meth:`Profile.heights`), so a 2D computation on
    the extruded surface reproduces the 1D one on the same grid.

    Examples
    --------
    >>> from viscocontact.profiles import Sinusoid
    >>> s = ExtrudedProfile(profile=Sinusoid(amplitude=0.1), aspect=0.5)
    >>> h = s.heights(8, 4)
    >>> h.shape, float(h[3, 0])
    ((4, 8), 0.1)
    """

    profile: Profile = attrs.field(converter=_as_profile, validator=_check_profile)
    aspect: float = attrs.field(default=1.0, converter=as_float, validator=positive)

    def heights(self, nx: int, ny: int) -> np.ndarray:
        """``q0·r(x̃_i)`` in every row ``j``, shape ``(ny, nx)``."""
        from ...methods.spectral.grid import uniform_heights

        nx, ny = check_grid(nx, ny)
        row = np.asarray(uniform_heights(self.profile, 0.0, nx), dtype=float)
        return np.broadcast_to(row - row.mean(), (ny, nx)).copy()
