//! Greenwood–Tripp asperity contact of two rough surfaces separated by a nominal gap h.
//!
//! Greenwood & Tripp, "The contact of two nominally flat rough surfaces", Proc. IMechE 185 (1970–71)
//! 625–633: Gaussian summit heights of composite standard deviation σ, summits of density η and radius
//! β in Hertzian contact, give the nominal contact pressure `p_a = K·F_5/2(h/σ)`, `K = (8√2/15)·π·(ηβσ)²
//! ·√(σ/β)·E'`, with `F_n(λ) = (2π)^(−1/2) ∫_λ^∞ (s − λ)^n e^(−s²/2) ds`. The pressure depends on h
//! alone: the asperities are elastic, and store per unit area `e_a(h) = ∫_h^∞ p_a dh' = K·σ·(2/7)·F_7/2(h/σ)`
//! (`dF_n/dλ = −n F_(n−1)`).

use crate::models::ModelError;
use std::f64::consts::PI;
use std::sync::OnceLock;

/// Roughness of the piston–liner pair for the Greenwood–Tripp asperity pressure.
///
/// Defaults: ηβσ = 0.04 and σ/β = 10⁻³ (Greenwood & Tripp give ηβσ ≈ 0.03–0.05 and σ/β ≈ 10⁻⁴–10⁻²
/// for engineering surfaces; this pair is the one the piston ring–liner literature commonly takes,
/// e.g. Styles, Rahmani, Rahnejat & Fitzsimons, Int. J. Engine Res. 15 (2014) 862–876), with σ = 0.5 µm
/// for a honed liner against a machined skirt, hence β = 0.5 mm and η = 0.04/(βσ) = 1.6·10⁸ m⁻²;
/// E' = 96 GPa from `2/E' = Σ (1 − ν²)/E` of an Al–Si piston (72 GPa, 0.33) and a grey cast iron liner
/// (110 GPa, 0.26).
#[derive(Clone, Debug, PartialEq)]
pub struct Roughness {
    /// Composite RMS roughness σ of the two surfaces' summit heights, m.
    pub sigma: f64,
    /// Asperity (summit) density η, 1/m².
    pub density: f64,
    /// Asperity summit radius β, m.
    pub radius: f64,
    /// Composite elastic modulus E', `2/E' = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂`, Pa.
    pub modulus: f64,
}

impl Default for Roughness {
    fn default() -> Self {
        let (sigma, radius) = (0.5e-6, 0.5e-3);
        Self { sigma, density: 0.04 / (radius * sigma), radius, modulus: 96e9 }
    }
}

impl Roughness {
    /// Refuses non-physical roughness data, naming the field: each value finite and positive, and
    /// the model's two dimensionless groups where its derivation holds, sparse Hertzian summits:
    /// `ηβσ` within `SUMMIT_GROUP` (0.03–0.05 on engineering surfaces, Greenwood & Tripp) and
    /// `σ/β` at most `LARGEST_SIGMA_OVER_RADIUS` (10⁻⁴–10⁻² there).
    pub fn validate(&self) -> Result<(), ModelError> {
        for (name, v) in [("sigma", self.sigma), ("density", self.density), ("radius", self.radius), ("modulus", self.modulus)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(ModelError(format!("skirt roughness: {name} = {v} must be finite and > 0")));
            }
        }
        let group = self.density * self.radius * self.sigma;
        let [low, high] = SUMMIT_GROUP;
        if !(low..=high).contains(&group) {
            return Err(ModelError(format!(
                "asperity_density·asperity_radius·skirt_roughness = {group:e} must lie in [{low}, {high}]: Greenwood–Tripp's sparse summits (0.03–0.05 on engineering surfaces)"
            )));
        }
        if self.sigma / self.radius > LARGEST_SIGMA_OVER_RADIUS {
            return Err(ModelError(format!(
                "skirt_roughness/asperity_radius = {:e} must be at most {LARGEST_SIGMA_OVER_RADIUS}: Greenwood–Tripp's summits are Hertzian, σ ≪ β (10⁻⁴–10⁻² on engineering surfaces)",
                self.sigma / self.radius
            )));
        }
        Ok(())
    }

    /// K of `p_a = K·F_5/2(h/σ)`, Pa.
    fn stiffness(&self) -> f64 {
        let b = self.density * self.radius * self.sigma;
        8.0 * 2.0_f64.sqrt() / 15.0 * PI * b * b * (self.sigma / self.radius).sqrt() * self.modulus
    }
}

/// The accepted range of `ηβσ`: a decade and more either side of the engineering surfaces' 0.03–0.05.
const SUMMIT_GROUP: [f64; 2] = [1e-3, 1.0];
/// The largest accepted `σ/β`: a decade above the engineering surfaces' 10⁻⁴–10⁻².
const LARGEST_SIGMA_OVER_RADIUS: f64 = 0.1;

const PANELS: usize = 600;

/// A moment and its derivative at λ = `Asperity::LOW` + k·`Asperity::STEP`.
type Table = Vec<(f64, f64)>;

/// `F_n(λ)` for 2n + 1 a whole number, by composite Simpson quadrature after `s = λ + t²`: `(2/√(2π)) ∫_0^T t^(2n+1) e^(−(λ+t²)²/2) dt`,
/// T where the exponent passes 12²/2 (e^(−72) ≈ 5·10⁻³², far below the values used), [`PANELS`] panels:
/// smooth integrand, error below 10⁻⁹ relative against the closed forms in the tests' range.
#[cfg(test)]
pub(crate) fn gaussian_moment(n: f64, lambda: f64) -> f64 {
    gaussian_moments([n], lambda)[0]
}

/// [`gaussian_moment`] of each order in `orders` at one λ: the orders share the quadrature's nodes and
/// so its exponentials, and each sum takes the operations a lone order's would.
fn gaussian_moments<const K: usize>(orders: [f64; K], lambda: f64) -> [f64; K] {
    let end = (12.0 - lambda).max(1.0).sqrt();
    let panels = PANELS;
    let step = end / panels as f64;
    // 2n + 1 is an integer for the integer and half-integer orders used.
    let powers = orders.map(|n| (2.0 * n + 1.0) as i32);
    let f = |t: f64| {
        let e = libm::exp(-0.5 * (lambda + t * t) * (lambda + t * t));
        powers.map(|power| t.powi(power) * e)
    };
    let (first, last) = (f(0.0), f(end));
    let mut s: [f64; K] = std::array::from_fn(|m| first[m] + last[m]);
    for k in 1..panels {
        let weight = if k % 2 == 1 { 4.0 } else { 2.0 };
        for (s, v) in s.iter_mut().zip(f(k as f64 * step)) {
            *s += weight * v;
        }
    }
    s.map(|s| 2.0 * s * step / 3.0 / (2.0 * PI).sqrt())
}

/// The asperity pressure law of one roughness, `F_5/2` tabulated once for cheap evaluation.
#[derive(Clone, Debug)]
pub(crate) struct Asperity {
    /// 1/σ, 1/m.
    inverse_sigma: f64,
    stiffness: f64,
    /// F_5/2 and its derivative −(5/2)·F_3/2 at λ = LOW + k·STEP: the same for every roughness, so
    /// tabulated once per process (a quadrature at each λ, which every skirt built, an FMU state
    /// restored included, would otherwise pay).
    table: &'static [(f64, f64)],
    /// F_7/2 and its derivative −(7/2)·F_5/2 likewise, for the stored energy.
    energy_table: &'static [(f64, f64)],
}

impl Asperity {
    const LOW: f64 = -4.0;
    /// Beyond λ = 8 F_5/2 < 10⁻¹⁵: no contact.
    const HIGH: f64 = 8.0;
    const STEP: f64 = 1.0 / 32.0;

    pub(crate) fn new(r: &Roughness) -> Self {
        // F_3/2, F_5/2 and F_7/2 at each λ of the tables, from one quadrature's exponentials.
        let moments = || {
            let count = ((Self::HIGH - Self::LOW) / Self::STEP) as usize + 1;
            (0..count).map(|k| gaussian_moments([1.5, 2.5, 3.5], Self::LOW + k as f64 * Self::STEP)).collect::<Vec<_>>()
        };
        let both = || {
            let f = moments();
            let table = f.iter().map(|&[f32, f52, _]| (f52, -2.5 * f32)).collect();
            let energy = f.iter().map(|&[_, f52, f72]| (f72, -3.5 * f52)).collect();
            (table, energy)
        };
        static TABLES: OnceLock<(Table, Table)> = OnceLock::new();
        let (table, energy_table) = TABLES.get_or_init(both);
        Self { inverse_sigma: 1.0 / r.sigma, stiffness: r.stiffness(), table, energy_table }
    }

    /// `F_5/2(λ)`: cubic Hermite on the table (error below 10⁻⁶ relative or 10⁻¹² absolute, the test
    /// measures); below it (a film collapsed past −4σ) the expansion of `E[(L + s)^(5/2)]`, L = −λ, s
    /// standard normal: `L^(5/2)·(1 + (15/8)/L² − (15/128)/L⁴ − (75/1024)/L⁶)`, the Gaussian tail under
    /// s < −L (< 3·10⁻⁵ of the value) included in the error, which the test bounds.
    pub(crate) fn f52(&self, lambda: f64) -> f64 {
        if lambda >= Self::HIGH {
            return 0.0;
        }
        if lambda < Self::LOW {
            let inverse = 1.0 / (lambda * lambda);
            let series = 1.0 + inverse * (15.0 / 8.0 - inverse * (15.0 / 128.0 + inverse * 75.0 / 1024.0));
            return (-lambda) * (-lambda) * (-lambda).sqrt() * series;
        }
        Self::interpolated(self.table, lambda)
    }

    /// `F_7/2(λ)` for λ ≥ `LOW` (the skirt reads the asperities no deeper than its film's floor, σ/10):
    /// cubic Hermite on its table, as [`Self::f52`].
    fn f72(&self, lambda: f64) -> f64 {
        if lambda >= Self::HIGH {
            return 0.0;
        }
        Self::interpolated(self.energy_table, lambda.max(Self::LOW))
    }

    /// The cubic Hermite of a table of (F_n, F_n') at λ in [LOW, HIGH).
    #[inline(always)]
    fn interpolated(table: &[(f64, f64)], lambda: f64) -> f64 {
        let x = (lambda - Self::LOW) / Self::STEP;
        let k = (x as usize).min(table.len() - 2);
        let t = x - k as f64;
        let ((f0, d0), (f1, d1)) = (table[k], table[k + 1]);
        let (t2, t3) = (t * t, t * t * t);
        (2.0 * t3 - 3.0 * t2 + 1.0) * f0 + (t3 - 2.0 * t2 + t) * Self::STEP * d0 + (-2.0 * t3 + 3.0 * t2) * f1 + (t3 - t2) * Self::STEP * d1
    }

    /// The elastic energy the asperities store per unit area at a film of thickness `h`, J/m²:
    /// `K·σ·(2/7)·F_7/2(h/σ)`, whose derivative in h is −[`Self::pressure`].
    pub(crate) fn energy(&self, h: f64) -> f64 {
        self.stiffness * (2.0 / 7.0) * self.f72(h * self.inverse_sigma) / self.inverse_sigma
    }

    /// Whether a film of thickness `h` carries asperity pressure (it is zero from λ = 8 up).
    pub(crate) fn touches(&self, h: f64) -> bool {
        h * self.inverse_sigma < Self::HIGH
    }

    /// Nominal asperity pressure at film thickness `h`, Pa.
    pub(crate) fn pressure(&self, h: f64) -> f64 {
        self.stiffness * self.f52(h * self.inverse_sigma)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Standard normal density.
    fn phi(x: f64) -> f64 {
        libm::exp(-0.5 * x * x) / (2.0 * PI).sqrt()
    }

    #[test]
    fn moments_match_their_closed_forms() {
        // Integer orders in closed form: F_0 = ½ erfc(λ/√2), F_1 = φ − λF_0, F_2 = −λF_1 + F_0
        // (F_(n+1) = −λF_n + n F_(n−1) by parts).
        for lambda in [-2.0, -0.5, 0.0, 0.7, 1.5, 3.0, 4.5] {
            let f0 = 0.5 * libm::erfc(lambda / 2.0_f64.sqrt());
            let f1 = phi(lambda) - lambda * f0;
            let f2 = -lambda * f1 + f0;
            for (n, exact) in [(0.0, f0), (1.0, f1), (2.0, f2)] {
                let q = gaussian_moment(n, lambda);
                assert!((q / exact - 1.0).abs() < 1e-9, "F_{n}({lambda}) = {q}, closed form {exact}");
            }
        }
        // F_5/2(0) = 2^(3/4)·Γ(7/4)/√(2π) = 0.6166342…; Γ(7/4) = 0.9190625268488832.
        let exact = libm::pow(2.0, 0.75) * 0.919_062_526_848_883_2 / (2.0 * PI).sqrt();
        assert!((gaussian_moment(2.5, 0.0) / exact - 1.0).abs() < 1e-10);
        // The half-integer recursion F_5/2 = −λF_3/2 + (3/2)F_1/2.
        for lambda in [-1.0, 0.5, 2.0, 3.5] {
            let r = -lambda * gaussian_moment(1.5, lambda) + 1.5 * gaussian_moment(0.5, lambda);
            assert!((gaussian_moment(2.5, lambda) / r - 1.0).abs() < 1e-9);
        }
        // Large λ: F_n ≈ Γ(n+1) φ(λ)/λ^(n+1)·(1 − (n+1)(n+2)/(2λ²) + (n+1)(n+2)(n+3)(n+4)/(8λ⁴)),
        // truncation below the next term, (n+1)…(n+6)/(48λ⁶): 1.3 % at λ = 7 for n = 5/2.
        let (n, lambda) = (2.5, 7.0);
        let gamma = 3.323_350_970_447_843; // Γ(7/2) = 15√π/8.
        let l2 = lambda * lambda;
        let asymptotic = gamma * phi(lambda) / libm::pow(lambda, n + 1.0)
            * (1.0 - (n + 1.0) * (n + 2.0) / (2.0 * l2) + (n + 1.0) * (n + 2.0) * (n + 3.0) * (n + 4.0) / (8.0 * l2 * l2));
        assert!((gaussian_moment(n, lambda) / asymptotic - 1.0).abs() < 0.013);
    }

    /// The tables take three orders from one quadrature's exponentials: each is its own quadrature
    /// bit for bit (the order hidden from the compiler there, so that its power is taken at run time).
    #[test]
    fn the_shared_quadrature_is_each_orders_own() {
        for k in 0..=40 {
            let lambda = Asperity::LOW + k as f64 * 0.3;
            let shared = gaussian_moments([1.5, 2.5, 3.5], lambda);
            for (n, s) in [1.5, 2.5, 3.5].into_iter().zip(shared) {
                assert_eq!(s.to_bits(), gaussian_moment(std::hint::black_box(n), lambda).to_bits(), "F_{n}({lambda})");
            }
        }
    }

    #[test]
    fn the_fmu_defaults_are_the_cited_roughness() {
        // The parameters' start values (the variable table) give Greenwood–Tripp's dimensionless
        // groups of the cited pair, ηβσ = 0.04 and σ/β = 1e-3, and E' = 96 GPa.
        let p = crate::fmus::piston_slap::Parameters::default();
        let (sigma, density, radius) = (p.skirt_roughness, p.asperity_density, p.asperity_radius);
        assert!((density * radius * sigma / 0.04 - 1.0).abs() < 1e-12, "ηβσ = {}", density * radius * sigma);
        assert!((sigma / radius / 1e-3 - 1.0).abs() < 1e-12, "σ/β = {}", sigma / radius);
        assert_eq!(Roughness { sigma, density, radius, modulus: p.composite_modulus }, Roughness::default());
    }

    #[test]
    fn table_follows_the_quadrature() {
        let a = Asperity::new(&Roughness::default());
        for k in 0..600 {
            let lambda = -3.99 + k as f64 * 0.0199;
            let (t, q) = (a.f52(lambda), gaussian_moment(2.5, lambda));
            assert!((t - q).abs() <= 1e-6 * q + 1e-12, "λ = {lambda}: table {t}, quadrature {q}");
        }
        assert_eq!(a.f52(8.5), 0.0);
        for lambda in [-4.0001, -5.0, -8.0, -20.0] {
            let (t, q) = (a.f52(lambda), gaussian_moment(2.5, lambda));
            assert!((t - q).abs() <= 1e-5 * q, "λ = {lambda}: expansion {t}, quadrature {q}");
        }
        // K of the defaults: (8√2/15)π·0.04²·√(10⁻³)·96 GPa = 0.2315 MPa… times F_5/2.
        let k = 8.0 * 2.0_f64.sqrt() / 15.0 * PI * 0.04 * 0.04 * 1e-3_f64.sqrt() * 96e9;
        assert!((a.pressure(0.0) / (k * gaussian_moment(2.5, 0.0)) - 1.0).abs() < 1e-12);
    }

    /// The stored energy is the work of the pressure from h to contact's end: its difference between
    /// two films equals the pressure integrated between them (Simpson, 2000 panels), and it is zero
    /// beyond the asperities' reach; at λ = 0, `K·σ·(2/7)·F_7/2(0)` with `F_7/2(0) = 2^(5/4)·Γ(9/4)/√(2π)`.
    #[test]
    fn the_stored_energy_is_the_pressures_work() {
        let r = Roughness::default();
        let a = Asperity::new(&r);
        for (h0, h1) in [(0.05, 0.5), (0.1, 1.0), (0.5, 2.0), (1.0, 3.0), (2.0, 4.0)].map(|(x, y)| (x * r.sigma, y * r.sigma)) {
            let n = 2000;
            let dh = (h1 - h0) / n as f64;
            let work: f64 = (0..=n)
                .map(|k| {
                    let weight = if k == 0 || k == n {
                        1.0
                    } else if k % 2 == 1 {
                        4.0
                    } else {
                        2.0
                    };
                    weight * a.pressure(h0 + k as f64 * dh)
                })
                .sum::<f64>()
                * dh
                / 3.0;
            let stored = a.energy(h0) - a.energy(h1);
            assert!((stored / work - 1.0).abs() < 1e-6, "{h0:e}..{h1:e} m: stored {stored:e} J/m², work {work:e} J/m²");
        }
        assert_eq!(a.energy(8.5 * r.sigma), 0.0);
        let gamma = 1.133_003_096_319_346_3; // Γ(9/4)
        let f72 = libm::pow(2.0, 1.25) * gamma / (2.0 * PI).sqrt();
        let k = a.pressure(0.0) / gaussian_moment(2.5, 0.0);
        assert!((a.energy(0.0) / (k * r.sigma * 2.0 / 7.0 * f72) - 1.0).abs() < 1e-6);
    }
}
