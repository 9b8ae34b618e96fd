//! Greenwood–Tripp asperity contact of two rough surfaces separated by a nominal gap h.

use crate::models::ModelError;

/// Roughness of the piston–liner pair for the Greenwood–Tripp asperity pressure
/// `p_a(h) = K·F_5/2(h/σ)`, `K = (8√2/15)·π·(η β σ)²·√(σ/β)·E'`.
#[derive(Clone, Debug, PartialEq)]
pub struct Roughness {
    /// Composite RMS roughness σ of the two surfaces' summit heights, m.
    pub sigma: f64,
    /// Asperity (summit) density η, 1/m².
    pub density: f64,
    /// Asperity summit radius β, m.
    pub radius: f64,
    /// Composite elastic modulus E' of the pair as it enters K, Pa.
    pub modulus: f64,
}

impl Default for Roughness {
    fn default() -> Self {
        Self { sigma: 0.5e-6, density: 4.0e10, radius: 2.0e-3, modulus: 1.0e11 }
    }
}

impl Roughness {
    /// Refuses non-physical roughness data, naming the field.
    pub fn validate(&self) -> Result<(), ModelError> {
        for (name, v) in [("sigma", self.sigma), ("density", self.density), ("radius", self.radius), ("modulus", self.modulus)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(ModelError(format!("skirt roughness: {name} = {v} must be finite and > 0")));
            }
        }
        Ok(())
    }
}
