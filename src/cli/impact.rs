//! The `impact` program's flags: the subcommands `run`, `green` and `edge` parsed by clap,
//! each turned into the inputs of its library call ([`crate::impact_api`]). The binary
//! prints the reports; other front ends (the Python package) parse the same flags.

use clap::{Args, Parser, Subcommand};

use super::MaterialArgs;
use crate::error::InputError;
use crate::impact_api::{EdgeInput, GreenInput, RunInput, StrikerGreenInput};

/// The transient impact of strikers on an elastic half-plane (plane strain, the impact
/// paper): rigid, elastic, full elastic cylinder and thin-shell strikers over a whole impact
/// to their rebound,
/// Lamb's surface influence functions, and the pressure at a moving contact edge.
#[derive(Parser, Debug)]
#[command(name = "impact", version, arg_required_else_help = true)]
pub struct ImpactCli {
    /// The subcommand.
    #[command(subcommand)]
    pub command: Command,
}

/// The impact program's subcommands (parsed once per call: the run's flags make its
/// variant the largest, which costs nothing worth a box).
#[derive(Subcommand, Debug)]
#[allow(clippy::large_enum_variant)]
pub enum Command {
    /// Lamb's surface influence functions g(s), step responses W(s), cell integrals and the
    /// Rayleigh constants of the half-plane.
    Green(GreenArgs),
    /// The transient impact of a striker on the half-plane, rigid, elastic (the local
    /// half-plane model), a full elastic cylinder or a thin cylindrical shell, free or
    /// driven: histories of the
    /// penetration, the contact half-width, the force, energies and pressure profiles, the
    /// rebound, each with an error estimate from grid refinement (`--geometry axisymmetric`:
    /// a body of revolution on the half-space). Without --poisson or --c1 and --c2 the
    /// material is Poisson's solid, nu = 1/4.
    Run(RunArgs),
    /// The power law p ~ d^lambda of the contact pressure at a contact edge moving at speed
    /// D, for each speed range and edge law (docs/edge.md).
    Edge(EdgeArgs),
    /// A striker's own influence function: the inward normal surface displacement of a free
    /// elastic cylinder (R = 1, mu_s = 1, rho_s = 1) under a unit pressure switched on at
    /// t = 0 over an arc, averaged over arcs of the same width, with its rigid translation
    /// and without (docs/strikers.md, section 7).
    StrikerGreen(StrikerGreenArgs),
}

/// Arguments of `impact striker-green`.
#[derive(Args, Debug)]
pub struct StrikerGreenArgs {
    /// The striker's material: its Poisson's ratio, or its --c1 and --c2 (m/s).
    #[command(flatten)]
    material: MaterialArgs,
    /// The striker: `cylinder` (a free elastic disk in plane strain).
    #[arg(long, default_value = "cylinder")]
    striker: String,
    /// The loaded arc's width 2 theta0 R over R, in [0.002, pi].
    #[arg(long = "arc-over-R")]
    arc_over_r: Option<f64>,
    /// Comma-separated centres of the receiver arcs, degrees from the loaded arc's centre.
    #[arg(long, allow_hyphen_values = true)]
    at_deg: Option<String>,
    /// The times, `c2t/R=T1,T2,...`, each in (0, 100] (c2 the striker's S-wave speed).
    #[arg(long)]
    times: Option<String>,
    /// JSON output (default: CSV with `#` header lines).
    #[arg(long)]
    json: bool,
}

impl StrikerGreenArgs {
    /// Whether JSON was asked for (`--json`) instead of CSV.
    pub fn json(&self) -> bool {
        self.json
    }
    /// The inputs of [`crate::impact_api::striker_green`] (a material flag that is not a
    /// finite number refused, naming it).
    pub fn input(&self) -> Result<StrikerGreenInput, InputError> {
        let (c1, c2, poisson) = self.material.numbers()?;
        Ok(StrikerGreenInput {
            c1,
            c2,
            poisson,
            striker: self.striker.clone(),
            arc_over_r: self.arc_over_r,
            at_deg: self.at_deg.clone(),
            times: self.times.clone(),
        })
    }
}

/// Arguments of `impact green`.
#[derive(Args, Debug)]
pub struct GreenArgs {
    #[command(flatten)]
    material: MaterialArgs,
    /// Comma-separated points s = |x|/(c1 t) > 0 (not s_R) for pointwise values.
    #[arg(long, allow_hyphen_values = true)]
    at: Option<String>,
    /// Comma-separated cells sa:sb with 0 <= sa <= sb (for sa = 0, It diverges and is reported
    /// unavailable with the reason).
    #[arg(long, allow_hyphen_values = true)]
    cells: Option<String>,
    /// Print the Rayleigh constants s_R, r_zz, r_xx, K_R.
    #[arg(long)]
    constants: bool,
    /// Significant decimal digits (arbitrary precision); omit for f64.
    #[arg(long)]
    digits: Option<u32>,
    /// JSON output (default: CSV with a `#` header).
    #[arg(long)]
    json: bool,
}

/// Arguments of `impact run`.
#[derive(Args, Debug)]
pub struct RunArgs {
    #[command(flatten)]
    material: MaterialArgs,
    /// The striker: `rigid`; `elastic:c1=..,c2=..,density_ratio=..` (its wave speeds in m/s,
    /// its density over the half-plane's; local half-plane model, valid until c1 t/R =
    /// 2 c1/c1s); `cylinder:c1=..,c2=..,density_ratio=..` (the full elastic cylinder of
    /// radius R, valid for all times, its mass pi rho_s R^2; profile circle:R=1 or
    /// parabola:R=1); `shell:thickness_over_R=..,c1=..,c2=..,density_ratio=..` (a thin
    /// cylindrical shell of radius R, its mass from its geometry). Deformable strikers need
    /// the half-plane's --c1 and --c2.
    #[arg(long, default_value = "rigid")]
    striker: String,
    /// The profile: circle:R=.., parabola:R=.., power:A=..,k=.., wedge:theta_deg=..,
    /// flat:a=.., table:FILE (two columns x f in metres, from x = 0).
    #[arg(long)]
    profile: Option<String>,
    /// m0/(rho R^2), the striker's mass per unit length (free striker; a shell's and a
    /// cylinder's follow from their geometry).
    #[arg(long, allow_hyphen_values = true)]
    mass_ratio: Option<f64>,
    /// V0/c1, the initial speed (free striker).
    #[arg(long, allow_hyphen_values = true)]
    v0_over_c1: Option<f64>,
    /// Prescribed penetration instead of the equation of motion: speed:V_over_c1=.. or
    /// table:FILE (two columns c1 t/R, h/R from (0, 0)).
    #[arg(long)]
    driven: Option<String>,
    /// The edge law: signorini (unilateral conditions) or kinematic (eq (4), f(b) = h).
    #[arg(long, default_value = "signorini")]
    law: String,
    /// End time: c1t/R=VALUE (the last reported time exactly), or `separation` (shortly
    /// after the free striker leaves the surface; at most c1 t/R = 400) or
    /// `separation:max=VALUE` (at most c1 t/R = VALUE).
    #[arg(long)]
    end: Option<String>,
    /// The length scale R in metres for the flat punch, the wedge and the power law (the
    /// radius for the circle and the parabola).
    #[arg(long, allow_hyphen_values = true)]
    length: Option<f64>,
    /// Cell width dx/R of the finest grid of a plane run (default 0.005).
    #[arg(long, allow_hyphen_values = true)]
    dx: Option<f64>,
    /// The geometry: `plane` (plane strain: cylinders, wedges, shells; the default) or
    /// `axisymmetric` (a sphere, paraboloid, cone or flat punch on the elastic half-space;
    /// --mass-ratio is then m/(rho R^3)).
    #[arg(long, default_value = "plane")]
    geometry: String,
    /// Ring width dr/R of the finest grid of an axisymmetric run (default: about 30 rings
    /// across the largest contact radius expected).
    #[arg(long, allow_hyphen_values = true)]
    dr: Option<f64>,
    /// kappa = c1 dt/dx, in [0.5, 64].
    #[arg(long, default_value_t = 2.0, allow_hyphen_values = true)]
    kappa: f64,
    /// Refinement levels for the error estimates (1 to 4).
    #[arg(long, default_value_t = 3)]
    levels: usize,
    /// The edge cell: `model` (the local behaviour of the pressure at a moving edge, the
    /// edge inside its cell) or `whole` (whole cells, the edge captured cell by cell), for
    /// comparing the two.
    #[arg(long)]
    edge_cell: Option<String>,
    /// How many times the grid is halved for the first steps (0 to 12, default 6): each
    /// level's first steps on cells 2, 4, ..., 2^K times finer, handed over as the contact
    /// widens (a rigid striker of a curved profile under Signorini's law); 0: one grid
    /// throughout.
    #[arg(long)]
    start_halvings: Option<usize>,
    /// Pressure profiles at these times: c1t/R=T1,T2,...
    #[arg(long)]
    pressure_at: Option<String>,
    /// JSON output (default: CSV with `#` headers).
    #[arg(long)]
    json: bool,
    /// Significant digits of the reported values (1 to 30): the march in double-double,
    /// the discrete solution of the same grids to that many digits (regression data for the
    /// scheme; the error estimates stay those of the discretisation). Rigid strikers; the
    /// inputs are taken as their nearest doubles. Omit for f64.
    #[arg(long)]
    digits: Option<u32>,
    /// Run even when the estimated memory exceeds the limit (4 GiB by default, or
    /// --memory-limit-gib).
    #[arg(long)]
    force: bool,
    /// The memory limit in GiB above which a run is refused without --force.
    #[arg(long, default_value_t = impact::cost::DEFAULT_MEMORY_LIMIT_GIB)]
    memory_limit_gib: f64,
}

/// Arguments of `impact edge`.
#[derive(Args, Debug)]
pub struct EdgeArgs {
    #[command(flatten)]
    material: MaterialArgs,
    /// Comma-separated edge speeds D/c1 > 0 (not c_R/c1, c2/c1 or 1).
    #[arg(long, allow_hyphen_values = true)]
    speed_over_c1: Option<String>,
    /// The edge law: `signorini` (a free edge) or `kinematic` (a prescribed edge, f(b) = h).
    #[arg(long, default_value = "signorini")]
    law: String,
    /// JSON output (default: CSV with `#` header lines).
    #[arg(long)]
    json: bool,
}

impl GreenArgs {
    /// Whether JSON was asked for (`--json`) instead of CSV.
    pub fn json(&self) -> bool {
        self.json
    }
    /// The inputs of [`crate::impact_api::green`].
    pub fn input(&self) -> GreenInput {
        GreenInput {
            c1: self.material.c1.clone(),
            c2: self.material.c2.clone(),
            poisson: self.material.poisson.clone(),
            at: self.at.clone(),
            cells: self.cells.clone(),
            constants: self.constants,
            digits: self.digits,
        }
    }
}

impl RunArgs {
    /// Whether JSON was asked for (`--json`) instead of CSV.
    pub fn json(&self) -> bool {
        self.json
    }
    /// The inputs of [`crate::impact_api::run`] (a material flag that is not a finite
    /// number refused, naming it).
    pub fn input(&self) -> Result<RunInput, InputError> {
        let (c1, c2, poisson) = self.material.numbers()?;
        if self.geometry == "axisymmetric" {
            if self.dx.is_some() {
                return Err(InputError::new(
                    "dx",
                    "invalid --dx with --geometry axisymmetric: the rings' width is --dr",
                ));
            }
            if self.edge_cell.is_some() {
                return Err(InputError::new(
                    "edge_cell",
                    "invalid --edge-cell with --geometry axisymmetric: the rings are whole (the edge model is the plane march's)",
                ));
            }
            if self.start_halvings.is_some() {
                return Err(InputError::new(
                    "start_halvings",
                    "invalid --start-halvings with --geometry axisymmetric: the start on finer grids is the plane march's",
                ));
            }
        } else if self.dr.is_some() {
            return Err(InputError::new(
                "dr",
                "invalid --dr with --geometry plane: the cells' width is --dx",
            ));
        }
        Ok(RunInput {
            c1,
            c2,
            poisson,
            striker: self.striker.clone(),
            profile: self.profile.clone().unwrap_or_default(),
            mass_ratio: self.mass_ratio,
            v0_over_c1: self.v0_over_c1,
            driven: self.driven.clone(),
            law: self.law.clone(),
            end: self.end.clone().unwrap_or_default(),
            length: self.length,
            dx: self.dx.unwrap_or(0.005),
            kappa: self.kappa,
            levels: self.levels,
            edge_cell: self.edge_cell.clone().unwrap_or_else(|| "model".into()),
            start_halvings: self.start_halvings,
            pressure_at: self.pressure_at.clone(),
            digits: self.digits,
            force: self.force,
            memory_limit_gib: self.memory_limit_gib,
            geometry: self.geometry.clone(),
            dr: self.dr,
        })
    }
}

impl EdgeArgs {
    /// Whether JSON was asked for (`--json`) instead of CSV.
    pub fn json(&self) -> bool {
        self.json
    }
    /// The inputs of [`crate::impact_api::edge`] (a material flag that is not a finite
    /// number refused, naming it).
    pub fn input(&self) -> Result<EdgeInput, InputError> {
        let (c1, c2, poisson) = self.material.numbers()?;
        Ok(EdgeInput {
            c1,
            c2,
            poisson,
            speed_over_c1: self.speed_over_c1.clone(),
            law: self.law.clone(),
        })
    }
}
