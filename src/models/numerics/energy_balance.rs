//! What a model tells about its energy, so that a long run can check, window by window,
//!   ΔE = ∫ (P_drive + P_gas − D − F) dt − Σ impact dissipation + Σ impulsive drive work,
//! E the mechanical energy, D the joint damping's and F the liner friction's dissipation rate (the
//! lubricated skirt's absorbed power with it) (`tools/soak.rs`).

/// Rates of work on the moving parts at one instant, W.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PowerFlows {
    /// Work rate of what is prescribed: the drive holding the crank speed (crank_mode 1), or the
    /// load torque on a free crank (negative); for the roller also its moving walls while sliding.
    pub drive: f64,
    /// Work rate of the gas force on the piston.
    pub gas: f64,
    /// Dissipation rate of the joint damping, ≥ 0.
    pub damping: f64,
    /// Dissipation rate of liner friction in persistent contact, ≥ 0.
    pub friction: f64,
    /// The power the lubricated skirt takes from the motion (film, asperities, their friction).
    pub film: f64,
}

/// The terms of the energy balance a model can state about itself.
pub trait EnergyBalance {
    /// Mechanical energy E now, J.
    fn mechanical_energy(&self) -> f64;
    /// Power flows now.
    fn power_flows(&self) -> PowerFlows;
    /// Work the prescribed motion has done through impulses since the start, J: a crank held at
    /// speed takes an impulse at every impact (and every start of sliding), and does work with it.
    fn impulse_work(&self) -> f64;
}
