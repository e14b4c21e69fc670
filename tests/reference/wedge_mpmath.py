#!/usr/bin/env python3
"""Independent high-precision reference values for the dynamic wedge-indentation solution.

Paper: "Dynamic indentation of an elastic half-plane by a rigid wedge: frictional and
tangential-displacement effects" (Brock & Georgiadis type self-similar solution), with the
corrections of notes/paper-errata.md sections 1-5 (branch of p_k, eq (32), |p_k| in (56b)/(57b),
Rayleigh-pole terms, edge quantities) and the apex contour formula of section 6.

Written from the paper and the errata only (no Rust code consulted). Units: c1 = 1, m = c2/c1,
p = alpha/c1, beta = -cot(Theta) (coupled) or 0, gamma = friction coefficient.

Run from the repository root:
    python3 tests/reference/wedge_mpmath.py > tests/reference/wedge_reference.json
Everything is computed twice, at mp.dps = 40 and mp.dps = 50 (each with 20 guard digits in the
inner Cauchy-integral sums); the JSON carries only the digits on which both runs agree, plus the
relative difference of the two runs ("rel_err").  Independent checks are printed to stderr.

Formulas used (derived/re-derived from eqs (18), (31)-(40), (48)-(57) of the paper):
  omega(u) = Omega(sqrt u) - Omega0, analytic in u = xi^2 on (-inf, m^2):
      Omega = atan(z)/pi, z = -m^2 (beta+gamma) N(u) / ((2 sqrt(A) + K)(s1 - beta gamma s2)),
      s1 = sqrt(1-u), s2 = sqrt(1-u/m^2), A = s1^2 s2^2, K = 2-u/m^2, N = -4 + u(4/m^2 - 1/m^4)
      (this equals eq (31) with L = 2 - K|p1||p2| = u N / ((2 sqrt A + K) sqrt A)).
  Lambda0(zeta) = Int_0^{p^2} omega(u)/(u - zeta^2) du        (= eq (38))
  b(xi)         = Int_0^{p^2} (omega(u) - omega(xi^2))/(u - xi^2) du,  S0 = b(0)
  H(v)/v on (p,m) = v^(-2 Omega(v)) (v^2-p^2)^(-1/2+Omega(v)) e^(b(v))
  H(v)/v on (m,1) = v^(-2 Omega0) (v^2-p^2)^(-1/2+Omega0) e^(Lambda0(v))
  R/u = -c(w)/(m^2 (4 sqrt A + K^2) sqrt A),  c(w) = w^3 - 8w^2 + (24-16m^2)w - 16(1-m^2), w=u/m^2
  Y_a = |p2| v^2/(m^2 R) = -(4 sqrt A + K^2) s1/c(w),  T_a = gamma |p1| v^2/(m^2 R) = -gamma (4 sqrt A+K^2) s2/c(w)
  Y_b, T_b: (56b), (57b) with denominators 16 + K^4 |p1|^2 |p2|^2 and K |p2|^2 (errata 3)
  Principal values at v = m_R: the segment [m_R-h, m_R+h] is replaced by the upper half circle
  (PV = Re of the contour integral; the integrands are real-analytic there), no excision.
  Pole terms (errata 4), with U = pi L(m_R) H(m_R)/(m_R R'(m_R)):
      I1 += gamma U, I3 += gamma U/m_R, I5 -= U, I7 -= U/m_R      (variant "paper")
  Q[(I3-I4) - beta(I7+I8)] = cot Theta,  V = Q[(I1-I2) - beta(I5+I6)]           (53)
  sigma_theta/(mu cot Theta) = -q_hat Int_w^p e^b cos(pi Omega) v^(-1-2 Omega) (p^2-v^2)^(-1/2+Omega) dv
  u_r(0+)/(Q t) = (gamma/m^2) Int_0^inf p1(iy) y H(iy)/R(iy) dy                   (errata 6)

Checks (stderr):
  (i)   classical case: pi q_hat/p = 2/(1-nu) = 4(1-m^2)
  (ii)  gamma = 0: apex u_r = 0, computed *directly* from eq (49) (real-axis integral over (0,p)
        with the boundary values of errata 2, plus Q(I5+I6) over (p,1)); for all cases this
        direct value is also compared with the contour formula of errata 6
  (iii) 2 Int_0^p v f(v) dv = pi  (i.e. P from integrating (40) equals pi mu Q t/c1)
  (iv)  (dps-40 run) q_hat and v_hat recomputed without any real-axis principal value or pole
        term: the contact condition (7) written along the vertical line zeta = v0 + i y,
        v0 in (0,p), from the analytic F, G and p_k(zeta) = -i m_k/(sqrt(zeta-m_k) sqrt(zeta+m_k)):
        (I3-I4)-beta(I7+I8) = Int_0^inf Im[-i H (A+iB)/zeta^2] dy, (I1-I2)-beta(I5+I6) = same /zeta.
"""
import sys
import json
import time
from multiprocessing import Pool

from mpmath import mp, mpf, mpc, sqrt, atan, log, exp, cos, sin, pi
from mpmath.calculus.quadrature import GaussLegendre

C1 = "1870.83"
C2 = "1000"
# name, Theta (deg), gamma, coupled, p
CASES = [
    ("A", 89, "0.6", True, "0.3"),
    ("B", 86, "0.001", True, "0.3"),
    ("C", 86, "0.6", True, "0.3"),
    ("D", 86, "0", False, "0.3"),
    ("E", 89, "0", True, "0.2"),
    ("F", 86, "0.4", True, "0.45"),
    ("G", 89, "0.4", False, "0.1"),
]
RHOS = ["0.05", "0.3", "0.6", "0.9"]
GUARD = 20
VERBOSE = False
INNER_DEG = 7  # 192 Gauss-Legendre nodes on [0, p^2] for Lambda0 / b


def log_err(*a):
    print(*a, file=sys.stderr, flush=True)


def cubic(w, m2):
    return ((w - 8) * w + (24 - 16 * m2)) * w - 16 * (1 - m2)


def cubic_d(w, m2):
    return (3 * w - 16) * w + (24 - 16 * m2)


def rayleigh_x(m2):
    """Root x in (0,1) of x^3 - 8x^2 + (24-16m^2)x - 16(1-m^2) (x = (m_R/m)^2)."""
    f = lambda x: cubic(x, m2)
    assert f(mpf(0)) < 0 and f(mpf(1)) > 0
    lo, hi = mpf(0), mpf(1)
    for _ in range(60):  # bisection to a safe start, then Newton
        mid = (lo + hi) / 2
        if f(mid) < 0:
            lo = mid
        else:
            hi = mid
    x = (lo + hi) / 2
    for _ in range(100):
        dx = f(x) / cubic_d(x, m2)
        x -= dx
        if abs(dx) < mpf(2) ** (-mp.prec - 4):
            break
    return x


def rayleigh_mr(m, dps):
    with mp.workdps(dps + 20):
        m = mpf(m)
        x = rayleigh_x(m * m)
        return m * sqrt(x)


class Model:
    def __init__(self, theta_deg, gamma, coupled, p, dps, inner_deg=INNER_DEG):
        mp.dps = dps
        self.dps = dps
        self.G = dps + GUARD
        with mp.workdps(self.G):
            self.m = mpf(C2) / mpf(C1)
            self.m2 = self.m ** 2
            self.p = mpf(p)
            self.p2 = self.p ** 2
            self.gamma = mpf(gamma)
            self.cot = mp.cot(mp.pi * theta_deg / 180)
            self.beta = -self.cot if coupled else mpf(0)
            self.bg = self.beta + self.gamma
            self.bgp = self.beta * self.gamma
            self.xR = rayleigh_x(self.m2)
            self.mR = self.m * sqrt(self.xR)
            self.Om0 = atan(self.m2 * self.bg / (1 - self.bgp)) / pi
            self.ex = mpf(-1) / 2 + self.Om0
            nodes = GaussLegendre(mp).calc_nodes(inner_deg, mp.prec)
            half = self.p2 / 2
            self.U = [half * (x + 1) for x, w in nodes]
            self.W = [half * w for x, w in nodes]
            self.OM = [self.omega_u(u) for u in self.U]
            # half-width of the circle around the Rayleigh pole
            self.h = min(self.mR - self.p, self.m - self.mR) / 4
        self.cache_in = {}

    # ---------------- Omega, Lambda0, b ----------------
    def zfun(self, u, s1=None, s2=None):
        m2 = self.m2
        if s1 is None:
            s1 = sqrt(1 - u)
        if s2 is None:
            s2 = sqrt(1 - u / m2)
        K = 2 - u / m2
        N = -4 + u * (4 / m2 - 1 / m2 ** 2)
        return -m2 * self.bg * N / ((2 * s1 * s2 + K) * (s1 - self.bgp * s2))

    def omega_u(self, u, s1=None, s2=None):
        """omega(u) = Omega(sqrt u) - Omega0 (analytic continuation in u)."""
        return atan(self.zfun(u, s1, s2)) / pi - self.Om0

    def bsum(self, c, wc):
        """Int_0^{p^2} (omega(u) - wc)/(u - c) du, wc = omega(c) (G precision)."""
        with mp.workdps(self.G):
            ds = [uj - c for uj in self.U]
            dmin = min(abs(d) for d in ds)
            if dmin < mpf(10) ** (-15):
                extra = int(-mp.log10(dmin)) + 10 if dmin > 0 else self.G
                with mp.workdps(self.G + extra):
                    wc2 = self.omega_u(c)
                    terms = []
                    for uj, wj, oj, d in zip(self.U, self.W, self.OM, ds):
                        if abs(d) < mpf(10) ** (-6):
                            oj = self.omega_u(uj)
                        terms.append(wj * (oj - wc2) / d)
                    return mp.fsum(terms)
            return mp.fsum(wj * (oj - wc) / d for wj, oj, d in zip(self.W, self.OM, ds))

    def lam_plain(self, c):
        with mp.workdps(self.G):
            return mp.fsum(wj * oj / (uj - c) for uj, wj, oj in zip(self.U, self.W, self.OM))

    def lam(self, c):
        """Lambda0 at zeta^2 = c (c not on [0,p^2]); subtracted form near the cut."""
        with mp.workdps(self.G):
            re, im = mp.re(c), mp.im(c)
            dre = -re if re < 0 else (re - self.p2 if re > self.p2 else 0)
            dist = sqrt(dre ** 2 + im ** 2)
            if dist > self.p2 / 2:
                return self.lam_plain(c)
            wc = self.omega_u(c)
            return self.bsum(c, wc) + wc * log((c - self.p2) / c)

    def S0(self):
        with mp.workdps(self.G):
            return self.bsum(mpf(0), mpf(0))

    # ---------------- point evaluations ----------------
    def pt_in(self, v, dp=None):
        """0 < v < p.  Returns (f, v f, apex_direct_integrand); dp = p - v exact if given."""
        key = (v, dp)
        r = self.cache_in.get(key)
        if r is not None:
            return r
        with mp.workdps(self.G):
            p, m2 = self.p, self.m2
            if dp is None:
                dp = p - v
            u = v * v
            s1 = sqrt(1 - u)
            s2 = sqrt(1 - u / m2)
            wc = self.omega_u(u, s1, s2)
            Om = self.Om0 + wc
            b = self.bsum(u, wc)
            pm = dp * (p + v)  # p^2 - v^2
            Mv = v ** (-2 * Om) * pm ** (Om - mpf(1) / 2) * exp(b)  # M/v, M = |H|
            cP, sP = cos(pi * Om), sin(pi * Om)
            f = Mv * cP / v
            K = 2 - u / m2
            sA = s1 * s2
            w = u / m2
            cw = cubic(w, m2)
            N = -4 + u * (4 / m2 - 1 / m2 ** 2)
            S = -m2 * N * (4 * sA + K ** 2) / ((2 * sA + K) * cw)  # L/R
            T0 = -self.gamma * (4 * sA + K ** 2) * s2 / cw  # gamma|p1| v^2/(m^2 R)
            apex = Mv * (T0 * sP - S * cP)
            r = (f, v * f, apex)
        self.cache_in[key] = r
        return r

    def hv_a(self, v, dlo=None, dhi=None):
        """H(v)/v for p < v < m (real); dlo = v - p, dhi = m - v (exact if given)."""
        p, m, m2 = self.p, self.m, self.m2
        u = v * v
        s1 = sqrt(1 - u)
        s2 = sqrt(dhi * (2 * m - dhi)) / m if dhi is not None else sqrt(1 - u / m2)
        wc = self.omega_u(u, s1, s2)
        Om = self.Om0 + wc
        b = self.bsum(u, wc)
        vp = dlo * (2 * p + dlo) if dlo is not None else u - self.p2
        return v ** (-2 * Om) * vp ** (Om - mpf(1) / 2) * exp(b), u, s1, s2

    def ya_ta(self, u, s1, s2):
        m2 = self.m2
        K = 2 - u / m2
        sA = s1 * s2
        cw = cubic(u / m2, m2)
        q = -(4 * sA + K ** 2) / cw
        return q * s1, self.gamma * q * s2

    def pt_a(self, v, dlo=None, dhi=None):
        with mp.workdps(self.G):
            Hv, u, s1, s2 = self.hv_a(v, dlo, dhi)
            Ya, Ta = self.ya_ta(u, s1, s2)
            return (Hv * Ya, Hv * Ya / v, Hv * Ta, Hv * Ta / v)

    def pt_arc(self, phi):
        """Integrand on the upper half circle zeta = m_R + h e^{i phi}, times d zeta/d phi."""
        with mp.workdps(self.G):
            eip = mp.expj(phi)
            z = self.mR + self.h * eip
            dz = mpc(0, 1) * self.h * eip
            u = z * z
            Hv = z ** (-2 * self.Om0) * (z - self.p) ** self.ex * (z + self.p) ** self.ex * exp(self.lam(u))
            s1 = sqrt(1 - u)
            s2 = sqrt(1 - u / self.m2)
            Ya, Ta = self.ya_ta(u, s1, s2)
            return (Hv * Ya * dz, Hv * Ya / z * dz, Hv * Ta * dz, Hv * Ta / z * dz)

    def pt_b(self, v, dlo=None, dhi=None):
        """m < v < 1; dlo = v - m, dhi = 1 - v (exact if given)."""
        with mp.workdps(self.G):
            m, m2, g = self.m, self.m2, self.gamma
            u = v * v
            sb = sqrt(dlo * (2 * m + dlo)) / m if dlo is not None else sqrt(u / m2 - 1)  # 1/|p2|
            sa = sqrt(dhi * (2 - dhi)) if dhi is not None else sqrt(1 - u)  # 1/|p1|
            a = 1 / sa
            Hv = v ** (-2 * self.Om0) * (u - self.p2) ** self.ex * exp(self.lam_plain(u))
            K = 2 - u / m2
            den = 16 * sb ** 2 + K ** 4 * a ** 2
            Yb = u * K * a * (K - 2 * g * sb) / (m2 * den)
            Tb = 2 * u * a * (2 * g * sb ** 2 - K * sb) / (m2 * den)
            return (Hv * Yb, Hv * Yb / v, Hv * Tb, Hv * Tb / v)

    def pole_unit(self):
        """U = pi L(m_R) H(m_R)/(m_R R'(m_R))  (H(m_R)/m_R = Hv(m_R))."""
        with mp.workdps(self.G):
            v = self.mR
            m2 = self.m2
            Hv, u, s1, s2 = self.hv_a(v)
            sA = s1 * s2
            K = 2 - u / m2
            N = -4 + u * (4 / m2 - 1 / m2 ** 2)
            L = u * N / ((2 * sA + K) * sA)
            Rp = u * (-cubic_d(self.xR, m2) * 2 * v / m2) / (m2 * (4 * sA + K ** 2) * sA)
            # cross-check R' by numerical differentiation of R = 4 - K^2 |p1||p2|
            Rf = lambda x: 4 - (2 - x * x / m2) ** 2 / sqrt((1 - x * x) * (1 - x * x / m2))
            Rp2 = mp.diff(Rf, v)
            assert abs(Rp - Rp2) < mpf(10) ** (-self.dps) * abs(Rp), (Rp, Rp2)
            return pi * L * Hv / Rp, L, Hv, Rp

    # ---------------- quadrature helpers ----------------
    def vquad(self, fvec, interval, ncomp, label, errs, method="tanh-sinh", comps=None):
        cache = {}
        t0 = time.time()

        def comp(k):
            def fk(s):
                r = cache.get(s)
                if r is None:
                    r = fvec(s)
                    cache[s] = r
                return r[k]
            return fk

        out = []
        for k in range(ncomp):
            if comps is not None and k not in comps:
                out.append(None)
                continue
            val, err = mp.quad(comp(k), interval, method=method, error=True)
            out.append(val)
            errs.append((label, k, err, val))
        if VERBOSE:
            log_err("  %s: %d evaluations, %.2f s, errs %s" % (label, len(cache), time.time() - t0,
                    [mp.nstr(e[2], 2) for e in errs[-ncomp:]]))
        return out

    # ---------------- the integrals I1..I8 ----------------
    def integrals(self, errs):
        p, m, mR, h = self.p, self.m, self.mR, self.h
        one = mpf(1)
        # (p, m_R - h): v = p + s^4
        L1 = (mR - h - p)
        sm1 = mp.root(L1, 4)

        def fa1(s):
            d = s ** 4
            r = self.pt_a(p + d, dlo=d)
            j = 4 * s ** 3
            return tuple(j * x for x in r)

        A1 = self.vquad(fa1, [0, sm1], 4, "a1", errs)

        # upper half circle around m_R: PV = Re( -Int_0^pi f(zeta) dzeta/dphi dphi )
        Aarc = self.vquad(self.pt_arc, [0, pi], 4, "arc", errs)
        Aarc = [-mp.re(x) for x in Aarc]
        Aarc_im = None

        # (m_R + h, m): v = m - s^2
        sm2 = sqrt(m - mR - h)

        def fa2(s):
            d = s ** 2
            r = self.pt_a(m - d, dhi=d)
            return tuple(2 * s * x for x in r)

        A2 = self.vquad(fa2, [0, sm2], 4, "a2", errs)
        Ia = [A1[k] + Aarc[k] + A2[k] for k in range(4)]  # PV I1, I3, I5, I7

        cm = (m + one) / 2
        sb1 = sqrt(cm - m)

        def fb1(s):
            d = s ** 2
            r = self.pt_b(m + d, dlo=d)
            return tuple(2 * s * x for x in r)

        sb2 = sqrt(one - cm)

        def fb2(s):
            d = s ** 2
            r = self.pt_b(one - d, dhi=d)
            return tuple(2 * s * x for x in r)

        B1 = self.vquad(fb1, [0, sb1], 4, "b1", errs)
        B2 = self.vquad(fb2, [0, sb2], 4, "b2", errs)
        Ib = [B1[k] + B2[k] for k in range(4)]  # I2, I4, I6, I8
        I = {1: Ia[0], 3: Ia[1], 5: Ia[2], 7: Ia[3], 2: Ib[0], 4: Ib[1], 6: Ib[2], 8: Ib[3]}
        return I

    # ---------------- contact-zone integrals ----------------
    def contact(self, errs):
        """Cumulative Int_w^p f for w = rho p, Int_0^p v f, Int_0^p apex-direct integrand."""
        p = self.p
        rh = [mpf(x) for x in RHOS]
        # (0.9p, p): v = p - s^4
        s4 = mp.root(p * (1 - rh[3]), 4)

        def fin4(s):
            d = s ** 4
            r = self.pt_in(p - d, dp=d)
            j = 4 * s ** 3
            return tuple(j * x for x in r)

        pieces = [self.vquad(fin4, [0, s4], 3, "in4", errs)]
        for lo, hi, lab in ((rh[2], rh[3], "in3"), (rh[1], rh[2], "in2"), (rh[0], rh[1], "in1")):
            pieces.append(self.vquad(lambda v: self.pt_in(v), [lo * p, hi * p], 3, lab, errs))
        s0 = sqrt(rh[0] * p)

        def fin0(s):
            v = s ** 2
            r = self.pt_in(v)
            return (None, 2 * s * r[1], 2 * s * r[2])

        pieces.append(self.vquad(fin0, [0, s0], 3, "in0", errs, comps=(1, 2)))
        # sigma integrals at w = 0.9p, 0.6p, 0.3p, 0.05p (cumulative)
        sig = []
        acc = mpf(0)
        for k in range(4):
            acc += pieces[k][0]
            sig.append(acc)
        sig = sig[::-1]  # order rho = 0.05, 0.3, 0.6, 0.9
        force_int = mp.fsum(pc[1] for pc in pieces)
        apex_int = mp.fsum(pc[2] for pc in pieces)
        return sig, force_int, apex_int

    def apex_contour(self, errs):
        """u_r(0+)/(Q t) = (gamma/m^2) Int_0^inf p1(iy) y H(iy)/R(iy) dy."""
        if self.gamma == 0:
            return mpf(0)
        m2 = self.m2

        def fy(y, ys2=None):
            with mp.workdps(self.G):
                y2 = y * y
                u = -y2
                s1 = sqrt(1 + y2)
                s2 = sqrt(1 + y2 / m2)
                wc = self.omega_u(u, s1, s2)
                lam = self.bsum(u, wc) + wc * log((y2 + self.p2) / y2)
                # H(iy)/y  (H(iy) is real positive)
                Hy = y ** (-2 * self.Om0) * (y2 + self.p2) ** self.ex * exp(lam)
                K = 2 - u / m2
                sA = s1 * s2
                Ru = -cubic(u / m2, m2) / (m2 * (4 * sA + K ** 2) * sA)  # R/u > 0
                # p1(iy) y H/R = (-1/s1) * y H / (-y^2 Ru) = Hy/(s1 Ru)
                return (self.gamma / m2 * Hy / (s1 * Ru),)

        def f0(s):
            y = s ** 2
            return (2 * s * fy(y)[0],)

        a = self.vquad(f0, [0, 1], 1, "apx0", errs)[0]
        b = self.vquad(fy, [1, mp.inf], 1, "apx1", errs)[0]
        return a + b

    # ---------------- check (iv): vertical line, no principal values ----------------
    def vertical_check(self, v0, errs):
        p, m, m2 = self.p, self.m, self.m2
        ii = mpc(0, 1)

        def pk(z, mk):
            return -ii * mk / (sqrt(z - mk) * sqrt(z + mk))

        def fy(y):
            with mp.workdps(self.G):
                z = mpc(v0, y)
                u = z * z
                H = z ** (1 - 2 * self.Om0) * (z - p) ** self.ex * (z + p) ** self.ex * exp(self.lam(u))
                p1, p2 = pk(z, 1), pk(z, m)
                K = 2 - u / m2
                L = 2 - K * p1 * p2
                R = 4 - K * K * p1 * p2
                A = self.bg * L / R
                B = u * (p2 - self.bgp * p1) / (m2 * R)
                phi = -ii * H * (A + ii * B)
                return (mp.im(phi / z), mp.im(phi / u))

        r = self.vquad(fy, [0, mpf(1) / 4, 1, 4, mp.inf], 2, "vert", errs)
        return r[0], r[1]  # (I1-I2)-beta(I5+I6), (I3-I4)-beta(I7+I8)


def matching(M, I, U, pole_terms):
    """The integrals I1..I8 as used (with the Rayleigh-pole terms of errata 4 when
    `pole_terms`, the "paper" variant) and the two brackets of (53): V = Q VQ, Q CQ = 1 (in
    units c1 cot Theta, c1^2 cot Theta)."""
    J = dict(I)
    if pole_terms:
        J[1] += M.gamma * U
        J[3] += M.gamma * U / M.mR
        J[5] -= U
        J[7] -= U / M.mR
    VQ = (J[1] - J[2]) - M.beta * (J[5] + J[6])
    CQ = (J[3] - J[4]) - M.beta * (J[7] + J[8])
    return J, VQ, CQ


def run_case(args):
    name, theta, gamma, coupled, p, dps, do_checks = args
    t0 = time.time()
    M = Model(theta, gamma, coupled, p, dps)
    errs = []
    res = {}
    with mp.workdps(dps):
        I = M.integrals(errs)
        U, Lm, Hm, Rp = M.pole_unit()
        variants = {}
        for var in ("paper", "as_printed"):
            J, VQ, CQ = matching(M, I, U, var == "paper")
            q_hat = 1 / CQ
            v_hat = q_hat * VQ
            d = {
                "q_hat": q_hat,
                "v_hat": v_hat,
                "force_over_a_mu_cot_theta": pi * q_hat / M.p,
                "edge_slip_velocity_over_speed": (J[5] + J[6]) / VQ,
                "edge_following_rate_over_speed": ((J[5] + J[6]) - (J[7] + J[8]) * M.p) / VQ,
                "_VQ": VQ,
                "_CQ": CQ,
                "_I56": J[5] + J[6],
            }
            for k in range(1, 9):
                d["_I%d" % k] = J[k]
            variants[var] = d
        sig, force_int, apex_int = M.contact(errs)
        P = variants["paper"]
        P["sigma_over_mu_cot_theta"] = [-P["q_hat"] * s for s in sig]
        ur0 = M.apex_contour(errs)
        P["apex_u_r_over_speed_t"] = ur0 / P["_VQ"]
        res["m"] = +M.m
        res["m_r"] = +M.mR
        res["omega0"] = +M.Om0
        res["s0"] = +M.S0()
        res["variants"] = variants
        chk = {
            "force_integral_2_int_v_f_over_pi": 2 * force_int / pi,
            "apex_direct_over_Qt": P["_I56"] + apex_int,
            "apex_contour_over_Qt": ur0,
            "apex_direct_as_printed_over_Qt": variants["as_printed"]["_I56"] + apex_int,
            "pole_unit": U,
            "classical_4(1-m^2)": 4 * (1 - M.m2),
        }
        if do_checks:
            for v0f in ("0.5", "0.75"):
                v0 = M.p * mpf(v0f)
                VQv, CQv = M.vertical_check(v0, errs)
                chk["vertical_v0=%sp_VQ" % v0f] = VQv
                chk["vertical_v0=%sp_CQ" % v0f] = CQv
        res["checks"] = chk
        worst = max((abs(e) / max(abs(v), mpf(10) ** -30), lab, k) for lab, k, e, v in errs)
        res["quad_worst_rel_err_estimate"] = worst[0]
        res["quad_worst_where"] = "%s[%d]" % (worst[1], worst[2])
    res["time"] = time.time() - t0
    # convert to strings for pickling across processes with full digits
    return name, dps, to_str(res)


def run_classical(p):
    """Check (i) at other expansion speeds: pi q_hat/p for beta = gamma = 0 (dps 30)."""
    M = Model(86, "0", False, p, 30)
    errs = []
    with mp.workdps(30):
        I = M.integrals(errs)
        q_hat = 1 / (I[3] - I[4])  # beta = 0; pole terms vanish for gamma = 0 in I3
        return p, mp.nstr(pi * q_hat / M.p, 25), mp.nstr(4 * (1 - M.m2), 25)


def to_str(x):
    if isinstance(x, dict):
        return {k: to_str(v) for k, v in x.items()}
    if isinstance(x, list):
        return [to_str(v) for v in x]
    if isinstance(x, (float, int, str)):
        return x
    return mp.nstr(x, mp.dps + 5, strip_zeros=False) if hasattr(x, "_mpf_") else str(x)


def inner_convergence(theta, gamma, coupled, p, dps):
    """Compare inner GL degree 7 (192 nodes) with degree 8 (384 nodes)."""
    out = []
    Ma = Model(theta, gamma, coupled, p, dps, inner_deg=INNER_DEG)
    Mb = Model(theta, gamma, coupled, p, dps, inner_deg=INNER_DEG + 1)
    with mp.workdps(dps + GUARD):
        for c in (mpf(0), Ma.p2 * mpf("0.999"), Ma.p2 * mpf("1.0001"), Ma.mR ** 2,
                  Ma.m2 * mpf("0.9999"), mpf("0.7") ** 2, mpc(Ma.p2 / 4, Ma.p2 / 3)):
            if c == 0 or (mp.im(c) == 0 and c < Ma.p2):
                a = Ma.bsum(c, Ma.omega_u(c))
                b = Mb.bsum(c, Mb.omega_u(c))
            elif mp.im(c) != 0 or c < Ma.m2:
                a = Ma.lam(c)
                b = Mb.lam(c)
            else:
                a = Ma.lam_plain(c)
                b = Mb.lam_plain(c)
            out.append(abs(a - b) / max(abs(b), mpf(10) ** -10))
    return max(out)


def agree(a_str, b_str, maxdig=30):
    """Return (string with digits on which the two precisions agree, rel_err)."""
    with mp.workdps(80):
        a, b = mpf(a_str), mpf(b_str)
        if b == 0 and a == 0:
            return "0", "0"
        diff = abs(a - b)
        scale = max(abs(b), mpf(10) ** -60)
        rel = diff / scale
        if rel == 0:
            nd = maxdig
        else:
            nd = int(mp.floor(-mp.log10(rel))) - 1
        nd = max(1, min(maxdig, nd))
        return mp.nstr(b, nd), mp.nstr(rel, 3) if rel > 0 else "0"


def merge(r40, r50):
    if isinstance(r50, dict):
        return {k: merge(r40[k], r50[k]) for k in r50}
    if isinstance(r50, list):
        return [merge(a, b) for a, b in zip(r40, r50)]
    v, e = agree(r40, r50)
    return {"value": v, "rel_err": e}


def main():
    t0 = time.time()
    tasks = []
    for (name, th, g, cp, p) in CASES[::-1]:  # slowest cases first
        tasks.append((name, th, g, cp, p, 40, True))
        tasks.append((name, th, g, cp, p, 50, False))
    results = {}
    with Pool(2) as pool:
        classical = pool.map_async(run_classical, ["0.05", "0.2", "0.45"])
        for name, dps, res in pool.imap_unordered(run_case, tasks):
            results[(name, dps)] = res
            log_err("case %s dps %d done in %.1f s (quad worst rel err est %s at %s)" % (
                name, dps, res["time"], mp.nstr(mpf(res["quad_worst_rel_err_estimate"]), 3),
                res["quad_worst_where"]))
    mp.dps = 50
    out = {
        "description": "Independent mpmath reference for the wedge-indentation solution "
                       "(paper + errata sections 1-6). Generated by tests/reference/wedge_mpmath.py; "
                       "values agree between mp.dps=40 and mp.dps=50 runs to the digits given; "
                       "rel_err = |x40 - x50|/|x50|.",
        "units": "c1 = 1, m = c2/c1, p = alpha/c1, beta = -cot(Theta) if coupled else 0",
        "c1": C1, "c2": C2,
        "m_r_80": None,
        "rayleigh": {},
        "cases": {},
    }
    # Rayleigh roots at 80 digits (computed at 100 and 120 digits, compared)
    for key, mval in (("m_r_80", mpf(C2) / mpf(C1)), ("m_0.5", mpf("0.5")), ("m_0.3", mpf("0.3"))):
        with mp.workdps(130):
            mv = mpf(C2) / mpf(C1) if key == "m_r_80" else mpf(key[2:])
        a = rayleigh_mr(mv, 100)
        b = rayleigh_mr(mv, 120)
        with mp.workdps(130):
            rel = abs(a - b) / b
            # independent check: R(m_R) = 4 - K^2 |p1||p2| = 0
            x = b
            Kx = 2 - x * x / (mv * mv)
            Rres = 4 - Kx ** 2 / sqrt((1 - x * x) * (1 - x * x / (mv * mv)))
            out["rayleigh"][key] = {"m": mp.nstr(mv, 80), "m_r": mp.nstr(b, 80),
                                    "rel_err": mp.nstr(rel, 3), "R_residual": mp.nstr(Rres, 3)}
    out["m_r_80"] = out["rayleigh"]["m_r_80"]["m_r"]
    # inner quadrature convergence (one representative hard case: F, largest p)
    conv = inner_convergence(86, "0.4", True, "0.45", 50)
    log_err("inner GL (192 vs 384 nodes) max rel diff, case F dps 50: %s" % mp.nstr(conv, 3))
    out["inner_gl_192_vs_384_rel_diff_caseF"] = mp.nstr(conv, 3)

    log_err("")
    for (name, th, g, cp, p) in CASES:
        r40, r50 = results[(name, 40)], results[(name, 50)]
        c = {
            "theta_deg": str(th), "gamma": g, "coupled": cp, "p": p,
            "beta": mp.nstr(-mp.cot(mp.pi * th / 180), 30) if cp else "0",
            "cot_theta": mp.nstr(mp.cot(mp.pi * th / 180), 30),
        }
        for k in ("m", "m_r", "omega0", "s0"):
            c[k] = merge(r40[k], r50[k])
        for var in ("paper", "as_printed"):
            v40, v50 = r40["variants"][var], r50["variants"][var]
            c[var] = {}
            for k in v50:
                if k.startswith("_"):
                    continue
                if k == "sigma_over_mu_cot_theta":
                    c[var][k] = [dict(r_over_alpha_t=rho, **merge(a, b))
                                 for rho, a, b in zip(RHOS, v40[k], v50[k])]
                else:
                    c[var][k] = merge(v40[k], v50[k])
            c[var]["integrals_I1_to_I8"] = [merge(v40["_I%d" % k], v50["_I%d" % k]) for k in range(1, 9)]
        out["cases"][name] = c

    # ---------------- checks ----------------
    log_err("=== checks (values from the dps-50 run unless noted) ===")
    checks = {}
    cl = {}
    for p, f, ex in classical.get():
        d = mpf(f) - mpf(ex)
        cl["p=" + p] = {"pi_q_hat_over_p": f, "minus_2_over_1_minus_nu": mp.nstr(d, 3)}
        log_err("classical (i) at p = %s (dps 30): pi q_hat/p = %s, 2/(1-nu) = %s, diff %.2e" % (
            p, f, ex, float(d)))
    checks["classical_force_other_p"] = cl
    with mp.workdps(50):
        for (name, th, g, cp, p) in CASES:
            r40, r50 = results[(name, 40)], results[(name, 50)]
            ch = r50["checks"]
            ch40 = r40["checks"]
            P = r50["variants"]["paper"]
            A = r50["variants"]["as_printed"]
            cc = {}
            fi = mpf(ch["force_integral_2_int_v_f_over_pi"])
            cc["iii_2_int_v_f_over_pi_minus_1"] = mp.nstr(fi - 1, 3)
            log_err("%s (iii) P from integrating (40) / (pi mu Q t): 1 %+.3e" % (name, float(fi - 1)))
            ad, ac = mpf(ch["apex_direct_over_Qt"]), mpf(ch["apex_contour_over_Qt"])
            ap = mpf(ch["apex_direct_as_printed_over_Qt"])
            cc["apex_u_r_over_Qt_direct_eq49"] = mp.nstr(ad, 20)
            cc["apex_u_r_over_Qt_contour_errata6"] = mp.nstr(ac, 20)
            cc["apex_u_r_over_Qt_direct_eq49_without_pole_terms"] = mp.nstr(ap, 20)
            log_err("%s (ii) apex u_r/(Qt): direct (49) = %s, contour = %s, |diff| = %.2e; "
                    "without pole terms: %s" % (name, mp.nstr(ad, 12), mp.nstr(ac, 12),
                                                 float(abs(ad - ac)), mp.nstr(ap, 8)))
            if name == "D":
                f = mpf(P["force_over_a_mu_cot_theta"])
                ex = mpf(ch["classical_4(1-m^2)"])
                cc["i_force_minus_2_over_1_minus_nu"] = mp.nstr(f - ex, 3)
                log_err("D (i) pi q_hat/p = %s, 2/(1-nu) = 4(1-m^2) = %s, diff %.2e" % (
                    mp.nstr(f, 20), mp.nstr(ex, 20), float(f - ex)))
            for v0f in ("0.5", "0.75"):
                VQv = mpf(ch40["vertical_v0=%sp_VQ" % v0f])
                CQv = mpf(ch40["vertical_v0=%sp_CQ" % v0f])
                qv = 1 / CQv
                vv = qv * VQv
                dq = abs(qv - mpf(P["q_hat"])) / abs(mpf(P["q_hat"]))
                dv = abs(vv - mpf(P["v_hat"])) / abs(mpf(P["v_hat"]))
                cc["iv_vertical_line_v0=%sp_q_hat_rel_diff" % v0f] = mp.nstr(dq, 3)
                cc["iv_vertical_line_v0=%sp_v_hat_rel_diff" % v0f] = mp.nstr(dv, 3)
                log_err("%s (iv) vertical line v0=%sp: q_hat %s (rel diff to paper %.2e), "
                        "v_hat %s (rel diff %.2e)" % (name, v0f, mp.nstr(qv, 15), float(dq),
                                                      mp.nstr(vv, 15), float(dv)))
            checks[name] = cc
    out["checks"] = checks
    out["run_time_s"] = round(time.time() - t0, 1)
    log_err("total run time %.1f s" % (time.time() - t0))
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
