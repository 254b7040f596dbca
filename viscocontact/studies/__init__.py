"""Studies: ζ-sweeps, approach-retraction cycles and realization averages, stored in HDF5.

=============================  ==================================================================
:class:`Sweep`                 area and friction against ζ (load or penetration control, adhesive
                               and adhesionless side by side, each point continued from its
                               neighbour)
:class:`Cycle`                 quasi-static approach-retraction cycles in penetration control:
                               hysteresis, pull-off, contact toughness T̃ (eq. 4.57)
:func:`run`                    compute a study into one HDF5 file, point by point, serially, in
                               ``workers`` processes or on a Dask cluster; ``resume=True``
                               continues an interrupted file
:func:`resume`                 continue the study a file holds
:func:`load_study`             the file as arrays (:class:`StudyData`: ``table``, ``band``,
                               ``cycles``, ``metrics``, ``fields``, ``to_xarray``,
                               ``to_dataframe``)
:func:`confidence_band`        mean and Student-t band over realizations
:func:`log_zetas`              log-spaced ζ
:func:`solve_point`            the unit of work, a pure function of (scene dict, spec, edges)
:class:`DaskScheduler`         where a Dask scheduler is (address, scheduler file or Dask's
                               configuration), connect timeout and retries
:class:`StudyFileError`        a foreign, damaged or mismatched study file
=============================  ==================================================================

See ``docs/studies.md``.
"""
from .base import Chain, Study, log_zetas
from .cycle import Cycle, CycleMetrics, cycle_metrics
from .data import StudyData, load_study
from .parallel import DaskScheduler
from .point import COLUMNS, PointSpec, solve_point
from .realizations import Band, confidence_band
from .runner import resume, run
from .storage import StudyFileError
from .sweep import Sweep

__all__ = ["Band", "COLUMNS", "Chain", "Cycle", "CycleMetrics", "DaskScheduler", "PointSpec",
           "Study", "StudyData", "StudyFileError", "Sweep", "confidence_band", "cycle_metrics",
           "load_study", "log_zetas", "resume", "run", "solve_point"]
