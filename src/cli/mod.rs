//! What the command lines share: the material flags of the impact program as one argument
//! group, one-line usage errors that name every missing or bad flag, numbers in messages
//! shortened to a readable width, and output that ends quietly when its reader has gone.

pub mod impact;
pub mod wedge;

use std::io::Write;
use std::process::ExitCode;

use clap::error::{ContextKind, ContextValue, ErrorKind};
use clap::Args;

use crate::error::InputError;

/// The half-plane's material: `--c1` and `--c2` (m/s) or `--poisson`.
#[derive(Args, Clone, Debug, Default, PartialEq)]
pub struct MaterialArgs {
    /// P-wave speed c1 in m/s (with --c2).
    #[arg(long, allow_hyphen_values = true)]
    pub c1: Option<String>,
    /// S-wave speed c2 in m/s (with --c1).
    #[arg(long, allow_hyphen_values = true)]
    pub c2: Option<String>,
    /// Poisson's ratio nu in (-1, 1/2), nu != 0 (instead of --c1, --c2).
    #[arg(long, allow_hyphen_values = true)]
    pub poisson: Option<String>,
}

/// The decimal text of a flag as a finite f64.
fn finite(
    parameter: &'static str,
    flag: &str,
    text: &Option<String>,
) -> Result<Option<f64>, InputError> {
    match text {
        None => Ok(None),
        Some(t) => match t.trim().parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(Some(x)),
            _ => Err(InputError::new(
                parameter,
                format!("invalid {flag} = {t:?}: not a finite number"),
            )),
        },
    }
}

/// The material flags as numbers: (c1, c2, poisson), each as given or absent.
pub type MaterialNumbers = (Option<f64>, Option<f64>, Option<f64>);

impl MaterialArgs {
    /// The three flags as f64 (each refused, naming it, when it is not a finite number).
    pub fn numbers(&self) -> Result<MaterialNumbers, InputError> {
        Ok((
            finite("c1", "--c1", &self.c1)?,
            finite("c2", "--c2", &self.c2)?,
            finite("poisson", "--poisson", &self.poisson)?,
        ))
    }
}

/// A flag as clap writes it in an error (`--theta-deg <THETA_DEG>`, or a group
/// `<--alpha <ALPHA>|--speed <SPEED>>`) as the user types it: `--theta-deg`, `--alpha or
/// --speed`.
fn flag_name(spec: &str) -> String {
    let inner = spec
        .strip_prefix('<')
        .and_then(|s| s.strip_suffix('>'))
        .filter(|s| s.starts_with("--"))
        .unwrap_or(spec);
    inner
        .split('|')
        .map(|alt| alt.split_whitespace().next().unwrap_or(alt).to_string())
        .collect::<Vec<_>>()
        .join(" or ")
}

/// A usage error of `program` in one line: every missing flag named (both where either of
/// two will do), or clap's own first line for the other errors; a call without a
/// subcommand gets the usage instead (`None` for help and version, which are not errors).
pub fn usage_error(program: &str, e: &clap::Error) -> Option<String> {
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => None,
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand | ErrorKind::MissingSubcommand => {
            Some(e.render().to_string())
        }
        ErrorKind::MissingRequiredArgument => {
            let missing: Vec<String> = match e.get(ContextKind::InvalidArg) {
                Some(ContextValue::Strings(list)) => list.iter().map(|s| flag_name(s)).collect(),
                Some(ContextValue::String(s)) => vec![flag_name(s)],
                _ => Vec::new(),
            };
            Some(if missing.is_empty() {
                format!("{program}: missing required flags (see {program} --help)")
            } else {
                format!("{program}: missing {}", missing.join("; "))
            })
        }
        _ => {
            let text = e.to_string();
            let first = text.lines().next().unwrap_or("invalid arguments");
            Some(format!(
                "{program}: {}",
                shorten_numbers(first.trim_start_matches("error: "))
            ))
        }
    }
}

/// The most characters of a number written in a message; longer ones are cut to
/// [`SHORT_DIGITS`] significant digits with their length noted.
pub const MAX_NUMBER_CHARS: usize = 40;

/// The significant digits a shortened number keeps.
pub const SHORT_DIGITS: usize = 17;

/// `message` with every number longer than [`MAX_NUMBER_CHARS`] characters cut to
/// [`SHORT_DIGITS`] significant digits (`3.1415926535897932... (600 digits)`); the rest
/// unchanged.
pub fn shorten_numbers(message: &str) -> String {
    let chars: Vec<char> = message.chars().collect();
    let mut out = String::with_capacity(message.len());
    let mut i = 0;
    while i < chars.len() {
        if chars[i].is_ascii_digit() {
            let start = i;
            while i < chars.len()
                && (chars[i].is_ascii_digit()
                    || chars[i] == '.'
                    || ((chars[i] == 'e' || chars[i] == 'E')
                        && chars
                            .get(i + 1)
                            .is_some_and(|c| c.is_ascii_digit() || *c == '-' || *c == '+'))
                    || ((chars[i] == '-' || chars[i] == '+')
                        && i > start
                        && (chars[i - 1] == 'e' || chars[i - 1] == 'E')))
            {
                i += 1;
            }
            let number: String = chars[start..i].iter().collect();
            if number.len() > MAX_NUMBER_CHARS {
                let (mantissa, exponent) = match number.find(['e', 'E']) {
                    Some(k) => (&number[..k], &number[k..]),
                    None => (number.as_str(), ""),
                };
                let digits = mantissa.chars().filter(|c| c.is_ascii_digit()).count();
                let mut kept = 0;
                let mut significant = false;
                let cut: String = mantissa
                    .chars()
                    .take_while(|c| {
                        if c.is_ascii_digit() {
                            significant |= *c != '0';
                            if significant {
                                kept += 1;
                            }
                        }
                        kept <= SHORT_DIGITS
                    })
                    .collect();
                out.push_str(&format!("{cut}...{exponent} ({digits} digits)"));
            } else {
                out.push_str(&number);
            }
        } else {
            out.push(chars[i]);
            i += 1;
        }
    }
    out
}

/// Writes `text` to standard output; a closed pipe (`| head`, `| true`) ends the output
/// quietly.
pub fn print(text: &str) {
    let mut out = std::io::stdout().lock();
    let _ = out.write_all(text.as_bytes()).and_then(|_| out.flush());
}

/// Prints `report` as JSON (`json`) or in its plain form (a table, or CSV with the command
/// line in its `#` header); a closed pipe ends the output quietly.
pub fn emit(report: &impl crate::report::Printed, json: bool) {
    print(&if json {
        report.json_text()
    } else {
        report.plain_text(&command_line())
    });
}

/// A command-line program: parses its flags as `C` (a usage error is one line on stderr with
/// exit code 2; help and version print and exit 0), runs `run`, and ends with exit code 0,
/// or 2 with the error on one line, its numbers shortened.
pub fn program<C: clap::Parser, E: std::fmt::Display>(
    name: &str,
    run: impl FnOnce(C) -> Result<(), E>,
) -> ExitCode {
    let cli = match C::try_parse() {
        Ok(c) => c,
        Err(e) => {
            return match usage_error(name, &e) {
                None => {
                    let _ = e.print();
                    ExitCode::SUCCESS
                }
                Some(line) => {
                    eprintln!("{}", line.trim_end());
                    ExitCode::from(2)
                }
            };
        }
    };
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{name}: {}", shorten_numbers(&e.to_string()));
            ExitCode::from(2)
        }
    }
}

/// The command line as it was typed, for the CSV headers.
pub fn command_line() -> String {
    std::env::args().collect::<Vec<_>>().join(" ")
}
