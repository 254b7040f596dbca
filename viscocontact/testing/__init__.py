"""Public conformance checks and hypothesis strategies for the authors of plugins.

``conformance`` checks profiles and rheologies (``check_profile``, ``check_rheology``),
``conformance_kernels`` kernels, ``conformance_solvers`` nonlinear solvers and
``conformance_methods`` solution methods, ``conformance_adhesion`` traction laws
(``check_traction_law``); the ``strategies_*`` modules generate valid components
for hypothesis tests. viscocontact's own components pass the same checks (``tests/conformance/``).
"""
