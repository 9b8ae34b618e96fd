//! The lubricated skirt's fields and the asperities' stored energy now, read from the crank train's state.

use super::crank_train::CrankTrain;
use super::linkage::LinkAngles;
use super::lubrication::Oil;
use crate::models::skirt::PressureMap;

impl CrankTrain {
    /// The lubricated skirt's film and asperity pressure and film thickness now; None dry.
    pub(super) fn skirt_pressure_map(&self) -> Option<PressureMap> {
        let lubrication = self.engine().lubrication.as_ref()?;
        let (phi, phid) = self.state_within_cycle();
        Some(lubrication.pressure_map((&phi, &LinkAngles::new(&phi)), &phid))
    }

    /// With a limited oil supply, the oil on the liner and in the film at the latest film solve
    /// (`Lubrication::oil`); None dry, flooded or before the first solve.
    pub fn oil(&self) -> Option<Oil> {
        self.engine().lubrication.as_ref()?.oil()
    }

    /// The asperities' elastic energy now, J (0 dry).
    pub(super) fn asperity_energy(&self) -> f64 {
        let Some(lubrication) = &self.engine().lubrication else { return 0.0 };
        let (phi, phid) = self.state_within_cycle();
        lubrication.loads_at((&phi, &LinkAngles::new(&phi)), &phid).asperity_energy
    }
}
