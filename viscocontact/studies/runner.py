"""Running a study: chains scheduled on a backend, each finished point appended to the file."""
from __future__ import annotations

import sys
from pathlib import Path
from typing import TextIO

from . import guard, storage
from .base import Study
from .data import StudyData, load_study
from .parallel import backend as make_backend
from .point import solve_point
from .progress import Progress


def run(study: Study, path, *, workers: int = 1, scheduler=None, resume: bool = False,
        overwrite: bool = False, progress: TextIO | None = sys.stderr,
        time_limit: float | None = None) -> StudyData:
    """Compute a study into the HDF5 file ``path`` and return what the file holds.

    Parameters
    ----------
    study : Sweep or Cycle
    path : str or Path
        The study file (see :mod:`~viscocontact.studies.storage` for its layout).
    workers : int
        Worker processes (1: compute in this process).
    scheduler : str or distributed.Client, optional
        Address of a Dask distributed scheduler (overrides ``workers``).
    resume : bool
        Continue the study in an existing file (its scene and parameters must equal
        ``study``'s; finished points are kept and not recomputed). A missing file starts afresh.
    overwrite : bool
        Replace an existing file. Without ``resume`` or ``overwrite`` an existing file is an error.
    progress : file or None
        Where the progress bar goes (default stderr; None: silent).
    time_limit : float or None
        Seconds allowed to one point; a point past it is stored as an error
        ("TimeLimitExceeded: time limit of ... s reached") and its chain goes on from the last
        converged point. The limit is a cooperative :func:`~viscocontact.deadline.deadline`
        checked at every residual evaluation, so it holds in this process, in worker processes
        and in Dask worker threads alike, and leaves any ``SIGALRM`` timer of the caller alone;
        it cannot stop a kernel-table precomputation, which runs to its end.

    Notes
    -----
    Chains are independent and run concurrently; the points of a chain run one after the other,
    each from the previous point's contact set (see :mod:`~viscocontact.studies.parallel`). A
    point is appended to the file as soon as it is back, whatever the order in which chains finish.
    """
    from ..errors import ValidationError

    if isinstance(workers, bool) or not isinstance(workers, int) or workers < 1:
        raise ValidationError("workers", workers, "an integer >= 1")
    if time_limit is not None and (isinstance(time_limit, bool)
                                   or not isinstance(time_limit, (int, float))
                                   or not time_limit > 0 or time_limit == float("inf")):
        raise ValidationError("time_limit", time_limit, "a finite number of seconds > 0, or None")
    path = Path(path)
    storage.check_output(path)      # a folder, a missing folder: said as such
    pool = make_backend(workers, scheduler)     # no Dask, no scheduler: said before a file exists
    try:
        return _compute(study, path, pool, resume=resume, overwrite=overwrite,
                        progress=progress, time_limit=time_limit)
    finally:
        pool.close()


def _compute(study: Study, path: Path, pool, *, resume: bool, overwrite: bool,
             progress: TextIO | None, time_limit: float | None) -> StudyData:
    """:func:`run` on its checked arguments, with the backend ``pool`` (closed by the caller)."""
    with guard.exclusive(path):     # one process at a time computes into a study file
        if path.exists() and resume:
            header = storage.read_header(path)
            storage.check_same_study(path, header, study)
            storage.note_resume(path)
            done = storage.records(storage.read_points(path))
        elif path.exists() and not overwrite:
            raise storage.StudyFileError(f"{path} exists: resume it (--resume) or replace it "
                                         "(--force)")
        else:
            storage.create(path, study)
            done = {}

        chains = study.chains()
        records = {c.index: list(done.get(c.index, [])) for c in chains}
        bar = Progress(study.kind,
                       sum(study.expected_points(c, records[c.index]) for c in chains),
                       done=sum(len(r) for r in records.values()), stream=progress)
        pending = {}
        try:
            def submit(chain):
                nxt = study.next_point(chain, records[chain.index])
                if nxt is not None:
                    pending[pool.submit(solve_point, *nxt, time_limit)] = chain

            for chain in chains:
                submit(chain)
            while pending:
                for handle in pool.wait(list(pending)):
                    chain = pending.pop(handle)
                    record = handle.result()
                    row = storage.append(path, record)
                    record.pop("fields", None)
                    records[chain.index].append(record)
                    _warn_uncertified(study, record, row)
                    total = sum(study.expected_points(c, records[c.index]) for c in chains)
                    bar.update(total=total, note=_note(record))
                    submit(chain)
        finally:
            bar.close()
        storage.set_complete(path, True)
        _warn_outside(records)
        return load_study(path)


def _warn_outside(records) -> None:
    """One :class:`~viscocontact.errors.ModelValidityWarning` for the points whose result lies
    outside the model (their message says why)."""
    from ..errors import OUTSIDE_MODEL, ModelValidityWarning, warn_user

    rows = [r for chain in records.values() for r in chain]
    outside = sum(OUTSIDE_MODEL in str(r.get("message", "")) for r in rows)
    if outside:
        warn_user(f"{outside} of {len(rows)} points lie outside the model: their 'message' "
                  f"column says why (docs/edges.md)", ModelValidityWarning)


def _warn_uncertified(study: Study, record, row: int) -> None:
    """A :class:`~viscocontact.errors.CertificationWarning` for a point that failed its
    certification (its message says by how much)."""
    from ..errors import CertificationWarning, warn_user
    from .certify import failed

    if failed(record, getattr(study, "certify", False)):
        message = str(record["message"])
        why = message[message.find("not certified"):] if "not certified" in message else ""
        warn_user(f"the {record['variant']} point at ζ = {record['zeta']:.6g}, "
                  f"{record['control']} = {record['target']:.6g} (row {row}) is "
                  f"{why or 'not certified'}", CertificationWarning)


def _note(record) -> str:
    control = "p̃∞" if record["control"] == "mean_pressure" else "Δ̃"
    return (f"{record['variant']} ζ={record['zeta']:.3g} {control}={record['target']:.3g} "
            f"{record['status']}")


def resume(path, **options) -> StudyData:
    """Continue the study a file holds (its own scene and parameters); see :func:`run`."""
    header = storage.read_header(path)
    study = storage.study_from_header(header)
    return run(study, path, resume=True, **options)
