#!/usr/bin/env python3
r"""Independent mpmath reference values for a thin elastic ring (cylindrical shell in plane
strain) with membrane, bending, transverse-shear and rotary-inertia terms (Timoshenko ring),
loaded by a radial contact pressure.

Derived from first principles below; no Rust code consulted.  python3 + mpmath only.

Run from the repository root:
    python3 tests/reference/shell_mpmath.py > tests/reference/shell_reference.json
(about 40 s).  Checks are printed to stderr and asserted.

Model and conventions
---------------------
Ring of mid-surface radius R, wall thickness h, unit axial length, density rho_s,
plane-strain modulus E' = E/(1 - nu^2), shear modulus G, shear coefficient k_s = 5/6.
With the wave speeds c1, c2 of the material and m = c2/c1:
    G = rho_s c2^2,   E' = 4 rho_s c2^2 (1 - m^2).
theta is measured from the contact point.  Unknowns: w(theta, t) radial displacement
(positive OUTWARD), v(theta, t) circumferential (positive towards +theta), psi(theta, t)
rotation of the cross-section.
    membrane strain     eps   = (v_theta + w)/R
    bending curvature   kappa = psi_theta/R
    transverse shear    gamma = psi + (w_theta - v)/R
(rigid translation w = A cos theta, v = -A sin theta, psi = 0, and rigid rotation
v = c, psi = c/R, w = 0, are strain free).
    U = 1/2 Int_0^{2pi} [E' h eps^2 + E' h^3/12 kappa^2 + k_s G h gamma^2] R dtheta
    T = 1/2 Int_0^{2pi} rho_s [h (w_t^2 + v_t^2) + h^3/12 psi_t^2] R dtheta
A pressure q(theta, t) acts radially INWARD (force per unit mid-surface area); its virtual
work is  -Int q dw R dtheta.  A concentrated inward line force P at theta = 0 is
q = (P/R) delta(theta).

Dimensionless units: lengths / R, time / (R/c1), stresses / (rho_s c1^2).  Hence R = 1,
rho_s = 1, c1 = 1, E' = 4 m^2 (1 - m^2), G = m^2, and the parameters are h/R and m.
Frequencies are omega R/c1; displacements are in units of R for a pressure amplitude of
rho_s c1^2 (line force P of rho_s c1^2 R per unit length).

Derivation (harmonic n)
-----------------------
Take w = W cos(n theta), v = V sin(n theta), psi = Psi sin(n theta) (for n = 0: w = W,
v = V, psi = Psi, all constant; the algebra is the same with n = 0).  Then
    eps   = (W + n V)/R cos(n theta)
    kappa = n Psi/R cos(n theta)
    gamma = (Psi - (n W + V)/R) sin(n theta).
With Int_0^{2pi} cos^2 = Int sin^2 = pi (n >= 1), and Int cos^2 -> 2 pi, sin -> 1 (n = 0),
put c_n = pi R (n >= 1), c_0 = 2 pi R.  For q = (W, V, Psi):
    U = 1/2 q^T K q,   T = 1/2 q_t^T M q_t,
    K = c_n [ (E' h/R^2) a a^T + (E' h^3 n^2/(12 R^2)) e3 e3^T + k_s G h b b^T ],
        a = (1, n, 0),  b = (-n/R, -1/R, 1),  e3 = (0, 0, 1),
    M = c_n rho_s h diag(1, 1, h^2/12).
Written out:
    K_WW = c_n (E' h + k_s G h n^2)/R^2        K_WV = c_n n (E' h + k_s G h)/R^2
    K_VV = c_n (E' h n^2 + k_s G h)/R^2        K_WPsi = -c_n k_s G h n/R
    K_VPsi = -c_n k_s G h/R                    K_PsiPsi = c_n (E' h^3 n^2/(12 R^2) + k_s G h)
Generalised force of a pressure q = Q(t) cos(n theta): f = (-c_n Q, 0, 0); of the line
force P at theta = 0: f = (-P, 0, 0) on EVERY harmonic (delta w(0) = sum_n delta W_n).
Lagrange's equations: M q'' + K q = f.
n = 0: block diagonal, breathing W (omega^2 = E'/(rho_s R^2)) and the torsional pair
(V, Psi) with K = 2 pi R k_s G h [[1/R^2, -1/R], [-1/R, 1]], whose eigenvalues are
0 (rigid rotation, (V, Psi) = (1, 1/R)) and omega^2 = (k_s G/rho_s)(1/R^2 + 12/h^2).
n = 1: K (1, -1, 0)^T = 0 (rigid translation), one zero frequency.

Numerics
--------
* mp.dps = 30 is the base precision of the reported run.  Linear algebra and time stepping
  are done with GUARD = 20 extra digits (the 3x3 problems are stiff: shear eigenvalues
  ~ 1e3 next to flexural ones ~ 1e-3, and 30 plain digits were found to leave a relative
  error up to ~1e-27 in the smallest frequencies, too close to the 25 digits written).
  The whole computation is repeated at mp.dps = 50 and every reported value is asserted
  to agree to the 25 significant digits written.
* Eigenproblem K phi = omega^2 M phi: M is diagonal, so with L = M^(1/2) the symmetric
  matrix A = L^-1 K L^-1 is diagonalised by mp.eigsy; phi = L^-1 x is mass-normalised
  (phi^T M phi = 1).  Eigenvalues with |lambda| < 10^-dps max|lambda| (the rigid modes,
  n = 0 torsional and n = 1) are set to exactly 0 (checked against the known strain-free
  vectors).  Cross-check: roots of the characteristic cubic det(A - lambda I) (mp.polyroots).
* Step response: M q'' + K q = f H(t), q(0) = q'(0) = 0, integrated directly by a
  fixed-step Taylor-series integrator of the first-order system q' = p,
  p' = -M^-1 K q + M^-1 f (Taylor coefficients by recursion, order chosen so that
  (omega_max dt)^P/P! < 10^-(working digits + 5)), at dt = 1/100 and again at dt = 1/200;
  both agreements (step halving, and the closed-form modal solution
  q = sum_j phi_j (phi_j . f)(1 - cos omega_j t)/omega_j^2) are reported.
* Point load: modal superposition, closed form in time.  A mode of frequency omega and
  modal force F = phi . f responds F (1 - cos omega t)/omega^2.  For n = 1 the zero-frequency
  (rigid translation) mode, which would respond F t^2/2, is dropped: what is summed is the
  deformation only (the rigid translation of the ring is entirely in that mode; the
  elastic modes are M-orthogonal to it).  Cross-check: n = 1 integrated directly, minus
  the rigid motion phi_r (phi_r . f) t^2/2.  n = 0 contributes only breathing.  The series
  converges like O(1/N) (high harmonics behave like a Timoshenko beam, compliance
  ~ R/(pi k_s G h n^2)).
"""
import sys
import json
import time

from mpmath import mp, mpf, sqrt, cos, pi

mp.dps = 30
BASE_DPS = 30          # reported run
CHECK_DPS = 50         # verification run
GUARD = 20             # extra working digits in linear algebra and time stepping
SIG = 25               # significant digits written

FREQ_CASES = [("0.02", "0.5"), ("0.05", "0.55"), ("0.1", "0.5")]
FREQ_N = list(range(0, 9))
CLASSICAL_N = list(range(2, 9))
STEP_CASE = ("0.05", "0.55")
STEP_N = [0, 2, 3, 5]
STEP_TIMES = ["0.3", "1.0", "2.5", "7.0"]
STEP_DT = (100, 200)   # steps per unit time (dt = 1/100, halved to 1/200)
POINT_TIMES = ["0.3", "1.0", "2.5"]
POINT_N = [50, 100, 200]
POINT_CONTRIB_N = list(range(0, 9))


def log_err(*a):
    print(*a, file=sys.stderr)


def check(cond, msg):
    log_err(("  ok   " if cond else "  FAIL ") + msg)
    assert cond, msg


def fmt(x, sig=SIG):
    if x == 0:
        return "0"
    return mp.nstr(x, sig, strip_zeros=False)


class Ring:
    """Material/geometry in dimensionless units (R = rho_s = c1 = 1)."""

    def __init__(self, h, m):
        self.h = mpf(h)
        self.m = mpf(m)
        self.R = mpf(1)
        self.rho = mpf(1)
        self.ks = mpf(5) / 6
        self.G = self.m ** 2
        self.Ep = 4 * self.m ** 2 * (1 - self.m ** 2)

    def cn(self, n):
        return (2 if n == 0 else 1) * pi * self.R

    def matrices(self, n):
        h, R, Ep, G, ks, rho = self.h, self.R, self.Ep, self.G, self.ks, self.rho
        c = self.cn(n)
        n = mpf(n)
        a = [mpf(1), n, mpf(0)]
        b = [-n / R, -1 / R, mpf(1)]
        K = mp.matrix(3, 3)
        for i in range(3):
            for j in range(3):
                K[i, j] = c * (Ep * h / R ** 2 * a[i] * a[j] + ks * G * h * b[i] * b[j])
        K[2, 2] += c * Ep * h ** 3 * n ** 2 / (12 * R ** 2)
        M = mp.matrix(3, 3)
        M[0, 0] = c * rho * h
        M[1, 1] = c * rho * h
        M[2, 2] = c * rho * h ** 3 / 12
        return M, K

    def eig(self, n):
        """Sorted eigenvalues lambda = omega^2 and mass-normalised eigenvectors (columns)."""
        M, K = self.matrices(n)
        Ls = [sqrt(M[i, i]) for i in range(3)]
        A = mp.matrix(3, 3)
        for i in range(3):
            for j in range(3):
                A[i, j] = K[i, j] / (Ls[i] * Ls[j])
        E, Q = mp.eigsy(A)
        lam = [E[i] for i in range(3)]
        order = sorted(range(3), key=lambda i: lam[i])
        lmax = max(abs(x) for x in lam)
        lams, phis = [], []
        for i in order:
            li = lam[i]
            if abs(li) < mpf(10) ** (-(mp.dps - 2)) * lmax:
                li = mpf(0)
            assert li >= 0, (n, li)
            lams.append(li)
            phis.append([Q[k, i] / Ls[k] for k in range(3)])
        return M, K, A, lams, phis


def mp_lu_solve(K, f):
    x = mp.lu_solve(K, mp.matrix(f))
    return [x[i] for i in range(3)]


def taylor_integrate(M, K, f, times, steps_per_unit, omega_max):
    """q'' = -M^-1 K q + M^-1 f, q(0) = q'(0) = 0; fixed-step Taylor series."""
    D = [[K[i, j] / M[i, i] for j in range(3)] for i in range(3)]
    g = [f[i] / M[i, i] for i in range(3)]
    dt = mpf(1) / steps_per_unit
    rho = omega_max * dt
    P = 10
    term = mpf(1)
    tol = mpf(10) ** (-(mp.dps + 5))
    while True:
        term = rho ** P / mp.factorial(P)
        if term < tol and P >= 10:
            break
        P += 1
    targets = {}
    for ts in times:
        k = mpf(ts) * steps_per_unit
        ki = int(mp.nint(k))
        assert abs(k - ki) < mpf(10) ** (-mp.dps + 5), ts
        targets[ki] = ts
    nsteps = max(targets)
    q = [mpf(0)] * 3
    p = [mpf(0)] * 3
    out = {}
    for s in range(1, nsteps + 1):
        Qk, Pk = q[:], p[:]
        qn, pn = q[:], p[:]
        for k in range(P):
            c = dt / (k + 1)
            Qn = [c * Pk[i] for i in range(3)]
            Pn = [c * (-(D[i][0] * Qk[0] + D[i][1] * Qk[1] + D[i][2] * Qk[2])
                       + (g[i] if k == 0 else 0)) for i in range(3)]
            Qk, Pk = Qn, Pn
            for i in range(3):
                qn[i] += Qk[i]
                pn[i] += Pk[i]
        q, p = qn, pn
        if s in targets:
            out[targets[s]] = q[:]
    return out, P


def modal_response(lams, phis, f, t, skip_zero=True):
    """sum over modes phi (phi.f)(1 - cos omega t)/omega^2 (zero modes: t^2/2 unless skipped)."""
    q = [mpf(0)] * 3
    for lam, ph in zip(lams, phis):
        F = sum(ph[i] * f[i] for i in range(3))
        if lam == 0:
            if skip_zero:
                continue
            r = t ** 2 / 2
        else:
            r = (1 - cos(sqrt(lam) * t)) / lam
        for i in range(3):
            q[i] += ph[i] * F * r
    return q


def rel(a, b):
    if a == b:
        return mpf(0)
    return abs(a - b) / max(abs(a), abs(b))


def compute(dps):
    """Everything at base precision dps (GUARD extra digits inside). Returns nested dicts of mpf."""
    mp.dps = dps
    res = {"frequencies": {}, "classical": {}, "step": {}, "point": {}, "diag": {}}
    with mp.workdps(dps + GUARD):
        # ---------- frequencies ----------
        for hs, ms in FREQ_CASES:
            ring = Ring(hs, ms)
            fr = {}
            log_err(f"[dps {dps}] h/R = {hs}, m = {ms}: E' = {mp.nstr(ring.Ep, 12)}, G = {mp.nstr(ring.G, 12)}")
            for n in FREQ_N:
                M, K, A, lams, phis = ring.eig(n)
                om = [sqrt(l) for l in lams]
                fr[n] = om
                # strain-free vectors
                if n == 1:
                    r = [mpf(1), mpf(-1), mpf(0)]
                elif n == 0:
                    r = [mpf(0), mpf(1), 1 / ring.R]
                else:
                    r = None
                if r is not None:
                    Kr = max(abs(sum(K[i, j] * r[j] for j in range(3))) for i in range(3))
                    assert Kr < mpf(10) ** (-(mp.dps - 5)), (n, Kr)
                    assert lams[0] == 0 and lams[1] > 0
                else:
                    assert lams[0] > 0
                # characteristic cubic of A
                c2 = A[0, 0] + A[1, 1] + A[2, 2]
                c1 = (A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0] + A[0, 0] * A[2, 2] - A[0, 2] * A[2, 0]
                      + A[1, 1] * A[2, 2] - A[1, 2] * A[2, 1])
                c0 = mp.det(A)
                roots = sorted([mp.re(x) for x in mp.polyroots([1, -c2, c1, -c0], maxsteps=200, extraprec=2 * mp.dps)])
                for l, rt in zip(lams, roots):
                    if l == 0:
                        assert abs(rt) < mpf(10) ** (-(mp.dps - 8)) * c2, (n, rt)
                    else:
                        assert rel(l, rt) < mpf(10) ** (-(mp.dps - 8)), (n, l, rt)
                # n = 0 closed forms
                if n == 0:
                    br = sqrt(ring.Ep / (ring.rho * ring.R ** 2))
                    sh = sqrt(ring.ks * ring.G / ring.rho * (1 / ring.R ** 2 + 12 / ring.h ** 2))
                    assert rel(om[1], br) < mpf(10) ** (-(mp.dps - 5)) and rel(om[2], sh) < mpf(10) ** (-(mp.dps - 5))
            res["frequencies"][(hs, ms)] = fr
            # ---------- classical ----------
            Ep, h, rho, R = ring.Ep, ring.h, ring.rho, ring.R
            cl = {"breathing": Ep / (rho * R ** 2), "flex": {}, "ext": {}}
            for n in CLASSICAL_N:
                n2 = mpf(n) ** 2
                cl["flex"][n] = Ep * h ** 2 / (12 * rho * R ** 4) * n2 * (n2 - 1) ** 2 / (n2 + 1)
                cl["ext"][n] = Ep / (rho * R ** 2) * (1 + n2)
            res["classical"][(hs, ms)] = cl
            log_err(f"    n=2..8 lowest omega / classical inextensional: "
                    + ", ".join(mp.nstr(fr[n][0] / sqrt(cl['flex'][n]), 8) for n in CLASSICAL_N))
            log_err(f"    n=2..8 middle omega / classical extensional:   "
                    + ", ".join(mp.nstr(fr[n][1] / sqrt(cl['ext'][n]), 8) for n in CLASSICAL_N))

        # ---------- step response ----------
        ring = Ring(*STEP_CASE)
        st = {}
        max_halving = mpf(0)
        max_modal = mpf(0)
        for n in STEP_N:
            M, K, A, lams, phis = ring.eig(n)
            f = [-ring.cn(n), mpf(0), mpf(0)]
            if n == 0:
                # torsional pair is singular (rigid rotation) and unloaded; breathing decouples
                assert K[0, 1] == 0 and K[0, 2] == 0
                static = -f[0] / K[0, 0]
            else:
                static = -mp_lu_solve(K, f)[0]
            om_max = sqrt(lams[-1])
            runs = {}
            orders = {}
            for spu in STEP_DT:
                out, P = taylor_integrate(M, K, f, STEP_TIMES, spu, om_max)
                runs[spu] = {ts: -out[ts][0] for ts in STEP_TIMES}
                orders[spu] = P
            modal = {ts: -modal_response(lams, phis, f, mpf(ts))[0] for ts in STEP_TIMES}
            hv = max(rel(runs[STEP_DT[0]][ts], runs[STEP_DT[1]][ts]) for ts in STEP_TIMES)
            mv = max(rel(runs[STEP_DT[1]][ts], modal[ts]) for ts in STEP_TIMES)
            max_halving = max(max_halving, hv)
            max_modal = max(max_modal, mv)
            # static from modes: sum phi_W (phi.f)/omega^2
            stat_modal = -sum(ph[0] * ph[0] * f[0] / l for l, ph in zip(lams, phis) if l != 0)
            assert rel(static, stat_modal) < mpf(10) ** (-(mp.dps - 8))
            log_err(f"[dps {dps}] step n={n}: Taylor order {orders}, halving rel diff {mp.nstr(hv, 3)},"
                    f" Taylor vs modal {mp.nstr(mv, 3)}, static {mp.nstr(static, 15)}")
            st[n] = {"values": runs[STEP_DT[1]], "coarse": runs[STEP_DT[0]], "modal": modal,
                     "static": static, "orders": orders, "halving": hv, "modal_diff": mv}
        res["step"] = st
        res["diag"]["step_halving"] = max_halving
        res["diag"]["step_modal"] = max_modal

        # ---------- point load ----------
        f = [mpf(-1), mpf(0), mpf(0)]
        ts_list = [mpf(t) for t in POINT_TIMES]
        partial = {ts: mpf(0) for ts in POINT_TIMES}
        sums = {}
        contrib = {}
        for n in range(0, max(POINT_N) + 1):
            M, K, A, lams, phis = ring.eig(n)
            for ts, t in zip(POINT_TIMES, ts_list):
                c = -modal_response(lams, phis, f, t, skip_zero=True)[0]
                partial[ts] += c
                if n in POINT_CONTRIB_N:
                    contrib.setdefault(n, {})[ts] = c
            if n == 1:
                # cross-check: direct integration of n = 1 minus the rigid translation
                out, P = taylor_integrate(M, K, f, POINT_TIMES, STEP_DT[0], sqrt(lams[-1]))
                r = [mpf(1), mpf(-1), mpf(0)]
                rMr = sum(M[i, i] * r[i] ** 2 for i in range(3))
                for ts, t in zip(POINT_TIMES, ts_list):
                    rigid_W = r[0] * (sum(r[i] * f[i] for i in range(3)) / rMr) * t ** 2 / 2
                    el = -(out[ts][0] - rigid_W)
                    assert rel(el, contrib[1][ts]) < mpf(10) ** (-(mp.dps - 10)), (ts, el, contrib[1][ts])
                log_err(f"[dps {dps}] point load n=1 elastic part: direct integration minus rigid motion"
                        f" agrees with modal sum (Taylor order {P})")
            if n in POINT_N:
                sums[n] = dict(partial)
        res["point"] = {"sums": sums, "contrib": contrib}
    return res


def flatten(res):
    """All reported quantities as {path: mpf} for run-to-run comparison."""
    flat = {}
    for k, fr in res["frequencies"].items():
        for n, om in fr.items():
            for i, x in enumerate(om):
                flat[("freq", k, n, i)] = x
    for k, cl in res["classical"].items():
        flat[("cl", k, "b")] = cl["breathing"]
        for n in CLASSICAL_N:
            flat[("cl", k, "f", n)] = cl["flex"][n]
            flat[("cl", k, "e", n)] = cl["ext"][n]
    for n, s in res["step"].items():
        flat[("st", n, "static")] = s["static"]
        for ts in STEP_TIMES:
            flat[("st", n, ts)] = s["values"][ts]
            flat[("stm", n, ts)] = s["modal"][ts]
    for N, s in res["point"]["sums"].items():
        for ts in POINT_TIMES:
            flat[("pt", N, ts)] = s[ts]
    for n, s in res["point"]["contrib"].items():
        for ts in POINT_TIMES:
            flat[("pc", n, ts)] = s[ts]
    return flat


def main():
    t0 = time.time()
    res = compute(BASE_DPS)
    log_err(f"base run (dps {BASE_DPS}) took {time.time() - t0:.1f} s")
    t1 = time.time()
    chk = compute(CHECK_DPS)
    log_err(f"check run (dps {CHECK_DPS}) took {time.time() - t1:.1f} s")
    mp.dps = CHECK_DPS + GUARD
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
          f"dps {BASE_DPS} vs dps {CHECK_DPS}: max relative difference {mp.nstr(worst, 3)}")
    check(res["diag"]["step_halving"] < mpf(10) ** -20,
          f"step halving dt=1/100 vs 1/200: max relative difference {mp.nstr(res['diag']['step_halving'], 3)}")
    check(res["diag"]["step_modal"] < mpf(10) ** -20,
          f"Taylor integration vs closed-form modal: max relative difference {mp.nstr(res['diag']['step_modal'], 3)}")
    mp.dps = BASE_DPS

    conventions = (
        "Dimensionless: lengths/R, time/(R/c1), stresses/(rho_s c1^2); R = rho_s = c1 = 1, "
        "E' = 4 m^2 (1 - m^2), G = m^2, k_s = 5/6, m = c2/c1; parameters h/R and m. "
        "theta from the contact point; w radial displacement positive OUTWARD, v circumferential "
        "positive towards +theta, psi cross-section rotation; eps = (v_theta + w)/R, kappa = psi_theta/R, "
        "gamma = psi + (w_theta - v)/R; U = 1/2 Int [E'h eps^2 + E'h^3/12 kappa^2 + k_s G h gamma^2] R dtheta, "
        "T = 1/2 Int rho_s [h (w_t^2 + v_t^2) + h^3/12 psi_t^2] R dtheta. Pressure q positive INWARD "
        "(virtual work -Int q dw R dtheta); point line force P inward at theta = 0 is q = (P/R) delta(theta). "
        "Harmonic n: w = W cos n theta, v = V sin n theta, psi = Psi sin n theta (n = 0: constants), "
        "q = (W, V, Psi), M q'' + K q = f. Frequencies are omega R/c1, sorted ascending, exact zeros "
        "(n = 0 rigid rotation, n = 1 rigid translation) written as \"0\". Displacements are the INWARD "
        "radial displacement at theta = 0, -w(0, t), in units of R, for unit load amplitude (pressure "
        "rho_s c1^2, line force rho_s c1^2 R), load applied as a step H(t) from rest. "
        f"Values at mp.dps = {BASE_DPS} with {GUARD} guard digits, {SIG} significant digits, all agree "
        f"with a mp.dps = {CHECK_DPS} rerun. Every number is a string."
    )

    out = {
        "description": ("Independent mpmath reference for a Timoshenko ring (plane-strain thin cylindrical "
                        "shell with membrane, bending, transverse shear and rotary inertia) under radial "
                        "contact pressure. Generated by tests/reference/shell_mpmath.py."),
        "conventions": conventions,
        "parameters": {"k_s": "5/6", "mp_dps": str(BASE_DPS), "guard_digits": str(GUARD),
                       "check_dps": str(CHECK_DPS), "significant_digits": str(SIG)},
        "matrices": (
            "c_n = pi R (n >= 1), 2 pi R (n = 0); a = (1, n, 0), b = (-n/R, -1/R, 1); "
            "K = c_n [(E' h/R^2) a a^T + (E' h^3 n^2/(12 R^2)) e3 e3^T + k_s G h b b^T]; "
            "M = c_n rho_s h diag(1, 1, h^2/12); pressure Q cos(n theta): f = (-c_n Q, 0, 0); "
            "line force P at theta = 0: f = (-P, 0, 0) for every n."),
    }

    freq = {}
    for hs, ms in FREQ_CASES:
        ring = Ring(hs, ms)
        fr = res["frequencies"][(hs, ms)]
        d = {"h_over_R": hs, "m": ms, "E_prime": fmt(ring.Ep), "G": fmt(ring.G),
             "by_n": {str(n): [fmt(x) for x in fr[n]] for n in FREQ_N},
             "n0_labels": ["torsional rigid rotation (0)", "breathing", "torsional thickness-shear"],
             "n1_note": "first entry is the rigid translation (0)"}
        freq[f"h{hs}_m{ms}"] = d
    out["frequencies"] = freq

    classical = {}
    for hs, ms in FREQ_CASES:
        cl = res["classical"][(hs, ms)]
        classical[f"h{hs}_m{ms}"] = {
            "h_over_R": hs, "m": ms,
            "breathing_n0": {"omega2": fmt(cl["breathing"]), "omega": fmt(sqrt(cl["breathing"]))},
            "inextensional_flexural": {str(n): {"omega2": fmt(cl["flex"][n]), "omega": fmt(sqrt(cl["flex"][n]))}
                                       for n in CLASSICAL_N},
            "extensional": {str(n): {"omega2": fmt(cl["ext"][n]), "omega": fmt(sqrt(cl["ext"][n]))}
                            for n in CLASSICAL_N},
            "formulas": ("inextensional: omega^2 = E' h^2/(12 rho_s R^4) n^2 (n^2-1)^2/(n^2+1); "
                         "breathing: omega^2 = E'/(rho_s R^2); extensional: omega^2 = E'/(rho_s R^2) (1+n^2)"),
        }
    out["classical"] = classical

    st = res["step"]
    out["step_response"] = {
        "h_over_R": STEP_CASE[0], "m": STEP_CASE[1],
        "load": "q(theta, t) = H(t) cos(n theta), unit amplitude, inward; start at rest",
        "quantity": "-w(0, t) (inward radial displacement at theta = 0), units of R",
        "method": ("fixed-step Taylor-series integration of M q'' + K q = f; values from dt = 1/200; "
                   "checked against dt = 1/100 and against the closed-form modal solution"),
        "times": STEP_TIMES,
        "by_n": {str(n): {
            "minus_w0": {ts: fmt(st[n]["values"][ts]) for ts in STEP_TIMES},
            "static_minus_w0": fmt(st[n]["static"]),
            "taylor_order": {f"dt=1/{k}": str(v) for k, v in st[n]["orders"].items()},
            "halving_max_rel_diff": mp.nstr(st[n]["halving"], 3),
            "modal_max_rel_diff": mp.nstr(st[n]["modal_diff"], 3),
        } for n in STEP_N},
        "halving_max_rel_diff": mp.nstr(res["diag"]["step_halving"], 3),
    }

    pt = res["point"]
    out["point_load"] = {
        "h_over_R": STEP_CASE[0], "m": STEP_CASE[1],
        "load": "unit inward line force P = 1 at theta = 0, step H(t), start at rest",
        "quantity": ("-w(0, t) of the deformation only: harmonics n = 0, 2..N plus the two elastic "
                     "(non-zero frequency) modes of n = 1; the rigid translation mode is excluded"),
        "method": "modal superposition, mass-normalised modes, F (1 - cos omega t)/omega^2 per mode",
        "times": POINT_TIMES,
        "by_N": {str(N): {ts: fmt(pt["sums"][N][ts]) for ts in POINT_TIMES} for N in POINT_N},
        "harmonic_contributions": {str(n): {ts: fmt(pt["contrib"][n][ts]) for ts in POINT_TIMES}
                                   for n in POINT_CONTRIB_N},
        "contributions_note": "n = 1 entry is the elastic part only",
    }
    json.dump(out, sys.stdout, indent=1)
    sys.stdout.write("\n")
    log_err(f"total {time.time() - t0:.1f} s")


if __name__ == "__main__":
    main()
