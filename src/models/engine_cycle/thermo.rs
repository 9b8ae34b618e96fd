//! Ideal-gas properties of the cylinder charge (`gas_properties = 2`): NASA 7-coefficient polynomials of
//! N2, O2, Ar, CO2 and H2O, mixed by mass.
//!
//! Per species, `c_p/R = a1 + a2 T + a3 T² + a4 T³ + a5 T⁴` with one coefficient set below and one above
//! 1000 K. The coefficients are those of GRI-Mech 3.0's `thermo30.dat` (G. P. Smith et al., GRI-Mech 3.0,
//! <http://combustion.berkeley.edu/gri-mech/version30/files30/thermo30.dat>), ranges 200 (N2: 300) to 3500
//! (N2: 5000) K. Only a1..a5 enter: the sensible internal energy is `u_s(T) = ∫_{T₀}^{T} c_v dT` with
//! `T₀ = 298.15 K` (continuous across 1000 K by construction), and the chemical energy enters as the Wiebe heat
//! release, so the formation enthalpies (a6) and entropies (a7) are not needed.
//!
//! The unburned charge is dry air of Lemmon et al. (J. Phys. Chem. Ref. Data 29, 331, 2000): mole fractions
//! N2 0.7812, O2 0.2096, Ar 0.0092. The burned gas is the complete-combustion product of a fuel CH_y with that
//! air at equivalence ratio φ ≤ 1: per mole of O2, φ/(1 + y/4) CO2, φ y/(2 (1 + y/4)) H2O, 1 − φ O2 and the
//! air's N2 and Ar. A charge whose burned mass fraction is x has mass fractions (1 − x) Y_air + x Y_burned; every
//! property is linear in them.

use serde::{Deserialize, Serialize};

/// J/(mol·K), the molar gas constant (CODATA 2018, exact).
const R_MOLAR: f64 = 8.314_462_618;
/// K, reference temperature of the sensible energy.
const T_REFERENCE: f64 = 298.15;
/// K, where each species' two coefficient sets meet.
const T_MID: f64 = 1000.0;
/// kg/mol, standard atomic weights of carbon and hydrogen (IUPAC conventional values).
const CARBON: f64 = 12.011e-3;
const HYDROGEN: f64 = 1.008e-3;

/// One species: molar mass (kg/mol) and a1..a5 below and above 1000 K.
struct Species {
    molar_mass: f64,
    low: [f64; 5],
    high: [f64; 5],
}

const N2: Species = Species {
    molar_mass: 28.0134e-3,
    low: [0.03298677E+02, 0.14082404E-02, -0.03963222E-04, 0.05641515E-07, -0.02444854E-10],
    high: [0.02926640E+02, 0.14879768E-02, -0.05684760E-05, 0.10097038E-09, -0.06753351E-13],
};
const O2: Species = Species {
    molar_mass: 31.9988e-3,
    low: [3.78245636E+00, -2.99673416E-03, 9.84730201E-06, -9.68129509E-09, 3.24372837E-12],
    high: [3.28253784E+00, 1.48308754E-03, -7.57966669E-07, 2.09470555E-10, -2.16717794E-14],
};
const AR: Species =
    Species { molar_mass: 39.948e-3, low: [0.02500000E+02, 0.0, 0.0, 0.0, 0.0], high: [0.02500000E+02, 0.0, 0.0, 0.0, 0.0] };
const CO2: Species = Species {
    molar_mass: 44.0095e-3,
    low: [2.35677352E+00, 8.98459677E-03, -7.12356269E-06, 2.45919022E-09, -1.43699548E-13],
    high: [3.85746029E+00, 4.41437026E-03, -2.21481404E-06, 5.23490188E-10, -4.72084164E-14],
};
const H2O: Species = Species {
    molar_mass: 18.01528e-3,
    low: [4.19864056E+00, -2.03643410E-03, 6.52040211E-06, -5.48797062E-09, 1.77197817E-12],
    high: [3.03399249E+00, 2.17691804E-03, -1.64072518E-07, -9.70419870E-11, 1.68200992E-14],
};

/// Dry air (Lemmon et al. 2000), moles per mole of O2: N2, Ar.
const AIR_N2_PER_O2: f64 = 0.7812 / 0.2096;
const AIR_AR_PER_O2: f64 = 0.0092 / 0.2096;

/// A gas of fixed composition per unit mass: c_p(T) = Σ c_k T^k in J/(kg·K) below and above 1000 K, and R.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Mixture {
    low: [f64; 5],
    high: [f64; 5],
    /// J/(kg·K), specific gas constant.
    pub r: f64,
}

impl Mixture {
    /// From (species, moles) pairs.
    fn of(parts: &[(&Species, f64)]) -> Self {
        let mass: f64 = parts.iter().map(|(s, n)| s.molar_mass * n).sum();
        let (mut low, mut high) = ([0.0; 5], [0.0; 5]);
        for (s, n) in parts {
            // Mass fraction times R/M of the species: c_p per kg of mixture.
            let w = n * R_MOLAR / mass;
            for k in 0..5 {
                low[k] += w * s.low[k];
                high[k] += w * s.high[k];
            }
        }
        let moles: f64 = parts.iter().map(|(_, n)| n).sum();
        Self { low, high, r: moles * R_MOLAR / mass }
    }

    fn coefficients(&self, t: f64) -> &[f64; 5] {
        if t < T_MID {
            &self.low
        } else {
            &self.high
        }
    }

    /// J/(kg·K), c_v = c_p − R at T.
    pub fn cv(&self, t: f64) -> f64 {
        let c = self.coefficients(t);
        c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * c[4]))) - self.r
    }

    /// ∫ c_v dT of one coefficient set, from 0 (an antiderivative).
    fn antiderivative(&self, c: &[f64; 5], t: f64) -> f64 {
        t * (c[0] - self.r + t * (c[1] / 2.0 + t * (c[2] / 3.0 + t * (c[3] / 4.0 + t * c[4] / 5.0))))
    }

    /// J/kg, sensible internal energy ∫_{T₀}^{T} c_v dT.
    pub fn u(&self, t: f64) -> f64 {
        let below = |t: f64| self.antiderivative(&self.low, t) - self.antiderivative(&self.low, T_REFERENCE);
        if t < T_MID {
            below(t)
        } else {
            below(T_MID) + self.antiderivative(&self.high, t) - self.antiderivative(&self.high, T_MID)
        }
    }
}

/// The charge: unburned air and the burned gas of one fuel at one equivalence ratio.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Charge {
    /// The unburned charge.
    pub air: Mixture,
    /// The products of complete combustion at the charge's equivalence ratio.
    pub burned: Mixture,
}

impl Charge {
    /// Air and the products of fuel CH_y burned with it at equivalence ratio `phi` (0..=1).
    pub fn new(hydrogen_carbon_ratio: f64, phi: f64) -> Self {
        let fuel = phi / (1.0 + 0.25 * hydrogen_carbon_ratio);
        let air = Mixture::of(&[(&N2, AIR_N2_PER_O2), (&O2, 1.0), (&AR, AIR_AR_PER_O2)]);
        let burned = Mixture::of(&[
            (&N2, AIR_N2_PER_O2),
            (&O2, 1.0 - phi),
            (&AR, AIR_AR_PER_O2),
            (&CO2, fuel),
            (&H2O, 0.5 * hydrogen_carbon_ratio * fuel),
        ]);
        Self { air, burned }
    }

    /// J/(kg·K), gas constant at burned mass fraction x.
    pub fn r(&self, x: f64) -> f64 {
        (1.0 - x) * self.air.r + x * self.burned.r
    }

    /// J/(kg·K), c_v at T and x.
    pub fn cv(&self, t: f64, x: f64) -> f64 {
        (1.0 - x) * self.air.cv(t) + x * self.burned.cv(t)
    }

    /// J/kg, sensible internal energy at T and x.
    pub fn u(&self, t: f64, x: f64) -> f64 {
        (1.0 - x) * self.air.u(t) + x * self.burned.u(t)
    }

    /// γ = c_p/c_v at T and x.
    pub fn gamma(&self, t: f64, x: f64) -> f64 {
        1.0 + self.r(x) / self.cv(t, x)
    }
}

/// Stoichiometric fuel/air mass ratio of fuel CH_y with the air above.
pub fn stoichiometric_fuel_air(hydrogen_carbon_ratio: f64) -> f64 {
    let air_per_o2 = O2.molar_mass + AIR_N2_PER_O2 * N2.molar_mass + AIR_AR_PER_O2 * AR.molar_mass;
    (CARBON + hydrogen_carbon_ratio * HYDROGEN) / (1.0 + 0.25 * hydrogen_carbon_ratio) / air_per_o2
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn air_has_the_textbook_gas_constant_and_heat_capacities() {
        // Heywood (1988) App. D and the NBS Circular 564 air table: R = 287 J/(kg K), c_v(300 K) = 718,
        // c_v(1000 K) = 855 J/(kg K) (3 figures).
        let air = Charge::new(1.87, 1.0).air;
        assert!((air.r - 287.0).abs() < 0.5, "R = {}", air.r);
        assert!((air.cv(300.0) - 718.0).abs() < 2.0, "cv(300) = {}", air.cv(300.0));
        assert!((air.cv(1000.0) - 855.0).abs() < 3.0, "cv(1000) = {}", air.cv(1000.0));
    }

    #[test]
    fn sensible_energy_is_the_integral_of_cv_and_continuous_at_1000_k() {
        let charge = Charge::new(1.8, 0.7);
        for x in [0.0, 0.4, 1.0] {
            let (a, b, n) = (300.0, 3000.0, 20_000);
            let h = (b - a) / n as f64;
            let simpson: f64 = (0..n)
                .map(|k| {
                    let t = a + k as f64 * h;
                    h / 6.0 * (charge.cv(t, x) + 4.0 * charge.cv(t + 0.5 * h, x) + charge.cv(t + h, x))
                })
                .sum();
            let du = charge.u(b, x) - charge.u(a, x);
            assert!((du / simpson - 1.0).abs() < 1e-9, "x = {x}: {du} vs {simpson}");
            assert!((charge.u(T_MID + 1e-9, x) - charge.u(T_MID - 1e-9, x)).abs() < 1e-5);
        }
    }

    #[test]
    fn stoichiometric_air_fuel_ratios_are_heywoods() {
        // Heywood (1988) App. D: gasoline (CH1.87) 14.6, diesel (CH1.8) 14.5.
        assert!((1.0 / stoichiometric_fuel_air(1.87) - 14.6).abs() < 0.05);
        assert!((1.0 / stoichiometric_fuel_air(1.8) - 14.5).abs() < 0.05);
    }
}
