//! The genuine contact solver: against the paper's analytic solution at gamma = 0, and, for
//! gamma > 0, against the contact condition (7) evaluated through Lamb's kernels.
use genuine::{load_through_kernels, GenuineCase, GenuineSolver, SolveOptions};
use wedge::ApexRegime;
use wedge::{Case, Coupling, Indenter, Material, Solution};

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

fn opts(degree: usize) -> SolveOptions {
    SolveOptions {
        degree,
        ..Default::default()
    }
}

#[test]
fn gamma_zero_reproduces_the_paper_to_ten_digits() {
    let mat = Material::paper();
    for (th, cp, p) in [
        (80.0, Coupling::On, 0.3),
        (89.9, Coupling::On, 0.45),
        (85.0, Coupling::On, 0.05),
        (89.0, Coupling::Off, 0.3),
        (80.0, Coupling::Off, 0.45),
    ] {
        let ind = Indenter::new(th, 0.0, cp).unwrap();
        let paper = Case::<f64>::new(&mat, &ind, p, Solution::Paper).unwrap();
        let g = GenuineCase::solve(&mat, &ind, p, opts(20)).unwrap();
        let (dv, df) = (
            rel(g.v_hat(), paper.v_hat().unwrap()),
            rel(g.force_hat(), paper.force_hat().unwrap()),
        );
        println!(
            "Theta {th} {cp:?} p {p}: dV {dv:.1e} dF {df:.1e} est {:.1e}",
            g.error_estimate()
        );
        assert!(
            dv < 1e-10 && df < 1e-10,
            "Theta {th} {cp:?} p {p}: {dv:e} {df:e}"
        );
        for f in [0.001, 0.2, 0.5, 0.9, 0.999] {
            let x = f * p;
            let ds = rel(
                g.stress_hat(x).unwrap(),
                paper.stress_hat(&x).unwrap().value,
            );
            assert!(ds < 1e-10, "Theta {th} {cp:?} p {p} x {x}: {ds:e}");
        }
        assert!(g.contact_compressive().unwrap());
    }
}

/// (7) through the kernels at stations that are not collocation points of the solve (the
/// solve collocates the second-derivative equation at Chebyshev points and takes the slope and
/// V at p/2); stated residual 1e-12 of V t.
#[test]
fn gamma_positive_satisfies_the_contact_condition_through_the_kernels() {
    let mat = Material::paper();
    for (th, gamma, cp, p) in [
        (89.0, 0.6, Coupling::On, 0.3),
        (80.0, 1.0, Coupling::On, 0.45),
        (86.0, 0.001, Coupling::On, 0.05),
        (85.0, 0.3, Coupling::Off, 0.2),
    ] {
        let ind = Indenter::new(th, gamma, cp).unwrap();
        let g = GenuineCase::solve(&mat, &ind, p, opts(16)).unwrap();
        let mut worst = 0.0_f64;
        for f in [1e-4, 0.013, 0.27, 0.61, 0.88, 0.997] {
            worst = worst.max(g.contact_residual(f * p).unwrap().abs());
        }
        println!(
            "Theta {th} gamma {gamma} {cp:?} p {p}: V {:.14} est {:.1e} max resid {worst:.1e}",
            g.v_hat(),
            g.error_estimate()
        );
        assert!(
            worst < 1e-12,
            "Theta {th} gamma {gamma}: residual {worst:e}"
        );
        assert!(g.contact_compressive().unwrap());
    }
}

#[test]
fn doubling_the_basis_changes_v_by_less_than_the_estimate() {
    let mat = Material::paper();
    for (th, gamma, p) in [(89.0, 0.6, 0.3), (80.0, 1.0, 0.45), (89.9, 0.2, 0.05)] {
        let ind = Indenter::new(th, gamma, Coupling::On).unwrap();
        let a = GenuineCase::solve(&mat, &ind, p, opts(10)).unwrap();
        let b = GenuineCase::solve(&mat, &ind, p, opts(20)).unwrap();
        let d = (a.v_hat() - b.v_hat()).abs();
        println!(
            "Theta {th} gamma {gamma} p {p}: |V(20) - V(10)| {d:.1e}, estimate(10) {:.1e}",
            a.error_estimate()
        );
        assert!(d <= a.error_estimate(), "{d:e} > {:e}", a.error_estimate());
        assert!(a.error_estimate() < 1e-10 * a.v_hat());
        let df = rel(a.force_hat(), b.force_hat());
        assert!(df < 1e-11, "force {df:e}");
    }
}

/// The apex: the solve carries the eigen-equation's exponent; replacing it by the paper's
/// 2 Omega0 (or by lambda + 0.05) leaves a residual of (7) near the apex that the eigen-equation
/// exponent does not.
#[test]
fn apex_exponent_is_the_eigen_equation_root() {
    let mat = Material::paper();
    let ind = Indenter::new(89.0, 0.6, Coupling::On).unwrap();
    let p = 0.3;
    let g = GenuineCase::solve(&mat, &ind, p, opts(16)).unwrap();
    let (ex, amp) = g.apex().unwrap();
    assert_eq!(ex.kind, ApexRegime::Power);
    let lam = ex.lambdas[0];
    // the root satisfies t^2 - m^2 (beta + gamma) t + beta gamma = 0
    let m2 = (1000.0f64 / 1870.83).powi(2);
    let t = (std::f64::consts::FRAC_PI_2 * lam).tan();
    let (b, ga) = (g.beta(), g.gamma());
    assert!((t * t - m2 * (b + ga) * t + b * ga).abs() < 1e-15);
    // fitted behaviour: S(x) (x/p)^lambda tends to the leading amplitude
    let s1 = g.stress_hat(1e-9 * p).unwrap() * 1e-9f64.powf(lam);
    let s2 = g.stress_hat(1e-12 * p).unwrap() * 1e-12f64.powf(lam);
    println!("lambda {lam}, amplitude {amp}, S (x/p)^lambda at 1e-9 p {s1}, 1e-12 p {s2}");
    assert!(rel(s2, amp) < rel(s1, amp) && rel(s2, amp) < 0.05);
    let near = |o: SolveOptions| -> f64 {
        let c = GenuineCase::solve(&mat, &ind, p, o).unwrap();
        [1e-5, 1e-3, 0.02]
            .iter()
            .map(|f| c.contact_residual(f * p).unwrap().abs())
            .fold(0.0, f64::max)
    };
    let good = near(opts(16));
    let omega0 = (m2 * (b + ga) / (1.0 - b * ga)).atan() / std::f64::consts::PI;
    for wrong in [
        vec![2.0 * omega0, ex.lambdas[1]],
        vec![lam + 0.05, ex.lambdas[1]],
    ] {
        let bad = near(SolveOptions {
            apex_lambdas: Some(wrong.clone()),
            ..opts(16)
        });
        println!("apex residual: eigen-equation {good:.1e}, exponents {wrong:?} {bad:.1e}");
        assert!(bad > 1e3 * good.max(1e-15));
    }
}

/// The paper's tractions (pole-corrected Q, eq (40), shear -sgn(x) gamma sigma_yy) loaded on
/// a genuine half-plane: (7) fails by about 11 percent of V t near the apex for gamma = 0.6,
/// and holds for gamma = 0.
#[test]
fn paper_tractions_violate_the_contact_condition_when_gamma_is_positive() {
    let mat = Material::paper();
    let m = 1000.0 / 1870.83;
    let p = 0.3;
    for (gamma, lo, hi) in [(0.6, 0.05, 0.2), (0.0, 0.0, 1e-10)] {
        let ind = Indenter::new(89.0, gamma, Coupling::On).unwrap();
        let paper = Case::<f64>::new(&mat, &ind, p, Solution::Paper).unwrap();
        let q = paper.q_hat().unwrap();
        let v = paper.v_hat().unwrap();
        let beta = *paper.beta();
        let h = |x: f64, pmx: f64| {
            let c = paper.x_on_contact(&x, &pmx);
            q * c.x * c.cos / (x * x)
        };
        let x0 = 0.01 * p;
        let u = load_through_kernels(m, p, gamma, x0, h).unwrap();
        let r = ((u[0] + beta * u[1] + v - x0) / v).abs();
        println!("paper tractions, gamma {gamma}: residual of (7) at 0.01 p = {r:.3e} of V t");
        assert!(r >= lo && r <= hi, "gamma {gamma}: {r}");
    }
}

#[test]
fn inverse_recovers_p() {
    let mat = Material::paper();
    let ind = Indenter::new(86.0, 0.4, Coupling::On).unwrap();
    let g = GenuineCase::solve(&mat, &ind, 0.27, opts(12)).unwrap();
    let speed = g.v_hat() * mat.c1().value() * ind.cot_theta(&0.0_f64);
    let solver = GenuineSolver::with_options(&mat, &ind, opts(12));
    let inv = wedge::for_speed(&solver, &speed.into(), &0.0_f64).unwrap();
    assert!((inv.p() - 0.27).abs() < 1e-11, "{}", inv.p());
}

#[test]
fn bad_parameters_are_refused_with_their_range() {
    let mat = Material::paper();
    let ind = Indenter::new(86.0, 0.4, Coupling::On).unwrap();
    for p in [0.0, -0.1, 0.6, f64::NAN] {
        let e = GenuineCase::solve(&mat, &ind, p, opts(12)).unwrap_err();
        assert!(e.to_string().contains("p = alpha/c1"), "{e}");
    }
    let e = GenuineCase::solve(&mat, &ind, 0.3, opts(2)).unwrap_err();
    assert!(e.to_string().contains("degree"));
    let g = GenuineCase::solve(&mat, &ind, 0.3, opts(8)).unwrap();
    assert!(g.stress_hat(0.31).is_err() && g.slip_rate(0.0).is_err());
}

/// Signorini outside the contact: for gamma = 0 the genuine gap, from Lamb's kernels, equals
/// the paper's gap from (18) (an independent representation); for gamma > 0 it is positive.
#[test]
fn normal_gap_outside_the_contact_matches_the_paper_and_is_open() {
    let mat = Material::paper();
    for (th, cp) in [(89.0, Coupling::On), (86.0, Coupling::Off)] {
        let ind = Indenter::new(th, 0.0, cp).unwrap();
        let p = 0.3;
        let paper = Case::<f64>::new(&mat, &ind, p, Solution::Paper).unwrap();
        let g = GenuineCase::solve(&mat, &ind, p, SolveOptions::default()).unwrap();
        for x in [0.301, 0.31, 0.4, 0.6, 0.9] {
            let (gg, err) = g.normal_gap(x).unwrap();
            let gp = paper.normal_gap(&x).unwrap();
            assert!(
                (gg - gp).abs() <= err && err < 1e-11,
                "Theta {th} {cp:?} x {x}: genuine {gg}, paper {gp}"
            );
            assert!(gg > 0.0, "gap closed at {x}: {gg}");
        }
        assert!(g.no_interpenetration().unwrap().0);
    }
    let ind = Indenter::new(89.0, 0.6, Coupling::On).unwrap();
    let g = GenuineCase::solve(&mat, &ind, 0.3, SolveOptions::default()).unwrap();
    let (ok, min_gap) = g.no_interpenetration().unwrap();
    assert!(ok && min_gap > 0.0, "min gap {min_gap}");
    assert!(
        g.normal_gap(0.2).is_err(),
        "x inside the contact is refused"
    );
}

/// The rows and the fits run on rayon's threads: the numbers must not depend on how many
/// (every sum keeps its order). One thread against the default pool, at double-double, where
/// the plateau probe's fit runs as well: V_hat, the force and the estimate to the bit.
#[test]
fn the_solve_is_the_same_on_one_thread_and_on_many() {
    use complexfn::{Dd, Real};
    // Dd compares both of its parts
    let mat = Material::paper();
    let ind = Indenter::new(89.0, 0.6, Coupling::On).unwrap();
    let p = Dd::from_f64(0.3);
    let opts = SolveOptions::for_precision(p.prec());
    let run = || {
        let g = GenuineCase::solve(&mat, &ind, p, opts.clone()).unwrap();
        (g.v_hat(), g.force_hat_with_error().0, g.error_estimate())
    };
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap()
        .install(run);
    let many = rayon::ThreadPoolBuilder::new()
        .num_threads(4)
        .build()
        .unwrap()
        .install(run);
    assert!(
        one.0 == many.0,
        "V_hat {} against {}",
        one.0.to_decimal(34),
        many.0.to_decimal(34)
    );
    assert!(
        one.1 == many.1,
        "force {} against {}",
        one.1.to_decimal(34),
        many.1.to_decimal(34)
    );
    assert_eq!(one.2.to_bits(), many.2.to_bits());
}
