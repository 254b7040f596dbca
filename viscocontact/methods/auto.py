"""The planned method: the spectral method for adhesionless scenes, the BEM for adhesive ones.

An adhesionless equilibrium is unique and does not depend on the loading path, so it needs no
approach path and no edge energy balance: a uniform-grid spectral solve finds it directly, to a
stated tolerance. An adhesive scene needs the energy balance at every edge, which only the BEM has
(the spectral method applies a finite-range cohesive law on its grid, following the approach on
its coarsest grid only, so it serves as a cross-check and is asked for by name). When
the spectral method cannot reach the requested tolerance on the largest grid it allows, the BEM
finishes the job seeded with the grid's contact set (where the BEM does not converge within
:data:`FINISH_RESTARTS` contact-set changes, the grid's converged answer stands, with its
estimate); when the grid solve does not converge at all (a very stiff solid at ζ ~ 1, whose
trailing-edge layer the grid does not resolve), the BEM solves the scene from the caller's start.
The other way round, when the BEM does not converge on an adhesive scene (or estimates its error
above the tolerance) and the scene has a finite-range law that the grid applies, the spectral
method solves it, and its answer is returned when it meets the tolerance: the events say which
method ran and why. The grid follows the approach from first touch on its coarsest grid and
carries that state to the finer ones: the same history on another discretisation, which can end
on another branch where the approach meets a fold or a birth, so a converged BEM answer above the
tolerance is first solved again on finer meshes from its own edges (:meth:`Auto._refined`).
"""
from __future__ import annotations

from typing import ClassVar

import attrs
import numpy as np

from .._validation import in_range, int_range
from .base import SolutionMethod


#: Restarts (contact-set changes) allowed to the BEM finishing a grid solve from the grid's
#: contact set (campaign seed 226: 4; seed 89's thin stiff layer grew from 18 contacts to 154
#: over 35 restarts, 100 s, without settling).
FINISH_RESTARTS = 20


@attrs.frozen(kw_only=True)
class Auto(SolutionMethod):
    """Chooses the method from the scene (see the module docstring).

    Parameters
    ----------
    tolerance : float
        Relative accuracy of Ã and μ asked of the spectral method.
    finish_with_bem : bool
        When the spectral estimate stays above ``tolerance``, solve again with the BEM from the
        grid's contact set; when the grid solve does not converge, with the BEM from ``initial``
        (the result then comes from the BEM and says so in its events).
    max_points : int or None
        Largest grid the spectral method may use (``None``: its default).
    spectral_fallback : bool
        When the BEM, chosen for an adhesive scene, does not converge or estimates its error
        above ``tolerance``, solve the scene on the spectral method's grid where the grid
        applies (a finite-range law, :meth:`Spectral.unsupported`); its answer is returned
        when it converges within the tolerance (or the BEM's did not converge at all), and
        the events say which method ran and why.
    """

    name: ClassVar[str] = "auto"

    tolerance: float = attrs.field(default=1e-3, validator=in_range(1e-8, 0.1))
    finish_with_bem: bool = attrs.field(default=True,
                                        validator=attrs.validators.instance_of(bool))
    max_points: int | None = attrs.field(default=None, validator=attrs.validators.optional(
        int_range(64, 1 << 22)))
    spectral_fallback: bool = attrs.field(default=True,
                                          validator=attrs.validators.instance_of(bool))

    def choose(self, problem) -> tuple[SolutionMethod, str]:
        """The method a solve of ``problem`` takes, and why."""
        from .bem import BEM

        spectral = self.spectral()
        gamma = float(problem.adhesion.work_of_adhesion)
        adhesion = problem.adhesion
        if gamma > 0 and adhesion.cohesive_law(1.0) is None and adhesion.traction(0.0) is not None:
            # a traction law without a Dugdale form has no edge condition for the BEM
            return spectral, (f"traction law on every gap ({type(adhesion).__name__}): no edge "
                              "condition for the boundary-element method; the grid applies it "
                              "cell by cell")
        if gamma > 0:
            # the grid applies a cohesive law too (a cross-check of the BEM), but an adhesive
            # equilibrium depends on the path that reached it, which the BEM follows
            return BEM(), (f"adhesive scene (work of adhesion {gamma:g}): the equilibrium "
                           "depends on the loading path, which the boundary-element method "
                           "follows from first touch")
        reason = spectral.unsupported(problem)
        if reason is None:
            return spectral, ("adhesionless scene: the equilibrium does not depend on the path; "
                              f"a uniform grid reaches the tolerance {self.tolerance:g}")
        return BEM(), reason

    def spectral(self) -> SolutionMethod:
        from .spectral import Spectral

        if self.max_points is None:
            return Spectral(tolerance=self.tolerance)
        return Spectral(tolerance=self.tolerance, max_points=self.max_points)

    def solve(self, problem, initial=None, *, fields: bool = False, prepared=None):
        from .bem import BEM

        from .._events import logger

        method, reason = self.choose(problem)
        logger.info("auto: method %s: %s", method.name, reason)
        result = method.solve(problem, initial, fields=fields, prepared=prepared)
        events = result.extras.setdefault("events", [])
        events.insert(0, f"method {method.name}: {reason}")
        if method.name == BEM.name:
            return self._spectral_instead(problem, result, fields, prepared)
        if self.finish_with_bem and not result.converged:
            # a grid solve that fails says nothing about the contact set: the BEM starts where
            # the caller asked (its approach path from first touch without a start)
            finished = BEM().solve(problem, initial, fields=fields, prepared=prepared)
            finished.extras.setdefault("events", []).insert(
                0, f"method bem: the {method.name} solve did not converge ({result.message})")
            return finished
        if (self.finish_with_bem and result.converged
                and not result.extras.get("tolerance_met", True)):
            estimate = result.extras.get("error_estimate")
            start = result if result.n_contacts or result.full_contact else initial
            # a finish starts from the grid's contact set, a few contact-set changes from the
            # BEM's equilibrium; one that keeps changing it gives the grid's answer back
            finishing = attrs.evolve(problem, max_restarts=min(problem.max_restarts,
                                                               FINISH_RESTARTS))
            finished = BEM().solve(finishing, start, fields=fields, prepared=prepared)
            why = (f"the grid's error estimate {estimate:.2g} stayed above the tolerance "
                   f"{self.tolerance:g}")
            if not finished.converged:
                # the grid's converged answer, with its estimate, is the better one to hand on
                # than a failure (an adhesionless equilibrium is unique: the two methods look
                # for the same state)
                events.append(f"the bem, tried from the {method.name} contact set because {why}, "
                              f"did not converge ({finished.message}); the grid's answer stands")
                return result
            finished.extras.setdefault("events", []).insert(
                0, f"method bem from the {method.name} contact set: {why}")
            return finished
        return result

    def _spectral_instead(self, problem, result, fields: bool, prepared):
        """``result`` of the BEM, or the spectral method's solve of ``problem`` when the BEM
        failed (or estimates its error above the tolerance) and the grid applies to the scene
        (:meth:`Spectral.unsupported`) and solves it. Either way the events say which ran."""
        from .._events import logger

        why = _shortfall(result, self.tolerance)
        if why is None or not self.spectral_fallback:
            return result
        spectral = self.spectral()
        unsupported = spectral.unsupported(problem)
        if unsupported is not None:
            result.extras["events"].append(f"the spectral method was not tried: {unsupported}")
            return result
        # the grid follows the approach on its coarsest grid only, where a fold or a birth can
        # lead to another branch: a converged answer short of the tolerance is first refined on
        # its own branch
        result = self._refined(problem, result, fields, prepared)
        why = _shortfall(result, self.tolerance)
        if why is None:
            return result
        logger.info("auto: method spectral: the bem solve %s", why)
        grid = spectral.solve(problem, fields=fields, prepared=prepared)
        if _shortfall(grid, self.tolerance) is None or (
                grid.converged and not result.converged):
            # the choice first, then why the grid solved it, then the grid's own events
            grid.extras.setdefault("events", [])[:0] = [
                result.extras["events"][0],
                f"method spectral: the bem solve {why}; the grid solves the scene (it follows "
                "the approach from first touch on its coarsest grid, then refines that state)"]
            return grid
        result.extras["events"].append(
            f"the spectral method, tried after the bem solve {why}, "
            f"{_shortfall(grid, self.tolerance)}")
        return result

    def _refined(self, problem, result, fields: bool, prepared):
        """``result`` of the BEM, solved again from its own edges at the same control on a mesh
        twice as fine (:func:`~.bem.estimate.finer`) while it converged with an estimate above
        the tolerance: the same equilibrium, resolved to what the grid would be asked for. A
        refinement is kept while its estimate falls and its contact set stays; the events say
        each one. A result that did not converge is returned as it is."""
        import attrs

        from .bem import BEM
        from .bem.estimate import finer

        while result.converged and np.isfinite(result.error_estimate) and (
                result.error_estimate > self.tolerance):
            disc = finer(problem.discretization)
            if disc == problem.discretization:
                break
            refining = attrs.evolve(problem, discretization=disc)
            refined = BEM().solve(refining, result, fields=fields, prepared=prepared)
            kept = (refined.converged and refined.n_contacts == result.n_contacts
                    and refined.error_estimate < result.error_estimate)
            events = result.extras["events"]
            events.append(
                f"the bem estimated its error at {result.error_estimate:.2g}, above the "
                f"tolerance {self.tolerance:g}: solved again with {disc.elements} elements per "
                f"contact, {'kept' if kept else 'not kept'} ("
                + (f"estimate {refined.error_estimate:.2g})" if refined.converged
                   else f"{refined.message})"))
            if not kept:
                break
            refined.extras["events"][:0] = events
            problem, result = refining, refined
        return result

    def plan_steps(self, problem, prepared) -> tuple:
        from ..plan import PlanStep

        method, reason = self.choose(problem)
        # the choice and its reason stand for the chosen method's own "method" step
        inner = [step for step in method.plan_steps(problem, prepared) if step.stage != "method"]
        return (PlanStep(stage="method", choice=method.name, reason=reason), *inner)


def _shortfall(result, tolerance: float) -> str | None:
    """Why ``result`` is not an answer to hand on (None: it is): it did not converge, or its
    method's error estimate (finite) is above ``tolerance``."""
    if not result.converged:
        return f"did not converge ({result.message})"
    estimate = result.error_estimate
    if np.isfinite(estimate) and estimate > tolerance:
        return f"estimates its error at {estimate:.2g}, above the tolerance {tolerance:g}"
    return None
