"""Sweeps: a dask LocalCluster's results equal the serial ones exactly; a failing case
leaves its exception in its slot and the rest survive; any executor works."""

from __future__ import annotations

import concurrent.futures as cf

import pytest

import dyncontact
from dyncontact import InvalidParameterError

CASES = dyncontact.cases(
    profile=["parabola:R=1"],
    mass_ratio=[5, 10],
    v0_over_c1=[0.005, 0.01],
    striker=["rigid"],
    end=[0.5, 1.0],
    poisson=[0.3],
)


def serial():
    return [dyncontact.impact.run(**c) for c in CASES]


def test_cases_is_the_product():
    assert len(CASES) == 8
    assert CASES[0] == dict(profile="parabola:R=1", mass_ratio=5, v0_over_c1=0.005, striker="rigid", end=0.5, poisson=0.3)
    assert CASES[1]["end"] == 1.0


def test_dask_local_cluster_equals_serial():
    distributed = pytest.importorskip("distributed")
    expected = serial()
    with distributed.Client(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as client:
        got = dyncontact.sweep(dyncontact.impact.run, CASES, client=client)
    assert [g.to_dict() for g in got] == [e.to_dict() for e in expected]


def test_one_bad_case_leaves_its_error_and_the_rest_survive():
    cases = [dict(c) for c in CASES]
    cases[3]["mass_ratio"] = -1
    with cf.ThreadPoolExecutor(2) as ex:
        got = dyncontact.sweep(dyncontact.impact.run, cases, client=ex)
    errors = [g for g in got if isinstance(g, BaseException)]
    assert len(errors) == 1 and isinstance(got[3], InvalidParameterError)
    assert got[3].parameter == "mass_ratio"
    assert len([g for g in got if not isinstance(g, BaseException)]) == 7


def test_the_default_process_pool_and_a_table():
    pd = pytest.importorskip("pandas")
    cases = dyncontact.cases(theta_deg=[80, 86], alpha=[300, 600])
    cases.append(dict(theta_deg=95, alpha=300))
    seen = []
    table = dyncontact.sweep(dyncontact.wedge.solve, cases, table=True, progress=seen.append)
    assert isinstance(table, pd.DataFrame) and len(table) == 5
    assert table["error"].isna().sum() == 4 and "theta_deg" in table["error"].iloc[4]
    direct = dyncontact.wedge.solve(theta_deg=86, alpha=600)
    assert table["v_over_c1_cot_theta"].iloc[3] == direct.v_over_c1_cot_theta
    assert seen[-1] == 1.0
