//! Influence coefficients of the uniform space-time grid (`docs/impact.md`, section 2).
//!
//! Cells [x_j - dx/2, x_j + dx/2] x [t_{m-1}, t_m], x_j = j dx, t_m = m dt, kappa = c1 dt/dx,
//! a unit pressure constant on a cell. The contact condition is imposed on the **mean** of the
//! normal surface displacement over each contact cell at the end of each step (Galerkin in
//! space, collocation at t_n in time): A(i - j, n - m) is the mean over cell i at t_n of the
//! displacement due to cell j loaded over step m. With Phi(X, T) the Lamb crate's space-time
//! primitive (`lamb::cells`) and
//!
//! ```text
//!   Xi(X, T) = Int_0^X Phi(X', T) dX'   (even in X),
//!   A(k, l) = (1/dx) [D Xi(t_{l+1}) - D Xi(t_l)],   D Xi = Xi(k + 1) - 2 Xi(k) + Xi(k - 1)
//! ```
//!
//! (X in cells). The mean displacement is the work-conjugate of a piecewise-constant
//! pressure, so the discrete energy input sum_n p_n . (wbar_n - wbar_{n-1}) is exactly the
//! work done on the half-plane, which is never negative: the march has no growing modes.
//! Point collocation at the cell centres has them (a mode about 2.4 cells long grows by about
//! 3 % a step for kappa = 2, whatever kappa; `docs/impact.md`, section 2).
//!
//! Xi is in closed form (`lamb::HalfPlane::cell_mean_primitive_zz`: Phi integrated by parts
//! twice into the moments M_1, M_0 and M_{-1} of the impulse response), so a table value costs
//! three moment evaluations and no quadrature crosses a wave arrival; the test module keeps
//! the quadrature of Phi over X (split at the arrivals, clustered Gauss-Legendre) as the second
//! route.
//!
//! Phi, hence Xi, is homogeneous (of degree 1, 2), so A = dx a(k, l) with a depending on kappa
//! and the material only: one table serves every grid of the same kappa (the refinement
//! levels). Units c1 = 1, mu = 1.

use complexfn::quadrature::{gauss_legendre_rule, CachedRules};
use lamb::HalfPlane;

use crate::error::Result;
use crate::scalar::Scalar;

/// Gauss-Legendre size of the rule for pieces clustered at their ends (the free edge's shape
/// correction, `march`).
const RULE_FINE: usize = 24;
/// Gauss-Legendre size of the rule for smooth pieces.
const SMOOTH_FINE: usize = 7;

/// Gauss-Legendre rules on [-1, 1] for pieces clustered at their ends and for smooth pieces.
/// With them, the far cells' kernel rows by distance (`march::far_kernel_row`).
pub(crate) type ShapeRules<'r, T = f64> = (
    &'r [(T, T)],
    &'r [(T, T)],
    &'r [[T; crate::march::FAR_SERIES]],
);

/// The normalised coefficients a(k, l) (dx = 1), grown on demand in k and l.
pub struct Tables<T = f64> {
    kappa: T,
    half_plane: HalfPlane<T>,
    /// xi[l][j] = Xi(j, l kappa) (dx = 1), j = 0, 1, ...
    xi: Vec<Vec<T>>,
    /// The largest error estimate of a value of each row of `xi`.
    xi_err: Vec<f64>,
    /// a[l][k] for l = 0 .. xi.len() - 2.
    a: Vec<Vec<T>>,
    /// Largest absolute error estimate of a coefficient so far.
    err: f64,
    /// The Gauss-Legendre rules on [-1, 1] of the shape correction.
    fine: std::sync::Arc<Vec<(T, T)>>,
    smooth_fine: std::sync::Arc<Vec<(T, T)>>,
    /// The shape defect's far-cell kernel, row d for a source cell d cells beyond the
    /// receiving one (`march::far_kernel_row`), grown with the coefficients.
    far_kernel: Vec<[T; crate::march::FAR_SERIES]>,
}

impl<T: Scalar + CachedRules> Tables<T> {
    /// Tables for the half-plane `half_plane` (units c1 = 1) and kappa = c1 dt/dx.
    pub fn new(half_plane: HalfPlane<T>, kappa: T) -> Result<Self> {
        Ok(Tables {
            kappa,
            half_plane,
            xi: vec![Vec::new()],
            xi_err: vec![0.0],
            a: Vec::new(),
            err: 0.0,
            fine: gauss_legendre_rule::<T>(RULE_FINE, T::BITS).map_err(lamb::LambError::from)?,
            smooth_fine: gauss_legendre_rule::<T>(SMOOTH_FINE, T::BITS)
                .map_err(lamb::LambError::from)?,
            far_kernel: Vec::new(),
        })
    }

    /// The half-plane.
    pub fn half_plane(&self) -> &HalfPlane<T> {
        &self.half_plane
    }

    /// The clustered and the smooth pieces' finer Gauss-Legendre rules on [-1, 1], shared with
    /// the march's shape correction of the free edge.
    pub(crate) fn shape_rules(&self) -> ShapeRules<'_, T> {
        (&self.fine, &self.smooth_fine, &self.far_kernel)
    }

    /// The largest absolute error estimate of a normalised coefficient computed so far.
    pub fn error(&self) -> f64 {
        self.err
    }

    /// Xi(X, T) (dx = 1) in closed form (`lamb::HalfPlane::cell_mean_primitive_zz`) and its
    /// absolute error estimate.
    fn xi_at(&self, x: T, t: T) -> Result<(T, f64)> {
        let e = self.half_plane.cell_mean_primitive_zz(&x, &t)?;
        Ok((e.value, e.error))
    }

    /// Makes a(k, l) available for k <= kmax and l <= lmax.
    pub fn ensure(&mut self, kmax: usize, lmax: usize) -> Result<()> {
        // the far kernel's rows for every distance within kmax + 1 cells (row 0 unused)
        for d in self.far_kernel.len()..=kmax + 1 {
            self.far_kernel.push(crate::march::far_kernel_row(d.max(1)));
        }
        // Xi at j = 0 ..= kmax + 1
        let width = kmax + 2;
        while self.xi.len() < lmax + 2 {
            self.xi.push(Vec::new());
            self.xi_err.push(0.0);
        }
        for l in 0..self.xi.len() {
            let have = self.xi[l].len();
            if have >= width {
                continue;
            }
            let t = self.kappa * l as f64;
            let mut worst = self.xi_err[l];
            for j in have..width {
                let (v, e) = if l == 0 || j == 0 {
                    (T::of(0.0), 0.0)
                } else {
                    self.xi_at(T::of(j as f64), t)?
                };
                worst = worst.max(e);
                self.xi[l].push(v);
            }
            // a coefficient takes eight values of Xi
            self.err = self.err.max(8.0 * worst);
            self.xi_err[l] = worst;
        }
        while self.a.len() < lmax + 1 {
            self.a.push(Vec::new());
        }
        for l in 0..self.a.len() {
            let have = self.a[l].len();
            if have > kmax {
                continue;
            }
            for k in have..=kmax {
                // mean over the receiver cell k of the displacement due to the source cell 0:
                // Xi(k + 1) - 2 Xi(k) + Xi(k - 1), Xi even in X
                let d2 = |row: &Vec<T>| -> T {
                    let left = if k == 0 { row[1] } else { row[k - 1] };
                    row[k + 1] - row[k] * 2.0 + left
                };
                // causality: nothing reaches cell k by t_{l+1} when its nearest point is
                // beyond c1 t_{l+1} (the differences of Xi would leave rounding there)
                let v = if k > self.reach_at(l) {
                    T::of(0.0)
                } else {
                    d2(&self.xi[l + 1]) - d2(&self.xi[l])
                };
                self.a[l].push(v);
            }
        }
        Ok(())
    }

    /// The largest k with a(k, l) not zero: the source cell's load over step l reaches the
    /// receiver cell k only if the cells' nearest points are closer than c1 t_{l+1}
    /// (k - 1 < (l + 1) kappa). At l = 0 it is the half-bandwidth of the step's system.
    pub fn reach_at(&self, l: usize) -> usize {
        ((l + 1) as f64 * self.kappa.to_f64()).ceil() as usize
    }

    /// The row a(., l) (dx = 1), available up to the k given to [`Tables::ensure`].
    pub fn row(&self, l: usize) -> &[T] {
        &self.a[l]
    }

    /// The rows computed so far: a(., l) for l below it.
    pub fn rows(&self) -> usize {
        self.a.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lamb::cells::{Cell, TimeShape};

    type Rule = std::sync::Arc<Vec<(f64, f64)>>;

    /// The second route to Xi: Gauss-Legendre quadrature of the closed-form Phi over each
    /// unit interval, split at the wave arrivals, with quadratic clustering at the pieces'
    /// ends (the arrivals are weak singularities of Phi: x log x at the Rayleigh ray,
    /// fractional powers at the fronts), two rule sizes compared for the error.
    struct Quadrature {
        hp: HalfPlane<f64>,
        clust: (Rule, Rule),
        smooth: (Rule, Rule),
    }

    impl Quadrature {
        fn new(hp: HalfPlane<f64>) -> Self {
            let r = |n| gauss_legendre_rule::<f64>(n, 53).unwrap();
            Quadrature {
                hp,
                clust: (r(24), r(16)),
                smooth: (r(7), r(5)),
            }
        }

        /// Xi(j, t) (dx = 1) as the sum over the unit intervals, with its error estimate.
        fn xi(&self, j: usize, t: f64) -> (f64, f64) {
            let (mut v, mut e) = (0.0, 0.0);
            for q in 0..j {
                let (a, b) = self.interval(q as f64, (q + 1) as f64, t).unwrap();
                v += a;
                e += b;
            }
            (v, e)
        }

        /// Phi(x, t) (normal displacement, normal load) and its error estimate.
        fn phi(&self, x: f64, t: f64) -> Result<(f64, f64)> {
            let e = self.hp.space_time_primitive(1, &x, &t)?.zz;
            Ok((e.value, e.error))
        }

        /// Int_a^b Phi(x, t) dx by two rules (sizes `RULE_FINE`, `RULE_COARSE`) after the
        /// substitution x = end + (mid - end) u^2 from each end (quadratic clustering, for a
        /// piece ending on a wave arrival or at X = 0), with the rules' difference as the error.
        fn clustered(&self, a: f64, b: f64, t: f64) -> Result<(f64, f64)> {
            let mid = 0.5 * (a + b);
            let mut vals = [0.0; 2];
            let mut round = 0.0;
            for (r, rule) in [&*self.clust.0, &*self.clust.1].into_iter().enumerate() {
                let mut s = 0.0;
                for (end, dir) in [(a, mid - a), (b, mid - b)] {
                    for (u, w) in rule.iter() {
                        let u = 0.5 * (u + 1.0);
                        let (v, e) = self.phi(end + dir * u * u, t)?;
                        // dx = 2 dir u du, du = dU/2 on [-1, 1]
                        let jac = w * dir.abs() * u;
                        s += v * jac;
                        if r == 0 {
                            round += e * jac;
                        }
                    }
                }
                vals[r] = s;
            }
            Ok((vals[0], (vals[0] - vals[1]).abs() + round))
        }

        /// Int_a^b Phi(x, t) dx for a piece with no wave arrival inside, with its error estimate.
        /// Beyond the P front (a >= t) Phi does not depend on X; a piece away from the arrivals
        /// and from X = 0 takes the plain rules (Phi is analytic there), unless their difference
        /// exceeds `SMOOTH_TOL` relative to the piece, when the clustered rules are used.
        fn piece(&self, a: f64, b: f64, t: f64) -> Result<(f64, f64)> {
            if a >= t {
                let (v, e) = self.phi(a, t)?;
                return Ok((v * (b - a), e * (b - a)));
            }
            let hp = &self.hp;
            let arrivals = [0.0, *hp.s_r() * t, *hp.m() * t, t];
            let near = |x: f64| {
                arrivals
                    .iter()
                    .any(|&q| (x - q).abs() <= 1e-12 * t.max(1.0))
            };
            if !near(a) && !near(b) {
                let (half, mid) = (0.5 * (b - a), 0.5 * (a + b));
                let mut vals = [0.0; 2];
                let mut round = 0.0;
                for (r, rule) in [&*self.smooth.0, &*self.smooth.1].into_iter().enumerate() {
                    let mut s = 0.0;
                    for (u, w) in rule.iter() {
                        let (v, e) = self.phi(mid + half * u, t)?;
                        s += v * w * half;
                        if r == 0 {
                            round += e * w * half;
                        }
                    }
                    vals[r] = s;
                }
                let err = (vals[0] - vals[1]).abs();
                if err <= 1e-13 * vals[0].abs().max(round) {
                    return Ok((vals[0], err + round));
                }
            }
            self.clustered(a, b, t)
        }

        /// Int_lo^hi Phi(x, t) dx, split at the wave arrivals s_R t, c2 t, c1 t.
        fn interval(&self, lo: f64, hi: f64, t: f64) -> Result<(f64, f64)> {
            let hp = &self.hp;
            let mut pts = [lo, 0.0, 0.0, 0.0, hi];
            let mut n = 1;
            let mut arrivals = [*hp.s_r() * t, *hp.m() * t, t];
            arrivals.sort_by(f64::total_cmp);
            for b in arrivals {
                if b > lo && b < hi {
                    pts[n] = b;
                    n += 1;
                }
            }
            pts[n] = hi;
            let (mut v, mut e) = (0.0, 0.0);
            for w in pts[..=n].windows(2) {
                let (pv, pe) = self.piece(w[0], w[1], t)?;
                v += pv;
                e += pe;
            }
            Ok((v, e))
        }
    }

    /// The closed-form Xi against the quadrature of Phi over X, at every region of s =
    /// X/T (ahead of P, between the fronts, around the Rayleigh ray, late times), for three
    /// materials (nu = 0.25, 0.3 and 0.45, where s_R nears c2).
    #[test]
    fn closed_form_xi_is_the_quadrature_of_phi() {
        for nu in [0.25, 0.3, 0.45] {
            let hp = HalfPlane::from_poisson(nu).unwrap();
            let quad = Quadrature::new(hp.clone());
            let mut worst: f64 = 0.0;
            for t in [0.5, 1.0, 2.0, 3.7, 6.0, 25.0, 200.0, 2000.0] {
                for j in [1usize, 2, 3, 5, 8, 13, 40] {
                    let (want, qerr) = quad.xi(j, t);
                    let got = hp.cell_mean_primitive_zz(&(j as f64), &t).unwrap();
                    let diff = (got.value - want).abs();
                    let scale = want.abs().max(1e-300);
                    worst = worst.max(diff / scale);
                    assert!(
                        diff <= 10.0 * (qerr + got.error) + 1e-13 * scale,
                        "nu {nu}, Xi({j}, {t}) = {} closed form, {want} by quadrature (errors {:e}, {qerr:e})",
                        got.value,
                        got.error
                    );
                    assert!(
                        got.error <= 1e-11 * scale,
                        "nu {nu}, Xi({j}, {t}): stated {:e} of {scale:e}",
                        got.error
                    );
                }
            }
            println!("nu {nu}: largest relative difference {worst:e}");
        }
    }

    /// The coefficients a(k, l) from the closed-form Xi against those from the quadrature of
    /// Phi, over 40 cells and 600 steps at kappa = 2 (lags to c1 t = 1200 dx, where the
    /// second differences cancel most): within the stated errors of both routes.
    #[test]
    fn coefficients_from_the_closed_form_equal_those_from_quadrature() {
        let (kappa, kmax, lmax) = (2.0, 40usize, 600usize);
        let t = tables(kappa, kmax, lmax);
        let quad = Quadrature::new(t.half_plane().clone());
        let mut worst: f64 = 0.0;
        for l in [0usize, 1, 2, 5, 17, 60, 200, 599] {
            let xi = |ll: usize| -> Vec<(f64, f64)> {
                (0..=kmax + 1)
                    .map(|j| quad.xi(j, ll as f64 * kappa))
                    .collect()
            };
            let (lo, hi) = (xi(l), xi(l + 1));
            for k in [0usize, 1, 3, 10, 25, 40] {
                let d2 = |row: &[(f64, f64)]| -> (f64, f64) {
                    let left = if k == 0 { row[1] } else { row[k - 1] };
                    (
                        row[k + 1].0 - 2.0 * row[k].0 + left.0,
                        row[k + 1].1 + 2.0 * row[k].1 + left.1,
                    )
                };
                let ((a1, e1), (a0, e0)) = (d2(&hi), d2(&lo));
                let want = a1 - a0;
                let got = t.row(l)[k];
                let d = (got - want).abs();
                assert!(
                    d <= 2.0 * (e1 + e0 + t.error()),
                    "a({k}, {l}) = {got} closed form, {want} quadrature ({d:e}; errors {:e}, {:e})",
                    e1 + e0,
                    t.error()
                );
                if want.abs() > 1e-12 {
                    worst = worst.max(d / want.abs());
                }
            }
        }
        println!(
            "largest relative difference {worst:e}, stated table error {:e}",
            t.error()
        );
        assert!(t.error() < 1e-9, "table error {:e}", t.error());
    }

    fn tables(kappa: f64, kmax: usize, lmax: usize) -> Tables {
        let hp = HalfPlane::from_poisson(0.3).unwrap();
        let mut t = Tables::new(hp, kappa).unwrap();
        t.ensure(kmax, lmax).unwrap();
        t
    }

    /// A second route: the mean over the receiver cell of the Lamb crate's point response to
    /// a loaded cell, by a many-point midpoint rule (the point response has only integrable
    /// singularities, so the rule converges, slowly).
    #[test]
    fn coefficients_are_receiver_means_of_the_point_response() {
        let kappa = 2.0;
        let t = tables(kappa, 6, 6);
        let hp = t.half_plane().clone();
        let cell = Cell {
            xa: -0.5,
            xb: 0.5,
            ta: 0.0,
            tb: kappa,
        };
        let n = 4000;
        for (k, l) in [(0, 0), (1, 0), (0, 3), (2, 2), (5, 4), (3, 6)] {
            // load on the first step, receiver at the end of step l + 1
            let tr = (l + 1) as f64 * kappa;
            let mut s = 0.0;
            for q in 0..n {
                let x = k as f64 - 0.5 + (q as f64 + 0.5) / n as f64;
                s += hp
                    .cell_response(&cell, TimeShape::Constant, &x, &tr)
                    .unwrap()
                    .zz
                    .value;
            }
            let want = s / n as f64;
            let got = t.row(l)[k];
            assert!(
                (got - want).abs() < 2e-5 * want.abs().max(0.01),
                "a({k}, {l}) = {got}, receiver mean {want}"
            );
        }
        assert!(t.error() < 1e-9, "table error estimate {}", t.error());
    }

    /// Cholesky factorisation of a symmetric matrix (row-major, n x n); false when a pivot is
    /// not positive.
    fn positive_definite(mut s: Vec<f64>, n: usize) -> bool {
        for c in 0..n {
            for r in 0..c {
                let mut v = s[c * n + r];
                for q in 0..r {
                    v -= s[c * n + q] * s[r * n + q];
                }
                s[c * n + r] = v / s[r * n + r];
            }
            let mut d = s[c * n + c];
            for q in 0..c {
                d -= s[c * n + q] * s[c * n + q];
            }
            if !(d > 0.0) {
                return false;
            }
            s[c * n + c] = d.sqrt();
        }
        true
    }

    /// The discrete energy input sum_n p_n . (wbar_n - wbar_{n-1}) of any pressure history
    /// (cells 0..N, steps 1..M) is the work done on the half-plane, never negative: the
    /// symmetric part of its matrix is positive semi-definite. (With point collocation at the
    /// cell centres it is not: its smallest eigenvalue is -0.062 for 32 cells and 40 steps at
    /// kappa = 2, which is why that march has growing modes.)
    #[test]
    fn discrete_energy_input_is_never_negative() {
        for (kappa, nc, ns) in [(2.0, 32, 40), (1.0, 16, 30), (4.0, 16, 30)] {
            let t = tables(kappa, nc, ns);
            let n = nc * ns;
            let a = |k: usize, l: i64| if l < 0 { 0.0 } else { t.row(l as usize)[k] };
            let mut b = vec![0.0; n * n];
            for sn in 0..ns {
                for sm in 0..=sn {
                    for i in 0..nc {
                        for j in 0..nc {
                            let k = i.abs_diff(j);
                            let l = (sn - sm) as i64;
                            b[(sn * nc + i) * n + sm * nc + j] = a(k, l) - a(k, l - 1);
                        }
                    }
                }
            }
            let mut s = vec![0.0; n * n];
            for r in 0..n {
                for c in 0..n {
                    // a small shift: the form is only semi-definite in the limit
                    s[r * n + c] =
                        0.5 * (b[r * n + c] + b[c * n + r]) + if r == c { 1e-9 } else { 0.0 };
                }
            }
            assert!(positive_definite(s, n), "kappa = {kappa}");
        }
    }

    /// The tables in double-double against the same coefficients from the Lamb crate's Xi on
    /// MPFR at 200 bits (a second precision), and the f64 tables against them at f64's
    /// rounding: nu = 0.25, kappa = 2, the lags and offsets of a short march.
    #[test]
    fn double_double_tables_agree_with_mpfr() {
        use complexfn::{Dd, Real};
        use rug::Float;
        let bits = 200;
        let nu = 0.25;
        let hp_mp = HalfPlane::from_poisson(Float::with_val(bits, nu)).unwrap();
        let kappa = 2.0;
        let xi = |j: usize, l: usize| -> Float {
            if j == 0 || l == 0 {
                return Float::with_val(bits, 0);
            }
            let (x, t) = (
                Float::with_val(bits, j),
                Float::with_val(bits, l as f64 * kappa),
            );
            hp_mp.cell_mean_primitive_zz(&x, &t).unwrap().value
        };
        let d2 = |k: usize, l: usize| -> Float {
            let left = if k == 0 { xi(1, l) } else { xi(k - 1, l) };
            xi(k + 1, l) - Float::with_val(bits, 2) * xi(k, l) + left
        };
        let (kmax, lmax) = (12, 6);
        let mut dd =
            Tables::new(HalfPlane::from_poisson(Dd::of(nu)).unwrap(), Dd::of(kappa)).unwrap();
        dd.ensure(kmax, lmax).unwrap();
        let mut f = Tables::new(HalfPlane::from_poisson(nu).unwrap(), kappa).unwrap();
        f.ensure(kmax, lmax).unwrap();
        let (mut worst_dd, mut worst_f) = (0.0f64, 0.0f64);
        for l in 0..=lmax {
            for k in 0..=kmax {
                let want = if k > f.reach_at(l) {
                    Float::with_val(bits, 0)
                } else {
                    d2(k, l + 1) - d2(k, l)
                };
                let got = dd.row(l)[k].to_mpfr(bits);
                worst_dd = worst_dd.max((got - &want).abs().to_f64());
                worst_f = worst_f.max((f.row(l)[k] - want.to_f64()).abs());
            }
        }
        // the coefficients are of order 0.1 to 1
        assert!(worst_dd < 1e-28, "double-double against MPFR: {worst_dd:e}");
        assert!(worst_f < 1e-13, "f64 against MPFR: {worst_f:e}");
        assert!(
            dd.error() < 1e-25,
            "double-double stated error {:e}",
            dd.error()
        );
        eprintln!(
            "largest differences: double-double {worst_dd:.1e} (stated {:.1e}), f64 {worst_f:.1e}",
            dd.error()
        );
    }
}
