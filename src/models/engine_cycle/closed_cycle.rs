//! The closed part of the cycle, inlet valve closing at bottom dead centre (ϑ = −π) to exhaust valve opening:
//! one zone of ideal gas of mass m, integrated once (RK4 in ϑ on a 0.1° grid) and read back by cubic Hermite
//! interpolation, so the pressure is C¹ and an output costs one table look-up.
//!
//! - `gas_properties = 1`: the first law with a polytropic exponent n in place of γ,
//!   `dp/dϑ = −n p/V dV/dϑ + (n − 1)/V (dQ/dϑ − dQ_w/dϑ)` (`p Vⁿ` constant when neither heat flows), and the
//!   temperature `T = p V/(m R)`;
//! - `gas_properties = 2`: the first law in the temperature with the charge's sensible energy u(T, x)
//!   ([`super::thermo`]) at burned mass fraction `x = x_r + (1 − x_r) x_b`,
//!   `m (c_v dT/dϑ + (u_b − u_a) dx/dϑ) = dQ/dϑ − dQ_w/dϑ − p dV/dϑ`, and `p = m R(x) T/V`.
//!
//! `Q = Q_fuel x_b` with the Wiebe burn fraction `x_b = 1 − exp(−a ((ϑ − ϑ_s)/Δϑ)^(m+1))` for ϑ ≥ ϑ_s
//! (Heywood eq 9.23; the number not checked), `Q_w` the wall heat ([`super::heat_transfer`]). The mass follows from
//! `p_intake V(−π) = m R(x_r) T_intake`; the fuel the charge holds bounds the heat release: `Q_fuel ≤ (1 − x_r) m
//! (F/A)_s LHV`, and the burned gas is the product at `φ = Q_fuel / ((1 − x_r) m (F/A)_s LHV)`.

use super::heat_transfer::{Correlation, Reference, WallHeat};
use super::thermo::{stoichiometric_fuel_air, Charge};
use super::CycleDesign;
use crate::models::ModelError;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Grid of the closed-cycle table, rad (0.1°).
const TABLE_SPACING: f64 = PI / 1800.0;
/// Pa: a peak cylinder pressure above this is refused (production engines stay below about 250 bar).
pub const PEAK_PRESSURE_LIMIT: f64 = 300e5;
/// K: the upper end of the GRI-Mech 3.0 polynomials of O2, CO2 and H2O.
pub const PEAK_TEMPERATURE_LIMIT: f64 = 3500.0;

/// One table node: pressure, temperature and cumulative wall heat with their crank-angle derivatives.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
struct Node {
    p: f64,
    dp: f64,
    t: f64,
    dt: f64,
    q: f64,
    dq: f64,
}

/// The closed cycle's state at one crank angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClosedState {
    /// Pa.
    pub p: f64,
    /// Pa/rad.
    pub dp: f64,
    /// K.
    pub t: f64,
    /// J, wall heat since inlet valve closing.
    pub q: f64,
    /// J/rad, its rate.
    pub dq: f64,
    /// J/rad², that rate's derivative.
    pub d2q: f64,
}

/// The charge and the integrated table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ClosedCycle {
    /// kg, trapped mass.
    pub mass: f64,
    /// Equivalence ratio of the burned gas.
    pub equivalence_ratio: f64,
    /// The air and burned-gas mixtures.
    pub charge: Charge,
    /// Node k at ϑ = −π + k · TABLE_SPACING, up to and including the first node past ϑ_EVO.
    nodes: Vec<Node>,
}

/// What the right-hand side needs besides the state.
struct Dynamics<'a> {
    parameters: &'a CycleDesign,
    charge: Charge,
    mass: f64,
    wall: WallHeat,
}

/// What the right-hand side gives: the state's rates, and p, dp/dϑ and T at the state.
struct Rates {
    dy: [f64; 2],
    p: f64,
    dp: f64,
    t: f64,
    dt: f64,
}

/// Wiebe burn fraction x_b and dx_b/dϑ at ϑ (0 when nothing burns).
pub fn wiebe(parameters: &CycleDesign, theta: f64) -> (f64, f64) {
    let p = parameters;
    let x = (theta - p.burn_start) / p.burn_duration;
    if x <= 0.0 || p.heat_release == 0.0 {
        return (0.0, 0.0);
    }
    let (a, m) = (p.wiebe_efficiency, p.wiebe_form);
    let xm = x.powi(m);
    let rate = a * f64::from(m + 1) / p.burn_duration * xm * libm::exp(-a * xm * x);
    (1.0 - libm::exp(-a * xm * x), rate)
}

impl Dynamics<'_> {
    /// y = [p (gas_properties 1) or T (2), Q_w].
    fn rates(&self, theta: f64, y: [f64; 2]) -> Rates {
        let par = self.parameters;
        let vol = par.volume(theta);
        let (xb, dxb) = wiebe(par, theta);
        let release = par.heat_release * dxb;
        let x_r = par.residual_gas_fraction;
        let m = self.mass;
        if par.gas_properties == 1 {
            let (n, pressure) = (par.polytropic_exponent, y[0]);
            let r = self.charge.r(x_r);
            let t = pressure * vol.v / (m * r);
            let wall = self.wall.per_angle(theta, pressure, t, vol.v);
            let dp = (-n * pressure * vol.dv + (n - 1.0) * (release - wall)) / vol.v;
            let dt = (pressure * vol.dv + vol.v * dp) / (m * r);
            Rates { dy: [dp, wall], p: pressure, dp, t, dt }
        } else {
            let (t, charge) = (y[0], &self.charge);
            let (x, dx) = (x_r + (1.0 - x_r) * xb, (1.0 - x_r) * dxb);
            let r = charge.r(x);
            let pressure = m * r * t / vol.v;
            let wall = self.wall.per_angle(theta, pressure, t, vol.v);
            let mixing = charge.burned.u(t) - charge.air.u(t);
            let dt = (release - wall - pressure * vol.dv - m * mixing * dx) / (m * charge.cv(t, x));
            let dp = (m * (r * dt + (charge.burned.r - charge.air.r) * t * dx) - pressure * vol.dv) / vol.v;
            Rates { dy: [dt, wall], p: pressure, dp, t, dt }
        }
    }
}

impl ClosedCycle {
    /// The charge of a validated design `parameters`, its plausibility checked, and the integrated table.
    pub fn new(parameters: &CycleDesign) -> Result<Self, ModelError> {
        let par = parameters;
        let (y, x_r) = (par.fuel_hydrogen_carbon_ratio, par.residual_gas_fraction);
        let v_ivc = par.volume(-PI).v;
        let mass = |charge: &Charge| par.intake_pressure * v_ivc / (charge.r(x_r) * par.intake_temperature);
        let fuel_energy = |phi: f64| (1.0 - x_r) * mass(&Charge::new(y, phi)) * stoichiometric_fuel_air(y) * par.fuel_heating_value;
        let most = fuel_energy(1.0);
        if par.heat_release > most {
            return Err(ModelError(format!(
                "heat_release = {} J is implausible: the charge trapped at intake_pressure = {} Pa, intake_temperature = {} K \
                 and residual_gas_fraction = {} holds fuel for at most {most:.1} J (stoichiometric, fuel_heating_value = {} J/kg)",
                par.heat_release, par.intake_pressure, par.intake_temperature, x_r, par.fuel_heating_value
            )));
        }
        // φ enters the mass only through the residual's gas constant: a contraction that settles in a few rounds.
        let mut phi = par.heat_release / most;
        for _ in 0..6 {
            phi = (par.heat_release / fuel_energy(phi)).min(1.0);
        }
        let charge = Charge::new(y, phi);
        let m = mass(&charge);
        let speed = par.cycle_speed();
        let mut wall = WallHeat::new(
            Correlation::from_parameter(par.heat_transfer),
            par.bore,
            par.stroke,
            par.displacement(),
            par.wall_temperature,
            speed,
        );
        let gamma = if par.gas_properties == 1 { par.polytropic_exponent } else { charge.gamma(par.intake_temperature, x_r) };
        wall.reference = Reference { pressure: par.intake_pressure, temperature: par.intake_temperature, volume: v_ivc, gamma };
        wall.burn_start = par.burn_start;
        let dynamics = Dynamics { parameters: par, charge, mass: m, wall };
        let count = ((par.exhaust_valve_opening + PI) / TABLE_SPACING).ceil() as usize + 1;
        let mut nodes = Vec::with_capacity(count);
        let mut y = [if par.gas_properties == 1 { par.intake_pressure } else { par.intake_temperature }, 0.0];
        let h = TABLE_SPACING;
        for k in 0..count {
            let theta = -PI + k as f64 * h;
            let k1 = dynamics.rates(theta, y);
            nodes.push(Node { p: k1.p, dp: k1.dp, t: k1.t, dt: k1.dt, q: y[1], dq: k1.dy[1] });
            let step = |y: [f64; 2], k: &[f64; 2], f: f64| [y[0] + f * h * k[0], y[1] + f * h * k[1]];
            let k2 = dynamics.rates(theta + 0.5 * h, step(y, &k1.dy, 0.5)).dy;
            let k3 = dynamics.rates(theta + 0.5 * h, step(y, &k2, 0.5)).dy;
            let k4 = dynamics.rates(theta + h, step(y, &k3, 1.0)).dy;
            for i in 0..2 {
                y[i] += h / 6.0 * (k1.dy[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
        }
        let cycle = Self { mass: m, equivalence_ratio: phi, charge, nodes };
        cycle.check_plausible(par)?;
        Ok(cycle)
    }

    fn check_plausible(&self, par: &CycleDesign) -> Result<(), ModelError> {
        let finite = self.nodes.iter().all(|n| [n.p, n.dp, n.t, n.dt, n.q, n.dq].iter().all(|v| v.is_finite()) && n.p > 0.0 && n.t > 0.0);
        if !finite {
            return Err(ModelError("the closed-cycle pressure or temperature is not finite and positive: check heat_release".into()));
        }
        let (peak_p, peak_t) = self.nodes.iter().fold((0.0_f64, 0.0_f64), |(p, t), n| (p.max(n.p), t.max(n.t)));
        if peak_p > PEAK_PRESSURE_LIMIT {
            return Err(ModelError(format!(
                "the cycle is implausible: its peak cylinder pressure {:.0} bar exceeds {:.0} bar (heat_release = {} J, \
                 intake_pressure = {} Pa, compression_ratio = {})",
                peak_p / 1e5,
                PEAK_PRESSURE_LIMIT / 1e5,
                par.heat_release,
                par.intake_pressure,
                par.compression_ratio
            )));
        }
        if par.gas_properties == 2 && peak_t > PEAK_TEMPERATURE_LIMIT {
            return Err(ModelError(format!(
                "heat_release = {} J is implausible: the peak charge temperature {peak_t:.0} K exceeds {PEAK_TEMPERATURE_LIMIT} K, \
                 the end of the gas data (GRI-Mech 3.0)",
                par.heat_release
            )));
        }
        Ok(())
    }

    /// The state at ϑ in [−π, ϑ_EVO], cubic Hermite between the nodes.
    pub fn state(&self, theta: f64) -> ClosedState {
        let u = ((theta + PI) / TABLE_SPACING).max(0.0);
        let k = (u.floor() as usize).min(self.nodes.len() - 2);
        let s = u - k as f64;
        let (a, b) = (&self.nodes[k], &self.nodes[k + 1]);
        let (p, dp, _) = hermite(s, (a.p, a.dp), (b.p, b.dp));
        let (t, _, _) = hermite(s, (a.t, a.dt), (b.t, b.dt));
        let (q, dq, d2q) = hermite(s, (a.q, a.dq), (b.q, b.dq));
        ClosedState { p, dp, t, q, dq, d2q }
    }
}

/// Value, first and second derivative in ϑ of the cubic Hermite interpolant at fraction `s` of a table interval
/// between (value, slope) pairs.
fn hermite(s: f64, (y0, d0): (f64, f64), (y1, d1): (f64, f64)) -> (f64, f64, f64) {
    let h = TABLE_SPACING;
    let (s2, s3) = (s * s, s * s * s);
    let value = (2.0 * s3 - 3.0 * s2 + 1.0) * y0 + (s3 - 2.0 * s2 + s) * h * d0 + (-2.0 * s3 + 3.0 * s2) * y1 + (s3 - s2) * h * d1;
    let slope = ((6.0 * s2 - 6.0 * s) * y0 + (6.0 * s2 - 6.0 * s) * -y1) / h + (3.0 * s2 - 4.0 * s + 1.0) * d0 + (3.0 * s2 - 2.0 * s) * d1;
    let curvature = ((12.0 * s - 6.0) * (y0 - y1)) / (h * h) + ((6.0 * s - 4.0) * d0 + (6.0 * s - 2.0) * d1) / h;
    (value, slope, curvature)
}
