#!/usr/bin/env python3
"""The self-similar frictionless wedge with a moving contact edge, by analytic functions
(mpmath), independent of the time-marching solver (`docs/edge.md`, section 5).

A rigid wedge of face slope s driven at speed V into the half-plane (c1 = 1, mu = 1); the
contact |x| < D t; with z = x/t the pressure is P(z) and the normal displacement w = t W(z),
W = V - s|z| on the contact. Off [-1, 1] the half-plane gives

    lam Phi_W(lam) = -g(lam) Phi_P(lam),   g = a1/(m^2 R),
    a_j = sqrt(1/c_j^2 - 1/lam^2),   R = (1/m^2 - 2/lam^2)^2 + 4 a1 a2/lam^2,

Phi_f the Cauchy transform of f'' (W) or f' (P). For D < c2 the contact's condition makes
Phi_P = X Q, X = (lam^2 - D^2)^(-1/2), Q = i (r/lam + a lam/(lam^2 - D^2)):

    P(z) = -(2 r/D) arccosh(D/|z|) - 2 a/sqrt(D^2 - z^2),   r = -s D/(pi (1 - nu)),

r from the apex (the face slope), a the edge's square-root term. Where c_R < D the Rayleigh
points z = +-c_R lie in the contact and W'' carries Q(c_R) delta(z -+ c_R) (a kink in w that
the contact forbids) unless Q(c_R) = 0, i.e. a = r (D^2 - c_R^2)/c_R^2; the edge's height
W(D) = V - s D is a second condition on the same a. The free edge (Signorini) takes a = 0 below
c_R and the Rayleigh condition above it, and V follows from W(0); the kinematic edge (V = s D)
takes a from the height, and above c_R no a meets both.

W on the real axis from the vertical-contour integral W(z) = -Int_0^inf y [Phi_W(z + i y) -
Phi_W(z - i y)] dy (W vanishes beyond the P-wave front, so no constant is left over).

Usage: python3 tests/reference/selfsimilar_wedge.py [nu] [D ...]   (default 0.25 and the
speeds of the docs' table); prints one JSON record per speed.
       python3 tests/reference/selfsimilar_wedge.py --write [FILE]   writes the march's reference
data (nu = 1/4, D = 0.15, 0.3, 0.45; default tests/reference/selfsimilar_wedge_reference.json).
"""
import json
import sys

import mpmath as mp

mp.mp.dps = 20


def material(nu):
    nu = mp.mpf(nu)
    m = mp.sqrt((1 - 2 * nu) / (2 * (1 - nu)))  # c2/c1

    def rayleigh_real(v):
        return (2 - v**2 / m**2) ** 2 - 4 * mp.sqrt(1 - v**2) * mp.sqrt(1 - v**2 / m**2)

    c_r = mp.re(mp.findroot(rayleigh_real, 0.92 * m))
    return nu, m, c_r


def kernel(m):
    def a(lam, c):
        return mp.sqrt(lam - c) * mp.sqrt(lam + c) / (c * lam)

    def g(lam):
        r = (1 / m**2 - 2 / lam**2) ** 2 + 4 * a(lam, 1) * a(lam, m) / lam**2
        return a(lam, 1) / (m**2 * r)

    return g


def w_of(z, g, d, q):
    """W(z) of the pressure whose Phi_P = X i q (unit slope scale)."""
    z = mp.mpf(z)

    def phi_w(lam):
        x = 1 / (mp.sqrt(lam - d) * mp.sqrt(lam + d))
        return -g(lam) * x * 1j * q(lam) / lam

    def f(y):
        return -y * (phi_w(mp.mpc(z, y)) - phi_w(mp.mpc(z, -y)))

    return mp.quad(f, [0, 0.02, 0.1, 0.5, 2, mp.inf]).real


def case(nu, d):
    nu, m, c_r = material(nu)
    g = kernel(m)
    d = mp.mpf(d)
    s = 1  # the face slope: W = V - |z| on the contact, V in units of s
    r = -s * d / (mp.pi * (1 - nu))
    q_r = lambda lam: 1 / lam  # noqa: E731
    q_a = lambda lam: lam / (lam**2 - d**2)  # noqa: E731
    # the contact's points where W is matched: below the Rayleigh point
    z0 = d / 4
    wr, wa = w_of(z0, g, d, q_r), w_of(z0, g, d, q_a)
    out = {"nu": float(nu), "c2_over_c1": float(m), "cR_over_c1": float(c_r), "D": float(d)}
    if d < m:
        # the free edge: a = 0 below c_R, the Rayleigh condition above
        a_free = 0 if d < c_r else r * (d**2 - c_r**2) / c_r**2
        v_free = r * wr + a_free * wa + s * z0  # W(0) = W(z0) + s z0
        out["free_edge"] = {
            "V_over_sD": float(v_free / d),
            "a_over_sD": float(a_free / d),
            # P/(mu s) = C0 arccosh(D/|z|) + C1 D/sqrt(D^2 - z^2)
            "arccosh_coefficient": float(-2 * r / d),
            "edge_coefficient": float(-2 * a_free / d),
        }
        # the kinematic edge: V = s D, a from W(z0) = V - s z0
        a_kin = (s * d - s * z0 - r * wr) / wa
        q_kin = lambda lam: r / lam + a_kin * lam / (lam**2 - d**2)  # noqa: E731
        out["kinematic_edge"] = {
            "a_over_sD": float(a_kin / d),
            "rayleigh_condition_Q_cR": float(q_kin(c_r)) if d > c_r else None,
            # W - (V - s z) on the contact, over V: zero below c_R, not above it
            "height_mismatch_over_V": [
                [float(f), float((w_of(f * d, g, d, q_kin) - (s * d - s * f * d)) / (s * d))]
                for f in (mp.mpf("0.5"), mp.mpf("0.9"), mp.mpf("0.97"), mp.mpf("0.995"))
            ],
        }
    return out


REFERENCE_SPEEDS = ["0.15", "0.3", "0.45"]


if __name__ == "__main__":
    if sys.argv[1:2] == ["--write"]:
        # the reference data of the march's test (`crates/impact/tests/suite/selfsimilar.rs`):
        # nu = 1/4, sub-Rayleigh speeds, where both edge laws have a solution
        out = sys.argv[2] if len(sys.argv) > 2 else "tests/reference/selfsimilar_wedge_reference.json"
        cases = [case("0.25", d) for d in REFERENCE_SPEEDS]
        with open(out, "w") as f:
            json.dump({"source": "tests/reference/selfsimilar_wedge.py --write", "cases": cases}, f, indent=1)
            f.write("\n")
        sys.exit(0)
    nu = sys.argv[1] if len(sys.argv) > 1 else "0.25"
    speeds = sys.argv[2:] or ["0.3", "0.5", "0.555", "0.5558"]
    for d in speeds:
        print(json.dumps(case(nu, d)))
        sys.stdout.flush()
