//! `accuracy`: error against run time of the wedge solution, f64 and MPFR paths, against a
//! 400-bit reference. Prints a Markdown table and writes `figures/error_vs_time.csv`.
//!
//! Run: `cargo run --release --bin accuracy [-- --out DIR]`.

use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let out = match args.as_slice() {
        [] => "figures".to_string(),
        [flag, dir] if flag == "--out" => dir.clone(),
        _ => {
            eprintln!("accuracy: usage: accuracy [--out DIR]");
            return ExitCode::from(2);
        }
    };
    match dyncontact::accuracy::report(false) {
        Ok(rows) => {
            print!("{}", dyncontact::accuracy::markdown(&rows));
            let path = std::path::Path::new(&out).join("error_vs_time.csv");
            if let Err(e) = std::fs::create_dir_all(&out).and_then(|_| {
                std::fs::write(
                    &path,
                    dyncontact::accuracy::csv(&rows, dyncontact::accuracy::REFERENCE_BITS),
                )
            }) {
                eprintln!("accuracy: cannot write {}: {e}", path.display());
                return ExitCode::from(1);
            }
            eprintln!("wrote {}", path.display());
            match dyncontact::accuracy::curve_check(200, 200) {
                Ok(c) => println!(
                    "\nalpha-V curve (Theta = 89 deg, gamma = 0.6, coupled, paper), {} points in f64 on one thread: {:.1} ms; largest relative error of V against 200 bits {:.1e} (stated at most {:.1e}; worst actual/stated {:.2})",
                    c.points,
                    c.seconds * 1e3,
                    c.max_error,
                    c.max_stated,
                    c.worst_ratio
                ),
                Err(e) => {
                    eprintln!("accuracy: {e}");
                    return ExitCode::from(1);
                }
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("accuracy: {e}");
            ExitCode::from(1)
        }
    }
}
