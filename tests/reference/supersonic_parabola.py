#!/usr/bin/env python3
"""The pressure under a parabola driven at a constant speed through its supersonic stage: the
double series against its sum in closed form (mpmath), the two routes of `docs/impact.md`,
section 6, independent of the time-marching solver.

Units c1 = 1, R = 1, rho = 1. While the contact's edge b = (t_s t)^(1/2) outruns the P wave
(u = t/t_s < 1/4, t_s = 2 V) the displacement of the whole surface is known, and the
half-plane's impedance Z = s zeta(kappa/s),

    zeta(q) = m^4 [(2 q^2 + 1/m^2)^2 - 4 q^2 (q^2 + 1)^(1/2) (q^2 + 1/m^2)^(1/2)]/(q^2 + 1)^(1/2),

m = c2/c1, gives the pressure (where the cone of dependence of (x, t) lies inside the contact,
|x| < b - t) as a double series in its Taylor coefficients zeta_j (in q^2),

    p(x, t)/V = sum_j zeta_j u^j P_j(xi),   xi = x/b,
    P_j(xi) = sum_(i=0..j) (-1)^i (2i + 2j)!/((2i)! (i + j)! (j - i)!) xi^(2i)
            = (1/pi) Int_0^pi (2 cos phi)^(2j) cos((2j + 1) beta)/cos beta dphi,
              sin beta = xi |cos phi|   (Morgan-Voyce polynomials),

whose sum is

    p(x, t)/V = (1/pi) Int_0^pi Re[e^(i beta) zeta(2 u^(1/2) cos phi e^(i beta))]/cos beta dphi,

at the centre (1/pi) Int_0^pi zeta(2 u^(1/2) cos phi) dphi. The series in xi converges while
16 u xi^2 < 1. The script compares the series, summed to convergence, with the integral at
points of the stage (u up to 0.2, 16 u xi^2 up to 0.5) and exits nonzero on a difference above
1e-15; `crates/impact/tests/suite/physics.rs` evaluates the integral in f64 against the march.

Usage: python3 tests/reference/supersonic_parabola.py [nu ...]   (default 0.25 and 0.2)
"""
import sys

import mpmath as mp

mp.mp.dps = 130


def impedance_series(nu, n):
    """zeta_0 .. zeta_(n-1), the Taylor coefficients of zeta in y = q^2."""
    nu = mp.mpf(nu)
    m2 = (1 - 2 * nu) / (2 * (1 - nu))
    m = mp.sqrt(m2)

    def mul(a, b):
        r = [mp.mpf(0)] * n
        for i, x in enumerate(a):
            for j in range(n - i):
                r[i + j] += x * b[j]
        return r

    half = mp.mpf(1) / 2
    s1 = [mp.binomial(half, k) for k in range(n)]  # (1 + y)^(1/2)
    s2 = [mp.binomial(half, k) * m2**k / m for k in range(n)]  # (y + 1/m^2)^(1/2)
    r1 = [mp.binomial(-half, k) for k in range(n)]  # (1 + y)^(-1/2)
    delta = [mp.mpf(0)] * n
    delta[0], delta[1], delta[2] = 1 / m2**2, 4 / m2, mp.mpf(4)
    prod = mul(s1, s2)
    for k in range(n - 1):
        delta[k + 1] -= 4 * prod[k]
    return [x * m2**2 for x in mul(delta, r1)], m


def impedance(m, q):
    n1, n2 = mp.sqrt(q * q + 1), mp.sqrt(q * q + 1 / m**2)
    return m**4 * ((2 * q * q + 1 / m**2) ** 2 - 4 * q * q * n1 * n2) / n1


def polynomial(zeta, u):
    """c_i with p/V = sum_i c_i xi^(2i) at u."""
    n = len(zeta)
    f = mp.factorial
    c = [mp.mpf(0)] * n
    for j in range(n):
        zj = zeta[j] * u**j
        for i in range(j + 1):
            c[i] += zj * (-1) ** i * f(2 * i + 2 * j) / (f(2 * i) * f(i + j) * f(j - i))
    return c


def integral(m, u, xi):
    """The closed form: (1/pi) Int_0^pi Re[e^(i beta) zeta(2 u^(1/2) cos phi e^(i beta))]/cos beta."""
    def f(phi):
        c = mp.cos(phi)
        beta = mp.asin(xi * abs(c))
        e = mp.expj(beta)
        return mp.re(e * impedance(m, 2 * mp.sqrt(u) * c * e)) / mp.cos(beta)
    return mp.quad(f, [0, mp.pi / 2, mp.pi]) / mp.pi


def main():
    nus = sys.argv[1:] or ["0.25", "0.2"]
    worst = mp.mpf(0)
    for nu in nus:
        zeta, m = impedance_series(nu, 160)
        zeta2, _ = impedance_series(nu, 200)
        for u in ("0.02", "0.075", "0.125", "0.2"):
            u = mp.mpf(u)
            c, c2 = polynomial(zeta, u), polynomial(zeta2, u)
            top = mp.sqrt(mp.mpf("0.5") / (16 * u))
            for xi in (mp.mpf(0), top / 2, top):
                xi = min(xi, 1 - mp.sqrt(u))
                series = mp.fsum(ci * xi ** (2 * i) for i, ci in enumerate(c))
                series2 = mp.fsum(ci * xi ** (2 * i) for i, ci in enumerate(c2))
                closed = integral(m, u, xi)
                worst = max(worst, abs(series - closed), abs(series2 - closed))
                print(f"nu = {nu}  u = {mp.nstr(u, 4):6s} xi = {mp.nstr(xi, 4):7s} "
                      f"p/V = {mp.nstr(closed, 18)}  series - closed = "
                      f"{mp.nstr(series - closed, 3)}, {mp.nstr(series2 - closed, 3)}")
    print(f"largest difference {mp.nstr(worst, 3)}")
    sys.exit(0 if worst < mp.mpf(10) ** -15 else 1)


if __name__ == "__main__":
    main()
