"""Components of a scene built from their tables: a registered ``kind`` and its parameters.

Each component section of a scene (``[profile]``, ``[rheology]``, ``[kernel]``, ``[adhesion]``,
``[solver]``, ``[method]``) is built generically from its entry-point registry,
``registry.get(kind)(**params)``, with every error naming ``section.key``, the value and the
allowed values (a mistyped kind or key gets a "did you mean"). Adhesion models, solvers and
methods whose module cannot be imported yet are kept as a :class:`ComponentSpec` (kind and
parameters) and built on demand. :func:`dump_component` writes a component back as its table.
"""
from __future__ import annotations

import difflib
import re
import types
from typing import Any, Mapping

import attrs
import numpy as np

from . import _registry
from ._numbers import _overflows
from .errors import PluginError, ValidationError


#: Scene sections and the registry that builds each component section.
COMPONENT_SECTIONS = {"profile": "profiles", "rheology": "rheologies", "kernel": "kernels",
                      "adhesion": "adhesion", "solver": "solvers", "method": "methods"}


def did_you_mean(word: Any, names) -> str:
    """`` (did you mean 'x'?)`` for the closest of ``names`` to a mistyped ``word``, or ``""``."""
    close = difflib.get_close_matches(word, list(names), n=1) if isinstance(word, str) else []
    return f" (did you mean {close[0]!r}?)" if close else ""


def _registry_for(section: str) -> _registry.Registry:
    return _registry.REGISTRIES[COMPONENT_SECTIONS[section]]


def _init_fields(cls: type) -> dict[str, attrs.Attribute]:
    """``{keyword: attribute}`` of the constructor arguments of an attrs class."""
    if not attrs.has(cls):
        raise PluginError(f"{cls.__module__}.{cls.__qualname__} is not an attrs class; components "
                          "must be frozen attrs classes")
    return {f.alias: f for f in attrs.fields(cls) if f.init}


def _plain(value: Any) -> Any:
    """A component field value as plain data (numpy → lists/floats, attrs → dicts)."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, (np.floating, np.integer, np.bool_)):
        return value.item()
    if attrs.has(type(value)):
        return {k: _plain(getattr(value, f.name)) for k, f in _init_fields(type(value)).items()}
    if isinstance(value, Mapping):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    return value


@attrs.frozen(kw_only=True)
class ComponentSpec:
    """A component given by its registered name and parameters, built on demand.

    Used for components whose class cannot be imported when the scene is read (and by
    :meth:`Scene.resolve`). ``resolve(section)`` builds it with the same checks as a scene file.
    """

    kind: str = attrs.field(validator=attrs.validators.instance_of(str))
    params: Mapping[str, Any] = attrs.field(
        factory=dict, converter=lambda p: types.MappingProxyType(dict(p)), hash=False)

    def resolve(self, section: str) -> Any:
        """The component object (``section`` is ``"solver"``, ``"adhesion"``, ...)."""
        return build_component(section, {"kind": self.kind, **self.params})


def build_component(section: str, table: Mapping[str, Any], *, lazy: bool = False) -> Any:
    """Build the component of scene section ``section`` from its table (``kind`` + parameters).

    Raises :class:`ValidationError` naming ``section.key`` for an unknown kind, an unknown or
    missing key and a rejected value; a plugin that fails to import raises :class:`PluginError`,
    unless ``lazy`` is set, in which case a :class:`ComponentSpec` is returned instead.
    """
    registry = _registry_for(section)
    params = dict(table)
    kind = params.pop("kind", None)
    try:
        if not isinstance(kind, str):
            raise PluginError(f"{section}.kind must be a string")
        cls = registry.get(kind)  # cached after the first look-up
    except PluginError as exc:
        names = registry.names()
        if isinstance(kind, str) and kind in names:  # registered, but failed to load
            if lazy and isinstance(exc.__cause__, ImportError):
                return ComponentSpec(kind=kind, params=params)
            raise
        hint = did_you_mean(kind, names)
        raise ValidationError(f"{section}.kind", kind, f"one of the registered {registry.group} "
                                                        f"names {names}{hint}") from None
    return _instantiate(section, kind, cls, params)


def _instantiate(section: str, kind: str, cls: type, params: dict[str, Any]) -> Any:
    fields = _init_fields(cls)
    for key in params:
        if key not in fields:
            raise ValidationError(f"{section}.{key}", params[key],
                                  f"a key of {section} kind {kind!r}: one of {sorted(fields)}"
                                  f"{did_you_mean(key, fields)}")
    required = [k for k, f in fields.items() if f.default is attrs.NOTHING]
    for key in required:
        if key not in params:
            raise ValidationError(f"{section}.{key}", None,
                                  f"a value ({section} kind {kind!r} requires {required})")
    params = _nested_options(section, cls, fields, params)
    try:
        return cls(**params)
    except ValidationError as exc:
        attr = exc.field.rsplit(".", 1)[-1]  # "StandardLinearSolid.beta" -> "rheology.beta"
        raise ValidationError(f"{section}.{attr}", exc.value, exc.allowed) from exc
    except (TypeError, ValueError, OverflowError) as exc:
        message = str(exc).replace("\n", " ")
        named = [k for k in fields if re.search(rf"\b{re.escape(k)}\b", message)]
        if isinstance(exc, OverflowError) and len(named) != 1:  # "int too large to convert"
            named = [k for k, v in params.items() if _overflows(v)]
        if len(named) == 1:
            raise ValidationError(f"{section}.{named[0]}", params.get(named[0]), message) from exc
        raise ValidationError(section, params, message) from exc


def _nested_options(section: str, cls: type, fields: dict, params: dict) -> dict:
    """Build attrs-typed fields given as sub-tables (``[solver.options]``) into their class."""
    nested = [k for k, v in params.items() if isinstance(v, Mapping)]
    if not nested:
        return params
    try:
        attrs.resolve_types(cls)
    except Exception:  # unresolvable annotations: pass the tables through unchanged
        return params
    out = dict(params)
    for key in nested:
        ftype = fields[key].type
        if isinstance(ftype, type) and attrs.has(ftype):
            out[key] = _instantiate(f"{section}.{key}", ftype.__name__, ftype, dict(params[key]))
    return out


def dump_component(section: str, component: Any) -> dict[str, Any]:
    """``{"kind": registered name, **parameters}`` of a component or :class:`ComponentSpec`."""
    if isinstance(component, ComponentSpec):
        return {"kind": component.kind,
                **{k: _plain(v) for k, v in component.params.items() if v is not None}}
    out = {"kind": kind_of(section, component)}
    for key, f in _init_fields(type(component)).items():
        value = getattr(component, f.name)
        if value is None and f.default is None:
            continue  # TOML has no null: an omitted key rebuilds the default
        out[key] = _plain(value)
    return out


def kind_of(section: str, component: Any) -> str:
    """The registered name of a component (or of a :class:`ComponentSpec`)."""
    if isinstance(component, ComponentSpec):
        return component.kind
    registry = _registry_for(section)
    cls = type(component)
    for name, cached in registry._cache.items():  # classes already looked up (no metadata scan)
        if cached is cls:
            return name
    return registry.name_of(component)


def _param(component: Any, key: str) -> Any:
    if isinstance(component, ComponentSpec):
        return component.params.get(key)
    return getattr(component, key, None)


def _has_param(component: Any, key: str) -> bool | None:
    """Whether the component takes ``key`` (``None`` if unknown: an unresolved spec)."""
    if isinstance(component, ComponentSpec):
        return None
    return key in _init_fields(type(component))
