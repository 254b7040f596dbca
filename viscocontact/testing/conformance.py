"""Conformance checks for components, public so that plugin authors run them on their own classes.

Each check raises :class:`AssertionError` with a message saying which property failed, by how much,
and what the contract is (see :mod:`viscocontact.profiles.base` and
:mod:`viscocontact.rheology.base`).

Examples
--------
In a plugin's test suite::

    from viscocontact.testing.conformance import check_profile

    def test_my_profile_conforms():
        check_profile(MyProfile(amplitude=0.1))
"""
from __future__ import annotations

import tomllib
from typing import Any

import attrs
import numpy as np

TWO_PI = 2.0 * np.pi

__all__ = ["check_profile", "check_rheology"]


def _fail(name: str, message: str) -> None:
    raise AssertionError(f"{name}: {message}")


def _check_frozen(obj: Any, name: str) -> None:
    cls = type(obj)
    if not attrs.has(cls):
        _fail(name, f"{cls.__qualname__} is not an attrs class (components are frozen attrs "
                    "classes, keyword-only)")
    fields = attrs.fields(cls)
    if fields:
        first = fields[0].name
        try:
            setattr(obj, first, getattr(obj, first))
        except attrs.exceptions.FrozenInstanceError:
            pass
        else:
            _fail(name, f"{cls.__qualname__} is mutable: setting {first!r} did not raise "
                        "FrozenInstanceError (use @attrs.frozen)")
    copy = attrs.evolve(obj)
    if copy != obj:
        _fail(name, "attrs.evolve(obj) != obj: equality must compare by value "
                    "(array fields need eq=attrs.cmp_using(eq=np.array_equal))")


def _check_hashable(obj: Any, name: str) -> None:
    try:
        h = hash(obj)
    except TypeError as exc:
        _fail(name, f"hash() failed ({exc}); frozen components must be hashable (give array "
                    "fields hash=False, or store tuples)")
    if hash(attrs.evolve(obj)) != h:
        _fail(name, "equal objects have different hashes")


def _check_round_trip(section: str, obj: Any, name: str, registered: bool) -> None:
    from .._toml import dumps
    from ..components import _init_fields, _plain, build_component, dump_component

    if registered:
        try:
            table = dump_component(section, obj)
        except Exception as exc:  # PluginError: not registered
            _fail(name, f"cannot serialise through the scene format: {exc} (register the class "
                        "under the entry-point group and install the distribution)")
        parsed = tomllib.loads(dumps({section: table}))[section]
        try:
            rebuilt = build_component(section, parsed)
        except Exception as exc:
            _fail(name, f"rebuilding from the scene table {parsed!r} failed: {exc}")
    else:
        fields = _init_fields(type(obj))
        params = {k: _plain(getattr(obj, f.name)) for k, f in fields.items()}
        parsed = tomllib.loads(dumps({section: params}))[section]
        try:
            rebuilt = type(obj)(**parsed)
        except Exception as exc:
            _fail(name, f"rebuilding from the TOML parameters {parsed!r} failed: {exc}")
    if rebuilt != obj:
        _fail(name, f"round trip through the scene format changed the object: {obj!r} -> "
                    f"{rebuilt!r}")


def _max_rel(a, b, scale):
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b)))) / scale


def check_profile(profile: Any, *, registered: bool = True, rtol: float = 1e-6) -> None:
    """Check a :class:`~viscocontact.profiles.base.Profile` against its contract.

    Checks: frozen attrs value semantics and hashability; vectorised heights/slopes; periodicity
    over 2π; zero-mean heights; slopes equal to the derivative of the heights (4th-order central
    differences); ``peak()`` is the global maximum and ``amplitude`` equals it; ``statistics()``
    finite and consistent with the samples; round trip through the scene serialisation (needs the
    class registered in ``viscocontact.profiles`` unless ``registered=False``).

    Raises
    ------
    AssertionError
        Naming the failed property.
    """
    name = f"check_profile({type(profile).__qualname__})"
    from ..profiles.base import Profile

    if not isinstance(profile, Profile):
        _fail(name, "not a subclass of viscocontact.profiles.base.Profile")
    _check_frozen(profile, name)
    _check_hashable(profile, name)

    x, r, s = _profile_samples(profile, name)
    scale = max(float(np.max(np.abs(r))), 1e-300)
    sscale = max(float(np.max(np.abs(s))), scale)
    _check_periodic_zero_mean(profile, x, r, s, scale, sscale, name)
    _check_slopes(profile, x, s, sscale, rtol, name)
    top = _check_peak(profile, scale, rtol, name)
    _check_statistics(profile, top, rtol, name)
    _check_round_trip("profile", profile, name, registered)


def _profile_samples(profile: Any, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(x, heights, slopes)`` at 4096 points over a period, checked to keep the shape of
    ``x`` (also 2-d) and to be finite."""
    n = 1 << 12
    x = np.linspace(0.0, TWO_PI, n, endpoint=False) + 0.1234
    r = np.asarray(profile.heights(x), dtype=float)
    s = np.asarray(profile.slopes(x), dtype=float)
    if r.shape != x.shape or s.shape != x.shape:
        _fail(name, f"heights/slopes must keep the shape of x: {x.shape} -> {r.shape}, {s.shape}")
    if not (np.all(np.isfinite(r)) and np.all(np.isfinite(s))):
        _fail(name, "heights or slopes are not finite")
    x2 = x.reshape(64, -1)
    if np.asarray(profile.heights(x2)).shape != x2.shape:
        _fail(name, "heights are not vectorised over 2-d arrays")
    return x, r, s


def _check_periodic_zero_mean(profile: Any, x, r, s, scale: float, sscale: float,
                              name: str) -> None:
    """Heights and slopes repeat over 2π; the heights' mean over the period is zero."""
    for shift in (TWO_PI, -TWO_PI, 3 * TWO_PI):
        err = _max_rel(profile.heights(x + shift), r, scale)
        if err > 1e-9:
            _fail(name, f"heights are not 2π-periodic: max |r(x+{shift:.4g}) - r(x)|/max|r| = "
                        f"{err:.3g}")
        err = _max_rel(profile.slopes(x + shift), s, sscale)
        if err > 1e-9:
            _fail(name, f"slopes are not 2π-periodic (relative error {err:.3g})")
    mean = abs(float(np.mean(r)))
    if mean > 1e-8 * scale:
        _fail(name, f"heights must have zero mean over the period: mean = {mean:.3g}")


def _check_slopes(profile: Any, x, s, sscale: float, rtol: float, name: str) -> None:
    """The slopes are the heights' derivative (4th-order central differences) within ``rtol``."""
    h = 1e-4
    fd = (-profile.heights(x + 2 * h) + 8 * profile.heights(x + h) - 8 * profile.heights(x - h)
          + profile.heights(x - 2 * h)) / (12 * h)
    err = _max_rel(fd, s, sscale)
    if err > rtol:
        i = int(np.argmax(np.abs(fd - s)))
        _fail(name, f"slopes are not the derivative of the heights: at x = {x[i]:.6g} slope "
                    f"{s[i]:.10g} vs finite difference {fd[i]:.10g} (relative error {err:.3g} > "
                    f"{rtol:g})")


def _check_peak(profile: Any, scale: float, rtol: float, name: str) -> float:
    """``peak()`` lies in the period, is the global maximum (on 32768 points) and is the
    ``amplitude``; returns the peak height."""
    xp, top = profile.peak()
    if not (0.0 <= xp < TWO_PI):
        _fail(name, f"peak() position {xp!r} is not in [0, 2π)")
    if abs(float(profile.heights(np.asarray(xp))) - top) > 1e-9 * scale:
        _fail(name, f"peak() value {top!r} != heights(x_peak) = {float(profile.heights(xp))!r}")
    rmax = float(np.max(profile.heights(_fine_grid())))
    if rmax > top * (1 + rtol) + 1e-12 * scale:
        _fail(name, f"peak() value {top!r} is not the maximum: heights reach {rmax!r}")
    amplitude = float(profile.amplitude)
    if abs(amplitude - top) > rtol * abs(top):
        _fail(name, f"amplitude {amplitude!r} must equal the peak height Λ̃ = q0·max r = {top!r}")
    return top


def _fine_grid() -> np.ndarray:
    """32768 points over the period, for the peak and the sampled moments."""
    return np.linspace(0.0, TWO_PI, 1 << 15, endpoint=False)


def _check_statistics(profile: Any, top: float, rtol: float, name: str) -> None:
    """``statistics()`` is finite, its moments are >= 0 and agree with the sampled means of
    the squared heights and slopes, ``rms = √m0`` and its amplitude is the peak height ``top``."""
    stats = profile.statistics()
    values = attrs.asdict(stats)
    bad = {k: v for k, v in values.items() if not np.isfinite(v)}
    if bad:
        _fail(name, f"statistics() has non-finite values {bad}")
    if stats.m0 < 0 or stats.m2 < 0 or stats.m4 < 0:
        _fail(name, f"spectral moments must be >= 0: {values}")
    if abs(stats.rms - np.sqrt(stats.m0)) > 1e-6 * max(stats.rms, 1e-300):
        _fail(name, f"statistics().rms = {stats.rms!r} != sqrt(m0) = {np.sqrt(stats.m0)!r}")
    fine = _fine_grid()
    sf = np.asarray(profile.slopes(fine))
    rf = np.asarray(profile.heights(fine))
    for key, sample in (("m0", np.mean(rf**2)), ("m2", np.mean(sf**2))):
        got = getattr(stats, key)
        if abs(got - sample) > 1e-4 * max(abs(sample), 1e-300):
            _fail(name, f"statistics().{key} = {got!r} disagrees with the sampled mean {sample!r}")
    if abs(stats.amplitude - top) > rtol * abs(top):
        _fail(name, f"statistics().amplitude = {stats.amplitude!r} != peak height {top!r}")


def check_rheology(rheology: Any, *, registered: bool = True, rtol: float = 1e-8) -> None:
    """Check a :class:`~viscocontact.rheology.base.Rheology` against its contract.

    Checks: frozen attrs value semantics; ``E(ω)·C(ω) = 1``; ``E''(ω) >= 0``; the limits
    ``E(0) = E0`` and ``E(∞) = E∞``; the creep spectrum (``c_i >= 0``, ``θ_i > 0``,
    ``J(0+) = 1/E∞``, ``J(∞) = 1/E0``) consistent with the complex compliance
    ``C(ω) = J(0+) + Σ c_i/(1 + iωθ_i)``; round trip through the scene serialisation.

    Raises
    ------
    AssertionError
        Naming the failed property.
    """
    name = f"check_rheology({type(rheology).__qualname__})"
    from ..rheology.base import Rheology

    if not isinstance(rheology, Rheology):
        _fail(name, "not a subclass of viscocontact.rheology.base.Rheology")
    _check_frozen(rheology, name)

    e0 = float(rheology.relaxed_modulus)
    einf = float(rheology.instantaneous_modulus)
    tau = float(rheology.reference_time)
    if not (np.isfinite(e0) and np.isfinite(einf) and e0 > 0 and einf >= e0):
        _fail(name, f"need 0 < E0 <= E∞ (finite): E0 = {e0!r}, E∞ = {einf!r}")
    if not (np.isfinite(tau) and tau > 0):
        _fail(name, f"reference_time must be finite and > 0: {tau!r}")
    if abs(rheology.modulus_ratio - einf / e0) > 1e-12 * einf / e0:
        _fail(name, f"modulus_ratio {rheology.modulus_ratio!r} != E∞/E0 = {einf / e0!r}")

    cs = rheology.creep_spectrum()
    w = np.atleast_1d(np.asarray(cs.weights, dtype=float))
    t = np.atleast_1d(np.asarray(cs.times, dtype=float))
    if w.shape != t.shape:
        _fail(name, f"creep weights and times differ in shape: {w.shape} vs {t.shape}")
    if np.any(w < 0) or np.any(t <= 0) or not (np.all(np.isfinite(w)) and np.all(np.isfinite(t))):
        _fail(name, f"creep weights must be >= 0 and times > 0 (finite): {w}, {t}")
    if abs(cs.instantaneous - 1.0 / einf) > 1e-10 / einf:
        _fail(name, f"J(0+) = {cs.instantaneous!r} != 1/E∞ = {1.0 / einf!r}")
    if abs(cs.instantaneous + w.sum() - 1.0 / e0) > 1e-10 / e0:
        _fail(name, f"J(∞) = J(0+) + Σc = {cs.instantaneous + w.sum()!r} != 1/E0 = {1.0 / e0!r}")

    tmin = float(t.min()) if t.size else tau
    tmax = float(t.max()) if t.size else tau
    omega = np.logspace(np.log10(1e-4 / tmax), np.log10(1e4 / tmin), 240)
    e = np.asarray(rheology.complex_modulus(omega))
    c = np.asarray(rheology.complex_compliance(omega))
    if e.shape != omega.shape:
        _fail(name, f"complex_modulus must keep the shape of ω: {omega.shape} -> {e.shape}")
    err = float(np.max(np.abs(e * c - 1.0)))
    if err > rtol:
        _fail(name, f"E(ω)·C(ω) != 1 (max deviation {err:.3g})")
    if np.any(e.imag < -1e-12 * np.abs(e)):
        i = int(np.argmin(e.imag))
        _fail(name, f"loss modulus E'' must be >= 0: E''({omega[i]:.3g}) = {e.imag[i]:.3g}")
    c_spec = cs.instantaneous + np.sum(w / (1.0 + 1j * omega[:, None] * t), axis=-1)
    err = float(np.max(np.abs(c - c_spec) / np.abs(c)))
    if err > 1e-7:
        _fail(name, f"complex compliance disagrees with the creep spectrum, C(ω) = J(0+) + "
                    f"Σ c_i/(1+iωθ_i): max relative deviation {err:.3g}")
    # θ are creep (retardation) times; relaxation times are up to β = E∞/E0 times shorter, so the
    # glassy limit is probed β times further out (E(ω) - E∞ ~ E∞ β/(ω θ_min)).
    beta = max(einf / e0, 1.0)
    lo = complex(np.asarray(rheology.complex_modulus(np.array([1e-9 / tmax])))[0])
    hi = complex(np.asarray(rheology.complex_modulus(np.array([1e9 * beta / tmin])))[0])
    if abs(lo - e0) > 1e-6 * e0:
        _fail(name, f"E(ω → 0) = {lo!r} != relaxed_modulus E0 = {e0!r}")
    if abs(hi - einf) > 1e-6 * einf:
        _fail(name, f"E(ω → ∞) = {hi!r} != instantaneous_modulus E∞ = {einf!r}")

    _check_round_trip("rheology", rheology, name, registered)
