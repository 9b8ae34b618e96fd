//! The skirt: both sides' grids built once from the design, and the film solved per motion.

use super::{PressureMap, SkirtDesign, SkirtLoads, SkirtMotion};
use crate::models::ModelError;

/// A skirt ready to evaluate: the design checked and its grids and tables built.
///
/// [`Skirt::loads`] is a pure function of the design and the motion, deterministic to the bit.
#[derive(Clone, Debug)]
pub struct Skirt {
    design: SkirtDesign,
}

impl Skirt {
    /// Checks the design and builds the grids, or refuses it naming the field and reason.
    pub fn new(design: SkirtDesign) -> Result<Self, ModelError> {
        design.validate()?;
        Ok(Self { design })
    }

    /// The design this skirt was built from.
    pub fn design(&self) -> &SkirtDesign {
        &self.design
    }

    /// Film and asperity loads, their damping, friction and dissipation at `motion`.
    pub fn loads(&self, motion: &SkirtMotion) -> SkirtLoads {
        let _ = motion;
        unimplemented!("skirt film solver: API skeleton")
    }

    /// The pressure and film fields of both sides at `motion`, for plots.
    pub fn pressure_map(&self, motion: &SkirtMotion) -> PressureMap {
        let _ = motion;
        unimplemented!("skirt film solver: API skeleton")
    }
}
