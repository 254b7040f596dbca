r"""Uniform-grid spectral method for adhesionless scenes and cohesive laws: :class:`Spectral`.

A :class:`~viscocontact.methods.base.SolutionMethod` for the scenes of
:class:`~viscocontact.problem.ContactProblem` without adhesion (a uniform grid has no edge energy
balance: :meth:`Spectral.unsupported` says so for ``work_of_adhesion > 0``), in the same
dimensionless groups (thesis eq. 4.17), the same penetration ``Δ̃`` (from the mean plane of the
deformed solid, or from the far surface of a compressible layer through ``c0``) and the same result
schema: area, load, penetration, friction (eq. 4.16), edges in the BEM's window, closed contact
and no contact as the BEM reports them.

Method
------
* Grid (:mod:`~viscocontact.methods.spectral.grid`): ``N`` cells of constant pressure centred at
  ``x_peak + k h``, the contact conditions collocated at the centres.
* Operator (:mod:`~viscocontact.methods.spectral.operator`): ``u = A p`` with ``A`` circulant,
  applied by ``scipy.fft``; its eigenvalues from the prepared kernel's Fourier multiplier (any
  rheology with a creep spectrum, half-plane and layers), the instantaneous part in closed form
  (Clausen), the rest by alias sums. Cached per (prepared kernel, ``N``) in
  :class:`SpectralPrepared`.
* Solvers (:mod:`~viscocontact.methods.spectral.solvers`): preconditioned Polonsky-Keer conjugate
  gradients when ``A`` is symmetric (elastic, or ζ at a limit), a primal-dual active set with
  right-preconditioned GMRES otherwise (viscoelastic), and a Fischer-Burmeister Newton method
  where the active set fails (a strongly non-symmetric operator); load control
  (``p̃∞`` given) and penetration control (``Δ̃`` given).
* Grids (:mod:`~viscocontact.methods.spectral.ladder`): nested iteration from at most 256 cells,
  each grid starting from the previous one's solution; from the first grid with
  ``32·√(1e-3/tolerance)`` cells per shortest wavelength of the profile
  (:attr:`Profile.shortest_wavelength`) on, the change of ``Ã`` and ``μ`` from the previous grid
  gives the error estimate (Richardson at order 1, and at least half the previous change: see
  below), and the grid is doubled until it meets the tolerance or reaches ``max_points``. ``μ`` is
  measured relative to ``max(|μ|, friction_floor·√m2)``.
* Edges (:mod:`~viscocontact.methods.spectral.edges`): to a fraction of a cell from the square-root
  field at an adhesionless edge: left edges from the pressures of the two outermost loaded cells,
  right edges from the gaps of the two first free cells (maps fitted on Westergaard's solution).
* Friction: eq. 4.16 exactly for the piecewise-constant pressure (``Σ p_k Δr_k``);
  ``extras["friction_dissipation"]`` is ``μ`` from the power fed into the solid (the loss
  compliance and the pressure spectrum), an independent check that converges to it.

Accuracy (measured, 2026-11-24)
-------------------------------
Default tolerance 1e-3. Westergaard (sinusoid on an elastic half-plane), relative error of ``Ã``
and the method's estimate:

=============  ========  ========  =====  ==========================
p̃∞             error     estimate  cells  BEM, 64 elements (error)
=============  ========  ========  =====  ==========================
0.02           +5.9e-05  4.1e-04   1024   -2.4e-04
0.1 / 0.3      +7e-05    2e-04     256    -2.3e-04 / -2.2e-04
0.6 / 0.9      -3.0e-04  4.7e-04   256    -1.6e-04 / -2.0e-04
0.99           -7.2e-05  9.3e-04   256    -2.2e-04
=============  ========  ========  =====  ==========================

Against the BEM (default mesh, Broyden; standard linear solid β = 10, p̃∞ = 0.3), relative
differences of ``Ã``, ``μ`` and ``Δ̃``: sinusoid at ζ = 1 +1.5e-4, -2.6e-5, -2.1e-5; rough
(``N_q = 8``, seeds 1 and 3) at ζ = 1 within 1.0e-4, 2.5e-5, 6e-6; confined (d̃ = 1) and free
(d̃ = 2) layers at ζ = 0.1 within 2.3e-4, 1.9e-4, 3e-6. At ζ = 1e-2 (``N_q = 8``, seed 1) ``μ``
differs by 1.5e-3: the BEM's error at 64 elements (1.5e-3 against its own 256, which agree
with this method to 1e-5).

Thesis rough profile (H = 0.8, ``N_q = 50``, seeds 0-4, p̃∞ = 0.25) at the default tolerance,
against 131072 cells: ``|Ã|`` errors 7e-7 to 1.7e-4 (elastic) and 1e-5 to 1.5e-4 (β = 10,
ζ = 1e-2), ``μ`` within 3.9e-4 (relative to ``max(|μ|, 1e-2√m2)``), on 4096-32768 cells; the
FFT peer of ``benchmarks/peer_fft.py`` at 8192 cells is off by up to 1.0e-3 (elastic) and
1.8e-3 (viscoelastic) in ``Ã``.

Observed orders (least squares over 512-16384 cells, ``benchmarks/spectral.py --orders``):
``Ã`` 1.6-3.2 on Westergaard (p̃∞ = 0.05, 0.3, 0.7, 0.95), 1.8 on the rough profile (elastic and
ζ = 1e-2); ``μ`` 2.0 (elastic, where it is discretisation error around 0) and 2.5 (ζ = 1e-2).
The errors scatter about these rates by a factor of a few (an edge's sub-cell position depends
on where it falls in its cell, two contacts a few cells apart, a leading edge whose memory
length spans a few cells), so the estimate assumes order 1: the change between the last two
grids, and at least half the change between the two before. It was at or above the error in
every case above.

Speed (``benchmarks/spectral.py``, same process, alternating, median of 3 runs, seeds 0-4, on
the 2-core machine shared with other jobs): at the default tolerance the thesis rough point
takes 0.41 times the time of the FFT peer at 8192 cells, median over the seeds (0.29-0.76 per
seed; the slowest refines to 32768 cells), elastic, and 0.51 times (0.38-0.53), β = 10 at
ζ = 1e-2: 44 ms against 107 ms and 64 ms against 126 ms, from scratch (profile and kernel
preparation included). Where a cold solve spends its time (cProfile, five seeds): elastic,
about 40 % in the FFT products, 25 % in the rest of the conjugate-gradient steps, 10 % in
:meth:`ContactProblem.prepare` (peak, statistics), 8 % locating the edges; viscoelastic, 35 % in
the FFT products, 15 % in the rest of GMRES, 20 % in :meth:`ContactProblem.prepare` (with the
memory tables the BEM needs and this method does not) and 9 % in the eigenvalues of the grids
(cached by :class:`SpectralPrepared` along a sweep).

Cohesive law (:mod:`~viscocontact.methods.spectral.cohesive`): a finite-range adhesion model
with a grid form (:meth:`AdhesionModel.cohesive_law`; :class:`~viscocontact.adhesion.MaugisDugdale`)
is applied cell by cell, a uniform tension σ̃0 wherever the gap is below the range, its tips
between cells; no edge condition, and cohesive runs without contact are allowed. The grid must
resolve the zones (:data:`~viscocontact.methods.spectral.cohesive.CELLS_PER_ZONE` cells per
quasi-static zone on the first trusted grid), so this is the low-Tabor side: the cross-check of
the BEM's cohesive zones where they are wide (``docs/cohesive.md``, "The spectral
cross-check"). The law is non-convex, so a scene may have several equilibria; the solve
follows the project's default history, the approach from first touch
(:mod:`~viscocontact.methods.spectral.approach`: a continuation in ``Δ̃`` on the first grid, its
states and events in ``extras["history"]`` and ``extras["path_events"]``), as the BEM does;
:class:`~viscocontact.methods.auto.Auto` keeps adhesive scenes on the BEM. A model with only a
smooth traction (:meth:`AdhesionModel.traction`; :class:`~viscocontact.adhesion.LennardJones`)
is applied cell by cell as a tension at every gap (:mod:`~viscocontact.methods.spectral.traction`).

Limits: adhesive scenes without a cohesive law, short-range laws (use the BEM); contacts narrower than two cells get their cells as
their extent (the estimate sees them and refines); a grid solve that does not converge (all
its solvers: :mod:`~viscocontact.methods.spectral.solvers`) says so.
"""
from .method import Spectral, SpectralPrepared

__all__ = ["Spectral", "SpectralPrepared"]
