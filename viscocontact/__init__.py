"""viscocontact: adhesive, rough, viscoelastic contact in steady sliding.

A rigid periodic profile slides at speed V over a linear viscoelastic half-plane or layer; the
steady-state contact problem (Mastropasqua's thesis, Chapter 4) is solved with a boundary-element
method on edge-clustered meshes and a viscoelastic Griffith energy balance at every contact edge.
All numerics run in the dimensionless groups of the thesis's eq. 4.17.
"""
from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("viscocontact")
except PackageNotFoundError:  # pragma: no cover - running from a source tree
    __version__ = "0.0.0+unknown"

from .errors import ConvergenceError, PluginError, ValidationError, ViscoContactError  # noqa: E402

__all__ = ["ConvergenceError", "PluginError", "ValidationError", "ViscoContactError", "__version__"]
