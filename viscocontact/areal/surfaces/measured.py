"""Measured areal surfaces: the trigonometric interpolant of a height map over one cell.

A height map ``z_ij = z(x_i, y_j)``, ``x_i = i·Δx`` (``i = 0..nx-1``), ``y_j = j·Δy``, is taken as
one cell of a periodic surface, ``L_x = nx·Δx`` and ``L_y = ny·Δy`` (the end points repeat the
first ones and are not in the map), so ``q0 = 2π/L_x`` and ``aspect = L_y/L_x``. Its discrete
Fourier transform gives the trigonometric interpolant of the (detrended) samples, which passes
through every sample; a Nyquist bin of an even side is split evenly between ``±n/2`` so that the
interpolant is real. Heights are converted once, at the named constructors, from file units to
``q0·h``.
"""
from __future__ import annotations

import functools
import math
import os

import attrs
import numpy as np

from ..._validation import array_eq, positive
from ...errors import ValidationError
from ...profiles.spectral import as_float
from .base import TWO_PI
from .spectral import SpectralSurface, SurfaceModes, check_grid

__all__ = ["MeasuredSurface"]

#: Fewest samples accepted along each side.
MIN_SIDE = 4
_DETRENDS = ("mean", "plane")


def _read_only(value):
    arr = np.array(value, dtype=float, copy=True)
    arr.setflags(write=False)
    return arr


def _check_samples(inst, attribute, value):
    name = "MeasuredSurface.samples"
    if value.ndim != 2 or min(value.shape) < MIN_SIDE:
        raise ValidationError(name, value.shape, f"a 2-d array (ny, nx), both >= {MIN_SIDE}")
    if not np.all(np.isfinite(value)):
        raise ValidationError(name, "array with NaN/inf", "finite entries")
    scale = float(np.max(np.abs(value)))
    if scale == 0.0:
        raise ValidationError(name, "all zero", "samples with some roughness")
    if abs(float(value.mean())) > 1e-9 * scale:
        raise ValidationError(name, f"mean {float(value.mean()):.3g}", "zero-mean samples (q0·h)")


def _split_nyquist(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(source bin, wavenumber, weight)`` of one axis: an even side's Nyquist bin goes half to
    ``+n/2`` and half to ``-n/2``."""
    src = np.arange(n)
    k = np.where(src <= (n - 1) // 2, src, src - n)
    w = np.ones(n)
    if n % 2 == 0:
        w[n // 2] = 0.5
        src, k, w = np.append(src, n // 2), np.append(k, n // 2), np.append(w, 0.5)
    return src, k, w


@attrs.frozen(kw_only=True)
class MeasuredSurface(SpectralSurface):
    """A periodic surface through measured heights (see the module docstring).

    Parameters
    ----------
    samples : array_like, shape (ny, nx)
        Zero-mean ``q0·h`` on the cell's grid (both sides ``>= 4``).
    length : float
        ``L_x`` in metres (``q0 = 2π/L_x``).
    aspect : float
        ``L_y/L_x > 0``.

    Notes
    -----
    Use the named constructors :meth:`from_samples`, :meth:`from_npy`, :meth:`from_text` and
    :meth:`from_hdf5`, which take heights and pixel sizes in physical units.

    Examples
    --------
    >>> import numpy as np
    >>> j, i = np.mgrid[0:32, 0:64]
    >>> z = 1e-6 * np.cos(2 * np.pi * i / 64)              # 1 µm waves along x
    >>> s = MeasuredSurface.from_samples(z, pixel_size=1e-5)  # 10 µm pixels: 640 µm × 320 µm
    >>> s.aspect, round(float(s.heights(64, 32).max()) / s.q0 * 1e6, 9)
    (0.5, 1.0)
    """

    samples: np.ndarray = attrs.field(converter=_read_only, validator=_check_samples,
                                      eq=array_eq(), hash=False)
    length: float = attrs.field(converter=as_float, validator=positive)
    aspect: float = attrs.field(converter=as_float, validator=positive)

    @property
    def q0(self) -> float:
        """``q0 = 2π/L_x`` (1/m)."""
        return TWO_PI / self.length

    @property
    def pixel_size(self) -> tuple[float, float]:
        """``(Δx, Δy)`` in metres."""
        ny, nx = self.samples.shape
        return self.length / nx, self.length * self.aspect / ny

    @functools.cached_property
    def modes(self) -> SurfaceModes:
        """The interpolant's modes of the half plane (computed once)."""
        ny, nx = self.samples.shape
        X = np.fft.fft2(self.samples) / (nx * ny)
        sx, kx, wx = _split_nyquist(nx)
        sy, ky, wy = _split_nyquist(ny)
        c = X[np.ix_(sy, sx)] * np.outer(wy, wx)
        K, L = np.meshgrid(kx, ky)
        half = (L > 0) | ((L == 0) & (K > 0))
        c = c[half]
        return SurfaceModes(kx=K[half], ky=L[half], amplitudes=2.0 * np.abs(c),
                            phases=np.angle(c))

    def heights(self, nx: int, ny: int) -> np.ndarray:
        """The samples themselves on their own grid; elsewhere the interpolant, sampled."""
        nx, ny = check_grid(nx, ny)
        if (ny, nx) == self.samples.shape:
            return np.array(self.samples)
        return super().heights(nx, ny)

    # -- named constructors ------------------------------------------------------------------------

    @classmethod
    def from_samples(cls, heights, pixel_size, *, unit: float = 1.0, detrend: str = "mean",
                     length: float | None = None) -> MeasuredSurface:
        """A surface through a height map.

        Parameters
        ----------
        heights : array_like, shape (ny, nx)
            Heights in units of ``unit`` metres; row j at ``y_j = j·Δy``, column i at
            ``x_i = i·Δx``.
        pixel_size : float or (float, float)
            ``Δx`` (and ``Δy``, default ``Δx``) in metres.
        unit : float
            Metres per height unit (``1e-9`` for nm).
        detrend : {"mean", "plane"}
            Subtract the mean, or the least-squares plane (the tilt of the measurement).
        length : float or None
            ``L_x`` in metres if known: checked against ``nx·Δx``.

        Raises
        ------
        ValidationError
            For a map whose peak-to-valley height exceeds the cell's length (slopes far above 1:
            a height unit or pixel size off by orders of magnitude), or inconsistent sizes.
        """
        z = np.array(heights, dtype=float, copy=True)
        if z.ndim != 2 or min(z.shape) < MIN_SIDE:
            raise ValidationError("MeasuredSurface.heights", z.shape,
                                  f"a 2-d array (ny, nx), both >= {MIN_SIDE}")
        bad = np.flatnonzero(~np.isfinite(z))
        if bad.size:
            raise ValidationError("MeasuredSurface.heights", f"{bad.size} NaN/inf values",
                                  "finite numbers")
        if detrend not in _DETRENDS:
            raise ValidationError("MeasuredSurface.detrend", detrend, f"one of {list(_DETRENDS)}")
        dx, dy = _pixel(pixel_size)
        unit = _positive("MeasuredSurface.unit", unit)
        ny, nx = z.shape
        lx, ly = nx * dx, ny * dy
        if length is not None:
            length = _positive("MeasuredSurface.length", length)
            if abs(length - lx) > 1e-6 * lx:
                raise ValidationError("MeasuredSurface.length", length,
                                      f"nx·Δx = {nx}·{dx:g} = {lx:g} m (the map covers one cell, "
                                      "end points excluded)")
        if detrend == "plane":
            j, i = np.mgrid[0:ny, 0:nx]
            design = np.column_stack([np.ones(z.size), i.ravel(), j.ravel()])
            coef = np.linalg.lstsq(design, z.ravel(), rcond=None)[0]
            z = z - (design @ coef).reshape(z.shape)
        z = (z - z.mean()) * unit
        span = float(z.max() - z.min())
        if span == 0.0:
            raise ValidationError("MeasuredSurface.heights", "constant after detrending",
                                  "a map with some roughness")
        if span > lx:
            raise ValidationError("MeasuredSurface.unit", unit,
                                  f"a height unit that makes the peak-to-valley height "
                                  f"({span:g} m) smaller than the cell ({lx:g} m × {ly:g} m); "
                                  "check the height unit and the pixel size")
        return cls(samples=z * (TWO_PI / lx), length=lx, aspect=ly / lx)

    @classmethod
    def from_npy(cls, path: str | os.PathLike, pixel_size, **options) -> MeasuredSurface:
        """A surface from a ``.npy`` height map; ``options`` as in :meth:`from_samples`."""
        return cls.from_samples(np.load(path, allow_pickle=False), pixel_size, **options)

    @classmethod
    def from_text(cls, path: str | os.PathLike, pixel_size, *, delimiter: str | None = None,
                  **options) -> MeasuredSurface:
        """A surface from a text height map (``numpy.loadtxt``: one row of the map per line,
        ``#`` comments); ``options`` as in :meth:`from_samples`."""
        try:
            z = np.loadtxt(path, delimiter=delimiter, ndmin=2)
        except ValueError as exc:
            raise ValidationError("MeasuredSurface.heights", f"{os.fspath(path)}: {exc}",
                                  "a text table of numbers, one map row per line") from None
        return cls.from_samples(z, pixel_size, **options)

    @classmethod
    def from_hdf5(cls, path: str | os.PathLike, dataset: str, *, pixel_size=None,
                  unit: float | None = None, **options) -> MeasuredSurface:
        """A surface from an HDF5 dataset of shape (ny, nx).

        The pixel size (m) and the height unit (m per unit) default to the dataset's attributes
        ``"pixel_size"`` (a number or a pair) and ``"unit"`` (else 1); other ``options`` as in
        :meth:`from_samples`.
        """
        import h5py  # imported here to keep `import viscocontact` light

        where = f"{os.fspath(path)}:{dataset}"
        with h5py.File(path, "r") as f:
            if dataset not in f or not isinstance(f[dataset], h5py.Dataset):
                raise ValidationError("MeasuredSurface.dataset", dataset,
                                      f"a dataset in {os.fspath(path)}")
            ds = f[dataset]
            z = np.array(ds[()], dtype=float)
            if pixel_size is None and "pixel_size" in ds.attrs:
                pixel_size = np.asarray(ds.attrs["pixel_size"], dtype=float)
            if unit is None and "unit" in ds.attrs:
                unit = float(np.asarray(ds.attrs["unit"]).reshape(()))
        if pixel_size is None:
            raise ValidationError("MeasuredSurface.pixel_size", None,
                                  f"a pixel size in metres (argument or 'pixel_size' attribute "
                                  f"of {where})")
        return cls.from_samples(z, pixel_size, unit=1.0 if unit is None else unit, **options)


def _positive(name: str, value) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        v = math.nan
    if not (math.isfinite(v) and v > 0):
        raise ValidationError(name, value, "a real number in (0, inf)")
    return v


def _pixel(value) -> tuple[float, float]:
    arr = np.atleast_1d(np.asarray(value, dtype=float)) if not isinstance(value, str) else None
    if arr is None or arr.ndim != 1 or arr.size not in (1, 2):
        raise ValidationError("MeasuredSurface.pixel_size", value,
                              "a size in metres, or a pair (Δx, Δy)")
    dx = _positive("MeasuredSurface.pixel_size", arr[0])
    dy = _positive("MeasuredSurface.pixel_size", arr[-1])
    return dx, dy
