//! The FMU's variable contract (`ARCHITECTURE.md` §4) as plain Rust values, in SI units.
//! Field names are the FMI variable names: the value-reference dispatch generated from
//! `modelDescription/` addresses these fields by name.

use crate::models::{check_integer, check_real, InputPolynomial, ModelError, StepInputs};
use serde::{Deserialize, Serialize};

// From modelDescription/piston_slap.xml: the three struct macros, `impl Default for Parameters` and `for
// Inputs`, `Parameters::check_ranges`, `Outputs::first_non_finite`, and `InputDerivatives` with `with_values`
// and `of_mut`.
include!(concat!(env!("OUT_DIR"), "/piston_slap_contract.rs"));

parameters_struct! {
    /// Model parameters; defaults are Awrejcewicz & Kudra section 8 unless ARCHITECTURE.md says otherwise.
    /// The fields, their documentation, `Default` and the range checks are generated from the variables,
    /// units, descriptions, start, min and max values of `modelDescription/piston_slap.xml`, so the FMU's
    /// XML and the Rust contract cannot disagree.
    #[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
    pub struct Parameters {}
}

inputs_struct! {
    /// Continuous inputs, held constant over a communication step unless their derivatives are set.
    #[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
    pub struct Inputs {}
}

impl InputDerivatives {
    /// Refuses an input whose value or derivatives are not finite, naming it.
    pub fn check_finite(&self, inputs: &Inputs) -> Result<(), ModelError> {
        let inputs = self.with_values(inputs);
        // One sum clears them all (an infinite or NaN term makes it so; finite terms that overflow it
        // are looked at one by one) before any is named: every step checks its inputs.
        if inputs.iter().map(|(_, value, [slope, curvature])| value + slope + curvature).sum::<f64>().is_finite() {
            return Ok(());
        }
        let finite =
            |(_, value, [slope, curvature]): &(&str, f64, [f64; 2])| value.is_finite() && slope.is_finite() && curvature.is_finite();
        match inputs.into_iter().find(|input| !finite(input)) {
            Some((name, value, [slope, curvature])) => {
                Err(ModelError(format!("input {name} = {value} (derivatives {slope}, {curvature}) is not finite")))
            }
            None => Ok(()),
        }
    }

    /// The inputs over a step starting at `t`: `inputs` there, with these derivatives.
    pub fn polynomials(&self, inputs: &Inputs, t: f64) -> StepInputs {
        let [crank_speed, gas_pressure, load_torque] =
            self.with_values(inputs).map(|(_, value, [slope, curvature])| InputPolynomial { time: t, value, slope, curvature });
        StepInputs { crank_speed, gas_pressure, load_torque }
    }
}

outputs_struct! {
    /// Outputs (ARCHITECTURE.md §4). Impact statistics are filled by the caller from the event record;
    /// the kinematic and force outputs by the model.
    #[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
    pub struct Outputs {
        /// J, the piston–liner friction work since the start (corners and skirt; no variable: the
        /// statistics take `cycle_skirt_fmep` from its cycles' differences).
        pub liner_friction_work: f64,
        /// N·s, the liner's impulse on the piston since the start per wall [anti-thrust, major thrust]:
        /// impacts and contact forces and, lubricated, the wall's film and asperity push (no variable:
        /// the `_in_step` outputs are its steps' differences).
        pub liner_impulse_total: [f64; 2],
    }
}

impl Parameters {
    /// Refuses what no model can run: a value outside its physical range (negative masses or lengths,
    /// `restitution` outside [0, 1], an unknown variant or mode), a bore not larger than the piston, a
    /// crank not shorter than the rod. The message names the parameter. Model-specific checks come with
    /// each mechanism's design.
    pub fn validate(&self) -> Result<(), ModelError> {
        self.check_ranges()?;
        if self.bore <= self.piston_diameter {
            return Err(ModelError(format!(
                "bore = {} m must exceed piston_diameter = {} m (the diametral clearance c = bore − piston_diameter must be > 0)",
                self.bore, self.piston_diameter
            )));
        }
        if self.crank_radius >= self.rod_length {
            return Err(ModelError(format!(
                "crank_radius = {} m must be shorter than rod_length = {} m",
                self.crank_radius, self.rod_length
            )));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refused(change: impl FnOnce(&mut Parameters), name: &str) {
        let mut p = Parameters::default();
        change(&mut p);
        let err = p.validate().expect_err(name);
        assert!(err.0.contains(name), "message {:?} should name {name}", err.0);
    }

    #[test]
    fn defaults_are_the_design_values_and_valid() {
        let p = Parameters::default();
        assert_eq!((p.model_variant, p.crank_mode, p.pressure_source, p.roller_forcing), (1, 1, 2, 2));
        assert_eq!((p.bore, p.piston_diameter, p.restitution, p.peak_pressure), (0.08008, 0.08, 0.5, 8e6));
        assert_eq!(p.impact_log, "");
        assert_eq!(Inputs::default().crank_speed, 125.66);
        p.validate().unwrap();
    }

    #[test]
    fn out_of_range_parameters_are_refused_by_name() {
        refused(|p| p.piston_mass = -0.4, "piston_mass");
        refused(|p| p.rod_mass = 0.0, "rod_mass");
        refused(|p| p.crank_radius = -0.04, "crank_radius");
        refused(|p| p.skirt_length = -1e-3, "skirt_length");
        refused(|p| p.restitution = 1.5, "restitution");
        refused(|p| p.restitution = -0.1, "restitution");
        refused(|p| p.model_variant = 3, "model_variant");
        refused(|p| p.crank_mode = 0, "crank_mode");
        refused(|p| p.damping_main = -1.0, "damping_main");
        refused(|p| p.gravity = f64::NAN, "gravity");
        refused(|p| p.bore = 0.079, "bore");
        refused(|p| p.crank_radius = 0.2, "crank_radius");
    }

    #[test]
    fn the_first_non_finite_output_is_named() {
        // Finite values whose sum overflows: named by none.
        let finite = Outputs {
            impact_velocity: f64::MAX,
            crank_angle: f64::MAX,
            kinetic_energy: -0.0,
            side_force: f64::MIN_POSITIVE,
            ..Outputs::default()
        };
        assert_eq!(finite.first_non_finite(), None);
        for x in [f64::INFINITY, f64::NEG_INFINITY] {
            let out = Outputs { crank_torque: x, kinetic_energy: f64::NAN, ..finite.clone() };
            assert_eq!(out.first_non_finite(), Some(("crank_torque", x)));
        }
        let nan = Outputs { kinetic_energy: f64::NAN, ..finite }.first_non_finite();
        assert!(matches!(nan, Some(("kinetic_energy", x)) if x.is_nan()), "{nan:?}");
    }

    #[test]
    fn finite_inputs_pass_however_large_and_the_first_other_is_named() {
        let inputs = Inputs { gas_pressure: f64::MAX, ..Inputs::default() };
        let mut derivatives = InputDerivatives { gas_pressure: [f64::MAX, f64::MAX], ..InputDerivatives::default() };
        assert_eq!(derivatives.check_finite(&inputs), Ok(()));
        derivatives.load_torque[1] = f64::NEG_INFINITY;
        let err = derivatives.check_finite(&inputs).unwrap_err();
        assert!(err.0.starts_with("input load_torque"), "{err}");
    }

    #[test]
    fn boundary_values_are_accepted() {
        let mut p = Parameters { restitution: 0.0, skirt_length: 0.0, ..Parameters::default() };
        p.validate().unwrap();
        p.restitution = 1.0;
        p.validate().unwrap();
    }
}
