//! One grid's march history ([`Run`]) and its smoothed reads: the edge and the force at a
//! step, averaged over the sawtooth of the cell crossings (`docs/impact.md`, section 4).

use crate::march::StepState;
use crate::scalar::Scalar;

/// One grid's history, at the precision T.
#[derive(Clone, Debug)]
pub struct Run<T = f64> {
    /// Cell width (units R).
    pub dx: T,
    /// Time step (units R/c1).
    pub dt: T,
    /// The steps.
    pub steps: Vec<StepState<T>>,
    /// Steps marched past the run's end, only so that the smoothed reports of its last
    /// steps ([`Run::edge_at`], [`Run::force_at`]) take whole windows centred on them, not
    /// one-sided fits (`docs/impact.md`, section 4; empty where the run could not go on).
    pub beyond: Vec<StepState<T>>,
    /// The defect the start's last hand-over left on this grid, which its steps after it take
    /// off their history sums ([`HandoverDefect`]; `None` without one).
    pub handover: Option<HandoverDefect<T>>,
    /// The times the contact ended, in order (the end of the last step in contact).
    pub separations: Vec<T>,
    /// The times contact began again after a separation.
    pub reimpacts: Vec<T>,
    /// A bound of the error of the normalised influence coefficients used (quadrature of the
    /// half-plane's and an elastic striker's tables, truncation of a shell's modal sums).
    pub coefficient_error: f64,
}

/// The reported edge's smoothing window, in cell crossings (`Run::edge_at`).
pub const EDGE_CROSSINGS: f64 = 3.0;

/// The largest window of the reported edge's smoothing, in steps (`Run::edge_at`).
pub const EDGE_WINDOW_STEPS: usize = 40;

/// The coefficients of the reports' quadratic and of the quartic it is tested against
/// (`Run::crossing_fit`).
const QUADRATIC: usize = 3;
const QUARTIC: usize = 5;

/// The coefficients of the leading k x k block of the normal equations `m` (row-major,
/// stride [`QUARTIC`]) and `r`.
fn solve_leading<T: Scalar>(
    m: &[T; QUARTIC * QUARTIC],
    r: &[T; QUARTIC],
    k: usize,
) -> Option<Vec<T>> {
    let block: Vec<T> = (0..k)
        .flat_map(|i| m[QUARTIC * i..QUARTIC * i + k].iter().copied())
        .collect();
    complexfn::linalg::Lu::new(block, k).and_then(|lu| lu.solve(&r[..k]))
}

/// The smallest half-window (in steps) whose quadratic is tested against the quartic
/// (`Run::crossing_fit`).
const FIT_TEST_HALF: usize = 8;

/// How many standard errors the quartic's value may differ from the quadratic's before the
/// window is halved (`Run::crossing_fit`).
const FIT_TEST_SIGMAS: f64 = 3.0;

/// The largest window of the reported force's smoothing, in steps (`Run::force_at`): one
/// crossing takes 1/(kappa |db/dt|) steps on every grid (37 near the reference case's peak
/// force), and three of them are needed to average the force's sawtooth out
/// (`docs/impact.md`, section 4).
pub const FORCE_WINDOW_STEPS: usize = 120;

/// The steps a march goes on past a step so that the smoothed reports of that step take
/// whole windows centred on it ([`Run::edge_at`], [`Run::force_at`]): half of
/// [`EDGE_CROSSINGS`] cell crossings at the edge's speed `speed` (units c1; at most half of
/// [`FORCE_WINDOW_STEPS`]), and two more. At most [`WINDOW_MARGIN_MAX`].
pub(crate) fn window_margin(speed: f64, dx: f64, dt: f64) -> usize {
    let crossings = EDGE_CROSSINGS * dx / (dt * speed.abs().max(1e-300));
    (0.5 * crossings.min(FORCE_WINDOW_STEPS as f64)).ceil() as usize + 2
}

/// The largest [`window_margin`].
pub(crate) const WINDOW_MARGIN_MAX: usize = FORCE_WINDOW_STEPS / 2 + 2;

/// The most steps a run of `steps` steps marches past its end ([`Run::beyond`]): up to the
/// next power of two, where the fast history sum's next square, as long as the run so far,
/// would be summed for them alone (`crate::history`), and at most [`WINDOW_MARGIN_MAX`].
pub(crate) fn end_margin(steps: usize) -> usize {
    (steps.next_power_of_two() - steps).min(WINDOW_MARGIN_MAX)
}

/// The defect of a grid's displacements at the step a finer grid handed over
/// (`docs/impact.md`, section 11, the last hand-over's defect): this grid's displacements of
/// that step's merged pressures less the merged displacements, on the cells inside its
/// contact. The m-th step after it takes `weight` times the defect off its history sums, so
/// its contact conditions read w_i - weight d_i = h - mean f_i.
#[derive(Clone, Debug)]
pub struct HandoverDefect<T = f64> {
    /// The step handed over (the steps after it carry the defect).
    pub step: usize,
    /// The defect of the cells inside the contact; beyond them, the last one's.
    pub defect: Vec<T>,
    /// K: the steps over which it is let go.
    pub decay_steps: f64,
}

impl<T: Scalar> HandoverDefect<T> {
    /// The defect's weight at step n: (1 - m/K)^2 at the m-th step after the hand-over, 0
    /// from K on.
    pub fn weight(&self, n: usize) -> f64 {
        let m = n.saturating_sub(self.step) as f64;
        if n > self.step && m < self.decay_steps {
            (1.0 - m / self.decay_steps).powi(2)
        } else {
            0.0
        }
    }

    /// The defect of cell i (beyond the cells inside the contact, the last one's).
    pub fn at(&self, i: usize) -> T {
        self.defect
            .get(i)
            .or(self.defect.last())
            .copied()
            .unwrap_or(T::of(0.0))
    }
}

impl<T: Scalar> Run<T> {
    /// Step n (time t_n = n dt, n >= 1), if the march reached it.
    pub fn step(&self, n: usize) -> Option<&StepState<T>> {
        n.checked_sub(1).and_then(|i| self.steps.get(i))
    }

    /// Whether the last step's smoothed reports ([`Run::edge_at`], [`Run::force_at`]) take
    /// whole windows: the run marched past its end ([`Run::beyond`]), or it is out of
    /// contact at its end (its windows closed with the contact).
    pub fn last_reports_centred(&self) -> bool {
        !self.beyond.is_empty() || self.steps.last().is_none_or(|s| s.pressure.is_empty())
    }

    /// Step n for the smoothing windows: the steps, then those marched past the end.
    fn window_step(&self, n: usize) -> Option<&StepState<T>> {
        let i = n.checked_sub(1)?;
        self.steps
            .get(i)
            .or_else(|| self.beyond.get(i - self.steps.len()))
    }

    /// The contact half-width at t_n (`docs/impact.md`, section 4, the edge's report): the
    /// edge of step n where it stands for t_n (geometric); otherwise the value at t_n of the
    /// least-squares quadratic through the steps' edges (at the times they stand for) over a
    /// window of [`EDGE_CROSSINGS`] cell crossings centred on t_n (at most
    /// [`EDGE_WINDOW_STEPS`] steps, narrowed to stay symmetric within the steps whose edges
    /// the pressures set), which averages out the edge's phase error within its cell; where
    /// the window holds fewer than five edges, the edges of the two steps around t_n
    /// interpolated. A step marched on a finer grid reports that grid's edge
    /// ([`StepState::finer`]).
    pub fn edge_at(&self, n: usize) -> Option<T> {
        let s = self.step(n)?;
        if let Some((b, _)) = s.finer {
            return Some(b);
        }
        if s.edge_time == s.t {
            return Some(s.b);
        }
        let mid = |x: &StepState<T>| x.edge_time != x.t && x.b > 0.0;
        self.crossing_fit(n, EDGE_WINDOW_STEPS, false, mid, |x| (x.edge_time, x.b))
            .or_else(|| self.edge_interpolated(n))
    }

    /// The value at t_n of the least-squares quadratic through `value` (time, value) of the
    /// steps in a window of [`EDGE_CROSSINGS`] cell crossings of the edge centred on step n,
    /// at most `cap` steps and narrowed to stay symmetric within the block of steps around n
    /// that satisfy `eligible` (n among them); `None` where the window holds fewer than five
    /// steps (`docs/impact.md`, section 4: the edge's phase within its cell leaves a sawtooth
    /// of one crossing's period in the per-step values, which the fit averages out).
    fn crossing_fit(
        &self,
        n: usize,
        cap: usize,
        test_curvature: bool,
        eligible: impl Fn(&StepState<T>) -> bool,
        value: impl Fn(&StepState<T>) -> (T, T),
    ) -> Option<T> {
        let ok = |m: usize| self.window_step(m).is_some_and(&eligible);
        if !ok(n) {
            return None;
        }
        // the block of eligible steps around n
        let (mut first, mut last) = (n, n);
        while first > 1 && ok(first - 1) && n - first < cap {
            first -= 1;
        }
        while ok(last + 1) && last - n < cap {
            last += 1;
        }
        // the window (a choice of steps, taken in f64)
        let (dx, dt) = (self.dx.to_f64(), self.dt.to_f64());
        let b = |m: usize| self.window_step(m).map_or(0.0, |x| x.b.to_f64());
        let k = (n - first).min(last - n).min(5);
        let speed = if k > 0 {
            ((b(n + k) - b(n - k)) / (2.0 * k as f64 * dt)).abs()
        } else {
            0.0
        };
        let steps = (EDGE_CROSSINGS * dx / (speed * dt)).min(cap as f64);
        let half = ((0.5 * steps) as usize).min(n - first).min(last - n);
        if half < 2 {
            return None;
        }
        // the quadratic's value at t_n, over windows halved while the quartic through the same
        // steps differs from it at t_n by more than the scatter allows: then the window is
        // wider than the history is a quadratic (a nearly still edge on a coarse grid: the
        // cap in steps is a long time), and the crossings' sawtooth no longer dominates what
        // the fit averages
        let mut half = half;
        let dims = if test_curvature { QUARTIC } else { QUADRATIC };
        loop {
            // one pass: the quartic's normal equations, whose leading block is the quadratic's
            let (m, r) = self.normal_equations(n, half, dims, &value)?;
            let quadratic = solve_leading(&m, &r, QUADRATIC)?[0];
            if !test_curvature || half < FIT_TEST_HALF {
                return Some(quadratic);
            }
            let c = solve_leading(&m, &r, QUARTIC)?;
            let scatter = self.scatter(n, half, &c, &value)?;
            // the quartic's value at the centre differs from the quadratic's by its P4 term,
            // whose standard error over 2 half + 1 evenly spread steps is
            // scatter (81/(64 (2 half + 1)))^(1/2)
            let spread = scatter * (81.0 / (64.0 * (2 * half + 1) as f64)).sqrt();
            if (quadratic - c[0]).abs().to_f64() <= FIT_TEST_SIGMAS * spread {
                return Some(quadratic);
            }
            half /= 2;
        }
    }

    /// The window's abscissa x = (time - t_n)/width of a step's (time, value), and its powers
    /// 1, x, ..., x^(QUARTIC - 1).
    fn powers(&self, n: usize, half: usize, time: T) -> Option<[T; QUARTIC]> {
        let width = self.dt * (half as f64 + 0.5);
        let x = (time - self.step(n)?.t) / width;
        let mut phi = [T::of(1.0); QUARTIC];
        for i in 1..QUARTIC {
            phi[i] = phi[i - 1] * x;
        }
        Some(phi)
    }

    /// The normal equations of the least-squares polynomial with `dims` coefficients through
    /// `value` (time, value) of steps n - half ..= n + half, in x = (time - t_n)/width: the
    /// leading dims x dims block of the matrix (row-major, stride QUARTIC) and of the right
    /// side are filled, each entry summed over the steps in order (so the quadratic's block is
    /// the same whether or not the quartic's is summed with it).
    fn normal_equations(
        &self,
        n: usize,
        half: usize,
        dims: usize,
        value: &impl Fn(&StepState<T>) -> (T, T),
    ) -> Option<([T; QUARTIC * QUARTIC], [T; QUARTIC])> {
        let zero = T::of(0.0);
        let (mut m, mut r) = ([zero; QUARTIC * QUARTIC], [zero; QUARTIC]);
        for j in n - half..=n + half {
            let (time, v) = value(self.window_step(j)?);
            let phi = self.powers(n, half, time)?;
            for i in 0..dims {
                for (mij, &pj) in m[QUARTIC * i..QUARTIC * i + dims].iter_mut().zip(&phi) {
                    *mij += phi[i] * pj;
                }
                r[i] += phi[i] * v;
            }
        }
        Some((m, r))
    }

    /// The root mean square, over the degrees of freedom, of the residuals of the polynomial
    /// `c` (in x = (time - t_n)/width) through the steps n - half ..= n + half, in f64.
    fn scatter(
        &self,
        n: usize,
        half: usize,
        c: &[T],
        value: &impl Fn(&StepState<T>) -> (T, T),
    ) -> Option<f64> {
        let mut ssr = 0.0;
        for j in n - half..=n + half {
            let (time, v) = value(self.window_step(j)?);
            let phi = self.powers(n, half, time)?;
            let fit = phi
                .iter()
                .zip(c)
                .fold(T::of(0.0), |a, (&p, &ci)| a + p * ci);
            ssr += (v - fit).to_f64().powi(2);
        }
        let dof = (2 * half + 1).saturating_sub(c.len()).max(1) as f64;
        Some((ssr / dof).sqrt())
    }

    /// The edge at t_n interpolated between the edges of the steps around it by the times
    /// they stand for (`StepState::edge_time`; the last step's extrapolated from the two
    /// before).
    pub fn edge_interpolated(&self, n: usize) -> Option<T> {
        let s = self.step(n)?;
        let (a, b) = match (
            self.window_step(n + 1),
            n.checked_sub(1).and_then(|m| self.step(m)),
        ) {
            (Some(next), _) => (s, next),
            (None, Some(before)) => (before, s),
            (None, None) => return Some(s.b),
        };
        let span = b.edge_time - a.edge_time;
        if !(span > 0.0) {
            return Some(s.b);
        }
        Some(a.b + (b.b - a.b) * (s.t - a.edge_time) / span)
    }

    /// The force at t_n (`docs/impact.md`, sections 3 and 4): a step's force stands for the
    /// middle of the step, and it carries the sawtooth of the edge's cell crossings (large
    /// under the kinematic law, whose edge cell has no condition of its own), so the value at
    /// t_n of the least-squares quadratic through the steps' forces over a window of
    /// [`EDGE_CROSSINGS`] cell crossings (at most [`FORCE_WINDOW_STEPS`] steps, symmetric
    /// within the steps in contact); where that window holds fewer than five steps,
    /// [`Run::force_interpolated`]. Where the edge is free (placed by the step's pressures,
    /// its time the step's middle) the window is halved while the history is no quadratic
    /// over it (`Run::crossing_fit`); a geometric edge's (the kinematic law's, the supersonic
    /// stage's) keeps its window, as its phase error near a standstill would read as
    /// curvature. A step marched on a finer grid reports that grid's force
    /// ([`StepState::finer`]).
    pub fn force_at(&self, n: usize) -> Option<T> {
        let s = self.step(n)?;
        if let Some((_, f)) = s.finer {
            return Some(f);
        }
        let free_edge = s.edge_time != s.t;
        let dt = self.dt;
        self.crossing_fit(
            n,
            FORCE_WINDOW_STEPS,
            free_edge,
            |x| !x.pressure.is_empty(),
            |x| (x.t - dt * 0.5, x.force),
        )
        .or_else(|| self.force_interpolated(n))
    }

    /// The force at t_n from the two steps around it (their forces stand for the middles of
    /// the steps): their mean, the last step's extrapolated from the two before it.
    pub fn force_interpolated(&self, n: usize) -> Option<T> {
        let f = |n: usize| self.window_step(n).map(|s| s.force);
        match (f(n), f(n + 1)) {
            (Some(a), Some(b)) => Some((a + b) * 0.5),
            (Some(a), None) if n >= 2 => f(n - 1).map(|z| a * 1.5 - z * 0.5),
            (a, _) => a,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A run whose edges follow a smooth b(t) plus a sawtooth of one cell crossing's period
    /// and zero mean (the phase error of the edge cell), at the middle of each step.
    fn sawtooth_run(amplitude: f64) -> (Run, impl Fn(f64) -> f64) {
        let (dx, dt) = (0.01, 0.02);
        let truth = |t: f64| 0.05 + 0.05 * t - 0.002 * t * t;
        let steps = (1..=400)
            .map(|n| {
                let t = n as f64 * dt;
                let tau = t - 0.5 * dt;
                let phase = (truth(tau) / dx).fract();
                StepState {
                    t,
                    h: 0.0,
                    v: 0.0,
                    k: 0,
                    b: truth(tau) + amplitude * dx * (phase - 0.5),
                    edge_time: tau,
                    force: 0.0,
                    pressure: Vec::new(),
                    w: Vec::new(),
                    ws: Vec::new(),
                    work: 0.0,
                    striker_work: 0.0,
                    finer: None,
                }
            })
            .collect();
        let run = Run {
            dx,
            dt,
            steps,
            beyond: Vec::new(),
            handover: None,
            separations: Vec::new(),
            reimpacts: Vec::new(),
            coefficient_error: 0.0,
        };
        (run, truth)
    }

    #[test]
    fn the_reported_edge_averages_out_the_phase_sawtooth() {
        let (run, truth) = sawtooth_run(0.02);
        let (mut smooth, mut raw) = (0.0f64, 0.0f64);
        // away from the run's ends, where the window is whole
        for n in 60..=340 {
            let t = n as f64 * run.dt;
            smooth = smooth.max((run.edge_at(n).unwrap() - truth(t)).abs() / run.dx);
            raw = raw.max((run.edge_interpolated(n).unwrap() - truth(t)).abs() / run.dx);
        }
        // the sawtooth's amplitude is 0.01 cells
        assert!(raw > 0.008, "raw edge error {raw} cells");
        assert!(
            smooth < 0.002,
            "smoothed edge error {smooth} cells (raw {raw})"
        );
        // a smooth quadratic history is reproduced to rounding, up to two steps from the
        // run's ends (where the edges are interpolated)
        let (run, truth) = sawtooth_run(0.0);
        for n in 3..=398 {
            let t = n as f64 * run.dt;
            let e = (run.edge_at(n).unwrap() - truth(t)).abs();
            assert!(e < 1e-12, "step {n}: {e}");
        }
        for n in [1, 2, 399, 400] {
            let t = n as f64 * run.dt;
            let e = (run.edge_at(n).unwrap() - truth(t)).abs();
            assert!(e < 1e-3 * run.dx, "step {n}: {e}");
        }
    }

    /// The force of a smooth history plus the sawtooth of the edge's crossings (a drop at
    /// each cell's entry, then a rise through the crossing, zero mean), as under the
    /// kinematic law: the report removes the sawtooth and reproduces a quadratic history.
    #[test]
    fn the_reported_force_averages_out_the_crossing_sawtooth() {
        let force = |t: f64| 1.0 + 0.3 * t - 0.02 * t * t;
        let with_sawtooth = |amplitude: f64| {
            let (mut run, _) = sawtooth_run(0.0);
            let dx = run.dx;
            for s in run.steps.iter_mut() {
                let tau = s.t - 0.5 * run.dt;
                let phase = (s.b / dx).fract();
                s.force = force(tau) + amplitude * (phase - 0.5);
                s.pressure = vec![s.force];
            }
            run
        };
        let run = with_sawtooth(0.03);
        let (mut smooth, mut raw) = (0.0f64, 0.0f64);
        for n in 100..=300 {
            let t = n as f64 * run.dt;
            smooth = smooth.max((run.force_at(n).unwrap() - force(t)).abs());
            raw = raw.max((run.force_interpolated(n).unwrap() - force(t)).abs());
        }
        // the sawtooth's amplitude is 0.015
        assert!(raw > 0.012, "raw force error {raw}");
        assert!(smooth < 0.003, "smoothed force error {smooth} (raw {raw})");
        let run = with_sawtooth(0.0);
        for n in 3..=398 {
            let t = n as f64 * run.dt;
            let e = (run.force_at(n).unwrap() - force(t)).abs();
            assert!(e < 1e-12, "step {n}: {e}");
        }
        // a step out of contact (205, given a wild force here) bounds the windows: it
        // enters no fit on either side
        let mut run = with_sawtooth(0.0);
        run.steps[204].pressure.clear();
        run.steps[204].force = 1e3;
        for n in [200, 210] {
            let t = n as f64 * run.dt;
            let e = (run.force_at(n).unwrap() - force(t)).abs();
            assert!(e < 1e-9, "step {n}: {e}");
        }
    }

    /// Where the edge stands still the window is the cap, 120 steps, which on a coarse grid
    /// is a long time: a force with a peak narrower than that is not a quadratic over it. The
    /// quartic through the same steps shows it, and the window is halved until it is.
    #[test]
    fn the_force_window_narrows_where_the_history_is_not_a_quadratic() {
        let (mut run, _) = sawtooth_run(0.0);
        let dt = run.dt;
        let force = |t: f64| 1.0 / (1.0 + ((t - 4.0) / 0.5).powi(2));
        for s in run.steps.iter_mut() {
            // a still edge, and the force at the middle of the step
            s.b = 0.3;
            s.edge_time = s.t - 0.5 * dt;
            s.force = force(s.t - 0.5 * dt);
            s.pressure = vec![s.force];
        }
        let f = |m: &StepState<f64>| (m.t - 0.5 * dt, m.force);
        let n = 200;
        let t = n as f64 * dt;
        let wide = run
            .crossing_fit(n, FORCE_WINDOW_STEPS, false, |x| !x.pressure.is_empty(), f)
            .unwrap();
        let reported = run.force_at(n).unwrap();
        // the quadratic over +-60 steps (+-1.2 R/c1) misses the peak by a fifth
        assert!((wide - force(t)).abs() > 0.1, "wide window {wide}");
        assert!(
            (reported - force(t)).abs() < 1e-3,
            "reported {reported} against {}",
            force(t)
        );
    }

    /// Steps marched past the end (`Run::beyond`) give the last steps' smoothed edge and
    /// force the whole run's values there: the windows centred on them, not the one-sided
    /// ends (whose raw values carry the sawtooth).
    #[test]
    fn steps_past_the_end_give_the_last_reports_whole_windows() {
        let (mut whole, truth) = sawtooth_run(0.02);
        let dt = whole.dt;
        for s in whole.steps.iter_mut() {
            // a step's force stands for the middle of the step
            let phase = (s.b / whole.dx).fract();
            s.force = 1.0 + 0.3 * (s.t - 0.5 * dt) + 0.03 * (phase - 0.5);
            s.pressure = vec![s.force];
        }
        let end = 300;
        let mut cut = whole.clone();
        cut.beyond = cut.steps.split_off(end);
        let mut bare = cut.clone();
        bare.beyond.clear();
        for n in end - 3..=end {
            assert_eq!(cut.edge_at(n), whole.edge_at(n), "edge at step {n}");
            assert_eq!(cut.force_at(n), whole.force_at(n), "force at step {n}");
        }
        // without them the last step's edge and force are the raw, one-sided values
        let t = end as f64 * whole.dt;
        let (with, without) = (
            (cut.edge_at(end).unwrap() - truth(t)).abs(),
            (bare.edge_at(end).unwrap() - truth(t)).abs(),
        );
        assert!(with < 0.25 * without, "edge error {with} against {without}");
        let force = 1.0 + 0.3 * t;
        let (with, without) = (
            (cut.force_at(end).unwrap() - force).abs(),
            (bare.force_at(end).unwrap() - force).abs(),
        );
        assert!(
            with < 0.25 * without,
            "force error {with} against {without}"
        );
        // past the end nothing is reported
        assert!(cut.step(end + 1).is_none());
    }

    #[test]
    fn a_geometric_edge_is_reported_as_it_is() {
        let (mut run, _) = sawtooth_run(0.02);
        let s = &mut run.steps[199];
        s.edge_time = s.t;
        assert_eq!(run.edge_at(200), Some(run.steps[199].b));
    }
}
