//! The skirt's design data and their checks.

use super::{OilSupply, Roughness, SkirtProfile};
use crate::models::ModelError;
use std::sync::Arc;

/// Design data of the skirt and its oil, SI.
///
/// Geometry follows the crank train's corners (`crank_train/linkage.rs`): the piston axis lies `pin_offset`
/// on the −x side of the pin O3; along the axis, the skirt spans from `pin_from_top` above the pin (its
/// top edge, the corners K1, K3) to `pin_from_top − length` (its bottom edge, K2, K4). A point of the
/// skirt at axial distance z above the pin and angle θ from +x has the film thickness
/// `h = R − r(z)·cos φ3 − e(z)·cos θ + ovality·sin²θ`, with `e(z) = x − z·sin φ3 − a·cos φ3` the axis's
/// lateral position there and `r(z) = d/2 − drop(z)`: at θ = 0 and π with no drop it is exactly the
/// linkage's corner gap (K3/K4 on +x, K1/K2 on −x), so a collapsed film meets the dry contact.
/// `d` and `D` are the running (hot) diameters; the profile and ovality are the hot shape's drops below d/2.
#[derive(Clone, Debug, PartialEq)]
pub struct SkirtDesign {
    /// Bore radius D/2, m.
    pub radius_bore: f64,
    /// Piston radius d/2 at zero drop, m.
    pub radius_piston: f64,
    /// Skirt length along the axis, m (`skirt_length`).
    pub length: f64,
    /// Axial distance from the skirt's top edge down to the pin axis, m (`pin_height`).
    pub pin_from_top: f64,
    /// Lateral offset of the piston axis from the pin toward −x, m (`pin_offset`, the linkage's a).
    pub pin_offset: f64,
    /// Angular extent of EACH side, rad (`skirt_arc`): thrust side centred on +x, anti-thrust on −x.
    pub arc: f64,
    /// Radial drop against axial position (`skirt_profile`).
    pub profile: SkirtProfile,
    /// Radial reduction of the piston at the pin axis (θ = ±90°) against the thrust axis, m; 0 = round.
    pub ovality: f64,
    /// Dynamic viscosity of the oil, Pa·s (`oil_viscosity`).
    pub viscosity: f64,
    /// Greenwood–Tripp asperity data of the piston–liner pair.
    pub roughness: Roughness,
    /// Coefficient of boundary friction on the asperity load, –.
    pub boundary_friction: f64,
    /// Interior grid nodes per side: (circumferential, axial).
    pub grid: (usize, usize),
    /// How the film cavitates (`cavitation`).
    pub cavitation: CavitationCondition,
    /// How oil reaches the skirt's edges (`oil_supply`, `liner_oil_film`).
    pub supply: OilSupply,
    /// How the skirt deforms under its film (`skirt_compliance`).
    pub compliance: Compliance,
}

/// How the skirt deforms under the film's and the asperities' pressure.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum Compliance {
    /// A rigid skirt (`skirt_compliance = 0`).
    #[default]
    Rigid,
    /// The built-in shell (`skirt_compliance = 1`, `skirt/shell.rs`).
    Shell {
        /// Wall thickness, m.
        thickness: f64,
        /// Young's modulus, Pa.
        modulus: f64,
    },
    /// One side's compliance on the film's nodes, m/N, both sides alike (`skirt_compliance = 2`):
    /// row-major (deflected node, loaded node), nodes in node order (axial row by circumferential
    /// column), the deflection away from the liner per newton pressing.
    Matrix(Arc<[f64]>),
}

/// The film's cavitation condition.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum CavitationCondition {
    /// Reynolds (Swift–Stieber): p ≥ 0, the film ruptures where its pressure gradient vanishes and
    /// re-forms wherever pressure would rise; no history (`cavitation = 1`).
    #[default]
    Reynolds,
    /// Mass-conserving (JFO): the cavitated film's fill fraction is carried with the sliding between
    /// solves as state, and the film re-forms where the oil it carries meets the full film (`cavitation = 2`).
    MassConserving,
}

impl TryFrom<i32> for CavitationCondition {
    type Error = ModelError;

    fn try_from(value: i32) -> Result<Self, ModelError> {
        match value {
            1 => Ok(Self::Reynolds),
            2 => Ok(Self::MassConserving),
            _ => Err(ModelError(format!("cavitation = {value} must be 1 (Reynolds) or 2 (mass-conserving)"))),
        }
    }
}

impl SkirtDesign {
    /// The default grid per side (circumferential, axial): within 0.4 % of (24, 36) in the crank train's
    /// film, FMEP and forces (`make film-convergence`); see also the grid-convergence tests.
    pub const DEFAULT_GRID: (usize, usize) = (12, 18);

    /// The most film nodes per side an elastic skirt takes: its compliance is a dense matrix of the
    /// nodes by the closed grid (under 10 MB and a fraction of a second to build at this size).
    pub const ELASTIC_NODES: usize = 1024;

    /// Boundary friction coefficient by default, –.
    pub const DEFAULT_BOUNDARY_FRICTION: f64 = 0.1;

    /// A straight skirt of the crank train's geometry with the default oil, roughness and grid.
    pub fn new(radius_bore: f64, radius_piston: f64, length: f64, pin_from_top: f64, pin_offset: f64, arc: f64, viscosity: f64) -> Self {
        Self {
            radius_bore,
            radius_piston,
            length,
            pin_from_top,
            pin_offset,
            arc,
            profile: SkirtProfile::default(),
            ovality: 0.0,
            viscosity,
            roughness: Roughness::default(),
            boundary_friction: Self::DEFAULT_BOUNDARY_FRICTION,
            grid: Self::DEFAULT_GRID,
            cavitation: CavitationCondition::Reynolds,
            supply: OilSupply::Flooded,
            compliance: Compliance::Rigid,
        }
    }

    /// Refuses a design the film cannot be solved on, naming the field and the reason.
    pub fn validate(&self) -> Result<(), ModelError> {
        let refuse = |what: &str| Err(ModelError(format!("skirt: {what}")));
        let positive = [
            ("radius_bore", self.radius_bore),
            ("radius_piston", self.radius_piston),
            ("length", self.length),
            ("viscosity", self.viscosity),
        ];
        for (name, v) in positive {
            if !(v.is_finite() && v > 0.0) {
                return refuse(&format!("{name} = {v} must be finite and > 0"));
            }
        }
        for (name, v) in [("pin_from_top", self.pin_from_top), ("pin_offset", self.pin_offset)] {
            if !v.is_finite() {
                return refuse(&format!("{name} = {v} must be finite"));
            }
        }
        if self.radius_piston >= self.radius_bore {
            return refuse(&format!("radius_piston {} m must be below radius_bore {} m", self.radius_piston, self.radius_bore));
        }
        if !(self.arc > 0.0 && self.arc <= std::f64::consts::PI) {
            return refuse(&format!("arc = {} rad must lie in (0, π]: each side is at most a half circle", self.arc));
        }
        if !(self.ovality.is_finite() && self.ovality >= 0.0) {
            return refuse(&format!("ovality = {} m must be finite and ≥ 0", self.ovality));
        }
        if !(self.boundary_friction.is_finite() && self.boundary_friction >= 0.0) {
            return refuse(&format!("boundary_friction = {} must be finite and ≥ 0", self.boundary_friction));
        }
        let (nc, na) = self.grid;
        if !(2..=256).contains(&nc) || !(2..=256).contains(&na) {
            return refuse(&format!("grid ({nc}, {na}) must have 2 to 256 nodes each way"));
        }
        self.validate_compliance()?;
        self.profile.validate()?;
        self.supply.validate(self.cavitation == CavitationCondition::MassConserving)?;
        self.roughness.validate()
    }

    /// Refuses an elastic skirt on a grid too fine for its dense compliance, a shell no thinner than the
    /// skirt's radius, or a compliance matrix of the wrong shape.
    fn validate_compliance(&self) -> Result<(), ModelError> {
        let nodes = self.grid.0 * self.grid.1;
        if self.compliance != Compliance::Rigid && nodes > Self::ELASTIC_NODES {
            return Err(ModelError(format!(
                "skirt_compliance needs a film grid of at most {} nodes per side, ({}, {}) has {nodes}: its dense compliance grows as their square",
                Self::ELASTIC_NODES,
                self.grid.0,
                self.grid.1
            )));
        }
        match &self.compliance {
            Compliance::Rigid => Ok(()),
            Compliance::Shell { thickness, modulus } => {
                if !(thickness.is_finite() && *thickness > 0.0 && *thickness < self.radius_piston) {
                    return Err(ModelError(format!(
                        "skirt_wall_thickness = {thickness} m must be finite, > 0 and below the piston's radius {} m",
                        self.radius_piston
                    )));
                }
                if !(modulus.is_finite() && *modulus > 0.0) {
                    return Err(ModelError(format!("skirt_modulus = {modulus} Pa must be finite and > 0")));
                }
                Ok(())
            }
            Compliance::Matrix(matrix) => {
                if matrix.len() != nodes * nodes {
                    return Err(ModelError(format!(
                        "skirt compliance matrix has {} entries, the film grid ({}, {}) needs {nodes} × {nodes}",
                        matrix.len(),
                        self.grid.0,
                        self.grid.1
                    )));
                }
                match matrix.iter().position(|v| !v.is_finite()) {
                    Some(k) => Err(ModelError(format!("skirt compliance matrix entry ({}, {}) is not finite", k / nodes, k % nodes))),
                    None => Ok(()),
                }
            }
        }
    }
}
