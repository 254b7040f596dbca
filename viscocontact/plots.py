"""Figures of a study file (matplotlib, imported only when plotting).

* a sweep: contact area Ã and reduced friction μ/√m2 against ζ (thesis Figs. 4.7, 4.10),
  adhesive solid, adhesionless dashed, one colour per load; with realizations the mean and its
  confidence band; points reached through a jump, the speed ramp's events and points that failed
  their certification are marked (:mod:`~viscocontact.plot_marks`);
* a cycle: p̃∞ and Ã against Δ̃ along each approach-retraction path (Fig. 4.8), approach solid,
  retraction dashed, detachment marked ×; with several ζ also the toughness T̃ against ζ (Fig. 4.9).

Layouts of the thesis's figures for the ``examples/fig_4_*.py`` scripts: :func:`plot_panels`
(sweep panels side by side, several studies per panel, e.g. a δX family; Figs. 4.7, 4.10),
:func:`plot_cycles_panels` (Fig. 4.8), :func:`plot_toughness` (Fig. 4.9) and
:func:`plot_solution_fields` (pressure and gap of single solutions).
"""
from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

import numpy as np

from .plot_marks import draw_marks

ZETA_LABEL = "ζ = q0 V τ"


def _figure(**options):
    """A :class:`matplotlib.figure.Figure` that is no part of pyplot's state: drawing it to a
    file neither selects nor switches the caller's backend, nor leaves a figure open."""
    from matplotlib.figure import Figure

    return Figure(**options)


class _Figures:
    """The two calls of :mod:`matplotlib.pyplot` that report generators make, on figures of
    :func:`_figure`: no backend is selected or switched, and there is nothing to close."""

    @staticmethod
    def subplots(nrows: int = 1, ncols: int = 1, *, figsize=None, constrained_layout=False,
                 **options):
        fig = _figure(figsize=figsize, constrained_layout=constrained_layout)
        return fig, fig.subplots(nrows, ncols, **options)

    @staticmethod
    def close(fig) -> None:
        """Nothing to do: the figure is no part of pyplot's state."""

    @property
    def rcParams(self):
        import matplotlib

        return matplotlib.rcParams


#: ``plt``-like drawing for library code (the report generators).
pyplot_free = _Figures()


#: The y label of the contact length: Ã = q0·(length in contact), 2π when the contact is full.
AREA_LABEL = "contact length Ã (2π: full contact)"


def scene_label(scene) -> str:
    """A one-line description of a scene for a figure: ``β``, the load, ``Γ̃`` when adhesive."""
    from .groups import dimensionless_groups

    if hasattr(scene, "surface"):       # an areal scene
        from .areal.report import areal_groups

        g = areal_groups(scene)
        g["profile"] = f"{g['surface']} surface, {g['grid']}"
        g["Gamma"] = g["gamma"] / g["amplitude"]**2
    else:
        g = dimensionless_groups(scene)
    load = (f"p̃∞ = {g['mean_pressure']:.3g}" if "mean_pressure" in g
            else f"Δ̃ = {g['penetration']:.3g}")
    parts = [f"{g['profile']}", f"β = {g['beta']:.3g}", load]
    if g["gamma"] > 0:
        parts.append(f"Γ̃ = {g['Gamma']:.3g}")
    return ", ".join(parts)


def _study_title(data, extra: str = "") -> str:
    """The scene of a study file (its name, β, load, Γ̃), then ``extra``."""
    name = data.path.stem if getattr(data, "path", None) is not None else ""
    try:
        text = scene_label(data.scene)
    except Exception:       # a scene whose plugin is missing here: its file name is enough
        text = ""
    head = " — ".join(t for t in (name, text) if t)
    return "\n".join(t for t in (head, extra) if t)


def _colors() -> list:
    """The colours of matplotlib's property cycle (``rcParams``)."""
    import matplotlib

    return matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]


def _save(fig, path, dpi: int = 90) -> Path:
    """Lay out and write ``fig``; the path written."""
    fig.tight_layout()
    path = Path(path)
    fig.savefig(path, dpi=dpi)
    return path


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
    """``<prefix>_area.png`` and ``<prefix>_friction.png`` of a sweep (areal: A/A0 and μ)."""
    axes = data.axes()
    zetas = np.asarray(axes["zeta"])
    control = "p̃∞" if data.study.control == "mean_pressure" else "Δ̃"
    realizations = len(axes["seed"]) > 1
    files = []
    quantities = ((("area_fraction", "contact area A/A0", "area"),
                   ("friction", "friction coefficient μ", "friction")) if data.areal else
                  (("area", AREA_LABEL, "area"),
                   ("reduced_friction", "reduced friction μ/√m2", "friction")))
    for key, ylabel, name in quantities:
        band = data.band(key)
        fig = _figure(figsize=(6.4, 4.2))
        ax = fig.subplots()
        colors = _colors()
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
        draw_marks(ax, data, key, colors)
        _xscale(ax, zetas)
        ax.set_xlabel(ZETA_LABEL)
        ax.set_ylabel(ylabel)
        band_note = (f"mean of {len(axes['seed'])} realizations, "
                     f"{100 * band.confidence:.0f}% confidence band" if realizations else "")
        ax.set_title(_study_title(data, band_note), fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        files.append(_save(fig, out / f"{prefix}_{name}.png", dpi=120))
    return files


def plot_cycle(data, out: Path, prefix: str) -> list[Path]:
    """``<prefix>_cycle.png`` (p̃∞-Δ̃ and Ã-Δ̃ loops), plus ``<prefix>_toughness.png`` (T̃ against
    ζ) when the study has several ζ."""
    from .studies.realizations import confidence_band

    cycles = data.cycles()
    fig = _figure(figsize=(10, 4.2))
    ax_p, ax_a = fig.subplots(1, 2)
    colors = _colors()
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
    for ax, ylabel in ((ax_p, "mean pressure p̃∞"), (ax_a, AREA_LABEL)):
        ax.set_xlabel("penetration Δ̃")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
    ax_p.axhline(0.0, color="k", lw=0.5)
    ax_p.legend(fontsize=8)
    fig.suptitle(_study_title(data, "approach (solid) and retraction (dashed)"), fontsize=10)
    files = [_save(fig, out / f"{prefix}_cycle.png", dpi=120)]

    metrics = data.metrics()
    if len(metrics["zeta"]) > 1:
        band = confidence_band(metrics["toughness"], axis=2)
        fig = _figure(figsize=(6.4, 4.2))
        ax = fig.subplots()
        for ig, gamma in enumerate(metrics["gamma"]):
            legend = f"γ̃ = {gamma:g}" if np.isfinite(gamma) else None
            ax.plot(metrics["zeta"], band.mean[:, ig], "-o", ms=3, label=legend)
            if metrics["toughness"].shape[2] > 1:
                ax.fill_between(metrics["zeta"], band.lower[:, ig], band.upper[:, ig], alpha=0.2,
                                lw=0)
        _xscale(ax, metrics["zeta"])
        ax.set_xlabel(ZETA_LABEL)
        ax.set_ylabel("contact toughness T̃ (eq. 4.57)")
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=8)
        files.append(_save(fig, out / f"{prefix}_toughness.png", dpi=120))
    return files


def _pressure_at(points, penetration: float) -> float:
    sel = (points["target"] == penetration) & points["converged"]
    return float(points["mean_pressure"][sel][0]) if sel.any() else np.nan


# ---- thesis figure layouts (Figs. 4.7-4.10 and a single solution) -------------------------------
def draw_sweep(ax, data, quantity: str, *, label: str = "", colors=None, marker: str = "o",
               variants=None, marks: bool = True) -> None:
    """Draw one sweep's ``quantity`` against ζ on ``ax`` the thesis's way.

    Adhesive curves solid, adhesionless dashed, one colour per load (``colors[i]`` for the i-th
    load); with several realizations the mean and its confidence band. Failed points are gaps.

    Parameters
    ----------
    ax : matplotlib Axes
    data : StudyData
        A loaded sweep.
    quantity : str
        A column of :meth:`StudyData.table`, e.g. ``"area"`` or ``"reduced_friction"``.
    label : str
        Appended to each curve's legend entry (e.g. ``"δX = 1e-4"``).
    colors : sequence of colours, optional
        One per load (default: matplotlib's cycle).
    marker : str
    variants : sequence of str, optional
        Which of ``"adhesive"``/``"adhesionless"`` to draw (default: all in the file).
    marks : bool
        Mark how the points were reached (:func:`~viscocontact.plot_marks.draw_marks`: jumps,
        the speed ramp's events, failed certifications).
    """
    axes = data.axes()
    zetas = np.asarray(axes["zeta"])
    colors = colors or _colors()
    control = r"$\tilde p_\infty$" if data.study.control == "mean_pressure" else r"$\tilde\Delta$"
    band = data.band(quantity)
    several = len(axes["seed"]) > 1
    for iv, variant in enumerate(axes["variant"]):
        if variants is not None and variant not in variants:
            continue
        style = "-" if variant == "adhesive" else "--"
        for il, load in enumerate(axes["load"]):
            color = colors[il % len(colors)]
            text = f"{variant}, {control} = {load:g}"
            if label and variant == "adhesive":
                text += f", {label}"
            ax.plot(zetas, band.mean[iv, il], style, marker=marker, ms=3, color=color,
                    label=text, mfc="none" if variant != "adhesive" else color)
            if several:
                ax.fill_between(zetas, band.lower[iv, il], band.upper[iv, il], color=color,
                                alpha=0.15, lw=0)
    if marks:
        draw_marks(ax, data, quantity, colors, variants=variants)
    _xscale(ax, zetas)
    ax.set_xlabel(ZETA_LABEL)
    ax.grid(alpha=0.3)


def plot_panels(panels, path, *, title: str | None = None, width: float = 5.2,
                height: float = 4.0) -> Path:
    """A row of sweep panels in one PNG (the layout of thesis Figs. 4.7 and 4.10).

    Parameters
    ----------
    panels : sequence of dict
        One per panel: ``title``, ``quantity``, ``ylabel`` and ``curves``, a list of dicts with
        ``data`` (a loaded sweep) and optionally ``label``, ``colors``, ``marker``, ``variants``
        (the keywords of :func:`draw_sweep`).
    path : str or Path
        The PNG written.
    title : str, optional
        Figure title.

    Returns
    -------
    Path
    """
    fig = _figure(figsize=(width * len(panels), height))
    axs = fig.subplots(1, len(panels), squeeze=False)
    for ax, panel in zip(axs[0], panels):
        for curve in panel["curves"]:
            draw_sweep(ax, curve["data"], panel["quantity"],
                       **{k: v for k, v in curve.items() if k != "data"})
        ax.set_ylabel(panel["ylabel"])
        ax.set_title(panel.get("title", ""), fontsize=10)
        ax.legend(fontsize=6.5)
    if title:
        fig.suptitle(title, fontsize=10)
    return _save(fig, path)


def plot_cycles_panels(panels, path, *, title: str | None = None) -> Path:
    """Approach-retraction loops Ã against Δ̃ side by side (the layout of thesis Fig. 4.8).

    Parameters
    ----------
    panels : sequence of dict
        One per panel: ``title`` and ``curves``, a list of dicts with ``data`` (a loaded cycle
        study) and optionally ``zetas`` and ``gammas`` (draw only the cycles with these ζ, γ̃).
        Approach solid, retraction dashed, detachment marked ×.
    path : str or Path
    title : str, optional

    Returns
    -------
    Path
    """
    fig = _figure(figsize=(5.2 * len(panels), 4.0))
    axs = fig.subplots(1, len(panels), squeeze=False)
    for ax, panel in zip(axs[0], panels):
        i = 0
        for curve in panel["curves"]:
            for cyc in curve["data"].cycles():
                if "zetas" in curve and not np.isclose(curve["zetas"], cyc["zeta"]).any():
                    continue
                if "gammas" in curve and not np.isclose(curve["gammas"], cyc["gamma"],
                                                        rtol=1e-9, atol=0).any():
                    continue
                pts = cyc["points"]
                if not len(pts["chain"]) or not pts["converged"].any():
                    continue
                color = f"C{i % 10}"
                i += 1
                approach, retract = _branches(pts)
                label = f"ζ = {cyc['zeta']:g}, γ̃ = {cyc['gamma']:.3g}"
                ax.plot(pts["target"][approach], pts["area"][approach], "-o", ms=3, color=color,
                        label=label)
                ax.plot(pts["target"][retract], pts["area"][retract], "--s", ms=3, color=color,
                        mfc="none")
                m = cyc["metrics"]
                if m is not None and m.detached:
                    sel = (pts["converged"] & (pts["phase"] == "retract")
                           & (pts["target"] == m.detachment_penetration))
                    if sel.any():
                        ax.plot([m.detachment_penetration], [pts["area"][sel][0]], "x",
                                color=color, ms=8)
        ax.set_xlabel(r"penetration $\tilde\Delta$")
        ax.set_ylabel(r"contact area $\tilde A$")
        ax.set_title(panel.get("title", ""), fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    if title:
        fig.suptitle(title, fontsize=10)
    return _save(fig, path)


def _branches(pts):
    """Row indices of the converged approach (ascending Δ̃) and of the retraction points in
    contact (from the turning point, descending Δ̃) of one cycle."""
    shown = pts["converged"]
    approach = np.flatnonzero(shown & (pts["phase"] == "approach"))
    approach = approach[np.argsort(pts["target"][approach], kind="stable")]
    contact = (pts["n_contacts"] > 0) | pts["full_contact"]
    retract = np.flatnonzero(shown & contact & (pts["phase"] == "retract"))
    retract = retract[np.argsort(-pts["target"][retract], kind="stable")]
    return approach, np.r_[approach[-1:], retract].astype(int)


def plot_toughness(curves, path, *, title: str | None = None) -> Path:
    """Contact toughness T̃ (eq. 4.57) against ζ (the layout of thesis Fig. 4.9).

    Parameters
    ----------
    curves : sequence of dict
        ``data`` (a loaded cycle study with several ζ) and ``label``; each γ̃ of the study is one
        curve, the mean over its seeds with the confidence band when there are several.
    path : str or Path
    title : str, optional

    Returns
    -------
    Path
    """
    from .studies.realizations import confidence_band

    fig = _figure(figsize=(5.6, 4.0))
    ax = fig.subplots()
    for curve in curves:
        metrics = curve["data"].metrics()
        band = confidence_band(metrics["toughness"], axis=2)
        for ig, gamma in enumerate(metrics["gamma"]):
            if np.isfinite(gamma) and gamma == 0.0:
                continue
            label = curve.get("label", "") + (f" γ̃ = {gamma:.3g}" if np.isfinite(gamma) else "")
            ax.plot(metrics["zeta"], band.mean[:, ig], "-o", ms=3, label=label.strip())
            if metrics["toughness"].shape[2] > 1:
                ax.fill_between(metrics["zeta"], band.lower[:, ig], band.upper[:, ig], alpha=0.2,
                                lw=0)
        _xscale(ax, metrics["zeta"])
    values = np.concatenate([line.get_ydata() for line in ax.get_lines()] or [np.zeros(0)])
    values = values[np.isfinite(values)]
    if values.size and values.min() > 0 and values.max() > 100 * values.min():
        ax.set_yscale("log")                     # T̃ spans decades between ζ and profiles
    ax.set_xlabel(ZETA_LABEL)
    ax.set_ylabel("contact toughness T̃ (eq. 4.57)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    if title:
        ax.set_title(title, fontsize=10)
    return _save(fig, path)


def plot_solution_fields(solutions, path, *, title: str | None = None, scene=None) -> Path:
    """Pressure and gap of single solutions against x̃ (two stacked panels).

    Parameters
    ----------
    solutions : ContactResult, or sequence of ContactResult or dict
        Results solved with ``fields=True`` (labelled with their Ã, p̃∞ and ζ), or dicts with
        ``fields`` (a mapping with ``x``, ``pressure`` and ``gap`` arrays, as
        ``ContactResult.fields`` or ``StudyData.fields(row)``), ``label`` and optionally
        ``style`` (a matplotlib format string).
    path : str or Path
    title : str, optional
        Default: the scene's description (:func:`scene_label`) when ``scene`` is given.
    scene : Scene, optional
        The scene the solutions solve.

    Returns
    -------
    Path
    """
    from .result import ContactResult

    if isinstance(solutions, (ContactResult, Mapping)):
        solutions = [solutions]
    solutions = [_as_solution(s, i) if isinstance(s, ContactResult) else s
                 for i, s in enumerate(solutions)]
    if title is None and scene is not None:
        title = scene_label(scene)
    fig = _figure(figsize=(7.0, 5.6))
    ax_p, ax_g = fig.subplots(2, 1, sharex=True)
    for sol in solutions:
        f = sol["fields"]
        style = sol.get("style", "-")
        ax_p.plot(f["x"], f["pressure"], style, lw=1.0, label=sol["label"])
        ax_g.plot(f["x"], f["gap"], style, lw=1.0, label=sol["label"])
    ax_p.set_ylabel("pressure p̃ (compressive > 0)")
    ax_g.set_ylabel("gap g̃")
    ax_g.set_xlabel("x̃ = q0 x (material moves towards −x)")
    for ax in (ax_p, ax_g):
        ax.grid(alpha=0.3)
        ax.axhline(0.0, color="k", lw=0.5)
    ax_p.legend(fontsize=7)
    if title:
        ax_p.set_title(title, fontsize=10)
    return _save(fig, path)


def _as_solution(result, index: int) -> dict:
    """The ``{"fields", "label"}`` of a :class:`~viscocontact.result.ContactResult`."""
    from .errors import ValidationError

    if result.fields is None:
        raise ValidationError(f"solutions[{index}]", result,
                              "a result solved with fields=True (vc.solve(scene, fields=True))")
    label = (f"Ã = {result.area:.4g} (2π: full), p̃∞ = {result.mean_pressure:.3g}, "
             f"ζ = {result.zeta:.3g}")
    return {"fields": result.fields, "label": label}
