//! Stability on stiff and extreme cases (the grid of `dyncontact::stability`): every case
//! returns a result whose f64 value agrees with its 256-bit value within the accuracy the
//! library states for it (floored at 1e-13), or a typed error; never a panic, a NaN or an
//! infinity. The whole grid runs in f64; every STRIDE-th case is also solved at 256 bits here
//! (all of them in `cargo run --release --example stability_report`).

use dyncontact::stability::{check, grid, Outcome};

const STRIDE: usize = 9;

#[test]
fn stability_grid_f64_against_256_bits() {
    let (mut compared, mut refused, mut worst) = (0, 0, 0.0_f64);
    for (i, pt) in grid().iter().enumerate() {
        match check(pt, i % STRIDE == 0) {
            Err(e) => panic!("{e}"),
            Ok(Outcome::Refused(msg)) => {
                assert!(!msg.is_empty());
                refused += 1;
            }
            Ok(Outcome::Solved { stated, actual }) => {
                if let Some(a) = actual {
                    assert!(
                        a <= stated,
                        "{}: actual {a:e} > stated {stated:e}",
                        pt.label()
                    );
                    worst = worst.max(a / stated);
                    compared += 1;
                }
            }
        }
    }
    eprintln!("extreme grid: compared {compared} cases at 256 bits, {refused} refused; worst actual/stated error = {worst:.3}");
    assert!(compared > 100);
}
