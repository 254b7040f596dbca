"""Hypothesis runs the same examples on every machine and in every run (``derandomize``), and
gives no example a deadline: a loaded machine is slower, not wrong. A test's own ``@settings``
override only what they name. ``pytest --hypothesis-profile=explore`` draws new examples, to
look for failures by hand."""
from hypothesis import settings

settings.register_profile("ci", derandomize=True, deadline=None)
settings.register_profile("explore", deadline=None)
settings.load_profile("ci")
