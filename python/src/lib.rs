//! The extension module `dyncontact._dyncontact`: the Python package's one door into the
//! library. Each call takes the command line's arguments (the package turns keyword
//! arguments into flags: `theta_deg=86` is `--theta-deg 86`), parses them with the programs'
//! own parsers (`dyncontact::cli`), computes the typed report with the GIL released, and
//! returns the report's JSON text, the same the command line prints with `--json`. The
//! Python side reads it into result objects (floats or `decimal.Decimal`, numpy arrays).
//!
//! Long work runs on a worker thread while the calling thread polls every
//! `POLL` (50 ms): it passes the fraction done to the progress callable and checks for signals, so
//! that Ctrl-C (KeyboardInterrupt) stops an impact march or a curve between its steps or rows.
//! The engine's own threads (rayon) are limited by `set_num_threads`.

use std::ops::ControlFlow;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use clap::Parser;
use dyncontact::cli::impact::{Command as ImpactCommand, ImpactCli};
use dyncontact::cli::wedge::{Command as WedgeCommand, WedgeCli};
use dyncontact::cli::{shorten_numbers, usage_error};
use dyncontact::impact_api;
use dyncontact::report::Printed;
use dyncontact::Error;
use pyo3::create_exception;
use pyo3::exceptions::{PyArithmeticError, PyValueError};
use pyo3::prelude::*;

create_exception!(
    _dyncontact,
    InvalidParameterError,
    PyValueError,
    "A bad input: its `parameter` attribute names the keyword argument responsible, and the \
     message says what range or form is admissible."
);
create_exception!(
    _dyncontact,
    NumericalError,
    PyArithmeticError,
    "A numerical failure: a case that cannot be computed to its tolerance, with the reason and \
     the case's inputs."
);

/// How often the calling thread looks at signals and progress while a worker computes.
const POLL: Duration = Duration::from_millis(50);

/// The thread pool the engine's parallel loops run in (`None`: rayon's global pool).
static POOL: Mutex<Option<Arc<rayon::ThreadPool>>> = Mutex::new(None);

fn pool() -> Option<Arc<rayon::ThreadPool>> {
    POOL.lock().map(|p| p.clone()).unwrap_or(None)
}

/// The state a worker shares with the calling thread: a stop request and the fraction done.
struct Control {
    stop: AtomicBool,
    fraction: AtomicU64,
}

impl Control {
    fn new() -> Self {
        Control {
            stop: AtomicBool::new(false),
            fraction: AtomicU64::new(0f64.to_bits()),
        }
    }
    fn set_fraction(&self, f: f64) {
        self.fraction.store(f.to_bits(), Ordering::Relaxed);
    }
    fn fraction(&self) -> f64 {
        f64::from_bits(self.fraction.load(Ordering::Relaxed))
    }
    /// Continue, or Break once a stop was asked for.
    fn go_on(&self) -> ControlFlow<()> {
        if self.stop.load(Ordering::Relaxed) {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    }
}

/// A flag as the command line spells it (`--theta-deg`) turned into the keyword argument's
/// name (`theta_deg`), in a whole message.
fn keyword_names(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    while let Some(k) = rest.find("--") {
        out.push_str(&rest[..k]);
        let after = &rest[k + 2..];
        let len = after
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
            .unwrap_or(after.len());
        if len == 0 {
            out.push_str("--");
        } else {
            out.push_str(&after[..len].replace('-', "_"));
        }
        rest = &after[len..];
    }
    out.push_str(rest);
    out
}

fn invalid(py: Python<'_>, parameter: &str, message: &str) -> PyErr {
    let mut message = keyword_names(&shorten_numbers(message));
    if !parameter.is_empty() && !message.contains(parameter) {
        // the engines name some inputs in words ("V0/c1"): the keyword comes first
        message = format!("{parameter}: {message}");
    }
    let err = InvalidParameterError::new_err(message);
    let _ = err.value(py).setattr("parameter", parameter);
    err
}

/// A usage error of the flags (missing, unknown or malformed) as an `InvalidParameterError`
/// naming the first keyword argument concerned.
fn usage(py: Python<'_>, program: &str, e: &clap::Error) -> PyErr {
    use clap::error::{ContextKind, ContextValue};
    let line = usage_error(program, e).unwrap_or_else(|| e.to_string());
    let line = line.trim_end();
    let line = line
        .strip_prefix(&format!("{program}: "))
        .unwrap_or(line)
        .to_string();
    let spec = match e.get(ContextKind::InvalidArg) {
        Some(ContextValue::String(s)) => Some(s.clone()),
        Some(ContextValue::Strings(v)) => v.first().cloned(),
        _ => None,
    };
    let parameter = spec
        .as_deref()
        .and_then(|s| s.find("--").map(|k| &s[k + 2..]))
        .map(|s| {
            let end = s
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
                .unwrap_or(s.len());
            s[..end].replace('-', "_")
        })
        .unwrap_or_default();
    invalid(py, &parameter, &line)
}

/// A library error as the Python exception of its kind.
fn to_py(py: Python<'_>, e: Error) -> PyErr {
    match e.parameter() {
        Some(p) => invalid(py, p, &e.to_string()),
        None => NumericalError::new_err(keyword_names(&shorten_numbers(&e.to_string()))),
    }
}

/// How long an interrupted call waits for its worker to stop before it returns: a worker
/// inside one long step (a curve's row at hundreds of digits) finishes that step in the
/// background, and its result is dropped.
const GRACE: Duration = Duration::from_millis(300);

/// Runs `work` on a worker thread (in the engine's pool) with the GIL released, while the
/// calling thread passes the fraction done to `progress` and checks for signals every
/// [`POLL`]; a signal's exception (KeyboardInterrupt) or the callable's own asks the worker
/// to stop and is raised once it has, or after [`GRACE`].
fn supervised<R: Send + 'static>(
    py: Python<'_>,
    progress: Option<Py<PyAny>>,
    work: impl FnOnce(&Control) -> R + Send + 'static,
) -> PyResult<R> {
    let control = Arc::new(Control::new());
    let pool = pool();
    let mut raised: Option<PyErr> = None;
    let caller = std::thread::current();
    let worker = {
        let control = Arc::clone(&control);
        std::thread::spawn(move || {
            let r = match &pool {
                Some(p) => p.install(|| work(&control)),
                None => work(&control),
            };
            caller.unpark();
            r
        })
    };
    let finished = py.detach(|| {
        let mut shown = f64::NAN;
        let mut stopped_at = None;
        loop {
            std::thread::park_timeout(POLL);
            if worker.is_finished() {
                return true;
            }
            if let Some(t) = stopped_at {
                if std::time::Instant::now().duration_since(t) > GRACE {
                    return false;
                }
                continue;
            }
            Python::attach(|py| {
                let mut stop = |e: PyErr| {
                    raised = Some(e);
                    control.stop.store(true, Ordering::Relaxed);
                    stopped_at = Some(std::time::Instant::now());
                };
                if let Err(e) = py.check_signals() {
                    stop(e);
                    return;
                }
                let f = control.fraction();
                if let (Some(cb), false) = (&progress, f == shown) {
                    shown = f;
                    if let Err(e) = cb.call1(py, (f,)) {
                        stop(e);
                    }
                }
            });
        }
    });
    if let Some(e) = raised {
        // a worker still inside its step ends on its own; its result is dropped
        if finished {
            let _ = worker.join();
        }
        return Err(e);
    }
    let r = worker.join().map_err(|panic| {
        let what = panic
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_else(|| "unknown".into());
        NumericalError::new_err(format!("internal error of the engine: {what}"))
    })?;
    if let Some(cb) = &progress {
        cb.call1(py, (1.0,))?;
    }
    Ok(r)
}

/// `wedge SUBCOMMAND FLAGS...` (the flags as the command line takes them): the report's JSON
/// text; a curve is a JSON array of its rows.
#[pyfunction]
#[pyo3(name = "wedge", signature = (argv, progress=None))]
fn wedge_call(py: Python<'_>, argv: Vec<String>, progress: Option<Py<PyAny>>) -> PyResult<String> {
    let cli = WedgeCli::try_parse_from(std::iter::once("wedge".to_string()).chain(argv))
        .map_err(|e| usage(py, "wedge", &e))?;
    let done = supervised(py, progress, move |control| -> Result<String, Error> {
        Ok(match cli.command {
            WedgeCommand::Solve(a) => a.report()?.json_text(),
            WedgeCommand::Stress(a) => a.report()?.json_text(),
            WedgeCommand::Field(a) => a.report()?.json_text(),
            WedgeCommand::Curve(a) => {
                let plan = a.plan()?;
                let total = plan.alphas.len().max(1) as f64;
                let mut rows = Vec::with_capacity(plan.alphas.len());
                plan.rows(
                    || control.go_on(),
                    |chunk| {
                        rows.extend(chunk.iter().map(|r| r.to_json().to_string()));
                        control.set_fraction(rows.len() as f64 / total);
                        control.go_on()
                    },
                )?;
                format!("[{}]\n", rows.join(","))
            }
        })
    })?;
    done.map_err(|e| to_py(py, e))
}

/// `impact SUBCOMMAND FLAGS...` (the flags as the command line takes them): the report's JSON
/// text.
#[pyfunction]
#[pyo3(name = "impact", signature = (argv, progress=None))]
fn impact_call(py: Python<'_>, argv: Vec<String>, progress: Option<Py<PyAny>>) -> PyResult<String> {
    let cli = ImpactCli::try_parse_from(std::iter::once("impact".to_string()).chain(argv))
        .map_err(|e| usage(py, "impact", &e))?;
    let done = supervised(py, progress, move |control| -> Result<String, Error> {
        Ok(match cli.command {
            ImpactCommand::Run(a) => impact_api::run_any(&a.input()?, |p| {
                control.set_fraction(p.fraction);
                control.go_on()
            })?
            .json_text(),
            ImpactCommand::Green(a) => impact_api::green(&a.input())?.json_text(),
            ImpactCommand::Edge(a) => impact_api::edge(&a.input()?)?.json_text(),
            ImpactCommand::StrikerGreen(a) => impact_api::striker_green(&a.input()?)?.json_text(),
        })
    })?;
    done.map_err(|e| to_py(py, e))
}

/// Limits the engine's own threads (its parallel loops) to `n`; `0` returns to the default
/// (one per core, or `RAYON_NUM_THREADS`).
#[pyfunction]
fn set_num_threads(py: Python<'_>, n: usize) -> PyResult<()> {
    let new = if n == 0 {
        None
    } else {
        Some(Arc::new(
            rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| NumericalError::new_err(format!("no thread pool of {n}: {e}")))?,
        ))
    };
    match POOL.lock() {
        Ok(mut p) => *p = new,
        Err(_) => return Err(invalid(py, "n", "the thread setting is unusable")),
    }
    Ok(())
}

/// The number of threads the engine's parallel loops use.
#[pyfunction]
fn get_num_threads() -> usize {
    pool().map_or_else(rayon::current_num_threads, |p| p.current_num_threads())
}

/// The extension module.
#[pymodule]
fn _dyncontact(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add(
        "InvalidParameterError",
        m.py().get_type::<InvalidParameterError>(),
    )?;
    m.add("NumericalError", m.py().get_type::<NumericalError>())?;
    m.add("VERSION", dyncontact::VERSION)?;
    m.add("RUN_MAX_DIGITS", impact_api::RUN_MAX_DIGITS)?;
    m.add("MAX_DIGITS", dyncontact::MAX_DIGITS)?;
    m.add_function(wrap_pyfunction!(wedge_call, m)?)?;
    m.add_function(wrap_pyfunction!(impact_call, m)?)?;
    m.add_function(wrap_pyfunction!(set_num_threads, m)?)?;
    m.add_function(wrap_pyfunction!(get_num_threads, m)?)?;
    Ok(())
}
