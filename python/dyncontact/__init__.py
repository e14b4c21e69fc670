"""dyncontact: dynamic contact mechanics of an elastic half-plane, from Python.

Two engines, each verified against independent references and reporting every number with
its error estimate:

- :mod:`dyncontact.wedge`: the self-similar indentation by a rigid wedge with friction and
  displacement coupling (``solve``, ``stress``, ``field``, ``curve``);
- :mod:`dyncontact.impact`: the transient impact of rigid, elastic (local model, full
  cylinder) and thin-shell strikers
  (``run``, ``edge``, ``striker_green``), and :mod:`dyncontact.lamb`: Lamb's surface influence functions
  (``green``).

Every call takes the command line's flags as keyword arguments (``theta_deg=86`` is
``--theta-deg 86``) and returns a result whose attributes are the command line's JSON keys
(``to_dict()`` is that JSON). Bad inputs raise :class:`InvalidParameterError` (a
``ValueError``) naming the parameter; numerical failures raise :class:`NumericalError` (an
``ArithmeticError``). :func:`sweep` spreads a call over many cases (process pool, executor
or dask cluster); :func:`set_num_threads` limits the engine's own threads.

The extension links GMP, MPFR and MPC statically (LGPL-3.0-or-later; their licence texts are
in ``dyncontact/licenses``).
"""

from . import _dyncontact
from ._dyncontact import (
    InvalidParameterError,
    NumericalError,
    get_num_threads,
    set_num_threads,
)
from ._sweep import cases, sweep
from . import impact, lamb, wedge

__version__ = _dyncontact.VERSION

InvalidParameterError.__module__ = "dyncontact"
NumericalError.__module__ = "dyncontact"

__all__ = [
    "wedge",
    "impact",
    "lamb",
    "sweep",
    "cases",
    "set_num_threads",
    "get_num_threads",
    "InvalidParameterError",
    "NumericalError",
    "__version__",
]
