"""Parameter sweeps: one call over many cases, on a local process pool, any
``concurrent.futures.Executor`` or a dask.distributed cluster.

Cases travel to the workers as plain keyword dicts and results come back as the same result
objects (they pickle as their JSON). Each worker limits the engine's threads to
``threads_per_case`` so that the workers do not oversubscribe the cores.
"""

from __future__ import annotations

import concurrent.futures as cf
import itertools
import multiprocessing
import os
from typing import Any, Callable, Dict, Iterable, List, Mapping, Optional, Sequence

from . import _dyncontact, _progress


def cases(**axes: Iterable[Any]) -> List[Dict[str, Any]]:
    """The Cartesian product of keyword values as a list of cases, the last axis fastest:
    ``cases(theta_deg=[80, 86], alpha=[100, 200])`` is four keyword dicts."""
    names = list(axes)
    return [dict(zip(names, values)) for values in itertools.product(*axes.values())]


def _one(func: Callable[..., Any], kwargs: Mapping[str, Any], threads: int) -> Any:
    """Runs one case on a worker; a failure is returned as its exception instance."""
    _dyncontact.set_num_threads(threads)
    try:
        return func(**kwargs)
    except Exception as e:  # the case's failure fills its slot; the sweep goes on
        return e


def _is_dask_client(client: Any) -> bool:
    return type(client).__module__.startswith("distributed") and hasattr(client, "gather")


def sweep(
    func: Callable[..., Any],
    cases: Sequence[Mapping[str, Any]],
    client: Any = None,
    progress: _progress.Progress = False,
    table: bool = False,
    threads_per_case: int = 1,
) -> Any:
    """Runs ``func(**case)`` for every case and returns the results in the order of
    ``cases``; a case that fails leaves its exception instance in its slot.

    ``func`` is one of the package's calls (``dyncontact.wedge.solve``,
    ``dyncontact.impact.run``, ...). ``client``: ``None`` for a local process pool (one
    process per core; a script must guard its entry with ``if __name__ == "__main__":``),
    a ``dask.distributed.Client`` (``Client()`` for a LocalCluster, ``Client("tcp://...")``
    for a running cluster; every worker needs the package installed), or any
    ``concurrent.futures.Executor``. ``progress=True`` shows a tqdm bar of the cases done
    (a callable receives the fraction). ``table=True`` returns one ``pandas.DataFrame``
    instead: a row per case with its keywords, the result's scalar values and ``error``
    (the failure's message, or ``None``).
    """
    cases = [dict(c) for c in cases]
    if threads_per_case < 1:
        from ._args import _invalid

        raise _invalid("threads_per_case", "invalid threads_per_case: admissible range is >= 1")
    cb = _progress.callback(progress, "sweep")
    own: Optional[cf.Executor] = None
    try:
        if client is None:
            own = cf.ProcessPoolExecutor(
                max_workers=min(len(cases), os.cpu_count() or 1) or 1,
                mp_context=multiprocessing.get_context("spawn"),
            )
            client = own
        if _is_dask_client(client):
            futures = [
                client.submit(_one, func, c, threads_per_case, pure=False) for c in cases
            ]
            from distributed import as_completed
        else:
            futures = [client.submit(_one, func, c, threads_per_case) for c in cases]
            as_completed = cf.as_completed
        slot = {id(f): i for i, f in enumerate(futures)}
        results: List[Any] = [None] * len(cases)
        done = 0
        for f in as_completed(futures):
            results[slot[id(f)]] = f.result()
            done += 1
            if cb is not None:
                cb(done / max(len(cases), 1))
    finally:
        _progress.close(cb)
        if own is not None:
            own.shutdown()
    if table:
        return _table(cases, results)
    return results


def _table(cases: List[Dict[str, Any]], results: List[Any]) -> Any:
    import pandas as pd

    rows = []
    for case, r in zip(cases, results):
        row: Dict[str, Any] = dict(case)
        if isinstance(r, BaseException):
            row["error"] = f"{type(r).__name__}: {r}"
        else:
            row["error"] = None
            data = r.to_dict() if hasattr(r, "to_dict") else {}
            for k, v in data.items():
                if k not in row and (isinstance(v, (int, float, str, bool)) or v is None):
                    row[k] = v
        rows.append(row)
    return pd.DataFrame(rows)
