//! The histories' error estimates against the actual errors (`docs/impact.md`, section 5):
//! six cases of the twelve-case sweep (`examples/estimate_sweep.rs`, whose full numbers the
//! docs quote), on shorter runs, at dx = R/100 with three levels against one grid four times
//! finer. The actual error is bounded by the difference from that grid plus its own error (its
//! difference from the grid twice finer than dx).

use impact::Estimator;

#[path = "../../examples/sweep/mod.rs"]
mod sweep;

use sweep::{cases, compare, median, PICKS};

/// Every row of every history carries an estimate, the bound of the actual error never
/// exceeds it, and the estimates are no more pessimistic than measured: over these shorter
/// runs (their early part weighs more) the medians of actual/stated are 0.089 (h), 0.067 (b),
/// 0.065 (the force), 0.059 (the penetration speed and the kinetic energy), 0.081 (the work)
/// and 0.130 (the energy defect), held at three quarters of that (over the full sweep at
/// R/100: 0.21, 0.070, 0.11, 0.16, 0.12 and 0.14; the aim is 0.1). The rigid strikers of
/// curved profiles under Signorini's law take the policies measured with the start on finer
/// grids, the sharp estimator for every history but the striker's; the kinematic law keeps
/// the conservative bound for the penetration speed, the work and the energy defect.
#[test]
fn estimates_bound_the_actual_errors_and_are_sharp() {
    // the sweep's cases run here, and the ends they take
    let shorter = [
        ("reference", 4.0),
        ("reference kinematic", 4.0),
        ("light fast nu .3", 3.2),
        ("circle M 100 V .05", 2.4),
        ("kinematic power k 3", 4.0),
        ("wedge 80", 2.0),
    ];
    // the medians held, in the order of PICKS
    let least = [0.067, 0.05, 0.049, 0.044, 0.044, 0.061, 0.097];
    let dx = 0.01;
    let mut ratios = vec![Vec::new(); PICKS.len()];
    let mut run = 0;
    // the start's extra sharp histories (the penetration speed, the work, the defect)
    let mut sharp_started = 0;
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
        // b's and the force's last rows are conservative (one-sided crossing fits)
        for m in [models.h, models.b, models.force] {
            assert!(m.safety > 0.0, "{name}: {m:?}");
        }
        for m in [models.b, models.force] {
            assert!(m.conservative_rows >= 1, "{name}: {m:?}");
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
        sharp_started >= 6,
        "{sharp_started} of the started cases' dh/dt, work and defect took the sharp estimator"
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
