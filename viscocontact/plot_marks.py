"""The marks on a sweep's ζ-curves (:mod:`viscocontact.plots`): how its points were reached.

* a point reached through a jump (its events, the approach's ``path_events`` or the speed
  ramp's, hold a ``"jump"``): a wide open circle in the curve's colour;
* the speed ramp's located events (birth, loss, closure, opening, jump) at their own ζ, on the
  curve, one marker per kind;
* with ``certify``, a converged adhesive point that failed its certification: a red ring.

Each kind of mark has one legend entry. With realizations a mark stands on the mean curve
where any realization has it.
"""
from __future__ import annotations

import json

import numpy as np

#: Legend labels of the marks.
JUMP_LABEL = "reached through a jump"
UNCERTIFIED_LABEL = "not certified (a tenth of the tolerance differs)"
RAMP_LABEL = "speed ramp: {kind}"

#: Markers of the speed ramp's event kinds.
RAMP_MARKERS = {"birth": "^", "loss": "v", "closure": "s", "opening": "D", "jump": "X"}


def _events(text) -> list:
    try:
        events = json.loads(str(text) or "[]")
    except ValueError:          # a damaged record draws no events
        return []
    return [e for e in events if isinstance(e, dict)] if isinstance(events, list) else []


def _jumped(points, row: int) -> bool:
    return any(e.get("kind") == "jump" for e in _events(points["events"][row]))


def _uncertified(data, points, row: int) -> bool:
    from .studies.certify import failed

    record = {k: points[k][row] for k in ("variant", "converged", "certified")}
    return failed(record, data.params.get("certify", False))


def _ramp_events(points, rows) -> list[tuple[str, float]]:
    """``(kind, ζ)`` of the speed ramp's events recorded with ``rows``."""
    out = []
    for row in rows:
        if points["history"][row] != "speed-ramp":
            continue
        for e in _events(points["events"][row]):
            if "zeta" in e and np.isfinite(float(e["zeta"])):
                out.append((str(e.get("kind", "event")), float(e["zeta"])))
    return out


def _on_curve(zetas, values, at: float) -> float:
    """The curve's value at ``at`` (linear in log ζ between its finite points)."""
    zetas, values = np.asarray(zetas, float), np.asarray(values, float)
    ok = np.isfinite(values) & (zetas > 0)
    if not ok.any() or at <= 0:
        return np.nan
    return float(np.interp(np.log10(at), np.log10(zetas[ok]), values[ok]))


def draw_marks(ax, data, quantity: str, colors, *, variants=None) -> None:
    """Mark on ``ax`` the points of the sweep ``data`` drawn as ``quantity`` against ζ (the
    curves of :func:`~viscocontact.plots.plot_sweep` or
    :func:`~viscocontact.plots.draw_sweep`, one colour of ``colors`` per load)."""
    axes = data.axes()
    zetas = np.asarray(axes["zeta"], float)
    rows = data.rows()
    mean = data.band(quantity).mean
    points = data.points
    labelled: set = set()

    def once(label):
        if label in labelled:
            return None
        labelled.add(label)
        return label

    for iv, variant in enumerate(axes["variant"]):
        if variants is not None and variant not in variants:
            continue
        for il in range(len(axes["load"])):
            color = colors[il % len(colors)]
            chains = rows[iv, il]                         # (seed, zeta)
            y = mean[iv, il]
            for test, style, label in (
                    (lambda r: _jumped(points, r),
                     dict(ms=9, mfc="none", mec=color, mew=1.2), JUMP_LABEL),
                    (lambda r: _uncertified(data, points, r),
                     dict(ms=12, mfc="none", mec="red", mew=1.4), UNCERTIFIED_LABEL)):
                hit = np.array([any(r >= 0 and test(r) for r in chains[:, iz])
                                for iz in range(len(zetas))], dtype=bool)
                if hit.any():
                    ax.plot(zetas[hit], y[hit], "o", ls="none", label=once(label), **style)
            by_kind: dict = {}
            for kind, zeta in _ramp_events(points, chains[chains >= 0].ravel()):
                by_kind.setdefault(kind, []).append(zeta)
            for kind, at in sorted(by_kind.items()):
                ax.plot(at, [_on_curve(zetas, y, z) for z in at], RAMP_MARKERS.get(kind, "|"),
                        ls="none", ms=6, color=color, mfc="none", mew=1.2,
                        label=once(RAMP_LABEL.format(kind=kind)))
