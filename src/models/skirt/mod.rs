//! The lubricated piston skirt: film thickness from the piston's lateral position and tilt,
//! the Reynolds equation with the Reynolds (Swift–Stieber) or the mass-conserving (JFO) cavitation
//! condition solved as a linear complementarity problem, flooded or fed by the oil on the liner, Greenwood–Tripp asperity contact, and the loads, damping and friction they
//! put on the piston. Pure numerics: nothing here knows the crank train's state or the FMU.

mod asperity;
mod band;
mod design;
mod elastic;
#[cfg(test)]
mod elastic_tests;
mod fill;
#[cfg(test)]
mod fill_tests;
mod loads;
mod profile;
mod reynolds;
#[cfg(test)]
mod reynolds_tests;
mod shear;
mod shell;
#[cfg(test)]
mod shell_tests;
mod supply;
#[cfg(test)]
mod supply_tests;
mod surface;
#[cfg(test)]
mod surface_tests;

pub use asperity::Roughness;
pub use design::{CavitationCondition, Compliance, SkirtDesign};
pub use elastic::read_matrix;
pub use fill::Fill;
pub use loads::{FilmLinear, PressureMap, SideMap, SkirtLoads, SkirtMotion};
pub use profile::SkirtProfile;
pub use shear::Shear;
pub use supply::OilSupply;
pub use surface::{Skirt, BOUNDARY_SLIP};
