"""Entry-point registry of components.

One small generic class serves the seven component kinds. Listing names imports nothing; looking a
name up loads the entry point, checks that it is a subclass of the kind's base class, and caches it.
An unknown name lists the registered ones with a "did you mean"; a broken plugin fails only when it
is asked for, chained to its original ImportError. When two distributions register one name for
different targets, the first found is used and a :class:`~viscocontact.errors.PluginWarning` names
both. Built-ins are registered through the package's own entry points, exactly like third-party
plugins.
"""
from __future__ import annotations

import difflib
from importlib import metadata
from typing import Any, Callable, Iterable

from .errors import PluginError, PluginWarning, warn_user

GROUPS = {
    "profiles": "viscocontact.profiles",
    "rheologies": "viscocontact.rheologies",
    "kernels": "viscocontact.kernels",
    "solvers": "viscocontact.solvers",
    "adhesion": "viscocontact.adhesion",
    "methods": "viscocontact.methods",
    "surfaces": "viscocontact.surfaces",
}


class Registry:
    """Components of one kind, found through the entry-point group ``group``.

    Parameters
    ----------
    group : str
        Entry-point group, e.g. ``"viscocontact.rheologies"``.
    base : callable returning a class
        Returns the abstract base class every entry must subclass (a callable so that the base's
        module is imported only when a component is loaded).
    entry_points : callable, optional
        Returns the entry points to use (tests pass fakes); defaults to ``importlib.metadata``.
    """

    def __init__(self, group: str, base: Callable[[], type],
                 entry_points: Callable[[], Iterable[metadata.EntryPoint]] | None = None):
        self.group = group
        self._base = base
        self._entry_points = entry_points or (lambda: metadata.entry_points(group=group))
        self._cache: dict[str, type] = {}
        self._warned: set[tuple[str, str, str]] = set()

    def _eps(self) -> dict[str, metadata.EntryPoint]:
        found: dict[str, metadata.EntryPoint] = {}
        for ep in self._entry_points():
            # First registration wins; a clash with another target is warned about (once).
            kept = found.setdefault(ep.name, ep)
            if kept is not ep and kept.value != ep.value:
                self._warn_clash(kept, ep)
        return found

    def _warn_clash(self, kept: metadata.EntryPoint, dropped: metadata.EntryPoint) -> None:
        key = (kept.name, kept.value, dropped.value)
        if key in self._warned:
            return
        self._warned.add(key)
        warn_user(
            f"{self.group} name {kept.name!r} is registered twice: by {_dist(kept)} "
            f"({kept.value}), which is used, and by {_dist(dropped)} ({dropped.value}), which "
            f"is ignored; uninstall one of them, or ask its authors to register another name",
            PluginWarning)

    def names(self) -> list[str]:
        """Registered names (imports nothing)."""
        return sorted(self._eps())

    def describe(self) -> list[dict[str, Any]]:
        """``[{"name": ..., "distribution": ...}, ...]`` for every registered name."""
        return [{"name": name, "distribution": _dist(ep, None), "value": ep.value}
                for name, ep in sorted(self._eps().items())]

    def __contains__(self, name: str) -> bool:
        return name in self._eps()

    def get(self, name: str) -> type:
        """The class registered as ``name``."""
        if name in self._cache:
            return self._cache[name]
        eps = self._eps()
        if name not in eps:
            close = difflib.get_close_matches(name, list(eps), n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            raise PluginError(f"unknown {self.group.split('.')[-1]} kind {name!r}: registered are "
                              f"{sorted(eps)}{hint}")
        try:
            cls = eps[name].load()
        except Exception as exc:  # a broken plugin fails only when asked for
            raise PluginError(f"{self.group} entry {name!r} ({eps[name].value}) failed to load: "
                              f"{exc}") from exc
        base = self._base()
        if not (isinstance(cls, type) and issubclass(cls, base)):
            raise PluginError(f"{self.group} entry {name!r} ({eps[name].value}) is not a subclass "
                              f"of {base.__module__}.{base.__qualname__}")
        self._cache[name] = cls
        return cls

    __getitem__ = get

    def name_of(self, obj: Any) -> str:
        """The registered name of a component instance or class (the tag written to files)."""
        cls = obj if isinstance(obj, type) else type(obj)
        target = f"{cls.__module__}:{cls.__qualname__}"
        for name, ep in sorted(self._eps().items()):
            if ep.value.replace(" ", "") == target:
                return name
        for name, cached in self._cache.items():
            if cached is cls:
                return name
        raise PluginError(f"{target} is not registered in {self.group}")


def _dist(ep: metadata.EntryPoint, unknown: Any = "an unknown distribution") -> Any:
    """The name of the distribution that provides ``ep`` (``unknown`` when it has none)."""
    name = getattr(getattr(ep, "dist", None), "name", None)
    return name if name else unknown


def _base(kind: str) -> Callable[[], type]:
    def load():
        import importlib

        module, attr = {
            "profiles": ("viscocontact.profiles.base", "Profile"),
            "rheologies": ("viscocontact.rheology.base", "Rheology"),
            "kernels": ("viscocontact.kernels.base", "GreenKernel"),
            "solvers": ("viscocontact.solvers.base", "NonlinearSolver"),
            "adhesion": ("viscocontact.adhesion.base", "AdhesionModel"),
            "methods": ("viscocontact.methods.base", "SolutionMethod"),
            "surfaces": ("viscocontact.areal.surfaces.base", "Surface"),
        }[kind]
        return getattr(importlib.import_module(module), attr)

    return load


profiles = Registry(GROUPS["profiles"], _base("profiles"))
rheologies = Registry(GROUPS["rheologies"], _base("rheologies"))
kernels = Registry(GROUPS["kernels"], _base("kernels"))
solvers = Registry(GROUPS["solvers"], _base("solvers"))
adhesion = Registry(GROUPS["adhesion"], _base("adhesion"))
methods = Registry(GROUPS["methods"], _base("methods"))
surfaces = Registry(GROUPS["surfaces"], _base("surfaces"))

REGISTRIES = {"profiles": profiles, "rheologies": rheologies, "kernels": kernels,
              "solvers": solvers, "adhesion": adhesion, "methods": methods,
              "surfaces": surfaces}
