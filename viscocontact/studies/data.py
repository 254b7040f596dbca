"""What a study file holds, as arrays: :func:`load_study` and :class:`StudyData`.

Besides its own arrays (:meth:`StudyData.table`, :meth:`StudyData.band`,
:meth:`StudyData.metrics`), a study converts to the tools of the Python data stack
(``pip install 'viscocontact[xarray]'``; both are imported only when called):

* :meth:`StudyData.to_dataframe` — a pandas DataFrame, one row per stored point, every column;
* :meth:`StudyData.to_xarray` — an xarray Dataset on the study's grid: dimensions
  ``(variant, load, seed, zeta)`` for a sweep, ``(zeta, gamma, seed, step)`` for cycles, where
  ``step`` is the position along a cycle's approach-retraction path (cycles differ in length:
  the retraction ends at detachment; missing steps are padded) and ``phase`` and ``target``
  (Δ̃) say what each step is. The cycle metrics (:class:`~viscocontact.studies.CycleMetrics`)
  are variables on ``(zeta, gamma, seed)``.

In the Dataset a point not computed has ``row = -1``, NaN in the float variables (the counts
``n_contacts``, ``iterations`` and ``function_evaluations`` are floats for this reason), False
in the booleans and ``""`` in the strings. Points that did not converge keep their values, as
in the file: ``ds.area.where(ds.converged)`` masks them (as :meth:`StudyData.table` does). The
scene (TOML), the study parameters (JSON), the viscocontact version that wrote the file and the
time it was created are attributes, so ``ds.to_netcdf(...)`` keeps them. The ``edges`` of a
point, of variable length, are left out (``data.points["edges"][row]``).
"""
from __future__ import annotations

import importlib
import json
import math
from pathlib import Path
from typing import Any

import attrs
import numpy as np

from ..errors import ValidationError
from . import storage
from .point import COLUMNS
from .realizations import Band, confidence_band

#: Result columns that :meth:`StudyData.table` arranges on the study's grid.
QUANTITIES = ("area", "mean_pressure", "penetration", "friction", "reduced_friction",
              "n_contacts", "residual", "min_gap")


#: Integer columns that count something: floats in :meth:`StudyData.to_xarray` (NaN: no point).
COUNTS = ("n_contacts", "iterations", "function_evaluations")

#: What the variables of :meth:`StudyData.to_xarray` are (their ``description`` attribute).
DESCRIPTIONS = {
    "row": "row of the point in the study file (-1: not computed)",
    "area": "contact length Ã = q0·(length in contact) per period (eq. 4.17; 2π in full contact)",
    "mean_pressure": "mean pressure p̃∞ (eq. 4.17)",
    "penetration": "penetration Δ̃ = Δ/Λ",
    "friction": "friction coefficient μ",
    "reduced_friction": "μ/√m2",
    "target": "the imposed value of the controlled load (p̃∞ or Δ̃)",
    "gamma": "γ̃, dimensionless work of adhesion (0: adhesionless)",
    "seconds": "wall time of the point (s)",
    "certified": "the point agrees with its history run with a tenth of the tolerance "
                 "(Sweep certify; False: not certified or not run)",
    "certified_area": "Ã of the certifying run (a tenth of the tolerance; NaN: not run)",
    "certified_friction": "μ of the certifying run (a tenth of the tolerance; NaN: not run)",
}


#: CF attributes (``long_name``, ``units``) of the variables and coordinates of
#: :meth:`StudyData.to_xarray`, which xarray's plots take as axis labels. Units "1":
#: dimensionless (the groups of eq. 4.17).
CF_ATTRS = {
    "area": ("contact length Ã = q0 a (2π: full contact)", "1"),
    "mean_pressure": ("mean pressure p̃∞", "1"),
    "penetration": ("penetration Δ̃ = Δ/Λ", "1"),
    "friction": ("friction coefficient μ", "1"),
    "reduced_friction": ("reduced friction μ/√m2", "1"),
    "n_contacts": ("number of contacts per period", "1"),
    "min_gap": ("smallest gap outside the contacts g̃", "1"),
    "target": ("imposed load (p̃∞ or Δ̃)", "1"),
    "seconds": ("wall time of the point", "s"),
    "zeta": ("ζ = q0 V τ", "1"),
    "load": ("imposed load (p̃∞ or Δ̃)", "1"),
    "gamma": ("γ̃, work of adhesion (0: adhesionless)", "1"),
    "seed": ("profile seed (-1: the scene's profile)", "1"),
    "step": ("step along the cycle", "1"),
    "residual": ("largest edge residual at the end", "1"),
    "iterations": ("solver iterations", "1"),
    "function_evaluations": ("residual evaluations", "1"),
    "edge_perturbation": ("edge advance q0 δX of the energy balance", "1"),
    "error_estimate": ("estimated relative discretisation error of Ã and μ", "1"),
    "certified_area": ("Ã of the certifying run (2π: full contact)", "1"),
    "certified_friction": ("μ of the certifying run", "1"),
    # areal scenes (NaN or -1 for a profile)
    "area_fraction": ("contact area fraction A/A0", "1"),
    "mean_gap": ("mean gap over the cell g̃ (units of Λ)", "1"),
    "dissipated_power": ("dissipated power −<p ∂u/∂s> per unit area and sliding speed", "1"),
    "friction_dissipation": ("friction coefficient from the dissipated power", "1"),
    "patch_mean_area": ("mean contact patch area (q0² × area)", "1"),
    "patch_largest_area": ("largest contact patch area (q0² × area)", "1"),
    "patch_elongation": ("patch elongation √(λmax/λmin), area-weighted (1: round)", "1"),
    "patch_orientation": ("patch axis angle from the sliding direction, area-weighted", "rad"),
    "patch_alignment": ("patch alignment with the sliding direction (+1 along, −1 across)", "1"),
    "percolating": ("patches that wrap around the cell", "1"),
    "cells_per_zone": ("finest-grid cells per cohesive zone", "1"),
}


def _optional(module: str, what: str):
    """Import ``module`` for ``StudyData.what``, or say which extra provides it."""
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        raise ImportError(f"StudyData.{what}() needs {module}: pip install "
                          f"'viscocontact[xarray]'", name=module) from exc


def _short(values, fmt: str = "{:.3g}") -> str:
    values = list(values)
    if len(values) <= 4:
        return ", ".join(fmt.format(v) for v in values)
    return f"{len(values)} in [{fmt.format(min(values))}, {fmt.format(max(values))}]"


@attrs.frozen(kw_only=True, eq=False, repr=False)
class StudyData:
    """A loaded study file.

    Attributes
    ----------
    path : Path
    kind : str
        ``"sweep"`` or ``"cycle"``.
    scene_toml : str
        The base scene as TOML text (:attr:`scene` builds it).
    params : dict
        The study parameters.
    seeds : ndarray of int
    version : str
        viscocontact version that created the file.
    created : str
        ISO time of creation (UTC).
    complete : bool
        Whether every chain has ended (False for an interrupted study: resume it).
    points : dict of ndarray
        One array per column of :data:`~viscocontact.studies.point.COLUMNS`, one entry per
        finished point in the order they finished (``edges``: object array of flat arrays).
    """

    path: Path
    kind: str
    scene_toml: str
    params: dict
    seeds: np.ndarray
    version: str
    created: str
    complete: bool
    points: dict

    @property
    def scene(self):
        """The base :class:`~viscocontact.scene.Scene` (an
        :class:`~viscocontact.areal.scene.ArealScene` for a study of an areal scene)."""
        from ..read import read_scene

        return read_scene(self.scene_toml)

    @property
    def areal(self) -> bool:
        """Whether the study's scene is areal (a ``[surface]``)."""
        import tomllib

        return "surface" in tomllib.loads(self.scene_toml)

    @property
    def study(self):
        """The :class:`~viscocontact.studies.Sweep` or :class:`~viscocontact.studies.Cycle`."""
        return storage.study_from_header({"kind": self.kind, "scene": self.scene_toml,
                                          "params": self.params})

    def __len__(self) -> int:
        return len(self.points["chain"])

    def __repr__(self) -> str:
        n, converged = len(self), int(np.count_nonzero(self.points["converged"]))
        state = "complete" if self.complete else "interrupted, --resume continues it"
        p = self.params
        seeds = _short(p["seeds"], "{}") if p.get("seeds") else "none"
        if self.kind == "sweep":
            load = "p̃∞" if p["control"] == "mean_pressure" else "Δ̃"
            try:
                variants = ", ".join(self.study.variants)
            except Exception:  # a repr never fails: the variants stored so far
                variants = ", ".join(dict.fromkeys(self.points["variant"].tolist())) or "?"
            grid = (f"  variants {variants}; loads {load} {_short(p['loads'])}; seeds {seeds}; "
                    f"ζ {_short(p['zetas'])}")
        else:
            gammas = "the scene's" if p.get("gammas") is None else _short(p["gammas"])
            grid = (f"  ζ {_short(p['zetas'])}; γ̃ {gammas}; seeds {seeds}; Δ̃ {p['start']:.3g} "
                    f"to {p['max_penetration']:.3g} in steps of {p['step']:.3g}")
        return (f"<StudyData {self.kind} {str(self.path)!r}: {n} points, {converged} "
                f"converged ({state})\n{grid}\n  viscocontact {self.version}, created "
                f"{self.created}>")

    def fields(self, row: int) -> dict[str, np.ndarray] | None:
        """``x``, ``pressure``, ``displacement``, ``gap`` of point ``row`` (None if not stored)."""
        return storage.read_fields(self.path, row)

    def chain(self, index: int) -> dict[str, np.ndarray]:
        """The points of one chain, in step order."""
        rows = np.flatnonzero(self.points["chain"] == index)
        rows = rows[np.argsort(self.points["step"][rows], kind="stable")]
        return {k: v[rows] for k, v in self.points.items()} | {"row": rows}

    @property
    def failed(self) -> np.ndarray:
        """Rows of the points that did not converge (their ``message`` says why)."""
        return np.flatnonzero(~self.points["converged"])

    # ---- sweeps -------------------------------------------------------------------------------
    def _require(self, kind: str, what: str) -> None:
        if self.kind != kind:
            raise ValidationError(what, self.kind, f"a {kind} study file ({self.path} holds a "
                                                   f"{self.kind})")

    def axes(self) -> dict[str, tuple]:
        """The grid of a sweep: ``variant``, ``load``, ``seed`` and ``zeta`` values."""
        self._require("sweep", "StudyData.axes")
        study = self.study
        return {"variant": study.variants, "load": study.loads,
                "seed": tuple(study.seeds) if study.seeds else (-1,), "zeta": study.zetas}

    def table(self, name: str, converged_only: bool = True) -> np.ndarray:
        """A sweep's column ``name`` on the grid ``(variant, load, seed, zeta)`` of :meth:`axes`.

        Points not (yet) computed are NaN, and so are those that did not converge unless
        ``converged_only`` is False.
        """
        self._require("sweep", "StudyData.table")
        if name not in self.points or name in ("edges",):
            raise ValidationError("name", name, f"a numeric column, one of {list(QUANTITIES)}")
        rows = self.rows(converged_only)
        out = np.full(rows.shape, np.nan)
        out[rows >= 0] = np.asarray(self.points[name], dtype=float)[rows[rows >= 0]]
        return out

    def rows(self, converged_only: bool = True) -> np.ndarray:
        """The row of each point of a sweep on the grid ``(variant, load, seed, zeta)`` of
        :meth:`axes` (-1: not computed, or not converged unless ``converged_only`` is False)."""
        self._require("sweep", "StudyData.rows")
        ax = self.axes()
        out = np.full(tuple(len(v) for v in ax.values()), -1, dtype=np.int64)
        index = {key: {v: i for i, v in enumerate(values)} for key, values in ax.items()}
        p = self.points
        for row in range(len(self)):
            if converged_only and not p["converged"][row]:
                continue
            try:
                at = tuple(index[key][p[key][row].item()] for key in ax)
            except KeyError:
                continue
            out[at] = row
        return out

    def band(self, name: str, confidence: float = 0.95) -> Band:
        """Mean and confidence band of a sweep's ``name`` over the realizations (seed axis):
        arrays of shape ``(variant, load, zeta)``."""
        return confidence_band(self.table(name), axis=2, confidence=confidence)

    # ---- cycles -------------------------------------------------------------------------------
    def cycles(self) -> list[dict[str, Any]]:
        """One entry per cycle: its labels (``zeta``, ``gamma``, ``seed``, ``variant``), its
        points (:meth:`chain`) and its :class:`~viscocontact.studies.cycle.CycleMetrics`."""
        from .cycle import cycle_metrics

        self._require("cycle", "StudyData.cycles")
        out = []
        for chain in self.study.chains():
            pts = self.chain(chain.index)
            metrics = cycle_metrics(pts) if len(pts["chain"]) else None
            out.append({"chain": chain.index, "zeta": chain.zetas[0], **dict(chain.labels),
                        "points": pts, "metrics": metrics})
        return out

    def metrics(self) -> dict[str, np.ndarray]:
        """Cycle metrics on the grid ``(zeta, gamma, seed)`` (NaN for cycles not run), plus the
        axes ``zeta``, ``gamma``, ``seed``."""
        from .cycle import CycleMetrics

        study = self.study
        zetas = study.zetas
        gammas = study.gammas if study.gammas is not None else (math.nan,)
        seeds = tuple(study.seeds) if study.seeds else (-1,)
        shape = (len(zetas), len(gammas), len(seeds))
        names = [f.name for f in attrs.fields(CycleMetrics)]
        out = {n: np.full(shape, np.nan) for n in names}
        for i, cyc in enumerate(self.cycles()):
            iz, rest = divmod(i, len(gammas) * len(seeds))
            ig, iseed = divmod(rest, len(seeds))
            if cyc["metrics"] is not None:
                for n in names:
                    out[n][iz, ig, iseed] = float(getattr(cyc["metrics"], n))
        return out | {"zeta": np.asarray(zetas), "gamma": np.asarray(gammas),
                      "seed": np.asarray(seeds)}


    # ---- the Python data stack ----------------------------------------------------------------
    def physical(self) -> dict[str, np.ndarray]:
        """The points in SI units, by row: ``contact_length`` (m), ``contact_fraction`` (1),
        ``penetration`` (m), ``mean_pressure`` and ``tangential_stress`` (Pa), ``friction``
        (1), from the scene's ``[physical]`` table, each point with its own chain's profile (a
        seed changes the profile's amplitude Λ, the scale of Δ̃ and p̃∞); what
        :meth:`ContactResult.physical <viscocontact.result.ContactResult.physical>` gives for
        one result. Raises :class:`~viscocontact.errors.ValidationError` naming the missing
        ``physical`` key (or the areal scene, whose results are not converted)."""
        from types import SimpleNamespace

        from ..errors import ValidationError
        from ..scene import Scene
        from ..units import physical_result

        if self.areal:
            raise ValidationError("scene", "an areal scene",
                                  "a profile's scene: SI results of areal studies are not given")
        scenes = {c.index: Scene.from_dict(c.scene) for c in self.study.chains()}
        keys = ("contact_length", "contact_fraction", "penetration", "mean_pressure",
                "tangential_stress", "friction")
        out = {k: np.full(len(self), np.nan) for k in keys}
        p = self.points
        for row in range(len(self)):
            point = SimpleNamespace(area=float(p["area"][row]), edges=(),
                                    penetration=float(p["penetration"][row]),
                                    mean_pressure=float(p["mean_pressure"][row]),
                                    friction=float(p["friction"][row]))
            si = physical_result(point, scenes[int(p["chain"][row])])
            for k in keys:
                out[k][row] = getattr(si, k)
        return out

    def to_dataframe(self):
        """The stored points as a pandas DataFrame: one row per point (index ``row``, the order
        in which they finished), one column per :data:`~viscocontact.studies.COLUMNS` entry
        (``edges``: arrays). ``df.attrs`` holds the scene, the parameters and the version.

        Raises ImportError naming the ``xarray`` extra when pandas is not installed.
        """
        pd = _optional("pandas", "to_dataframe")
        frame = pd.DataFrame({k: self.points[k] for k in COLUMNS},
                             index=pd.RangeIndex(len(self), name="row"))
        frame.attrs.update(self._attrs())
        return frame

    def to_xarray(self):
        """The study as an xarray Dataset on its grid (see the module docstring).

        Raises ImportError naming the ``xarray`` extra when xarray is not installed.
        """
        xr = _optional("xarray", "to_xarray")
        study = self.study
        chains = study.chains()
        if self.kind == "sweep":
            dims = ("variant", "load", "seed", "zeta")
            coords = {"variant": list(study.variants), "load": list(study.loads),
                      "seed": list(study.seeds or (-1,)), "zeta": list(study.zetas)}
            where = [(*at[:3], at[3] + step) for at, step in self._steps(study.grid())]
            if any(iz >= len(study.zetas) for *_, iz in where):
                raise storage.StudyFileError(f"{self.path} is damaged: its points name ζ steps "
                                             "beyond the study's ζ")
            skip = set(dims) | {"control", "phase"}
        else:
            dims = ("zeta", "gamma", "seed", "step")
            grid = study.grid()
            gammas = {at[1]: c.labels["gamma"] for at, c in zip(grid, chains)}
            steps = int(self.points["step"].max()) + 1 if len(self) else 0
            coords = {"zeta": list(study.zetas), "gamma": [gammas[i] for i in sorted(gammas)],
                      "seed": list(study.seeds or (-1,)), "step": np.arange(steps)}
            where = [(*at, step) for at, step in self._steps(grid)]
            skip = set(dims) | {"control", "load", "variant"}
        shape = tuple(len(coords[d]) for d in dims)
        index = tuple(np.array(i, dtype=np.intp).reshape(-1) for i in zip(*where)) if where \
            else tuple(np.zeros(0, np.intp) for _ in dims)
        variables = {"row": (dims, _on_grid(np.arange(len(self)), index, shape, -1))}
        for column, kind in COLUMNS.items():
            if column in skip or kind == "edges":
                continue
            values = self.points[column]
            fill = {"float": np.nan, "int": -1, "bool": False, "str": ""}[kind]
            if column in COUNTS:
                values, fill = values.astype(float), np.nan
            variables[column] = (dims, _on_grid(values, index, shape, fill))
        if self.kind == "cycle":
            variables.update(_metrics_on(self.cycles(), grid, shape[:3], dims[:3]))
            by_gamma = {at[1]: c.labels["variant"] for at, c in zip(grid, chains)}
            coords["variant"] = ("gamma", [by_gamma[i] for i in sorted(by_gamma)])
        data = xr.Dataset(variables, coords=coords, attrs=self._attrs())
        for name, text in DESCRIPTIONS.items():
            if name in data:
                data[name].attrs["description"] = text
        for name, (long_name, units) in CF_ATTRS.items():
            if name in data.variables:
                data[name].attrs.update(long_name=long_name, units=units)
        return data

    def _steps(self, grid):
        """``(grid position of the point's chain, step)`` of every stored row."""
        chain, step = self.points["chain"], self.points["step"]
        if len(self) and not (0 <= chain.min() and chain.max() < len(grid) and step.min() >= 0):
            raise storage.StudyFileError(f"{self.path} is damaged: its points name chains or "
                                         "steps that its study does not have")
        return [(grid[int(c)], int(k)) for c, k in zip(chain, step)]

    def _attrs(self) -> dict:
        """Attributes that survive netCDF (strings and numbers)."""
        out = {"kind": self.kind, "scene": self.scene_toml, "study": json.dumps(self.params),
               "viscocontact_version": self.version, "created": self.created,
               "complete": int(self.complete), "source": str(self.path)}
        if self.kind == "sweep":
            out["control"] = self.params["control"]
        return out


def _metrics_on(cycles: list, grid, shape: tuple, dims) -> dict:
    """The cycles' metrics (:class:`~.cycle.CycleMetrics`) at their ``grid`` positions on
    arrays of ``shape``, as xarray ``(dims, values)`` pairs."""
    from .cycle import CycleMetrics

    names = [f.name for f in attrs.fields(CycleMetrics)]
    out = {n: np.full(shape, False if n == "detached" else np.nan) for n in names}
    for at, cyc in zip(grid, cycles):
        if cyc["metrics"] is not None:
            for n in names:
                out[n][at] = getattr(cyc["metrics"], n)
    return {n: (dims, v) for n, v in out.items()}


def _on_grid(values: np.ndarray, index: tuple, shape: tuple, fill) -> np.ndarray:
    """``values`` (one per stored row) placed at ``index`` on an array of ``shape``."""
    values = np.asarray(values)
    dtype = object if values.dtype.kind == "U" else values.dtype
    out = np.full(shape, fill, dtype=dtype)
    out[index] = values
    return out.astype(str) if dtype is object else out


def load_study(path) -> StudyData:
    """Read a study file.

    Raises
    ------
    FileNotFoundError
        No such file.
    StudyFileError
        Not HDF5, damaged, or an HDF5 file that is not a viscocontact study.
    """
    path = Path(path)
    header = storage.read_header(path)
    points = storage.read_points(path)
    return StudyData(path=path, kind=header["kind"], scene_toml=header["scene"],
                     params=header["params"], seeds=header["seeds"], version=header["version"],
                     created=header["created"], complete=header["complete"], points=points)
