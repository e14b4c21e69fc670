//! Typed reports of both engines, the values the library returns: the wedge's
//! ([`wedge::SolveReport`], [`wedge::StressReport`], [`wedge::FieldReport`]) and the impact
//! engine's ([`impact::RunReport`], [`impact::GreenReport`], [`impact::EdgeReport`]).
//!
//! What every report shares lives here: a number with its error estimate ([`Quantity`] for
//! the wedge's decimal text, [`Number`] for the impact's columns), a quantity that may be
//! unavailable with its reason ([`Entry`]), the print floor, and the JSON numbers. Each report
//! has one ordered key list (`SOLVE_KEYS`, `RUN_KEYS`, ...) and is written as JSON and CSV in
//! its own module, from its typed fields: the command lines and the figures only print.

use ::wedge::{Result, WedgeError};
use complexfn::Real;
use rug::Float;
use serde_json::{json, Number as JsonNumber, Value};

pub mod axisym;
pub mod impact;
pub mod wedge;

use self::wedge::Selection;

/// A report as the command lines print it: its JSON, and its plain form.
pub trait Printed {
    /// The report as one JSON object.
    fn to_json(&self) -> Value;
    /// The JSON as printed: one line for the wedge's reports, indented for the impact's.
    fn json_text(&self) -> String;
    /// The plain form: a table (the wedge's reports) or CSV with `#` header lines holding
    /// `cmdline` (the impact's).
    fn plain_text(&self, cmdline: &str) -> String;
}

macro_rules! printed {
    ($t:ty, one_line, table) => {
        impl Printed for $t {
            fn to_json(&self) -> Value {
                <$t>::to_json(self)
            }
            fn json_text(&self) -> String {
                format!("{}\n", <$t>::to_json(self))
            }
            fn plain_text(&self, _cmdline: &str) -> String {
                self.to_table()
            }
        }
    };
    ($t:ty, indented, csv) => {
        impl Printed for $t {
            fn to_json(&self) -> Value {
                <$t>::to_json(self)
            }
            fn json_text(&self) -> String {
                serde_json::to_string_pretty(&<$t>::to_json(self)).unwrap_or_default() + "\n"
            }
            fn plain_text(&self, cmdline: &str) -> String {
                self.to_csv(cmdline)
            }
        }
    };
}

printed!(wedge::SolveReport, one_line, table);
printed!(wedge::StressReport, one_line, table);
printed!(wedge::FieldReport, one_line, table);
printed!(impact::RunReport, indented, csv);
printed!(axisym::AxiReport, indented, csv);
printed!(impact::GreenReport, indented, csv);
printed!(impact::EdgeReport, indented, csv);
printed!(impact::StrikerGreenReport, indented, csv);

/// A JSON number with exactly the digits given (arbitrary precision), from decimal text in
/// any form the inputs accept (`+86`, `.5`, `500.`, `086` are written `86`, `0.5`, `500.0`,
/// `86`); null for text that is not a number.
pub fn num(s: &str) -> Value {
    match json_decimal(s.trim()).parse::<JsonNumber>() {
        Ok(n) => Value::Number(n),
        Err(_) => Value::Null,
    }
}

/// Decimal text in JSON's number grammar: no leading `+`, a digit before and after the
/// point, no leading zeros.
fn json_decimal(s: &str) -> String {
    let (sign, body) = match s.strip_prefix('-') {
        Some(b) => ("-", b),
        None => ("", s.strip_prefix('+').unwrap_or(s)),
    };
    let (mantissa, exponent) = match body.find(['e', 'E']) {
        Some(k) => body.split_at(k),
        None => (body, ""),
    };
    let (int, frac) = match mantissa.split_once('.') {
        Some((i, f)) => (i, Some(f)),
        None => (mantissa, None),
    };
    let int = int.trim_start_matches('0');
    let int = if int.is_empty() { "0" } else { int };
    let frac = match frac {
        Some("") => ".0".to_string(),
        Some(f) => format!(".{f}"),
        None => String::new(),
    };
    let exponent = exponent.replacen("e+", "e", 1).replacen("E+", "E", 1);
    format!("{sign}{int}{frac}{exponent}")
}

/// An f64 (an error estimate) as a JSON number in scientific notation.
pub fn ratio(x: f64) -> Value {
    num(&format!("{x:e}"))
}

/// A number of a report: its value in f64 and, when the report was asked for more digits
/// than f64 holds, its decimal text to those digits.
#[derive(Clone, Debug, PartialEq)]
pub struct Number {
    /// The value, rounded to f64.
    pub value: f64,
    /// The decimal text at the digits asked for (`None`: the f64 is the value).
    pub text: Option<String>,
}

impl Number {
    /// The JSON number: the decimal text when there is one, else the f64.
    pub fn json(&self) -> Value {
        match &self.text {
            None => json!(self.value),
            Some(t) => num(t),
        }
    }
    /// The CSV cell: the JSON number's text.
    pub fn cell(&self) -> String {
        self.json().to_string()
    }
}

/// A reported number: the decimal text of its value (the digits printed) and its absolute
/// error estimate, in the quantity's own units.
#[derive(Clone, Debug, PartialEq)]
pub struct Quantity {
    pub(crate) text: String,
    pub(crate) error: f64,
}

impl Quantity {
    /// `x` printed to `digits` significant digits, with the estimate `error` (at least
    /// `floor` |x|, the print floor); an error naming `key` when either is not finite.
    pub(crate) fn new<T: Real>(
        key: &str,
        x: &T,
        error: f64,
        floor: f64,
        digits: usize,
    ) -> Result<Self> {
        if !x.is_finite() {
            return Err(not_finite(key));
        }
        if !error.is_finite() {
            return Err(not_finite(&format!("the error estimate of {key}")));
        }
        Ok(Quantity {
            text: x.to_decimal(digits),
            error: error.max(floor * x.to_f64().abs()),
        })
    }
    /// The value as decimal text, with the digits of the report.
    pub fn text(&self) -> &str {
        &self.text
    }
    /// The value rounded to f64 (use [`Self::text`] or [`Self::to_float`] for the digits
    /// beyond).
    pub fn value(&self) -> f64 {
        self.text.parse().unwrap_or(f64::NAN)
    }
    /// The value at `bits` of precision (exactly the printed digits, rounded to `bits`).
    pub fn to_float(&self, bits: u32) -> Float {
        match Float::parse(&self.text) {
            Ok(x) => Float::with_val(bits, x),
            Err(_) => Float::with_val(bits, f64::NAN),
        }
    }
    /// The absolute error estimate.
    pub fn error(&self) -> f64 {
        self.error
    }
    /// The same quantity printed to `digits` digits (its estimate kept, at least `floor`
    /// |value|).
    pub(crate) fn rounded(&self, digits: usize, floor: f64) -> Quantity {
        let x = self.to_float(4096);
        Quantity {
            text: x.to_decimal(digits),
            error: self.error.max(floor * self.value().abs()),
        }
    }
}

pub(crate) fn not_finite(key: &str) -> WedgeError {
    WedgeError::NotFinite {
        what: key.to_string(),
    }
}

/// A quantity that a case may lack: its value, the reason it is unavailable, or left out by
/// the caller's [`Selection`].
#[derive(Clone, Debug, PartialEq)]
pub enum Entry<V> {
    /// The value.
    Value(V),
    /// Why there is no value.
    Unavailable(String),
    /// Not computed: the selection left it out.
    Omitted,
}

impl<V> Entry<V> {
    /// The value, if available.
    pub fn value(&self) -> Option<&V> {
        match self {
            Entry::Value(v) => Some(v),
            _ => None,
        }
    }
    /// The reason, if unavailable.
    pub fn reason(&self) -> Option<&str> {
        match self {
            Entry::Unavailable(r) => Some(r),
            _ => None,
        }
    }
    /// The entry of `key` when `sel` wants it (computed by `f`), else [`Entry::Omitted`].
    pub(crate) fn when(sel: &Selection, key: &str, f: impl FnOnce() -> Self) -> Self {
        if sel.wants(key) {
            f()
        } else {
            Entry::Omitted
        }
    }
}

/// The relative error floor of a value printed to `digits` significant digits and computed
/// at `bits` bits: half a unit in the last printed digit, or 8 units of round-off.
pub fn print_floor(digits: usize, bits: u32) -> f64 {
    (0.5 * 10f64.powi(1 - digits as i32)).max(8.0 * 2f64.powi(-(bits as i32)))
}

/// One history's error model as JSON (`error_model.<key>` of an impact run, plane or
/// axisymmetric): its `estimator`, `safety`, `order_credited` (when one is),
/// `conservative_rows`, and `cell_floor_rows` and `order_shown` (its `rows`, `safety` and
/// `order_credited`; when there are).
pub(crate) fn error_model_json(m: &::impact::ErrorModel) -> serde_json::Value {
    let mut o = serde_json::Map::new();
    o.insert("estimator".into(), serde_json::json!(m.estimator.name()));
    o.insert("safety".into(), serde_json::json!(m.safety));
    if let Some(p) = m.order_credited {
        o.insert("order_credited".into(), serde_json::json!(p));
    }
    o.insert(
        "conservative_rows".into(),
        serde_json::json!(m.conservative_rows),
    );
    if m.cell_floor_rows > 0 {
        o.insert(
            "cell_floor_rows".into(),
            serde_json::json!(m.cell_floor_rows),
        );
    }
    if let Some(s) = m.order_shown {
        o.insert(
            "order_shown".into(),
            serde_json::json!({
                "rows": s.rows,
                "safety": s.safety,
                "order_credited": s.order_credited,
            }),
        );
    }
    serde_json::Value::Object(o)
}
