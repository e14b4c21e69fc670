//! Quadrature: a small rule interface, rules cached per precision, error from level doubling.
//!
//! * [`TanhSinhRule`]: the double-exponential rule on [-1, 1], generic over [`Real`], nodes
//!   computed once per precision and cached ([`tanh_sinh_rule`]). Each node stores `1 - |x|`
//!   computed directly (not as a difference), so integrands with algebraic endpoint
//!   singularities receive their exact distance to the endpoint ([`Point`]).
//! * [`tanh_sinh`]: the adaptive driver. Level k halves the step; the error of the last level
//!   is extrapolated from the differences of the last three levels (the rule roughly doubles
//!   its correct digits per level once resolved; see `extrapolated_error`), with a
//!   round-off floor, so the driver stops one level earlier than the plain difference would.
//! * [`gauss_legendre`], [`gauss_jacobi`]: f64 rules from `gauss-quad`, built once per
//!   (degree, exponents) and cached (Gauss-Jacobi nodes cost O(n^3) to build), and
//!   [`gauss_legendre_doubling`], a driver with an error estimate from n and 2n nodes.
//!
//! The integrand receives a [`Point`]: the abscissa and its distances to both endpoints.
//!
//! # The other tanh-sinh implementation (`genuine::quad`)
//! The genuine wedge solver keeps its own tanh-sinh rules (the module `quad` of the `genuine`
//! crate, which depends on this one), and this module's rules serve the wedge crate and the
//! rest of this layer. The two are not interchangeable:
//! * variable map and node set: here the rule lives on [-1, 1] with steps 2^-k only, its
//!   levels cached once per precision; `genuine::quad` places a rule of (0, 1) on each
//!   interval, at any step h (a solver option such as `h_quad`), its nodes indexed by
//!   t = k h formed in the working precision, so that the collocation points sit on the
//!   quarter points of that same t-grid and the basis sampled once on the rule serves every
//!   collocation row; it also has the single-exponential tanh map and the mixed
//!   single/double-exponential map of the contour integrals' F-functions, which this module
//!   does not;
//! * truncation: here |t| <= t_max of the precision ([`Tails`], offsets down to 2^(-3 bits));
//!   there from the precision and the weakest endpoint exponent of the case (`t_max_for`);
//! * driver and error: [`tanh_sinh`] extrapolates the error from the last three levels, maps
//!   endpoint singularities ([`EndExponent`]) and refuses a result short of its tolerance;
//!   `genuine::quad::integrate_vec` integrates a vector of integrands from h = 1/2, stops on
//!   the plain difference of two levels over the components it is told to check, and returns
//!   that difference.
//!
//! Sharing one of them would change the nodes' rounding, the truncation or the stopping level
//! of the other's integrals, and with them the reported digits of the solutions that rest on
//! them.

use std::collections::HashMap;
use std::num::NonZeroUsize;
use std::sync::{Arc, Mutex, OnceLock};

use gauss_quad::{GaussJacobi, GaussLegendre};

use crate::cx::Cx;
use crate::error::{Error, Result};
use crate::estimate::{ErrorKind, Estimate};
use crate::scalar::Real;

/// An abscissa `v` of an interval [a, b] with `from_a = v - a` and `to_b = b - v`, each
/// accurate to working precision even when tiny.
#[derive(Clone, Debug)]
pub struct Point<T> {
    /// The abscissa.
    pub v: T,
    /// v - a.
    pub from_a: T,
    /// b - v.
    pub to_b: T,
}

/// How fast an integrand may blow up at the interval's ends; decides how far into the
/// endpoint tails the tanh-sinh rule samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tails {
    /// Bounded at both ends: nodes closer to an end than eps (b - a) are skipped.
    Smooth,
    /// Integrable algebraic singularities up to |v - a|^(-2/3): nodes down to eps^3 (b - a).
    Singular,
}

/// A value the drivers can sum: a real or a complex number.
pub trait QuadValue<T: Real>: Clone {
    /// Zero at the precision of `like`.
    fn zero_like(like: &T) -> Self;
    /// self += w * v.
    fn add_scaled(&mut self, v: &Self, w: &T);
    /// A magnitude (for stopping and error estimates).
    fn magnitude(&self) -> T;
    /// self * s.
    fn scaled(&self, s: &T) -> Self;
    /// |self - other|.
    fn distance(&self, other: &Self) -> T;
    /// self - other.
    fn minus(&self, other: &Self) -> Self;
}

impl<T: Real> QuadValue<T> for T {
    fn zero_like(like: &T) -> Self {
        like.zero()
    }
    fn add_scaled(&mut self, v: &Self, w: &T) {
        self.mul_add_assign(v, w);
    }
    fn magnitude(&self) -> T {
        self.clone().abs()
    }
    fn scaled(&self, s: &T) -> Self {
        self.clone() * s
    }
    fn distance(&self, other: &Self) -> T {
        (self.clone() - other).abs()
    }
    fn minus(&self, other: &Self) -> Self {
        self.clone() - other
    }
}

impl<T: Real> QuadValue<T> for Cx<T> {
    fn zero_like(like: &T) -> Self {
        Cx::real(like.zero())
    }
    fn add_scaled(&mut self, v: &Self, w: &T) {
        self.re.mul_add_assign(&v.re, w);
        self.im.mul_add_assign(&v.im, w);
    }
    fn magnitude(&self) -> T {
        self.abs()
    }
    fn scaled(&self, s: &T) -> Self {
        self.clone().scale(s)
    }
    fn distance(&self, other: &Self) -> T {
        (self.clone() - other).abs()
    }
    fn minus(&self, other: &Self) -> Self {
        self.clone() - other
    }
}

impl<T: Real, const N: usize> QuadValue<T> for [T; N] {
    fn zero_like(like: &T) -> Self {
        std::array::from_fn(|_| like.zero())
    }
    fn add_scaled(&mut self, v: &Self, w: &T) {
        for (a, b) in self.iter_mut().zip(v.iter()) {
            a.mul_add_assign(b, w);
        }
    }
    /// The largest |component|; a component that is not finite is returned as it is, so
    /// that a NaN is never hidden by the comparisons.
    fn magnitude(&self) -> T {
        let mut m = self[0].zero();
        for a in self.iter() {
            if !a.is_finite() {
                return a.clone().abs();
            }
            m = m.max(a.clone().abs());
        }
        m
    }
    fn scaled(&self, s: &T) -> Self {
        std::array::from_fn(|i| self[i].clone() * s)
    }
    fn distance(&self, other: &Self) -> T {
        let mut m = self[0].zero();
        for (a, b) in self.iter().zip(other.iter()) {
            let d = (a.clone() - b).abs();
            if !d.is_finite() {
                return d;
            }
            m = m.max(d);
        }
        m
    }
    fn minus(&self, other: &Self) -> Self {
        std::array::from_fn(|i| self[i].clone() - &other[i])
    }
}

/// A quadrature result: the integral with its absolute error estimate (an [`Estimate`] of
/// kind [`ErrorKind::Quadrature`], an over-estimate once the rule has converged) and the
/// number of integrand evaluations it took. It reads as its estimate (`q.value`, `q.error`).
#[derive(Clone, Debug)]
pub struct Quadrature<V> {
    /// The integral and its error estimate.
    pub estimate: Estimate<V>,
    /// Number of integrand evaluations.
    pub evals: usize,
}

impl<V> Quadrature<V> {
    /// The integral `value` with the estimated absolute error `error`, after `evals`
    /// evaluations of the integrand.
    pub fn new(value: V, error: f64, evals: usize) -> Self {
        Quadrature {
            estimate: Estimate::new(value, error, ErrorKind::Quadrature),
            evals,
        }
    }
}

impl<V> std::ops::Deref for Quadrature<V> {
    type Target = Estimate<V>;
    fn deref(&self) -> &Estimate<V> {
        &self.estimate
    }
}

impl<V> std::ops::DerefMut for Quadrature<V> {
    fn deref_mut(&mut self) -> &mut Estimate<V> {
        &mut self.estimate
    }
}

/// One node of the tanh-sinh rule on [-1, 1] for t >= 0: x = tanh(pi/2 sinh t) >= 0.
#[derive(Clone, Debug)]
pub struct TsNode<T> {
    /// 1 - x, computed as 2/(exp(pi sinh t) + 1).
    pub one_minus_x: T,
    /// dx/dt = (pi/2) cosh t / cosh^2(pi/2 sinh t).
    pub weight: T,
}

/// Tanh-sinh nodes for one precision: level 0 has step 1 (t = 0, 1, 2, ...), level k >= 1
/// adds the odd multiples of 2^-k. Only t >= 0 is stored; the rule is symmetric. Levels are
/// computed on first use (each costs a few transcendentals per node at the rule's precision).
#[derive(Debug)]
pub struct TanhSinhRule<T> {
    prec: u32,
    t_max: f64,
    levels: Vec<OnceLock<Vec<TsNode<T>>>>,
}

impl<T: Real> TanhSinhRule<T> {
    /// The rule at `prec` bits with `max_level` levels; nodes go out to
    /// 1 - x ~ 2^(-3 prec) so that [`Tails::Singular`] integrands are resolved.
    pub fn new(prec: u32, max_level: usize) -> Self {
        // tail: pi sinh t_max = 3 prec ln 2 + 2
        let tail = 3.0 * f64::from(prec) * std::f64::consts::LN_2 + 2.0;
        let t_max = (tail / std::f64::consts::PI).asinh();
        TanhSinhRule {
            prec,
            t_max,
            levels: (0..=max_level).map(|_| OnceLock::new()).collect(),
        }
    }

    fn build_level(&self, k: usize) -> Vec<TsNode<T>> {
        let like = T::from_f64_prec(0.0, self.prec);
        let half_pi = like.pi() / 2.0;
        let h = 0.5_f64.powi(k as i32);
        let mut nodes = Vec::new();
        let mut j: u64 = if k == 0 { 0 } else { 1 };
        loop {
            let t = j as f64 * h;
            if t > self.t_max {
                break;
            }
            let tt = like.lit(2.0).powi(-(k as i32)) * like.lit(j as f64);
            let (sh, ch) = (tt.clone().sinh(), tt.cosh());
            let u = half_pi.clone() * sh;
            let e2u = (u.clone() * 2.0).exp();
            let one_minus_x = like.lit(2.0) / (e2u + 1.0);
            let cu = u.cosh();
            let weight = half_pi.clone() * ch / cu.sqr();
            nodes.push(TsNode {
                one_minus_x,
                weight,
            });
            j += if k == 0 { 1 } else { 2 };
        }
        nodes
    }

    /// Precision of the nodes in bits.
    pub fn prec(&self) -> u32 {
        self.prec
    }
    /// Number of levels (0 ..= max).
    pub fn max_level(&self) -> usize {
        self.levels.len() - 1
    }
    /// The nodes added at `level` (computed on first use).
    pub fn level(&self, level: usize) -> &[TsNode<T>] {
        self.levels[level].get_or_init(|| self.build_level(level))
    }
}

/// Default number of levels for a precision: about log2(prec) + 3 (each level doubles the
/// number of correct digits once resolved).
pub fn default_max_level(prec: u32) -> usize {
    (f64::from(prec).log2().ceil() as usize + 3).max(7)
}

type LegendreCache<T> = Mutex<HashMap<(u32, usize), Arc<Vec<(T, T)>>>>;

/// Per-backend cache of tanh-sinh rules keyed by precision.
#[derive(Debug)]
pub struct RuleStore<T> {
    rules: Mutex<HashMap<u32, Arc<TanhSinhRule<T>>>>,
    legendre: LegendreCache<T>,
}

impl<T> Default for RuleStore<T> {
    fn default() -> Self {
        RuleStore {
            rules: Mutex::new(HashMap::new()),
            legendre: Mutex::new(HashMap::new()),
        }
    }
}

/// The n-point Gauss-Legendre rule on [-1, 1] at `prec` bits, as (node, weight) pairs,
/// cached per (prec, n). In f64 the nodes come from `gauss-quad`; at higher precision they
/// are polished by Newton's method on P_n (three-term recurrence) from the f64 nodes, each
/// step doubling the number of correct bits.
pub fn gauss_legendre_rule<T: CachedRules>(n: usize, prec: u32) -> Result<Arc<Vec<(T, T)>>> {
    let base = gauss_legendre(n)?;
    let store = T::store();
    if let Some(r) = store
        .legendre
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .get(&(prec, n))
    {
        return Ok(r.clone());
    }
    let like = T::from_f64_prec(0.0, prec);
    let steps = if prec <= 53 {
        0
    } else {
        (f64::from(prec) / 40.0).log2().ceil() as usize + 2
    };
    let mut nodes = Vec::with_capacity(n);
    for &(x0, w0) in &base.nodes {
        if steps == 0 {
            nodes.push((like.lit(x0), like.lit(w0)));
            continue;
        }
        let mut x = like.lit(x0);
        let mut dp = like.one();
        for _ in 0..steps {
            // P_n(x) and P_{n-1}(x)
            let mut p0 = like.one();
            let mut p1 = x.clone();
            for k in 1..n {
                let kf = k as f64;
                let p2 = (x.clone() * &p1 * (2.0 * kf + 1.0) - p0 * kf) / (kf + 1.0);
                p0 = p1;
                p1 = p2;
            }
            let x2m1 = x.clone().sqr() - 1.0;
            dp = (x.clone() * &p1 - &p0) * (n as f64) / &x2m1;
            x -= p1 / &dp;
        }
        let w = like.lit(2.0) / ((like.one() - x.clone().sqr()) * dp.sqr());
        nodes.push((x, w));
    }
    let r = Arc::new(nodes);
    store
        .legendre
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .insert((prec, n), r.clone());
    Ok(r)
}

/// Backends that keep a process-wide cache of tanh-sinh rules.
pub trait CachedRules: Real {
    /// The cache of this backend.
    fn store() -> &'static RuleStore<Self>;
}

impl CachedRules for f64 {
    fn store() -> &'static RuleStore<f64> {
        static S: OnceLock<RuleStore<f64>> = OnceLock::new();
        S.get_or_init(RuleStore::default)
    }
}

impl CachedRules for crate::double_double::Dd {
    fn store() -> &'static RuleStore<crate::double_double::Dd> {
        static S: OnceLock<RuleStore<crate::double_double::Dd>> = OnceLock::new();
        S.get_or_init(RuleStore::default)
    }
}

impl CachedRules for rug::Float {
    fn store() -> &'static RuleStore<rug::Float> {
        static S: OnceLock<RuleStore<rug::Float>> = OnceLock::new();
        S.get_or_init(RuleStore::default)
    }
}

/// The cached tanh-sinh rule for `prec` bits (built on first use).
pub fn tanh_sinh_rule<T: CachedRules>(prec: u32) -> Arc<TanhSinhRule<T>> {
    let store = T::store();
    let mut map = store.rules.lock().unwrap_or_else(|e| e.into_inner());
    map.entry(prec)
        .or_insert_with(|| Arc::new(TanhSinhRule::new(prec, default_max_level(prec))))
        .clone()
}

/// Options of the tanh-sinh driver.
#[derive(Clone, Copy, Debug)]
pub struct TsOptions {
    /// Requested relative accuracy (relative to the integral, or to the sum of |terms| when
    /// the integral cancels).
    pub rel_tol: f64,
    /// Endpoint behaviour.
    pub tails: Tails,
    /// Fewest levels before the error estimate is trusted.
    pub min_level: usize,
    /// Exponent alpha of an algebraic singularity |v - a|^alpha at the left end, if any.
    pub left_exponent: Option<EndExponent>,
    /// Exponent alpha of an algebraic singularity |b - v|^alpha at the right end, if any.
    pub right_exponent: Option<EndExponent>,
}

/// The exponent alpha > -1 of an endpoint singularity |v - end|^alpha, with its distance
/// from -1, the gap 1 + alpha, kept apart as an unevaluated sum of two doubles (about 106
/// bits) so that it keeps its relative accuracy however close alpha is to -1.
///
/// Close to -1 the integral is dominated by the part within a distance far below any
/// floating-point range of the end, which the map sums in closed form from the gap (see
/// [`tanh_sinh`]): a gap rounded as -1 + gap in f64 would carry the relative error
/// 1e-16/gap into that part.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EndExponent {
    /// alpha, rounded to f64 (decides the form of the map).
    alpha: f64,
    /// 1 + alpha = gap_hi + gap_lo.
    gap_hi: f64,
    gap_lo: f64,
}

impl EndExponent {
    /// The exponent alpha (its gap 1 + alpha formed in f64, exact for alpha in [-1, -1/2]).
    pub fn new(alpha: f64) -> Self {
        EndExponent {
            alpha,
            gap_hi: 1.0 + alpha,
            gap_lo: 0.0,
        }
    }
    /// The exponent alpha = -1 + gap from the gap at any precision (kept to about 106 bits).
    pub fn from_gap<T: Real>(gap: &T) -> Self {
        let hi = gap.to_f64();
        let lo = (gap.clone() - &gap.lit(hi)).to_f64();
        EndExponent {
            alpha: hi - 1.0,
            gap_hi: hi,
            gap_lo: if lo.is_finite() { lo } else { 0.0 },
        }
    }
    /// alpha, rounded to f64.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }
    /// The gap 1 + alpha, rounded to f64 (full relative accuracy).
    pub fn gap(&self) -> f64 {
        self.gap_hi
    }
    /// The gap 1 + alpha at the precision of `like` (exact to about 106 bits).
    pub fn gap_at<T: Real>(&self, like: &T) -> T {
        like.lit(self.gap_hi) + &like.lit(self.gap_lo)
    }
}

impl TsOptions {
    /// Tolerance `rel_tol` with singular tails.
    pub fn new(rel_tol: f64) -> Self {
        TsOptions {
            rel_tol,
            tails: Tails::Singular,
            min_level: 3,
            left_exponent: None,
            right_exponent: None,
        }
    }
    /// Builder: the integrand behaves like |v - a|^alpha at the left end (alpha > -1).
    pub fn left_singularity(self, alpha: f64) -> Self {
        self.left_end(EndExponent::new(alpha))
    }
    /// Builder: the integrand behaves like |b - v|^alpha at the right end (alpha > -1).
    pub fn right_singularity(self, alpha: f64) -> Self {
        self.right_end(EndExponent::new(alpha))
    }
    /// Builder: the left end's singularity with its gap 1 + alpha given to full accuracy
    /// (exponents close to -1).
    pub fn left_end(mut self, e: EndExponent) -> Self {
        self.left_exponent = Some(e);
        self
    }
    /// Builder: the right end's singularity with its gap 1 + alpha given to full accuracy.
    pub fn right_end(mut self, e: EndExponent) -> Self {
        self.right_exponent = Some(e);
        self
    }
    /// The same options without endpoint exponents (for a sub-interval that touches neither
    /// singular end).
    pub fn without_ends(mut self) -> Self {
        self.left_exponent = None;
        self.right_exponent = None;
        self
    }
    /// Builder: endpoint behaviour.
    pub fn tails(mut self, tails: Tails) -> Self {
        self.tails = tails;
        self
    }
}

/// Exponents above this are left to the plain rule (its tail reaches 2^(-3 prec), enough for
/// |v - a|^alpha with alpha >= -2/3); below it the end is mapped.
const MAP_BELOW: f64 = -1.0 / 3.0;
/// Largest power-map exponent kappa = 1/(1 + alpha): closer to alpha = -1 the map squeezes
/// the integrand's variation into a layer of width about 1/kappa at y = 1 that the levels can
/// step over unseen, and the exponential map takes over (see [`tanh_sinh`]).
const KAPPA_POWER_MAX: f64 = 1e4;
/// The longest interval of the exponential map's variable s for a type without a floor
/// (MPFR): (b - a) e^(-S) stays far inside MPFR's default exponent range (2^(-2^30)).
const S_CAP_WIDE: f64 = 1e8;
/// Largest power-map exponent kappa that is rounded up to an integer (see [`tanh_sinh`]).
/// Up to it, where the exponent range is narrow, the continuation below y_f (at most
/// 1e-72 for kappa <= 4) stays far below every precision's resolution.
const INTEGER_KAPPA: f64 = 4.0;
/// Margin above a type's normal floor below which the distance to a mapped end is not formed
/// (it keeps |v - a|^alpha and the factors of the integrand clear of subnormal numbers).
const FLOOR_MARGIN: f64 = 1e20;

/// One side's tail of a tanh-sinh sum beyond level 0: where its terms stop mattering.
struct Tail {
    /// The largest t at which a term was above the tail threshold.
    big: f64,
    /// The t beyond which the side is not evaluated.
    end: f64,
    /// Consecutive negligible terms beyond `big` on the current level.
    run: usize,
}

impl Tail {
    /// Records the term at t: two consecutive negligible terms beyond the last large one end
    /// the tail there, for this and the later levels.
    fn observe(&mut self, t: f64, negligible: bool) {
        if !negligible {
            self.big = self.big.max(t);
            self.run = 0;
        } else if t > self.big {
            self.run += 1;
            if self.run == 2 {
                self.end = t;
            }
        }
    }
}

/// Tanh-sinh integral of `f` over [a, b] (a < b), adaptive in the level.
///
/// Strong endpoint singularities declared in `opts` (|v - a|^alpha with alpha < -1/3) are
/// removed by the substitution v - a = (b - a) y^kappa, kappa = 1/(1 + alpha) (rounded up to
/// an integer when that is at most 4, so that the powers are products; otherwise formed at the
/// working precision from the declared gap 1 + alpha, [`EndExponent`]), with both
/// distances to the ends of [a, b] recomputed exactly in the original variable
/// (b - v = -(b - a) expm1(kappa ln1p(-(1 - y))), or (b - a)(1 - y)(1 + y + ... + y^(kappa - 1))):
/// the mapped integrand kappa (b - a)^(1 + alpha) y^(kappa (1 + alpha) - 1) g(v),
/// g = f/|v - a|^alpha, is bounded at y = 0. Two singular ends
/// are split at the midpoint. Plain tanh-sinh alone truncates such tails at 2^(-3 prec), which
/// would lose (2^(-3 prec))^(1 + alpha): 7 percent of the integral at alpha = -0.99 in f64.
///
/// Close to alpha = -1, kappa is large and the nodes of a whole range y < y_f put v - a below
/// what a type with a narrow exponent range represents (f64: y_f = 0.0067 at alpha = -0.9925,
/// where |v - a| = 1e-288 |b - a|). There the mapped integrand is taken as its value at y_f:
/// it equals kappa (b - a)^(1 + alpha) g(a + (b - a) y^kappa) (y to the power
/// kappa (1 + alpha) - 1 = 0, kappa being formed from the gap), constant to the relative
/// variation of g over 1e-288 (b - a), far below the precision. MPFR's exponent range never
/// needs this.
///
/// Beyond kappa = 10^4 (gap below 1e-4) the power map gives way to the exponential map
/// v - a = (b - a) e^(-s): the integral is Int_0^inf F(s) ds with F = f (v - a)
/// = (b - a)^gap e^(-gap s) g(v), a smooth function of s whose variation (that of g) lies at
/// s of order one. It is summed by tanh-sinh over [0, S], and beyond S in closed form:
/// Int_S^inf F = F(S)/gap, g being constant there to the working precision. S is where
/// e^(-gap S) falls below the working precision (the tail is then negligible), at least
/// 2 (prec + 16) ln 2 and at most where v - a nears the type's floor (f64: S = 662; MPFR:
/// 10^8). Once gap S is small the tail is almost all of the integral and carries the gap's
/// relative error (2^-104 from its two doubles, counted in the estimate).
///
/// Returns the estimate of the last level and `|S_k - S_{k-1}|` as its error; fails with
/// [`Error::NoConvergence`] when the finest cached level does not reach `opts.rel_tol`, and
/// with [`Error::InvalidParameter`] for a declared exponent not above -1.
pub fn tanh_sinh<T, V, F>(a: &T, b: &T, opts: TsOptions, mut f: F) -> Result<Quadrature<V>>
where
    T: CachedRules,
    V: QuadValue<T>,
    F: FnMut(&Point<T>) -> V,
{
    tanh_sinh_dyn(a, b, opts, &mut f)
}

/// The integrand as the rules see it: one dynamic call per node, so that the rules are
/// compiled once per precision and value type rather than once per integrand (a node's
/// integrand costs far more than the call).
type Integrand<'f, T, V> = &'f mut dyn FnMut(&Point<T>) -> V;

/// [`tanh_sinh`] behind its generic shim.
fn tanh_sinh_dyn<T, V>(
    a: &T,
    b: &T,
    opts: TsOptions,
    f: Integrand<'_, T, V>,
) -> Result<Quadrature<V>>
where
    T: CachedRules,
    V: QuadValue<T>,
{
    let strong = |e: Option<EndExponent>| e.filter(|x| !(x.alpha >= MAP_BELOW));
    match (strong(opts.left_exponent), strong(opts.right_exponent)) {
        (None, None) => tanh_sinh_plain(a, b, opts, f),
        (Some(al), None) => mapped_end(a, b, al, true, opts, f),
        (None, Some(ar)) => mapped_end(a, b, ar, false, opts, f),
        (Some(al), Some(ar)) => {
            let mid = (a.clone() + b) / 2.0;
            let l = mapped_end(a, &mid, al, true, opts, &mut |p: &Point<T>| {
                f(&Point {
                    v: p.v.clone(),
                    from_a: p.from_a.clone(),
                    to_b: p.to_b.clone() + &(b.clone() - &mid),
                })
            })?;
            let r = mapped_end(&mid, b, ar, false, opts, &mut |p: &Point<T>| {
                f(&Point {
                    v: p.v.clone(),
                    from_a: p.from_a.clone() + &(mid.clone() - a),
                    to_b: p.to_b.clone(),
                })
            })?;
            let mut value = l.estimate.value;
            value.add_scaled(&r.value, &a.one());
            Ok(Quadrature::new(
                value,
                l.estimate.error + r.error,
                l.evals + r.evals,
            ))
        }
    }
}

/// The point of [a, b] at distance `near` from the singular end (the left one when `left`),
/// `far` = (b - a) - near from the other.
fn end_point<T: Real>(a: &T, b: &T, left: bool, near: T, far: T) -> Point<T> {
    if left {
        Point {
            v: if near < far {
                a.clone() + &near
            } else {
                b.clone() - &far
            },
            from_a: near,
            to_b: far,
        }
    } else {
        Point {
            v: if near < far {
                b.clone() - &near
            } else {
                a.clone() + &far
            },
            from_a: far,
            to_b: near,
        }
    }
}

/// The map at one singular end (see [`tanh_sinh`]): the power map, or the exponential map for
/// a gap 1 + alpha below 1/[`KAPPA_POWER_MAX`].
fn mapped_end<T, V>(
    a: &T,
    b: &T,
    e: EndExponent,
    left: bool,
    opts: TsOptions,
    f: Integrand<'_, T, V>,
) -> Result<Quadrature<V>>
where
    T: CachedRules,
    V: QuadValue<T>,
{
    if !(e.gap_hi > 0.0 && e.gap_hi.is_finite()) {
        return Err(Error::InvalidParameter(crate::error::InvalidParameter {
            name: "endpoint exponent",
            value: format!("{}", e.alpha),
            range: "(-1, 0) (an integrable endpoint singularity)".into(),
        }));
    }
    if 1.0 / e.gap_hi > KAPPA_POWER_MAX {
        exponential_end(a, b, e, left, opts, f)
    } else {
        power_end(a, b, e, left, opts, f)
    }
}

/// The power map v - a = (b - a) y^kappa at one end (see [`tanh_sinh`]).
fn power_end<T, V>(
    a: &T,
    b: &T,
    e: EndExponent,
    left: bool,
    opts: TsOptions,
    f: Integrand<'_, T, V>,
) -> Result<Quadrature<V>>
where
    T: CachedRules,
    V: QuadValue<T>,
{
    // kappa = 1/(1 + alpha), rounded up to an integer up to INTEGER_KAPPA: the powers of y
    // are then products, and the mapped integrand keeps the bounded factor
    // y^(kappa (1 + alpha) - 1), of non-negative exponent; otherwise formed from the gap at
    // the working precision, so that this factor is 1 to that precision
    let kappa = 1.0 / e.gap_hi;
    let (kappa, k, kappa_int) = if kappa.ceil() <= INTEGER_KAPPA {
        let n = kappa.ceil();
        (n, a.lit(n), Some(n as u32))
    } else {
        (kappa, e.gap_at(a).recip(), None)
    };
    let len = b.clone() - a;
    let zero = a.zero();
    let one = a.one();
    // the point and the mapped integrand at y, given near = y^kappa (b - a) and
    // far = (1 - y^kappa) (b - a)
    let mut mapped = |y: &T, near: T, far: T| -> V {
        // dv/dy = kappa len y^(kappa - 1) = kappa near/y
        let jac = near.clone() * &k / y.clone();
        f(&end_point(a, b, left, near, far)).scaled(&jac)
    };
    // a narrow exponent range: below y_f (where near = FLOOR_MARGIN times the normal floor)
    // the mapped integrand is continued from its value at y_f
    let len_f = len.to_f64().abs();
    let floor = a
        .normal_floor()
        .map(|fl| fl * FLOOR_MARGIN)
        .filter(|&near_f| near_f < len_f)
        .map(|near_f| a.lit((near_f / len_f).powf(1.0 / kappa)));
    let mut frozen: Option<V> = None;
    // (y^kappa, 1 - y^kappa), each with full relative accuracy (1 - y exact from the offsets)
    let powers = |y: &T, one_minus_y: &T| -> (T, T) {
        if let Some(n) = kappa_int {
            // y^n, and 1 - y^n = (1 - y)(1 + y + ... + y^(n - 1)): positive terms only
            let mut yn = y.clone();
            let mut sum = one.clone();
            for _ in 1..n {
                yn *= y;
                sum *= y;
                sum += 1.0;
            }
            return (yn, sum * one_minus_y);
        }
        // kappa ln y, with ln y from 1 - y where y is close to 1
        let z = if y.to_f64() < 0.5 {
            y.clone().ln()
        } else {
            (-one_minus_y.clone()).ln_1p()
        } * &k;
        if z.to_f64() < -0.7 {
            // y^kappa < 1/2: 1 - y^kappa > 1/2 without cancellation
            let yk = z.exp();
            let rest = one.clone() - &yk;
            (yk, rest)
        } else {
            // y^kappa >= 1/2: 1 - y^kappa = -expm1(kappa ln y)
            let e = z.exp_m1();
            (e.clone() + 1.0, -e)
        }
    };
    tanh_sinh_plain(&zero, &one, opts.without_ends(), &mut |q: &Point<T>| {
        // y = distance from the singular end, normalised; 1 - y exactly from the offsets
        let (y, one_minus_y) = (&q.from_a, &q.to_b);
        if *y == 0.0 {
            return V::zero_like(a);
        }
        if let Some(y_f) = &floor {
            if y < y_f {
                // the value at y_f, its distances formed from y_f itself (so that the
                // Jacobian and the point agree to the working precision)
                return frozen
                    .get_or_insert_with(|| {
                        let (yk, rest) = powers(y_f, &(one.clone() - y_f));
                        mapped(y_f, yk * &len, rest * &len)
                    })
                    .clone();
            }
        }
        let (yk, rest) = powers(y, one_minus_y);
        let near = yk * &len;
        if near == 0.0 {
            // y^kappa underflowed (only for an interval shorter than the continuation's
            // margin above the normal floor): the mapped integrand is bounded there and the
            // node's weight is below the underflow threshold.
            return V::zero_like(a);
        }
        mapped(y, near, rest * &len)
    })
}

/// The exponential map v - a = (b - a) e^(-s) at one end, for a gap 1 + alpha below
/// 1/[`KAPPA_POWER_MAX`]: tanh-sinh over [0, S] and the closed-form tail F(S)/gap beyond
/// (see [`tanh_sinh`]).
fn exponential_end<T, V>(
    a: &T,
    b: &T,
    e: EndExponent,
    left: bool,
    opts: TsOptions,
    f: Integrand<'_, T, V>,
) -> Result<Quadrature<V>>
where
    T: CachedRules,
    V: QuadValue<T>,
{
    let len = b.clone() - a;
    let len_f = len.to_f64().abs();
    // S: far enough that the tail e^(-gap S) is below the working precision (then its closed
    // form is a formality), but at most where (b - a) e^(-S) nears the type's floor; at least
    // where that distance is below the working precision's resolution of g
    let bits = f64::from(a.prec()) + 16.0;
    let s_prec = 2.0 * bits * std::f64::consts::LN_2;
    let s_cap = match a.normal_floor() {
        Some(fl) => (len_f / (fl * FLOOR_MARGIN)).ln(),
        None => S_CAP_WIDE,
    };
    let s_max = (bits * std::f64::consts::LN_2 / e.gap_hi)
        .min(s_cap)
        .max(s_prec.min(s_cap));
    if !(s_max > 1.0) {
        return Err(Error::NoConvergence(crate::error::NoConvergence {
            what: "tanh-sinh quadrature (an interval too short for its endpoint map)".into(),
            reached: f64::INFINITY,
            asked: opts.rel_tol,
        }));
    }
    let s_end = a.lit(s_max);
    let mut at = |s: &T| -> V {
        // near = (b - a) e^(-s), far = -(b - a) expm1(-s), each to full relative accuracy
        let near = (-s.clone()).exp() * &len;
        let far = -((-s.clone()).exp_m1() * &len);
        let jac = near.clone();
        f(&end_point(a, b, left, near, far)).scaled(&jac)
    };
    let zero = a.zero();
    let body = tanh_sinh_plain(&zero, &s_end, opts.without_ends(), &mut |q: &Point<T>| {
        at(&q.from_a)
    })?;
    let tail = at(&s_end).scaled(&e.gap_at(a).recip());
    // the tail carries the gap's relative error: 2^-104 from its two doubles, or the
    // working precision's round-off, whichever is larger
    let rel = (2f64.powi(-104)).max(4.0 * a.epsilon().to_f64());
    let tail_error = tail.magnitude().to_f64() * rel;
    let mut value = body.estimate.value;
    value.add_scaled(&tail, &a.one());
    Ok(Quadrature::new(
        value,
        body.estimate.error + tail_error,
        body.evals + 1,
    ))
}

fn tanh_sinh_plain<T, V>(
    a: &T,
    b: &T,
    opts: TsOptions,
    f: Integrand<'_, T, V>,
) -> Result<Quadrature<V>>
where
    T: CachedRules,
    V: QuadValue<T>,
{
    let rule = tanh_sinh_rule::<T>(a.prec());
    let half = (b.clone() - a) / 2.0;
    let eps = a.epsilon();
    let min_offset = match opts.tails {
        Tails::Smooth => eps.clone() * 0.5,
        Tails::Singular => T::from_f64_prec(0.0, a.prec()),
    };
    let tail_drop = eps.clone() * 1e-3;
    let mut evals = 0usize;

    // value at a node of [-1,1] on the positive side (sign = +1) or the negative side.
    let mut eval_pair =
        |node: &TsNode<T>, acc: &mut V, mag: &mut T, skip_pos: bool, skip_neg: bool| -> (T, T) {
            let c = node.one_minus_x.clone();
            let big = half.clone() * (T::from_f64_prec(2.0, c.prec()) - &c);
            let small = half.clone() * &c;
            let mut tp = c.zero();
            let mut tn = c.zero();
            if !skip_pos {
                // x > 0: near b
                let p = Point {
                    v: b.clone() - &small,
                    from_a: big.clone(),
                    to_b: small.clone(),
                };
                let y = f(&p);
                evals += 1;
                let m = y.magnitude() * &node.weight;
                acc.add_scaled(&y, &node.weight);
                *mag += &m;
                tp = m;
            }
            if !skip_neg && node.one_minus_x < 1.0 {
                let p = Point {
                    v: a.clone() + &small,
                    from_a: small.clone(),
                    to_b: big,
                };
                let y = f(&p);
                evals += 1;
                let m = y.magnitude() * &node.weight;
                acc.add_scaled(&y, &node.weight);
                *mag += &m;
                tn = m;
            }
            (tp, tn)
        };

    // Level 0 decides how far into each tail the rule goes.
    let mut acc = V::zero_like(a);
    let mut mag = a.zero();
    let mut cut_pos = 0usize;
    let mut cut_neg = 0usize;
    let mut small_pos = 0;
    let mut small_neg = 0;
    // the largest t at which a term was above the tail threshold, per side
    let mut big_pos = 0.0_f64;
    let mut big_neg = 0.0_f64;
    let lvl0 = rule.level(0);
    for (j, node) in lvl0.iter().enumerate() {
        let skip =
            node.one_minus_x.clone() * &half < min_offset.clone() * &half.clone().abs() * 2.0;
        if skip {
            break;
        }
        let (done_p, done_n) = (small_pos >= 2, small_neg >= 2);
        if done_p && done_n {
            break;
        }
        let (tp, tn) = eval_pair(node, &mut acc, &mut mag, done_p, done_n || j == 0);
        let thr = mag.clone() * &tail_drop;
        if !done_p {
            cut_pos = j;
            small_pos = if tp < thr { small_pos + 1 } else { 0 };
            if small_pos == 0 {
                big_pos = j as f64;
            }
        }
        if !done_n {
            cut_neg = j;
            small_neg = if j > 0 && tn < thr { small_neg + 1 } else { 0 };
            if small_neg == 0 {
                big_neg = j as f64;
            }
        }
    }
    let mut pos = Tail {
        big: big_pos,
        end: cut_pos as f64 + 0.5,
        run: 0,
    };
    let mut neg = Tail {
        big: big_neg,
        end: cut_neg as f64 + 0.5,
        run: 0,
    };
    let mut sum = acc; // sum with step h = 1
    let mut prev: Option<V> = None;
    let mut err = f64::INFINITY;
    // relative difference of the previous level (for the extrapolated estimate)
    let mut last_rel: Option<f64> = None;
    let eps_f = eps.to_f64().max(f64::MIN_POSITIVE);
    for k in 1..=rule.max_level() {
        let h = 0.5_f64.powi(k as i32);
        let mut acc = V::zero_like(a);
        (pos.run, neg.run) = (0, 0);
        for (i, node) in rule.level(k).iter().enumerate() {
            let t = (2 * i + 1) as f64 * h;
            let sp = t > pos.end;
            let sn = t > neg.end;
            if sp && sn {
                break;
            }
            if node.one_minus_x.clone() * &half < min_offset.clone() * &half.clone().abs() * 2.0 {
                break;
            }
            let (tp, tn) = eval_pair(node, &mut acc, &mut mag, sp, sn);
            // Beyond the last term above the threshold the tail decays double-exponentially:
            // two consecutive negligible terms there end this side's tail for this and later
            // levels (as two do at level 0).
            let thr = mag.clone() * &tail_drop;
            if !sp {
                pos.observe(t, tp < thr);
            }
            if !sn {
                neg.observe(t, tn < thr);
            }
        }
        // S_k = S_{k-1}/2 + h * new, all times (b-a)/2 at the end
        let hk = a.lit(h);
        let mut next = sum.scaled(&a.lit(0.5));
        next.add_scaled(&acc, &hk);
        let val_prev = sum.scaled(&half.clone().abs());
        let val = next.scaled(&half.clone().abs());
        let diff = val.distance(&val_prev).to_f64();
        let l1 = (mag.clone() * &hk * &half.clone().abs()).to_f64();
        let scale = val.magnitude().to_f64().max(l1);
        sum = next;
        prev = Some(val);
        let rel = diff / scale.max(f64::MIN_POSITIVE);
        let roundoff = 4.0 * eps_f * l1 / scale.max(f64::MIN_POSITIVE);
        err = extrapolated_error(rel, last_rel, roundoff) * scale;
        last_rel = Some(rel);
        // converged, or at the round-off floor (where further levels cannot help)
        if k >= opts.min_level && err <= opts.rel_tol.max(roundoff) * scale {
            break;
        }
    }
    let value = prev.unwrap_or_else(|| sum.scaled(&half));
    let value = if half.is_sign_negative() {
        value.scaled(&a.lit(-1.0))
    } else {
        value
    };
    let scale = value.magnitude().to_f64();
    // an infinite scale would pass the tolerance test below: never accept a non-finite result
    if !(scale.is_finite() && err.is_finite()) {
        return Err(Error::NonFinite {
            what: "tanh-sinh quadrature",
        });
    }
    if !(err <= opts.rel_tol * scale.max(f64::MIN_POSITIVE) || err <= opts.rel_tol * 1e-300) {
        // report, but let the caller decide: a NaN or non-convergence is an error
        if !err.is_finite() || err > opts.rel_tol.sqrt() * scale.max(f64::MIN_POSITIVE) {
            return Err(Error::NoConvergence(crate::error::NoConvergence {
                what: "tanh-sinh quadrature".into(),
                reached: if scale > 0.0 { err / scale } else { err },
                asked: opts.rel_tol,
            }));
        }
    }
    Ok(Quadrature::new(value, err, evals))
}

/// Order of convergence per level assumed by [`extrapolated_error`].
///
/// Resolved tanh-sinh roughly doubles its correct digits per level (the trapezoidal error
/// exp(-c/h) is squared when h is halved), but the ratio of successive log-differences
/// scatters around 2 before the asymptotic regime (1.8 to 2.6 seen on the matching and stress
/// integrals of this library at 133 and 400 bits); mpmath's estimate, which extrapolates with
/// the observed ratio capped at 2, was optimistic by 10^4 on one of them. 1.5 stays below
/// every ratio observed.
const ORDER: f64 = 1.5;

/// Relative error of the last tanh-sinh level from the relative differences of the last two
/// level pairs, `rel` = |S_k - S_(k-1)| and `last` = |S_(k-1) - S_(k-2)| (both over the
/// integral's scale), in the spirit of mpmath's `TanhSinh.estimate_error`.
///
/// When the levels already converge at least with the order [`ORDER`]
/// (ln rel/ln last >= 1.5), the error of S_k is taken as rel^1.5: one more level of that
/// order. Otherwise (not yet resolved, rel >= last, or rel >= 1/2) it is the plain
/// difference `rel`, which bounds the error of S_(k-1) and hence of S_k. `roundoff` (4 eps
/// times the L1 norm of the integrand over the scale) is the floor below which no estimate
/// goes.
pub(crate) fn extrapolated_error(rel: f64, last: Option<f64>, roundoff: f64) -> f64 {
    let floor = roundoff;
    if !rel.is_finite() {
        return f64::INFINITY;
    }
    let est = match last {
        Some(l) if rel > 0.0 && rel < 0.5 && l < 1.0 && rel < l => {
            if rel.ln() / l.ln() >= ORDER {
                rel.powf(ORDER)
            } else {
                rel
            }
        }
        Some(_) if rel == 0.0 => 0.0,
        _ => rel,
    };
    est.max(floor)
}

/// A cached f64 rule: nodes on [-1, 1] with 1 - |x| and weights.
#[derive(Debug)]
pub struct F64Rule {
    /// (x, w) pairs.
    pub nodes: Vec<(f64, f64)>,
}

type RuleKey = (usize, u64, u64);

fn f64_rule_cache() -> &'static Mutex<HashMap<RuleKey, Arc<F64Rule>>> {
    static C: OnceLock<Mutex<HashMap<RuleKey, Arc<F64Rule>>>> = OnceLock::new();
    C.get_or_init(|| Mutex::new(HashMap::new()))
}

/// The n-point Gauss-Legendre rule on [-1, 1] (cached).
pub fn gauss_legendre(n: usize) -> Result<Arc<F64Rule>> {
    let nz =
        NonZeroUsize::new(n).ok_or(Error::InvalidParameter(crate::error::InvalidParameter {
            name: "quadrature degree",
            value: "0".into(),
            range: ">= 1".into(),
        }))?;
    let mut c = f64_rule_cache().lock().unwrap_or_else(|e| e.into_inner());
    Ok(c.entry((n, u64::MAX, u64::MAX))
        .or_insert_with(|| {
            let r = GaussLegendre::new(nz);
            Arc::new(F64Rule {
                nodes: r.as_node_weight_pairs().to_vec(),
            })
        })
        .clone())
}

/// The n-point Gauss-Jacobi rule on [-1, 1] for the weight (1 - x)^alpha (1 + x)^beta,
/// alpha, beta > -1 (cached per (n, alpha, beta)).
pub fn gauss_jacobi(n: usize, alpha: f64, beta: f64) -> Result<Arc<F64Rule>> {
    let nz =
        NonZeroUsize::new(n).ok_or(Error::InvalidParameter(crate::error::InvalidParameter {
            name: "quadrature degree",
            value: "0".into(),
            range: ">= 1".into(),
        }))?;
    let bad = |name, v: f64| {
        Error::InvalidParameter(crate::error::InvalidParameter {
            name,
            value: format!("{v}"),
            range: "(-1, inf), finite".into(),
        })
    };
    let a = gauss_quad::FiniteAboveNegOneF64::try_from(alpha)
        .map_err(|_| bad("jacobi alpha", alpha))?;
    let b =
        gauss_quad::FiniteAboveNegOneF64::try_from(beta).map_err(|_| bad("jacobi beta", beta))?;
    let mut c = f64_rule_cache().lock().unwrap_or_else(|e| e.into_inner());
    Ok(c.entry((n, alpha.to_bits(), beta.to_bits()))
        .or_insert_with(|| {
            let r = GaussJacobi::new(nz, a, b);
            Arc::new(F64Rule {
                nodes: r.as_node_weight_pairs().to_vec(),
            })
        })
        .clone())
}

impl F64Rule {
    /// Sum of w f over the rule mapped to [a, b] (the Jacobi weight, if any, is implied and
    /// not multiplied in; the caller scales by ((b - a)/2)^(1 + alpha + beta)).
    pub fn integrate<V: QuadValue<f64>, F: FnMut(&Point<f64>) -> V>(
        &self,
        a: f64,
        b: f64,
        mut f: F,
    ) -> V {
        let half = 0.5 * (b - a);
        let mut acc = V::zero_like(&0.0);
        for &(x, w) in &self.nodes {
            let p = if x < 0.0 {
                let from_a = half * (1.0 + x);
                Point {
                    v: a + from_a,
                    from_a,
                    to_b: half * (1.0 - x),
                }
            } else {
                let to_b = half * (1.0 - x);
                Point {
                    v: b - to_b,
                    from_a: half * (1.0 + x),
                    to_b,
                }
            };
            acc.add_scaled(&f(&p), &w);
        }
        acc.scaled(&half)
    }
}

/// Gauss-Legendre with n and 2n nodes; returns the 2n result and |I_2n - I_n| as its error.
pub fn gauss_legendre_doubling<V: QuadValue<f64>, F: FnMut(&Point<f64>) -> V>(
    a: f64,
    b: f64,
    n: usize,
    mut f: F,
) -> Result<Quadrature<V>> {
    let r1 = gauss_legendre(n)?;
    let r2 = gauss_legendre(2 * n)?;
    let i1 = r1.integrate(a, b, &mut f);
    let i2 = r2.integrate(a, b, &mut f);
    let error = i2.distance(&i1);
    if !(i2.magnitude().is_finite() && error.is_finite()) {
        return Err(Error::NonFinite {
            what: "Gauss-Legendre quadrature",
        });
    }
    Ok(Quadrature::new(i2, error, 3 * n))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    #[test]
    fn tanh_sinh_f64_endpoint_singularity() {
        // int_0^1 v^(-1/2) (1 - v)^(-1/3) dv = B(1/2, 2/3)
        let exact = 2.587_109_559_229_790_5; // B(1/2, 2/3), mpmath
        let e = tanh_sinh(&0.0, &1.0, TsOptions::new(1e-15), |p: &Point<f64>| {
            p.from_a.powf(-0.5) * p.to_b.powf(-1.0 / 3.0)
        })
        .unwrap();
        assert!(
            (e.value - exact).abs() < 3e-15 * exact,
            "{} {}",
            e.value,
            e.error
        );
    }

    #[test]
    fn tanh_sinh_256_bits_reaches_1e70() {
        let a = Float::with_val(256, 0);
        let b = Float::with_val(256, 1);
        // int_0^1 ln(1 + v) / (1 + v^2) dv = pi ln 2 / 8
        let e = tanh_sinh(&a, &b, TsOptions::new(1e-72), |p: &Point<Float>| -> Float {
            let v = p.v.clone();
            Real::ln(v.clone() + 1.0) / (v.clone() * &v + 1.0)
        })
        .unwrap();
        let exact = a.pi() * b.clone().lit(2.0).ln() / 8.0;
        assert!(crate::scalar::rel_diff(&e.value, &exact) < 1e-72);
        assert!(e.error < 1e-60);
    }

    #[test]
    fn gauss_legendre_at_256_bits_integrates_exp_to_full_precision() {
        let r = gauss_legendre_rule::<Float>(40, 256).unwrap();
        let mut acc = Float::with_val(256, 0);
        for (x, w) in r.iter() {
            acc += x.clone().exp() * w;
        }
        let one = Float::with_val(256, 1);
        let exact = one.clone().exp() - (-one).exp();
        assert!(crate::scalar::rel_diff(&acc, &exact) < 1e-74);
    }

    #[test]
    fn endpoint_map_resolves_near_nonintegrable_singularities() {
        // int_0^1 v^(-0.9) (1 - v)^(-0.8) dv = B(0.1, 0.2)
        let exact = 14.599_371_492_764_83; // mpmath beta(0.1, 0.2)
        let opts = TsOptions::new(1e-15)
            .left_singularity(-0.9)
            .right_singularity(-0.8);
        let e = tanh_sinh(&0.0, &1.0, opts, |p: &Point<f64>| {
            p.from_a.powf(-0.9) * p.to_b.powf(-0.8)
        })
        .unwrap();
        assert!(
            (e.value - exact).abs() < 1e-13 * exact,
            "{} {exact}",
            e.value
        );
        // without the declaration the plain rule loses the tails
        let plain = tanh_sinh(&0.0, &1.0, TsOptions::new(1e-15), |p: &Point<f64>| {
            p.from_a.powf(-0.9) * p.to_b.powf(-0.8)
        });
        assert!(plain
            .map(|e| (e.value - exact).abs() > 1e-6)
            .unwrap_or(true));
    }

    #[test]
    fn endpoint_map_reaches_exponents_close_to_minus_one() {
        // int_0^1 v^alpha (1 - v)^(-1/2) (1 + v) dv = B(1 + alpha, 1/2) + B(2 + alpha, 1/2)
        // (mpmath, 30 digits); at alpha = -0.9925, 7 percent of it lies within 1e-300 of 0,
        // beyond f64's range: the map continues the bounded mapped integrand there
        for (alpha, exact) in [
            (-0.962, 29.631_755_397_176_98),
            (-0.9925, 136.705_384_311_714_26),
            (-0.9995, 2_003.385_339_055_123_6),
        ] {
            let opts = TsOptions::new(1e-15)
                .left_singularity(alpha)
                .right_singularity(-0.5);
            let f = |p: &Point<f64>| p.from_a.powf(alpha) * p.to_b.powf(-0.5) * (1.0 + p.v);
            let e = tanh_sinh(&0.0, &1.0, opts, f).unwrap();
            let actual = (e.value - exact).abs();
            assert!(actual < 1e-13 * exact, "alpha {alpha}: {} {exact}", e.value);
            assert!(
                actual <= e.error.max(4.0 * f64::EPSILON * exact),
                "{alpha}: {actual:e} {:e}",
                e.error
            );
            // the same at 128 bits, where no continuation is needed
            let (a, b) = (Float::with_val(128, 0), Float::with_val(128, 1));
            let e = tanh_sinh(
                &a,
                &b,
                TsOptions::new(1e-33)
                    .left_singularity(alpha)
                    .right_singularity(-0.5),
                |p: &Point<Float>| {
                    let al = Float::with_val(128, alpha);
                    Real::powf(p.from_a.clone(), &al) / Real::sqrt(p.to_b.clone())
                        * (p.v.clone() + 1.0)
                },
            )
            .unwrap();
            let x = Float::with_val(128, alpha + 1.0);
            let half = Float::with_val(128, 0.5);
            let beta = |x: Float| -> Float {
                (x.clone().ln_gamma() + half.clone().ln_gamma() - (x + &half).ln_gamma()).exp()
            };
            let exact128 = beta(x.clone()) + beta(x + 1.0);
            assert!(
                crate::scalar::rel_diff(&e.value, &exact128) < 1e-30,
                "{alpha} at 128 bits"
            );
        }
    }

    /// int_0^1 v^(-1 + g) (1 - v)^(-1/2) (1 + v) dv = B(g, 1/2) + B(1 + g, 1/2) at 600 bits.
    fn beta_sum(gap: f64) -> Float {
        let x = Float::with_val(600, gap);
        let half = Float::with_val(600, 0.5);
        let beta = |x: Float| -> Float {
            (x.clone().ln_gamma() + half.clone().ln_gamma() - (x + &half).ln_gamma()).exp()
        };
        beta(x.clone()) + beta(x + 1.0)
    }

    /// The integral of [`beta_sum`] at the precision of `like`, its exponent's gap declared
    /// exactly and the integrand's power formed from the gap (v^(-1 + g) = e^(g ln v)/v).
    fn gap_integral<T: CachedRules>(like: &T, gap: f64, tol: f64) -> (f64, f64) {
        let g = like.lit(gap);
        let opts = TsOptions::new(tol)
            .left_end(EndExponent::from_gap(&g))
            .right_singularity(-0.5);
        let f = |p: &Point<T>| {
            (p.from_a.clone().ln() * &g).exp() / p.from_a.clone() / p.to_b.clone().sqrt()
                * (p.v.clone() + 1.0)
        };
        let e: Quadrature<T> = tanh_sinh(&like.zero(), &like.one(), opts, f).unwrap();
        let exact = beta_sum(gap);
        let actual = Float::with_val(600, e.value.to_mpfr(600) - &exact).abs() / &exact;
        (actual.to_f64(), e.error / exact.to_f64())
    }

    #[test]
    fn endpoint_map_reaches_gaps_far_below_the_exponent_range() {
        // alpha = -1 + gap with gap from 1e-3 (power map) to 1e-100 (exponential map, the tail
        // beyond the floor in closed form): the integral ~ 1/gap, its regular part 3.4, to
        // the working precision in f64, double-double and MPFR, the estimates honest (above
        // a round-off floor of 16 units)
        let floor = |bits: i32| 16.0 * 2f64.powi(-bits);
        for gap in [1e-3, 1e-4, 9e-5, 1e-6, 1e-10, 1e-14, 1e-30, 1e-100] {
            let (a, e) = gap_integral(&0.0_f64, gap, 1e-15);
            assert!(
                a < 1e-15 && a <= e.max(floor(53)),
                "f64 gap {gap:e}: {a:e} {e:e}"
            );
            let (a, e) = gap_integral(&crate::Dd::from_f64(0.0), gap, 1e-30);
            assert!(
                a < 1e-30 && a <= e.max(floor(104)),
                "double-double gap {gap:e}: {a:e} {e:e}"
            );
            let (a, e) = gap_integral(&Float::with_val(165, 0), gap, 1e-45);
            assert!(
                a < 1e-45 && a <= e.max(floor(165)),
                "165 bits gap {gap:e}: {a:e} {e:e}"
            );
        }
    }

    #[test]
    fn gauss_jacobi_cached_and_exact_for_weighted_polynomials() {
        // int_{-1}^{1} (1-x)^(-1/2) (1+x)^(1/3) x^2 dx
        let r = gauss_jacobi(8, -0.5, 1.0 / 3.0).unwrap();
        let r2 = gauss_jacobi(8, -0.5, 1.0 / 3.0).unwrap();
        assert!(Arc::ptr_eq(&r, &r2));
        let q: f64 = r.integrate(-1.0, 1.0, |p: &Point<f64>| p.v * p.v);
        let e = tanh_sinh(&-1.0, &1.0, TsOptions::new(1e-15), |p: &Point<f64>| {
            p.to_b.powf(-0.5) * p.from_a.powf(1.0 / 3.0) * p.v * p.v
        })
        .unwrap();
        assert!((q - e.value).abs() < 1e-13, "{q} {}", e.value);
    }
}
