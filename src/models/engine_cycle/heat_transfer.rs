//! Heat transfer from the charge to the walls over the closed part of the cycle (`heat_transfer`).
//!
//! `Q̇_w = h A_w (T − T_w)` with the wall area `A_w = π B²/2 + 4 V/B` (flat head and crown, the liner down to the
//! piston; Heywood, *Internal Combustion Engine Fundamentals*, 1988, §2.2), one wall temperature `T_w`, and h by:
//! - 1 Woschni (G. Woschni, SAE 670931, 1967): `h = 3.26 B^−0.2 p^0.8 T^−0.53 w^0.8` in W/(m²·K) with B in m,
//!   p in kPa, T in K, w in m/s; `w = C1 S̄p + C2 (V_d T_r)/(p_r V_r) (p − p_m)` with C1 = 2.28 over compression,
//!   combustion and expansion (6.18 over gas exchange, not modelled) and C2 = 3.24e-3 m/(s·K) from the start of
//!   combustion on (0 before; 6.22e-3 would be a prechamber engine's); r is the state at inlet valve closing and
//!   `p_m = p_r (V_r/V)^γ_r` the motored pressure, `p − p_m` taken ≥ 0. Woschni's 110 kcal/(m²·h·K) with p in at
//!   is 130 W/(m²·K) with p in bar and 3.26 with p in kPa. Heywood's eq 12.19 prints the same constant with
//!   T^−0.55, which at 300–2500 K gives 11–14 % less heat than the paper's T^−0.53 used here.
//! - 2 Hohenberg (G. F. Hohenberg, SAE 790825, 1979): `h = 130 V^−0.06 p^0.8 T^−0.4 (S̄p + 1.4)^0.8` with V in m³,
//!   p in bar, T in K, S̄p in m/s (129.8 in some tools' rounding).
//!
//! `S̄p = S ω/π` is the mean piston speed at the cycle's speed ω; per crank angle `dQ_w/dϑ = Q̇_w/ω`.

use std::f64::consts::PI;

/// Woschni's C1 (compression, combustion, expansion), C2 in m/(s·K), the leading constant (p in kPa) and the
/// exponent of the gas temperature.
const WOSCHNI_C1: f64 = 2.28;
const WOSCHNI_C2: f64 = 3.24e-3;
const WOSCHNI_CONSTANT: f64 = 3.26;
const WOSCHNI_TEMPERATURE_EXPONENT: f64 = -0.53;
/// Hohenberg's constant and the speed offset in m/s.
const HOHENBERG_CONSTANT: f64 = 130.0;
const HOHENBERG_SPEED_OFFSET: f64 = 1.4;

/// The correlation `heat_transfer` selects.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Correlation {
    /// Adiabatic walls (`heat_transfer = 0`).
    None,
    /// Woschni (1967), `heat_transfer = 1`.
    Woschni,
    /// Hohenberg (1979), `heat_transfer = 2`.
    Hohenberg,
}

impl Correlation {
    /// The correlation of a `heat_transfer` value within its table range.
    pub fn from_parameter(value: i32) -> Self {
        match value {
            1 => Self::Woschni,
            2 => Self::Hohenberg,
            _ => Self::None,
        }
    }
}

/// The state at inlet valve closing Woschni's combustion term refers to.
#[derive(Clone, Copy, Debug)]
pub struct Reference {
    /// Pa, K, m³ and c_p/c_v at inlet valve closing.
    pub pressure: f64,
    pub temperature: f64,
    pub volume: f64,
    pub gamma: f64,
}

/// The wall heat flux of one engine at one speed.
#[derive(Clone, Copy, Debug)]
pub struct WallHeat {
    pub correlation: Correlation,
    /// m.
    pub bore: f64,
    /// m³.
    pub displacement: f64,
    /// K.
    pub wall_temperature: f64,
    /// rad/s, the speed of the cycle.
    pub speed: f64,
    /// rad, where Woschni's combustion term starts.
    pub burn_start: f64,
    pub reference: Reference,
    /// m/s.
    pub mean_piston_speed: f64,
}

impl WallHeat {
    pub fn new(correlation: Correlation, bore: f64, stroke: f64, displacement: f64, wall_temperature: f64, speed: f64) -> Self {
        let reference = Reference { pressure: 0.0, temperature: 0.0, volume: 0.0, gamma: 1.0 };
        let mean_piston_speed = stroke * speed / PI;
        Self { correlation, bore, displacement, wall_temperature, speed, burn_start: 0.0, reference, mean_piston_speed }
    }

    /// W/(m²·K) at crank angle ϑ (about firing TDC), pressure p (Pa), temperature T (K) and volume V (m³).
    pub fn coefficient(&self, theta: f64, p: f64, t: f64, v: f64) -> f64 {
        match self.correlation {
            Correlation::None => 0.0,
            Correlation::Woschni => {
                let r = &self.reference;
                let combustion = if theta >= self.burn_start {
                    let motored = r.pressure * libm::pow(r.volume / v, r.gamma);
                    WOSCHNI_C2 * self.displacement * r.temperature / (r.pressure * r.volume) * (p - motored).max(0.0)
                } else {
                    0.0
                };
                let w = WOSCHNI_C1 * self.mean_piston_speed + combustion;
                WOSCHNI_CONSTANT
                    * libm::pow(self.bore, -0.2)
                    * libm::pow(1e-3 * p, 0.8)
                    * libm::pow(t, WOSCHNI_TEMPERATURE_EXPONENT)
                    * libm::pow(w, 0.8)
            }
            Correlation::Hohenberg => {
                HOHENBERG_CONSTANT
                    * libm::pow(v, -0.06)
                    * libm::pow(1e-5 * p, 0.8)
                    * libm::pow(t, -0.4)
                    * libm::pow(self.mean_piston_speed + HOHENBERG_SPEED_OFFSET, 0.8)
            }
        }
    }

    /// J/rad, dQ_w/dϑ: heat to the walls per crank angle (0 without a correlation).
    pub fn per_angle(&self, theta: f64, p: f64, t: f64, v: f64) -> f64 {
        if self.correlation == Correlation::None {
            return 0.0;
        }
        let area = 0.5 * PI * self.bore * self.bore + 4.0 * v / self.bore;
        self.coefficient(theta, p, t, v) * area * (t - self.wall_temperature) / self.speed
    }
}
