//! The histories' error estimates against the actual errors (`docs/impact.md`, section 5):
//! six cases of the twelve-case sweep (`examples/estimate_sweep.rs`, whose full numbers the
//! docs quote; four here, the two fast strikers in the explicit tier), on shorter runs, at dx = R/100 with three levels against one grid four times
//! finer. The actual error is bounded by the difference from that grid plus its own error (its
//! difference from the grid twice finer than dx).

use impact::Estimator;

#[path = "../../examples/sweep/mod.rs"]
mod sweep;

use sweep::{cases, compare, median, PICKS};

/// Every row of every history carries an estimate, the bound of the actual error never
/// exceeds it, and the estimates are no more pessimistic than measured: the medians of
/// actual/stated over the shorter runs of `shorter` are held at `least` (in the order of
/// [`PICKS`]). Rigid strikers of curved profiles under Signorini's law take the policies
/// measured with the start on finer grids, the sharp estimator for every history but the
/// striker's where the order shows; the kinematic law keeps the conservative bound for the
/// penetration speed, the work and the energy defect.
/// The medians held by [`estimates_bound_the_actual_errors_and_are_sharp`].
const LEAST_SLOW: [f64; PICKS.len()] = [0.138, 0.083, 0.069, 0.032, 0.032, 0.070, 0.074];
/// The medians held by [`estimates_of_fast_strikers_bound_the_actual_errors`].
const LEAST_FAST: [f64; PICKS.len()] = [0.168, 0.006, 0.0075, 0.073, 0.073, 0.051, 0.43];

/// `shown_least`: how many of the cases' h and b histories must take the order their rows
/// show one by one at some rows (`ErrorModel::order_shown`).
fn check_estimates(
    shorter: &[(&str, f64)],
    least: [f64; PICKS.len()],
    sharp_least: usize,
    shown_least: usize,
) {
    let dx = 0.01;
    let mut ratios = vec![Vec::new(); PICKS.len()];
    let mut run = 0;
    // the start's extra sharp histories (the penetration speed, the work, the defect)
    let mut sharp_started = 0;
    // the h and b histories that took the order shown row by row somewhere
    let mut shown = 0;
    for (name, mut base) in cases() {
        let Some(&(_, end)) = shorter.iter().find(|(n, _)| *n == name) else {
            continue;
        };
        run += 1;
        base.end = end;
        let (sol, _, compared) = compare(&base, dx);
        let models = sol
            .history()
            .1
            .models
            .expect("three levels have error models");
        for m in [models.h, models.b, models.force] {
            assert!(m.safety > 0.0, "{name}: {m:?}");
        }
        for m in [models.h, models.b] {
            if let Some(o) = m.order_shown {
                assert!(
                    o.rows > 0 && (1.0..=2.0).contains(&o.order_credited),
                    "{name}: {m:?}"
                );
                shown += 1;
            }
        }
        assert!(
            models.force.order_shown.is_none(),
            "{name}: {:?}",
            models.force
        );
        // b's and the force's last rows are conservative where their crossing fits are
        // one-sided there: a level that neither marched past the end nor left the contact
        let whole_windows = sol.runs.iter().all(|r| r.last_reports_centred());
        for m in [models.b, models.force] {
            assert!(whole_windows || m.conservative_rows >= 1, "{name}: {m:?}");
        }
        assert_eq!(models.others.estimator, Estimator::Conservative);
        // the start's policies: every history but the striker's sharp where the order shows;
        // the kinematic law's penetration speed, work and energy defect conservative
        let started = base.starts_finer();
        for m in [models.hdot, models.work, models.energy_defect] {
            if !started {
                assert_eq!(m.estimator, Estimator::Conservative, "{name}: {m:?}");
            }
        }
        if started {
            for m in [models.hdot, models.work, models.energy_defect] {
                // the sharp estimator wherever the order shows
                if m.estimator == Estimator::Richardson {
                    sharp_started += 1;
                }
            }
        }
        assert!(
            compared.len() >= 20,
            "{name}: {} rows compared",
            compared.len()
        );
        let mut line = format!("{name}:");
        for (q, (key, _)) in PICKS.iter().enumerate() {
            let mut own = Vec::new();
            for c in &compared {
                if c.q[q].0.is_nan() {
                    continue;
                }
                let err = c.q[q].1.expect("every row carries an estimate");
                assert!(
                    err.is_finite() && err > 0.0,
                    "{name} {key} at {}: {err}",
                    c.t
                );
                let bound = c.bound(q);
                assert!(
                    bound <= err,
                    "{name}: {key} at c1 t/R = {}: actual up to {bound:.3e}, stated {err:.3e}",
                    c.t
                );
                own.push(bound / err);
            }
            ratios[q].extend(&own);
            line += &format!(" {key} median {:.3}", median(&mut own));
        }
        eprintln!("{line}");
    }
    assert_eq!(run, shorter.len(), "every named case is in the sweep");
    assert!(
        sharp_started >= sharp_least,
        "{sharp_started} of the started cases' dh/dt, work and defect took the sharp estimator"
    );
    assert!(
        shown >= shown_least,
        "{shown} of the cases' h and b histories took the order shown row by row"
    );
    let summary: Vec<(f64, f64)> = ratios
        .iter_mut()
        .map(|r| (r.iter().copied().fold(0.0, f64::max), median(r)))
        .collect();
    for ((key, _), (max, med)) in PICKS.iter().zip(&summary) {
        eprintln!("{key}: actual/stated at most {max:.3}, median {med:.3}");
    }
    for (((key, _), (_, med)), least) in PICKS.iter().zip(&summary).zip(least) {
        assert!(
            *med >= least,
            "{key}: the median of actual/stated is {med:.3}, below {least}: the estimates are not sharp"
        );
    }
}

/// Four of the sweep's cases on shorter runs (the reference case under both laws, the wedge,
/// the kinematic power law k = 3) at R/100: the medians of actual/stated are 0.184 (h), 0.111
/// (b), 0.092 (the force), 0.043 (dh/dt and the kinetic energy), 0.094 (the work) and 0.099
/// (the energy defect); the two kinematic cases' h and b take the order their rows show one
/// by one at most rows (h's and b's medians were held at 0.067 and 0.052 before);
/// held at three quarters of that (over the full sweep at R/100: 0.24 (h), 0.090 (b), 0.11
/// (the force), 0.16 (dh/dt and the kinetic energy), 0.12 (the work) and 0.14 (the energy
/// defect); the aim is 0.1; the early part weighs more in short runs).
#[test]
fn estimates_bound_the_actual_errors_and_are_sharp() {
    check_estimates(
        &[
            ("reference", 4.0),
            ("reference kinematic", 4.0),
            ("kinematic power k 3", 4.0),
            ("wedge 80", 2.0),
        ],
        LEAST_SLOW,
        4,
        4,
    );
}

/// The two fast strikers of the sweep on shorter runs (the light parabola at V0/c1 = 0.1 and
/// the circle at 0.05, whose finer grids' starts march wide contacts at fast edges: about a
/// minute in release), in the explicit tier: the medians of actual/stated are 0.224 (h), 0.008 (b),
/// 0.010 (the force: their early rows, where the contact widens fastest, weigh most in these
/// short runs), 0.098 (dh/dt, the kinetic energy), 0.068 (the work) and 0.575 (the energy
/// defect),
/// held at three quarters of that.
#[test]
#[ignore = "the explicit tier: about a minute in release"]
fn estimates_of_fast_strikers_bound_the_actual_errors() {
    check_estimates(
        &[("light fast nu .3", 3.2), ("circle M 100 V .05", 2.4)],
        LEAST_FAST,
        2,
        0,
    );
}

/// The kinematic law's force on the reference case at the default grid (R/200, three
/// levels) against R/800: within its stated error at every report time, where the edge
/// advances and where it nearly stands still near the largest penetration. (Its actual error
/// is printed, the last report time, one-sided, aside: about 1e-3 of the peak,
/// `docs/impact.md`, section 4; the aim of 1e-4 is not reached.)
#[test]
fn the_kinematic_force_is_within_its_stated_error_at_the_default_grid() {
    let base = impact::ImpactCase::reference(impact::EdgeLaw::Kinematic);
    let (_, rows, compared) = compare(&base, 0.005);
    let q = PICKS
        .iter()
        .position(|(k, _)| *k == "force")
        .expect("the force is compared");
    let peak = compared.iter().map(|c| c.q[q].2.abs()).fold(0.0, f64::max);
    let (mut advancing, mut standing) = ((0.0f64, 0.0), (0.0f64, 0.0));
    for c in &compared {
        let err = c.q[q].1.expect("every row carries an estimate");
        let bound = c.bound(q);
        assert!(
            bound <= err,
            "c1 t/R = {}: the force's actual error up to {bound:.3e}, stated {err:.3e}",
            c.t
        );
        if c.i + 1 == rows.len() {
            continue;
        }
        // an edge slower than 0.01 c1 takes over fifty steps to cross a cell: it stands
        // still for the crossing fits
        let worst = if rows[c.i].bdot > 0.01 {
            &mut advancing
        } else {
            &mut standing
        };
        if bound / peak > worst.0 {
            *worst = (bound / peak, c.t);
        }
    }
    assert!(compared.len() >= 100, "{} rows compared", compared.len());
    eprintln!(
        "the kinematic force's error, share of its peak: at most {:.2e} (c1 t/R = {}) while the edge advances, {:.2e} (c1 t/R = {}) where it does not",
        advancing.0, advancing.1, standing.0, standing.1
    );
}
