"""The self-similar indentation of an elastic half-plane by a rigid wedge (plane strain, the
wedge paper), with Coulomb friction and tangential-displacement coupling: the ``wedge``
command line as Python calls.

Conventions (as ``wedge --help``): c1, c2 the dilatational and shear wave speeds in m/s
(or ``poisson`` with c2); ``theta_deg`` the wedge half-angle Theta in degrees, in (0, 90);
``alpha`` the contact-zone expansion speed in m/s, 0 < alpha < c_R, or ``speed`` the
indenter speed V in m/s instead; ``gamma`` the friction coefficient (or ``"cot"``);
``coupling`` ``"on"`` (beta = -cot Theta) or ``"off"``; ``solution`` ``"genuine"``,
``"paper"`` or ``"as-printed"``; ``digits`` the significant digits (omit for f64; above 15
the values come as ``decimal.Decimal``). Results are dimensionless and their keys say how:
``v_over_c1_cot_theta`` = V/(c1 cot Theta), ``force_over_a_mu_cot_theta`` =
P/(alpha t mu cot Theta), ``sigma_over_mu_cot_theta``, ``r_over_alpha_t``, ...; every
value's absolute error estimate is in ``error_estimates``.

Numbers are taken as decimal text: a ``str`` or ``Decimal`` as written, a ``float`` as its
shortest repr (``alpha=561.249`` is the decimal 561.249).
"""

from __future__ import annotations

from typing import Any, Optional, Sequence, Tuple, Union

from . import _args, _dyncontact, _progress
from ._result import CurveResult, Report, TableReport
from ._types import Number

__all__ = ["solve", "stress", "field", "curve", "SolveResult"]


class SolveResult(Report):
    """``wedge.solve``: the case's quantities as attributes (``v_over_c1_cot_theta``,
    ``force_over_a_mu_cot_theta``, ``regime``, ...), ``error_estimates[key]`` each value's
    absolute error estimate, ``unavailable[key]`` why a quantity has no value."""


def _call(argv: Sequence[str], digits: Any, cls: Any, progress: Any = None) -> Any:
    cb = _progress.callback(progress, "wedge")
    try:
        text = _dyncontact.wedge(list(argv), cb)
    finally:
        _progress.close(cb)
    return cls(text, _args.decimal_digits(digits))


def solve(
    *,
    theta_deg: Number,
    alpha: Optional[Number] = None,
    speed: Optional[Number] = None,
    gamma: Optional[Union[Number, str]] = None,
    coupling: Optional[str] = None,
    solution: Optional[str] = None,
    c1: Optional[Number] = None,
    c2: Optional[Number] = None,
    poisson: Optional[Number] = None,
    digits: Optional[int] = None,
    quantities: Optional[Union[str, Sequence[str]]] = None,
) -> SolveResult:
    """Solves one case (``wedge solve``): Q, V (or alpha), the force, the apex regime, the
    edge velocities and the admissibility checks, each value with its error estimate.

    Give ``alpha`` (m/s) or ``speed`` (V, m/s). ``quantities`` limits what is computed to
    these keys (the inputs, V, the regime and the estimates of what is printed come along).
    Raises ``InvalidParameterError`` for a bad input, ``NumericalError`` for a case that
    cannot be computed to its tolerance.
    """
    kw = dict(locals())  # the keyword arguments, in the signature's order
    return _call(_args.argv("solve", kw, lists=("quantities",)), digits, SolveResult)


def stress(
    *,
    theta_deg: Number,
    at: Union[str, Sequence[Number]],
    alpha: Optional[Number] = None,
    speed: Optional[Number] = None,
    gamma: Optional[Union[Number, str]] = None,
    coupling: Optional[str] = None,
    solution: Optional[str] = None,
    c1: Optional[Number] = None,
    c2: Optional[Number] = None,
    poisson: Optional[Number] = None,
    digits: Optional[int] = None,
) -> TableReport:
    """The contact stress sigma_theta/(mu cot Theta) at the fractions r/(alpha t) in (0, 1]
    given by ``at`` (``wedge stress``): arrays ``r_over_alpha_t``,
    ``sigma_over_mu_cot_theta`` and their ``sigma_error_estimates``."""
    kw = dict(locals())  # the keyword arguments, in the signature's order
    return _call(_args.argv("stress", kw, lists=("at",)), digits, TableReport)


def field(
    *,
    theta_deg: Number,
    at: Union[str, Sequence[Tuple[Number, Number]]],
    alpha: Optional[Number] = None,
    speed: Optional[Number] = None,
    gamma: Optional[Union[Number, str]] = None,
    coupling: Optional[str] = None,
    solution: Optional[str] = None,
    c1: Optional[Number] = None,
    c2: Optional[Number] = None,
    poisson: Optional[Number] = None,
    digits: Optional[int] = None,
) -> TableReport:
    """The field inside the half-plane (``wedge field``) at the points (x/(c1 t), y/(c1 t)),
    y < 0, given by ``at`` as pairs: stresses over mu cot Theta, particle velocities over
    c1 cot Theta and displacements over c1 t cot Theta, Cartesian, y out of the body (the
    paper's construction)."""
    kw = dict(locals())  # the keyword arguments, in the signature's order
    return _call(_args.argv("field", kw, lists=("at",)), digits, TableReport)


def curve(
    *,
    theta_deg: Number,
    alpha_range: Union[str, Tuple[Number, Number, int]],
    gamma: Optional[Union[Number, str]] = None,
    coupling: Optional[str] = None,
    solution: Optional[str] = None,
    c1: Optional[Number] = None,
    c2: Optional[Number] = None,
    poisson: Optional[Number] = None,
    digits: Optional[int] = None,
    force: bool = False,
    quantities: Optional[Union[str, Sequence[str]]] = None,
    progress: _progress.Progress = False,
) -> CurveResult:
    """The alpha-V relation (and the force, Omega0, the regime) over evenly spaced alpha
    (``wedge curve``): ``alpha_range=(min, max, steps)`` in m/s, 0 < min < max < c_R. Each
    key is a column over the rows, ``error_estimates[key]`` its estimates. At most 10^4
    rows without ``force=True``. ``progress=True`` shows a tqdm bar; Ctrl-C stops it."""
    kw = dict(locals())  # the keyword arguments, in the signature's order
    del kw["progress"]
    argv = _args.argv("curve", kw, lists=("alpha_range", "quantities"))
    return _call(argv, digits, CurveResult, progress)
