//! The march in double-double (`ImpactCase::solve_at`, `docs/impact.md`, section 7): the same
//! discrete solution as in f64 to f64's rounding, and its own digits checked on MPFR at 200
//! bits by a second route: the contact conditions of the cells behind the edge's (the
//! displacement of every past step's cells by the naive sum over the Lamb crate's Xi,
//! against the penetration less the parabola's exact cell means) and the striker's equation
//! of motion, evaluated with the double-double pressures.
use complexfn::{Dd, Real};
use impact::{Drive, EdgeLaw, ImpactCase, Profile};
use lamb::HalfPlane;
use rug::Float;

const BITS: u32 = 200;

fn f(x: f64) -> Float {
    Float::with_val(BITS, x)
}

/// A free rigid cylinder (parabola R = 1), nu = 1/4, m0/(rho R^2) = 10, V0/c1 = 1/100, one grid
/// of dx = R/50 to c1 t/R = 2 (50 steps, about ten contact cells at the end).
fn case(law: EdgeLaw) -> ImpactCase {
    let mut c = ImpactCase::new(
        0.25,
        Profile::Parabola { radius: 1.0 },
        Drive::Free {
            mass_ratio: 10.0,
            v0_over_c1: 0.01,
        },
        law,
        2.0,
    );
    c.dx = 0.02;
    c.levels = 1;
    // the start on a grid twice finer, handing over early (on the schedule of R/400), so
    // that most steps are this grid's own
    c.start_halvings = 1;
    c.start_grid = Some(0.0025);
    c
}

#[test]
fn double_double_march_agrees_with_f64_and_satisfies_its_equations_on_mpfr() {
    for law in [EdgeLaw::Signorini, EdgeLaw::Kinematic] {
        let c = case(law);
        let sol64 = c.solve(|_| {}).unwrap();
        let sol = c.solve_at::<Dd>(|_| {}).unwrap();
        let (run64, run) = (&sol64.runs[0], &sol.runs[0]);
        assert_eq!(run64.steps.len(), run.steps.len());
        // the same discrete solution at f64's rounding
        let hmax = run64.steps.iter().map(|s| s.h).fold(0.0, f64::max);
        let fmax = run64.steps.iter().map(|s| s.force).fold(0.0, f64::max);
        let mut worst64 = 0.0f64;
        for (a, b) in run64.steps.iter().zip(&run.steps) {
            assert_eq!(a.k, b.k, "{}: contact sets differ at {}", law.name(), a.t);
            worst64 = worst64
                .max((a.h - b.h.to_f64()).abs() / hmax)
                .max((a.force - b.force.to_f64()).abs() / fmax);
        }
        assert!(
            worst64 < 1e-12,
            "{}: f64 against double-double {worst64:e}",
            law.name()
        );

        // the second route on MPFR: the coefficients a(k, l) from Xi at 200 bits
        let hp = HalfPlane::from_poisson(f(0.25)).unwrap();
        let kappa = f(2.0);
        let dx: Float = f(1.0) / 50u32;
        let n_steps = run.steps.len();
        let kmax = run.steps.iter().map(|s| s.k).max().unwrap() + 1;
        let xi: Vec<Vec<Float>> = (0..=n_steps + 1)
            .map(|l| {
                (0..=2 * kmax + 2)
                    .map(|j| {
                        if l == 0 || j == 0 {
                            f(0.0)
                        } else {
                            let t = kappa.clone() * l as u32;
                            hp.cell_mean_primitive_zz(&f(j as f64), &t).unwrap().value
                        }
                    })
                    .collect()
            })
            .collect();
        let d2 = |k: usize, l: usize| -> Float {
            let row = &xi[l];
            let left = if k == 0 {
                row[1].clone()
            } else {
                row[k - 1].clone()
            };
            row[k + 1].clone() - row[k].clone() * 2u32 + left
        };
        // causality: the march's tables hold exact zeros beyond the reach
        let reach = |l: usize| ((l + 1) as f64 * 2.0).ceil() as usize;
        let a = |k: usize, l: usize| -> Float {
            if k > reach(l) {
                f(0.0)
            } else {
                d2(k, l + 1) - d2(k, l)
            }
        };
        let mc2 = (f(1.0) - f(0.5)) / (f(2.0) * (f(1.0) - f(0.25)));
        let mass = f(10.0) / mc2;
        let dt = kappa.clone() * &dx;
        let p = |s: usize, j: usize| -> Float {
            run.steps[s - 1]
                .pressure
                .get(j)
                .map_or(f(0.0), |v| v.to_mpfr(BITS))
        };
        let weight = |j: usize| {
            if j == 0 {
                dx.clone()
            } else {
                dx.clone() * 2u32
            }
        };
        let (mut worst_row, mut worst_motion, mut rows) = (0.0f64, 0.0f64, 0);
        // the inputs are their decimal values (V0/c1 = 1/100 exactly)
        let v0 = f(1.0) / 100u32;
        let (mut h_prev, mut v_prev) = (f(0.0), v0.clone());
        let mut seeded = 0;
        for n in 1..=n_steps {
            let st = &run.steps[n - 1];
            let h = st.h.to_mpfr(BITS);
            if st.finer.is_some() {
                // a step of the start, marched on a finer grid and merged onto this one
                // (its pressures enter the later steps' histories as this grid's)
                (h_prev, v_prev) = (h, st.v.to_mpfr(BITS));
                seeded += 1;
                continue;
            }
            // the equation of motion with the step's force from its pressures
            let force = (0..st.pressure.len()).fold(f(0.0), |acc, j| acc + weight(j) * p(n, j));
            let h_want = h_prev.clone() + dt.clone() * &v_prev
                - dt.clone() * &dt * &force / (mass.clone() * 2u32);
            let v_want = v_prev.clone() - dt.clone() * &force / &mass;
            worst_motion = worst_motion
                .max((h.clone() - &h_want).abs().to_f64() / hmax)
                .max(((st.v.to_mpfr(BITS) - &v_want) / &v0).abs().to_f64());
            (h_prev, v_prev) = (h.clone(), st.v.to_mpfr(BITS));
            // the plain contact conditions: cells 0 ..= k - 2 (the edge cell k and the one
            // behind it carry the edge model's terms)
            for i in 0..=st.k.saturating_sub(2) {
                if st.k < 2 {
                    break;
                }
                let mut w = f(0.0);
                for s in 1..=n {
                    let len = run.steps[s - 1].pressure.len();
                    for j in 0..len {
                        let mut coef = a(i.abs_diff(j), n - s);
                        if j > 0 {
                            coef += a(i + j, n - s);
                        }
                        w += coef * &dx * p(s, j);
                    }
                }
                // the parabola's exact mean over cell i
                let (lo, hi) = if i == 0 {
                    (f(0.0), dx.clone() / 2u32)
                } else {
                    (dx.clone() * (i as f64 - 0.5), dx.clone() * (i as f64 + 0.5))
                };
                let mean = (hi.clone() * &hi * &hi - lo.clone() * &lo * &lo) / ((hi - lo) * 6u32);
                // the defect the start's last hand-over left, which the steps after it take
                // off their history sums (`Run::handover`)
                if let Some(d) = &run.handover {
                    w -= d.at(i).to_mpfr(BITS) * d.weight(n);
                }
                let residual = (w - (h.clone() - mean)).abs().to_f64() / hmax;
                worst_row = worst_row.max(residual);
                rows += 1;
            }
        }
        eprintln!(
            "{}: f64 {worst64:.1e}; on MPFR, {rows} contact conditions {worst_row:.1e}, motion {worst_motion:.1e} (relative to the largest h)",
            law.name()
        );
        assert!(rows > 100, "{}: {rows} conditions checked", law.name());
        // the start's last hand-over left its defect, which the conditions above include
        assert_eq!(
            run.handover.is_some(),
            law == EdgeLaw::Signorini,
            "{}: the hand-over's defect",
            law.name()
        );
        // the start on finer grids is Signorini's alone
        assert_eq!(
            seeded > 0,
            law == EdgeLaw::Signorini,
            "{}: {seeded} steps of the start",
            law.name()
        );
        assert!(
            worst_row < 1e-28,
            "{}: conditions {worst_row:e}",
            law.name()
        );
        assert!(
            worst_motion < 1e-28,
            "{}: motion {worst_motion:e}",
            law.name()
        );
    }
}

#[test]
fn double_double_is_refused_for_deformable_strikers() {
    let c =
        case(EdgeLaw::Signorini).with_striker(impact::Striker::Elastic(impact::StrikerMaterial {
            c1_ratio: 1.0,
            c2_ratio: 0.5,
            density_ratio: 1.0,
        }));
    let e = c.solve_at::<Dd>(|_| {}).unwrap_err().to_string();
    assert!(e.contains("striker"), "{e}");
}
