"""What a study file holds, as arrays: :func:`load_study` and :class:`StudyData`."""
from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import attrs
import numpy as np

from ..errors import ValidationError
from . import storage
from .realizations import Band, confidence_band

#: Result columns that :meth:`StudyData.table` arranges on the study's grid.
QUANTITIES = ("area", "mean_pressure", "penetration", "friction", "reduced_friction",
              "n_contacts", "residual", "min_gap")


@attrs.frozen(kw_only=True, eq=False)
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
        """The base :class:`~viscocontact.scene.Scene`."""
        from ..scene import Scene

        return Scene.from_toml(self.scene_toml)

    @property
    def study(self):
        """The :class:`~viscocontact.studies.Sweep` or :class:`~viscocontact.studies.Cycle`."""
        return storage.study_from_header({"kind": self.kind, "scene": self.scene_toml,
                                          "params": self.params})

    def __len__(self) -> int:
        return len(self.points["chain"])

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
        ax = self.axes()
        out = np.full(tuple(len(v) for v in ax.values()), np.nan)
        index = {key: {v: i for i, v in enumerate(values)} for key, values in ax.items()}
        p = self.points
        for row in range(len(self)):
            if converged_only and not p["converged"][row]:
                continue
            try:
                at = tuple(index[key][p[key][row].item()] for key in ax)
            except KeyError:
                continue
            out[at] = float(p[name][row])
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
