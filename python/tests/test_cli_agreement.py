"""Every call agrees with the command line's JSON for the same arguments: bit for bit in
f64, digit for digit at digits=40."""

from __future__ import annotations

import json
import math
from decimal import Decimal

import numpy as np
import pytest

import dyncontact

MATERIAL = dict(c1=1870.83, c2=1000)


def same_bits(a, b, path="") -> None:
    """Equal JSON values, floats compared by their bits, Decimals by their digits."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and list(a) == list(b), path
        for k in a:
            same_bits(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            same_bits(x, y, f"{path}[{i}]")
    elif isinstance(a, float):
        assert isinstance(b, float) and math.copysign(1, a) == math.copysign(1, b), path
        assert a.hex() == b.hex(), f"{path}: {a!r} != {b!r}"
    elif isinstance(a, Decimal):
        assert isinstance(b, Decimal) and str(a) == str(b), f"{path}: {a} != {b}"
    else:
        assert type(a) is type(b) and a == b, f"{path}: {a!r} != {b!r}"


def cli_json(text: str, decimal: bool):
    return json.loads(text, parse_float=Decimal if decimal else float)


WEDGE_CASES = [
    ("solve", dict(theta_deg=86, gamma=0.6, alpha=561.249), ["--theta-deg", "86", "--gamma", "0.6", "--alpha", "561.249"]),
    ("solve", dict(theta_deg=80, speed="40", coupling="off"), ["--theta-deg", "80", "--speed", "40", "--coupling", "off"]),
    ("stress", dict(theta_deg=86, alpha=561.249, at=[0.1, 0.5, 1]), ["--theta-deg", "86", "--alpha", "561.249", "--at", "0.1,0.5,1"]),
    ("field", dict(theta_deg=86, alpha=561.249, at=[(0.1, -0.1), (0.3, -0.2)]), ["--theta-deg", "86", "--alpha", "561.249", "--at", "0.1:-0.1,0.3:-0.2"]),
]


@pytest.mark.parametrize("digits", [None, 40])
@pytest.mark.parametrize("sub,kwargs,flags", WEDGE_CASES)
def test_wedge_calls_agree_with_the_cli(cli, sub, kwargs, flags, digits):
    extra = [] if digits is None else ["--digits", str(digits)]
    expected = cli_json(cli("wedge", sub, *flags, *extra, "--json"), digits is not None)
    r = getattr(dyncontact.wedge, sub)(**kwargs, digits=digits)
    same_bits(expected, r.to_dict())


@pytest.mark.parametrize("digits", [None, 40])
def test_curve_agrees_with_the_cli(cli, digits):
    extra = [] if digits is None else ["--digits", str(digits)]
    expected = cli_json(
        cli("wedge", "curve", "--theta-deg", "86", "--gamma", "0.2", "--alpha-range", "100,900,4", *extra, "--json"),
        digits is not None,
    )
    r = dyncontact.wedge.curve(theta_deg=86, gamma=0.2, alpha_range=(100, 900, 4), digits=digits)
    same_bits(expected, r.to_list())
    # each column is the rows' values, in order
    for key in ("alpha", "v_over_c1_cot_theta", "force_over_a_mu_cot_theta"):
        col = getattr(r, key)
        assert len(col) == 4
        for i, row in enumerate(expected):
            assert col[i] == row[key]
    est = r.error_estimates["v_over_c1_cot_theta"]
    assert [e for e in est] == [row["error_estimates"]["v_over_c1_cot_theta"] for row in expected]


RUN_FLAGS = ["--profile", "parabola:R=1", "--mass-ratio", "10", "--v0-over-c1", "0.01",
             "--law", "signorini", "--end", "c1t/R=1", "--c1", "1870.83", "--c2", "1000",
             "--pressure-at", "c1t/R=0.5,1"]
RUN_KWARGS = dict(striker="rigid", profile="parabola:R=1", mass_ratio=10, v0_over_c1=0.01,
                  law="signorini", end=1, pressure_at=[0.5, 1], **MATERIAL)


def test_impact_run_agrees_with_the_cli(cli):
    expected = cli_json(cli("impact", "run", *RUN_FLAGS, "--json"), False)
    r = dyncontact.impact.run(**RUN_KWARGS)
    same_bits(expected, r.to_dict())
    # the arrays hold the same doubles
    for key in ("c1t_over_R", "h_over_R", "b_over_R", "force_over_rho_c1sq_R"):
        a = getattr(r, key)
        assert a.dtype == np.float64
        assert [x.hex() for x in a.tolist()] == [x.hex() for x in map(float, expected[key])]
        if key in expected["error_estimate"]:
            assert np.array_equal(r.error_estimate[key], np.array(expected["error_estimate"][key]))
    p = r.pressure
    assert p.p_over_rho_c1sq.shape == (2, max(len(q["x_over_R"]) for q in expected["pressure"]))
    for i, q in enumerate(expected["pressure"]):
        k = len(q["p_over_rho_c1sq"])
        assert p.p_over_rho_c1sq[i, :k].tolist() == q["p_over_rho_c1sq"]
        assert p.error_estimate[i, :k].tolist() == q["error_estimate"]
        assert bool(np.all(p.p_over_rho_c1sq.mask[i, k:]))


def test_impact_run_at_30_digits_agrees_with_the_cli(cli):
    flags = ["--profile", "parabola:R=1", "--mass-ratio", "10", "--v0-over-c1", "0.01",
             "--end", "c1t/R=0.2", "--poisson", "0.25", "--digits", "30", "--levels", "2"]
    expected = cli_json(cli("impact", "run", *flags, "--json"), True)
    r = dyncontact.impact.run(profile="parabola:R=1", mass_ratio=10, v0_over_c1=0.01, end=0.2,
                              poisson=0.25, digits=30, levels=2)
    same_bits(expected, r.to_dict())
    assert r.h_over_R.dtype == object and isinstance(r.h_over_R[-1], Decimal)


def test_impact_run_with_the_cylinder_striker_agrees_with_the_cli(cli):
    # the striker's text passes through; the cylinder's mass is its own (no mass_ratio)
    striker = "cylinder:c1=1870.83,c2=1000,density_ratio=1"
    flags = ["--c1", "1870.83", "--c2", "1000", "--striker", striker, "--profile", "parabola:R=1",
             "--v0-over-c1", "0.01", "--end", "c1t/R=0.5", "--dx", "0.02", "--levels", "2"]
    expected = cli_json(cli("impact", "run", *flags, "--json"), False)
    r = dyncontact.impact.run(c1=1870.83, c2=1000, striker=striker, profile="parabola:R=1",
                              v0_over_c1=0.01, end=0.5, dx=0.02, levels=2)
    same_bits(expected, r.to_dict())
    assert expected["striker"] == "cylinder"
    assert math.isclose(expected["mass_ratio"], math.pi, rel_tol=1e-15)
    parts = r.striker_strain_energy_over_rho_c1sq_Rsq + r.striker_vibration_energy_over_rho_c1sq_Rsq
    assert np.allclose(parts, r.striker_energy_over_rho_c1sq_Rsq, rtol=1e-9, atol=0.0)


def test_impact_run_axisymmetric_agrees_with_the_cli(cli):
    # the sphere on the half-space: the same call, --geometry axisymmetric, its own keys
    flags = ["--geometry", "axisymmetric", "--poisson", "0.25", "--profile", "sphere:R=1",
             "--mass-ratio", "4.18879", "--v0-over-c1", "0.05", "--law", "signorini",
             "--end", "separation:max=15", "--dr", "0.02", "--levels", "2",
             "--pressure-at", "c1t/R=3"]
    expected = cli_json(cli("impact", "run", *flags, "--json"), False)
    r = dyncontact.impact.run(geometry="axisymmetric", poisson=0.25, profile="sphere:R=1",
                              mass_ratio=4.18879, v0_over_c1=0.05, law="signorini",
                              end="separation:max=15", dr=0.02, levels=2, pressure_at=[3])
    same_bits(expected, r.to_dict())
    assert expected["geometry"] == "axisymmetric"
    for key in ("a_over_R", "force_over_rho_c1sq_Rsq", "radiated_energy_fraction"):
        assert len(expected[key]) == len(expected["c1t_over_R"])
        assert key in expected["error_estimate"]
    assert 0.0 < expected["restitution"] < 1.0
    assert r.pressure.r_over_R.shape == r.pressure.p_over_rho_c1sq.shape[1:]


@pytest.mark.parametrize("law", ["signorini", "kinematic"])
def test_impact_edge_agrees_with_the_cli(cli, law):
    expected = cli_json(cli("impact", "edge", "--poisson", "0.25", "--speed-over-c1", "0.3,0.55,0.7,1.4", "--law", law, "--json"), False)
    r = dyncontact.impact.edge(poisson=0.25, speed_over_c1=[0.3, 0.55, 0.7, 1.4], law=law)
    same_bits(expected, r.to_dict())
    assert r.records.speed_over_c1.tolist() == [0.3, 0.55, 0.7, 1.4]


def test_impact_striker_green_agrees_with_the_cli(cli):
    expected = cli_json(
        cli("impact", "striker-green", "--poisson", "0.25", "--arc-over-R", "0.1", "--at-deg", "0,5.73,180", "--times", "c2t/R=0.1,1", "--json"),
        False,
    )
    r = dyncontact.impact.striker_green(poisson=0.25, arc_over_R=0.1, at_deg=[0, 5.73, 180], times=[0.1, 1])
    same_bits(expected, r.to_dict())
    assert r.w_over_p0R_mu.shape == (3, 2)
    # the deformation is the total without the translation's mean over the arc
    theta0 = 0.05
    x = 2 * np.sin(theta0) * np.asarray([0.1, 1.0]) ** 2 / (2 * np.pi)
    mean = np.outer(np.cos(np.radians([0, 5.73, 180])), x) * np.sin(theta0) / theta0
    assert np.allclose(r.w_over_p0R_mu - r.w_def_over_p0R_mu, mean, rtol=0, atol=1e-15)


@pytest.mark.parametrize("digits", [None, 40])
def test_lamb_green_agrees_with_the_cli(cli, digits):
    extra = [] if digits is None else ["--digits", str(digits)]
    expected = cli_json(
        cli("impact", "green", "--poisson", "0.25", "--at", "0.3,0.6,1.5", "--cells", "0:0.5,0.5:0.9", "--constants", *extra, "--json"),
        digits is not None,
    )
    r = dyncontact.lamb.green(poisson=0.25, at=[0.3, 0.6, 1.5], cells=[(0, 0.5), (0.5, 0.9)], constants=True, digits=digits)
    same_bits(expected, r.to_dict())
    assert len(r.points.g_zz) == 3
    assert list(r.points.error_estimate["g_zz"]) == [p["error_estimate"]["g_zz"] for p in expected["points"]]


def test_decimal_inputs_are_taken_as_written(cli):
    expected = cli_json(cli("wedge", "solve", "--theta-deg", "86", "--alpha", "561.24900000000000000001", "--digits", "40", "--json"), True)
    r = dyncontact.wedge.solve(theta_deg="86", alpha=Decimal("561.24900000000000000001"), digits=40)
    same_bits(expected, r.to_dict())
    assert isinstance(r.v_over_c1_cot_theta, Decimal)
    # a float is its shortest repr: 561.249 is the decimal 561.249
    a = dyncontact.wedge.solve(theta_deg=86, alpha=561.249, digits=40)
    b = dyncontact.wedge.solve(theta_deg=86, alpha="561.249", digits=40)
    same_bits(a.to_dict(), b.to_dict())
