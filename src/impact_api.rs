//! The impact engine's calls, inputs in and typed reports out: [`run`] (a striker's
//! transient impact, [`RunReport`]), [`green`] (Lamb's surface influence functions,
//! [`GreenReport`]) and [`edge`] (the pressure's power law at a moving contact edge,
//! [`EdgeReport`]). Their inputs ([`RunInput`], [`GreenInput`], [`EdgeInput`]) hold the
//! command line's flags by name, as text or numbers; a bad one is an [`Error::Input`] naming
//! it.
// `!(x > a)` is used on purpose: it is true for NaN, so range checks reject NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use std::ops::ControlFlow;

use complexfn::quadrature::CachedRules;
use complexfn::{Dd, Precision, Real};
use impact::{EdgeLaw, ImpactCase, Stop};
use lamb::HalfPlane;
use rug::Float;

use crate::error::{Error, InputError};
use crate::input::impact as spec;
use crate::report::axisym::AxiReport;
use crate::report::impact::{EdgeReport, GreenReport, RunReport, StrikerGreenReport};
use crate::report::Printed;

/// The most digits a run gives: the march runs in double-double (about 32 digits) above
/// f64.
pub const RUN_MAX_DIGITS: u32 = 30;

/// Poisson's ratio of `impact run` when no material is given: 1/4, Poisson's solid
/// (c1/c2 = 3^(1/2)), the usual reference of Lamb's problem.
pub const DEFAULT_POISSON: f64 = 0.25;

type R<T> = std::result::Result<T, Error>;

/// The inputs of an impact run, named as the command line's flags (`impact run --help`).
#[derive(Clone, Debug, PartialEq)]
pub struct RunInput {
    /// The half-plane's P-wave speed c1 in m/s (with `c2`).
    pub c1: Option<f64>,
    /// The half-plane's S-wave speed c2 in m/s (with `c1`).
    pub c2: Option<f64>,
    /// Poisson's ratio (instead of `c1`, `c2`).
    pub poisson: Option<f64>,
    /// The striker: `rigid`, `elastic:c1=..,c2=..,density_ratio=..` or
    /// `shell:thickness_over_R=..,c1=..,c2=..,density_ratio=..`.
    pub striker: String,
    /// The profile: `circle:R=..`, `parabola:R=..`, `power:A=..,k=..`, `wedge:theta_deg=..`,
    /// `flat:a=..` or `table:FILE`.
    pub profile: String,
    /// m0/(rho R^2) of a free striker.
    pub mass_ratio: Option<f64>,
    /// V0/c1 of a free striker.
    pub v0_over_c1: Option<f64>,
    /// A prescribed penetration: `speed:V_over_c1=..` or `table:FILE`.
    pub driven: Option<String>,
    /// The edge law: `signorini` or `kinematic`.
    pub law: String,
    /// The end: `c1t/R=VALUE`, `separation` or `separation:max=VALUE`.
    pub end: String,
    /// The length scale R in metres of the flat punch, the wedge, the power law and a table.
    pub length: Option<f64>,
    /// dx/R of the finest grid.
    pub dx: f64,
    /// kappa = c1 dt/dx.
    pub kappa: f64,
    /// Grid levels (1 to 4).
    pub levels: usize,
    /// The edge cell: `model` or `whole`.
    pub edge_cell: String,
    /// How many times the grid is halved for the first steps (`None`: the engine's default,
    /// [`impact::solve::START_HALVINGS`]; 0: one grid throughout; `docs/impact.md`, section 11).
    pub start_halvings: Option<usize>,
    /// Pressure profiles at `c1t/R=T1,T2,...`.
    pub pressure_at: Option<String>,
    /// Significant digits (1 to [`RUN_MAX_DIGITS`], the march in double-double); `None` for f64.
    pub digits: Option<u32>,
    /// Run even above the memory limit.
    pub force: bool,
    /// The memory limit in GiB.
    pub memory_limit_gib: f64,
    /// `plane` (plane strain, the default) or `axisymmetric` (a body of revolution on the
    /// half-space, `docs/axisymmetric.md`).
    pub geometry: String,
    /// dr/R of the finest grid of an axisymmetric run (`None`: about 30 rings across the
    /// largest contact radius expected).
    pub dr: Option<f64>,
}

impl Default for RunInput {
    /// The command line's defaults: a rigid striker, Signorini's conditions, dx/R = 0.005,
    /// kappa = 2, three levels, the edge model, the default memory limit; the material, the
    /// profile, the drive and the end left to the caller.
    fn default() -> Self {
        RunInput {
            c1: None,
            c2: None,
            poisson: None,
            striker: "rigid".into(),
            profile: String::new(),
            mass_ratio: None,
            v0_over_c1: None,
            driven: None,
            law: "signorini".into(),
            end: String::new(),
            length: None,
            dx: 0.005,
            kappa: 2.0,
            levels: 3,
            edge_cell: "model".into(),
            start_halvings: None,
            pressure_at: None,
            digits: None,
            force: false,
            memory_limit_gib: impact::cost::DEFAULT_MEMORY_LIMIT_GIB,
            geometry: "plane".into(),
            dr: None,
        }
    }
}

fn impact_law(law: &str) -> R<EdgeLaw> {
    match law {
        "signorini" => Ok(EdgeLaw::Signorini),
        "kinematic" => Ok(EdgeLaw::Kinematic),
        other => Err(InputError::new(
            "law",
            format!("invalid --law {other:?}: signorini or kinematic"),
        )
        .into()),
    }
}

impl RunInput {
    /// The case these inputs describe (checked by the engine when it is solved).
    pub fn case(&self) -> R<ImpactCase> {
        self.check_missing()?;
        let nu = self.nu()?;
        let c1 = match (self.c1, self.c2, self.poisson) {
            (Some(c1), Some(_), None) => Some(c1),
            _ => None,
        };
        let striker = spec::striker(&self.striker, c1)?;
        let prof = spec::profile(&self.profile, self.length)?;
        let law = impact_law(&self.law)?;
        let (end, stop, drive) = self.end_and_drive(&striker)?;
        let mut c = ImpactCase::new(nu, prof, drive, law, end).with_striker(striker);
        c.stop = stop;
        c.dx = self.dx;
        c.kappa = self.kappa;
        c.levels = self.levels;
        if let Some(k) = self.start_halvings {
            c.start_halvings = k;
        }
        c.edge_model = match self.edge_cell.as_str() {
            "model" => true,
            "whole" => false,
            other => {
                return Err(InputError::new(
                    "edge_cell",
                    format!("invalid --edge-cell {other}: admissible values are model, whole"),
                )
                .into())
            }
        };
        Ok(c)
    }

    /// The end, where the run stops and the drive (a free `striker` or a prescribed
    /// penetration); stopping at the separation is refused for a driven striker.
    fn end_and_drive(&self, striker: &impact::Striker) -> R<(f64, Stop, impact::Drive)> {
        let (end, stop) = spec::end(&self.end)?;
        let drive = spec::drive(
            self.driven.as_deref(),
            self.mass_ratio,
            self.v0_over_c1,
            striker,
        )?;
        if stop == Stop::AtSeparation && !matches!(drive, impact::Drive::Free { .. }) {
            return Err(InputError::new(
                "end",
                "invalid --end separation: only a free striker separates (give --mass-ratio and --v0-over-c1, or an end time c1t/R=VALUE)",
            )
            .into());
        }
        Ok((end, stop, drive))
    }

    /// Poisson's ratio of the run: from `--poisson` or `--c1`, `--c2`, and
    /// [`DEFAULT_POISSON`] when neither is given.
    fn nu(&self) -> R<f64> {
        match (self.c1, self.c2, self.poisson) {
            (None, None, None) => Ok(DEFAULT_POISSON),
            (c1, c2, nu) => Ok(spec::poisson(c1, c2, nu)?),
        }
    }

    /// Every input missing, named in one error (the first one's parameter).
    fn check_missing(&self) -> R<()> {
        let mut missing: Vec<(&'static str, &str)> = Vec::new();
        if self.profile.is_empty() {
            missing.push(("profile", "--profile"));
        }
        // the shell's and the cylinder's masses follow from their geometry
        let shell = self.striker.starts_with("shell:") || self.striker.starts_with("cylinder:");
        if self.driven.is_none() && self.v0_over_c1.is_none() {
            if self.mass_ratio.is_none() && !shell {
                missing.push(("mass_ratio", "--mass-ratio and --v0-over-c1 (or --driven)"));
            } else {
                missing.push(("v0_over_c1", "--v0-over-c1 (or --driven)"));
            }
        } else if self.driven.is_none() && self.mass_ratio.is_none() && !shell {
            missing.push(("mass_ratio", "--mass-ratio (or --driven)"));
        }
        if self.end.is_empty() {
            missing.push(("end", "--end"));
        }
        match missing.first() {
            None => Ok(()),
            Some((parameter, _)) => Err(InputError::new(
                parameter,
                format!(
                    "missing {}",
                    missing.iter().map(|m| m.1).collect::<Vec<_>>().join("; ")
                ),
            )
            .into()),
        }
    }

    /// The times of the pressure profiles asked for, each refused unless in (0, `end`].
    pub fn pressure_times_within(&self, end: f64) -> R<Vec<f64>> {
        let times = self.pressure_times()?;
        for &t in &times {
            if !(t > 0.0 && t <= end) {
                return Err(InputError::new(
                    "pressure_at",
                    format!(
                        "invalid --pressure-at time {t}: admissible range is (0, {end}], the run's times"
                    ),
                )
                .into());
            }
        }
        Ok(times)
    }

    /// The times of the pressure profiles asked for.
    pub fn pressure_times(&self) -> R<Vec<f64>> {
        match &self.pressure_at {
            None => Ok(Vec::new()),
            Some(s) => Ok(spec::time_list("pressure_at", s, "--pressure-at")?),
        }
    }
}

impl RunInput {
    /// Whether the run is axisymmetric (`geometry` = `axisymmetric`); an error for a
    /// geometry other than `plane` and `axisymmetric`.
    pub fn axisymmetric(&self) -> R<bool> {
        match self.geometry.as_str() {
            "plane" => Ok(false),
            "axisymmetric" => Ok(true),
            other => Err(InputError::new(
                "geometry",
                format!("invalid --geometry {other:?}: plane or axisymmetric"),
            )
            .into()),
        }
    }

    /// The axisymmetric case these inputs describe (`geometry` = `axisymmetric`): a rigid
    /// striker, `mass_ratio` = m/(rho R^3); the plane runs' striker models, `--digits`
    /// and `--edge-cell` refused with the reason.
    pub fn axi_case(&self) -> R<impact::axisym::AxiCase> {
        self.check_missing()?;
        let nu = self.nu()?;
        if self.striker != "rigid" {
            return Err(InputError::new(
                "striker",
                format!(
                    "invalid --striker {:?} with --geometry axisymmetric: only rigid strikers (the deformable ones are plane-strain models)",
                    self.striker
                ),
            )
            .into());
        }
        if self.digits.is_some() {
            return Err(InputError::new(
                "digits",
                "invalid --digits with --geometry axisymmetric: the axisymmetric march runs in f64 (its ring coefficients are f64 quadratures)",
            )
            .into());
        }
        let profile = spec::axi_profile(&self.profile, self.length)?;
        let law = impact_law(&self.law)?;
        let (end, stop, drive) = self.end_and_drive(&impact::Striker::Rigid)?;
        let c = impact::axisym::AxiCase {
            poisson: nu,
            profile,
            drive,
            law,
            end,
            stop,
            dr: self.dr,
            kappa: self.kappa,
            levels: self.levels,
        };
        c.validate()?;
        Ok(c)
    }
}

/// The report of either geometry's run ([`run_any`]).
#[derive(Clone, Debug)]
pub enum AnyRunReport {
    /// A plane-strain run.
    Plane(Box<RunReport>),
    /// An axisymmetric run.
    Axisymmetric(Box<AxiReport>),
}

impl Printed for AnyRunReport {
    fn to_json(&self) -> serde_json::Value {
        match self {
            AnyRunReport::Plane(r) => r.to_json(),
            AnyRunReport::Axisymmetric(r) => r.to_json(),
        }
    }
    fn json_text(&self) -> String {
        match self {
            AnyRunReport::Plane(r) => Printed::json_text(r.as_ref()),
            AnyRunReport::Axisymmetric(r) => Printed::json_text(r.as_ref()),
        }
    }
    fn plain_text(&self, cmdline: &str) -> String {
        match self {
            AnyRunReport::Plane(r) => r.to_csv(cmdline),
            AnyRunReport::Axisymmetric(r) => r.to_csv(cmdline),
        }
    }
}

/// Runs the impact of `input` in its geometry ([`run`] or [`run_axisymmetric`]).
pub fn run_any(
    input: &RunInput,
    progress: impl FnMut(impact::Progress) -> ControlFlow<()>,
) -> R<AnyRunReport> {
    Ok(if input.axisymmetric()? {
        AnyRunReport::Axisymmetric(Box::new(run_axisymmetric(input, progress)?))
    } else {
        AnyRunReport::Plane(Box::new(run(input, progress)?))
    })
}

/// Runs the axisymmetric impact of `input` (`geometry` = `axisymmetric`) and reports it.
pub fn run_axisymmetric(
    input: &RunInput,
    progress: impl FnMut(impact::Progress) -> ControlFlow<()>,
) -> R<AxiReport> {
    let c = input.axi_case()?;
    let times = input.pressure_times_within(c.end)?;
    let sol = c.solve(progress)?;
    AxiReport::of(&sol, crate::VERSION, &times).map_err(|m| {
        if m.starts_with("invalid --pressure-at") {
            InputError::new("pressure_at", m).into()
        } else {
            Error::Impact(impact::ImpactError::Step {
                time: "the report".into(),
                reason: m,
            })
        }
    })
}

/// Runs the impact of `input`, calling `progress` as the march goes on, and reports it.
/// When `progress` answers [`ControlFlow::Break`] the march stops and the call ends with
/// [`impact::ImpactError::Stopped`] (an interrupt).
///
/// Refused before any work: a bad input (naming it), `digits` outside 1 to [`RUN_MAX_DIGITS`], a
/// pressure time outside the run, and a run whose estimated memory exceeds
/// `memory_limit_gib` without `force` (to the separation, the march checks the width the
/// contact reaches as it goes).
pub fn run(
    input: &RunInput,
    progress: impl FnMut(impact::Progress) -> ControlFlow<()>,
) -> R<RunReport> {
    if input.axisymmetric()? {
        return Err(InputError::new(
            "geometry",
            "an axisymmetric run is reported by run_axisymmetric (or run_any)",
        )
        .into());
    }
    let mut c = input.case()?;
    c.validate()?;
    if !(input.memory_limit_gib.is_finite() && input.memory_limit_gib > 0.0) {
        return Err(InputError::new(
            "memory_limit_gib",
            format!(
                "invalid --memory-limit-gib {}: admissible range is (0, inf)",
                input.memory_limit_gib
            ),
        )
        .into());
    }
    let times = input.pressure_times_within(c.end)?;
    if let Some(d) = input.digits {
        if !(1..=RUN_MAX_DIGITS).contains(&d) {
            return Err(InputError::new(
                "digits",
                format!(
                    "invalid --digits {d}: admissible range is 1..={RUN_MAX_DIGITS} (the march runs in double-double above f64)"
                ),
            )
            .into());
        }
    }
    if !input.force {
        c.memory_limit = Some(input.memory_limit_gib * 1024.0 * 1024.0 * 1024.0);
    }
    let cost = c.cost_estimate();
    // to an end time the estimate bounds the run; to the separation its cap does, and the
    // march checks the width the contact reaches
    if cost.gib() > input.memory_limit_gib && !input.force && c.stop == Stop::AtEnd {
        return Err(InputError::new(
            "dx",
            format!(
                "the run would take about {:.1} GiB ({} steps by {} cells on the finest grid{}), above the limit of {} GiB: raise --dx, shorten --end, or pass --force (or --memory-limit-gib)",
                cost.gib(),
                cost.steps,
                cost.width,
                if c.starts_finer() {
                    format!(
                        ", its first steps on cells {} times finer: lower --start-halvings",
                        1u64 << c.start_halvings.min(63)
                    )
                } else {
                    String::new()
                },
                input.memory_limit_gib
            ),
        )
        .into());
    }
    let version = crate::VERSION;
    let report = match input.digits {
        None => {
            let sol = c.solve_reporting::<f64>(progress)?;
            let (mut r, rows) = RunReport::of(&sol, version, None, &times).map_err(to_error)?;
            r.add_striker_energy(&sol, &rows)?;
            r
        }
        Some(d) => {
            let sol = c.solve_reporting::<Dd>(progress)?;
            RunReport::of(&sol, version, Some(d as usize), &times)
                .map_err(to_error)?
                .0
        }
    };
    Ok(report)
}

/// A report's own refusal: a pressure time beyond the run's last step, or a value that is
/// not finite (named).
fn to_error(e: crate::report::impact::ReportError) -> Error {
    match e {
        crate::report::impact::ReportError::PressureTime(message) => {
            InputError::new("pressure_at", message).into()
        }
        crate::report::impact::ReportError::NotFinite(key) => {
            Error::Impact(impact::ImpactError::Step {
                time: "the report".into(),
                reason: format!("{key} is not finite"),
            })
        }
    }
}

/// The inputs of `impact green`, named as its flags; numbers as decimal text, parsed at the
/// working precision.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GreenInput {
    /// The P-wave speed c1 in m/s (with `c2`).
    pub c1: Option<String>,
    /// The S-wave speed c2 in m/s (with `c1`).
    pub c2: Option<String>,
    /// Poisson's ratio (instead of `c1`, `c2`).
    pub poisson: Option<String>,
    /// Points s = |x|/(c1 t) > 0, comma-separated.
    pub at: Option<String>,
    /// Cells `sa:sb`, comma-separated, 0 <= sa <= sb.
    pub cells: Option<String>,
    /// The Rayleigh constants.
    pub constants: bool,
    /// Significant digits (MPFR); `None` for f64.
    pub digits: Option<u32>,
}

fn parse_num<T: Real>(parameter: &'static str, name: &str, text: &str, bits: u32) -> R<T> {
    let v = T::parse_prec(text, bits).map_err(|_| {
        InputError::new(
            parameter,
            format!("invalid {name} = {text:?}: not a number"),
        )
    })?;
    if !v.is_finite() {
        return Err(InputError::new(
            parameter,
            format!("invalid {name} = {text}: must be finite"),
        )
        .into());
    }
    Ok(v)
}

fn split_list(parameter: &'static str, name: &str, text: &str) -> R<Vec<String>> {
    let items: Vec<String> = text.split(',').map(|s| s.trim().to_string()).collect();
    if items.iter().any(|s| s.is_empty()) {
        return Err(InputError::new(
            parameter,
            format!("invalid {name} = {text:?}: a comma-separated list of numbers"),
        )
        .into());
    }
    Ok(items)
}

/// The half-plane from `c1`/`c2` or `poisson` at the precision of `bits`.
fn half_plane<T: CachedRules>(a: &GreenInput, bits: u32) -> R<HalfPlane<T>> {
    match (&a.c1, &a.c2, &a.poisson) {
        (None, None, Some(nu)) => {
            let nu: T = parse_num("poisson", "--poisson", nu, bits)?;
            Ok(HalfPlane::from_poisson(nu)?)
        }
        (Some(c1), Some(c2), None) => {
            let c1: T = parse_num("c1", "--c1", c1, bits)?;
            let c2: T = parse_num("c2", "--c2", c2, bits)?;
            if c1.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater)
                || c2.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater)
            {
                return Err(InputError::new(
                    "c1",
                    format!(
                        "invalid --c1, --c2 = {}, {}: wave speeds must be > 0 m/s",
                        c1.to_f64(),
                        c2.to_f64()
                    ),
                )
                .into());
            }
            Ok(HalfPlane::new(c2 / &c1)?)
        }
        (c1, c2, nu) => {
            // the same refusals as a run's material: every other combination is one
            let some = |x: &Option<String>| x.as_ref().map(|_| 1.0);
            Err(match spec::poisson(some(c1), some(c2), some(nu)) {
                Err(e) => e,
                Ok(_) => InputError::new("poisson", "give --poisson, or --c1 and --c2 (m/s)"),
            }
            .into())
        }
    }
}

fn green_at<T: CachedRules>(a: &GreenInput, bits: u32, digits: usize) -> R<GreenReport> {
    let hp: HalfPlane<T> = half_plane(a, bits)?;
    if a.at.is_none() && a.cells.is_none() && !a.constants {
        return Err(InputError::new(
            "at",
            "nothing asked: give --at s1,s2,..., --cells sa:sb,... or --constants",
        )
        .into());
    }
    let at = match &a.at {
        None => None,
        Some(at) => {
            let mut points = Vec::new();
            for text in split_list("at", "--at", at)? {
                let s: T = parse_num("at", "s", &text, bits)?;
                if !(s > 0.0) {
                    return Err(InputError::new(
                        "at",
                        "invalid s <= 0: admissible range is (0, inf) for pointwise values (the step responses diverge at s = 0, i.e. at x = 0 or t -> inf)",
                    )
                    .into());
                }
                points.push(s);
            }
            Some(points)
        }
    };
    let cells = match &a.cells {
        None => None,
        Some(cells) => {
            let mut list = Vec::new();
            for text in split_list("cells", "--cells", cells)? {
                let (sa, sb) = text.split_once(':').ok_or_else(|| {
                    InputError::new(
                        "cells",
                        format!("invalid cell {text:?}: write sa:sb with 0 <= sa <= sb"),
                    )
                })?;
                let sa: T = parse_num("cells", "sa", sa, bits)?;
                let sb: T = parse_num("cells", "sb", sb, bits)?;
                if sa > sb || sa < 0.0 {
                    return Err(InputError::new(
                        "cells",
                        format!("invalid cell {text}: admissible range is 0 <= sa <= sb"),
                    )
                    .into());
                }
                list.push((sa, sb));
            }
            Some(list)
        }
    };
    Ok(GreenReport::of(
        &hp,
        bits,
        digits,
        at.as_deref(),
        cells.as_deref(),
        a.constants,
        crate::VERSION,
    )?)
}

/// Lamb's surface influence functions of the half-plane of `input` at its points and cells,
/// and its Rayleigh constants: f64 (17 digits printed) or `digits` digits in MPFR.
pub fn green(input: &GreenInput) -> R<GreenReport> {
    match input.digits {
        None => green_at::<f64>(input, 53, 17),
        Some(d) if !(1..=crate::MAX_DIGITS).contains(&d) => Err(InputError::new(
            "digits",
            format!(
                "invalid --digits {d}: admissible range is 1..={}",
                crate::MAX_DIGITS
            ),
        )
        .into()),
        Some(d) => {
            let p = Precision::from_digits(d, 24)
                .map_err(|e| InputError::new("digits", e.to_string()))?;
            green_at::<Float>(input, p.bits(), d as usize)
        }
    }
}

/// The inputs of `impact edge`, named as its flags.
#[derive(Clone, Debug, PartialEq)]
pub struct EdgeInput {
    /// The P-wave speed c1 in m/s (with `c2`).
    pub c1: Option<f64>,
    /// The S-wave speed c2 in m/s (with `c1`).
    pub c2: Option<f64>,
    /// Poisson's ratio (instead of `c1`, `c2`).
    pub poisson: Option<f64>,
    /// Edge speeds D/c1, comma-separated.
    pub speed_over_c1: Option<String>,
    /// The edge law: `signorini` or `kinematic`.
    pub law: String,
}

impl Default for EdgeInput {
    /// No material and no speeds; Signorini's law.
    fn default() -> Self {
        EdgeInput {
            c1: None,
            c2: None,
            poisson: None,
            speed_over_c1: None,
            law: "signorini".into(),
        }
    }
}

/// The local behaviour of the contact pressure at an edge moving at each speed of `input`.
pub fn edge(input: &EdgeInput) -> R<EdgeReport> {
    let nu = spec::poisson(input.c1, input.c2, input.poisson)?;
    let hp = HalfPlane::from_poisson(nu)?;
    let law = match input.law.as_str() {
        "signorini" => lamb::edge::EdgeLaw::Signorini,
        "kinematic" => lamb::edge::EdgeLaw::Kinematic,
        other => {
            return Err(InputError::new(
                "law",
                format!("invalid --law = {other}: admissible values are signorini, kinematic"),
            )
            .into())
        }
    };
    let list = input.speed_over_c1.as_deref().ok_or_else(|| {
        InputError::new(
            "speed_over_c1",
            "missing --speed-over-c1 D1,D2,... (edge speeds over c1)",
        )
    })?;
    let speeds = list
        .split(',')
        .map(|item| {
            item.trim().parse::<f64>().map_err(|_| {
                InputError::new(
                    "speed_over_c1",
                    format!("invalid --speed-over-c1 entry '{item}': not a number"),
                )
            })
        })
        .collect::<std::result::Result<Vec<f64>, _>>()?;
    Ok(EdgeReport::of(&hp, law, &speeds, crate::VERSION)?)
}

/// The inputs of `impact striker-green` ([`striker_green`]).
#[derive(Clone, Debug, Default)]
pub struct StrikerGreenInput {
    /// The striker's P-wave speed in m/s (with `c2`).
    pub c1: Option<f64>,
    /// The striker's S-wave speed in m/s (with `c1`).
    pub c2: Option<f64>,
    /// The striker's Poisson's ratio (instead of `c1`, `c2`).
    pub poisson: Option<f64>,
    /// The striker: `cylinder`.
    pub striker: String,
    /// The loaded arc's width over R.
    pub arc_over_r: Option<f64>,
    /// The receiver arcs' centres in degrees, comma-separated.
    pub at_deg: Option<String>,
    /// The times, `c2t/R=T1,T2,...`.
    pub times: Option<String>,
}

/// A free elastic cylinder's own influence function: the mean inward normal displacement
/// over receiver arcs under a unit step pressure on an arc of the same width
/// (`impact::striker::green`, `docs/strikers.md`, section 7).
pub fn striker_green(input: &StrikerGreenInput) -> R<StrikerGreenReport> {
    if input.striker != "cylinder" {
        return Err(InputError::new(
            "striker",
            format!(
                "invalid --striker {:?}: admissible value is cylinder (a free elastic disk)",
                input.striker
            ),
        )
        .into());
    }
    let nu = spec::poisson(input.c1, input.c2, input.poisson)?;
    let arc = input.arc_over_r.ok_or_else(|| {
        InputError::new(
            "arc_over_R",
            "missing --arc-over-R ARC (the loaded arc's width over R)",
        )
    })?;
    let at = input.at_deg.as_deref().ok_or_else(|| {
        InputError::new(
            "at_deg",
            "missing --at-deg A1,A2,... (receiver arcs' centres in degrees)",
        )
    })?;
    let angles = split_list("at_deg", "--at-deg", at)?
        .iter()
        .map(|a| {
            a.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    InputError::new(
                        "at_deg",
                        format!("invalid --at-deg entry {a:?}: not a finite number"),
                    )
                })
        })
        .collect::<std::result::Result<Vec<f64>, _>>()?;
    let times_spec = input.times.as_deref().ok_or_else(|| {
        InputError::new("times", "missing --times c2t/R=T1,T2,... (times over R/c2)")
    })?;
    let times = spec::scaled_time_list("times", times_spec, "--times", "c2t/R")?;
    let disk = impact::striker::disk::Disk::new(nu)?;
    let radians: Vec<f64> = angles.iter().map(|a| a.to_radians()).collect();
    let response = disk.arc_step_response(arc, &radians, &times)?;
    Ok(StrikerGreenReport::of(
        nu,
        &angles,
        response,
        crate::VERSION,
    ))
}
