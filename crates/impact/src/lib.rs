//! Transient impact of a striker on an elastic half-plane (plane strain), the second
//! reference paper's eqs (3)-(8): rigid (G0 = 0), elastic or a thin cylindrical shell (G0 from
//! [`striker`], `docs/strikers.md`). The contact integral equation (7) is marched in
//! time on a uniform space-time grid whose influence coefficients are the Lamb crate's
//! closed-form cell integrals, the striker's equation of motion (5)/(8), two edge laws
//! (`kinematic`, eq (4); `signorini`, the unilateral conditions), the history reported with
//! error estimates from grid refinement. Derivations and the method's limits: `docs/impact.md`.
//!
//! Dimensionless variables (R the profile's length scale): x/R, c1 t/R, h/R, V0/c1,
//! m0/(rho R^2), c2/c1; pressure over rho c1^2, force per unit length over rho c1^2 R.
#![warn(missing_docs)]
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod axisym;
pub mod case;
pub mod cost;
pub mod edge_fit;
pub mod error;
pub mod history;
pub(crate) mod linalg;
pub mod march;
pub mod profile;
pub mod run;
pub mod scalar;
pub mod solve;
pub mod solved;
pub mod striker;
pub mod tables;

pub use case::{Drive, ImpactCase, ReferenceCase, Stop, REFERENCE};
pub use error::{ImpactError, Result};
pub use march::EdgeLaw;
pub use profile::Profile;
pub use run::Run;
pub use solve::{Progress, Solvable};
pub use solved::{
    coarse_means, ErrorModel, Estimator, HistoryRow, Models, OrderShown, Orders, PressureProfile,
    Rebound, SolvedImpact, Stage, StrikerEnergyStep, Value, CYLINDER_MODES_BELOW, PEAK_DROP,
};
pub use striker::{ShellStriker, Striker, StrikerMaterial};
