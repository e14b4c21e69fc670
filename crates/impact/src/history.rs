//! The fast history sum of the march (`docs/impact.md`, section 7).
//!
//! At step t (0-based) the march needs the displacements of the cells due to all past steps,
//!
//! ```text
//!   H_i(t) = sum_{s < t} sum_j A(i, j, t - s) p_j(s),   A(i, j, l) = dx [a(|i - j|, l) + a(i + j, l)]
//! ```
//!
//! (the mirror term only for j > 0: cell j stands for itself and its mirror image). Written on
//! the symmetric extension p~_j' = p_|j'|, j' in (-W, W), the space sum is a plain Toeplitz
//! convolution, sum_j' a(|i - j'|, l) p~_j', and the whole sum a two-dimensional convolution in
//! (time, space). The naive sum costs O(N_t^2 N_x^2).
//!
//! Here the pairs (s, t), s < t, are tiled by squares, as in the fast convolution of Hairer,
//! Lubich and Schlichte: a pair belongs to level q, the highest bit in which s and t differ,
//! and the pairs of level q with the same higher bits form the square of sources
//! [c - 2^q, c) and targets [c, c + 2^q), c an odd multiple of 2^q. That square is complete as
//! soon as step c - 1 has been solved, just when its first target is needed: after the c-th
//! step the square of level q = (trailing zeros of c) is added into accumulators of its
//! targets. Small squares (2^q < `DIRECT_BELOW`) are summed directly; larger ones by a 2-D FFT
//! of size 2^(q+1) x 4W, exact (no wrap-around) because the lags of a square run over
//! [1, 2^(q+1) - 1] and the space offsets i - j' over (-W, 2W). The kernel's transform
//! depends on the level only (the kernel is Toeplitz in time), so it is formed once per level.
//! The cost is O(N_t log^2 N_t W log W) instead of O(N_t^2 W^2).
//!
//! The width W (a power of two) grows with the contact: when a step asks for more cells, the
//! accumulators of the pending targets are rebuilt at the new width from the squares that
//! reach them (one per level).

use std::sync::Arc;

use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};

use complexfn::quadrature::CachedRules;

use crate::error::{ImpactError, Result};
use crate::scalar::Scalar;
use crate::striker::Compliance;
use crate::tables::Tables;

/// Squares with fewer steps than this are summed directly.
const DIRECT_BELOW: usize = 8;

/// Smallest width (cells) of the space dimension.
const MIN_WIDTH: usize = 8;

/// A source of influence rows: the unscaled row a(., l) and its scale (the half-plane's tables,
/// or a striker's compliance).
pub trait KernelRows<T = f64> {
    /// Makes a(k, l) available for k <= kmax and l <= lmax.
    fn ensure_rows(&mut self, kmax: usize, lmax: usize) -> Result<()>;
    /// The row a(., l) and its scale.
    fn scaled_row(&self, l: usize) -> (&[T], T);
    /// The largest k with a(k, l) possibly not zero (causality), `None` when every k may be.
    fn reach(&self, l: usize) -> Option<usize>;
}

impl<T: Scalar + CachedRules> KernelRows<T> for Tables<T> {
    fn ensure_rows(&mut self, kmax: usize, lmax: usize) -> Result<()> {
        self.ensure(kmax, lmax)
    }
    fn scaled_row(&self, l: usize) -> (&[T], T) {
        (self.row(l), T::of(1.0))
    }
    fn reach(&self, l: usize) -> Option<usize> {
        Some(self.reach_at(l))
    }
}

impl KernelRows for Compliance {
    fn ensure_rows(&mut self, kmax: usize, lmax: usize) -> Result<()> {
        self.ensure(kmax, lmax)
    }
    fn scaled_row(&self, l: usize) -> (&[f64], f64) {
        self.row(l)
    }
    fn reach(&self, l: usize) -> Option<usize> {
        self.reach_at(l)
    }
}

/// The history sum of one kernel: the pressures of the steps so far and the accumulated
/// displacements of the steps to come.
pub(crate) struct HistorySum<T = f64> {
    /// The factor of every coefficient (dx: A = dx a).
    scale: T,
    /// Width W of the space dimension (a power of two).
    width: usize,
    /// The last step that will be asked for (no target beyond it is accumulated).
    horizon: Option<usize>,
    /// The pressures of the steps pushed so far.
    pressures: Vec<Vec<T>>,
    /// acc[t - first]: the displacement at cells 0..W of target step t from the squares
    /// summed so far; `first` is the first target not yet consumed.
    acc: std::collections::VecDeque<Vec<T>>,
    first: usize,
    /// The kernel's transform by level, laid out [space][time] (space 4W, time 2^(q+1)), for
    /// the current width.
    levels: Vec<Option<Vec<Complex<f64>>>>,
    planner: Planner,
}

/// The FFT planner behind non-generic calls: the planner's code is compiled once, here, not
/// again in every crate that instantiates [`HistorySum`] (its generic code is most of a
/// test binary's).
pub(crate) struct Planner(FftPlanner<f64>);

impl Planner {
    #[inline(never)]
    pub(crate) fn new() -> Self {
        Planner(FftPlanner::new())
    }

    /// Plans for size n (forward and inverse).
    #[inline(never)]
    pub(crate) fn plans(&mut self, n: usize) -> (Arc<dyn Fft<f64>>, Arc<dyn Fft<f64>>) {
        (self.0.plan_fft_forward(n), self.0.plan_fft_inverse(n))
    }
}

impl<T: Scalar> HistorySum<T> {
    /// An empty history for coefficients scaled by `scale` (dx), accumulating targets up to
    /// `horizon` steps (all, when `None`).
    pub(crate) fn new(scale: T, horizon: Option<usize>) -> Self {
        HistorySum {
            scale,
            width: MIN_WIDTH,
            horizon,
            pressures: Vec::new(),
            acc: std::collections::VecDeque::new(),
            first: 0,
            levels: Vec::new(),
            planner: Planner::new(),
        }
    }

    /// Accumulates no target beyond `horizon` steps (the run's length).
    pub(crate) fn set_horizon(&mut self, horizon: usize) {
        self.horizon = Some(horizon);
    }

    /// Number of steps pushed.
    pub(crate) fn len(&self) -> usize {
        self.pressures.len()
    }

    /// Whether target t is accumulated at all.
    fn wanted(&self, t: usize) -> bool {
        self.horizon.is_none_or(|h| t < h)
    }

    /// The accumulator of target t (created zero when absent).
    fn acc_mut(&mut self, t: usize) -> &mut Vec<T> {
        let idx = t - self.first;
        while self.acc.len() <= idx {
            self.acc.push_back(vec![T::of(0.0); self.width]);
        }
        &mut self.acc[idx]
    }

    /// Records the pressures of the next step (cells 0, 1, ...) and adds the square it
    /// completes.
    pub(crate) fn push(
        &mut self,
        kernel: &mut (impl KernelRows<T> + ?Sized),
        p: &[T],
    ) -> Result<()> {
        if p.len() > self.width {
            self.grow(kernel, p.len())?;
        }
        self.pressures.push(p.to_vec());
        let c = self.pressures.len();
        self.square(kernel, c, c)
    }

    /// The displacements at cells 0..=imax of the next target step (step `len()`, 0-based)
    /// due to every step pushed.
    pub(crate) fn at(
        &mut self,
        kernel: &mut (impl KernelRows<T> + ?Sized),
        imax: usize,
    ) -> Result<Vec<T>> {
        if imax + 1 > self.width {
            self.grow(kernel, imax + 1)?;
        }
        let t = self.pressures.len();
        if !self.wanted(t) {
            return Err(ImpactError::Step {
                time: format!("step {}", t + 1),
                reason: "past the horizon the history sum was built for".into(),
            });
        }
        // drop the targets already consumed
        while self.first < t {
            self.acc.pop_front();
            self.first += 1;
        }
        let row = self.acc_mut(t);
        Ok(row[..=imax].to_vec())
    }

    /// Widens the space dimension to at least `cells` and rebuilds the pending targets'
    /// accumulators from the squares that reach them (one per level).
    fn grow(&mut self, kernel: &mut (impl KernelRows<T> + ?Sized), cells: usize) -> Result<()> {
        let mut w = self.width;
        while w < cells {
            w *= 2;
        }
        self.width = w;
        self.levels.clear();
        self.acc.clear();
        let count = self.pressures.len();
        self.first = count;
        let mut c = 1;
        while c <= count {
            let len = 1usize << c.trailing_zeros();
            if c + len > count {
                self.square(kernel, c, count)?;
            }
            c += 1;
        }
        Ok(())
    }

    /// Adds the square completed by the c-th step, sources [c - L, c) and targets [c, c + L),
    /// L = 2^(trailing zeros of c), into the accumulators of the targets >= `from`.
    fn square(
        &mut self,
        kernel: &mut (impl KernelRows<T> + ?Sized),
        c: usize,
        from: usize,
    ) -> Result<()> {
        let len = 1usize << c.trailing_zeros();
        let t_end = match self.horizon {
            Some(h) => (c + len).min(h),
            None => c + len,
        };
        if t_end <= from.max(c) {
            return Ok(());
        }
        // lags up to the last target's from the first source
        let lag_max = t_end - 1 - (c - len);
        kernel.ensure_rows(2 * self.width, lag_max.max(1))?;
        // the FFT's rounding is f64's: other precisions sum every square directly
        if len < DIRECT_BELOW || !T::FFT {
            self.direct(kernel, c, len, from.max(c), t_end);
            Ok(())
        } else {
            self.by_fft(kernel, c, len, from.max(c), t_end, lag_max)
        }
    }

    /// The square summed directly (Toeplitz plus mirror rows).
    fn direct(
        &mut self,
        kernel: &(impl KernelRows<T> + ?Sized),
        c: usize,
        len: usize,
        t0: usize,
        t1: usize,
    ) {
        let w = self.width;
        let scale = self.scale;
        for t in t0..t1 {
            if !self.wanted(t) {
                continue;
            }
            let mut out = vec![T::of(0.0); w];
            for s in c - len..c {
                let (row, f) = kernel.scaled_row(t - s);
                let f = f * scale;
                // a source reaches only the cells within the kernel's reach at this lag
                let r = kernel.reach(t - s).unwrap_or(2 * w).min(2 * w);
                for (j, &pj) in self.pressures[s].iter().enumerate() {
                    if pj == 0.0 {
                        continue;
                    }
                    let pj = pj * f;
                    let near = j.saturating_sub(r)..(j + r + 1).min(w);
                    for (i, o) in out[near.clone()].iter_mut().enumerate() {
                        *o += row[(i + near.start).abs_diff(j)] * pj;
                    }
                    // the mirror cell -j reaches the cells i with i + j <= r
                    if j > 0 && j <= r {
                        for (i, o) in out[..(r + 1 - j).min(w)].iter_mut().enumerate() {
                            *o += row[i + j] * pj;
                        }
                    }
                }
            }
            let acc = self.acc_mut(t);
            for (a, o) in acc.iter_mut().zip(out) {
                *a += o;
            }
        }
    }

    /// The 2-D transform, in place, of data laid out [time][space] (nt x ns), returned laid
    /// out [space][time].
    fn forward_2d(&mut self, data: &mut [Complex<f64>], nt: usize, ns: usize) -> Vec<Complex<f64>> {
        let (fs, _) = self.planner.plans(ns);
        let (ft, _) = self.planner.plans(nt);
        fs.process(data);
        let mut tr = vec![Complex::default(); nt * ns];
        for t in 0..nt {
            for s in 0..ns {
                tr[s * nt + t] = data[t * ns + s];
            }
        }
        ft.process(&mut tr);
        tr
    }

    /// The kernel's transform for a square of `len` steps at the current width: K[lag][k mod M]
    /// = scale a(|k|, lag) for lags 1 ..= lag_max (< 2 len) and k in (-W, 2W).
    fn kernel_spectrum(
        &mut self,
        kernel: &(impl KernelRows<T> + ?Sized),
        len: usize,
        lag_max: usize,
    ) -> Vec<Complex<f64>> {
        let (nt, w) = (2 * len, self.width);
        let ns = 4 * w;
        let mut data = vec![Complex::default(); nt * ns];
        for lag in 1..=lag_max.min(nt - 1) {
            let (row, f) = kernel.scaled_row(lag);
            let f = (f * self.scale).to_f64();
            let line = &mut data[lag * ns..(lag + 1) * ns];
            for k in 0..2 * w {
                line[k] = Complex::new(row[k].to_f64() * f, 0.0);
            }
            for k in 1..w {
                line[ns - k] = Complex::new(row[k].to_f64() * f, 0.0);
            }
        }
        self.forward_2d(&mut data, nt, ns)
    }

    /// The square by a 2-D FFT of size 2L x 4W.
    fn by_fft(
        &mut self,
        kernel: &(impl KernelRows<T> + ?Sized),
        c: usize,
        len: usize,
        t0: usize,
        t1: usize,
        lag_max: usize,
    ) -> Result<()> {
        let q = len.trailing_zeros() as usize;
        let (nt, w) = (2 * len, self.width);
        let ns = 4 * w;
        if self.levels.len() <= q {
            self.levels.resize_with(q + 1, || None);
        }
        // with a horizon the last squares see fewer lags: their kernel is not the level's
        let full = self.horizon.is_none_or(|h| c + len <= h);
        let spectrum = if full {
            if self.levels[q].is_none() {
                self.levels[q] = Some(self.kernel_spectrum(kernel, len, nt - 1));
            }
            None
        } else {
            Some(self.kernel_spectrum(kernel, len, lag_max))
        };
        // the sources, on the symmetric extension p~_j' = p_|j'|
        let mut data = vec![Complex::default(); nt * ns];
        for (sigma, p) in self.pressures[c - len..c].iter().enumerate() {
            let line = &mut data[sigma * ns..(sigma + 1) * ns];
            for (j, pj) in p.iter().enumerate() {
                let pj = pj.to_f64();
                line[j] = Complex::new(pj, 0.0);
                if j > 0 {
                    line[ns - j] = Complex::new(pj, 0.0);
                }
            }
        }
        let mut tr = self.forward_2d(&mut data, nt, ns);
        let ker = match &spectrum {
            Some(s) => s.as_slice(),
            None => self.levels[q].as_deref().unwrap_or(&[]),
        };
        for (a, b) in tr.iter_mut().zip(ker) {
            *a *= b;
        }
        // inverse: time (on the [space][time] layout), then space for the target rows
        let (_, it) = self.planner.plans(nt);
        let (_, is) = self.planner.plans(ns);
        it.process(&mut tr);
        let norm = 1.0 / (nt * ns) as f64;
        let mut line = vec![Complex::default(); ns];
        for t in t0..t1 {
            if !self.wanted(t) {
                continue;
            }
            let nu = t - c + len;
            for (s, v) in line.iter_mut().enumerate() {
                *v = tr[s * nt + nu];
            }
            is.process(&mut line);
            let acc = self.acc_mut(t);
            for (a, v) in acc.iter_mut().zip(&line) {
                *a += T::of(v.re * norm);
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lamb::HalfPlane;

    /// The naive sum at target t over cells 0..=imax.
    fn naive(tables: &Tables, dx: f64, pressures: &[Vec<f64>], imax: usize) -> Vec<f64> {
        let t = pressures.len();
        let mut out = vec![0.0; imax + 1];
        for (s, p) in pressures.iter().enumerate() {
            let row = tables.row(t - s);
            for (j, &pj) in p.iter().enumerate() {
                for (i, o) in out.iter_mut().enumerate() {
                    let a = row[i.abs_diff(j)] + if j > 0 { row[i + j] } else { 0.0 };
                    *o += a * pj * dx;
                }
            }
        }
        out
    }

    /// The fast sum equals the naive one at every step of a march-like history: a contact
    /// that grows from one cell to 37 and shrinks again (so the width doubles twice and the
    /// pending targets are rebuilt), pressures of either sign, 300 steps (squares up to 128
    /// steps by FFT), with and without a horizon.
    #[test]
    fn fast_history_equals_the_naive_sum() {
        let hp = HalfPlane::from_poisson(0.3).unwrap();
        let mut tables = Tables::new(hp, 2.0).unwrap();
        let dx = 0.01;
        let n = 300;
        for horizon in [None, Some(n), Some(200)] {
            let mut fast = HistorySum::new(dx, horizon);
            let mut pressures: Vec<Vec<f64>> = Vec::new();
            let mut worst: f64 = 0.0;
            let steps = horizon.unwrap_or(n).min(n);
            for t in 0..steps {
                let k = ((t as f64 * 0.2).min(36.0) - (t as f64 - 220.0).max(0.0) * 0.3).max(0.0)
                    as usize;
                let imax = k + 3;
                tables.ensure(2 * imax + 2, t + 1).unwrap();
                let want = naive(&tables, dx, &pressures, imax);
                let got = fast.at(&mut tables, imax).unwrap();
                let scale = want.iter().fold(1e-300f64, |m, v| m.max(v.abs()));
                for (g, w) in got.iter().zip(&want) {
                    let d = (g - w).abs() / scale;
                    worst = worst.max(d);
                    assert!(
                        d < 1e-12,
                        "step {t} (horizon {horizon:?}): {g} fast, {w} naive"
                    );
                }
                let p: Vec<f64> = (0..=k)
                    .map(|j| {
                        (1.0 + 0.3 * (t as f64 * 0.37 + j as f64).sin()) * (1.0 - j as f64 * 0.01)
                    })
                    .collect();
                fast.push(&mut tables, &p).unwrap();
                pressures.push(p);
            }
            println!("horizon {horizon:?}: largest relative difference {worst:e}");
            assert_eq!(fast.len(), steps);
        }
    }

    /// In double-double every square is summed directly: the history equals the naive sum
    /// in double-double to its rounding, and the f64 history (by FFT) to f64's.
    #[test]
    fn double_double_history_is_the_naive_sum() {
        use complexfn::{Dd, Real};
        let nu = 0.3;
        let mut tables =
            Tables::new(HalfPlane::from_poisson(Dd::of(nu)).unwrap(), Dd::of(2.0)).unwrap();
        let mut tables64 = Tables::new(HalfPlane::from_poisson(nu).unwrap(), 2.0).unwrap();
        let dx = 0.01;
        let n = 80;
        let mut fast = HistorySum::new(Dd::of(dx), None);
        let mut fast64 = HistorySum::new(dx, None);
        let mut pressures: Vec<Vec<Dd>> = Vec::new();
        let (mut worst, mut worst64, mut size) = (0.0f64, 0.0f64, 0.0f64);
        for t in 0..n {
            let k = (t as f64 * 0.3).min(20.0) as usize;
            let imax = k + 3;
            tables.ensure(2 * imax + 2, t + 1).unwrap();
            // the naive sum in double-double
            let mut want = vec![Dd::of(0.0); imax + 1];
            for (s, p) in pressures.iter().enumerate() {
                let row = tables.row(t - s);
                for (j, &pj) in p.iter().enumerate() {
                    for (i, o) in want.iter_mut().enumerate() {
                        let mirror = if j > 0 { row[i + j] } else { Dd::of(0.0) };
                        *o += (row[i.abs_diff(j)] + mirror) * pj * dx;
                    }
                }
            }
            let got = fast.at(&mut tables, imax).unwrap();
            let got64 = fast64.at(&mut tables64, imax).unwrap();
            for ((g, w), g64) in got.iter().zip(&want).zip(&got64) {
                worst = worst.max((*g - *w).abs().to_f64());
                worst64 = worst64.max((g64 - w.to_f64()).abs());
                size = size.max(w.abs().to_f64());
            }
            let p: Vec<Dd> = (0..=k)
                .map(|j| Dd::of(1.0 + 0.3 * j as f64) / Dd::of(3.0 + t as f64))
                .collect();
            fast.push(&mut tables, &p).unwrap();
            fast64
                .push(
                    &mut tables64,
                    &p.iter().map(|v| v.to_f64()).collect::<Vec<_>>(),
                )
                .unwrap();
            pressures.push(p);
        }
        let (worst, worst64) = (worst / size, worst64 / size);
        assert!(worst < 1e-30, "double-double against naive: {worst:e}");
        // f64 carries its tables' rounding (1.5e-14 absolute in the coefficients, the
        // tables' test), summed over the history
        assert!(worst64 < 1e-12, "f64 against double-double: {worst64:e}");
        eprintln!("largest relative differences: double-double {worst:.1e}, f64 {worst64:.1e}");
    }
}
