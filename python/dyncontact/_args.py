"""Keyword arguments to command-line flags: one naming rule for every call.

A keyword argument is the flag of the same name with dashes for underscores
(``theta_deg=86`` is ``--theta-deg 86``). Values are passed as the decimal text the
command line takes: a ``str`` or ``decimal.Decimal`` as written, an ``int`` as its digits,
a ``float`` as its shortest repr (``alpha=561.249`` means the decimal 561.249), ``True``
as a bare switch (``force=True`` is ``--force``). Lists become the comma-separated lists of
the flags (``at=[0.1, 0.5]``), pairs the ``x:y`` items (``at=[(0.1, -0.1)]``).
"""

from __future__ import annotations

import numbers
from decimal import Decimal
from typing import Any, Dict, List, Optional

from . import _dyncontact

#: Flags the Python API does not take: results are always typed objects.
_OUTPUT_FLAGS = ("json", "csv")


def _invalid(parameter: str, message: str) -> Exception:
    err = _dyncontact.InvalidParameterError(message)
    err.parameter = parameter
    return err


def text(parameter: str, value: Any) -> str:
    """The decimal text of one value, as the command line takes it."""
    if isinstance(value, bool):
        raise _invalid(parameter, f"invalid {parameter} = {value!r}: a number or text, not a bool")
    if isinstance(value, Decimal):
        return str(value)
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        # the shortest repr of the double: 561.249 is the decimal 561.249
        return float.__repr__(float(value))
    if isinstance(value, str):
        return value
    raise _invalid(
        parameter,
        f"invalid {parameter} = {value!r}: a number (int, float, Decimal) or decimal text",
    )


def item(parameter: str, value: Any) -> str:
    """One item of a list flag: a number, or a pair ``x:y``."""
    if isinstance(value, (tuple, list)) and len(value) == 2:
        return f"{text(parameter, value[0])}:{text(parameter, value[1])}"
    return text(parameter, value)


def listed(parameter: str, value: Any) -> str:
    """A list flag's text: a str as written, a sequence comma-separated."""
    if isinstance(value, str):
        return value
    try:
        values = list(value)
    except TypeError:
        return item(parameter, value)
    if not values:
        raise _invalid(parameter, f"invalid {parameter}: an empty list")
    return ",".join(item(parameter, v) for v in values)


def argv(subcommand: str, kwargs: Dict[str, Any], lists: tuple = ()) -> List[str]:
    """The command line of ``subcommand`` for ``kwargs`` (``None`` values left out: the
    command line's default), always asking for JSON."""
    out = [subcommand]
    for name, value in kwargs.items():
        if name in _OUTPUT_FLAGS:
            raise _invalid(name, f"{name}: the Python calls always return typed results")
        if value is None or value is False:
            continue
        flag = "--" + name.replace("_", "-")
        if value is True:
            out.append(flag)
        elif name in lists:
            out += [flag, listed(name, value)]
        else:
            out += [flag, text(name, value)]
    out.append("--json")
    return out


def decimal_digits(digits: Optional[int]) -> bool:
    """Whether values come as ``decimal.Decimal``: above 15 digits a float would round."""
    try:
        return digits is not None and not isinstance(digits, bool) and int(digits) > 15
    except (TypeError, ValueError):
        return False  # refused by the call, naming digits
