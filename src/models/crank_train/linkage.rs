//! Crank, rod and piston as a triple physical pendulum (A&K sections 6–7) in SI units, with the four
//! piston corners against the liner as unilateral constraints.
//!
//! Coordinates φ = (φ1, φ2, φ3): absolute angles of crank, rod and piston axis, each link pointing along
//! `e(φ) = (−sin φ, cos φ)` (A&K eq 25; y is the cylinder axis away from the crank, x lateral). Body k's
//! centre of mass lies at `Σ_{j<k} L_j e(φ_j) + b_k e(φ_k) + c_k n(φ_k)`, `n(φ) = (cos φ, sin φ)`, with
//! `L = (l1, l2)`, `b = (ey1, ey2, ey3)` and `c = (0, 0, −a)`: the piston's mass is symmetric about its
//! axis, which lies the pin offset `a` on the −x side of the pin O3.
//!
//! Lagrange's equations `d/dt ∂T/∂φ̇ − ∂T/∂φ = Q` with `T = ½ Σ m_k |ṙ_k|² + J_k φ̇_k²` read
//! `M φ̈ = f` with `M = Σ m_k J_kᵀ J_k + diag(J_zk)`, `J_k = ∂r_k/∂φ`. Written out, the diagonal is
//! constant and each off-diagonal entry depends on one angle difference, `M_ij = F_ij(φi − φj)`:
//! `F_12(x) = (m2 b2 + m3 l2) l1 cos x`, `F_13(x) = m3 l1 (b3 cos x + a sin x)`,
//! `F_23(x) = m3 l2 (b3 cos x + a sin x)`; then `∂T/∂φ_i` cancels the velocity products of
//! `d/dt (Mφ̇)_i` but for `f_i ∋ Σ_j F'_ij(φi − φj) φ̇_j²` (with `F'_ji = −F'_ij`). They
//! reproduce A&K eqs 22–24/33–34 (times M1, with `p(φ) = −(M1 sin φ1, M2 sin φ2, M3 sin φ3)`) for a = 0.
//! The generalized forces Q: gravity `−g` along y; viscous joint torques `−C φ̇` (A&K's C matrix:
//! main bearing c̄1 on φ̇1, crank pin c̄2 on φ̇2 − φ̇1, piston pin c̄3 on φ̇3 − φ̇2); the gas force `(0, −F)`
//! at the point of the piston axis level with the pin, `O3 − a n(φ3)`, which gives A&K eq 32 plus the
//! pin-offset moment `F a cos φ3` on φ3; a load torque `−M0` on φ1.
//!
//! Corners (A&K eq 26): `x_K = x_O3 − z sin φ3 + w cos φ3` with z = h (K1, K3) or h − s (K2, K4) and
//! w = −(d/2 + a) (K1, K2) or d/2 − a (K3, K4); gaps `h_i = D/2 + x_K` (K1, K2, wall −D/2) and
//! `D/2 − x_K` (K3, K4), in metres, so a multiplier is the normal contact force in newtons.

use crate::dynamics::{Evaluation, Tangents};
use crate::models::numerics::trig;
use nalgebra::{Matrix3, Vector2, Vector3, Vector4};
use serde::{Deserialize, Serialize};

/// Geometry, inertia and damping of the crank train (ARCHITECTURE.md §4 parameters), SI.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(from = "Bodies", into = "Bodies")]
pub struct Linkage {
    bodies: Bodies,
    /// Derived from `bodies`, so not part of a saved state.
    terms: Terms,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct Bodies {
    /// (l1, l2).
    pub(crate) links: [f64; 2],
    /// Centre-of-mass offsets along each link (ey1, ey2, ey3).
    pub(crate) along: [f64; 3],
    /// Centre-of-mass offsets across each link (0, 0, −a).
    pub(crate) across: [f64; 3],
    pub(crate) masses: [f64; 3],
    pub(crate) inertias: [f64; 3],
    /// (c̄1, c̄2, c̄3).
    pub(crate) damping: [f64; 3],
    pub(crate) gravity: f64,
    /// Gravity's lateral component, along +x (`gravity_lateral`).
    pub(crate) gravity_lateral: f64,
    pub(crate) pin_offset: f64,
    pub(crate) bore: f64,
    /// Per corner: z (distance from the pin along the axis), w (offset across it), wall side σ.
    pub(crate) corners: [(f64, f64, f64); 4],
}

impl From<Bodies> for Linkage {
    fn from(bodies: Bodies) -> Self {
        Self { terms: Terms::new(&bodies), bodies }
    }
}

impl From<Linkage> for Bodies {
    fn from(linkage: Linkage) -> Self {
        linkage.bodies
    }
}

/// Constant factors of M and f (module docs): `M_kk`, `F_ij(x) = P_ij cos x + Q_ij sin x`, and the
/// weight moments `f_k ∋ G_k sin φ_k` plus `G_a cos φ3` (the piston's centre of mass off its axis).
#[derive(Clone, Debug, PartialEq)]
struct Terms {
    diagonal: [f64; 3],
    p12: f64,
    p13: f64,
    q13: f64,
    p23: f64,
    q23: f64,
    weight: [f64; 3],
    weight_offset: f64,
    /// The same of the lateral gravity: `f_k ∋ −G^x_k cos φ_k`, plus `G^x_a sin φ3`.
    lateral: [f64; 3],
    lateral_offset: f64,
    /// The crank, the rod and the farthest corner from the pin (`Linkage::lengths`).
    lengths: Vector3<f64>,
}

impl Terms {
    fn new(bodies: &Bodies) -> Self {
        let ([l1, l2], [b1, b2, b3], [m1, m2, m3], [j1, j2, j3]) = (bodies.links, bodies.along, bodies.masses, bodies.inertias);
        let (a, g, gx) = (bodies.pin_offset, bodies.gravity, bodies.gravity_lateral);
        Self {
            diagonal: [j1 + m1 * b1 * b1 + (m2 + m3) * l1 * l1, j2 + m2 * b2 * b2 + m3 * l2 * l2, j3 + m3 * (b3 * b3 + a * a)],
            p12: (m2 * b2 + m3 * l2) * l1,
            p13: m3 * l1 * b3,
            q13: m3 * l1 * a,
            p23: m3 * l2 * b3,
            q23: m3 * l2 * a,
            weight: [g * (m1 * b1 + (m2 + m3) * l1), g * (m2 * b2 + m3 * l2), g * m3 * b3],
            weight_offset: g * m3 * a,
            lateral: [gx * (m1 * b1 + (m2 + m3) * l1), gx * (m2 * b2 + m3 * l2), gx * m3 * b3],
            lateral_offset: gx * m3 * a,
            lengths: Vector3::new(l1, l2, bodies.corners.iter().fold(0.0_f64, |r, &(z, w, _)| r.max(libm::hypot(z, w)))),
        }
    }
}

/// Generalized forces that vary with the host's inputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Loads {
    /// Gas force on the piston toward the crank, N.
    pub gas_force: f64,
    /// Load torque opposing crank rotation, N·m.
    pub load_torque: f64,
}

/// Sines and cosines of the three link angles: the only transcendental work of an evaluation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinkAngles {
    /// sin φ1, sin φ2, sin φ3.
    pub sin: [f64; 3],
    /// cos φ1, cos φ2, cos φ3.
    pub cos: [f64; 3],
}

impl LinkAngles {
    /// The sines and cosines of φ.
    pub fn new(phi: &Vector3<f64>) -> Self {
        Self::with_crank(trig::sin_cos(phi[0]), phi)
    }

    /// With the crank angle's sine and cosine at hand.
    pub fn with_crank((s1, c1): (f64, f64), phi: &Vector3<f64>) -> Self {
        let [(s2, c2), (s3, c3)] = [trig::small_sin_cos(phi[1]), trig::small_sin_cos(phi[2])];
        Self { sin: [s1, s2, s3], cos: [c1, c2, c3] }
    }

    /// The cosines and sines of φi − φj, each `[12, 13, 23]`.
    #[inline(always)]
    fn differences(&self) -> ([f64; 3], [f64; 3]) {
        let ([s1, s2, s3], [c1, c2, c3]) = (self.sin, self.cos);
        ([c1 * c2 + s1 * s2, c1 * c3 + s1 * s3, c2 * c3 + s2 * s3], [s1 * c2 - c1 * s2, s1 * c3 - c1 * s3, s2 * c3 - c2 * s3])
    }
}

fn along(phi: f64) -> Vector2<f64> {
    Vector2::new(-libm::sin(phi), libm::cos(phi))
}

#[cfg(test)]
fn across(phi: f64) -> Vector2<f64> {
    Vector2::new(libm::cos(phi), libm::sin(phi))
}

/// Each link's `along` and `across` directions: `along` and `across` of each angle, by one
/// `libm::sincos` per angle, which gives `libm::sin`'s and `libm::cos`'s bits (the same
/// reduction and kernels, one reduction for both; below 2⁻²⁶ `sin` returns x where `sincos`
/// takes the kernel, whose x³/6 is below half an ulp of x there).
fn directions(phi: &Vector3<f64>) -> [(Vector2<f64>, Vector2<f64>); 3] {
    std::array::from_fn(|k| {
        let (sin, cos) = libm::sincos(phi[k]);
        (Vector2::new(-sin, cos), Vector2::new(cos, sin))
    })
}

impl Linkage {
    /// Pin O3 position (x, y), m.
    pub fn pin(&self, phi: &Vector3<f64>) -> Vector2<f64> {
        self.bodies.links[0] * along(phi[0]) + self.bodies.links[1] * along(phi[1])
    }

    /// The pin O3 and the corner gaps from the angles' sines and cosines (the outputs' kinematics).
    pub fn pin_and_gaps(&self, trig: &LinkAngles) -> (Vector2<f64>, Vector4<f64>) {
        let ([s1, s2, s3], [c1, c2, c3]) = (trig.sin, trig.cos);
        let [l1, l2] = self.bodies.links;
        let pin = Vector2::new(-l1 * s1 - l2 * s2, l1 * c1 + l2 * c2);
        (pin, self.corner_gaps(pin.x, s3, c3))
    }

    /// Lengths that turn errors of (φ1, φ2, φ3) into displacements: the crank, the rod, and the
    /// farthest corner from the pin, m.
    pub fn lengths(&self) -> Vector3<f64> {
        self.terms.lengths
    }

    /// Corner gaps h(φ), m.
    pub fn gaps(&self, phi: &Vector3<f64>) -> Vector4<f64> {
        let [l1, l2] = self.bodies.links;
        let (s3, c3) = trig::small_sin_cos(phi[2]);
        self.corner_gaps(-l1 * trig::sin_cos(phi[0]).0 - l2 * trig::small_sin_cos(phi[1]).0, s3, c3)
    }

    /// The poses (φ2, φ3) at crank angle φ1 in which two corners touch the liner and none is outside
    /// it: the vertices of the region the clearance leaves the piston (a wall's pair flat against it,
    /// a diagonal pair at the largest tilt).
    pub fn touching_poses(&self, phi1: f64) -> Vec<Vector3<f64>> {
        let [l1, l2] = self.bodies.links;
        let corners = self.bodies.corners;
        let mut poses = Vec::new();
        for i in 0..4 {
            for j in i + 1..4 {
                let ((zi, wi, si), (zj, wj, sj)) = (corners[i], corners[j]);
                if zi == zj {
                    continue; // Two corners at one height touch opposite walls only without clearance.
                }
                // Gap zero: x − z s3 = −R·side − w c3; solved for (x, s3), c3 from the s3 found.
                let (mut x, mut s3, mut c3) = (0.0, 0.0, 1.0);
                for _ in 0..3 {
                    let (ri, rj) = (-0.5 * self.bodies.bore * si - wi * c3, -0.5 * self.bodies.bore * sj - wj * c3);
                    s3 = (ri - rj) / (zj - zi);
                    x = ri + zi * s3;
                    c3 = (1.0 - s3 * s3).max(0.0).sqrt();
                }
                let rod = -(x + l1 * libm::sin(phi1)) / l2;
                if rod.abs() >= 1.0 || s3.abs() >= 1.0 {
                    continue;
                }
                let pose = Vector3::new(phi1, libm::asin(rod), libm::asin(s3));
                if self.gaps(&pose).min() >= -1e-9 * self.bodies.bore {
                    poses.push(pose);
                }
            }
        }
        poses
    }

    /// Gaps from the pin's lateral position and the piston tilt's sine and cosine.
    fn corner_gaps(&self, x_pin: f64, s3: f64, c3: f64) -> Vector4<f64> {
        Vector4::from_fn(|i, _| {
            let (z, w, side) = self.bodies.corners[i];
            0.5 * self.bodies.bore + side * (x_pin - z * s3 + w * c3)
        })
    }

    /// M, f, h, J = ∂h/∂φ and d = φ̇ᵀ ∂²h/∂φ² φ̇ at (φ, φ̇); the constraints are scleronomic in φ.
    pub fn evaluate(&self, phi: &Vector3<f64>, phid: &Vector3<f64>, loads: Loads) -> Evaluation<3, 4> {
        self.evaluate_with(&LinkAngles::new(phi), phid, loads)
    }

    /// [`Self::evaluate`] from the angles' sines and cosines.
    #[inline(always)]
    pub fn evaluate_with(&self, trig: &LinkAngles, phid: &Vector3<f64>, loads: Loads) -> Evaluation<3, 4> {
        let (mass, force) = self.inertia_and_force_with(trig, phid, loads);
        let ([s1, s2, s3], [_, _, c3]) = (trig.sin, trig.cos);
        let [l1, l2] = self.bodies.links;
        let (w1, w2, w3) = (phid[0] * phid[0], phid[1] * phid[1], phid[2] * phid[2]);
        // The second derivative of x_O3 = −l1 s1 − l2 s2 at φ̈ = 0.
        let pin_bias = l1 * s1 * w1 + l2 * s2 * w2;
        Evaluation {
            force,
            gap_bias: Vector4::from_fn(|i, _| {
                let (z, w, side) = self.bodies.corners[i];
                side * (pin_bias + (z * s3 - w * c3) * w3)
            }),
            ..self.configuration_with(trig, mass)
        }
    }

    /// The terms of [`Self::evaluate_with`] that the configuration alone sets (M the given `mass`, h,
    /// J), with f and d zero: what a projection onto the liner reads.
    #[inline(always)]
    pub fn configuration_with(&self, trig: &LinkAngles, mass: Matrix3<f64>) -> Evaluation<3, 4> {
        let ([s1, s2, s3], [c1, c2, c3]) = (trig.sin, trig.cos);
        let [l1, l2] = self.bodies.links;
        // x_O3 = −l1 s1 − l2 s2.
        let x_pin = -l1 * s1 - l2 * s2;
        let (jacobian_1, jacobian_2) = (-l1 * c1, -l2 * c2);
        Evaluation {
            mass,
            implicit: None,
            force: Vector3::zeros(),
            gap: self.corner_gaps(x_pin, s3, c3),
            gap_jacobian: nalgebra::Matrix4x3::from_fn(|i, j| {
                let (z, w, side) = self.bodies.corners[i];
                side * [jacobian_1, jacobian_2, -(z * c3 + w * s3)][j]
            }),
            gap_time_rate: Vector4::zeros(),
            gap_bias: Vector4::zeros(),
        }
    }

    /// M of [`Self::evaluate_with`] alone.
    #[inline(always)]
    pub fn inertia_with(&self, trig: &LinkAngles) -> Matrix3<f64> {
        let k = &self.terms;
        let ([c12, c13, c23], [_, s13, s23]) = trig.differences();
        let (m12, m13, m23) = (k.p12 * c12, k.p13 * c13 + k.q13 * s13, k.p23 * c23 + k.q23 * s23);
        Matrix3::new(k.diagonal[0], m12, m13, m12, k.diagonal[1], m23, m13, m23, k.diagonal[2])
    }

    /// M and f of [`Self::evaluate_with`] alone (an RK4 stage in flight needs no more).
    #[inline(always)]
    pub fn inertia_and_force_with(&self, trig: &LinkAngles, phid: &Vector3<f64>, loads: Loads) -> (Matrix3<f64>, Vector3<f64>) {
        let ([s1, s2, s3], [c1, c2, c3]) = (trig.sin, trig.cos);
        let k = &self.terms;
        let mass = self.inertia_with(trig);
        let ([_, c13, c23], [s12, s13, s23]) = trig.differences();
        // F'_ij(φi − φj) and the squared rates.
        let (g12, g13, g23) = (-k.p12 * s12, k.q13 * c13 - k.p13 * s13, k.q23 * c23 - k.p23 * s23);
        let (w1, w2, w3) = (phid[0] * phid[0], phid[1] * phid[1], phid[2] * phid[2]);
        let [l1, l2] = self.bodies.links;
        let [cb1, cb2, cb3] = self.bodies.damping;
        let (crank_pin, piston_pin) = (phid[1] - phid[0], phid[2] - phid[1]);
        let gas = loads.gas_force;
        let force = Vector3::new(
            g12 * w2 + g13 * w3 + (k.weight[0] + gas * l1) * s1 - k.lateral[0] * c1 - loads.load_torque + cb2 * crank_pin - cb1 * phid[0],
            g23 * w3 - g12 * w1 + (k.weight[1] + gas * l2) * s2 - k.lateral[1] * c2 + cb3 * piston_pin - cb2 * crank_pin,
            -g13 * w1 - g23 * w2 + k.weight[2] * s3 + (k.weight_offset + gas * self.bodies.pin_offset) * c3 - k.lateral[2] * c3
                + k.lateral_offset * s3
                - cb3 * piston_pin,
        );
        (mass, force)
    }

    /// The power of the gas force `gas_force` on the crown, W, and the joint damping's dissipation
    /// rate, ≥ 0, W, at the angles `trig` and rates φ̇: the gas and damping terms of
    /// [`Self::inertia_and_force_with`]'s generalized force times φ̇ (the gas's with its sign, the
    /// damping's negated).
    #[inline(always)]
    pub fn gas_and_damping_power(&self, trig: &LinkAngles, phid: &Vector3<f64>, gas_force: f64) -> (f64, f64) {
        let ([s1, s2, _], [_, _, c3]) = (trig.sin, trig.cos);
        let [l1, l2] = self.bodies.links;
        let [cb1, cb2, cb3] = self.bodies.damping;
        let (crank_pin, piston_pin) = (phid[1] - phid[0], phid[2] - phid[1]);
        let gas = gas_force * (l1 * s1 * phid[0] + l2 * s2 * phid[1] + self.bodies.pin_offset * c3 * phid[2]);
        (gas, cb1 * phid[0] * phid[0] + cb2 * crank_pin * crank_pin + cb3 * piston_pin * piston_pin)
    }

    /// Kinetic and gravitational potential energy (zero at the crank axis), J.
    pub fn energy(&self, phi: &Vector3<f64>, phid: &Vector3<f64>) -> (f64, f64) {
        self.energy_with(&LinkAngles::new(phi), phi, phid)
    }

    /// [`Self::energy`] with the angles' sines and cosines `trig` (of `phi`) at hand.
    pub fn energy_with(&self, trig: &LinkAngles, phi: &Vector3<f64>, phid: &Vector3<f64>) -> (f64, f64) {
        let kinetic = self.kinetic_energy(trig, phid);
        // Each angle's directions once (libm's sine and cosine): the centres of mass share them.
        let directions = directions(phi);
        let (g, gx) = (self.bodies.gravity, self.bodies.gravity_lateral);
        let potential = (0..3)
            .map(|k| {
                let r = self.centre_of_mass_in(&directions, k);
                self.bodies.masses[k] * (g * r.y - gx * r.x)
            })
            .sum();
        (kinetic, potential)
    }

    /// The corners' tangential kinematics (module docs): each slips along the liner, +y, at
    /// `ẏ_K = −l1 sin φ1 φ̇1 − l2 sin φ2 φ̇2 + (w cos φ3 − z sin φ3) φ̇3`; friction `λ_T` on a
    /// corner is the liner's force on the piston along +y.
    pub fn tangents(&self, phi: &Vector3<f64>, phid: &Vector3<f64>) -> Tangents<3, 4> {
        let trig = LinkAngles::new(phi);
        let ([s1, s2, s3], [c1, c2, c3]) = (trig.sin, trig.cos);
        let [l1, l2] = self.bodies.links;
        let (w1, w2, w3) = (phid[0] * phid[0], phid[1] * phid[1], phid[2] * phid[2]);
        Tangents {
            jacobian: nalgebra::Matrix4x3::from_fn(|i, j| {
                let (z, w, _) = self.bodies.corners[i];
                [-l1 * s1, -l2 * s2, w * c3 - z * s3][j]
            }),
            time_rate: Vector4::zeros(),
            bias: Vector4::from_fn(|i, _| {
                let (z, w, _) = self.bodies.corners[i];
                -l1 * c1 * w1 - l2 * c2 * w2 - (z * c3 + w * s3) * w3
            }),
        }
    }

    /// Kinetic energy ½ φ̇ᵀ M φ̇ from the angles' sines and cosines, J.
    pub fn kinetic_energy(&self, trig: &LinkAngles, phid: &Vector3<f64>) -> f64 {
        let (mass, _) = self.inertia_and_force_with(trig, phid, Loads { gas_force: 0.0, load_torque: 0.0 });
        0.5 * phid.dot(&(mass * phid))
    }

    /// The piston's kinetic energy of lateral motion and tilt, J: `½ m3 ẋ_c² + ½ J3 φ̇3²` with
    /// `ẋ_c = −l1 cos φ1 φ̇1 − l2 cos φ2 φ̇2 − (e3 cos φ3 + a3 sin φ3) φ̇3` the lateral velocity of its
    /// centre of mass (`e3` along the piston axis from the pin, `a3` across it).
    pub fn lateral_kinetic_energy(&self, trig: &LinkAngles, phid: &Vector3<f64>) -> f64 {
        let b = &self.bodies;
        let ([_, _, s3], [c1, c2, c3]) = (trig.sin, trig.cos);
        let [l1, l2] = b.links;
        let lateral = -l1 * c1 * phid[0] - l2 * c2 * phid[1] - (b.along[2] * c3 + b.across[2] * s3) * phid[2];
        0.5 * (b.masses[2] * lateral * lateral + b.inertias[2] * phid[2] * phid[2])
    }

    /// Each corner's depth below the skirt top (the upper corners' height above the pin), m.
    pub fn corner_depths(&self) -> [f64; 4] {
        let top = self.bodies.corners[0].0;
        self.bodies.corners.map(|(z, _, _)| top - z)
    }

    /// The skirt top's height above the pin along the piston axis, m.
    pub fn pin_depth(&self) -> f64 {
        self.bodies.corners[0].0
    }

    /// Link k's centre of mass (k = 0 crank, 1 rod, 2 piston) from the crank axis, m.
    #[cfg(test)]
    fn centre_of_mass(&self, phi: &Vector3<f64>, k: usize) -> Vector2<f64> {
        self.centre_of_mass_in(&directions(phi), k)
    }

    /// [`Self::centre_of_mass`] from the links' `directions`.
    fn centre_of_mass_in(&self, directions: &[(Vector2<f64>, Vector2<f64>); 3], k: usize) -> Vector2<f64> {
        let joints: Vector2<f64> = (0..k).map(|j| self.bodies.links[j] * directions[j].0).sum();
        joints + self.bodies.along[k] * directions[k].0 + self.bodies.across[k] * directions[k].1
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fmus::piston_slap::mechanisms;
    use crate::fmus::piston_slap::Parameters;

    fn linkage(pin_offset: f64) -> Linkage {
        mechanisms::crank_train::linkage(&Parameters { pin_offset, ..Parameters::default() })
    }

    /// `directions` takes `libm::sincos`, `along` and `across` `libm::sin` and `libm::cos`: the
    /// same bits, tiny, small, reduced, huge and special angles alike.
    #[test]
    fn sincos_gives_the_bits_of_sin_and_cos() {
        let tiny = [1e-300, 5e-324, 1e-9, 1.05e-8, 1.0e-8, 1.4e-8, 1.49e-8, 1.5e-8, 2f64.powi(-26), 2f64.powi(-27) * 2f64.sqrt()];
        let mut angles: Vec<f64> = tiny.iter().flat_map(|&x| [x, -x, x.next_up(), x.next_down()]).collect();
        angles.extend([0.0, -0.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e300, -3e22, std::f64::consts::FRAC_PI_4]);
        let mut x = 0.123_456_789_f64;
        for _ in 0..200_000 {
            // Angles of every size from 1e-12 to 1e6, both signs, by a multiplicative walk.
            x = (x * 1.000_37 + 1e-12) % 1e6;
            angles.extend([x, -x, 1e-6 * x, 4.0 * std::f64::consts::PI * (x / 1e6)]);
        }
        for phi in angles {
            let d = directions(&Vector3::new(phi, phi, phi));
            let (a, n) = (along(phi), across(phi));
            for (u, v) in [(d[0].0, a), (d[0].1, n)] {
                assert_eq!([u.x.to_bits(), u.y.to_bits()], [v.x.to_bits(), v.y.to_bits()], "{phi:e}");
            }
        }
    }

    /// States away from any symmetry, including a tilted piston.
    fn states() -> Vec<(Vector3<f64>, Vector3<f64>)> {
        vec![
            (Vector3::new(0.3, -0.07, 0.002), Vector3::new(125.0, -30.0, 4.0)),
            (Vector3::new(2.1, 0.2, -0.4), Vector3::new(-80.0, 12.0, -9.0)),
            (Vector3::new(-1.2, 0.25, 0.9), Vector3::new(1.0, 2.0, 3.0)),
        ]
    }

    const LOADS: Loads = Loads { gas_force: 3.0e4, load_torque: 24.7 };

    /// The same equations by the generic link loop: `M = Σ m_k J_kᵀ J_k + diag(J_zk)` and
    /// `f = Q − Σ m_k J_kᵀ J̇_k φ̇` from each body's Jacobian columns, the gas force through the
    /// Jacobian of its point, the corner rows from the corner positions. An independent derivation.
    fn by_link_jacobians(
        l: &Linkage,
        phi: &Vector3<f64>,
        phid: &Vector3<f64>,
        loads: Loads,
    ) -> (Matrix3<f64>, Vector3<f64>, nalgebra::Matrix4x3<f64>, Vector4<f64>) {
        let e = [along(phi[0]), along(phi[1]), along(phi[2])];
        let n = [across(phi[0]), across(phi[1]), across(phi[2])];
        let weight = Vector2::new(0.0, -l.bodies.gravity);
        let mut mass = Matrix3::from_diagonal(&Vector3::from(l.bodies.inertias));
        let mut force = Vector3::zeros();
        for k in 0..3 {
            // Columns of J_k and the velocity-product acceleration J̇_k φ̇.
            let mut columns = [Vector2::zeros(); 3];
            let mut bias = Vector2::zeros();
            for j in 0..k {
                columns[j] = -l.bodies.links[j] * n[j];
                bias -= l.bodies.links[j] * phid[j] * phid[j] * e[j];
            }
            let body = l.bodies.along[k] * e[k] + l.bodies.across[k] * n[k];
            columns[k] = -l.bodies.along[k] * n[k] + l.bodies.across[k] * e[k];
            bias -= phid[k] * phid[k] * body;
            let applied = l.bodies.masses[k] * (weight - bias);
            for i in 0..=k {
                force[i] += columns[i].dot(&applied);
                for j in 0..=k {
                    mass[(i, j)] += l.bodies.masses[k] * columns[i].dot(&columns[j]);
                }
            }
        }
        // Gas force (0, −F) at O3 − a n(φ3): J_P columns −l1 n1, −l2 n2, −a e3.
        let gas = Vector2::new(0.0, -loads.gas_force);
        force[0] -= l.bodies.links[0] * n[0].dot(&gas) + loads.load_torque;
        force[1] -= l.bodies.links[1] * n[1].dot(&gas);
        force[2] -= l.bodies.pin_offset * e[2].dot(&gas);
        let [c1, c2, c3] = l.bodies.damping;
        let (crank_pin, piston_pin) = (phid[1] - phid[0], phid[2] - phid[1]);
        force[0] += c2 * crank_pin - c1 * phid[0];
        force[1] += c3 * piston_pin - c2 * crank_pin;
        force[2] -= c3 * piston_pin;
        // Corner K: x_K = x_O3 + z e3.x + w n3.x; ∂x_K/∂φ and the second derivative along φ̇.
        let mut jacobian = nalgebra::Matrix4x3::zeros();
        let mut bias = Vector4::zeros();
        for (i, &(z, w, side)) in l.bodies.corners.iter().enumerate() {
            let tilt = z * e[2] + w * n[2];
            let columns = [l.bodies.links[0] * -n[0].x, l.bodies.links[1] * -n[1].x, -z * n[2].x + w * e[2].x];
            for j in 0..3 {
                jacobian[(i, j)] = side * columns[j];
            }
            let accel = -l.bodies.links[0] * phid[0] * phid[0] * e[0].x
                - l.bodies.links[1] * phid[1] * phid[1] * e[1].x
                - phid[2] * phid[2] * tilt.x;
            bias[i] = side * accel;
        }
        (mass, force, jacobian, bias)
    }

    /// The lateral kinetic energy from the piston's centre of mass moved by central differences
    /// along the motion, with a pin offset (so that the centre lies off the axis).
    #[test]
    fn lateral_kinetic_energy_is_the_piston_centres_lateral_motion_and_its_tilt() {
        let p = Parameters { pin_offset: 0.002, piston_com: 0.013, ..Parameters::default() };
        let l = mechanisms::crank_train::linkage(&p);
        for (phi, phid) in states() {
            let dt = 1e-7;
            let x = |sign: f64| l.centre_of_mass(&(phi + phid * sign * dt), 2).x;
            let lateral = (x(1.0) - x(-1.0)) / (2.0 * dt);
            let expected = 0.5 * (p.piston_mass * lateral * lateral + p.piston_inertia * phid[2] * phid[2]);
            let energy = l.lateral_kinetic_energy(&LinkAngles::new(&phi), &phid);
            assert!((energy - expected).abs() < 1e-8 * expected, "{energy} vs {expected}");
        }
        assert_eq!(l.corner_depths(), [0.0, p.skirt_length, 0.0, p.skirt_length]);
        assert_eq!(l.pin_depth(), p.pin_height);
    }

    #[test]
    fn written_out_equations_match_the_link_jacobians_at_random_states() {
        // A linear congruential generator: reproducible states over whole turns and fast rates.
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut uniform = |lo: f64, hi: f64| {
            seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            lo + (hi - lo) * (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for a in [0.0, 0.002, -0.0035] {
            let l = mechanisms::crank_train::linkage(&Parameters {
                pin_offset: a,
                damping_main: 0.3,
                damping_crank_pin: 0.05,
                damping_piston_pin: 0.02,
                ..Parameters::default()
            });
            for _ in 0..200 {
                let phi = Vector3::new(uniform(-40.0, 40.0), uniform(-0.4, 0.4), uniform(-0.5, 0.5));
                let phid = Vector3::new(uniform(-300.0, 300.0), uniform(-100.0, 100.0), uniform(-50.0, 50.0));
                let loads = Loads { gas_force: uniform(0.0, 4e4), load_torque: uniform(-50.0, 50.0) };
                let ev = l.evaluate(&phi, &phid, loads);
                let (mass, force, jacobian, bias) = by_link_jacobians(&l, &phi, &phid, loads);
                let close = |x: f64, reference: f64, scale: f64| (x - reference).abs() <= 1e-12 * scale;
                assert!(ev.mass.iter().zip(mass.iter()).all(|(x, r)| close(*x, *r, mass.norm())), "M {} vs {mass}", ev.mass);
                assert!(ev.force.iter().zip(force.iter()).all(|(x, r)| close(*x, *r, force.norm())), "f {} vs {force}", ev.force);
                assert!(
                    ev.gap_jacobian.iter().zip(jacobian.iter()).all(|(x, r)| close(*x, *r, jacobian.norm())),
                    "J {} vs {jacobian}",
                    ev.gap_jacobian
                );
                assert!(ev.gap_bias.iter().zip(bias.iter()).all(|(x, r)| close(*x, *r, bias.norm())), "d {} vs {bias}", ev.gap_bias);
                // The corners' gaps from their positions.
                let pin = l.pin(&phi);
                let expected = Vector4::from_fn(|i, _| {
                    let (z, w, side) = l.bodies.corners[i];
                    0.5 * l.bodies.bore + side * (pin.x + z * along(phi[2]).x + w * across(phi[2]).x)
                });
                assert!((ev.gap - expected).norm() < 1e-15, "h {} vs {expected}", ev.gap);
                assert_eq!(ev.gap, l.gaps(&phi));
            }
        }
    }

    /// Kinetic energy from finite differences of the body positions: independent of M.
    fn kinetic_by_differences(l: &Linkage, phi: &Vector3<f64>, phid: &Vector3<f64>) -> f64 {
        let dt = 1e-6;
        (0..3)
            .map(|k| {
                let v = (l.centre_of_mass(&(phi + phid * dt), k) - l.centre_of_mass(&(phi - phid * dt), k)) / (2.0 * dt);
                0.5 * (l.bodies.masses[k] * v.norm_squared() + l.bodies.inertias[k] * phid[k] * phid[k])
            })
            .sum()
    }

    #[test]
    fn mass_matrix_is_symmetric_positive_definite_and_matches_the_kinetic_energy() {
        for a in [0.0, 0.002] {
            let l = linkage(a);
            for (phi, phid) in states() {
                let m = l.evaluate(&phi, &phid, LOADS).mass;
                assert!((m - m.transpose()).norm() < 1e-15);
                assert!(m.symmetric_eigenvalues().min() > 0.0);
                // T is quadratic in φ̇: M_ij by polarization of T from positions.
                let unit = |i: usize| Vector3::from_fn(|r, _| if r == i { 1.0 } else { 0.0 });
                for i in 0..3 {
                    for j in 0..3 {
                        let t = |v: Vector3<f64>| kinetic_by_differences(&l, &phi, &v);
                        let mij = t(unit(i) + unit(j)) - t(unit(i)) - t(unit(j));
                        assert!((mij - m[(i, j)]).abs() < 1e-8 * m.norm(), "M[{i},{j}] {mij} vs {}", m[(i, j)]);
                    }
                }
            }
        }
    }

    /// f from Lagrange's equations by finite differences: f = Q_nc − ∂V/∂φ − (∂(Mφ̇)/∂φ) φ̇ + ∂T/∂φ.
    #[test]
    fn force_matches_lagrange_equations_by_finite_differences() {
        let eps = 1e-6;
        for a in [0.0, 0.002] {
            let l = linkage(a);
            for (phi, phid) in states() {
                let free = Loads { gas_force: 0.0, load_torque: 0.0 };
                let mass_at = |p: &Vector3<f64>| l.evaluate(p, &phid, free).mass;
                let dp = (mass_at(&(phi + phid * eps)) - mass_at(&(phi - phid * eps))) * phid / (2.0 * eps);
                let mut lagrange = -dp;
                for i in 0..3 {
                    let step = Vector3::from_fn(|r, _| if r == i { eps } else { 0.0 });
                    let (kp, vp) = l.energy(&(phi + step), &phid);
                    let (km, vm) = l.energy(&(phi - step), &phid);
                    lagrange[i] += (kp - km - (vp - vm)) / (2.0 * eps);
                }
                // Non-conservative forces: virtual work of damping, gas and load, written out directly.
                let [c1, c2, c3] = l.bodies.damping;
                let damping = Vector3::new(
                    -c1 * phid[0] + c2 * (phid[1] - phid[0]),
                    -c2 * (phid[1] - phid[0]) + c3 * (phid[2] - phid[1]),
                    -c3 * (phid[2] - phid[1]),
                );
                let gas_point = |p: &Vector3<f64>| l.pin(p).y - a * libm::sin(p[2]);
                let gas = Vector3::from_fn(|i, _| {
                    let step = Vector3::from_fn(|r, _| if r == i { eps } else { 0.0 });
                    -LOADS.gas_force * (gas_point(&(phi + step)) - gas_point(&(phi - step))) / (2.0 * eps)
                });
                let expected = lagrange + damping + gas - Vector3::new(LOADS.load_torque, 0.0, 0.0);
                let f = l.evaluate(&phi, &phid, LOADS).force;
                assert!((f - expected).norm() < 1e-6 * f.norm().max(1.0), "f {f} vs {expected}");
            }
        }
    }

    #[test]
    fn matches_the_printed_triple_pendulum_for_zero_pin_offset() {
        // A&K eqs 22b, 24, 32–34 in physical units (multiplied back by M1).
        let p = Parameters::default();
        let l = linkage(0.0);
        let (m1, m2, m3) = (p.crank_mass, p.rod_mass, p.piston_mass);
        let (l1, l2, e1, e2, e3, g) = (p.crank_radius, p.rod_length, p.crank_com, p.rod_com, p.piston_com, p.gravity);
        let b = [
            p.crank_inertia + e1 * e1 * m1 + l1 * l1 * (m2 + m3),
            p.rod_inertia + e2 * e2 * m2 + l2 * l2 * m3,
            p.piston_inertia + e3 * e3 * m3,
        ];
        let (n12, n13, n23) = (m2 * e2 * l1 + m3 * l1 * l2, m3 * e3 * l1, m3 * e3 * l2);
        let big_m = [m1 * g * e1 + (m2 + m3) * g * l1, m2 * g * e2 + m3 * g * l2, m3 * g * e3];
        let (c1, c2, c3) = (p.damping_main, p.damping_crank_pin, p.damping_piston_pin);
        let damping = Matrix3::new(c1 + c2, -c2, 0.0, -c2, c2 + c3, -c3, 0.0, -c3, c3);
        for (phi, phid) in states() {
            let c = |i: usize, j: usize| libm::cos(phi[i] - phi[j]);
            let s = |i: usize, j: usize| libm::sin(phi[i] - phi[j]);
            let mass =
                Matrix3::new(b[0], n12 * c(0, 1), n13 * c(0, 2), n12 * c(0, 1), b[1], n23 * c(1, 2), n13 * c(0, 2), n23 * c(1, 2), b[2]);
            let gyro =
                Matrix3::new(0.0, n12 * s(0, 1), n13 * s(0, 2), -n12 * s(0, 1), 0.0, n23 * s(1, 2), -n13 * s(0, 2), -n23 * s(1, 2), 0.0);
            let squares = phid.component_mul(&phid);
            let restoring = -Vector3::new(big_m[0] * libm::sin(phi[0]), big_m[1] * libm::sin(phi[1]), big_m[2] * libm::sin(phi[2]));
            let f_e =
                Vector3::new(LOADS.gas_force * l1 * libm::sin(phi[0]) - LOADS.load_torque, LOADS.gas_force * l2 * libm::sin(phi[1]), 0.0);
            let printed_force = f_e - gyro * squares - damping * phid - restoring;
            let ev = l.evaluate(&phi, &phid, LOADS);
            assert!((ev.mass - mass).norm() < 1e-14);
            assert!((ev.force - printed_force).norm() < 1e-9 * printed_force.norm());
            // Eq 28 times l1.
            let (d, big_d, h, sk) = (p.piston_diameter, p.bore, p.pin_height, p.skirt_length);
            let common = l1 * libm::sin(phi[0]) + l2 * libm::sin(phi[1]);
            let printed_gaps = Vector4::new(
                big_d / 2.0 - common - h * libm::sin(phi[2]) - d / 2.0 * libm::cos(phi[2]),
                big_d / 2.0 - common + (sk - h) * libm::sin(phi[2]) - d / 2.0 * libm::cos(phi[2]),
                big_d / 2.0 + common + h * libm::sin(phi[2]) - d / 2.0 * libm::cos(phi[2]),
                big_d / 2.0 + common - (sk - h) * libm::sin(phi[2]) - d / 2.0 * libm::cos(phi[2]),
            );
            assert!((ev.gap - printed_gaps).norm() < 1e-15);
        }
    }

    #[test]
    fn gap_jacobian_and_bias_match_finite_differences() {
        let eps = 1e-5;
        for a in [0.0, 0.002] {
            let l = linkage(a);
            for (phi, phid) in states() {
                let ev = l.evaluate(&phi, &phid, LOADS);
                for i in 0..3 {
                    let step = Vector3::from_fn(|r, _| if r == i { eps } else { 0.0 });
                    let column = (l.gaps(&(phi + step)) - l.gaps(&(phi - step))) / (2.0 * eps);
                    assert!((column - ev.gap_jacobian.column(i)).norm() < 1e-9);
                }
                // d = d²/dτ² h(φ + φ̇ τ) at τ = 0.
                let tau = 1e-4 / phid.norm();
                let second = (l.gaps(&(phi + phid * tau)) - 2.0 * l.gaps(&phi) + l.gaps(&(phi - phid * tau))) / (tau * tau);
                assert!((second - ev.gap_bias).norm() < 1e-5 * ev.gap_bias.norm().max(1.0), "{second} vs {}", ev.gap_bias);
            }
        }
    }
}
