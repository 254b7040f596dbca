"""Measured profiles: the Fourier series of height samples over one period.

A measured trace ``z_j = z(x_j)``, ``x_j = j·L/n`` (``j = 0..n-1``, the end point ``x = L`` excluded
because it repeats ``x = 0``) is taken as one period ``λ0 = L`` of a periodic profile, so
``q0 = 2π/L``. Its discrete Fourier transform gives the trigonometric interpolant of the samples,
``q0·r(x̃) = Σ_{k=1}^{⌊n/2⌋} a_k cos(k x̃ + φ_k)``, which passes exactly through the (detrended)
samples; the profile between samples is this band-limited interpolant.
"""
from __future__ import annotations

import csv
import math
import os

import attrs
import numpy as np

from .._validation import array_eq, positive
from ..errors import ValidationError
from .base import TWO_PI
from .spectral import Modes, SpectralProfile, as_float

__all__ = ["MeasuredProfile"]

#: Fewest samples accepted by the constructors (two modes).
MIN_SAMPLES = 4
_DETRENDS = ("mean", "linear")


def _read_only(value):
    arr = np.array(value, dtype=float, copy=True)
    arr.setflags(write=False)
    return arr


def _check_coefficients(inst, attribute, value):
    name = f"MeasuredProfile.{attribute.name}"
    if value.ndim != 1 or value.size < 1:
        raise ValidationError(name, value.shape, "a 1-d array with at least 1 entry")
    if not np.all(np.isfinite(value)):
        raise ValidationError(name, "array with NaN/inf", "finite entries")
    if attribute.name == "amplitudes":
        if np.any(value < 0):
            raise ValidationError(name, float(value.min()), "amplitudes >= 0")
        if not np.any(value > 0):
            raise ValidationError(name, "all zero", "at least one non-zero amplitude (a flat "
                                  "profile has no amplitude to normalise by)")
    elif value.shape != inst.amplitudes.shape:
        raise ValidationError(name, value.shape, f"the shape of amplitudes {inst.amplitudes.shape}")


@attrs.frozen(kw_only=True)
class MeasuredProfile(SpectralProfile):
    """Periodic profile from measured data, stored as its Fourier coefficients.

    Parameters
    ----------
    amplitudes : array_like, shape (N,)
        ``a_k >= 0`` for ``k = 1..N``, in units of 1/q0 (``q0·`` the physical amplitude).
    phases : array_like, shape (N,)
        ``φ_k`` in radians.
    length : float
        Physical period ``λ0 = L`` in metres (``q0 = 2π/L``).

    Notes
    -----
    Use the named constructors :meth:`from_samples`, :meth:`from_csv` and :meth:`from_hdf5`. The
    heights are ``q0·r``, so the profile is scale-free; ``length`` keeps the physical scale.

    Examples
    --------
    >>> import numpy as np
    >>> x = np.arange(64) * 1e-3 / 64                      # 1 mm period, 64 samples
    >>> z = 2e-6 * np.cos(2 * np.pi * x / 1e-3)            # 2 µm amplitude
    >>> p = MeasuredProfile.from_samples(z, length=1e-3)
    >>> round(p.amplitude / p.q0 * 1e6, 9)                  # back to µm
    2.0
    """

    amplitudes: np.ndarray = attrs.field(converter=_read_only, validator=_check_coefficients,
                                         eq=array_eq(), hash=False)
    phases: np.ndarray = attrs.field(converter=_read_only, validator=_check_coefficients,
                                     eq=array_eq(), hash=False)
    length: float = attrs.field(converter=as_float, validator=positive)

    @property
    def q0(self) -> float:
        """Fundamental wavevector ``q0 = 2π/L`` (1/m)."""
        return TWO_PI / self.length

    @property
    def modes(self) -> Modes:
        """Modes ``k = 1..N``."""
        return Modes(wavenumbers=np.arange(1, self.amplitudes.size + 1), amplitudes=self.amplitudes,
                     phases=self.phases)

    # -- named constructors ------------------------------------------------------------------------

    @classmethod
    def from_samples(cls, heights, length: float, *, detrend: str = "mean",
                     max_modes: int | None = None) -> MeasuredProfile:
        """Profile through uniform height samples over one period.

        Parameters
        ----------
        heights : array_like, shape (n,)
            Heights ``z_j`` (m) at ``x_j = j·length/n``, ``j = 0..n-1`` (end point excluded),
            ``n >= 4``.
        length : float
            Period L (m).
        detrend : {"mean", "linear"}
            Subtract the mean, or the least-squares straight line (tilt of the measurement).
        max_modes : int or None
            Keep only ``k <= max_modes`` (a low-pass filter); default all ``k <= n/2``.

        Notes
        -----
        With ``X = rfft(q0·z)/n``: ``a_k = 2|X_k|``, ``φ_k = arg X_k`` for ``0 < k < n/2`` and, for
        even n, the Nyquist term ``a = |X_{n/2}|``, ``φ ∈ {0, π}`` (its sine part is invisible at
        the samples), so the profile reproduces the detrended samples exactly. (The Nyquist term's
        mean square is ``a²`` at the samples but ``a²/2`` for the continuous profile, so ``m0`` is
        the sample variance minus ``|X_{n/2}|²/2``.)
        """
        length = _check_length(length)
        z = np.array(heights, dtype=float, copy=True)
        if z.ndim != 1:
            raise ValidationError("MeasuredProfile.heights", z.shape, "a 1-d array")
        _check_samples(z, "MeasuredProfile.heights")
        if detrend not in _DETRENDS:
            raise ValidationError("MeasuredProfile.detrend", detrend, f"one of {list(_DETRENDS)}")
        if max_modes is not None:
            if isinstance(max_modes, bool) or not isinstance(max_modes, (int, np.integer)) \
                    or max_modes < 1:
                raise ValidationError("MeasuredProfile.max_modes", max_modes,
                                      "None or an integer >= 1")
        n = z.size
        size = float(np.max(np.abs(z)))
        if detrend == "linear":
            j = np.arange(n, dtype=float)
            z = z - np.polyval(np.polyfit(j, z, 1), j)
        z = (z - z.mean()) * (TWO_PI / length)
        X = np.fft.rfft(z) / n
        a = 2.0 * np.abs(X[1:])
        phi = np.angle(X[1:])
        if n % 2 == 0:
            a[-1] = abs(X[-1].real)
            phi[-1] = 0.0 if X[-1].real >= 0 else np.pi
        if max_modes is not None:
            a, phi = a[:max_modes], phi[:max_modes]
        if not np.any(a > 1e-13 * size * (TWO_PI / length)):
            raise ValidationError("MeasuredProfile.heights", "constant after detrending",
                                  "samples with some roughness")
        return cls(amplitudes=a, phases=phi, length=length)

    @classmethod
    def from_csv(cls, path: str | os.PathLike, *, column: int | str | None = None,
                 length: float | None = None, unit: float = 1.0, detrend: str = "mean",
                 max_modes: int | None = None) -> MeasuredProfile:
        """Read a profile from a CSV/text file.

        Parameters
        ----------
        path : path-like
            Delimited text (comma, semicolon, or tabs/blanks; ``#`` comments and one header line
            allowed). One column: heights z (then ``length`` is required). Two or more: the first
            is x (uniform, increasing, end point excluded), heights from ``column``.
        column : int, str or None
            Index or header name of the heights column; default the last column.
        length : float or None
            Period in file units; default ``n·Δx`` from the x column (checked against it if both).
        unit : float
            Metres per file unit (e.g. ``1e-6`` for µm), applied to x, z and ``length``.
        detrend, max_modes
            As in :meth:`from_samples`.
        """
        header, rows = _read_table(path)
        data = np.array(rows, dtype=float)
        ncol = data.shape[1]
        if column is None:
            icol = ncol - 1
        elif isinstance(column, str):
            if header is None or column not in header:
                raise ValidationError("MeasuredProfile.column", column,
                                      f"one of the header names {header} of {os.fspath(path)}")
            icol = header.index(column)
        else:
            icol = int(column)
            if not -ncol <= icol < ncol:
                raise ValidationError("MeasuredProfile.column", column,
                                      f"a column index in [0, {ncol - 1}] of {os.fspath(path)}")
            icol %= ncol
        z = data[:, icol]
        _check_samples(z, "MeasuredProfile.heights", where=os.fspath(path))
        x = data[:, 0] if ncol >= 2 and icol != 0 else None
        return cls._from_xz(x, z, length, unit, detrend, max_modes, os.fspath(path))

    @classmethod
    def from_hdf5(cls, path: str | os.PathLike, dataset: str, *, length: float | None = None,
                  unit: float = 1.0, detrend: str = "mean",
                  max_modes: int | None = None) -> MeasuredProfile:
        """Read a profile from an HDF5 dataset.

        Parameters
        ----------
        path : path-like
            HDF5 file.
        dataset : str
            Dataset holding the heights z, shape (n,), or x and z as shape (n, 2).
        length : float or None
            Period in file units; default the dataset's attribute ``"length"``, else ``n·Δx``.
        unit, detrend, max_modes
            As in :meth:`from_csv`.
        """
        import h5py  # imported here to keep `import viscocontact` light

        where = f"{os.fspath(path)}:{dataset}"
        with h5py.File(path, "r") as f:
            if dataset not in f or not isinstance(f[dataset], h5py.Dataset):
                raise ValidationError("MeasuredProfile.dataset", dataset,
                                      f"a dataset in {os.fspath(path)}")
            ds = f[dataset]
            data = np.array(ds[()], dtype=float)
            if length is None and "length" in ds.attrs:
                length = float(np.asarray(ds.attrs["length"]).reshape(()))
        if data.ndim == 2 and data.shape[1] == 2:
            x, z = data[:, 0], data[:, 1]
        elif data.ndim == 1:
            x, z = None, data
        else:
            raise ValidationError("MeasuredProfile.dataset", f"{where} with shape {data.shape}",
                                  "shape (n,) of heights or (n, 2) of x, z")
        _check_samples(z, "MeasuredProfile.heights", where=where)
        return cls._from_xz(x, z, length, unit, detrend, max_modes, where)

    @classmethod
    def _from_xz(cls, x, z, length, unit, detrend, max_modes, where) -> MeasuredProfile:
        unit = _check_length(unit, "MeasuredProfile.unit")
        if x is not None:
            _check_samples(x, "MeasuredProfile.x", where=where)
            dx = np.diff(x)
            step = (x[-1] - x[0]) / (x.size - 1)
            if not step > 0 or np.max(np.abs(dx - step)) > 1e-6 * step:
                raise ValidationError("MeasuredProfile.x",
                                      f"{where}: spacing {dx.min():g}..{dx.max():g}",
                                      "uniformly spaced, increasing x (relative spread < 1e-6)")
            period = step * x.size
            if length is None:
                length = period
            elif abs(_check_length(length) - period) > 1e-6 * period:
                raise ValidationError("MeasuredProfile.length", length,
                                      f"n·Δx = {period:g} of the x column in {where} (samples "
                                      "cover one period, end point excluded)")
        if length is None:
            raise ValidationError("MeasuredProfile.length", None,
                                  f"a period > 0 (no x column or 'length' attribute in {where})")
        length = _check_length(length)
        return cls.from_samples(z * unit, length * unit, detrend=detrend, max_modes=max_modes)


def _check_length(value, name: str = "MeasuredProfile.length") -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        v = math.nan
    if not (math.isfinite(v) and v > 0):
        raise ValidationError(name, value, "a real number in (0, inf)")
    return v


def _check_samples(z: np.ndarray, name: str, where: str | None = None) -> None:
    prefix = f"{where}: " if where else ""
    if z.size < MIN_SAMPLES:
        raise ValidationError(name, f"{prefix}{z.size} samples", f"at least {MIN_SAMPLES} samples")
    bad = np.flatnonzero(~np.isfinite(z))
    if bad.size:
        raise ValidationError(name, f"{prefix}{bad.size} NaN/inf values (first at sample {bad[0]})",
                              "finite numbers")


def _read_table(path) -> tuple[list[str] | None, list[list[float]]]:
    """Numeric rows of a delimited text file and its optional header line."""
    where = os.fspath(path)
    with open(path, newline="") as f:
        lines = [ln.strip() for ln in f if ln.strip() and not ln.lstrip().startswith("#")]
    if not lines:
        raise ValidationError("MeasuredProfile.heights", f"{where}: empty file", "at least "
                              f"{MIN_SAMPLES} samples")
    delim = next((d for d in (",", ";") if d in lines[0]), None)

    def split(line: str) -> list[str]:
        cells = next(csv.reader([line], delimiter=delim)) if delim else line.split()
        return [c.strip() for c in cells]

    header = None
    first = split(lines[0])
    try:
        [float(c) for c in first]
    except ValueError:
        header, lines = first, lines[1:]
    rows = []
    for i, line in enumerate(lines):
        cells = split(line)
        try:
            row = [float(c) if c not in ("", "nan", "NaN") else math.nan for c in cells]
        except ValueError:
            raise ValidationError("MeasuredProfile.heights", f"{where}: row {i + 1} = {line!r}",
                                  "numbers only") from None
        rows.append(row)
    widths = {len(r) for r in rows}
    if len(widths) > 1:
        raise ValidationError("MeasuredProfile.heights",
                              f"{where}: rows of {sorted(widths)} columns",
                              "the same number of columns on every row")
    if not rows:
        raise ValidationError("MeasuredProfile.heights", f"{where}: no data rows",
                              f"at least {MIN_SAMPLES} samples")
    return header, rows
