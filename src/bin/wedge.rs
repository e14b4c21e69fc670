//! Command line for the wedge-indentation solution.
fn main() {
    eprintln!("wedge: the command line is not available yet");
    std::process::exit(2);
}
