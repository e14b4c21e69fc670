"""Arrays are float64, C-contiguous, writable, owned by their result and not shared between
calls; results never hold NaN."""

from __future__ import annotations

import math

import numpy as np

import dyncontact

RUN = dict(profile="parabola:R=1", mass_ratio=10, v0_over_c1=0.01, end=1, c1=1870.83, c2=1000)


def test_arrays_are_owned_writable_float64():
    a = dyncontact.impact.run(**RUN)
    b = dyncontact.impact.run(**RUN)
    for key in a.history_keys():
        if key == "stage":
            continue
        x = getattr(a, key)
        assert isinstance(x, np.ndarray) and x.dtype == np.float64, key
        assert x.flags["C_CONTIGUOUS"] and x.flags["WRITEABLE"] and x.flags["OWNDATA"], key
        assert x.shape == a.c1t_over_R.shape
    h = a.h_over_R
    saved = b.h_over_R.copy()
    h[:] = -1.0  # mutating one result's array touches nothing else
    assert np.array_equal(b.h_over_R, saved)
    assert np.all(a.h_over_R == -1.0)  # the attribute is the result's own array
    assert a.to_dict()["h_over_R"] != [-1.0] * len(h)  # nor the JSON it came from
    e = a.error_estimate["h_over_R"]
    assert e.dtype == np.float64 and e.shape == h.shape and np.all(e >= 0)


def test_the_error_model_of_each_estimated_history_is_stated():
    a = dyncontact.impact.run(**RUN)
    models = a.to_dict()["error_model"]
    assert a.error_model == models  # a key of the report, as an attribute
    assert set(models) == set(a.to_dict()["error_estimate"]) & set(a.history_keys())
    for key, m in models.items():
        assert m["estimator"] in ("richardson", "conservative"), key
        assert m["safety"] > 0 and m["conservative_rows"] >= 0, key


def _finite(v, path=""):
    if isinstance(v, dict):
        for k, x in v.items():
            _finite(x, f"{path}.{k}")
    elif isinstance(v, list):
        for i, x in enumerate(v):
            _finite(x, f"{path}[{i}]")
    elif isinstance(v, float):
        assert math.isfinite(v), path


def test_no_nan_in_results():
    _finite(dyncontact.impact.run(**RUN, pressure_at=[0.5]).to_dict())
    _finite(dyncontact.wedge.solve(theta_deg=86, gamma=0.6, alpha=561.249).to_dict())
    _finite(dyncontact.lamb.green(poisson=0.25, at=[0.3], cells=[(0, 0.5)]).to_dict())


def test_results_pickle_as_their_json():
    import pickle

    r = dyncontact.wedge.solve(theta_deg=86, alpha=561.249, digits=20)
    s = pickle.loads(pickle.dumps(r))
    assert s.to_dict() == r.to_dict() and type(s) is type(r)


def test_tables_fit_pandas():
    pd = __import__("pytest").importorskip("pandas")
    df = dyncontact.impact.run(**RUN).to_pandas()
    assert isinstance(df, pd.DataFrame) and "h_over_R_error_estimate" in df
    c = dyncontact.wedge.curve(theta_deg=86, alpha_range=(100, 500, 3)).to_pandas()
    assert len(c) == 3 and "v_over_c1_cot_theta_error_estimate" in c
