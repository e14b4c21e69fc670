#!/usr/bin/env python3
r"""Independent high-precision reference values for the 3-D Lamb problem (Pekeris' problem):
surface normal displacement of an elastic half-space under a normal surface point force that
is a step in time, and its area averages over ring cells.

Written from first principles (3-D elastodynamics); no Rust code consulted.

Run from the repository root (mpmath only; 2 worker processes, ~12 CPU-minutes in total;
8.5 minutes wall measured while another job occupied about one of the two cores):
    python3 tests/reference/half_space_mpmath.py > tests/reference/half_space_reference.json
The stored values are computed twice, at mp.dps = 45 and mp.dps = 60 (integrands evaluated
with GUARD extra digits); the JSON keeps only the digits (at most 40 significant) on which both
runs agree, each value as {"value": "...", "rel_err": "..."} with rel_err = |x45 - x60|/|x60|.
Checks go to stderr and are asserted.

Conventions
-----------
Half-space z > 0 (z points into the medium), shear modulus mu, P speed c1, S speed c2,
m = c2/c1, m^2 = (1 - 2 nu)/(2 (1 - nu)).  Units c1 = 1, mu = 1, hence density rho = 1/m^2.
Slownesses a = 1/c1 = 1, b = 1/c2 = 1/m.  A point force P H(t) at the origin pushing into the
medium gives the surface normal displacement (positive into the medium)
    u(r, t) = P/(pi mu r) V(s),   s = r/(c1 t),
with V(s) = 0 for s >= 1 and V -> (1 - nu)/2 as s -> 0 (Boussinesq u = (1 - nu) P/(2 pi mu r)).
Rings of unit width: b_k = k + 1/2 (k >= 0), b_{-1} = 0, ring i = {b_{i-1} <= r <= b_i}, area
A_i = pi (b_i^2 - b_{i-1}^2).  U_ij(T) = (1/A_i) Int_{ring i} dA Int_{ring j} dA' u(|x - x'|, T)
for P = 1 (unit pressure switched on at t = 0 on ring j, mean displacement over ring i).

1. Transform-domain solution (route B)
--------------------------------------
Laplace transform in t (parameter p > 0), Hankel transform in r:
    f~(k) = Int_0^inf f(r) J0(k r) r dr,   f(r) = Int_0^inf f~(k) J0(k r) k dk.
Potentials u = grad phi + curl curl(psi e_z), phi = A exp(-nu1 z) J0(k r),
psi = B exp(-nu2 z) J0(k r), nu1 = sqrt(k^2 + p^2/c1^2), nu2 = sqrt(k^2 + p^2/c2^2) (Re > 0).
With J0' = -k J1 and lap psi = (p^2/c2^2) psi:
    u_r = -k J1 (A e1 - nu2 B e2),   u_z = J0 (-nu1 A e1 + k^2 B e2),   (e_j = exp(-nu_j z))
and on z = 0, using lambda p^2/c1^2 + 2 mu nu1^2 = mu (2 k^2 + p^2/c2^2) =: mu Kp,
    sigma_zz = mu J0 (Kp A - 2 k^2 nu2 B),   sigma_rz = -mu k J1 (-2 nu1 A + Kp B).
The surface's outward normal is -e_z, so a pressure q pushing into the medium means
-sigma_zz = q, sigma_rz = 0:  B = 2 nu1 A/Kp,  A = -q Kp/(mu Delta), and
    w~ = u_z~(k, p) = W(k, p) q~,  W = nu1 p^2/(c2^2 mu Delta),
    Delta = (2 k^2 + p^2/c2^2)^2 - 4 k^2 nu1 nu2
(the plane-strain Lamb symbol with k the radial wavenumber).  Rationalised (no cancellation
for real k, used in all numerics):  Delta = p^2 N/Dp,  Dp = Kp^2 + 4 k^2 nu1 nu2,
    N = 16 (b^2 - 1) k^6 + 8 b^2 (3 b^2 - 2) p^2 k^4 + 8 b^6 p^4 k^2 + b^8 p^6,
    W = b^2 nu1 Dp / N   (mu = 1).
Static limit p -> 0: W -> 1/(2 (1 - m^2) k) = (1 - nu)/k (Boussinesq, since
Int_0^inf J0(k r) dk = 1/r).  (The 2x2 boundary system is also solved numerically in the checks.)
Loads (step in time: an extra 1/p):  point force P = 1: q~ = 1/(2 pi);  unit pressure on the
disk r <= c: q~ = c J1(k c)/k, and Int_0^a J0(k r) r dr = a J1(k a)/k, so
    point:      u~(r, p) = (1/(2 pi p)) Int_0^inf k J0(k r) W(k, p) dk,
    disk-disk:  DD~(a, c; p) = Int_{disk a} dA Int_{disk c} dA' u~ = (2 pi a c/p) Int_0^inf
                J1(k a) J1(k c) W(k, p)/k dk,
and a ring is the difference of two disks (the four signed disk pairs of rings i, j, divided
by A_i).  Static limit: DD_static = 2 pi a c (1 - nu) Int J1(ka) J1(kc)/k^2 dk
= (1 - nu) pi a c^2 2F1(1/2, -1/2; 2; c^2/a^2)  (c <= a, Weber-Schafheitlin); for a = c this
is (1 - nu) 8 a^3/3, i.e. the mean displacement of a uniformly loaded disk of radius a is
(1 - nu) 8 a/(3 pi mu)  [NOT 8 a/(3 pi^2 mu): that is off by a factor pi; with E = 2 mu (1 + nu)
it is the classical 16 (1 - nu^2) q a/(3 pi E)].

Oscillatory Hankel integrals (route B numerics).  For real k and real g,
J1(ka) J1(kc) = Re[H1(ka) J1(kc)] (H1 = Hankel function of the first kind), a >= c; likewise
J0(kr) = Re H1_0(kr).  The integral is split at K0 = Z/c (Z = 1.15 (dps + 8) + 2):
  * [0, K0] on the real axis, mp.quad split into pieces of one period 2 pi/(a + c);
    J by mpmath's besselj (real argument, cached across p and nu);
  * [K0, inf) is moved onto the vertical ray k = K0 + i t, t >= 0 (Cauchy: the integrand is
    analytic for Re k > 0, Im k > 0 - the branch points and Rayleigh poles of W lie on the
    imaginary axis - and decays on the arc at infinity), where H1(ka) J1(kc) ~ exp(-(a - c) t)
    (a > c) or ~ t^-3 (a = c; then a non-oscillatory algebraic tail, also fine for tanh-sinh
    to infinity).  On the ray |k c| >= Z, so H1 and H2 are summed from their asymptotic Hankel
    series (least term ~ exp(-2 |z|) < 10^-(dps+8)), J1 = (H1 + H2)/2.
No series acceleration or tail extrapolation is needed; route B is run at mp.dps = 20.

2. Time domain (route A)
------------------------
Cagniard-de Hoop.  Write the Hankel integral as a 2-D Fourier integral over the horizontal
slowness (q1, q2) (k = p |q|): for the impulsive point force
    u~(r, p) = (p/(4 pi^2)) Int dq2 Int dq1 F(q1^2 + q2^2) exp(i p q1 r),
    F(xi^2) = b^2 alpha/R,  alpha = sqrt(xi^2 + a^2), beta = sqrt(xi^2 + b^2),
    R = (b^2 + 2 xi^2)^2 - 4 xi^2 alpha beta   (W = F/p with k = p xi).
At fixed q2 the q1 integral is Lamb's 2-D problem with a'^2 = a^2 + q2^2, b'^2 = b^2 + q2^2:
closing in Im q1 > 0 around the cut q1 = i sigma, sigma > a',
    Int dq1 F exp(i p q1 r) = -2 Int_{a'}^inf Im F(q1 = i sigma + 0) exp(-p sigma r) dsigma.
With t = sigma r and the step (1/p) the time integrand is read off:
    V(s) = -(1/pi) Int_0^Q Im F(i sigma + 0, q2) dq2,   sigma = 1/s,  Q = sqrt(sigma^2 - a^2),
a finite integral (q2 = Q sin(theta) makes it smooth; split where beta changes from imaginary
to real).  Here xi^2 = w = q2^2 - sigma^2 + i0, alpha = i sqrt(Q^2 - q2^2), beta =
sqrt(w + b^2 + i0).  For s < s_R the Rayleigh pole R = 0 lies on the path and its half residue
makes V = (1 - nu)/2 (static) behind the Rayleigh front (confirmed by route B).
Closed form.  R (b^2 + 2 w)^2 + ... : rationalising, R R+ = b^8 C(x) with w = -b^2 x and
    C(x) = -16 (1 - a2) x^3 + 8 (3 - 2 a2) x^2 - 8 x + 1,   a2 = m^2
(Kausel's cubic; its roots x1, x2, x3, x3 = (c2/c_R)^2 > 1 the Rayleigh root; x1, x2 real and
< a2 for nu < 0.2631, a complex pair above).  Partial fractions over the roots and the
elementary integral Int_0^Q sqrt(Q^2 - q^2)/(q^2 + c) dq = (pi/2)(sqrt(1 + Q^2/c) - 1) give, with
tau = c2 t/r = m/s (Kausel 2012, Mooney 1974; Pekeris 1955 for nu = 1/4),
    A_j = (x_j - 1/2)^2 sqrt(a2 - x_j)/prod_{k != j}(x_j - x_k)  (j = 1, 2; principal sqrt),
    A_3 = (x3 - 1/2)^2 sqrt(x3 - a2)/((x3 - x1)(x3 - x2)),
    V = (1 - nu)/2 * G,
    m < s < 1:    G = (1/2)[1 - A1/sqrt(tau^2 - x1) - A2/sqrt(tau^2 - x2) - A3/sqrt(x3 - tau^2)]
                  (complex pair: the first two terms are 2 Re(A1/sqrt(tau^2 - x1)), real),
    s_R < s < m:  G = 1 - A3/sqrt(x3 - tau^2),
    s < s_R:      G = 1.
This is the literature's form (Kausel 2013, Mooney 1974; Pekeris 1955 at nu = 1/4), taken as
it stands: no sign, factor or branch correction was needed.  It is checked against the finite de Hoop integral above (~40 digits, every nu, both
sides of s = m, near s_R and s = 1) and, end to end, against route B.  Properties (checked):
G(1-) = 0 (Lagrange: sum_j P(x_j)/prod(x_j - x_k) = 1 for a monic quadratic P);
V continuous at s = m; V ~ -(1 - nu) A3 s_R/(2 sqrt(2 x3 s_R (s - s_R))) -> -inf as s -> s_R+,
then a jump to (1 - nu)/2; V < 0 (outward) between the P and Rayleigh arrivals.
Integral identity: a uniform pressure on the whole surface gives the 1-D P wave
u = t/(rho c1) = m^2 t, and by superposition Int_0^inf u 2 pi r dr = 2 t Int_0^1 V ds, so
    Int_0^1 V(s) ds = m^2/2   (checked; it involves the Rayleigh singularity).
Abel relation to the 2-D Lamb problem (a line load is a line of point loads):
    W_zz(sigma) = 2 Int_sigma^1 V(s)/sqrt(s^2 - sigma^2) ds = 2 Int_0^acosh(1/sigma) V(sigma cosh u) du,
checked against tests/reference/lamb_reference.json (when present, nu in {0.25, 0.1, 0.3, 0.45}).

Ring cells (lens formula).  Int_{disk a} Int_{disk c} f(|x - x'|) dA dA'
= Int_0^{a+c} f(rho) 2 pi rho L(rho; a, c) d rho, L = area of the intersection of the disks
(centres rho apart): L = pi min(a,c)^2 for rho <= |a - c|, 0 for rho >= a + c, else
    L = a^2 th_a + c^2 th_c - sqrt(K)/2,  K = (a+c-rho)(rho+a-c)(rho-a+c)(rho+a+c),
    th_a = atan2(sqrt(K), rho^2 + a^2 - c^2),  th_c = atan2(sqrt(K), rho^2 + c^2 - a^2).
With u = V/(pi rho):  A_i U_ij(T) = Int_0^{rho_max} 2 V(rho/T) Lr(rho) d rho,
Lr = the signed sum of L over the four disk pairs (formed pointwise, GUARD digits absorb the
cancellation), rho_max = min(T, b_i + b_j), starting at the smallest ring-ring distance
(U = 0 exactly if T is below it).  mp.quad (tanh-sinh) is split at every |a - c|, a + c and at
the fronts rho_R = s_R T, rho_S = m T, rho_P = T:
  * rho < rho_R: V = (1 - nu)/2;
  * rho_R < rho < rho_S: rho = rho_R + v^2 and x3 - tau^2 = x3 v^2 (2 rho_R + v^2)/rho^2, so
    the integrand 2 (1 - nu) Lr (v - A3 rho/(sqrt(x3) sqrt(2 rho_R + v^2))) is smooth at v = 0
    (removes the inverse square root and all cancellation next to the front);
  * rho_S < rho < rho_P: the P-S formula (analytic there).  When x2 is real and just below m^2
    (nu = 0.1: 9e-5 below, nu = -0.3: 1e-3 below) V has a branch point at s* = m/sqrt(x2)
    = 1 + eps, just beyond the P front; every quadrature ending at a P front then gets extra
    split points graded geometrically (eps, 4 eps, 16 eps, ... times the front position).
    Without them tanh-sinh at 18 digits returned a Laplace transform off by 2e-12 (relative) while
    estimating its error as 1e-20; the route B comparison caught it.
Static T = inf: (1 - nu) Int Lr d rho (checked against Weber-Schafheitlin).  For
T >= (b_i + b_j)/s_R every rho lies behind the Rayleigh front and U is exactly static
(T = 60 is static except for nu = 0.45 with (10, 11), (20, 2)).

3. Route A vs route B (checks run at low precision, in parallel)
----------------------------------------------------------------
Laplace transforms at p in {0.5, 1, 2, 4}:
  * point: (1/pi) Int_1^inf exp(-p T) V(1/T) dT (r = 1; u~ depends on p r only), split at
    T = 1/m and T = 1/s_R (T = 1/s_R - v^2 near the front), static tail (1 - nu)/(2p) e^{-p/s_R};
  * rings: Int_0^Ts exp(-p T) U_ij(T) dT + U_static exp(-p Ts)/p, Ts = (b_i + b_j)/s_R, using
    the same U_ij(T) function as for the stored values (mp.dps = 18), split at T = d/s_R, d/m, d
    for every disk-pair distance d; U(1.001 Ts) = U_static is asserted;
versus route B at mp.dps = 20; asserted relative agreement < 1e-12 (found <= 5e-16; most
values ~1e-18, the largest differences come from the 18-digit route A side).
Other checks (both precisions): cubic roots vs the irrational Rayleigh function (and
x3 = (3 + sqrt 3)/4 at nu = 1/4), closed form vs de Hoop integral, Int V = m^2/2, continuity at
s = m and s = 1, static disk value (1 - nu) 8 a/(3 pi), static rings vs Weber-Schafheitlin,
reciprocity A_i U_ij = A_j U_ji, the transform symbol from the 2x2 boundary system, Abel
relation to the 2-D reference.
"""
import sys
import os
import json
import time
from multiprocessing import Pool

from mpmath import (mp, mpf, mpc, sqrt, pi, re, im, fabs, sin, cos, asin, atan2, exp, expj,
                    acosh, cosh, quad, polyroots, besselj, hyp2f1, lu_solve, matrix)

NUS = ["0.25", "0.1", "0.3", "0.45", "-0.3"]
S_LIST = ["0.05", "0.2", "0.4", "0.52", "0.54", "0.55", "0.6", "0.65", "0.7", "0.8", "0.9",
          "0.95", "0.99"]
PAIRS = [(0, 0), (0, 1), (1, 0), (1, 1), (2, 2), (3, 5), (5, 3), (10, 10), (10, 11), (20, 2)]
TIMES = ["0.3", "1", "2.5", "7", "20", "60", "inf"]
RUN_DPS = (45, 60)
GUARD = 15          # extra digits inside integrand evaluations (stored values)
KEEP = 40           # significant digits kept in the JSON
P_LAPLACE = ["0.5", "1", "2", "4"]
DPS_B = 20          # route B (Hankel) check precision
GB = 8              # guard digits for route B integrands
DPS_AL = 18         # route A Laplace-transform check precision
GUARD_AL = 8
LAP_TOL = mpf("1e-12")
# ring pairs for the route A / route B Laplace comparison (route A is the costly side)
# ((0, 1) at nu = 0.1 and (1, 1) at nu = 0.45 also pass, rel <= 5e-16, but cost ~4 min each)
LAP_PAIRS = {"0.25": [(0, 0), (0, 1), (3, 5)], "0.1": [(0, 0)], "0.3": [(0, 0), (0, 1)],
             "0.45": [(0, 0), (0, 1)], "-0.3": [(0, 0), (0, 1)]}
LAMB_JSON = os.path.join(os.path.dirname(os.path.abspath(__file__)), "lamb_reference.json")


def log_err(*a):
    print(*a, file=sys.stderr, flush=True)


def check(cond, msg):
    log_err(("  ok   " if cond else "  FAIL ") + msg)
    assert cond, msg


def quad_checked(f, pts, rel=None):
    """mp.quad with its error estimate checked (relative to max(1, |value|))."""
    v, e = quad(f, pts, error=True)
    tol = (mpf(10) ** (-mp.dps + 5) if rel is None else rel) * max(1, fabs(v))
    if not e <= tol:
        v, e = quad(f, pts, error=True, maxdegree=12)
        assert e <= tol, ("quadrature error", pts, v, e)
    return v


# --------------------------------------------------------------------------------------------
class HalfSpace:
    """Material constants and the closed-form V, kept with `guard` extra digits."""

    def __init__(self, nu, guard=GUARD):
        self.wdps = mp.dps + guard
        with mp.workdps(self.wdps):
            self.nu = nu = mpf(nu)
            self.a2 = a2 = (1 - 2 * nu) / (2 * (1 - nu))
            self.m = sqrt(a2)
            self.b2 = 1 / a2
            with mp.workdps(self.wdps + 20):
                r = polyroots([-16 * (1 - a2), 8 * (3 - 2 * a2), -8, 1], maxsteps=500,
                              extraprec=300)
            tiny = mpf(10) ** (-self.wdps + 5)
            big = [x for x in r if fabs(im(x)) < tiny and re(x) > 1]
            assert len(big) == 1
            self.x3 = re(big[0])
            oth = [x for x in r if x is not big[0]]
            if all(fabs(im(x)) < tiny for x in oth):
                self.cplx = False
                self.x1, self.x2 = sorted(re(x) for x in oth)
            else:
                self.cplx = True
                self.x1, self.x2 = sorted(oth, key=lambda z: im(z))
            x1, x2, x3 = self.x1, self.x2, self.x3
            h = mpf(1) / 2
            self.A1 = (x1 - h) ** 2 * sqrt(a2 - x1) / ((x1 - x2) * (x1 - x3))
            self.A2 = (x2 - h) ** 2 * sqrt(a2 - x2) / ((x2 - x1) * (x2 - x3))
            self.A3 = re((x3 - h) ** 2 * sqrt(x3 - a2) / ((x3 - x1) * (x3 - x2)))  # real (x1 x2 real or conjugate)
            self.sR = self.m / sqrt(x3)
            self.c3 = self.A3 / sqrt(x3)
            self.Vstat = (1 - nu) / 2
            # real x2 just below m^2 (nu = 0.1: 9e-5 below, nu = -0.3: 1e-3): V has a branch point
            # at s* = m/sqrt(x2) = 1 + epsP, just beyond the P front; quadratures touching the P
            # front get extra split points geometrically graded towards it.
            self.epsP = None if self.cplx else sqrt(a2 / x2) - 1
            if self.epsP is not None and self.epsP > mpf("0.01"):
                self.epsP = None

    def G_PS(self, t2):
        r = 1 - self.A1 / sqrt(t2 - self.x1) - self.A2 / sqrt(t2 - self.x2) - self.A3 / sqrt(self.x3 - t2)
        return re(r) / 2

    def V(self, s):
        """Closed form (Kausel), s = r/(c1 t) > 0."""
        with mp.workdps(self.wdps):
            s = mpf(s)
            if s >= 1:
                return mpf(0)
            if s <= self.sR:
                return +self.Vstat
            t2 = self.a2 / (s * s)
            if s < self.m:
                G = 1 - self.A3 / sqrt(self.x3 - t2)
            else:
                G = self.G_PS(t2)
            r = (1 - self.nu) * G / 2
        return +r

    def V_dehoop(self, s):
        """Finite Cagniard-de Hoop integral -(1/pi) Int_0^Q Im F(i sigma + 0, q2) dq2 (s > s_R)."""
        wd = self.wdps
        with mp.workdps(wd):
            s = mpf(s)
            sig = 1 / s
            Q = sqrt((sig - 1) * (sig + 1))
            b2 = self.b2

        def f(th):
            with mp.workdps(wd):
                q2 = Q * sin(th)
                w = q2 * q2 - sig * sig
                al = mpc(0, Q * cos(th))
                wb = w + b2
                be = sqrt(wb) if wb >= 0 else mpc(0, sqrt(-wb))
                R = (b2 + 2 * w) ** 2 - 4 * w * al * be
                r = im(b2 * al / R) * Q * cos(th)
            return +r

        pts = [mpf(0), pi / 2]
        if sig * sig > b2:
            with mp.workdps(wd):
                pts = [mpf(0), asin(sqrt(sig * sig - b2) / Q), pi / 2]
        return -quad_checked(f, pts) / pi

    def rayleigh_D(self, s):
        """Irrational Rayleigh function (2 - kappa^2)^2 - 4 sqrt(1 - s^2) sqrt(1 - kappa^2)."""
        k2 = s * s / self.a2
        return (2 - k2) ** 2 - 4 * sqrt(1 - s * s) * sqrt(1 - k2)


# ---- ring geometry ---------------------------------------------------------------------------
def graded(F, other, delta):
    """Points F + sign * delta * 4^k strictly between the front F and `other`."""
    out = []
    if delta is None:
        return out
    d = delta
    while d < fabs(other - F) * mpf("0.7"):
        out.append(F + d if other > F else F - d)
        d *= 4
    return out


def bk(k):
    return mpf(0) if k < 0 else k + mpf(1) / 2


def disk_pairs(i, j):
    out = []
    for si, a in ((1, bk(i)), (-1, bk(i - 1))):
        for sj, c in ((1, bk(j)), (-1, bk(j - 1))):
            if a > 0 and c > 0:
                out.append((si * sj, a, c))
    return out


def ring_area(i):
    return pi * (bk(i) ** 2 - bk(i - 1) ** 2)


def lens(r, a, c):
    """Area of the intersection of disks of radii a, c with centres r apart."""
    if r <= fabs(a - c):
        return pi * min(a, c) ** 2
    if r >= a + c:
        return mpf(0)
    sK = sqrt((a + c - r) * (r + a - c) * (r - a + c) * (r + a + c))
    return a * a * atan2(sK, r * r + a * a - c * c) + c * c * atan2(sK, r * r + c * c - a * a) - sK / 2


def ring_gap(i, j):
    """Smallest distance between points of rings i and j."""
    return max(mpf(0), bk(i - 1) - bk(j), bk(j - 1) - bk(i))


def U_ring(H, i, j, T):
    """U_ij(T) (T = None: static), at the current precision (integrands at H.wdps)."""
    P = disk_pairs(i, j)
    wd = H.wdps
    rmax = bk(i) + bk(j)
    r0 = ring_gap(i, j)
    brk = set()
    for sg, a, c in P:
        brk.add(fabs(a - c))
        brk.add(a + c)

    def Lr(r):
        return sum(sg * lens(r, a, c) for sg, a, c in P)

    def seg(lo, hi):
        return sorted(set([lo, hi] + [x for x in brk if lo < x < hi]))

    nu = H.nu
    if T is None:
        def fs(r):
            with mp.workdps(wd):
                v = (1 - nu) * Lr(r)
            return +v
        return quad_checked(fs, seg(r0, rmax)) / ring_area(i)
    T = mpf(T)
    if T <= r0:
        return mpf(0)
    with mp.workdps(wd):
        rR, rS, rP = H.sR * T, H.m * T, T
    tot = mpf(0)
    top = min(rR, rmax)
    if top > r0:
        def f1(r):
            with mp.workdps(wd):
                v = (1 - nu) * Lr(r)
            return +v
        tot += quad_checked(f1, seg(r0, top))
    lo, hi = max(rR, r0), min(rS, rmax, rP)
    if hi > lo:
        def f2(v):
            with mp.workdps(wd):
                r = rR + v * v
                x = 2 * (1 - nu) * Lr(r) * (v - H.c3 * r / sqrt(2 * rR + v * v))
            return +x
        with mp.workdps(wd):
            pts = [sqrt(x - rR) for x in seg(lo, hi)]
        tot += quad_checked(f2, pts)
    lo, hi = max(rS, r0), min(rP, rmax)
    if hi > lo:
        def f3(r):
            with mp.workdps(wd):
                t2 = H.a2 * T * T / (r * r)
                x = (1 - nu) * H.G_PS(t2) * Lr(r)
            return +x
        pts = seg(lo, hi)
        if hi == rP and H.epsP is not None:
            with mp.workdps(wd):
                pts = sorted(set(pts + graded(rP, lo, H.epsP * T)))
        tot += quad_checked(f3, pts)
    return tot / ring_area(i)


def U_static_ws(H, i, j):
    """Static U_ij from the Weber-Schafheitlin closed form (independent of the lens quadrature)."""
    tot = mpf(0)
    for sg, a, c in disk_pairs(i, j):
        A, C = max(a, c), min(a, c)
        tot += sg * (1 - H.nu) * pi * A * C * C * hyp2f1(mpf(1) / 2, -mpf(1) / 2, 2, (C / A) ** 2)
    return tot / ring_area(i)


# ---- route B: Laplace-Hankel domain ------------------------------------------------------------
def W_sym(H, k, p):
    """b^2 nu1 Dp/N: the surface symbol W(k, p) (mu = 1), rationalised."""
    b2 = H.b2
    k2, p2 = k * k, p * p
    n1, n2 = sqrt(k2 + p2), sqrt(k2 + b2 * p2)
    K = 2 * k2 + b2 * p2
    Dp = K * K + 4 * k2 * n1 * n2
    N = 16 * (b2 - 1) * k2 ** 3 + 8 * b2 * (3 * b2 - 2) * p2 * k2 ** 2 + 8 * b2 ** 3 * p2 ** 2 * k2 + b2 ** 4 * p2 ** 3
    return b2 * n1 * Dp / N


def hankel_asym(n, z):
    """(H1_n(z), H2_n(z)) from the asymptotic Hankel series (|z| large, Re z > 0)."""
    mu4 = 4 * n * n
    eps = mpf(10) ** (-mp.dps - 3)
    s1 = s2 = t1 = t2 = mpc(1)
    iz1, iz2 = mpc(0, 1) / z, mpc(0, -1) / z
    k = 0
    while True:
        k += 1
        c = mpf(mu4 - (2 * k - 1) ** 2) / (8 * k)
        t1 *= c * iz1
        t2 *= c * iz2
        s1 += t1
        s2 += t2
        if abs(t1) < eps:
            break
        assert k < 500, "asymptotic series"
    ph = z - n * pi / 2 - pi / 4
    f = sqrt(2 / (pi * z))
    return f * expj(ph) * s1, f * expj(-ph) * s2


_JC, _HC = {}, {}


def _J(n, x):
    key = (n, x)
    if key not in _JC:
        _JC[key] = besselj(n, x)
    return _JC[key]


def _Hs(n, z):
    key = (n, z)
    if key not in _HC:
        _HC[key] = hankel_asym(n, z)
    return _HC[key]


def _z_as():
    return mpf("1.15") * (mp.dps + GB) + 2


def disk_integral_B(H, a, c, p):
    """Int_0^inf J1(ka) J1(kc) W(k, p)/k dk (real segment + vertical ray)."""
    if a < c:
        a, c = c, a
    wd = mp.dps + GB
    with mp.workdps(wd):
        K0 = _z_as() / c
        n = int(K0 * (a + c) / (2 * pi)) + 1
        pts = [K0 * q / n for q in range(n + 1)]

    def f0(k):
        with mp.workdps(wd):
            v = _J(1, k * a) * _J(1, k * c) * W_sym(H, k, p) / k
        return +v

    def f1(t):
        with mp.workdps(wd):
            k = mpc(K0, t)
            ha = _Hs(1, k * a)[0]
            hc = _Hs(1, k * c)
            v = re(ha * (hc[0] + hc[1]) / 2 * W_sym(H, k, p) / k * 1j)
        return +v

    rel = mpf(10) ** (-mp.dps + 3)
    I0 = quad_checked(f0, pts, rel)
    I1 = quad_checked(f1, [0, 1, 5, 20, mp.inf] if a == c else [0, 5 / (a - c), 20 / (a - c), mp.inf], rel)
    return I0 + I1


def U_laplace_B(H, i, j, p):
    tot = mpf(0)
    for sg, a, c in disk_pairs(i, j):
        tot += sg * 2 * pi * a * c * disk_integral_B(H, a, c, p) / p
    return tot / ring_area(i)


def V_laplace_B(H, p):
    """Laplace transform of u(r = 1, t) for the unit step point force, from the Hankel integral."""
    wd = mp.dps + GB
    with mp.workdps(wd):
        K0 = _z_as()
        n = int(K0 / pi) + 1
        pts = [K0 * q / n for q in range(n + 1)]

    def f0(k):
        with mp.workdps(wd):
            v = k * _J(0, k) * W_sym(H, k, p)
        return +v

    def f1(t):
        with mp.workdps(wd):
            k = mpc(K0, t)
            v = re(k * W_sym(H, k, p) * _Hs(0, k)[0] * 1j)
        return +v

    rel = mpf(10) ** (-mp.dps + 3)
    return (quad_checked(f0, pts, rel) + quad_checked(f1, [0, 5, 20, mp.inf], rel)) / (2 * pi * p)


# ---- route A Laplace transforms ----------------------------------------------------------------
def V_laplace_A(H, p):
    nu = H.nu
    with mp.workdps(H.wdps):
        TR, TS = 1 / H.sR, 1 / H.m
        c3m = H.A3 / H.m
    f1 = lambda T: exp(-p * T) * H.V(1 / T)
    # T = TR - v^2 in the S-R interval: x3 - m^2 T^2 = m^2 v^2 (2 TR - v^2)
    f2 = lambda v: exp(-p * (TR - v * v)) * (1 - nu) * (v - c3m / sqrt(2 * TR - v * v))
    with mp.workdps(H.wdps):
        pts = [mpf(1)] + graded(mpf(1), TS, None if H.epsP is None else H.epsP / (1 + H.epsP)) + [TS]
    I = quad_checked(f1, pts) + quad_checked(f2, [0, sqrt(TR - TS)])
    I += H.Vstat * exp(-p * TR) / p
    return I / pi


def U_laplace_A(H, i, j, ps):
    """Int_0^inf exp(-pT) U_ij(T) dT for each p in ps, from the time-domain U_ij(T)."""
    D = set()
    for sg, a, c in disk_pairs(i, j):
        D.add(fabs(a - c))
        D.add(a + c)
    Ts = (bk(i) + bk(j)) / H.sR
    crit = set([ring_gap(i, j)])
    for d in D:
        for sp in (1, H.m, H.sR):
            if d / sp < Ts:
                crit.add(d / sp)
        if d > 0:
            crit.update(x for x in graded(d, Ts, None if H.epsP is None else d * H.epsP) if x < Ts)
    pts = sorted(crit) + [Ts]
    memo = {}
    ust = U_ring(H, i, j, None)
    chk = U_ring(H, i, j, Ts * mpf("1.001"))
    check(fabs(chk - ust) < mpf(10) ** (-mp.dps + 4) * max(1, fabs(ust)),
          f"nu = {mp.nstr(H.nu, 3)} ({i},{j}): U(1.001 Ts) = U_static, Ts = (b_i + b_j)/s_R")

    def Uc(T):
        if T not in memo:
            memo[T] = U_ring(H, i, j, T)
        return memo[T]

    out = []
    for p in ps:
        I = quad_checked(lambda T: exp(-p * T) * Uc(T), pts)
        out.append(I + ust * exp(-p * Ts) / p)
    return out, len(memo)


# ---- tasks -------------------------------------------------------------------------------------
def laplace_task(nu):
    """Route A vs route B in the Laplace domain (low precision, asserted)."""
    t0 = time.time()
    recs = []
    ps = [mpf(x) for x in P_LAPLACE]
    mp.dps = DPS_B
    HB = HalfSpace(nu, GB)
    mp.dps = DPS_AL
    HA = HalfSpace(nu, GUARD_AL)
    worst = mpf(0)
    # point response (r = 1)
    for pstr, p in zip(P_LAPLACE, ps):
        mp.dps = DPS_AL
        a = V_laplace_A(HA, p)
        mp.dps = DPS_B
        b = V_laplace_B(HB, p)
        rel = fabs(a - b) / fabs(b)
        worst = max(worst, rel)
        recs.append({"quantity": "point u~(r=1)", "p": pstr, "route_A": mp.nstr(a, 17),
                     "route_B": mp.nstr(b, 17), "rel_diff": mp.nstr(rel, 3)})
        check(rel < LAP_TOL, f"nu = {nu} point r = 1, p = {pstr}: A {mp.nstr(a, 17)}  B {mp.nstr(b, 17)}"
                             f"  rel {mp.nstr(rel, 3)}")
    for (i, j) in LAP_PAIRS[nu]:
        mp.dps = DPS_AL
        t1 = time.time()
        As, nT = U_laplace_A(HA, i, j, ps)
        tA = time.time() - t1
        for pstr, p, a in zip(P_LAPLACE, ps, As):
            mp.dps = DPS_B
            b = U_laplace_B(HB, i, j, p)
            rel = fabs(a - b) / fabs(b)
            worst = max(worst, rel)
            recs.append({"quantity": f"U_{i}{j}~", "p": pstr, "route_A": mp.nstr(a, 17),
                         "route_B": mp.nstr(b, 17), "rel_diff": mp.nstr(rel, 3)})
            check(rel < LAP_TOL, f"nu = {nu} U_{i}{j}~, p = {pstr}: A {mp.nstr(a, 17)}  B {mp.nstr(b, 17)}"
                                 f"  rel {mp.nstr(rel, 3)}")
        log_err(f"    (route A: {nT} values of U_{i}{j}(T), {tA:.0f} s)")
    # static limit p -> 0 of route B's symbol: W -> (1 - nu)/k
    mp.dps = DPS_B
    k = mpf(3)
    ws = W_sym(HB, k, mpf(10) ** -12) * k / (1 - HB.nu)
    check(fabs(ws - 1) < mpf(10) ** -15, f"nu = {nu}: k W(k, p -> 0) = 1 - nu")
    log_err(f"[laplace nu = {nu}] max rel A-B {mp.nstr(worst, 3)}, {time.time() - t0:.0f} s")
    return nu, recs, tostr(worst)


def symbol_check(H, nu):
    """Solve the 2x2 surface boundary system numerically; compare with W."""
    worst = mpf(0)
    with mp.workdps(H.wdps):
        c2sq = H.a2
        for k, p in ((mpf("0.3"), mpf(1)), (mpf(2), mpf("0.7")), (mpf(5), mpf(3))):
            n1 = sqrt(k * k + p * p)
            n2 = sqrt(k * k + p * p / c2sq)
            Kp = 2 * k * k + p * p / c2sq
            # sigma_zz = -1 (unit pressure into the medium), sigma_rz = 0 (mu = 1)
            M = matrix([[Kp, -2 * k * k * n2], [-2 * n1, Kp]])
            A, B = lu_solve(M, matrix([-1, 0]))
            uz = -n1 * A + k * k * B
            Wd = n1 * p * p / (c2sq * (Kp * Kp - 4 * k * k * n1 * n2))
            worst = max(worst, fabs(uz / W_sym(H, k, p) - 1), fabs(Wd / W_sym(H, k, p) - 1))
    check(worst < mpf(10) ** (-mp.dps), f"transform symbol: BC system = nu1 p^2/(c2^2 Delta) = rationalised"
                                        f" (max {mp.nstr(worst, 3)})")


def checks(H, nu):
    m, sR = H.m, H.sR
    tol = mpf(10) ** (-mp.dps + 8)
    log_err(f"[dps {mp.dps}] nu = {nu}: m = {mp.nstr(m, 20)}, s_R = {mp.nstr(sR, 20)}, "
            f"x = {mp.nstr(H.x1, 12)}, {mp.nstr(H.x2, 12)}, {mp.nstr(H.x3, 20)} "
            f"({'complex pair' if H.cplx else 'real'})")
    tight = mpf(10) ** (-mp.dps - 5)
    with mp.workdps(H.wdps):
        check(fabs(H.rayleigh_D(sR)) < tight, "irrational Rayleigh function vanishes at s_R = m/sqrt(x3)")
        if H.nu == mpf("0.25"):
            check(fabs(H.x3 - (3 + sqrt(3)) / 4) < tight, "nu = 1/4: x3 = (3 + sqrt 3)/4")
        check((H.cplx and H.nu > mpf("0.2631")) or (not H.cplx and H.x2 < H.a2),
              "x1, x2 real and < m^2 (nu < 0.2631) or a complex pair (nu > 0.2631)")
        e = tight / 10 ** 5
        jm = fabs(H.V(m - e) - H.V(m + e))
        j1 = fabs(H.V(1 - e))
    check(jm < mpf(10) ** (-mp.dps + 2), f"V continuous at s = m (jump {mp.nstr(jm, 3)})")
    check(j1 < mpf(10) ** (-mp.dps + 2), f"V(1-) = 0 (P arrival; Lagrange identity) ({mp.nstr(j1, 3)})")
    # closed form vs finite de Hoop integral
    worst = mpf(0)
    with mp.workdps(H.wdps):
        ss = [sR * mpf("1.0001"), sR + (m - sR) / 3, (sR + m) / 2, m - (m - sR) / 50,
              m + (1 - m) / 50, (m + 1) / 2, 1 - (1 - m) / 30]
    ss += [mpf(x) for x in S_LIST if mpf(x) > sR * mpf("1.0001")]
    for s in ss:
        a, b = H.V(s), H.V_dehoop(s)
        worst = max(worst, fabs(a - b) / max(fabs(b), mpf(10) ** -3))
    check(worst < tol, f"closed form = de Hoop integral at {len(ss)} points in (s_R, 1) (max rel {mp.nstr(worst, 3)})")
    # Int_0^1 V ds = m^2 / 2
    nu_ = H.nu
    f2 = lambda v: (1 - nu_) * (v - H.c3 * (sR + v * v) / sqrt(2 * sR + v * v))
    iv = H.Vstat * sR + quad_checked(f2, [0, sqrt(m - sR)]) + quad_checked(H.V, [m] + graded(mpf(1), m, H.epsP)[::-1] + [mpf(1)])
    check(fabs(iv - H.a2 / 2) < tol, f"Int_0^1 V ds = m^2/2 (diff {mp.nstr(iv - H.a2 / 2, 3)})")
    symbol_check(H, nu)


def abel_check(H, nu):
    """2-D Lamb W_zz(sigma) = 2 Int_sigma^1 V(s)/sqrt(s^2 - sigma^2) ds vs lamb_reference.json."""
    if not os.path.exists(LAMB_JSON):
        log_err("  (lamb_reference.json not found: Abel check skipped)")
        return
    lam = json.load(open(LAMB_JSON))
    case = [c for c in lam["cases"] if c["nu"] == nu]
    if not case:
        return
    n = 0
    worst = mpf(0)
    for pt in case[0]["points"]:
        with mp.workdps(H.wdps):
            sg = mpf(pt["s"])
        if not (mpf("0.1") < sg < 1) or fabs(sg - H.sR) < mpf("0.01") or fabs(sg - H.m) < mpf("1e-3"):
            continue
        ref = mpf(pt["W_zz"]["value"])
        wd = H.wdps
        if sg > H.sR:
            fu = lambda u: H.V(sg * cosh(u))
            with mp.workdps(wd):
                pts = ([mpf(0), acosh(H.m / sg)] if sg < H.m else [mpf(0)]) + [acosh(1 / sg)]
            I = quad_checked(fu, pts)
        else:
            with mp.workdps(wd):
                I = H.Vstat * acosh(H.sR / sg)
            c3, sR = H.c3, H.sR

            def g(v):
                with mp.workdps(wd):
                    s = sR + v * v
                    x = (1 - H.nu) * (v - c3 * s / sqrt(2 * sR + v * v)) / sqrt((s - sg) * (s + sg))
                return +x
            I += quad_checked(g, [0, sqrt(H.m - sR)])
            I += quad_checked(lambda s: H.V(s) / sqrt((s - sg) * (s + sg)), [H.m, 1])
        rel = fabs(2 * I - ref) / fabs(ref)
        worst = max(worst, rel)
        n += 1
    check(worst < mpf("1e-35"), f"Abel transform of V = 2-D Lamb W_zz (lamb_reference.json) at {n} points"
                                f" (max rel {mp.nstr(worst, 3)})")


def tostr(x):
    with mp.workdps(120):
        return mp.nstr(x, 100)


def main_task(dps):
    mp.dps = dps
    t0 = time.time()
    out = []
    for nu in NUS:
        H = HalfSpace(nu)
        checks(H, nu)
        abel_check(H, nu)
        case = {"nu": nu, "m": H.m, "s_R": H.sR, "V": [], "U": {}}
        for sstr in S_LIST:
            s = mpf(sstr)
            if fabs(s - H.sR) < mpf("1e-3") or fabs(s - H.m) < mpf("1e-3"):
                log_err(f"  skip s = {sstr} (within 1e-3 of s_R or m)")
                continue
            case["V"].append((sstr, H.V(s)))
        t1 = time.time()
        for (i, j) in PAIRS:
            for T in TIMES:
                case["U"][(i, j, T)] = U_ring(H, i, j, None if T == "inf" else mpf(T))
        tol = mpf(10) ** (-mp.dps + 6)
        # static checks
        u00 = case["U"][(0, 0, "inf")]
        ex = (1 - H.nu) * 8 * bk(0) / (3 * pi)
        check(fabs(u00 - ex) < tol, f"U_00(inf) = (1 - nu) 8 a/(3 pi), a = 1/2: {mp.nstr(u00, 20)}")
        wsd = max(fabs(case["U"][(i, j, "inf")] - U_static_ws(H, i, j)) for (i, j) in PAIRS)
        check(wsd < tol, f"static U_ij = Weber-Schafheitlin 2F1 closed form, all pairs (max {mp.nstr(wsd, 3)})")
        rd = mpf(0)
        for (i, j) in PAIRS:
            if (j, i) in PAIRS:
                for T in TIMES:
                    rd = max(rd, fabs(ring_area(i) * case["U"][(i, j, T)] - ring_area(j) * case["U"][(j, i, T)]))
        check(rd < tol, f"reciprocity A_i U_ij = A_j U_ji (max {mp.nstr(rd, 3)})")
        for (i, j) in PAIRS:
            Ts = (bk(i) + bk(j)) / H.sR
            for T in TIMES:
                if T != "inf" and mpf(T) >= Ts:
                    assert case["U"][(i, j, T)] == case["U"][(i, j, "inf")] or \
                        fabs(case["U"][(i, j, T)] - case["U"][(i, j, "inf")]) < tol
        log_err(f"[dps {dps}] nu = {nu}: U values {time.time() - t1:.0f} s")
        # full-precision strings: an mpf returned through multiprocessing is unpickled with
        # mp.mpf(x) at the parent's (default, 15-digit) precision under mpmath 1.4
        case["m"], case["s_R"] = tostr(case["m"]), tostr(case["s_R"])
        case["V"] = [(s_, tostr(v)) for s_, v in case["V"]]
        case["U"] = {k: tostr(v) for k, v in case["U"].items()}
        out.append(case)
    log_err(f"[dps {dps}] done in {time.time() - t0:.0f} s")
    return out


def run_task(task):
    kind, arg = task
    if kind == "main":
        return ("main", arg, main_task(arg))
    return ("laplace", arg, laplace_task(arg))


# ---- output ------------------------------------------------------------------------------------
def agree(a, b):
    """Digits on which a (dps 45) and b (dps 60) agree, at most KEEP; relative difference."""
    with mp.workdps(100):
        a, b = mpf(a), mpf(b)
        if a == 0 and b == 0:
            return {"value": "0", "rel_err": "0"}
        rel = fabs(a - b) / fabs(b)
        for n in range(KEEP, 0, -1):
            sa_, sb_ = mp.nstr(a, n, strip_zeros=False), mp.nstr(b, n, strip_zeros=False)
            if sa_ == sb_:
                return {"value": sb_, "rel_err": mp.nstr(rel, 3)}
        raise AssertionError(("no agreement", a, b))


def main():
    t0 = time.time()
    tasks = ([("laplace", "0.25")] + [("main", d) for d in reversed(RUN_DPS)]
             + [("laplace", nu) for nu in NUS if nu != "0.25"])
    res = {}
    with Pool(2) as pool:
        for kind, arg, r in pool.imap_unordered(run_task, tasks):
            res[(kind, arg)] = r
    r45, r60 = res[("main", RUN_DPS[0])], res[("main", RUN_DPS[1])]
    cases = []
    short = []
    worst_ab = mpf(0)
    for nu, c45, c60 in zip(NUS, r45, r60):
        _, recs, w = res[("laplace", nu)]
        worst_ab = max(worst_ab, mpf(w))
        sR = agree(c45["s_R"], c60["s_R"])
        case = {"nu": nu, "m": agree(c45["m"], c60["m"])["value"], "s_R": sR["value"],
                "V": [], "U": []}
        for (s, v45), (s2, v60) in zip(c45["V"], c60["V"]):
            assert s == s2
            case["V"].append(dict(s=s, **agree(v45, v60)))
        for (i, j) in PAIRS:
            for T in TIMES:
                v = agree(c45["U"][(i, j, T)], c60["U"][(i, j, T)])
                nd = len(v["value"].replace("-", "").replace(".", "").split("e")[0].lstrip("0"))
                if v["value"] != "0" and nd < KEEP:
                    short.append((nu, i, j, T, nd))
                case["U"].append(dict(i=i, j=j, T=T, **v))
        case["laplace_check"] = recs
        cases.append(case)
    for s_ in short:
        log_err("  fewer than KEEP agreeing digits:", s_)
    log_err(f"largest route A - route B relative difference (Laplace domain): {mp.nstr(worst_ab, 3)}")
    doc = {
        "description": ("Independent mpmath reference for the 3-D Lamb problem (Pekeris' problem): "
                        "surface normal displacement of an elastic half-space under a normal surface "
                        "point force P H(t), and ring-cell averages. Generated by "
                        "tests/reference/half_space_mpmath.py (derivation in its docstring): closed form "
                        "(Kausel/Mooney) checked against a finite Cagniard-de Hoop integral and, in the "
                        "Laplace domain, against Hankel-transform integrals (laplace_check). Each value "
                        "carries the digits (at most 40) on which the mp.dps = 45 and 60 runs agree, "
                        "rel_err = |x45 - x60|/|x60|."),
        "units": ("c1 = 1 (P speed), mu = 1, density 1/m^2, m = c2/c1, m^2 = (1 - 2 nu)/(2 (1 - nu)); "
                  "ring width 1; z and displacements positive into the medium; the force pushes into "
                  "the medium"),
        "definitions": ("V: u(rho, t) = P/(pi mu rho) V(s), s = rho/(c1 t), V = 0 for s >= 1, "
                        "V = (1 - nu)/2 for s < s_R = c_R/c1 (listed s within 1e-3 of s_R or m are "
                        "omitted). Rings: b_k = k + 1/2 (k >= 0), b_-1 = 0, ring i = b_{i-1} <= r <= b_i, "
                        "A_i = pi (b_i^2 - b_{i-1}^2); U_ij(T) = (1/A_i) Int_{ring i} dA Int_{ring j} dA' "
                        "u(|x - x'|, T) with u for a unit point force step, i.e. unit pressure step on ring "
                        "j, mean displacement over ring i, at c1 T = T; T = \"inf\": static (Boussinesq), "
                        "U_00(inf) = (1 - nu) 4/(3 pi). U = 0 exactly (\"0\", rel_err \"0\") when c1 T is "
                        "below the smallest distance between the rings. laplace_check: Int_0^inf "
                        "exp(-pT) f(T) dT for f = u(r = 1, T) of the unit point force and f = U_ij(T), "
                        "route A (time domain, mp.dps 18) vs route B (Hankel, mp.dps 20)."),
        "cases": cases,
    }
    json.dump(doc, sys.stdout, indent=1)
    sys.stdout.write("\n")
    log_err(f"total time {time.time() - t0:.1f} s")


if __name__ == "__main__":
    main()
