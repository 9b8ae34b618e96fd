//! The geometry an engine runs with: `bore` and `piston_diameter` are given at `reference_temperature`,
//! and each grows by linear thermal expansion to its running temperature,
//!
//! `D_hot = D (1 + α_liner (T_liner − T_ref))`, `d_hot = d (1 + α_piston (T_piston − T_ref))`.
//!
//! Both models (the crank train with either skirt, the roller) run with the hot diameters; the skirt's
//! profile and ovality are drops below the hot d/2, taken as specified at running temperature (a piston's
//! hot shape is what its designer specifies). With the temperatures at the reference (the default) both
//! factors are exactly 1 and the geometry is the parameters' own, bit for bit.

use super::Parameters;
use crate::models::ModelError;

/// The hot bore and piston diameter, m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RunningGeometry {
    /// The liner's bore at `liner_temperature`, m.
    pub bore: f64,
    /// The piston's diameter at `piston_temperature`, m.
    pub piston_diameter: f64,
}

impl RunningGeometry {
    /// The diameters of `p` grown to their running temperatures.
    pub fn of(p: &Parameters) -> Self {
        let grown = |size: f64, expansion: f64, temperature: f64| size * (1.0 + expansion * (temperature - p.reference_temperature));
        Self {
            bore: grown(p.bore, p.liner_expansion, p.liner_temperature),
            piston_diameter: grown(p.piston_diameter, p.piston_expansion, p.piston_temperature),
        }
    }

    /// The diametral running clearance, hot bore minus hot piston diameter, m.
    pub fn clearance(&self) -> f64 {
        self.bore - self.piston_diameter
    }

    /// `p` with its bore and piston diameter at running temperature, the form the models take; a
    /// design whose piston does not fit its bore when hot is refused, naming the temperatures.
    pub fn apply(p: &Parameters) -> Result<Parameters, ModelError> {
        let hot = Self::of(p);
        if hot.clearance() > 0.0 {
            return Ok(Parameters { bore: hot.bore, piston_diameter: hot.piston_diameter, ..p.clone() });
        }
        Err(ModelError(format!(
            "running clearance {:e} m ≤ 0: at piston_temperature = {} K and liner_temperature = {} K (reference_temperature = {} K) \
             the piston ({} m) does not fit the bore ({} m); lower the piston's temperature or piston_expansion, or give a larger bore",
            hot.clearance(),
            p.piston_temperature,
            p.liner_temperature,
            p.reference_temperature,
            hot.piston_diameter,
            hot.bore
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reference_temperatures_give_the_parameters_geometry_bit_for_bit() {
        let p = Parameters::default();
        assert_eq!((p.piston_temperature, p.liner_temperature), (p.reference_temperature, p.reference_temperature));
        assert_eq!(RunningGeometry::apply(&p).expect("default"), p);
        let diesel = Parameters { bore: 0.1101, piston_diameter: 0.11, piston_expansion: 19e-6, ..p };
        assert_eq!(RunningGeometry::apply(&diesel).expect("diesel"), diesel);
    }

    #[test]
    fn the_running_clearance_is_the_hand_calculation() {
        // An 80 mm aluminium piston in a grey-iron bore with 80 µm cold clearance, skirt at 140 °C, liner at
        // 110 °C, from 20 °C: the piston grows 0.08 × 21e-6 × 120 = 201.6 µm, the bore
        // 0.08008 × 11e-6 × 90 = 79.2792 µm, so the clearance is 80 + 79.2792 − 201.6 = −42.3208 µm: it seizes.
        // With the skirt at 100 °C: 0.08 × 21e-6 × 80 = 134.4 µm, clearance 80 + 79.2792 − 134.4 = 24.8792 µm.
        let at = |piston: f64| Parameters { piston_temperature: piston + 273.15, liner_temperature: 383.15, ..Parameters::default() };
        let hot = RunningGeometry::of(&at(100.0));
        assert!((hot.piston_diameter - (0.08 + 134.4e-6)).abs() < 1e-15, "{}", hot.piston_diameter);
        assert!((hot.bore - (0.08008 + 79.2792e-6)).abs() < 1e-15, "{}", hot.bore);
        assert!((hot.clearance() - 24.8792e-6).abs() < 1e-15, "{}", hot.clearance());
        let applied = RunningGeometry::apply(&at(100.0)).expect("fits");
        assert_eq!((applied.bore, applied.piston_diameter), (hot.bore, hot.piston_diameter));
        assert!((RunningGeometry::of(&at(140.0)).clearance() + 42.3208e-6).abs() < 1e-15);
        let refused = RunningGeometry::apply(&at(140.0)).expect_err("seizes");
        assert!(refused.0.starts_with("running clearance") && refused.0.contains("piston_temperature = 413.15 K"), "{}", refused.0);
    }
}
