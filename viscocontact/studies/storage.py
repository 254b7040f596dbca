"""One HDF5 file per study, written point by point (layout in ``docs/studies.md``).

::

    /                    attrs: format = "viscocontact.study", format_version = 1, kind,
                                viscocontact_version, created, complete (+ resumed_with_version)
    /scene               the base scene as TOML text
    /study               the study parameters as JSON text
    /seeds               int64 [K], the profile seeds (empty without realizations)
    /points              attrs: count = number of finished points
    /points/<column>     one 1-D dataset per column of point.COLUMNS, one row per point
                         (str columns are UTF-8 strings, ``edges`` variable-length float64)
    /points/row          int64 0 .. n-1, the dimension scale "row" of every column
    /fields/<row>        x, pressure, displacement, gap of point <row> (6 digits; on request;
                         x is the dimension scale of the others); an areal point: x, y and
                         the 2D pressure, displacement, gap of shape (y, x)

The header is written to a temporary file that is renamed into place, so a study file either
exists complete with its header or not at all. Each finished point is appended by opening the
file, writing the row, raising ``/points.count`` last and closing it, so a killed run leaves a
file holding every point finished before the kill; rows beyond ``count`` (a write cut short) are
ignored and overwritten on resume. The file is opened only for the moment of a write, which keeps
it readable (``viscocontact plot``) while the study runs; a write that finds the file open in
another program (HDF5's file lock) waits for it up to :data:`WRITE_WAIT` seconds, a read up to
:data:`READ_WAIT`. Signals that would end the process during an append are held until the append
is done, and only one process computes into a study file at a time
(:mod:`~viscocontact.studies.guard`).

HDF5 dimension scales name the dimensions, so that ``xarray.open_dataset(path, group="points",
engine="h5netcdf")`` opens the points with a ``row`` dimension (and no ``phony_dim_*``):
``/points/row`` holds ``0 .. n-1`` and is the scale of every column, ``/seeds`` is its own scale,
and ``x`` is the scale of the fields of a point. Files written by 0.1.0 have no scales; they
are read (and resumed) all the same.
"""
from __future__ import annotations

import contextlib
import datetime
import json
import os
import re
import time
from pathlib import Path
from typing import Any, Iterable, Mapping

import numpy as np

from ..errors import StudyFileError, ValidationError
from .guard import signals_deferred
from .point import COLUMNS, LATER_COLUMNS

FORMAT = "viscocontact.study"
FORMAT_VERSION = 1
FIELD_NAMES = ("x", "y", "pressure", "displacement", "gap")
ROW = "row"

#: Seconds a write (append) waits for another program to close the file (HDF5 file lock).
WRITE_WAIT = 60.0
#: Seconds a read waits for a write in progress to finish.
READ_WAIT = 5.0




def _h5py():
    import h5py

    return h5py


def _dtype(kind: str):
    h5py = _h5py()
    return {"int": np.int64, "float": np.float64, "bool": np.bool_,
            "str": h5py.string_dtype("utf-8"), "edges": h5py.vlen_dtype(np.float64)}[kind]


def _locked(exc: OSError) -> bool:
    return isinstance(exc, BlockingIOError) or "unable to lock file" in str(exc)


def _open_error(path: Path, exc: OSError, waited: float) -> StudyFileError:
    """The true reason why HDF5 could not open ``path``."""
    text = " ".join(str(exc).split())
    if _locked(exc):
        return StudyFileError(
            f"{path} is held open by another process (HDF5 file lock) and was not released "
            f"within {waited:g} s: a study appending a point holds it for a moment, a program "
            "that keeps it open (e.g. h5py.File in a notebook) until it closes it")
    truncated = re.search(r"truncated file: eof = (\d+).*stored_eof = (\d+)", text)
    if truncated:
        have, want = truncated.groups()
        return StudyFileError(f"{path} is truncated: it has {have} of its {want} bytes (a copy "
                              "or a transfer cut short, or a full disk); it cannot be read")
    if "file signature not found" in text:
        size = path.stat().st_size
        what = "it is empty" if size == 0 else f"its {size} bytes have no HDF5 signature"
        return StudyFileError(f"{path} is not a readable HDF5 file: {what} (not a study file)")
    if isinstance(exc, PermissionError):
        return StudyFileError(f"cannot open {path}: permission denied")
    return StudyFileError(f"{path} is not a readable HDF5 file (damaged or not HDF5): {text}")


def _open(path: Path, mode: str, wait: float = READ_WAIT):
    """``h5py.File(path, mode)``, waiting up to ``wait`` s while another process holds it."""
    h5py = _h5py()
    if not path.exists():
        raise FileNotFoundError(2, "No such file", str(path))
    if path.is_dir():
        raise StudyFileError(f"{path} is a folder, not a study file")
    start, pause = time.monotonic(), 0.005
    while True:
        try:
            return h5py.File(path, mode)
        except OSError as exc:
            waited = time.monotonic() - start
            if _locked(exc) and waited < wait:
                time.sleep(min(pause, wait - waited))
                pause = min(2 * pause, 0.25)
                continue
            raise _open_error(path, exc, wait) from exc


def check_output(path) -> None:
    """Raise :class:`StudyFileError` if ``path`` cannot be (or hold) a study file written here:
    a folder, in a missing folder or in one this process may not write to."""
    path = Path(path)
    folder = path.parent
    if path.is_dir():
        raise StudyFileError(f"{path} is a folder: the study file needs a file name, e.g. "
                             f"{path / 'study.h5'}")
    if not folder.exists():
        raise StudyFileError(f"cannot write {path}: the folder {folder} does not exist")
    if not folder.is_dir():
        raise StudyFileError(f"cannot write {path}: {folder} is not a folder")
    if not os.access(folder, os.W_OK | os.X_OK):
        raise StudyFileError(f"cannot write {path}: no permission to create files in {folder}")
    if path.exists() and not os.access(path, os.R_OK | os.W_OK):
        raise StudyFileError(f"cannot write {path}: no permission to read and write it")


def _check_header(f, path: Path) -> None:
    fmt = f.attrs.get("format")
    if isinstance(fmt, bytes):
        fmt = fmt.decode()
    if fmt != FORMAT:
        raise StudyFileError(f"{path} is an HDF5 file but not a viscocontact study file (its "
                             f"'format' attribute is {fmt!r}, expected {FORMAT!r})")
    version = int(f.attrs.get("format_version", -1))
    if version > FORMAT_VERSION or version < 1:
        raise StudyFileError(f"{path} has study-file format version {version}; this viscocontact "
                             f"reads versions 1 to {FORMAT_VERSION} (upgrade viscocontact)")
    for name in ("scene", "study", "seeds", "points"):
        if name not in f:
            raise StudyFileError(f"{path} is damaged: /{name} is missing")
    count = int(f["points"].attrs.get("count", -1))
    if count < 0:
        raise StudyFileError(f"{path} is damaged: /points has no 'count' attribute")
    for column in COLUMNS:
        if column not in f["points"] and column in LATER_COLUMNS:
            continue                          # a file written before the column existed
        if column not in f["points"]:
            raise StudyFileError(f"{path} is damaged: /points/{column} is missing")
        if f["points"][column].shape[0] < count:
            raise StudyFileError(f"{path} is damaged: /points/{column} has "
                                 f"{f['points'][column].shape[0]} rows, /points.count says {count}")


# ---- writing ------------------------------------------------------------------------------------
def _write_atomically(path: Path, fill) -> None:
    """Write a new file with ``fill(h5py.File)`` into ``path.tmp`` and rename it to ``path``;
    no temporary file is left behind, and an OSError becomes a :class:`StudyFileError`."""
    h5py = _h5py()
    tmp = path.with_name(path.name + ".tmp")
    try:
        with signals_deferred():
            with h5py.File(tmp, "w") as f:
                fill(f)
            os.replace(tmp, path)
    except BaseException as exc:
        tmp.unlink(missing_ok=True)
        if isinstance(exc, OSError):
            raise StudyFileError(f"cannot write {path}: {exc.strerror or exc}") from exc
        raise


def _layout(f, header: Mapping[str, Any], scene: str, params: str, seeds, count: int = 0):
    """The groups and datasets of a study file (``count`` rows); its ``/points`` group."""
    h5py = _h5py()
    for key, value in header.items():
        f.attrs[key] = value
    f.create_dataset("scene", data=scene, dtype=h5py.string_dtype("utf-8"))
    f.create_dataset("study", data=params, dtype=h5py.string_dtype("utf-8"))
    f.create_dataset("seeds", data=np.asarray(seeds, dtype=np.int64)).make_scale("seeds")
    points = f.create_group("points")
    row = points.create_dataset(ROW, data=np.arange(count, dtype=np.int64), maxshape=(None,),
                                chunks=(256,))
    row.make_scale(ROW)
    for column, kind in COLUMNS.items():
        ds = points.create_dataset(column, shape=(count,), maxshape=(None,), chunks=(256,),
                                   dtype=_dtype(kind))
        ds.dims[0].attach_scale(row)
    f.create_group("fields")
    points.attrs["count"] = count
    return points


def create(path, study) -> None:
    """Write the header of a new study file (atomically: temporary file, then rename).

    Raises :class:`StudyFileError` for a path that cannot hold a study file (:func:`check_output`)
    or a failed write; no temporary file is left behind.
    """
    from .. import __version__

    path = Path(path)
    check_output(path)
    header = {"format": FORMAT, "format_version": FORMAT_VERSION, "kind": study.kind,
              "viscocontact_version": __version__,
              "created": datetime.datetime.now(datetime.timezone.utc).isoformat(
                  timespec="seconds"),
              "complete": False}
    _write_atomically(path, lambda f: _layout(f, header, study.scene.to_toml(),
                                              json.dumps(study.params()), study.seeds or ()))


def rewrite(path) -> None:
    """Write a study file anew from the points it counts (atomically), in the current layout.

    A process killed in the middle of an append (``SIGKILL``, the out-of-memory killer) leaves
    a file whose counted points read correctly but whose HDF5 metadata may refuse the next
    write ("len not positive after adjustment for EOA"); the rewrite, done when a study is
    resumed, drops such leftovers (and gives files of 0.1.0 the dimension scales).
    """
    path = Path(path)
    tmp = path.with_name(path.name + ".tmp")
    with _reading(path) as src:
        count = int(src["points"].attrs["count"])
        header = {k: v for k, v in src.attrs.items()}

        def fill(f):
            points = _layout(f, header, _text(src["scene"]), _text(src["study"]),
                             src["seeds"][()], count)
            for column, kind in COLUMNS.items():
                if not count:
                    continue
                if column not in src["points"]:   # a file written before the column existed
                    points[column][:] = LATER_COLUMNS[column]
                    continue
                values = src["points"][column][:count]
                if kind == "edges":  # row by row: h5py makes equal-length rows one 2-D array
                    for i, value in enumerate(values):
                        points[column][i] = value
                else:
                    points[column][:] = values
            for name, group in src["fields"].items():
                if name.isdigit() and int(name) < count:
                    _write_fields(f["fields"].create_group(name),
                                  {k: group[k][()] for k in group})

        try:
            with signals_deferred():
                with _h5py().File(tmp, "w") as f:
                    fill(f)
        except BaseException as exc:
            tmp.unlink(missing_ok=True)
            if isinstance(exc, OSError):
                raise StudyFileError(f"cannot write {path}: {exc.strerror or exc}") from exc
            raise
    with signals_deferred():
        os.replace(tmp, path)


def append(path, record: Mapping[str, Any]) -> int:
    """Append one point (a :func:`~viscocontact.studies.point.solve_point` record); its row.

    The count is raised last, so a write that fails (a full disk) or is killed leaves the file
    with every earlier point; such a failure raises :class:`StudyFileError` saying so.
    """
    path = Path(path)
    row = None
    try:
        with signals_deferred(), _open(path, "r+", wait=WRITE_WAIT) as f:
            points = f["points"]
            row = int(points.attrs["count"])
            for column, kind in COLUMNS.items():
                if column not in points:       # a file written before the column existed
                    ds = points.create_dataset(column, shape=(row,), maxshape=(None,),
                                               chunks=(256,), dtype=_dtype(kind))
                    if row:
                        ds[:] = LATER_COLUMNS[column]
                    if ROW in points:
                        ds.dims[0].attach_scale(points[ROW])
                ds = points[column]
                if ds.shape[0] < row + 1:
                    ds.resize((row + 1,))
                value = record[column]
                if kind == "edges":
                    value = np.asarray(value, dtype=np.float64).ravel()
                elif kind == "str":
                    value = str(value)
                ds[row] = value
            fields = record.get("fields")
            name = f"{row:06d}"
            if name in f["fields"]:
                del f["fields"][name]          # left over from a write cut short
            if fields:
                _write_fields(f["fields"].create_group(name), fields)
            if ROW in points:                  # files of 0.1.0 have no row scale
                if points[ROW].shape[0] < row + 1:
                    points[ROW].resize((row + 1,))
                points[ROW][row] = row
            f.flush()                          # the row on disk before it counts
            points.attrs["count"] = row + 1    # last: the row now counts
    except OSError as exc:
        kept = "its earlier points" if row is None else f"the {row} points before it"
        raise StudyFileError(f"cannot write a point to {path}: {exc.strerror or exc}; the file "
                             f"keeps {kept}: remove the cause and continue with --resume") from exc
    return row


def _write_fields(group, fields: Mapping[str, Any]) -> None:
    """The fields of one point; ``x`` (and for an areal point ``y``) are the dimension scales
    of the others (a 1D field along ``x``, a 2D one of shape ``(y, x)``)."""
    scales = {}
    for key in FIELD_NAMES:
        if key not in fields:
            continue
        ds = group.create_dataset(key, data=np.asarray(fields[key], dtype=np.float64))
        if key in ("x", "y"):
            ds.make_scale(key)
            scales[key] = ds
            continue
        axes = ("x",) if ds.ndim == 1 else ("y", "x")
        for dim, name in enumerate(axes):
            scale = scales.get(name)
            if scale is not None and ds.ndim == len(axes) and ds.shape[dim] == scale.shape[0]:
                ds.dims[dim].attach_scale(scale)


def set_complete(path, complete: bool) -> None:
    """Mark the study finished (every chain has ended) or not."""
    with signals_deferred(), _open(Path(path), "r+", wait=WRITE_WAIT) as f:
        f.attrs["complete"] = bool(complete)


def note_resume(path) -> None:
    """Prepare a study file to be continued: :func:`rewrite` it, and record the version of
    viscocontact that resumed it (if it differs)."""
    from .. import __version__

    rewrite(path)
    with signals_deferred(), _open(Path(path), "r+", wait=WRITE_WAIT) as f:
        if str(f.attrs.get("viscocontact_version")) != __version__:
            f.attrs["resumed_with_version"] = __version__


# ---- reading ------------------------------------------------------------------------------------
@contextlib.contextmanager
def _reading(path: Path):
    """The open study file (header checked); an HDF5 error while reading says it is damaged."""
    with _open(path, "r") as f:
        try:
            _check_header(f, path)
            yield f
        except (OSError, KeyError) as exc:
            raise StudyFileError(f"{path} is damaged: {' '.join(str(exc).split())}") from exc


def _text(ds) -> str:
    value = ds[()]
    return value.decode("utf-8") if isinstance(value, bytes) else str(value)


def read_header(path) -> dict[str, Any]:
    """``kind``, ``scene`` (TOML), ``params``, ``seeds``, ``version``, ``created``, ``complete``,
    ``count`` of a study file; raises :class:`StudyFileError` for a foreign or damaged file."""
    path = Path(path)
    with _reading(path) as f:
        try:
            params = json.loads(_text(f["study"]))
        except ValueError as exc:
            raise StudyFileError(f"{path} is damaged: /study is not JSON ({exc})") from exc
        attrs_ = {k: (v.decode() if isinstance(v, bytes) else v) for k, v in f.attrs.items()}
        return {"kind": str(attrs_.get("kind")), "scene": _text(f["scene"]), "params": params,
                "seeds": np.asarray(f["seeds"][()], dtype=np.int64),
                "version": str(attrs_.get("viscocontact_version")),
                "created": str(attrs_.get("created", "")),
                "complete": bool(attrs_.get("complete", False)),
                "count": int(f["points"].attrs["count"])}


def read_points(path) -> dict[str, np.ndarray]:
    """Every finished point: one array per column (``edges``: an object array of float arrays)."""
    path = Path(path)
    with _reading(path) as f:
        points = f["points"]
        n = int(points.attrs["count"])
        out: dict[str, np.ndarray] = {}
        for column, kind in COLUMNS.items():
            if column not in points:           # a file written before the column existed
                out[column] = np.full(n, LATER_COLUMNS[column],
                                      dtype=str if kind == "str" else _dtype(kind))
                continue
            ds = points[column]
            if kind == "str":
                out[column] = np.array(ds.asstr()[:n] if n else [], dtype=str)
            elif kind == "edges":
                values = ds[:n] if n else []
                arr = np.empty(n, dtype=object)
                for i, v in enumerate(values):
                    arr[i] = np.asarray(v, dtype=np.float64)
                out[column] = arr
            else:
                out[column] = np.asarray(ds[:n], dtype=_dtype(kind))
        return out


def read_fields(path, row: int) -> dict[str, np.ndarray] | None:
    """The fields stored for point ``row`` (None if none were stored)."""
    path = Path(path)
    with _reading(path) as f:
        group = f["fields"].get(f"{int(row):06d}")
        if group is None or int(row) >= int(f["points"].attrs["count"]):
            return None
        return {k: np.asarray(group[k][()]) for k in group}


def records(points: Mapping[str, np.ndarray]) -> dict[int, list[dict[str, Any]]]:
    """Rows grouped by chain, each chain in step order (the records a study continues from)."""
    n = len(points["chain"])
    out: dict[int, list[dict[str, Any]]] = {}
    order: Iterable[int] = np.lexsort((points["step"], points["chain"])) if n else []
    for i in order:
        row = {k: (v[i].item() if hasattr(v[i], "item") and k != "edges" else v[i])
               for k, v in points.items()}
        out.setdefault(int(row["chain"]), []).append(row)
    return out


def study_from_header(header: Mapping[str, Any]):
    """The :class:`~viscocontact.studies.base.Study` a study file holds."""
    from ..read import read_scene
    from .base import Study
    from .cycle import Cycle
    from .sweep import Sweep

    kinds: dict[str, type[Study]] = {"sweep": Sweep, "cycle": Cycle}
    if header["kind"] not in kinds:
        raise StudyFileError(f"unknown study kind {header['kind']!r} (expected one of "
                             f"{sorted(kinds)})")
    return kinds[header["kind"]].from_params(read_scene(header["scene"]), header["params"])


def _same_scene(stored: str, scene) -> bool:
    """Whether the stored scene text, read by this version, is ``scene``: a file written before
    a component gained a parameter (its default then applies) holds the same scene."""
    from ..read import read_scene

    try:
        return read_scene(stored).to_toml() == scene.to_toml()
    except Exception:       # a scene this version cannot read is not the same scene
        return False


def check_same_study(path, header: Mapping[str, Any], study) -> None:
    """Raise a :class:`ValidationError` naming the first parameter that differs from the file."""
    where = f"the value stored in {path} (--resume continues the study the file holds)"
    if header["kind"] != study.kind:
        raise ValidationError("study kind", study.kind, f"{header['kind']!r}, {where}")
    if header["scene"] != study.scene.to_toml() and not _same_scene(header["scene"], study.scene):
        raise ValidationError("scene", "(the given scene)", f"the scene stored in {path}, which "
                              "differs (--resume continues the study the file holds)")
    new = json.loads(json.dumps(study.params()))
    for key in sorted(set(new) | set(header["params"])):
        if new.get(key) != header["params"].get(key):
            raise ValidationError(f"{study.kind}.{key}", new.get(key),
                                  f"{header['params'].get(key)!r}, {where}")
