#!/usr/bin/env python3
r"""Independent mpmath reference values for a free elastic disk (solid circular cylinder in
plane strain) loaded by a surface pressure: natural frequencies and the Laplace-domain
transfer function of the normal surface displacement for a cos(n theta) pressure.

Derived from first principles below (plane-strain linear isotropic elastodynamics); no Rust
code consulted.  python3 + mpmath only.

Run from the repository root:
    python3 tests/reference/disk_mpmath.py > tests/reference/disk_reference.json
(about 5 minutes, almost all of it in the Ritz-Galerkin cross-check).  Checks are printed to
stderr and asserted.

Model and conventions
---------------------
Disk of radius R = 1, shear modulus mu = 1, density rho = 1, hence c2 = 1 and
    c1^2 = lambda + 2 = 2 (1 - nu)/(1 - 2 nu),   lambda = 2 nu/(1 - 2 nu) = c1^2 - 2.
Polar coordinates (r, theta); u_r positive OUTWARD, u_theta positive towards +theta.
Units: lengths / R, time / (R/c2), stresses / mu.  Frequencies are omega R/c2; s is the
Laplace variable in units c2/R.  Surface r = 1: sigma_rr = -p(theta, t) (a positive pressure
pushes inward), sigma_rtheta = 0.  Zero initial conditions.

Harmonic n: u_r = U(r) cos(n theta), u_theta = V(r) sin(n theta).  For p = P(s) cos(n theta)
(P(s) = 1) the reported quantity is the transfer function of the INWARD normal displacement
    W_n(s) = -U(1; s) / P(s).

Derivation (potentials, Laplace domain)
---------------------------------------
u = grad(phi) + curl(psi e_z):  u_r = phi_r + psi_theta/r,  u_theta = phi_theta/r - psi_r.
Navier's equations reduce to  lap(phi) = (s/c1)^2 phi,  lap(psi) = (s/c2)^2 psi.  Solutions
regular at r = 0:
    phi = A I_n(x1 r) cos(n theta),  psi = B I_n(x2 r) sin(n theta),  x1 = s/c1, x2 = s/c2 = s.
Write, for x = x1 or x2 (at r = 1),
    I(x) = I_n(x),  Q(x) = x I_n'(x) = n I_n(x) + x I_{n+1}(x),
and use x^2 I_n'' = (x^2 + n^2) I_n - x I_n' and (lambda + 2) x1^2 = s^2.  At r = 1:
    U          =  A Q1 + n B I2
    V          = -n A I1 - B Q2
    sigma_rr   = [ (s^2 + 2 n^2) I1 - 2 Q1 ] A + 2 n [ Q2 - I2 ] B          (x cos n theta)
    sigma_rt   =  2 n [ I1 - Q1 ] A - [ (s^2 + 2 n^2) I2 - 2 Q2 ] B        (x sin n theta)
with I1 = I(x1), Q1 = Q(x1), I2 = I(x2), Q2 = Q(x2).  Imposing sigma_rr = -P, sigma_rt = 0
and eliminating A, B gives the closed form (P = 1)

    W_n(s) = N_n(s) / D_n(s),
    N_n(s) = Q1 [ (s^2 + 2 n^2) I2 - 2 Q2 ] + 2 n^2 I2 [ I1 - Q1 ],
    D_n(s) = [ (s^2 + 2 n^2) I1 - 2 Q1 ] [ (s^2 + 2 n^2) I2 - 2 Q2 ]
             - 4 n^2 [ Q1 - I1 ] [ Q2 - I2 ].

W_n depends on s^2 only (real for real s).  For n = 0 the shear part decouples and
W_0 = x1 I_1(x1) / [ s^2 I_0(x1) - 2 x1 I_1(x1) ].
Evaluation: directly with mpmath.besseli (complex argument allowed).  The numerator and the
denominator both cancel at leading order as s -> 0 (relative size s^2 for n != 1, s^4 for
D_1), so each evaluation is done with 20 + 6 max(0, -log10|s|) guard digits.

Frequency equation (free vibrations)
------------------------------------
Free modes are the zeros of D_n on the imaginary axis, s = i omega.  With
I_n(i y) = i^n J_n(y) and x I_n'(x) = i^n y J_n'(y):  D_n(i omega) = (-1)^n F_n(omega),

    F_n(omega) = [ (2 n^2 - omega^2) J_n(y1) - 2 y1 J_n'(y1) ] [ (2 n^2 - omega^2) J_n(y2) - 2 y2 J_n'(y2) ]
                 - 4 n^2 [ y1 J_n'(y1) - J_n(y1) ] [ y2 J_n'(y2) - J_n(y2) ],
    y1 = omega/c1,  y2 = omega/c2 = omega,   y J_n'(y) = n J_n(y) - y J_{n+1}(y),

(the classical Love/Onoe plane-strain disk equation, multiplied out: J_n is entire, so F_n has
no poles).  For n = 0, F_0 = G_0(omega) * omega^2 J_2(omega): the factor omega^2 J_2(omega)
holds the torsional modes (u_r = 0, J_2(omega) = 0) and is excluded; the radial breathing
modes are the zeros of
    G_0(omega) = 2 y1 J_1(y1) - omega^2 J_0(y1)      (i.e. y1 J_0(y1)/J_1(y1) = 2/c1^2
                                                       = (1 - 2 nu)/(1 - nu)).
Roots: sign changes of F_n (G_0 for n = 0) on the grid omega = 0.05 + 0.005 k, refined by
mpmath.findroot (Anderson bracketing solver); the count of sign changes is repeated on a
0.001 grid up to the 4th root, and the Ritz check below confirms that no root is missed.

Independent checks (all in the JSON under "checks")
---------------------------------------------------
(a) Static limits.  n = 0: W_0(0) = 1/(2 (lambda + mu)) = 1/(2 (c1^2 - 1)).  n >= 2: Airy
    stress function Phi = (a r^n + b r^(n+2)) cos(n theta) gives
        sigma_rr = [a n (1-n) r^(n-2) + b (n + 2 - n^2) r^n] cos,
        sigma_tt = [a n (n-1) r^(n-2) + b (n+2)(n+1) r^n] cos,
        sigma_rt = n [a (n-1) r^(n-2) + b (n+1) r^n] sin,
    traction conditions at r = 1: a = 1/(2 (n-1)), b = -1/(2 (n+1)); integrating the
    plane-strain eps_rr = [(1-nu) sigma_rr - nu sigma_tt]/(2 mu):
        U(1) = (1/2) [ (1-nu)(-a n + b (n+2-n^2)/(n+1)) - nu (a n + b (n+2)) ],
    which for n = 2 is W_2(0) = -U(1) = (3 - 2 nu)/6.  (The displacement field so obtained
    is verified to reproduce sigma_rt, i.e. compatibility, in the script.)  Compared with
    W_n(1e-6) (residual O(s^2)) and with the two-level Richardson extrapolation from
    s = 1e-6, 5e-7, 2.5e-7 (W is a function of s^2; residual O(s^6)).
(b) n = 1, rigid translation: the pressure resultant is pi P in -x, the mass is pi, so
    u_r(1, 0) ~ -P/s^2 and s^2 W_1(s) -> 1.  Residual s^2 W_1(s) - 1 at s = 1e-6, and the
    next coefficient C1 = lim (W_1 - 1/s^2) by Richardson extrapolation (informative).
(c) The potential solution is differentiated numerically (mpmath.diff of A I_n(x1 r),
    B I_n(x2 r), no Bessel identities) and inserted into the polar Navier equations
        c1^2 (Delta)' - (n/r) Omega = s^2 U,   -c1^2 (n/r) Delta + Omega' = s^2 V,
        Delta = U' + U/r + n V/r,  Omega = V' + V/r + n U/r,
    at r = 0.6, and into the traction conditions
        sigma_rr = lambda Delta + 2 U' = -1,  sigma_rt = -n U/r + V' - V/r = 0   at r = 1.
(d) Ritz-Galerkin with polynomials (no Bessel functions): U, V spanned by r^(n-1+2k)
    (n >= 2), U by r^(1+2k), V = 0 (n = 0), and for n = 1 the rigid field (U, V) = (1, -1)
    plus (r^(2k), 0), (0, r^(2k)), k >= 1.  Exact rational stiffness and mass matrices from
        energy  = (1/2) Int_0^1 [ lambda (e_rr + e_tt)^2 + 2 (e_rr^2 + e_tt^2) + g^2 ] r dr,
        kinetic = (1/2) Int_0^1 (U_t^2 + V_t^2) r dr,
        e_rr = U',  e_tt = (U + n V)/r,  g = V' - V/r - n U/r,
    load vector -U_i(1) (the common factor pi or 2 pi of the theta integration cancels).
    (K + s^2 M) q = f gives W_n(s) for every (n, s) reported, and K q = omega^2 M q the
    frequencies (Ritz values are upper bounds converging in order, so a missed root would
    show up).  Solved at 240 digits; truncation error estimated by a second, larger basis.
(e) Consistency D_n(i omega) = (-1)^n F_n(omega) at random omega; F_0 = G_0 omega^2 J_2.
(f) Literature: the n = 0 plane-stress disk equation z J0(z)/J1(z) = 1 - nu' is the
    plane-strain one with 2/c1^2 = 1 - nu', i.e. nu = nu'/(1 + nu').  The published roots
    z = 2.067364, 5.395106, 8.575401, 11.734360 (Giurgiutiu, Structural Health Monitoring
    with Piezoelectric Wafer Active Sensors, ch. 10, eq. (58); these numbers correspond to
    1 - nu' = 0.67) are compared with y1 = omega/c1 at nu = 0.33/1.33.  For n = 2 the
    plane-stress frequency parameter Omega = omega a sqrt(rho (1 - nu'^2)/E)
    = (omega a/c2) sqrt((1 - nu')/2) at nu' = 0.3 (nu = 3/13) is reported for comparison
    with tables of in-plane disk modes.

Numerics: reported run at mp.dps = 40 (findroot at 50 digits, W_n with the guard digits
above), repeated at mp.dps = 60; every reported value (30 significant digits) is asserted to
agree between the two runs.
"""
import sys
import json
import time
from fractions import Fraction as Fr

from mpmath import mp, mpf, mpc, sqrt, pi, besselj, besseli, findroot, log10, ceil

BASE_DPS = 40
CHECK_DPS = 60
SIG = 30
NUS = ["0.25", "0.3"]
FREQ_N = [0, 2, 3]
NROOTS = 4
GRID_START = "0.05"
GRID_H = "0.005"
FINE_H = "0.001"
LAP_N = [0, 1, 2, 3, 10]
S_LIST = [("0.1", "0"), ("1", "0"), ("3", "2"), ("10", "0"), ("0.5", "20")]
S_SMALL = "1e-6"
RITZ_DPS = 240
RITZ_K_FREQ = (20, 26)      # polynomial terms per component (base, convergence check)
RITZ_K_LAP = (32, 38)
LIT_N0 = ["2.067364", "5.395106", "8.575401", "11.734360"]


def log_err(*a):
    print(*a, file=sys.stderr)


def check(cond, msg):
    log_err(("  ok   " if cond else "  FAIL ") + msg)
    assert cond, msg


def fmt(x, sig=SIG):
    if x == 0:
        return "0"
    return mp.nstr(x, sig, strip_zeros=False)


def e3(x):
    return mp.nstr(x, 3)


def material(nu_s):
    nu = mpf(nu_s)
    c1sq = 2 * (1 - nu) / (1 - 2 * nu)
    return nu, sqrt(c1sq), c1sq - 2


def parse_s(re_s, im_s):
    return mpf(re_s) if mpf(im_s) == 0 else mpc(mpf(re_s), mpf(im_s))


# ---------------------------------------------------------------- frequency equation
def F_freq(n, w, c1):
    """F_n(omega) (n >= 1) or the breathing factor G_0(omega) (n = 0)."""
    y1, y2 = w / c1, w
    if n == 0:
        return 2 * y1 * besselj(1, y1) - w ** 2 * besselj(0, y1)
    J1, J2 = besselj(n, y1), besselj(n, y2)
    P1 = n * J1 - y1 * besselj(n + 1, y1)
    P2 = n * J2 - y2 * besselj(n + 1, y2)
    a = 2 * n * n - w * w
    return (a * J1 - 2 * P1) * (a * J2 - 2 * P2) - 4 * n * n * (P1 - J1) * (P2 - J2)


def F_full(n, w, c1):
    """The multiplied-out F_n without removing the torsional factor (also for n = 0)."""
    y1, y2 = w / c1, w
    J1, J2 = besselj(n, y1), besselj(n, y2)
    P1 = n * J1 - y1 * besselj(n + 1, y1)
    P2 = n * J2 - y2 * besselj(n + 1, y2)
    a = 2 * n * n - w * w
    return (a * J1 - 2 * P1) * (a * J2 - 2 * P2) - 4 * n * n * (P1 - J1) * (P2 - J2)


def sign_changes(n, c1, h, stop_after=None, w_end=None):
    """Brackets (a, b) of sign changes of F on 0.05 + k h (low precision suffices)."""
    out = []
    with mp.workdps(20):
        h = mpf(h)
        k = 0
        w = mpf(GRID_START)
        f = F_freq(n, w, c1)
        assert f != 0
        while True:
            k += 1
            w2 = mpf(GRID_START) + k * h
            f2 = F_freq(n, w2, c1)
            assert f2 != 0, (n, w2)
            if (f < 0) != (f2 < 0):
                out.append((w, w2))
                if stop_after is not None and len(out) >= stop_after:
                    return out
            if w_end is not None and w2 >= w_end:
                return out
            w, f = w2, f2


def refine_root(n, c1, a, b):
    with mp.workdps(mp.dps + 10):
        a, b = mpf(a), mpf(b)
        r = findroot(lambda x: F_freq(n, x, c1), (a, b), solver="anderson")
        assert a <= r <= b, (n, a, b, r)
        eps = mpf(10) ** (-(mp.dps - 10))
        fl, fr = F_freq(n, r - eps * r, c1), F_freq(n, r + eps * r, c1)
        assert (fl < 0) != (fr < 0), (n, r)
    return +r


# ---------------------------------------------------------------- Laplace transfer function
def guard_digits(s):
    return 20 + int(ceil(6 * max(mpf(0), -log10(abs(s)))))


def W_closed(n, s, c1):
    """W_n(s) = N_n/D_n (closed form of the module docstring)."""
    with mp.workdps(mp.dps + guard_digits(s)):
        x1, x2 = s / c1, s
        I1, I2 = besseli(n, x1), besseli(n, x2)
        Q1 = n * I1 + x1 * besseli(n + 1, x1)
        Q2 = n * I2 + x2 * besseli(n + 1, x2)
        a = s * s + 2 * n * n
        N = Q1 * (a * I2 - 2 * Q2) + 2 * n * n * I2 * (I1 - Q1)
        D = (a * I1 - 2 * Q1) * (a * I2 - 2 * Q2) - 4 * n * n * (Q1 - I1) * (Q2 - I2)
        w = N / D
    return +w


def D_closed(n, s, c1):
    x1, x2 = s / c1, s
    I1, I2 = besseli(n, x1), besseli(n, x2)
    Q1 = n * I1 + x1 * besseli(n + 1, x1)
    Q2 = n * I2 + x2 * besseli(n + 1, x2)
    a = s * s + 2 * n * n
    return (a * I1 - 2 * Q1) * (a * I2 - 2 * Q2) - 4 * n * n * (Q1 - I1) * (Q2 - I2)


def airy_static(n, nu):
    """(W_n(0), max compatibility residual) from the Airy solution, n >= 2."""
    a = mpf(1) / (2 * (n - 1))
    b = -mpf(1) / (2 * (n + 1))
    U1 = ((1 - nu) * (-a * n + b * (n + 2 - n * n) / (n + 1)) - nu * (a * n + b * (n + 2))) / 2
    # compatibility: gamma from the integrated displacements equals sigma_rt / mu
    worst = mpf(0)
    for r in [mpf("0.3"), mpf("0.7"), mpf(1)]:
        srr = a * n * (1 - n) * r ** (n - 2) + b * (n + 2 - n * n) * r ** n
        stt = a * n * (n - 1) * r ** (n - 2) + b * (n + 2) * (n + 1) * r ** n
        srt = n * (a * (n - 1) * r ** (n - 2) + b * (n + 1) * r ** n)

        def Uf(rr):
            return ((1 - nu) * (-a * n * rr ** (n - 1) + b * (n + 2 - n * n) * rr ** (n + 1) / (n + 1))
                    - nu * (a * n * rr ** (n - 1) + b * (n + 2) * rr ** (n + 1))) / 2

        def Vf(rr):
            s_rr = a * n * (1 - n) * rr ** (n - 2) + b * (n + 2 - n * n) * rr ** n
            s_tt = a * n * (n - 1) * rr ** (n - 2) + b * (n + 2) * (n + 1) * rr ** n
            ett = ((1 - nu) * s_tt - nu * s_rr) / 2
            return (rr * ett - Uf(rr)) / n

        gam = -n * Uf(r) / r + mp.diff(Vf, r) - Vf(r) / r
        worst = max(worst, abs(gam - srt))
        # and eps_rr
        err = mp.diff(Uf, r)
        worst = max(worst, abs(err - ((1 - nu) * srr - nu * stt) / 2))
    return -U1, worst


def richardson(f, s):
    """f(0) from f(s), f(s/2), f(s/4) for f = f0 + a s^2 + b s^4 + ... (error O(s^6))."""
    a, b, c = f(s), f(s / 2), f(s / 4)
    r1, r2 = (4 * b - a) / 3, (4 * c - b) / 3
    return (16 * r2 - r1) / 15


def pde_check(n, s, c1, lam):
    """Max relative residual of Navier equations (r = 0.6) and BCs (r = 1), numeric derivatives."""
    with mp.workdps(mp.dps + guard_digits(s) + 20):
        x1, x2 = s / c1, s
        I1, I2 = besseli(n, x1), besseli(n, x2)
        Q1 = n * I1 + x1 * besseli(n + 1, x1)
        Q2 = n * I2 + x2 * besseli(n + 1, x2)
        a = s * s + 2 * n * n
        a11, a12 = a * I1 - 2 * Q1, 2 * n * (Q2 - I2)
        a21, a22 = 2 * n * (I1 - Q1), -(a * I2 - 2 * Q2)
        D = a11 * a22 - a12 * a21
        A, B = -a22 / D, a21 / D          # sigma_rr = -1, sigma_rt = 0

        def phi(r):
            return A * besseli(n, x1 * r)

        def psi(r):
            return B * besseli(n, x2 * r)

        def fields(r):
            p = [mp.diff(phi, r, k) for k in range(4)]
            q = [mp.diff(psi, r, k) for k in range(4)]
            U = p[1] + n * q[0] / r
            U1 = p[2] + n * q[1] / r - n * q[0] / r ** 2
            U2 = p[3] + n * q[2] / r - 2 * n * q[1] / r ** 2 + 2 * n * q[0] / r ** 3
            V = -n * p[0] / r - q[1]
            V1 = -n * p[1] / r + n * p[0] / r ** 2 - q[2]
            V2 = -n * p[2] / r + 2 * n * p[1] / r ** 2 - 2 * n * p[0] / r ** 3 - q[3]
            return U, U1, U2, V, V1, V2

        r = mpf("0.6")
        U, U1, U2, V, V1, V2 = fields(r)
        Dl = U1 + U / r + n * V / r
        Dl_r = U2 + U1 / r - U / r ** 2 + n * V1 / r - n * V / r ** 2
        Om = V1 + V / r + n * U / r
        Om_r = V2 + V1 / r - V / r ** 2 + n * U1 / r - n * U / r ** 2
        e1 = c1 ** 2 * Dl_r - n * Om / r - s * s * U
        e2 = -c1 ** 2 * n * Dl / r + Om_r - s * s * V
        scale = max(abs(s * s * U), abs(s * s * V), abs(c1 ** 2 * Dl_r), abs(Om_r))
        nav = max(abs(e1), abs(e2)) / scale
        r = mpf(1)
        U, U1, U2, V, V1, V2 = fields(r)
        srr = lam * (U1 + U + n * V) + 2 * U1
        srt = -n * U + V1 - V
        bc = max(abs(srr + 1), abs(srt))
        wdiff = abs(-U - W_closed(n, s, c1)) / abs(U)
    return nav, bc, wdiff


# ---------------------------------------------------------------- Ritz-Galerkin (exact rationals)
def pmul(a, b):
    out = {}
    for e1, k1 in a.items():
        for e2, k2 in b.items():
            out[e1 + e2] = out.get(e1 + e2, 0) + k1 * k2
    return {e: k for e, k in out.items() if k != 0}


def padd(*ps):
    out = {}
    for p in ps:
        for e, k in p.items():
            out[e] = out.get(e, 0) + k
    return {e: k for e, k in out.items() if k != 0}


def pscale(p, c):
    return {e: k * c for e, k in p.items() if k * c != 0}


def pder(p):
    return {e - 1: k * e for e, k in p.items() if e != 0}


def pdivr(p):
    return {e - 1: k for e, k in p.items()}


def pint(p):
    """Int_0^1 p(r) r dr."""
    tot = Fr(0)
    for e, k in p.items():
        assert e >= -1, (e, k)
        tot += Fr(k) / (e + 2)
    return tot


def ritz_basis(n, K):
    B = []
    if n == 0:
        for k in range(K):
            B.append(({1 + 2 * k: Fr(1)}, {}))
    elif n == 1:
        B.append(({0: Fr(1)}, {0: Fr(-1)}))
        for k in range(1, K):
            B.append(({2 * k: Fr(1)}, {}))
            B.append(({}, {2 * k: Fr(1)}))
    else:
        for k in range(K):
            B.append(({n - 1 + 2 * k: Fr(1)}, {}))
            B.append(({}, {n - 1 + 2 * k: Fr(1)}))
    return B


_RITZ_CACHE = {}


def ritz_matrices(n, K):
    key = (n, K)
    if key in _RITZ_CACHE:
        return _RITZ_CACHE[key]
    B = ritz_basis(n, K)
    N = len(B)
    st = []
    for U, V in B:
        err = pder(U)
        ett = pdivr(padd(U, pscale(V, n)))
        g = padd(pder(V), pscale(pdivr(V), -1), pscale(pdivr(U), -n))
        st.append((err, ett, g, padd(err, ett)))
    KL = [[None] * N for _ in range(N)]
    KM = [[None] * N for _ in range(N)]
    M = [[None] * N for _ in range(N)]
    for i in range(N):
        for j in range(i, N):
            si, sj = st[i], st[j]
            KL[i][j] = KL[j][i] = pint(pmul(si[3], sj[3]))
            KM[i][j] = KM[j][i] = (2 * pint(pmul(si[0], sj[0])) + 2 * pint(pmul(si[1], sj[1]))
                                   + pint(pmul(si[2], sj[2])))
            M[i][j] = M[j][i] = pint(pmul(B[i][0], B[j][0])) + pint(pmul(B[i][1], B[j][1]))
    f = [sum(U.values(), Fr(0)) for U, V in B]   # U_i(1)
    _RITZ_CACHE[key] = (KL, KM, M, f)
    return _RITZ_CACHE[key]


def frac_mpf(x):
    return mpf(x.numerator) / x.denominator


def ritz_system(n, K, nu_s):
    KL, KM, M, f = ritz_matrices(n, K)
    nu = Fr(nu_s)
    lam = 2 * nu / (1 - 2 * nu)
    N = len(f)
    Km = mp.matrix([[frac_mpf(lam * KL[i][j] + KM[i][j]) for j in range(N)] for i in range(N)])
    Mm = mp.matrix([[frac_mpf(M[i][j]) for j in range(N)] for i in range(N)])
    fv = mp.matrix([frac_mpf(x) for x in f])
    return Km, Mm, fv


def ritz_freqs(n, K, nu_s):
    with mp.workdps(RITZ_DPS):
        Km, Mm, fv = ritz_system(n, K, nu_s)
        L = mp.cholesky(Mm)
        Li = mp.inverse(L)
        A = Li * Km * Li.T
        A = (A + A.T) / 2
        E = sorted(mp.eigsy(A, eigvals_only=True))
        assert E[0] > 0
        return [sqrt(x) for x in E]


def ritz_W(n, K, nu_s, svals):
    with mp.workdps(RITZ_DPS):
        Km, Mm, fv = ritz_system(n, K, nu_s)
        out = []
        for s in svals:
            q = mp.lu_solve(Km + s * s * Mm, -fv)
            out.append(-sum(q[i] * fv[i] for i in range(len(fv))))
        return out


def rel(a, b):
    if a == b:
        return mpf(0)
    return abs(a - b) / max(abs(a), abs(b))


# ---------------------------------------------------------------- main computation
def compute(dps, brackets=None):
    """All reported values at precision dps.  brackets: from the base run (else searched)."""
    mp.dps = dps
    res = {"cases": {}, "brackets": {}}
    for nu_s in NUS:
        nu, c1, lam = material(nu_s)
        case = {"c1": c1, "lambda": lam, "freq": {}, "lap": {}}
        for n in FREQ_N:
            if brackets is None:
                br = sign_changes(n, c1, GRID_H, stop_after=NROOTS)
                res["brackets"][(nu_s, n)] = br
            else:
                br = brackets[(nu_s, n)]
            case["freq"][n] = [refine_root(n, c1, a, b) for a, b in br]
        for n in LAP_N:
            for sr, si in S_LIST:
                case["lap"][(n, sr, si)] = W_closed(n, parse_s(sr, si), c1)
        res["cases"][nu_s] = case
    return res


def checks_base(res):
    """Independent checks (base precision).  Returns dict of strings for the JSON."""
    out = {}
    eps_s = mpf(S_SMALL)

    # --- root search completeness on the finer grid
    fine = {}
    for nu_s in NUS:
        nu, c1, lam = material(nu_s)
        for n in FREQ_N:
            roots = res["cases"][nu_s]["freq"][n]
            br = sign_changes(n, c1, FINE_H, w_end=roots[-1] + mpf(GRID_H))
            ok = len(br) == NROOTS and all(a <= r <= b for (a, b), r in zip(br, roots))
            check(ok, f"nu={nu_s} n={n}: {len(br)} sign changes on the {FINE_H} grid up to the 4th root "
                      f"({mp.nstr(roots[-1], 8)}), same brackets as the roots")
            fine[f"nu={nu_s},n={n}"] = str(len(br))
    out["fine_grid_sign_changes"] = fine

    # --- (e) consistency D_n(i w) = (-1)^n F_n(w); F_0 = G_0 w^2 J_2
    worst_e = mpf(0)
    for nu_s in NUS:
        nu, c1, lam = material(nu_s)
        for n in [0, 1, 2, 3, 10]:
            for w in [mpf("0.77"), mpf("2.9"), mpf("6.3")]:
                with mp.workdps(mp.dps + 10):
                    d = D_closed(n, mpc(0, w), c1)
                    f = (-1) ** n * F_full(n, w, c1)
                    worst_e = max(worst_e, abs(d - f) / abs(f))
                    if n == 0:
                        g = F_freq(0, w, c1) * w ** 2 * besselj(2, w)
                        worst_e = max(worst_e, abs(g - f) / abs(f))
        tol = mpf(10) ** (-(mp.dps - 8))
        for r in res["cases"][nu_s]["freq"][0]:
            with mp.workdps(mp.dps + 10):
                assert abs(F_full(0, r, c1)) < tol * r ** 4, (nu_s, r)
    check(worst_e < mpf(10) ** (-(mp.dps - 5)),
          f"(e) D_n(i w) = (-1)^n F_n(w) and F_0 = G_0 w^2 J_2(w): max rel residual {e3(worst_e)}")
    out["e_Dn_vs_Fn_max_rel"] = e3(worst_e)

    # --- (a) static limits, (b) rigid translation
    stat = {}
    for nu_s in NUS:
        nu, c1, lam = material(nu_s)
        W0s = 1 / (2 * (c1 ** 2 - 1))
        w0 = W_closed(0, eps_s, c1)
        r0 = abs(w0 - W0s) / W0s
        r0x = abs(richardson(lambda x: W_closed(0, x, c1), eps_s) - W0s) / W0s
        check(r0 < mpf("1e-10") and r0x < mpf("1e-30"),
              f"(a) nu={nu_s} n=0: W_0(1e-6) vs 1/(2(lambda+mu)) = {mp.nstr(W0s, 20)}: rel {e3(r0)}, "
              f"Richardson rel {e3(r0x)}")
        stat[f"nu={nu_s},n=0"] = {"W_static": fmt(W0s), "W_at_s_1e-6": fmt(w0),
                                  "rel_residual_s_1e-6": e3(r0), "rel_residual_richardson": e3(r0x)}
        for n in [2, 3, 10]:
            Wa, comp = airy_static(n, nu)
            if n == 2:
                assert rel(Wa, (3 - 2 * nu) / 6) < mpf(10) ** (-(mp.dps - 3))
            wn = W_closed(n, eps_s, c1)
            rn = abs(wn - Wa) / Wa
            rnx = abs(richardson(lambda x: W_closed(n, x, c1), eps_s) - Wa) / Wa
            check(rn < mpf("1e-10") and rnx < mpf("1e-30") and comp < mpf(10) ** (-(mp.dps - 10)),
                  f"(a) nu={nu_s} n={n}: W_n(1e-6) vs Airy {mp.nstr(Wa, 20)}: rel {e3(rn)}, Richardson rel "
                  f"{e3(rnx)}, Airy compatibility residual {e3(comp)}")
            stat[f"nu={nu_s},n={n}"] = {"W_static": fmt(Wa), "W_at_s_1e-6": fmt(wn),
                                        "rel_residual_s_1e-6": e3(rn), "rel_residual_richardson": e3(rnx),
                                        "airy_compatibility_residual": e3(comp)}
        # n = 1
        w1 = W_closed(1, eps_s, c1)
        r1 = abs(eps_s ** 2 * w1 - 1)
        # W_1 = 1/s^2 + C1 + C2 s^2 + ...
        C1 = richardson(lambda x: W_closed(1, x, c1) - 1 / x ** 2, eps_s)
        check(r1 < mpf("1e-10"), f"(b) nu={nu_s} n=1: s^2 W_1(s) - 1 at s = 1e-6: {e3(r1)}; "
                                 f"C1 = lim(W_1 - 1/s^2) = {mp.nstr(C1, 20)}")
        stat[f"nu={nu_s},n=1"] = {"s2_W1_minus_1_at_s_1e-6": e3(r1), "C1_lim_W1_minus_inv_s2": fmt(C1)}
    out["a_b_static_and_rigid_limits"] = stat

    # --- (c) PDE / BC residuals by numerical differentiation
    worst_nav = worst_bc = worst_w = mpf(0)
    for nu_s in NUS:
        nu, c1, lam = material(nu_s)
        for n in LAP_N:
            for sr, si in S_LIST:
                nav, bc, wd = pde_check(n, parse_s(sr, si), c1, lam)
                worst_nav, worst_bc, worst_w = max(worst_nav, nav), max(worst_bc, bc), max(worst_w, wd)
    check(worst_nav < mpf(10) ** (-(mp.dps - 10)) and worst_bc < mpf(10) ** (-(mp.dps - 10))
          and worst_w < mpf(10) ** (-(mp.dps - 10)),
          f"(c) numeric-derivative Navier residual {e3(worst_nav)}, traction residual {e3(worst_bc)}, "
          f"-U(1) vs W_n {e3(worst_w)}")
    out["c_navier_rel_residual_max"] = e3(worst_nav)
    out["c_traction_residual_max"] = e3(worst_bc)
    out["c_displacement_vs_closed_form_max"] = e3(worst_w)

    # --- (d) Ritz-Galerkin
    t0 = time.time()
    rf = {}
    worst_f = mpf(0)
    worst_fconv = mpf(0)
    for nu_s in NUS:
        for n in FREQ_N:
            ev = ritz_freqs(n, RITZ_K_FREQ[0], nu_s)
            ev2 = ritz_freqs(n, RITZ_K_FREQ[1], nu_s)
            roots = res["cases"][nu_s]["freq"][n]
            d = max(rel(a, b) for a, b in zip(ev[:NROOTS], roots))
            dc = max(rel(a, b) for a, b in zip(ev[:NROOTS], ev2[:NROOTS]))
            worst_f, worst_fconv = max(worst_f, d), max(worst_fconv, dc)
            rf[f"nu={nu_s},n={n}"] = {"ritz_lowest_4": [mp.nstr(x, 25) for x in ev[:NROOTS]],
                                      "max_rel_diff_vs_roots": e3(d), "ritz_K_change": e3(dc)}
    check(worst_f < mpf("1e-25"),
          f"(d) Ritz (K={RITZ_K_FREQ[0]}) lowest 4 frequencies vs Bessel roots: max rel diff {e3(worst_f)} "
          f"(K={RITZ_K_FREQ[0]} vs {RITZ_K_FREQ[1]}: {e3(worst_fconv)})")
    rw = {}
    worst_w = mpf(0)
    worst_wconv = mpf(0)
    for nu_s in NUS:
        nu, c1, lam = material(nu_s)
        svals = [parse_s(sr, si) for sr, si in S_LIST]
        for n in LAP_N:
            wr = ritz_W(n, RITZ_K_LAP[0], nu_s, svals)
            wr2 = ritz_W(n, RITZ_K_LAP[1], nu_s, svals)
            for (sr, si), s, a, b in zip(S_LIST, svals, wr, wr2):
                wc = res["cases"][nu_s]["lap"][(n, sr, si)]
                d = abs(a - wc) / abs(wc)
                dc = abs(a - b) / abs(wc)
                worst_w, worst_wconv = max(worst_w, d), max(worst_wconv, dc)
                rw[f"nu={nu_s},n={n},s={sr}+{si}i"] = {"rel_diff": e3(d), "ritz_K_change": e3(dc)}
    check(worst_w < mpf("1e-28"),
          f"(d) Ritz-Galerkin (K={RITZ_K_LAP[0]}) W_n(s) vs closed form, all reported (n, s): max rel diff "
          f"{e3(worst_w)} (K={RITZ_K_LAP[0]} vs {RITZ_K_LAP[1]}: {e3(worst_wconv)})")
    out["d_ritz"] = {
        "basis": ("U, V in span r^(n-1+2k) (n >= 2); U in span r^(1+2k), V = 0 (n = 0); n = 1: (1, -1) and "
                  "(r^(2k), 0), (0, r^(2k)), k >= 1; exact rational K, M; solved at %d digits" % RITZ_DPS),
        "K_terms_frequencies": [str(k) for k in RITZ_K_FREQ],
        "K_terms_laplace": [str(k) for k in RITZ_K_LAP],
        "frequencies_max_rel_diff": e3(worst_f),
        "frequencies_K_change_max": e3(worst_fconv),
        "laplace_max_rel_diff": e3(worst_w),
        "laplace_K_change_max": e3(worst_wconv),
        "frequencies": rf,
        "laplace": rw,
    }
    log_err(f"  Ritz checks took {time.time() - t0:.1f} s")

    # --- (f) literature
    nu_lit = mpf("0.33") / mpf("1.33")
    c1l = sqrt(2 * (1 - nu_lit) / (1 - 2 * nu_lit))
    br = sign_changes(0, c1l, GRID_H, stop_after=4)
    ys = [refine_root(0, c1l, a, b) / c1l for a, b in br]
    dl = max(abs(y - mpf(p)) for y, p in zip(ys, LIT_N0))
    check(dl < mpf("6e-7"), f"(f) n=0 roots y1 at nu = 0.33/1.33: {[mp.nstr(y, 10) for y in ys]} vs published "
                            f"{LIT_N0}: max abs diff {e3(dl)}")
    nu23 = mpf(3) / 13
    c1p = sqrt(2 * (1 - nu23) / (1 - 2 * nu23))
    br = sign_changes(2, c1p, GRID_H, stop_after=1)
    w2 = refine_root(2, c1p, *br[0])
    Om = w2 * sqrt((1 - mpf("0.3")) / 2)
    log_err(f"  (f) n=2 lowest at nu=3/13 (plane stress nu'=0.3): omega a/c2 = {mp.nstr(w2, 12)}, "
            f"Omega = omega a sqrt(rho(1-nu'^2)/E) = {mp.nstr(Om, 12)}")
    out["f_literature"] = {
        "n0_plane_stress_equivalent": {
            "nu_plane_strain": "0.33/1.33", "nu_plane_stress": "0.33",
            "y1_roots": [mp.nstr(y, 12) for y in ys], "published": LIT_N0, "max_abs_diff": e3(dl),
            "source": ("Giurgiutiu, Structural Health Monitoring with Piezoelectric Wafer Active Sensors "
                       "(2nd ed.), ch. 10, eq. (57)-(58): z J0(z)/J1(z) = 1 - nu, roots listed; they match "
                       "1 - nu = 0.67 to all 7 digits")},
        "n2_plane_stress_0.3": {
            "nu_plane_strain": "3/13", "omega_a_over_c2": mp.nstr(w2, 15),
            "Omega_plane_stress_parameter": mp.nstr(Om, 15),
            "note": ("Omega = omega a sqrt(rho (1 - nu'^2)/E) = (omega a/c2) sqrt((1 - nu')/2) with nu' = 0.3; "
                     "not compared with a retrieved table (none found), given for comparison only")},
    }
    return out


def flatten(res):
    flat = {}
    for nu_s, case in res["cases"].items():
        flat[(nu_s, "c1")] = case["c1"]
        for n, rs in case["freq"].items():
            for i, r in enumerate(rs):
                flat[(nu_s, "f", n, i)] = r
        for k, w in case["lap"].items():
            flat[(nu_s, "w") + k + ("re",)] = mp.re(w)
            flat[(nu_s, "w") + k + ("im",)] = mp.im(w)
    return flat


def main():
    t0 = time.time()
    res = compute(BASE_DPS)
    log_err(f"base run (dps {BASE_DPS}) took {time.time() - t0:.1f} s")
    for nu_s in NUS:
        for n in FREQ_N:
            log_err(f"  nu={nu_s} n={n}: " + ", ".join(mp.nstr(x, 15) for x in res["cases"][nu_s]["freq"][n]))
    t1 = time.time()
    chk = compute(CHECK_DPS, brackets=res["brackets"])
    log_err(f"check run (dps {CHECK_DPS}) took {time.time() - t1:.1f} s")
    mp.dps = CHECK_DPS
    fa, fb = flatten(res), flatten(chk)
    worst = mpf(0)
    for key, a in fa.items():
        b = fb[key]
        if a == 0 or b == 0:
            assert a == 0 and b == 0, key
            continue
        worst = max(worst, rel(a, b))
        assert fmt(a) == fmt(b) or rel(a, b) < mpf(10) ** (-SIG - 1), (key, fmt(a), fmt(b))
    check(worst < mpf(10) ** (-SIG - 1),
          f"dps {BASE_DPS} vs dps {CHECK_DPS}: max relative difference {e3(worst)} over all reported values")
    mp.dps = BASE_DPS
    t2 = time.time()
    checks = checks_base(res)
    checks["dps_40_vs_60_max_rel_diff"] = e3(worst)
    log_err(f"checks took {time.time() - t2:.1f} s")
    mp.dps = BASE_DPS

    out = {
        "description": ("Independent mpmath reference for a free elastic disk (solid circular cylinder, plane "
                        "strain): natural frequencies for n = 0 (breathing), 2, 3 and the Laplace-domain "
                        "transfer function W_n(s) of the inward normal surface displacement for a surface "
                        "pressure cos(n theta). Generated by tests/reference/disk_mpmath.py."),
        "conventions": (
            "R = 1, mu = 1, rho = 1 (c2 = 1), c1^2 = 2(1-nu)/(1-2nu), lambda = c1^2 - 2. Polar (r, theta); "
            "u_r positive outward. Surface r = 1: sigma_rr = -p, sigma_rtheta = 0 (pressure positive inward); "
            "zero initial conditions. Frequencies are omega R/c2, ascending, first 4 roots > 0 of the "
            "frequency equation (n = 0: radial breathing modes only, torsional J_2(omega) = 0 modes "
            "excluded). s in units c2/R; W_n(s) = -u_r(1, theta, s)/cos(n theta) for p = P(s) cos(n theta), "
            "P(s) = 1 (units R/mu per unit pressure). For real s, w_im = \"0\". Values at mp.dps = 40, "
            "30 significant digits, all agree with a mp.dps = 60 rerun. Every computed value is a decimal "
            "string; only \"digits\" and the harmonic order \"n\" are JSON integers."),
        "formulas": {
            "frequency_equation": (
                "F_n(omega) = [(2n^2 - omega^2) J_n(y1) - 2 y1 J_n'(y1)] [(2n^2 - omega^2) J_n(y2) - 2 y2 J_n'(y2)] "
                "- 4 n^2 [y1 J_n'(y1) - J_n(y1)] [y2 J_n'(y2) - J_n(y2)] = 0, y1 = omega/c1, y2 = omega; "
                "n = 0: F_0 = G_0 omega^2 J_2(omega), breathing modes G_0 = 2 y1 J_1(y1) - omega^2 J_0(y1) = 0"),
            "transfer_function": (
                "W_n(s) = N/D, x1 = s/c1, x2 = s, I_k = I_n(x_k), Q_k = x_k I_n'(x_k) = n I_k + x_k I_{n+1}(x_k); "
                "N = Q1 [(s^2 + 2n^2) I2 - 2 Q2] + 2 n^2 I2 (I1 - Q1); "
                "D = [(s^2 + 2n^2) I1 - 2 Q1][(s^2 + 2n^2) I2 - 2 Q2] - 4 n^2 (Q1 - I1)(Q2 - I2); "
                "D(i omega) = (-1)^n F_n(omega)"),
            "static_limits": ("W_0(0) = 1/(2(lambda + mu)); W_2(0) = (3 - 2 nu)/6; n >= 2: "
                              "W_n(0) = -(1/2)[(1-nu)(-a n + b(n+2-n^2)/(n+1)) - nu(a n + b(n+2))], "
                              "a = 1/(2(n-1)), b = -1/(2(n+1)); W_1(s) = 1/s^2 + C1 + O(s^2)"),
        },
        "digits": SIG,
        "parameters": {"mp_dps": str(BASE_DPS), "check_dps": str(CHECK_DPS), "significant_digits": str(SIG),
                       "grid": f"omega = {GRID_START} + {GRID_H} k (fine check {FINE_H})"},
        "cases": [],
        "checks": checks,
    }
    for nu_s in NUS:
        case = res["cases"][nu_s]
        d = {"nu": nu_s, "c1": fmt(case["c1"]), "lambda": fmt(case["lambda"]),
             "frequencies": {str(n): [fmt(x) for x in case["freq"][n]] for n in FREQ_N},
             "laplace": []}
        for n in LAP_N:
            for sr, si in S_LIST:
                w = case["lap"][(n, sr, si)]
                d["laplace"].append({"n": n, "s_re": sr, "s_im": si,
                                     "w_re": fmt(mp.re(w)), "w_im": fmt(mp.im(w))})
        out["cases"].append(d)
    json.dump(out, sys.stdout, indent=1)
    sys.stdout.write("\n")
    log_err(f"total {time.time() - t0:.1f} s")


if __name__ == "__main__":
    main()
