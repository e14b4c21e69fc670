"""The transient impact of rigid, elastic (local model, full cylinder) and thin-shell strikers
on an elastic half-plane (plane strain, the impact paper): the ``impact`` command line as
Python calls.

Conventions (as ``impact --help``): the half-plane's ``c1``, ``c2`` in m/s or its
``poisson`` (for ``run``, Poisson's solid, 1/4, when none is given); lengths over the striker's scale R, times as c1 t/R, speeds over c1, the force
over rho c1^2 R, energies over rho c1^2 R^2, pressures over rho c1^2. ``striker``:
``"rigid"``, ``"elastic:c1=..,c2=..,density_ratio=.."``,
``"cylinder:c1=..,c2=..,density_ratio=.."`` (the full elastic cylinder, its mass its own) or
``"shell:thickness_over_R=..,c1=..,c2=..,density_ratio=.."``; ``profile``:
``"circle:R=.."``, ``"parabola:R=.."``, ``"power:A=..,k=.."``, ``"wedge:theta_deg=.."``,
``"flat:a=.."`` or ``"table:FILE"``; ``law``: ``"signorini"`` or ``"kinematic"``.
``end`` is a time c1 t/R (a number), ``"separation"`` or ``"separation:max=VALUE"``.
Every history comes with its error estimate from grid refinement.
"""

from __future__ import annotations

import numbers
from typing import Any, Optional, Sequence, Union

import numpy as np

from . import _args, _dyncontact, _progress
from ._result import Report, RunResult
from ._types import Number

__all__ = ["run", "edge", "striker_green", "RunResult", "EdgeResult", "StrikerGreenResult"]


class EdgeResult(Report):
    """``impact.edge``: ``records``, one per edge speed, with the exponents lambda of
    p ~ d^lambda, the selected one, and the gap coefficients (docs/edge.md)."""


class StrikerGreenResult(Report):
    """``impact.striker_green``: ``c2t_over_R``, ``angle_deg``, the 2-D float64 arrays
    [angle][time] ``w_over_p0R_mu`` and ``w_def_over_p0R_mu``, and ``error_estimate`` with
    both (docs/strikers.md, section 7)."""

    def _init(self, text: str, data: Any, decimal: bool) -> None:
        super()._init(text, data, decimal)
        grid = lambda rows: np.array(rows, dtype=np.float64)  # noqa: E731
        for key in ("w_over_p0R_mu", "w_def_over_p0R_mu"):
            self._values[key] = grid(data[key])
            self._values["error_estimate"][key] = grid(data["error_estimate"][key])


def _time(parameter: str, value: Any) -> Any:
    """A time c1 t/R given as a number is the flag's ``c1t/R=VALUE``."""
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        return "c1t/R=" + _args.text(parameter, value)
    return value


def run(
    *,
    profile: str,
    striker: str = "rigid",
    mass_ratio: Optional[float] = None,
    v0_over_c1: Optional[float] = None,
    driven: Optional[str] = None,
    law: Optional[str] = None,
    end: Union[Number, str, None] = None,
    c1: Optional[Number] = None,
    c2: Optional[Number] = None,
    poisson: Optional[Number] = None,
    length: Optional[float] = None,
    dx: Optional[float] = None,
    kappa: Optional[float] = None,
    levels: Optional[int] = None,
    edge_cell: Optional[str] = None,
    start_halvings: Optional[int] = None,
    pressure_at: Union[str, Sequence[Number], None] = None,
    digits: Optional[int] = None,
    force: bool = False,
    memory_limit_gib: Optional[float] = None,
    geometry: Optional[str] = None,
    dr: Optional[float] = None,
    progress: _progress.Progress = False,
) -> RunResult:
    """Marches an impact (``impact run``): a free striker (``mass_ratio`` = m0/(rho R^2),
    ``v0_over_c1``) or a prescribed penetration (``driven``), to ``end``. Returns float64
    arrays over ``c1t_over_R`` (``h_over_R``, ``b_over_R``, ``force_over_rho_c1sq_R``, ...)
    with ``error_estimate[key]`` of the same shape, the rebound, the energy audit and the
    pressure profiles at ``pressure_at`` (times c1 t/R) as 2-D arrays.

    ``geometry="axisymmetric"``: a body of revolution on the elastic half-space
    (``profile`` ``"sphere:R=.."``, ``"paraboloid:R=.."``, ``"cone:theta_deg=.."`` or
    ``"flat:a=.."``; ``mass_ratio`` = m/(rho R^3); ring width ``dr``, by default about 30
    rings across the largest contact radius): ``a_over_R``, ``force_over_rho_c1sq_Rsq``,
    ``radiated_energy_fraction`` (a history), ``restitution`` after the separation, and
    Hertz's values and the first-order radiation beside them (``hertz``,
    ``first_order_radiation``).

    ``start_halvings``: how many times the grid is halved for the first steps (default 6, 0:
    one grid throughout; a rigid striker of a curved profile under Signorini's law).

    ``progress=True`` shows a tqdm bar, a callable receives the fraction done; Ctrl-C
    (KeyboardInterrupt) stops the march within a second. The GIL is released meanwhile.
    """
    kw = dict(locals())  # the keyword arguments, in the signature's order
    del kw["progress"]
    kw["end"] = _time("end", end)
    if pressure_at is not None and not isinstance(pressure_at, str):
        kw["pressure_at"] = "c1t/R=" + _args.listed("pressure_at", pressure_at)
    cb = _progress.callback(progress, "impact")
    try:
        text = _dyncontact.impact(_args.argv("run", kw), cb)
    finally:
        _progress.close(cb)
    return RunResult(text, _args.decimal_digits(digits))


def edge(
    *,
    speed_over_c1: Union[str, Sequence[Number], Number],
    law: Optional[str] = None,
    c1: Optional[Number] = None,
    c2: Optional[Number] = None,
    poisson: Optional[Number] = None,
) -> EdgeResult:
    """The power law p ~ d^lambda of the contact pressure at an edge moving at the speeds
    D/c1 of ``speed_over_c1`` (``impact edge``), for the edge ``law``."""
    kw = dict(locals())  # the keyword arguments, in the signature's order
    return EdgeResult(_dyncontact.impact(_args.argv("edge", kw, lists=("speed_over_c1",))))


def striker_green(
    *,
    arc_over_R: Number,
    at_deg: Union[str, Sequence[Number], Number],
    times: Union[str, Sequence[Number], Number],
    striker: str = "cylinder",
    c1: Optional[Number] = None,
    c2: Optional[Number] = None,
    poisson: Optional[Number] = None,
) -> StrikerGreenResult:
    """A free elastic cylinder's own influence function (``impact striker-green``): the mean
    inward normal surface displacement over arcs of width ``arc_over_R`` centred at the angles
    ``at_deg`` (degrees), under a unit pressure switched on at t = 0 over the arc at 0, at the
    ``times`` c2 t/R (numbers, or the flag's text ``"c2t/R=..."``); the striker's material by
    its ``poisson`` or its ``c1``, ``c2`` (m/s). Units R = 1, mu_s = 1, rho_s = 1."""
    if not isinstance(times, str):
        times = "c2t/R=" + _args.listed("times", times)
    kw = dict(locals())  # the keyword arguments, in the signature's order
    return StrikerGreenResult(_dyncontact.impact(_args.argv("striker-green", kw, lists=("at_deg",))))
