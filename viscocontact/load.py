"""The load control of a scene: the mean pressure p̃∞ or the penetration Δ̃ (equation 4.17)."""
from __future__ import annotations

from typing import Any, Mapping, cast

import attrs

from ._numbers import _as_float, _check_number
from .components import did_you_mean
from .errors import ValidationError


def _optional_number(inst, attribute, value):
    if value is not None:
        _check_number(f"load.{attribute.name}", value)


@attrs.frozen(kw_only=True)
class Load:
    """The load control: exactly one of ``mean_pressure`` (p̃∞, equation 4.17, any finite real;
    negative is a tensile load, legal with adhesion) and ``penetration`` (Δ̃ = Δ/Λ, finite)."""

    mean_pressure: float | None = attrs.field(default=None, converter=_as_float,
                                              validator=_optional_number)
    penetration: float | None = attrs.field(default=None, converter=_as_float,
                                            validator=_optional_number)

    def __attrs_post_init__(self):
        if (self.mean_pressure is None) == (self.penetration is None):
            raise ValidationError("load", {"mean_pressure": self.mean_pressure,
                                           "penetration": self.penetration},
                                  "exactly one of load.mean_pressure and load.penetration")

    @property
    def controlled(self) -> str:
        """``"mean_pressure"`` (load control) or ``"penetration"`` (displacement control)."""
        return "mean_pressure" if self.mean_pressure is not None else "penetration"

    @property
    def value(self) -> float:
        """The controlled value."""
        # exactly one of the two is set (checked at construction)
        return cast(float, self.mean_pressure if self.mean_pressure is not None
                    else self.penetration)


def _as_load(value: Any) -> Any:
    """``Scene(load={"mean_pressure": 0.3})``: a mapping is read as the ``[load]`` table."""
    if not isinstance(value, Mapping):
        return value
    for key in value:
        if key not in ("mean_pressure", "penetration"):
            raise ValidationError(f"load.{key}", value[key],
                                  "a key of [load]: 'mean_pressure' or 'penetration'"
                                  f"{did_you_mean(key, ('mean_pressure', 'penetration'))}")
    return Load(**value)


def _is_load(inst, attribute, value):
    if not isinstance(value, Load):
        raise ValidationError("Scene.load", value, "a Load or a mapping such as "
                                                   "{'mean_pressure': 0.3} or {'penetration': 0.5}")
