//! The collocation problem: the case's data, the samples of the basis on the row rule, the
//! collocation rows of the singular integral equation, the contour functionals of the slope
//! condition and one least-squares fit.

use complexfn::{Cx, Rayleigh, Real};
use wedge::{Coupling, Indenter, Material};

use super::options::*;
use crate::basis::{Basis, Family};
use crate::error::{invalid, GenuineError, Result};
use crate::kernels::{contour_integrand, y_integral_checked, CauchySums, Lamb};
use crate::quad::{tanh_sinh_unit, tanh_sinh_unit_node, UnitNode};
use complexfn::linalg::{least_squares, Matrix};

/// Everything that defines one case (shared by the two basis sizes).
#[derive(Clone, Debug)]
pub(super) struct Problem<T> {
    pub(super) p: T,
    pub(super) beta: T,
    pub(super) gamma: T,
    pub(super) cot_theta: T,
    pub(super) ray: Rayleigh<T>,
    pub(super) lamb: Lamb<T>,
    pub(super) prec: u32,
}

/// One sample of the basis: the abscissa, p - v, the quadrature weight, the family weights
/// and the Chebyshev argument (enough to evaluate the basis at any degree).
#[derive(Clone, Debug)]
pub(super) struct Sample<T> {
    pub(super) v: T,
    pub(super) pv: T,
    pub(super) w: T,
    pub(super) fam: Vec<T>,
    pub(super) t: T,
}

/// One collocation solve.
#[derive(Clone, Debug)]
pub(super) struct Fit<T> {
    pub(super) basis: Basis<T>,
    pub(super) coef: Vec<T>,
    pub(super) v_hat: T,
    pub(super) residual: f64,
}

/// The row rule's abscissae, weights and doubled abscissae as slices (the operands of the
/// rows' slice operations).
pub(super) struct RowColumns<T> {
    pub(super) v: Vec<T>,
    pub(super) w: Vec<T>,
    pub(super) v2: Vec<T>,
}

impl<T: Real> RowColumns<T> {
    pub(super) fn new(samples: &[Sample<T>]) -> Self {
        RowColumns {
            v: samples.iter().map(|s| s.v.clone()).collect(),
            w: samples.iter().map(|s| s.w.clone()).collect(),
            v2: samples.iter().map(|s| s.v.clone() * 2.0).collect(),
        }
    }
}

/// The collocation rows of the fine fit's basis by the grid index of their point (t = k h/4):
/// a fit whose basis is a part of it (the same families, a lower degree) takes its rows at the
/// points it shares from there (the row of a basis function does not depend on the others,
/// so the columns taken are the ones it would compute). With the default options at 104 bits
/// the plateau probe shares 111 of its 214 points with the fine fit, the degrees N/2 and 3N/4
/// 54 of 86 and 86 of 126 with the two. The rows are computed once, for the union of the
/// fine fit's and the plateau probe's points, in parallel (each row is a function of its point
/// alone, so the numbers do not depend on the threads); the fits then only read them.
pub(super) struct RowCache<T> {
    pub(super) families: Vec<Family>,
    pub(super) degree: usize,
    pub(super) rows: std::collections::HashMap<i64, Vec<T>>,
}

impl<T: Real> RowCache<T> {
    /// The rows of `full` at `points`, computed by `compute` on the available threads.
    pub(super) fn new(
        full: &Basis<T>,
        points: &[(i64, T, T)],
        compute: impl Fn(&T, &T) -> Vec<T> + Sync,
    ) -> Self {
        use rayon::prelude::*;
        RowCache {
            families: full.families().to_vec(),
            degree: full.degree(),
            rows: points
                .par_iter()
                .map(|(k, x, pmx)| (*k, compute(x, pmx)))
                .collect(),
        }
    }

    /// The row of `basis` at the point of index `k`, from `compute` unless held.
    pub(super) fn row(&self, basis: &Basis<T>, k: i64, compute: impl FnOnce() -> Vec<T>) -> Vec<T> {
        if basis.families() != self.families.as_slice() || basis.degree() > self.degree {
            return compute();
        }
        match self.rows.get(&k) {
            Some(full) if basis.degree() == self.degree => full.clone(),
            Some(full) => leading_columns(full, self.degree, basis.degree()),
            None => compute(),
        }
    }
}

/// Collocation points as (k, x, p - x), t = k h/4 on the row rule's grid
/// ([`Problem::collocation_points`]).
pub(super) type CollocationPoints<T> = Vec<(i64, T, T)>;

/// The values of a basis of degree `n` taken from those of a basis of the same families and
/// degree `big` >= n (laid out a family's `big` values after another, per row): each family's
/// first n, the values a fill at degree n gives (the Chebyshev recurrence being the same).
pub(super) fn leading_columns<T: Clone>(full: &[T], big: usize, n: usize) -> Vec<T> {
    full.chunks_exact(big)
        .flat_map(|f| f[..n].iter().cloned())
        .collect()
}

/// The contour functionals of [`Problem::contour_loads`]: the load's, the coarse level's, the
/// differences' (in f64), and the y-rule's estimated absolute error.
pub(super) struct ContourLoads<T> {
    pub(super) fine: [T; 4],
    pub(super) coarse: Option<[T; 4]>,
    pub(super) diffs: Vec<[f64; 4]>,
    pub(super) err: f64,
}

/// The terms of the moment expansion of the Cauchy sums ([`crate::kernels::CauchySums`]) kept
/// at `bits` for `samples` samples: as many as the bits (enough down to |z| = 1.43 max v, where
/// r^M reaches 2^-bits at r = 1/2), but no more than an eighth of the samples (the expansion
/// then costs under a fifth of the term-by-term sums).
pub(super) fn moment_terms(bits: u32, samples: usize) -> usize {
    (bits as usize).min(samples / 8)
}

impl<T: Real> Problem<T> {
    pub(super) fn new(material: &Material, indenter: &Indenter, p: T) -> Result<Self> {
        let m = material.m(&p);
        let ray = Rayleigh::new(m.clone())?;
        let m_r = ray.m_r().clone();
        if !(p.is_finite() && p > 0.0 && p < m_r) {
            return Err(invalid(
                "p = alpha/c1",
                p.to_f64(),
                format!("(0, m_R) = (0, {})", m_r.to_f64()),
            ));
        }
        let cot_theta = indenter.cot_theta(&p);
        let gamma = indenter.gamma().to_real(&p);
        let beta = match indenter.coupling() {
            Coupling::On => -cot_theta.clone(),
            Coupling::Off => p.zero(),
        };
        let prec = p.prec();
        Ok(Problem {
            p,
            beta,
            gamma,
            cot_theta,
            ray,
            lamb: Lamb::new(m),
            prec,
        })
    }

    pub(super) fn basis(&self, degree: usize, opts: &SolveOptions) -> Basis<T> {
        let regular = opts.regular_family.unwrap_or(self.gamma > 0.0);
        Basis::new(
            self.ray.clone(),
            self.p.clone(),
            self.beta.clone(),
            self.gamma.clone(),
            degree,
            regular,
            opts.apex_lambdas.as_deref(),
        )
    }

    /// The weakest endpoint exponent e of the integrands (tails behave like offset^(e - 1)):
    /// 1/2 + Omega(p) at the edge, 1 - lambda_max at the apex, at most 1, at least 0.05.
    pub(super) fn tail_exponent(&self, basis: &Basis<T>) -> f64 {
        let edge = 0.5 + basis.omega(&self.p).to_f64();
        let ex =
            crate::apex::exponents(self.ray.m().clone(), self.beta.clone(), self.gamma.clone());
        let mut lam_max = 0.0_f64;
        for f in basis.families() {
            match f {
                Family::Root(j) => lam_max = lam_max.max(ex.lambdas[*j].to_f64()),
                Family::Fixed(l) => lam_max = lam_max.max(*l),
                Family::Log | Family::Regular => {}
            }
        }
        edge.min(1.0 - lam_max).clamp(0.05, 1.0)
    }

    pub(super) fn sample(&self, basis: &Basis<T>, v: T, pv: T, w: T) -> Sample<T> {
        let fam = basis.weights(&v, &pv);
        let t = basis.cheb_arg(&v, &pv);
        Sample { v, pv, w, fam, t }
    }

    /// The tanh-sinh rule of (0, p) behind the collocation rows, sampled.
    pub(super) fn row_samples(&self, basis: &Basis<T>, h: f64) -> Vec<Sample<T>> {
        let tmax = crate::quad::t_max_for(self.prec, self.tail_exponent(basis));
        tanh_sinh_unit(&self.p, h, tmax)
            .iter()
            .map(|u| {
                let nd = u.on(&self.p.zero(), &self.p);
                self.sample(basis, nd.from_a, nd.to_b, nd.w)
            })
            .collect()
    }

    /// The v-rule of the contour integrals at x0 in (0, p), sampled: the mixed rule of
    /// [`crate::quad::se_de_unit`] on (0, x0) and (x0, p), single-exponential at x0; with, per
    /// sample, whether it is a node of the rule of step 2h (the coarser level of the probe).
    pub(super) fn contour_samples(
        &self,
        basis: &Basis<T>,
        x0: &T,
        h: f64,
    ) -> (Vec<Sample<T>>, Vec<bool>) {
        let e = self.tail_exponent(basis);
        let unit =
            crate::quad::se_de_unit_indexed(&self.p, h, v_rule_s_max(self.prec), self.prec, e);
        let p = &self.p;
        let left = x0.clone();
        let right = p.clone() - x0;
        let mut out = Vec::with_capacity(2 * unit.len());
        let mut coarse = Vec::with_capacity(2 * unit.len());
        for (k, u) in &unit {
            coarse.extend([k % 2 == 0; 2]);
            // (0, x0): the single-exponential end is x0
            let d_x0 = u.from_a.clone() * &left;
            let d_0 = u.to_b.clone() * &left;
            let v = if d_0 < d_x0 {
                d_0.clone()
            } else {
                x0.clone() - &d_x0
            };
            out.push(self.sample(basis, v, right.clone() + &d_x0, u.w.clone() * &left));
            // (x0, p)
            let d_x0 = u.from_a.clone() * &right;
            let d_p = u.to_b.clone() * &right;
            let v = if d_x0 < d_p {
                x0.clone() + &d_x0
            } else {
                p.clone() - &d_p
            };
            out.push(self.sample(basis, v, d_p, u.w.clone() * &right));
        }
        (out, coarse)
    }

    /// The collocation points: Chebyshev points of (0, p) moved to the nearest quarter point
    /// of the t-grid of the row rule (never onto a node), as (k, x, p - x), t = k h/4.
    pub(super) fn collocation_points(&self, count: usize, h: f64) -> Vec<(i64, T, T)> {
        // positions in units of h/4
        let mut ks: Vec<i64> = (0..count)
            .map(|i| {
                let th = std::f64::consts::PI * (i as f64 + 0.5) / count as f64;
                let frac = (1.0 - th.cos()) / 2.0;
                // x/p = 1/(1 + e^(-2u)), u = (pi/2) sinh t
                let u = 0.5 * (frac / (1.0 - frac)).ln();
                let t = (2.0 * u / std::f64::consts::PI).asinh();
                let q = t / h;
                let j = q.floor();
                let r = ((q - j) * 4.0).round().clamp(1.0, 3.0);
                4 * (j as i64) + r as i64
            })
            .collect();
        ks.sort_unstable();
        ks.dedup();
        ks.into_iter()
            .filter_map(|k| {
                tanh_sinh_unit_node(&self.p, k, h / 4.0)
                    .map(|u: UnitNode<T>| (k, u.from_a * &self.p, u.to_b * &self.p))
            })
            .collect()
    }

    /// The collocation row of the singular integral equation at x in (0, p), from the sampled
    /// basis values `bv` (row-major, one row of `kk` values per sample).
    pub(super) fn sie_row(
        &self,
        basis: &Basis<T>,
        x: &T,
        pmx: &T,
        samples: &[Sample<T>],
        cols: &RowColumns<T>,
        bv: &[T],
    ) -> Vec<T> {
        let kk = basis.len();
        let (p1, p2, l_s) = self.ray.cut_values(x);
        let a1 = p1.clone().recip();
        let a2 = self.gamma.clone() * &self.beta / &p2;
        let a2x = a2.clone() / x;
        let c = self.ray.m2().clone() * l_s / (p1 * p2);
        let mut phi_x = vec![x.zero(); kk];
        basis.eval(x, pmx, &mut phi_x);
        let a12 = a1.clone() - &a2;
        let log_term = (pmx.clone() / x).ln();
        let pc = x.pi() * (self.beta.clone() + &self.gamma) * c;
        // Sum_n w_n (f_n - f_x)/(v_n - x) = Sum_n c_n B_n - f_x Sum_n w_n/(v_n - x), with
        // c_n = w_n/(v_n - x) 2v_n/(v_n + x) (a1 - a2 v_n/x): one division per sample, the
        // loops over the samples in the slice operations of the precision layer
        let zero = x.zero();
        let n = samples.len();
        let mut dv = Vec::with_capacity(n);
        let mut vpx = Vec::with_capacity(n);
        for s in samples {
            dv.push(if s.pv < s.v {
                pmx.clone() - &s.pv
            } else {
                s.v.clone() - x
            });
            vpx.push(s.v.clone() + x);
        }
        let mut t = vec![zero.clone(); n];
        T::mul_slice(&mut t, &dv, &vpx);
        // r = w/((v - x)(v + x)); Sum w/(v - x) = Sum r (v + x)
        let mut r = dv;
        T::div_slice(&mut r, &cols.w, &t);
        let mut wsum = zero.clone();
        wsum.dot_add(&r, &vpx);
        let mut g = vec![a1.clone(); n];
        T::mul_add_slice(&mut g, &cols.v, &-a2x);
        T::mul_slice(&mut t, &r, &cols.v2);
        T::mul_slice(&mut r, &t, &g);
        let mut row = vec![zero; kk];
        for (cn, b) in r.iter().zip(bv.chunks_exact(kk)) {
            T::mul_add_slice(&mut row, b, cn);
        }
        let fx_coef = log_term - wsum;
        for (r, ph) in row.iter_mut().zip(&phi_x) {
            *r += ph.clone() * &a12 * &fx_coef - ph.clone() * &pc;
        }
        row
    }

    /// (U_y, U_x, U_y', U_x') at x0 > 0 of the load whose slope h = dS/dx, times the rule's
    /// weight, is `hw[i]` at the contour sample i; with the estimated absolute error.
    pub(super) fn contour(
        &self,
        samples: &[Sample<T>],
        hw: &[T],
        x0: &T,
        tol: f64,
    ) -> ([T; 4], f64) {
        let out = self.contour_loads(samples, hw, None, &[], x0, tol);
        (out.fine, out.err)
    }

    /// [`Self::contour`] of the load `hw` together with (one y-integral, the kernels shared):
    /// * with `coarse`, the same load on the samples marked there, times 2 (the rule of step
    ///   2h of the level-doubling probe; its terms are the fine load's, summed apart);
    /// * the loads `hw + diffs[j]/v`, given through their differences from `hw` in f64, times
    ///   v (the product, not the factors, in f64: a slope times a weight next to the apex can
    ///   lie beyond f64's range): those differences are what is wanted of them (the degrees'
    ///   and the collocation sets' changes), and f64 carries them to 16 digits of themselves
    ///   (`docs/contour-sums.md`).
    ///
    /// The y-rule's convergence is tested on the load `hw` alone.
    pub(super) fn contour_loads(
        &self,
        samples: &[Sample<T>],
        hw: &[T],
        coarse: Option<&[bool]>,
        diffs: &[Vec<f64>],
        x0: &T,
        tol: f64,
    ) -> ContourLoads<T> {
        let v: Vec<T> = samples.iter().map(|s| s.v.clone()).collect();
        let (class, classes) = match coarse {
            Some(c) => (c.iter().map(|&c| usize::from(c)).collect(), 2),
            None => (vec![0; v.len()], 1),
        };
        let terms = moment_terms(self.prec, v.len());
        let vhw: Vec<T> = v.iter().zip(hw).map(|(v, h)| v.clone() * h).collect();
        let sums = CauchySums::new(&v, &class, classes, &[&vhw], terms, &self.p);
        let v64: Vec<f64> = v.iter().map(|x| x.to_f64()).collect();
        let d64: Vec<&[f64]> = diffs.iter().map(|d| d.as_slice()).collect();
        let zeros = vec![0; v.len()];
        let sums64 = CauchySums::new(&v64, &zeros, 1, &d64, moment_terms(53, v.len()), &0.0);
        let lamb64 = Lamb::new(self.lamb.m().to_f64());
        let gamma64 = self.gamma.to_f64();
        let nd = diffs.len();
        let x064 = x0.to_f64();
        let y_scale = crate::kernels::y_scale(x0);
        let (y_lo, y_hi) = (y_scale.clone() * 2f64.powi(-60), y_scale * 2f64.powi(60));
        let (vals, err) =
            y_integral_checked(x0, 8 + 4 * nd, 4, tol, self.prec, |y, z, jac, out| {
                let zinv = z.clone().recip();
                let k = self.lamb.kernels(&zinv);
                let a = sums.at(&z);
                // class 0 (or all) and class 1 (the coarse level's nodes)
                let mut all = contour_integrand(&k, &a[0], &zinv, &self.gamma, y, jac);
                if classes == 2 {
                    let c = contour_integrand(&k, &a[1], &zinv, &self.gamma, y, jac);
                    for (j, (o, ci)) in all.iter_mut().zip(c).enumerate() {
                        out[4 + j] = ci.clone() * 2.0;
                        *o += &ci;
                    }
                }
                for (o, x) in out.iter_mut().zip(all) {
                    *o = x;
                }
                // the differences on the nodes within 2^60 of the y-scale (tails below: the
                // u-integrand is bounded, and the nodes beyond carry weights under 2^-60 of
                // the rule's, far under f64's 2^-53, while f64 could not hold their y, jac)
                let inside = *y > y_lo && *y < y_hi;
                if nd > 0 && inside {
                    let (y64, jac64) = (y.to_f64(), jac.to_f64());
                    let z64 = Cx::new(x064, y64);
                    let zinv64 = z64.clone().recip();
                    let k64 = lamb64.kernels(&zinv64);
                    for (j, s) in sums64.at(&z64).iter().enumerate() {
                        let u = contour_integrand(&k64, s, &zinv64, &gamma64, &y64, &jac64);
                        for (o, x) in out[8 + 4 * j..12 + 4 * j].iter_mut().zip(u) {
                            *o = x0.lit(x);
                        }
                    }
                }
            });
        let quad = |o: &[T]| -> [T; 4] { std::array::from_fn(|j| o[j].clone()) };
        ContourLoads {
            fine: quad(&vals[0..4]),
            coarse: coarse.map(|_| quad(&vals[4..8])),
            diffs: (0..nd)
                .map(|j| std::array::from_fn(|i| vals[8 + 4 * j + i].to_f64()))
                .collect(),
            err,
        }
    }

    /// The slope values h(v) w at the samples for coefficients `coef` of `basis`.
    pub(super) fn weighted_slopes(
        &self,
        basis: &Basis<T>,
        samples: &[Sample<T>],
        coef: &[T],
    ) -> Vec<T> {
        self.weighted_slopes_many(basis, samples, &[(basis, coef)])
            .pop()
            .unwrap_or_default()
    }

    /// [`Self::weighted_slopes`] for several coefficient sets, each of a basis that is a part of
    /// `full` (the same families, at most its degree): the basis is filled once per sample at
    /// the full degree, and each set sums its own columns (the values a fill at its degree
    /// gives, the Chebyshev recurrence being the same).
    pub(super) fn weighted_slopes_many(
        &self,
        full: &Basis<T>,
        samples: &[Sample<T>],
        sets: &[(&Basis<T>, &[T])],
    ) -> Vec<Vec<T>> {
        let big = full.degree();
        debug_assert!(sets
            .iter()
            .all(|(b, _)| b.families() == full.families() && b.degree() <= big));
        let zero = self.p.zero();
        let mut buf = vec![zero.clone(); full.len()];
        let mut out = vec![Vec::with_capacity(samples.len()); sets.len()];
        for s in samples {
            full.fill(&s.fam, &s.t, &mut buf);
            for ((b, coef), o) in sets.iter().zip(out.iter_mut()) {
                let n = b.degree();
                let mut acc = zero.clone();
                for (vals, c) in buf.chunks_exact(big).zip(coef.chunks_exact(n)) {
                    acc.dot_add(&vals[..n], c);
                }
                o.push(acc * &s.w);
            }
        }
        out
    }

    /// The values of `basis` at the row samples, one row of `basis.len()` values per sample.
    pub(super) fn basis_values(&self, basis: &Basis<T>, rows: &[Sample<T>]) -> Vec<T> {
        let kk = basis.len();
        let mut bv = vec![self.p.zero(); rows.len() * kk];
        for (s, out) in rows.iter().zip(bv.chunks_exact_mut(kk)) {
            basis.fill(&s.fam, &s.t, out);
        }
        bv
    }

    /// The collocation points of a fit of `basis` with the options `opts`.
    pub(super) fn fit_points(&self, basis: &Basis<T>, opts: &SolveOptions) -> CollocationPoints<T> {
        let count = ((basis.len() as f64) * opts.oversample).ceil() as usize;
        self.collocation_points(count, opts.h_quad)
    }

    /// The collocation least-squares solve of `basis` (its values at the row samples `bv`) at
    /// the collocation points `pts` ([`Self::fit_points`]): coefficients normalised by the
    /// force moment, and the max residual of the scaled rows.
    pub(super) fn fit(
        &self,
        basis: &Basis<T>,
        rows: &[Sample<T>],
        bv: &[T],
        cols: &RowColumns<T>,
        pts: &[(i64, T, T)],
        cache: &RowCache<T>,
    ) -> Result<(Vec<T>, f64)> {
        let kk = basis.len();
        let like = &self.p;
        let mpts = pts.len();
        if mpts < kk {
            return Err(GenuineError::SolveFailed {
                what: "collocation",
                detail: format!("{mpts} distinct points for {kk} unknowns: decrease h_quad"),
            });
        }
        let mut a = Matrix::zeros(mpts + 1, kk, like);
        for (i, (k, x, pmx)) in pts.iter().enumerate() {
            let row = cache.row(basis, *k, || self.sie_row(basis, x, pmx, rows, cols, bv));
            let norm = row
                .iter()
                .fold(like.zero(), |m, v| m.max(v.clone().abs()))
                .max(like.lit(1e-300));
            for (k, r) in row.into_iter().enumerate() {
                *a.get_mut(i, k) = r / &norm;
            }
        }
        // normalisation: the force moment Int_0^p v h dv = 1
        let mut nrow = vec![like.zero(); kk];
        for (s, b) in rows.iter().zip(bv.chunks_exact(kk)) {
            let wv = s.w.clone() * &s.v;
            T::mul_add_slice(&mut nrow, b, &wv);
        }
        let nn = nrow
            .iter()
            .fold(like.zero(), |m, v| m.max(v.clone().abs()))
            .max(like.lit(1e-300));
        let wgt = like.lit(1e3) / &nn;
        for (k, n) in nrow.into_iter().enumerate() {
            *a.get_mut(mpts, k) = n * &wgt;
        }
        let mut rhs = vec![like.zero(); mpts + 1];
        rhs[mpts] = like.lit(1e3);
        // column scaling
        let mut cs = Vec::with_capacity(kk);
        for k in 0..kk {
            let mut s = like.zero();
            for x in a.col(k) {
                s.mul_add_assign(x, x);
            }
            let n = s.sqrt().max(like.lit(1e-300));
            for x in a.col_mut(k) {
                *x /= &n;
            }
            cs.push(n);
        }
        let rcond = like.epsilon().to_f64() * 16.0;
        let (sol, _rank) = least_squares(&a, &rhs, rcond);
        let ax = a.mul_vec(&sol);
        let res = ax
            .iter()
            .zip(&rhs)
            .take(mpts)
            .fold(0.0_f64, |m, (u, v)| m.max((u.clone() - v).to_f64().abs()));
        let coef: Vec<T> = sol.into_iter().zip(&cs).map(|(s, c)| s / c).collect();
        Ok((coef, res))
    }

    /// The slope U_y' + beta U_x' at xs and V_hat = xs - (U_y + beta U_x)/slope, from the
    /// contour functionals `u` of an unscaled solution.
    pub(super) fn slope_and_v_hat(&self, u: [T; 4], xs: &T) -> Result<(T, T)> {
        let [uy, ux, duy, dux] = u;
        let slope = duy + self.beta.clone() * &dux;
        let value = uy + self.beta.clone() * &ux;
        let usable = slope.clone().abs() > 0.0 && slope.is_finite();
        if !usable {
            return Err(GenuineError::SolveFailed {
                what: "collocation solve",
                detail: format!("degenerate slope at p = {}", self.p.to_f64()),
            });
        }
        let v_hat = xs.clone() - value / &slope;
        if !v_hat.is_finite() {
            return Err(GenuineError::SolveFailed {
                what: "collocation solve",
                detail: format!("non-finite V_hat at p = {}", self.p.to_f64()),
            });
        }
        Ok((slope, v_hat))
    }

    /// Scale the coefficients so that U_y' + beta U_x' = 1 at xs, from the contour
    /// functionals `u` of the unscaled solution, and return (slope, V_hat).
    pub(super) fn normalise(&self, coef: &mut [T], u: [T; 4], xs: &T) -> Result<(T, T)> {
        let (slope, v_hat) = self.slope_and_v_hat(u, xs)?;
        coef.iter_mut().for_each(|c| *c /= &slope);
        Ok((slope, v_hat))
    }
}
