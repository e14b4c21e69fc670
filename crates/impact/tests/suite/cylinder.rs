//! The full elastic cylinder striker over whole impacts (`docs/strikers.md`, section 8), each
//! check against an independent quantity: the identity "a striker of the half-plane's own
//! material is a rigid striker on a half-plane of half the density" (exact for the local
//! model, so for the cylinder while its curvature is not yet felt), the local model itself at
//! early times with the difference shrinking at the curvature's order, the rigid striker as the
//! stiff limit, the energy balance to the separation, and the vibration energy of the free
//! disk's modes against the work done on the striker's deformation (two routes: Laplace
//! inversion of the disk's response, and its modes).

use crate::common;

use common::m2;
use impact::striker::disk::Disk;
use impact::{HistoryRow, ImpactCase, Stop, Striker, StrikerMaterial};
use std::f64::consts::PI;

const NU: f64 = 0.25;

fn own_material() -> StrikerMaterial {
    StrikerMaterial {
        c1_ratio: 1.0,
        c2_ratio: m2(NU).sqrt(),
        density_ratio: 1.0,
    }
}

/// A free parabola of R = 1, V0/c1 = 0.01, on one grid.
fn case(mass_ratio: f64, end: f64, dx: f64, striker: Striker) -> ImpactCase {
    let mut c = common::free_parabola(NU, mass_ratio, 0.01, end, dx).with_striker(striker);
    c.levels = 1;
    // the rigid striker compared on the cylinder's grid throughout (only a rigid striker
    // starts on finer grids)
    c.start_halvings = 0;
    c
}

fn rows(c: ImpactCase) -> Vec<HistoryRow> {
    c.solve(|_| {}).expect("the case solves").history().0
}

fn peak(rows: &[HistoryRow]) -> f64 {
    rows.iter().map(|r| r.force.value).fold(0.0, f64::max)
}

/// Over c1 t/R <= 0.3 the cylinder of the half-plane's own material is the rigid striker of
/// twice its mass on the same half-plane with twice the force (a half-plane of half the
/// density), to 1 percent of the peak; the difference is the curvature's, and grows.
#[test]
fn own_material_cylinder_is_rigid_on_half_the_density_early() {
    let cyl = rows(case(PI, 0.3, 0.01, Striker::Cylinder(own_material())));
    let rigid = rows(case(2.0 * PI, 0.3, 0.01, Striker::Rigid));
    assert_eq!(cyl.len(), rigid.len());
    let fmax = peak(&rigid);
    let hmax = rigid.iter().map(|r| r.h.value).fold(0.0, f64::max);
    let mut worst: f64 = 0.0;
    for (c, r) in cyl.iter().zip(&rigid) {
        let df = (2.0 * c.force.value - r.force.value).abs() / fmax;
        worst = worst.max(df);
        assert!(
            df < 0.01,
            "t = {}: 2 F_cyl {} against {}",
            c.t,
            2.0 * c.force.value,
            r.force.value
        );
        assert!((c.h.value - r.h.value).abs() < 0.01 * hmax, "t = {}", c.t);
    }
    // not identical: the curvature's correction is there
    assert!(worst > 1e-4, "largest difference {worst:e}");
}

/// At early times the cylinder is its local half-plane model; their forces part like t (the
/// curvature's order: the disk's own response exceeds the local one by a share k c2s t/R,
/// `docs/strikers.md`, section 2), measured from whole runs by the slope of
/// log|F_cyl/F_local - 1| against log t.
#[test]
fn cylinder_parts_from_its_local_model_at_the_curvatures_order() {
    let end = 0.08;
    let cyl = rows(case(PI, end, 0.005, Striker::Cylinder(own_material())));
    let local = rows(case(PI, end, 0.005, Striker::Elastic(own_material())));
    let rel = |t: f64| -> f64 {
        let i = cyl
            .iter()
            .position(|r| (r.t - t).abs() < 1e-9)
            .expect("a reported time");
        assert!((local[i].t - t).abs() < 1e-9);
        (cyl[i].force.value / local[i].force.value - 1.0).abs()
    };
    let (a, b) = (rel(0.02), rel(0.04));
    let slope = (b / a).ln() / 2f64.ln();
    assert!(
        (0.6..=1.4).contains(&slope),
        "slope {slope}: {a:e} at 0.02, {b:e} at 0.04"
    );
    // and small: the disk's early excess over the local compliance is k c2s t, k = 1/c1s - c1s/4
    // (in c2s units), shared with the half-plane's equal compliance
    assert!(a < 0.01 && b < 0.01, "{a:e} {b:e}");
}

/// c1s = 1000 c1 (c2s alike): the cylinder is the rigid striker of the same mass, to 1 percent
/// of the peak over c1 t/R in (0, 1] and over the whole impact to its separation.
#[test]
fn stiff_cylinder_is_the_rigid_striker() {
    let stiff = StrikerMaterial {
        c1_ratio: 1000.0,
        c2_ratio: 1000.0 * m2(NU).sqrt(),
        density_ratio: 1.0,
    };
    let mut c = case(PI, 40.0, 0.02, Striker::Cylinder(stiff));
    c.stop = Stop::AtSeparation;
    let mut r = case(PI, 40.0, 0.02, Striker::Rigid);
    r.stop = Stop::AtSeparation;
    let (sc, sr) = (c.solve(|_| {}).unwrap(), r.solve(|_| {}).unwrap());
    let (cyl, rigid) = (sc.history().0, sr.history().0);
    assert_eq!(cyl.len(), rigid.len());
    let fmax = peak(&rigid);
    for (a, b) in cyl.iter().zip(&rigid) {
        let d = (a.force.value - b.force.value).abs() / fmax;
        assert!(
            d < 0.01,
            "t = {}: {} against {}",
            a.t,
            a.force.value,
            b.force.value
        );
    }
    let (ra, rb) = (sc.rebound().unwrap(), sr.rebound().unwrap());
    assert!((ra.separation.value - rb.separation.value).abs() < 0.05);
    assert!((ra.restitution.value - rb.restitution.value).abs() < 0.01);
}

/// The energy over a whole impact of a cylinder of the half-plane's own material, to its
/// separation: the striker's kinetic energy of translation, its strain and vibration energies
/// and the work done on the half-plane add to the impact energy within 1e-3 of it; the
/// vibration energy is that of the free disk's modes, whose own strain energy approaches the
/// strain energy (the work on the deformation less the vibration, from the Laplace-inverted
/// response) from below as more modes are kept.
#[test]
fn cylinder_energy_balance_to_separation() {
    let mut c = case(PI, 40.0, 0.01, Striker::Cylinder(own_material()));
    c.stop = Stop::AtSeparation;
    let sol = c.solve(|_| {}).unwrap();
    let (rows, _) = sol.history();
    let rebound = sol.rebound().expect("the cylinder separates");
    assert!(rebound.restitution.value > 0.0 && rebound.restitution.value < 1.0);
    let ke0 = 0.5 * PI * 0.01 * 0.01;
    let parts = sol.striker_energies().unwrap().unwrap();
    let run = &sol.runs[0];
    let mut taken: f64 = 0.0;
    for r in &rows {
        let e = parts[(r.t / run.dt).round() as usize - 1];
        assert!(e.kinetic >= 0.0 && e.strain >= -1e-9 * ke0, "t = {}", r.t);
        let total = r.kinetic.unwrap().value + e.strain + e.kinetic + r.work.value;
        assert!(
            (total - ke0).abs() < 1e-3 * ke0,
            "t = {}: balance {:e}",
            r.t,
            total / ke0 - 1.0
        );
        taken = taken.max((e.strain + e.kinetic) / ke0);
    }
    // the cylinder takes a visible share
    assert!(taken > 1e-3, "largest share {taken:e}");
    // the free disk's modes: strain + kinetic of the modes below omega approach the work on
    // the deformation from below as omega doubles
    let mat = own_material();
    let modes = Disk::new(mat.poisson()).unwrap().modes(64.0).unwrap();
    let pressures: Vec<Vec<f64>> = run.steps.iter().map(|s| s.pressure.clone()).collect();
    let i = run.steps.len() / 2;
    let work = run.steps[i].striker_work;
    let shares: Vec<f64> = [16.0, 32.0, 64.0]
        .iter()
        .map(|&w| {
            let e = modes
                .below(w)
                .energies(run.dx, run.dt * mat.c2_ratio, &pressures);
            (e[i].0 + e[i].1) / work
        })
        .collect();
    assert!(
        shares.windows(2).all(|p| p[0] < p[1]) && shares[2] < 1.0 + 1e-6 && shares[2] > 0.9,
        "modal share of the work {shares:?}"
    );
}
