"""Bad inputs raise InvalidParameterError (a ValueError) naming the parameter and its
admissible range, as the command line's one line does; numerical failures raise
NumericalError (an ArithmeticError). Never a panic across the boundary."""

from __future__ import annotations

import pytest

import dyncontact
from dyncontact import InvalidParameterError, NumericalError

W = dict(theta_deg=86, alpha=561.249)
RUN = dict(profile="parabola:R=1", mass_ratio=10, v0_over_c1=0.01, end=1, c1=1870.83, c2=1000)


def wedge_solve(**kw):
    return dyncontact.wedge.solve(**{**W, **kw})


def run(**kw):
    return dyncontact.impact.run(**{**RUN, **kw})


CASES = [
    # (call, parameter named)
    (lambda: wedge_solve(theta_deg=95), "theta_deg"),
    (lambda: wedge_solve(theta_deg=0), "theta_deg"),
    (lambda: wedge_solve(alpha=1e6), "alpha"),
    (lambda: wedge_solve(alpha=-1), "alpha"),
    (lambda: wedge_solve(gamma=-0.5), "gamma"),
    (lambda: wedge_solve(c2=2000), "c2"),
    (lambda: wedge_solve(digits=0), "digits"),
    (lambda: wedge_solve(digits=5000), "digits"),
    (lambda: wedge_solve(solution="best"), "solution"),
    (lambda: wedge_solve(coupling="maybe"), "coupling"),
    (lambda: wedge_solve(quantities=["no_such_key"]), "quantities"),
    (lambda: dyncontact.wedge.solve(theta_deg=86), "alpha"),
    (lambda: wedge_solve(alpha=float("nan")), "alpha"),
    (lambda: dyncontact.wedge.stress(**W, at=[1.5]), "at"),
    (lambda: dyncontact.wedge.field(**W, at=[(0.1, 0.2)]), "at"),
    (lambda: dyncontact.wedge.curve(theta_deg=86, alpha_range=(500, 100, 3)), "alpha_range"),
    (lambda: dyncontact.wedge.curve(theta_deg=86, alpha_range=(100, 500, 20000)), "alpha_range steps"),
    (lambda: run(kappa=0.4), "kappa"),
    (lambda: run(levels=5), "levels"),
    (lambda: run(v0_over_c1=1.5), "v0_over_c1"),
    (lambda: run(mass_ratio=-1), "mass_ratio"),
    (lambda: run(dx=0), "dx"),
    (lambda: run(digits=31), "digits"),
    (lambda: run(end="t=1"), "end"),
    (lambda: run(profile="circle"), "profile"),
    (lambda: run(profile="wedge:theta_deg=120"), "profile"),
    (lambda: run(striker="x:y"), "striker"),
    (lambda: run(pressure_at=[5]), "pressure_at"),
    (lambda: run(end=0.01), "dx"),
    (lambda: run(law="sticky"), "law"),
    (lambda: run(mass_ratio="heavy"), "mass_ratio"),
    (lambda: dyncontact.impact.run(profile="parabola:R=1", mass_ratio=10, v0_over_c1=0.01, end=1, poisson=0.7), "poisson"),
    (lambda: dyncontact.impact.run(profile="parabola:R=1", mass_ratio=10, v0_over_c1=0.01, end=1, c1=3000.0), "c2"),
    (lambda: dyncontact.impact.edge(poisson=0.7, speed_over_c1=0.3), "poisson"),
    (lambda: dyncontact.lamb.green(poisson=0.25, at=[-1]), "at"),
    (lambda: dyncontact.lamb.green(poisson=0.25, at=[0.5], digits=3000), "digits"),
    (lambda: dyncontact.lamb.green(poisson=0.25, cells=[(0.5, 0.2)]), "cells"),
    (lambda: wedge_solve(c1="fast"), "c1"),
    (lambda: wedge_solve(gamma=True), "gamma"),
    (lambda: run(progress="yes"), "progress"),
]


@pytest.mark.parametrize("call,parameter", CASES)
def test_a_bad_input_names_its_parameter(call, parameter):
    with pytest.raises(InvalidParameterError) as info:
        call()
    e = info.value
    assert isinstance(e, ValueError)
    assert e.parameter == parameter, str(e)
    message = str(e)
    assert parameter.split()[0] in message, message
    # one line, numbers short, flags spelled as keyword arguments
    assert "\n" not in message and len(message) < 600 and "--" not in message, message


def test_the_refusals_say_the_admissible_range():
    with pytest.raises(InvalidParameterError, match=r"admissible range is \(0, 90\)"):
        wedge_solve(theta_deg=95)
    with pytest.raises(InvalidParameterError, match=r"\[0.5, 64\]"):
        run(kappa=0.4)


def test_a_numerical_failure_is_an_arithmetic_error():
    # a genuine solution next to the Rayleigh speed whose collocation degenerates in f64
    with pytest.raises(NumericalError, match="did not converge") as info:
        dyncontact.wedge.solve(theta_deg="89.9999999", gamma=100, alpha=927.4)
    assert isinstance(info.value, ArithmeticError)
    assert not isinstance(info.value, ValueError)
    assert "theta_deg" in str(info.value)  # the case's inputs come with the reason


def test_unknown_keyword_is_a_type_error():
    with pytest.raises(TypeError):
        dyncontact.wedge.solve(theta_deg=86, alpha=500, thetadeg=3)  # type: ignore[call-arg]
