"""Figures of a study file (matplotlib, Agg backend; imported only when plotting).

* a sweep: contact area Ã and reduced friction μ/√m2 against ζ (thesis Figs. 4.7, 4.10),
  adhesive solid, adhesionless dashed, one colour per load; with realizations the mean and its
  confidence band;
* a cycle: p̃∞ and Ã against Δ̃ along each approach-retraction path (Fig. 4.8), approach solid,
  retraction dashed, detachment marked ×; with several ζ also the toughness T̃ against ζ (Fig. 4.9).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

ZETA_LABEL = "ζ = q0 V τ"


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def plot_study(study, out=None, prefix: str | None = None) -> list[Path]:
    """Draw a study file (a path or a loaded :class:`~viscocontact.studies.StudyData`).

    Parameters
    ----------
    study : str, Path or StudyData
    out : folder, optional
        Where the PNG files go (default: next to the study file).
    prefix : str, optional
        File name prefix (default: the study file's stem), e.g. ``study`` gives
        ``study_area.png`` and ``study_friction.png``.

    Returns
    -------
    list of Path
        The files written.
    """
    from .studies import load_study

    data = study if hasattr(study, "points") else load_study(study)
    out = Path(out) if out is not None else data.path.parent
    out.mkdir(parents=True, exist_ok=True)
    prefix = prefix or data.path.stem
    if data.kind == "sweep":
        return plot_sweep(data, out, prefix)
    return plot_cycle(data, out, prefix)


def _xscale(ax, zetas) -> None:
    positive = np.asarray(zetas)[np.asarray(zetas) > 0]
    if positive.size and positive.size == len(zetas):
        ax.set_xscale("log")
    elif positive.size:
        ax.set_xscale("symlog", linthresh=float(positive.min()))


def plot_sweep(data, out: Path, prefix: str) -> list[Path]:
    """``<prefix>_area.png`` and ``<prefix>_friction.png`` of a sweep."""
    plt = _pyplot()
    axes = data.axes()
    zetas = np.asarray(axes["zeta"])
    control = "p̃∞" if data.study.control == "mean_pressure" else "Δ̃"
    realizations = len(axes["seed"]) > 1
    files = []
    for key, ylabel, name in (("area", "contact area Ã", "area"),
                              ("reduced_friction", "reduced friction μ/√m2", "friction")):
        band = data.band(key)
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
        for iv, variant in enumerate(axes["variant"]):
            style = "-o" if variant == "adhesive" else "--s"
            for il, load in enumerate(axes["load"]):
                color = colors[il % len(colors)]
                label = (f"{variant}, {control} = {load:g}" if len(axes["load"]) > 1
                         else variant)
                ax.plot(zetas, band.mean[iv, il], style, ms=3, color=color, label=label)
                if realizations:
                    ax.fill_between(zetas, band.lower[iv, il], band.upper[iv, il], color=color,
                                    alpha=0.2, lw=0)
        _xscale(ax, zetas)
        ax.set_xlabel(ZETA_LABEL)
        ax.set_ylabel(ylabel)
        if realizations:
            ax.set_title(f"mean of {len(axes['seed'])} realizations, "
                         f"{100 * band.confidence:.0f}% confidence band")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        path = out / f"{prefix}_{name}.png"
        fig.savefig(path, dpi=120)
        plt.close(fig)
        files.append(path)
    return files


def plot_cycle(data, out: Path, prefix: str) -> list[Path]:
    """``<prefix>_cycle.png`` (p̃∞-Δ̃ and Ã-Δ̃ loops), plus ``<prefix>_toughness.png`` (T̃ against
    ζ) when the study has several ζ."""
    from .studies.realizations import confidence_band

    plt = _pyplot()
    cycles = data.cycles()
    fig, (ax_p, ax_a) = plt.subplots(1, 2, figsize=(10, 4.2))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, cyc in enumerate(cycles):
        pts = cyc["points"]
        if not len(pts["chain"]):
            continue
        color = colors[i % len(colors)]
        shown = pts["converged"]
        label = f"ζ = {cyc['zeta']:g}, γ̃ = {cyc['gamma']:g}"
        if cyc["seed"] >= 0:
            label += f", seed {cyc['seed']}"
        approach = np.flatnonzero(shown & (pts["phase"] == "approach"))
        approach = approach[np.argsort(pts["target"][approach], kind="stable")]
        retract = np.flatnonzero(shown & (pts["phase"] == "retract"))
        retract = np.r_[approach[-1:], retract[np.argsort(-pts["target"][retract],
                                                           kind="stable")]].astype(int)
        for rows, style in ((approach, "-o"), (retract, "--s")):
            x = pts["target"][rows]
            ax_p.plot(x, pts["mean_pressure"][rows], style, ms=3, color=color,
                      label=label if style == "-o" else None)
            ax_a.plot(x, pts["area"][rows], style, ms=3, color=color)
        m = cyc["metrics"]
        if m is not None and m.detached:
            ax_p.plot([m.detachment_penetration], [_pressure_at(pts, m.detachment_penetration)],
                      "x", color=color, ms=8)
    for ax, ylabel in ((ax_p, "mean pressure p̃∞"), (ax_a, "contact area Ã")):
        ax.set_xlabel("penetration Δ̃")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
    ax_p.axhline(0.0, color="k", lw=0.5)
    ax_p.legend(fontsize=8)
    fig.suptitle("approach (solid) and retraction (dashed)", fontsize=10)
    fig.tight_layout()
    files = [out / f"{prefix}_cycle.png"]
    fig.savefig(files[0], dpi=120)
    plt.close(fig)

    metrics = data.metrics()
    if len(metrics["zeta"]) > 1:
        band = confidence_band(metrics["toughness"], axis=2)
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        for ig, gamma in enumerate(metrics["gamma"]):
            label = f"γ̃ = {gamma:g}" if np.isfinite(gamma) else None
            ax.plot(metrics["zeta"], band.mean[:, ig], "-o", ms=3, label=label)
            if metrics["toughness"].shape[2] > 1:
                ax.fill_between(metrics["zeta"], band.lower[:, ig], band.upper[:, ig], alpha=0.2,
                                lw=0)
        _xscale(ax, metrics["zeta"])
        ax.set_xlabel(ZETA_LABEL)
        ax.set_ylabel("contact toughness T̃ (eq. 4.57)")
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=8)
        fig.tight_layout()
        files.append(out / f"{prefix}_toughness.png")
        fig.savefig(files[-1], dpi=120)
        plt.close(fig)
    return files


def _pressure_at(points, penetration: float) -> float:
    sel = (points["target"] == penetration) & points["converged"]
    return float(points["mean_pressure"][sel][0]) if sel.any() else np.nan
