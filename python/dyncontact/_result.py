"""Result objects: the command line's JSON report as attributes, arrays and tables.

Every JSON key of a report is an attribute of the same name; ``to_dict()`` gives the JSON as
the command line prints it (``--json``), as plain Python values. Lists of numbers become
float64 numpy arrays (object arrays of ``decimal.Decimal`` above 15 digits), owned by the
result and writable; lists of uniform records become :class:`Records` (a column per key).
"""

from __future__ import annotations

import copy
import json
from decimal import Decimal
from typing import Any, Dict, Iterator, List, Optional

import numpy as np


def _is_number(v: Any) -> bool:
    return isinstance(v, (int, float, Decimal)) and not isinstance(v, bool)


def _array(values: List[Any], decimal: bool) -> Any:
    """A numpy array of a list of numbers; entries that are ``None`` (a quantity not
    defined for that row) are masked."""
    missing = [v is None for v in values]
    if decimal and any(isinstance(v, Decimal) for v in values):
        arr = np.array([v if v is not None else Decimal(0) for v in values], dtype=object)
    else:
        arr = np.array([0.0 if v is None else v for v in values], dtype=np.float64)
    if any(missing):
        return np.ma.masked_array(arr, mask=missing)
    return arr


def _convert(value: Any, decimal: bool) -> Any:
    """JSON values as the attributes show them: numeric lists as arrays, uniform records as
    :class:`Records`, objects as dicts of converted values."""
    if isinstance(value, dict):
        return {k: _convert(v, decimal) for k, v in value.items()}
    if isinstance(value, list):
        if value and all(_is_number(v) or v is None for v in value) and any(
            _is_number(v) for v in value
        ):
            return _array(value, decimal)
        if value and all(isinstance(v, bool) for v in value):
            return np.array(value, dtype=bool)
        if value and all(isinstance(v, dict) for v in value):
            return Records(value, decimal)
        return [_convert(v, decimal) for v in value]
    return value


class Report:
    """A report of one call: the JSON keys as attributes.

    ``to_dict()`` is the command line's JSON for the same arguments; numbers are floats
    (the doubles the command line printed, bit for bit) or, with ``digits`` above 15,
    ``decimal.Decimal`` holding every printed digit.
    """

    def __init__(self, text: str, decimal: bool = False):
        data = json.loads(text, parse_float=Decimal if decimal else float)
        self._init(text, data, decimal)

    def _init(self, text: str, data: Any, decimal: bool) -> None:
        self.__dict__["_text"] = text
        self.__dict__["_data"] = data
        self.__dict__["_decimal"] = decimal
        self.__dict__["_values"] = _convert(data, decimal) if isinstance(data, dict) else {}

    def __getattr__(self, name: str) -> Any:
        values = self.__dict__.get("_values", {})
        if name in values:
            return values[name]
        raise AttributeError(
            f"{type(self).__name__} has no attribute {name!r} (its keys: {', '.join(values)})"
        )

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"{type(self).__name__} is read-only")

    def __dir__(self) -> List[str]:
        return sorted(set(super().__dir__()) | set(self._values))

    def __reduce__(self) -> Any:
        return (type(self), (self._text, self._decimal))

    def keys(self) -> List[str]:
        """The report's JSON keys, in the command line's order."""
        return list(self._values)

    def to_dict(self) -> Dict[str, Any]:
        """The command line's JSON as a dict (a fresh copy)."""
        return copy.deepcopy(self._data)

    def __repr__(self) -> str:
        return f"<{type(self).__name__}: {', '.join(self.keys())}>"


class Records:
    """A list of uniform JSON records (points, cells, rows) as a table: ``records[i]`` is a
    dict, ``records.key`` the column as an array, ``records.error_estimate[key]`` that
    column's estimates where the records carry them."""

    def __init__(self, rows: List[Dict[str, Any]], decimal: bool):
        self._rows = rows
        self._decimal = decimal
        keys: List[str] = []
        for r in rows:
            keys += [k for k in r if k not in keys]
        self._keys = keys

    def __len__(self) -> int:
        return len(self._rows)

    def __getitem__(self, i: int) -> Dict[str, Any]:
        return _convert(self._rows[i], self._decimal)

    def __iter__(self) -> Iterator[Dict[str, Any]]:
        return (self[i] for i in range(len(self)))

    def column(self, key: str) -> Any:
        """The values of ``key`` over the records (an array where they are numbers; a
        dict of columns where they are objects, such as ``error_estimate``)."""
        if key not in self._keys:
            raise KeyError(f"no column {key!r} (columns: {', '.join(self._keys)})")
        values = [r.get(key) for r in self._rows]
        if all(isinstance(v, dict) or v is None for v in values):
            inner: List[str] = []
            for v in values:
                inner += [k for k in (v or {}) if k not in inner]
            return {
                k: _convert([(v or {}).get(k) for v in values], self._decimal) for k in inner
            }
        if all(_is_number(v) or v is None for v in values):
            return _array(values, self._decimal)
        return _convert(values, self._decimal)

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        try:
            return self.column(name)
        except KeyError as e:
            raise AttributeError(str(e)) from None

    def keys(self) -> List[str]:
        """The columns, in the records' order."""
        return list(self._keys)

    def to_list(self) -> List[Dict[str, Any]]:
        """The records as the command line's JSON (a fresh copy)."""
        return copy.deepcopy(self._rows)

    def to_pandas(self) -> Any:
        """The records as a ``pandas.DataFrame``: one row per record; nested estimates as
        ``<key>_error_estimate`` columns. Needs pandas (``pip install "./python[pandas]"``)."""
        import pandas as pd

        flat = []
        for r in self._rows:
            row: Dict[str, Any] = {}
            for k, v in r.items():
                if isinstance(v, dict):
                    # error_estimate(s) -> <key>_error_estimate; other objects -> <key>_<name>
                    suffix = "error_estimate" if k.startswith("error_estimate") else k
                    row.update({f"{kk}_{suffix}": vv for kk, vv in v.items()})
                else:
                    row[k] = v
            flat.append(row)
        return pd.DataFrame(flat)

    def __repr__(self) -> str:
        return f"<Records: {len(self)} rows of {', '.join(self._keys)}>"


class PressureProfiles:
    """Pressure profiles of an impact run as 2-D arrays: ``p_over_rho_c1sq[i, j]`` is the
    mean pressure p/(rho c1^2) of the cell at ``x_over_R[j]`` (the ring at ``r_over_R[j]``
    in an axisymmetric run) at time ``c1t_over_R[i]``, and ``error_estimate[i, j]`` its
    estimate. Profiles end at the
    contact's last cell at their time: beyond it the arrays are masked (numpy masked arrays;
    outside the contact the pressure is zero, ``p.filled(0)``)."""

    def __init__(self, records: List[Dict[str, Any]], decimal: bool):
        # the plane runs' cells are at x_over_R, the axisymmetric runs' rings at r_over_R
        key = "r_over_R" if records and "r_over_R" in records[0] else "x_over_R"
        n = max((len(r[key]) for r in records), default=0)
        longest = max(records, key=lambda r: len(r[key]), default=None)
        dtype = object if decimal else np.float64
        fill = Decimal(0) if decimal else 0.0
        self.c1t_over_R = _array([r["c1t_over_R"] for r in records], decimal)
        coords = _array(longest[key], decimal) if longest else np.zeros(0)
        setattr(self, key, coords)
        p = np.full((len(records), n), fill, dtype=dtype)
        e = np.full((len(records), n), fill, dtype=dtype)
        mask = np.ones((len(records), n), dtype=bool)
        for i, r in enumerate(records):
            k = len(r[key])
            p[i, :k] = r["p_over_rho_c1sq"]
            if r.get("error_estimate") is not None:
                e[i, :k] = r["error_estimate"]
            mask[i, :k] = False
        self.p_over_rho_c1sq = np.ma.masked_array(p, mask=mask.copy())
        self.error_estimate = np.ma.masked_array(e, mask=mask)

    def __len__(self) -> int:
        return len(self.c1t_over_R)

    def __repr__(self) -> str:
        return f"<PressureProfiles: {len(self)} times by {len(self.x_over_R)} cells>"


class RunResult(Report):
    """``impact.run``: histories as float64 arrays over ``c1t_over_R`` (``h_over_R``,
    ``b_over_R``, ``force_over_rho_c1sq_R``, ...), ``error_estimate[key]`` of the same shape,
    ``error_model[key]`` how each was formed (``estimator`` ``"richardson"`` or
    ``"conservative"``, ``safety``, ``order_credited``, ``conservative_rows``, and where there
    are, ``cell_floor_rows`` and ``order_shown``), the rebound's
    numbers, the energy audit, and ``pressure`` as :class:`PressureProfiles`."""

    def _init(self, text: str, data: Any, decimal: bool) -> None:
        super()._init(text, data, decimal)
        if isinstance(data.get("pressure"), list):
            self._values["pressure"] = PressureProfiles(data["pressure"], decimal)

    def history_keys(self) -> List[str]:
        """The keys of the histories (one value per reported time)."""
        n = len(self._data.get("c1t_over_R", []))
        return [k for k, v in self._data.items() if isinstance(v, list) and len(v) == n and n]

    def to_pandas(self) -> Any:
        """The histories as a ``pandas.DataFrame`` indexed by row, with each estimated
        column's ``<key>_error_estimate`` beside it."""
        import pandas as pd

        cols: Dict[str, Any] = {}
        estimates = self._data.get("error_estimate", {})
        for k in self.history_keys():
            cols[k] = self._data[k]
            if k in estimates:
                cols[f"{k}_error_estimate"] = estimates[k]
        return pd.DataFrame(cols)


class CurveResult(Report):
    """``wedge.curve``: the rows of ``wedge solve`` over alpha. Each key is a column (an
    array over the rows; masked where a row has no value, such as ``omega0`` in the power
    regime), ``error_estimates[key]`` its estimates, ``rows`` the rows as
    :class:`SolveResult`-like dicts (the command line's JSON array)."""

    def _init(self, text: str, data: Any, decimal: bool) -> None:
        super()._init(text, {}, decimal)
        self.__dict__["_data"] = data
        records = Records(data, decimal)
        self.__dict__["_records"] = records
        self.__dict__["_values"] = {k: records.column(k) for k in records.keys()}

    @property
    def rows(self) -> Records:
        """The rows (the command line's JSON array, one record per alpha)."""
        return self._records

    def to_list(self) -> List[Dict[str, Any]]:
        """The command line's JSON array (a fresh copy)."""
        return copy.deepcopy(self._data)

    def to_dict(self) -> Dict[str, Any]:  # type: ignore[override]
        """The columns as lists (a fresh copy): ``{key: [row values]}``."""
        return {k: copy.deepcopy([r.get(k) for r in self._data]) for k in self._records.keys()}

    def to_pandas(self) -> Any:
        """One row per alpha, each estimate as ``<key>_error_estimate``."""
        return self._records.to_pandas()

    def __len__(self) -> int:
        return len(self._data)


class TableReport(Report):
    """A report whose values are per point (``wedge.stress``, ``wedge.field``): arrays over
    the points; ``to_pandas()`` gives one row per point."""

    def to_pandas(self) -> Any:
        """One row per point: the per-point arrays as columns."""
        import pandas as pd

        n: Optional[int] = None
        cols: Dict[str, Any] = {}
        for k, v in self._data.items():
            if isinstance(v, list):
                n = len(v) if n is None else n
                if len(v) == n:
                    cols[k] = v
        return pd.DataFrame(cols)
