//! PistonSlap's parameters as the crank train's typed designs (`design_space.rs` checks them first). Each
//! mechanism takes a design of its own: the crank train its `CrankTrainDesign`, the linkage its `Bodies`, the
//! engine its `EngineDesign` (with the gas source and the skirt's `lubrication::Design`).

use super::design_space;
use super::running_geometry::RunningGeometry;
use super::{Inputs, Parameters};
use crate::models::crank_train::engine::{Engine, EngineDesign};
use crate::models::crank_train::kinematics::SliderCrank;
use crate::models::crank_train::linkage::{Bodies, Linkage};
use crate::models::crank_train::lubrication;
use crate::models::crank_train::{CrankTrainDesign, StartOffset};
use crate::models::gas::{FourStrokePressure, GasPressure, PressureTrace};
use crate::models::{InputPolynomial, ModelError};

/// The crank train of `p`, refused with a message naming the parameter: the table's ranges
/// (`Parameters::validate`), then the declared space (`design_space`) at running temperature, where the
/// model runs with the bore and piston diameter grown (`RunningGeometry`), the dry corners and the
/// lubricated skirt alike.
pub fn design(p: &Parameters) -> Result<CrankTrainDesign, ModelError> {
    p.validate()?;
    let p = &RunningGeometry::apply(p)?;
    design_space::validate(p)?;
    let engine = engine(p)?;
    design_space::consistent_friction(&engine.linkage, p)?;
    let start = StartOffset {
        lateral: p.piston_lateral_start,
        lateral_velocity: p.piston_lateral_velocity_start,
        tilt: p.piston_tilt_start,
        tilt_rate: p.piston_tilt_rate_start,
    };
    let inputs = Inputs::default();
    Ok(CrankTrainDesign {
        engine,
        geometry: SliderCrank { crank_radius: p.crank_radius, rod_length: p.rod_length, pin_offset: p.pin_offset },
        start,
        crank_angle: p.crank_angle_start,
        free_crank: p.crank_mode != 1,
        inputs: (inputs.crank_speed, inputs.load_torque),
        running_clearance: p.bore - p.piston_diameter,
    })
}

/// The linkage of parameters taken as given (`CrankTrain::new` validates them first).
pub fn linkage(p: &Parameters) -> Linkage {
    bodies(p).into()
}

/// The engine of validated parameters: the linkage, the gas source `pressure_source` names (reading the
/// trace, refusing a bad file), restitution, friction and, with `skirt_model = 2`, the skirt.
pub fn engine(p: &Parameters) -> Result<Engine, ModelError> {
    Engine::new(EngineDesign {
        linkage: bodies(p),
        pressure: gas(p)?,
        piston_diameter: p.piston_diameter,
        restitution: p.restitution,
        friction: p.friction,
        skirt: skirt(p)?,
    })
}

fn bodies(p: &Parameters) -> Bodies {
    let a = p.pin_offset;
    let (h, s, half) = (p.pin_height, p.skirt_length, 0.5 * p.piston_diameter);
    Bodies {
        links: [p.crank_radius, p.rod_length],
        along: [p.crank_com, p.rod_com, p.piston_com],
        across: [0.0, 0.0, -a],
        masses: [p.crank_mass, p.rod_mass, p.piston_mass],
        inertias: [p.crank_inertia, p.rod_inertia, p.piston_inertia],
        damping: [p.damping_main, p.damping_crank_pin, p.damping_piston_pin],
        gravity: p.gravity,
        gravity_lateral: p.gravity_lateral,
        pin_offset: a,
        bore: p.bore,
        corners: [(h, -(half + a), 1.0), (h - s, -(half + a), 1.0), (h, half - a, -1.0), (h - s, half - a, -1.0)],
    }
}

/// The source `pressure_source` names; a held input starts at the input's default.
fn gas(p: &Parameters) -> Result<GasPressure, ModelError> {
    Ok(match p.pressure_source {
        1 => GasPressure::Held(InputPolynomial::held(Inputs::default().gas_pressure)),
        3 => GasPressure::Trace(PressureTrace::read(&p.pressure_trace, p.crankcase_pressure)?),
        _ => GasPressure::BuiltIn(FourStrokePressure::new(p.peak_pressure, p.rod_length / p.crank_radius)),
    })
}

/// The skirt with `skirt_model = 2`, or none; an arc or grid no film can have is refused by name.
fn skirt(p: &Parameters) -> Result<Option<lubrication::Design>, ModelError> {
    if p.skirt_model != 2 {
        return Ok(None);
    }
    if p.skirt_arc > std::f64::consts::PI {
        return Err(ModelError(format!("skirt_arc = {} rad must be at most π: each side is at most a half circle", p.skirt_arc)));
    }
    let grid = |name: &str, n: i32| usize::try_from(n).map_err(|_| ModelError(format!("{name} = {n} must be positive")));
    Ok(Some(lubrication::Design {
        links: [p.crank_radius, p.rod_length],
        relaxation: p.film_relaxation,
        geometry: [0.5 * p.bore, 0.5 * p.piston_diameter, p.skirt_length, p.pin_height, p.pin_offset],
        viscosity: p.oil_viscosity,
        arc: p.skirt_arc,
        profile: p.skirt_profile.clone(),
        ovality: p.skirt_ovality,
        roughness: [p.skirt_roughness, p.asperity_density, p.asperity_radius, p.composite_modulus],
        boundary_friction: p.boundary_friction,
        cavitation: p.cavitation,
        oil_supply: p.oil_supply,
        liner_oil_film: p.liner_oil_film,
        compliance: p.skirt_compliance,
        wall: [p.skirt_wall_thickness, p.skirt_modulus],
        compliance_file: p.skirt_compliance_file.clone(),
        grid: (grid("skirt_grid_circumferential", p.skirt_grid_circumferential)?, grid("skirt_grid_axial", p.skirt_grid_axial)?),
    }))
}
