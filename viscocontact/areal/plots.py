"""Images of an areal solution: the contact map and the pressure (matplotlib, imported only
when plotting)."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..plots import _figure, _save


def plot_contact(result, path, *, title: str | None = None) -> Path:
    """Two panels of a solve with ``fields=True``: the contact map (contact cells over the
    heights' shading, with the sliding direction) and the pressure field, on the cell
    ``[0, 2π) × [0, 2π·aspect)``; returns the path written.

    Raises
    ------
    ValueError
        For a result without fields.
    """
    fields = getattr(result, "fields", None)
    if not fields or "pressure" not in fields or np.ndim(fields["pressure"]) != 2:
        raise ValueError("an areal result solved with fields=True is needed")
    x, y = fields["x"], fields["y"]
    extent = (0.0, float(x[0, -1] + x[0, 1]), 0.0, float(y[-1, 0] + y[1, 0]))
    p = np.asarray(fields["pressure"])
    fig = _figure(figsize=(10.0, 4.6))
    left, right = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    left.imshow(fields["heights"], origin="lower", extent=extent, cmap="Greys", alpha=0.6)
    left.imshow(np.ma.masked_where(p <= 0, np.ones_like(p)), origin="lower", extent=extent,
                cmap="autumn", vmin=0, vmax=1)
    left.annotate("", xy=(0.9, 0.06), xytext=(0.7, 0.06), xycoords="axes fraction",
                  arrowprops={"arrowstyle": "->"})
    left.set_title(f"contact: {result.extras.get('area_fraction', np.nan):.3g} of the area, "
                   f"{result.n_contacts} patches")
    image = right.imshow(p, origin="lower", extent=extent, cmap="viridis")
    fig.colorbar(image, ax=right, label="p̃")
    right.set_title(f"pressure, p̃∞ = {result.mean_pressure:.3g}, μ = {result.friction:.3g}")
    for ax in (left, right):
        ax.set_xlabel("x̃ (sliding →)")
        ax.set_ylabel("ỹ")
    if title:
        fig.suptitle(title)
    return _save(fig, path)
