"""Lamb's surface influence functions of the elastic half-plane (``impact green``).

For a line force at x = 0 (z into the medium) and s = |x|/(c1 t): the displacement is
u = I/(pi mu t) g(s) for an impulse I delta(t), and u = P/(pi mu) W(s) for a step P H(t).
Keys ``g_zz``, ``g_xz``, ``g_xx``, ``W_zz``, ``U_xz``, ``U_xx``; cell integrals
``Ix_*`` = Int g ds and ``It_*`` = Int g/s ds; with ``constants=True`` the Rayleigh
constants ``s_R``, ``r_zz``, ``r_xx``, ``K_R``. Each value has its absolute error estimate.
"""

from __future__ import annotations

from typing import Optional, Sequence, Tuple, Union

from . import _args, _dyncontact
from ._result import Report
from ._types import Number

__all__ = ["green", "GreenResult"]


class GreenResult(Report):
    """``lamb.green``: ``points`` and ``cells`` as records (a column per key, with
    ``error_estimate``), the constants when asked for."""


def green(
    *,
    at: Union[str, Sequence[Number], None] = None,
    cells: Union[str, Sequence[Tuple[Number, Number]], None] = None,
    constants: bool = False,
    digits: Optional[int] = None,
    c1: Optional[Number] = None,
    c2: Optional[Number] = None,
    poisson: Optional[Number] = None,
) -> GreenResult:
    """The influence functions at the points s = ``at`` (s > 0, not s_R), the cell
    integrals over ``cells`` [(sa, sb), ...] and, with ``constants=True``, the Rayleigh
    constants; ``digits`` for arbitrary precision (values as ``Decimal`` above 15)."""
    kw = dict(locals())  # the keyword arguments, in the signature's order
    text = _dyncontact.impact(_args.argv("green", kw, lists=("at", "cells")))
    return GreenResult(text, _args.decimal_digits(digits))
