#!/usr/bin/env python3
r"""Independent high-precision reference values for Lamb's problem (2-D, plane strain):
surface displacements of an elastic half-plane under a surface line force.

Written from first principles (plane-strain elastodynamics); no Rust code consulted.

Run from the repository root:
    python3 tests/reference/lamb_mpmath.py > tests/reference/lamb_reference.json
Everything is computed twice, at mp.dps = 45 and mp.dps = 60 (integrands evaluated with
GUARD extra digits); the JSON carries only the digits (at most 40 significant) on which
both runs agree, each value as {"value": "...", "rel_err": "..."} with
rel_err = |x45 - x60| / |x60| (quantities that vanish identically, |x| < 1e-37 in both runs,
as {"value": "0", "abs_err": "..."}).  Independent checks are printed to stderr (and asserted).

Conventions
-----------
Half-plane z > 0 (z points into the medium), shear modulus mu, speeds c1 > c2,
m = c2/c1, m^2 = (1 - 2 nu)/(2 (1 - nu)).  Units c1 = 1, mu = 1, so rho = 1/m^2 and
lambda = 1/m^2 - 2.  Line force at x = 0 on z = 0; F_z > 0 pushes into the medium,
F_x > 0 points along +x.  s = |x|/(c1 t), s_R = c_R/c1, kappa = s/m (= |x|/(c2 t)).
Impulse I delta(t):  u_z = I/(pi mu t) g_zz(s),  u_x = sign(x) I/(pi mu t) g_xz(s)  (F_z),
                     u_x = I/(pi mu t) g_xx(s),  u_z = sign(x) I/(pi mu t) g_zx(s)  (F_x).
Step P H(t):  u = P/(pi mu) W(s),  W(s) = Int_s^1 g(sigma)/sigma dsigma
(W_zz, U_xz, U_xx; principal value across s_R; the delta of g_xz counted when s < s_R).

Derivation
----------
Potentials: u = grad phi + curl(psi e_y), i.e. u_x = phi_x - psi_z, u_z = phi_z + psi_x,
with phi_tt = c1^2 lap phi, psi_tt = c2^2 lap psi.  Slownesses a = 1/c1 = 1, b = 1/c2 = 1/m.
Laplace transform in t (parameter p > 0) and, at fixed p, the transform in x with real
"imaginary-slowness" variable xi:
    f^(x, p) = (p / 2 pi) Int F(xi) exp(i p xi x) dxi,   F(xi) = Int f^(x) exp(-i p xi x) dx.
Bounded solutions: Phi = A exp(-p alpha z), Psi = B exp(-p beta z),
    alpha = sqrt(xi^2 + a^2), beta = sqrt(xi^2 + b^2)  (Re > 0, principal branches).
At z = 0 (with lambda a^2 + 2 alpha^2 = b^2 + 2 xi^2):
    sigma_zz = p^2 [ (b^2 + 2 xi^2) A - 2 i xi beta B ],
    sigma_xz = -p^2 [ 2 i xi alpha A + (b^2 + 2 xi^2) B ].
The outward normal of the medium is -e_z, so the traction applied to the surface is
(-sigma_xz, -sigma_zz).  Normal impulse: -sigma_zz = I delta(x) delta(t), sigma_xz = 0 (I = 1):
    A = -(b^2 + 2 xi^2)/(p^2 R),  B = 2 i xi alpha/(p^2 R),
    R(xi) = (b^2 + 2 xi^2)^2 - 4 xi^2 alpha beta   (no zero for real xi),
and on z = 0
    U_z = b^2 alpha/(p R),   U_x = -i xi (b^2 + 2 xi^2 - 2 alpha beta)/(p R).
Tangential impulse: -sigma_xz = delta(x) delta(t), sigma_zz = 0:
    U_x = b^2 beta/(p R),    U_z = +i xi (b^2 + 2 xi^2 - 2 alpha beta)/(p R)  (= -U_x of the
    normal case: reciprocity g_zx = -g_xz).
Hence u^(x, p) = (1/2 pi) Int F(xi) exp(i p xi x) dxi with F = p U.  Cagniard-de Hoop:
for x > 0 close the contour in Im xi > 0 around the cut xi = i sigma, sigma > a.  With
F(-conj xi) = conj F(xi) the two banks give
    u^(x, p) = Int_a^inf h(sigma) exp(-p sigma x) dsigma,  h = -(1/pi) Im F(i sigma + 0),
which is the Laplace transform of u(x, t) = h(t/x)/x.  So with sigma = 1/s:
    g(s) = -sigma Im F(i sigma + 0),   u = g(s)/(pi t).
On the right bank alpha/sigma = sqrt(s^2 - 1), beta/sigma = sqrt(kappa^2 - 1) taken at
s + i0 (principal branch), and R = sigma^4 Dc(s),  Dc = (2 - kappa^2)^2 + 4 (alpha/sigma)(beta/sigma):
    g_zz = -kappa^2 Im[ sqrt(s^2-1) / Dc ],   g_xx = -kappa^2 Im[ sqrt(kappa^2-1) / Dc ],
    g_xz = -Im[ N / Dc ],  N = kappa^2 - 2 - 2 sqrt(s^2-1) sqrt(kappa^2-1).
With A = sqrt(1 - s^2), B = sqrt(1 - kappa^2), Bb = sqrt(kappa^2 - 1):

  s > 1 (ahead of P):  F real, g = 0.
  P-S region m < s < 1:  Dc = (2-kappa^2)^2 + 4 i A Bb,  Delta = (2-kappa^2)^4 + 16 A^2 Bb^2,
      g_zz = -kappa^2 A (2 - kappa^2)^2 / Delta                        (< 0)
      g_xz = -2 kappa^2 (2 - kappa^2) A Bb / Delta                      (sign of kappa^2 - 2)
      g_xx = 4 kappa^2 A Bb^2 / Delta                                   (> 0)
  s < m (S-R region s_R < s < m, and behind R, s < s_R): Dc = D(s) is real,
      D(s) = (2 - kappa^2)^2 - 4 A B  (the Rayleigh function; D < 0 for s < s_R, D > 0 above),
      rationalized: D(s) [(2 - kappa^2)^2 + 4AB] = kappa^2 Ray(kappa^2),
      Ray(k) = k^3 - 8 k^2 + (24 - 16 m^2) k - 16 (1 - m^2),
      g_zz = -kappa^2 A / D = -A [(2-kappa^2)^2 + 4AB] / Ray(kappa^2)   (PV pole at s_R)
      g_xx = -kappa^2 B / D = -B [(2-kappa^2)^2 + 4AB] / Ray(kappa^2)   (PV pole at s_R)
      g_xz = 0 except the Rayleigh delta: 1/D(s + i0) = PV 1/D - i pi delta(s - s_R)/D'(s_R) gives
      g_xz = pi K_R s_R delta(s - s_R),  K_R = N_R/(s_R D'(s_R)),  N_R = -kappa_R^2 (2 - kappa_R^2)/2.
  Residues: r_zz = -kappa_R^2 A_R / D'(s_R),  r_xx = -kappa_R^2 B_R / D'(s_R)  (both < 0; K_R < 0).
  Signs fixed, not imposed: as s -> 0, D ~ -2 s^2 (1 - m^2)/m^2, so g_zz, g_xx -> 1/(2(1-m^2))
  = 1 - nu (Flamant: W_zz ~ -(1 - nu) log s); continuity at s = m and s = 1 follows.
  (K_R < 0: the Rayleigh pulse of u_x points towards the load, like Flamant's static
  -(1 - 2 nu) P sign(x)/(4 mu); at nu = 1/4, K_R = -1/8 and Int_m^1 g_xz/s ds = 0.)
  Rayleigh wave: u_x = K_R sign(x) delta(t - t_R), u_z = -(r_zz/s_R) (1/pi) PV 1/(t - t_R)
  (its Hilbert transform), so |u_x/u_z| per harmonic component = |K_R s_R / r_zz|, to be compared
  with the classical (2 - kappa_R^2)/(2 sqrt(1 - s_R^2)) = 2 sqrt(1 - kappa_R^2)/(2 - kappa_R^2).

Numerical method (no closed-form antiderivative of W)
-----------------------------------------------------
Moments Int_sa^sb g(s) s^-k ds (k = 0, 1, 2) by tanh-sinh quadrature (mp.quad):
  * P-S part: s = m + (1-m) sin^2(phi) (A and Bb become analytic in phi).
    End points of all substitutions are computed, with GUARD digits, by well-conditioned
    formulas (atan2) from the abscissae exactly as written in the JSON.
  * s < m, near s = 0: u = log s (for k >= 1), or s = m sin(theta) from s = 0 (k = 0).
  * s < m, from s_R/2 up: s = m sin(theta) (B = cos theta), with the pole term
    c/(s - s_R), c = r/s_R^k, subtracted from the integrand and integrated analytically
    (c log|(s_hi - s_R)/(s_lo - s_R)|); the cancellation next to s_R is absorbed by the
    GUARD digits.
  * g_xz: the delta contributes pi K_R s_R / s_R^k when sa < s_R < sb.
Cells starting at sa = 0: only Ix (and It_xz, which is 0); It_zz, It_xx diverge (log) and
I2 is not defined there, so those keys are absent.

Checks (stderr): g(0+) = 1 - nu; PV Int_0^1 g_zz = pi m^2/2 and Int_0^1 g_xx = pi m/2
(1-D plane-wave momentum), the former also by an indented complex contour; U_xz(s < s_R) =
-pi (1 - 2 nu)/4 (Flamant); ellipticity; residues from the Rayleigh function's derivative
(numerical and via the cubic) and from the limit of (s - s_R) g; K_R from the integral
across s_R of -sigma Im F_xz(i sigma + 1e-14) (smoothed delta); g evaluated directly from the transform-domain F(i sigma + eps);
reciprocity g_zx = -g_xz; continuity at s = m and s = 1; It = W(sa) - W(sb).
"""
import sys
import json
import time
from multiprocessing import Pool

from mpmath import mp, mpf, mpc, sqrt, log, exp, pi, sin, cos, asin, fabs, findroot

NUS = ["0.25", "0.1", "0.3", "0.45", "-0.5"]
RUN_DPS = (45, 60)
GUARD = 25          # extra digits inside integrand evaluations
KEEP = 40           # significant digits kept in the JSON
S_DIGITS = 50       # digits of the s-values written (and read back)
ZERO = mpf(10) ** -37   # |x| below this in both runs: written as "0" (all genuine values are far larger)

# points: (label, function of (m, s_R))
POINTS = [
    ("1e-6", lambda m, sr: mpf("1e-6")),
    ("0.01", lambda m, sr: mpf("0.01")),
    ("0.2", lambda m, sr: mpf("0.2")),
    ("s_R - 0.05", lambda m, sr: sr - mpf("0.05")),
    ("s_R - 1e-4", lambda m, sr: sr - mpf("1e-4")),
    ("s_R + 1e-4", lambda m, sr: sr + mpf("1e-4")),
    ("(s_R + m)/2", lambda m, sr: (sr + m) / 2),
    ("m - 1e-6", lambda m, sr: m - mpf("1e-6")),
    ("m + 1e-6", lambda m, sr: m + mpf("1e-6")),
    ("(m + 1)/2", lambda m, sr: (m + 1) / 2),
    ("1 - 1e-6", lambda m, sr: 1 - mpf("1e-6")),
    ("1.5", lambda m, sr: mpf("1.5")),
]
CELLS = [
    ("0", "0.2", lambda m, sr: (mpf(0), mpf("0.2"))),
    ("0.2", "s_R - 0.01", lambda m, sr: (mpf("0.2"), sr - mpf("0.01"))),
    ("0.1", "0.95", lambda m, sr: (mpf("0.1"), mpf("0.95"))),
    ("s_R + 0.001", "m", lambda m, sr: (sr + mpf("0.001"), m)),
    ("m", "1", lambda m, sr: (m, mpf(1))),
    ("0.5", "1.2", lambda m, sr: (mpf("0.5"), mpf("1.2"))),
    ("0.01", "0.05", lambda m, sr: (mpf("0.01"), mpf("0.05"))),
    ("s_R - 1e-3", "s_R + 2e-3", lambda m, sr: (sr - mpf("1e-3"), sr + mpf("2e-3"))),
]
COMPS = ("zz", "xz", "xx")


def log_err(*a):
    print(*a, file=sys.stderr, flush=True)


def check(cond, msg):
    log_err(("  ok   " if cond else "  FAIL ") + msg)
    assert cond, msg


class Lamb:
    """Quadratures at the current mp precision (set by the caller); the material constants
    and the Rayleigh-root quantities are computed and kept with GUARD extra digits."""

    def __init__(self, nu):
        self.wdps = mp.dps + GUARD
        with mp.workdps(self.wdps):
            self.nu = mpf(nu)
            self.m2 = (1 - 2 * self.nu) / (2 * (1 - self.nu))
            self.m = sqrt(self.m2)
            # Rayleigh root: kappa_R^2 is the only root of the cubic in (0, 1)
            # (Ray(0) = -16(1-m^2) < 0, Ray(1) = 1 > 0); bracket, then polish.
            k = findroot(self.ray, (mpf("0.01"), mpf(1)), solver="anderson")
            k = findroot(self.ray, k, solver="newton")
            self.kR = k
            self.sR = self.m * sqrt(k)
            sR = self.sR
            self.AR = sqrt(1 - sR * sR)
            self.BR = sqrt(1 - k)
            self.Dp = self.dD(sR)
            self.r = {"zz": -k * self.AR / self.Dp, "xx": -k * self.BR / self.Dp}
            self.NR = k - 2 + 2 * self.AR * self.BR
            self.KR = self.NR / (sR * self.Dp)

    # ---- Rayleigh function -------------------------------------------------
    def ray(self, k):
        return ((k - 8) * k + (24 - 16 * self.m2)) * k - 16 * (1 - self.m2)

    def ray_d(self, k):
        return (3 * k - 16) * k + (24 - 16 * self.m2)

    def D(self, s):
        """Irrational Rayleigh function (2 - kappa^2)^2 - 4 A B, s < m (also complex s)."""
        k2 = s * s / self.m2
        return (2 - k2) ** 2 - 4 * sqrt(1 - s * s) * sqrt(1 - k2)

    def dD(self, s):
        """Analytic d/ds of D."""
        k2 = s * s / self.m2
        A = sqrt(1 - s * s)
        B = sqrt(1 - k2)
        return -4 * s * (2 - k2) / self.m2 + 4 * s * (B / A + A / (self.m2 * B))

    # ---- Green's functions (regular parts) ---------------------------------
    def g_S(self, k2, A, B):
        """s < m: (g_zz, g_xx), rationalized form (no cancellation at small s)."""
        E = (2 - k2) ** 2 + 4 * A * B
        ry = self.ray(k2)
        return -A * E / ry, -B * E / ry

    def g_PS(self, k2, A, Bb):
        """m < s < 1: (g_zz, g_xz, g_xx)."""
        P = (2 - k2) ** 2
        Q = 4 * A * Bb
        den = P * P + Q * Q
        return (-k2 * A * P / den, -2 * k2 * (2 - k2) * A * Bb / den, k2 * Bb * Q / den)

    def g(self, s):
        """Pointwise (g_zz, g_xz, g_xx) at s > 0 (regular parts; the delta is not pointwise)."""
        with mp.workdps(self.wdps):
            s = mpf(s)
            if s >= 1:
                return mpf(0), mpf(0), mpf(0)
            k2 = s * s / self.m2
            A = sqrt((1 - s) * (1 + s))
            if s > self.m:
                Bb = sqrt((s - self.m) * (s + self.m)) / self.m
                r = self.g_PS(k2, A, Bb)
            else:
                B = sqrt((self.m - s) * (self.m + s)) / self.m
                zz, xx = self.g_S(k2, A, B)
                r = (zz, mpf(0), xx)
        return tuple(+x for x in r)

    # ---- transform-domain evaluation (check) -------------------------------
    def g_transform(self, s, eps):
        """-sigma Im F(i sigma + eps) straight from the transform-domain expressions.
        Returns (g_zz, g_xz, g_xx, g_zx)."""
        sig = 1 / mpf(s)
        xi = mpc(eps, sig)
        b2 = 1 / self.m2
        al = sqrt(xi * xi + 1)
        be = sqrt(xi * xi + b2)
        R = (b2 + 2 * xi * xi) ** 2 - 4 * xi * xi * al * be
        T = b2 + 2 * xi * xi - 2 * al * be
        F = (b2 * al / R, -1j * xi * T / R, b2 * be / R, 1j * xi * T / R)
        return tuple(-sig * f.imag for f in F)

    # ---- quadrature ----------------------------------------------------------
    def _quad(self, f, a, b):
        v, e = mp.quad(f, [a, b], error=True)
        tol = mpf(10) ** (-mp.dps + 4) * max(1, fabs(v))
        if not e <= tol:
            # retry with more levels before giving up
            v, e = mp.quad(f, [a, b], error=True, maxdegree=12)
            assert e <= tol, ("quadrature error", a, b, v, e)
        return v

    def theta(self, s):
        """theta with s = m sin(theta), well conditioned up to s = m."""
        with mp.workdps(self.wdps):
            return mp.atan2(s, sqrt((self.m - s) * (self.m + s)))

    def moment(self, comp, k, sa, sb):
        """PV Int_sa^sb g_comp(s) s^-k ds (delta of g_xz included when sa < s_R < sb)."""
        m, sR = self.m, self.sR
        # sa, sb are used as given (not rounded to the working precision): differences such as
        # 1 - sa or sa - s_R are then formed from the exact abscissae
        total = mpf(0)
        wd = self.wdps
        # P-S region
        lo, hi = max(sa, m), min(sb, mpf(1))
        if lo < hi:
            idx = COMPS.index(comp)
            w = 1 - m
            sqw = sqrt(w)

            def fps(ph):
                with mp.workdps(wd):
                    sp, cp = sin(ph), cos(ph)
                    s = m + w * sp * sp
                    k2 = s * s / self.m2
                    A = sqw * cp * sqrt(1 + s)
                    Bb = sqw * sp * sqrt(s + m) / m
                    gv = self.g_PS(k2, A, Bb)[idx]
                    r = gv * s ** (-k) * 2 * w * sp * cp
                return +r

            with mp.workdps(wd):   # end points well conditioned from the exact abscissae
                pa = mp.atan2(sqrt(lo - m), sqrt(1 - lo))
                pb = mp.atan2(sqrt(hi - m), sqrt(1 - hi))
            total += self._quad(fps, pa, pb)
        # s < m
        if comp == "xz":
            if sa < sR < sb:
                total += pi * self.KR * sR / sR ** k
            return total
        lo, hi = sa, min(sb, m)
        if lo < hi:
            i2 = 0 if comp == "zz" else 1
            sc = sR / 2
            # low piece, away from the pole
            if lo < sc:
                top = min(hi, sc)
                if lo == 0:
                    assert k == 0

                    def flow(th):
                        with mp.workdps(wd):
                            st, ct = sin(th), cos(th)
                            s = m * st
                            gv = self.g_S(st * st, sqrt(1 - s * s), ct)[i2]
                            r = gv * m * ct
                        return +r

                    total += self._quad(flow, mpf(0), self.theta(top))
                else:
                    def flog(u):
                        with mp.workdps(wd):
                            s = exp(u)
                            k2 = s * s / self.m2
                            gv = self.g_S(k2, sqrt(1 - s * s), sqrt(1 - k2))[i2]
                            r = gv * s ** (1 - k)
                        return +r

                    total += self._quad(flog, log(lo), log(top))
            # middle piece, pole term subtracted
            a = max(lo, sc)
            if a < hi:
                c = self.r[comp] / sR ** k
                tiny = mpf(10) ** (-(GUARD - 5))

                def fmid(th):
                    with mp.workdps(wd):
                        st, ct = sin(th), cos(th)
                        s = m * st
                        d = s - sR
                        assert fabs(d) > tiny, "node too close to the Rayleigh pole"
                        gv = self.g_S(st * st, sqrt(1 - s * s), ct)[i2]
                        r = (gv * s ** (-k) - c / d) * m * ct
                    return +r

                total += self._quad(fmid, self.theta(a), self.theta(hi))
                total += c * log(fabs((hi - sR) / (a - sR)))
        return total

    def W(self, comp, s):
        if s >= 1:
            return mpf(0)
        return self.moment(comp, 1, s, mpf(1))


# --------------------------------------------------------------------------------------------
def s_strings(nu):
    """Point and cell abscissae computed at high precision, as S_DIGITS-digit strings."""
    with mp.workdps(100):
        L = Lamb(nu)
        pts = [(lab, mp.nstr(f(L.m, L.sR), S_DIGITS)) for lab, f in POINTS]
        cells = []
        for la, lb, f in CELLS:
            a, b = f(L.m, L.sR)
            cells.append((la, lb, mp.nstr(a, S_DIGITS) if a != 0 else "0", mp.nstr(b, S_DIGITS)))
        return mp.nstr(L.m, S_DIGITS), pts, cells


def checks(L, nu):
    """Independent checks, printed to stderr and asserted."""
    m, sR, kR = L.m, L.sR, L.kR
    one_nu = 1 - L.nu
    log_err(f"[dps {mp.dps}] nu = {nu}: m = {mp.nstr(m, 20)}, s_R = {mp.nstr(sR, 20)}")
    # Rayleigh root: zero of the irrational function, single root of the cubic in (0,1)
    with mp.workdps(L.wdps):
        check(fabs(L.D(sR)) < mpf(10) ** (-mp.dps + GUARD + 5), "D(s_R) = 0 (irrational form)")
    roots = mp.polyroots([1, -8, 24 - 16 * L.m2, -16 * (1 - L.m2)], maxsteps=200, extraprec=100)
    inside = [r for r in roots if fabs(mp.im(r)) < mpf(10) ** -20 and 0 < mp.re(r) < 1]
    check(len(inside) == 1, "one root of the Rayleigh cubic in (0,1)")
    vik = (mpf("0.87") + mpf("1.12") * L.nu) / (1 + L.nu)
    if L.nu >= 0:   # the approximation (0.87 + 1.12 nu)/(1 + nu) is meant for 0 <= nu <= 1/2
        check(fabs(sqrt(kR) - vik) < mpf("0.01"),
              f"c_R/c2 = {mp.nstr(sqrt(kR), 12)} ~ Viktorov {mp.nstr(vik, 6)}")
    check(0 < sR < m, f"0 < s_R < m (c_R/c2 = {mp.nstr(sqrt(kR), 12)})")
    if L.nu == mpf("0.25"):   # Poisson solid: kappa_R^2 = 2 - 2/sqrt(3) in closed form
        with mp.workdps(L.wdps):
            check(fabs(kR - (2 - 2 / sqrt(3))) < mpf(10) ** -60, "nu = 1/4: kappa_R^2 = 2 - 2/sqrt(3)")
    # late-time limit
    with mp.workdps(L.wdps):
        g0 = L.g(mpf("1e-20"))
    check(fabs(g0[0] - one_nu) < mpf(10) ** -35 and fabs(g0[2] - one_nu) < mpf(10) ** -35,
          "g_zz(0+) = g_xx(0+) = 1 - nu")
    # plane-wave momentum identities
    izz = L.moment("zz", 0, 0, 1)
    ixx = L.moment("xx", 0, 0, 1)
    tol = mpf(10) ** (-mp.dps + 6)
    check(fabs(izz - pi * L.m2 / 2) < tol, f"PV Int_0^1 g_zz ds = pi m^2/2 (diff {mp.nstr(izz - pi * L.m2 / 2, 3)})")
    check(fabs(ixx - pi * m / 2) < tol, f"PV Int_0^1 g_xx ds = pi m/2 (diff {mp.nstr(ixx - pi * m / 2, 3)})")
    # the same PV by an indented contour in the theta plane (no pole subtraction)
    tR = asin(sR / m)
    d = min(tR, pi / 2 - tR) / 2

    def gz(th):
        with mp.workdps(L.wdps):
            st, ct = sin(th), cos(th)
            s = m * st
            r = L.g_S(st * st, sqrt(1 - s * s), ct)[0] * m * ct
        return +r

    def gz_arc(ph):
        th = tR + d * mp.expj(ph)
        return gz(th) * 1j * d * mp.expj(ph)

    pv_c = (mp.quad(gz, [0, tR - d]) + mp.quad(gz, [tR + d, pi / 2])
            + mp.re(-mp.quad(gz_arc, [0, pi])))
    pv_s = L.moment("zz", 0, 0, m)
    check(fabs(pv_c - pv_s) < tol, f"PV Int_0^m g_zz: indented contour vs pole subtraction (diff {mp.nstr(pv_c - pv_s, 3)})")
    # Flamant tangential displacement behind R
    ps = L.moment("xz", 1, m, 1)
    delta = pi * L.KR
    flam = -pi * (1 - 2 * L.nu) / 4
    log_err(f"    Int_m^1 g_xz/s ds = {mp.nstr(ps, 25)},  delta part pi K_R = {mp.nstr(delta, 25)},"
            f"  sum = {mp.nstr(ps + delta, 25)}")
    check(fabs(ps + delta - flam) < tol, "U_xz(s < s_R) = -pi (1 - 2 nu)/4 (Flamant)")
    uxz = L.W("xz", sR / 3)
    check(fabs(uxz - flam) < tol, "U_xz(s_R/3) via W = -pi (1 - 2 nu)/4")
    # Rayleigh-wave ellipticity
    ell = L.KR * sR / L.r["zz"]
    cl1 = (2 - kR) / (2 * sqrt(1 - sR * sR))
    cl2 = 2 * sqrt(1 - kR) / (2 - kR)
    check(fabs(ell - cl1) < tol and fabs(ell - cl2) < tol,
          f"|u_x/u_z| = K_R s_R/r_zz = {mp.nstr(ell, 20)} = classical (2-k^2)/(2 sqrt(1-s_R^2))")
    # residues: derivative of the Rayleigh function (numerical), via the cubic, and as a limit
    with mp.workdps(L.wdps):
        dnum = mp.diff(L.D, sR)
        r1 = -kR * L.AR / dnum
        r2 = -4 * L.m2 * L.AR ** 2 * L.BR / (sR * L.ray_d(kR))
        h = mpf(10) ** -20
        lim_zz = (h * L.g(sR + h)[0] - h * L.g(sR - h)[0]) / 2
        lim_xx = (h * L.g(sR + h)[2] - h * L.g(sR - h)[2]) / 2
    rz = L.r["zz"]
    check(fabs(r1 / rz - 1) < tol, "r_zz: analytic D' vs numerical derivative of D")
    check(fabs(r2 / rz - 1) < tol, "r_zz: via Ray'(kappa_R^2) of the cubic")
    check(fabs(lim_zz / rz - 1) < mpf(10) ** -30, "r_zz = lim (s - s_R) g_zz(s)")
    check(fabs(lim_xx / L.r["xx"] - 1) < mpf(10) ** -30, "r_xx = lim (s - s_R) g_xx(s)")
    # K_R from the transform domain with a small finite eps (smoothed delta)
    hw = min(mpf("0.01"), (m - sR) / 2, sR / 2)
    eps = mpf(10) ** -14
    with mp.workdps(L.wdps):
        fx = lambda s: L.g_transform(s, eps)[1]
        kint = mp.quad(fx, [sR - hw, sR, sR + hw])
    check(fabs(kint / (pi * L.KR * sR) - 1) < mpf(10) ** -9,
          f"Int g_xz^eps across s_R = pi K_R s_R (rel {mp.nstr(kint / (pi * L.KR * sR) - 1, 3)})")
    # pointwise: transform-domain evaluation, reciprocity
    worst = mpf(0)
    with mp.workdps(L.wdps):
        eps = mpf(10) ** (-mp.dps + 10)
        for s in (mpf("0.05"), sR / 2, (sR + m) / 2, sR * mpf("0.999"), (m + 1) / 2,
                  m + (1 - m) / 7, 1 - (1 - m) / 11, mpf("1.3")):
            gt = L.g_transform(s, eps)
            gr = L.g(s)
            for a_, b_ in ((gt[0], gr[0]), (gt[1], gr[1]), (gt[2], gr[2]), (-gt[3], gr[1])):
                worst = max(worst, fabs(a_ - b_) / max(1, fabs(b_)))
    check(worst < mpf(10) ** -30, f"g = -sigma Im F(i sigma + 0) from the transforms; g_zx = -g_xz (max {mp.nstr(worst, 3)})")
    # continuity at s = m and s = 1
    with mp.workdps(L.wdps):
        e = mpf(10) ** -30
        jm = max(fabs(a_ - b_) for a_, b_ in zip(L.g(m - e), L.g(m + e)))
        j1 = max(fabs(a_) for a_ in L.g(1 - e * e))
        gm = L.g(m - e)
    check(jm < mpf(10) ** -13, f"g continuous at s = m (jump {mp.nstr(jm, 3)} over 2e-30)")
    check(fabs(gm[0] + sqrt(1 - L.m2)) < mpf(10) ** -13 and fabs(gm[2]) < mpf(10) ** -13,
          "g_zz(m) = -sqrt(1 - m^2), g_xx(m) = 0, g_xz(m) = 0")
    check(j1 < mpf(10) ** -13, "g -> 0 at s = 1 (continuous with the zero ahead of P)")
    return {"Int_m^1 g_xz/s": ps, "pi K_R": delta}


def run(dps):
    mp.dps = dps
    t0 = time.time()
    out = []
    for nu in NUS:
        mstr, pts, cells = S_TABLE[nu]
        L = Lamb(nu)
        info = checks(L, nu)
        case = {"nu": nu, "s_R": L.sR, "r_zz": L.r["zz"], "r_xx": L.r["xx"], "K_R": L.KR,
                "info": info, "points": [], "cells": []}
        for lab, sstr in pts:
            with mp.workdps(S_DIGITS + 30):
                s = mpf(sstr)      # the abscissa exactly as written
            g = L.g(s)
            case["points"].append({
                "g_zz": g[0], "g_xz": g[1], "g_xx": g[2],
                "W_zz": L.W("zz", s), "U_xz": L.W("xz", s), "U_xx": L.W("xx", s)})
        wcheck = mpf(0)
        for la, lb, sa_s, sb_s in cells:
            with mp.workdps(S_DIGITS + 30):
                sa, sb = mpf(sa_s), mpf(sb_s)
            if la == "0.1":
                check(sa < L.sR < L.m < sb, "cell [0.1, 0.95] contains s_R and m")
            rec = {}
            for c in COMPS:
                rec["Ix_" + c] = L.moment(c, 0, sa, sb)
                if sa > 0 or c == "xz":
                    rec["It_" + c] = L.moment(c, 1, sa, sb)
                if sa > 0:
                    rec["I2_" + c] = L.moment(c, 2, sa, sb)
                    wcheck = max(wcheck, fabs(rec["It_" + c] - (L.W(c, sa) - L.W(c, sb))))
            case["cells"].append(rec)
        check(wcheck < mpf(10) ** (-mp.dps + 6), f"It = W(sa) - W(sb) for all cells (max diff {mp.nstr(wcheck, 3)})")
        out.append(case)
    log_err(f"[dps {dps}] done in {time.time() - t0:.1f} s")
    return out


def agree(a, b):
    """Digits on which a (dps 45) and b (dps 60) agree, at most KEEP; and the relative difference."""
    with mp.workdps(100):
        a, b = mpf(a), mpf(b)
        if fabs(a) < ZERO and fabs(b) < ZERO:
            # vanishes identically (exact zero, or cancellation down to the working precision)
            e = max(fabs(a), fabs(b))
            return {"value": "0", "abs_err": mp.nstr(e, 3) if e else "0"}
        rel = fabs(a - b) / fabs(b)
        for n in range(KEEP, 0, -1):
            sa_, sb_ = mp.nstr(a, n, strip_zeros=False), mp.nstr(b, n, strip_zeros=False)
            if sa_ == sb_:
                return {"value": sb_, "rel_err": mp.nstr(rel, 3)}
        raise AssertionError(("no agreement", a, b))


S_TABLE = {nu: s_strings(nu) for nu in NUS}


def main():
    t0 = time.time()
    with Pool(2) as pool:
        r45, r60 = pool.map(run, RUN_DPS)
    worst = 0
    short = []
    cases = []
    for nu, c45, c60 in zip(NUS, r45, r60):
        mstr, pts, cells = S_TABLE[nu]

        def ag(key, x45, x60, where):
            v = agree(x45, x60)
            nd = len(v["value"].replace("-", "").replace(".", "").split("e")[0].lstrip("0"))
            if v["value"] != "0" and nd < KEEP:
                short.append((nu, where, key, nd))
            return v

        case = {"nu": nu, "m": mstr}
        for key in ("s_R", "r_zz", "r_xx", "K_R"):
            case[key] = ag(key, c45[key], c60[key], "case")
        case["points"] = []
        for (lab, sstr), p45, p60 in zip(pts, c45["points"], c60["points"]):
            rec = {"label": lab, "s": sstr}
            for key in p60:
                rec[key] = ag(key, p45[key], p60[key], lab)
            case["points"].append(rec)
        case["cells"] = []
        for (la, lb, sa_s, sb_s), q45, q60 in zip(cells, c45["cells"], c60["cells"]):
            rec = {"sa_label": la, "sb_label": lb, "sa": sa_s, "sb": sb_s}
            for key in q60:
                rec[key] = ag(key, q45[key], q60[key], f"[{la}, {lb}]")
            case["cells"].append(rec)
        cases.append(case)
        i60 = c60["info"]
        log_err(f"nu = {nu}: Int_m^1 g_xz/s ds = {mp.nstr(i60['Int_m^1 g_xz/s'], 30)}, "
                f"pi K_R = {mp.nstr(i60['pi K_R'], 30)}")
    for s_ in short:
        log_err("  fewer than KEEP agreeing digits:", s_)
    doc = {
        "description": ("Independent mpmath reference for Lamb's problem (2-D plane strain, surface line "
                        "force on a half-plane). Generated by tests/reference/lamb_mpmath.py (derivation "
                        "in its docstring); each value carries the digits (at most 40) on which the "
                        "mp.dps = 45 and mp.dps = 60 runs agree, rel_err = |x45 - x60|/|x60|."),
        "units": ("c1 = 1, mu = 1, impulse I = 1: u = g(s)/(pi t) (u_x due to F_z and u_z due to F_x "
                  "carry sign(x)); step P = 1: u = W(s)/pi; s = |x|/(c1 t); F_z > 0 pushes into the "
                  "medium z > 0"),
        "definitions": ("r = lim_{s->s_R} (s - s_R) g(s); g_xz contains pi K_R s_R delta(s - s_R); "
                        "W_zz, U_xz, U_xx = Int_s^1 g/sigma dsigma (PV at s_R, delta counted for s < s_R); "
                        "Ix, It, I2 = Int_sa^sb g s^-k ds for k = 0, 1, 2 (PV, delta counted when "
                        "sa < s_R < sb); cells with sa = 0 have no I2 and no It_zz, It_xx (log divergence); "
                        "values that vanish identically (|x| < 1e-37 in both runs, e.g. g_xz for s < m, "
                        "everything for s > 1, U_xz for s_R < s < m at nu = 1/4) are written as "
                        "{\"value\": \"0\", \"abs_err\": max(|x45|, |x60|)}"),
        "cases": cases,
    }
    json.dump(doc, sys.stdout, indent=1)
    sys.stdout.write("\n")
    log_err(f"total time {time.time() - t0:.1f} s")


if __name__ == "__main__":
    main()
