//! The crank train's declared space: the designs in which its model is well posed, refused outside
//! with the parameter and the reason (the FMU documentation, "Declared space", states the same).

use super::Parameters;
use crate::models::crank_train::kinematics::SliderCrank;
use crate::models::crank_train::linkage::{Linkage, Loads};
use crate::models::{check, ModelError};
use nalgebra::{DMatrix, Vector3};
use std::f64::consts::PI;

/// Smallest rod ratio `rod_length / (crank_radius + |pin_offset|)`: the rod then swings at most
/// 41.8° off the cylinder axis. Engines have 2.8–4.5, the Flores slider 2; towards 1 the rod's rate
/// and acceleration grow as 1/cos φ2 and 1/cos³ φ2 and two corners' constraint gradients become
/// dependent (runs at ratios 1.03–1.3 failed so, at 1.01 the corners left the bore by 11 µm).
pub const MIN_ROD_RATIO: f64 = 1.5;

/// Smallest radial clearance `(bore − piston_diameter)/2`, m: 10⁴ times the depth the event search
/// may leave a corner in the liner (100 ε_h = 1e-10 m); a clearance of 1e-9 m ended in a multiple-
/// impact exception, and a bore of d (1 + 1e-15) is below the round-off of the corner positions.
pub const MIN_CLEARANCE: f64 = 1e-6;

/// Largest ratio of any two of the three link masses: beyond it the inertia matrix of the linkage
/// is too ill-conditioned for its state to stay finite (a 1.3 g piston on a 15.7 kg rod failed so).
pub const MAX_MASS_RATIO: f64 = 1e3;

/// Bounds on each link's radius of gyration about its centre of mass, √(J/m), as multiples of its
/// length (piston: `piston_diameter`, rod: `rod_length`, crank: `crank_radius`). Below: a link's
/// mass spans its length (the crown its diameter, the rod its two eyes, the crank its journal and
/// pin), so none of them has its mass within 5 % of that length of one point (the presets' smallest
/// is the Flores slider's piston, 0.12). Such links made the slipping contact problem inconsistent
/// off-centre, and a piston of 0.001 × d broke the event tolerances. Above: a piston's mass and a
/// rod's lie within their length of their centre of mass, so √(J/m) cannot exceed it (the defaults
/// have 0.63 and 0.58); the crank's bound is larger, for a flywheel on the shaft.
const GYRATION: [(f64, f64); 3] = [(0.05, 1.0), (0.05, 1.0), (0.05, 100.0)];

/// Bounds on `piston_mass / piston_diameter³`, kg/m³. Below: a piston carries the gas load on its
/// crown, which weighs at least as much as an aluminium disc a fiftieth of the diameter thick (42 d³;
/// a 22 g piston of 1 m under 94 bar spun a free crank to 10⁶ rad/s). Above: no piston outweighs a
/// solid tungsten cylinder as long as its diameter (15 000 d³; a 49 kg piston of 38 mm was drawn).
/// The presets have 600–1000.
pub const PISTON_DENSITY: (f64, f64) = (40.0, 15_000.0);

/// Crank angles over one revolution at which the contact problem's consistency is checked.
const ANGLES: usize = 720;

/// Refuses parameters the crank train cannot run with, naming the parameter: the ranges every
/// model needs (`Parameters::validate`), then what the corner geometry and the linkage need.
/// Perfectly elastic impacts with friction on a prescribed crank are refused: a random declared
/// design (e = 1, μ = 0.72) rattled from 0.3 to 2600 m/s in 0.05 s; below e = 1 the impacts' normal
/// loss, growing as the square of the speed, bounds what the drive feeds in proportion to it (the
/// same design: 0.14 m/s at e = 0.99, 2000 m/s at 0.999, and it runs).
pub fn validate(p: &Parameters) -> Result<(), ModelError> {
    p.validate()?;
    check(p.skirt_length > 0.0, || format!("skirt_length ({} m) must be positive: the corners K2, K4 lie at its end", p.skirt_length))?;
    // The corner description (A&K eq 26) holds while the piston cannot turn across the bore.
    let diagonal = libm::hypot(p.piston_diameter, p.skirt_length);
    check(p.bore < diagonal, || {
        format!("bore ({} m) must be below the piston diagonal √(piston_diameter² + skirt_length²) ({diagonal} m)", p.bore)
    })?;
    let clearance = 0.5 * (p.bore - p.piston_diameter);
    check(clearance >= MIN_CLEARANCE, || {
        format!(
            "bore ({} m) must exceed piston_diameter ({} m) by 2 × {MIN_CLEARANCE} m: a diametral clearance c = bore − \
             piston_diameter of {:e} m is below what the event search resolves",
            p.bore,
            p.piston_diameter,
            2.0 * clearance
        )
    })?;
    check(p.pin_offset.abs() < 0.5 * p.piston_diameter, || {
        format!("pin_offset ({} m) must be smaller than piston_diameter/2 ({} m)", p.pin_offset, 0.5 * p.piston_diameter)
    })?;
    let reach = p.crank_radius + p.pin_offset.abs();
    check(p.rod_length >= MIN_ROD_RATIO * reach, || {
        format!(
            "rod_length ({} m) must be at least {MIN_ROD_RATIO} × (crank_radius + |pin_offset|) ({} m): a shorter rod swings so \
             far off the axis that the corner constraints become dependent",
            p.rod_length,
            MIN_ROD_RATIO * reach
        )
    })?;
    check(!(p.crank_mode == 1 && p.friction > 0.0 && p.restitution == 1.0), || {
        format!(
            "restitution = 1 with friction ({}) on a prescribed crank (crank_mode = 1): no impact then loses normal energy, \
             while each impact's friction impulse draws work from the drive, which holds its speed whatever it gives, so a \
             rattle can grow without bound; give restitution below 1 or a free crank",
            p.friction
        )
    })?;
    plausible_links(p)
}

/// The masses within `MAX_MASS_RATIO` of each other, the radii of gyration within `GYRATION`, the
/// piston's within `PISTON_DENSITY`.
fn plausible_links(p: &Parameters) -> Result<(), ModelError> {
    let links = [
        ("piston", p.piston_mass, p.piston_inertia, p.piston_diameter, "piston_diameter"),
        ("rod", p.rod_mass, p.rod_inertia, p.rod_length, "rod_length"),
        ("crank", p.crank_mass, p.crank_inertia, p.crank_radius, "crank_radius"),
    ];
    let (lightest, heaviest) =
        links.iter().fold((links[0], links[0]), |(lo, hi), &l| (if l.1 < lo.1 { l } else { lo }, if l.1 > hi.1 { l } else { hi }));
    check(heaviest.1 <= MAX_MASS_RATIO * lightest.1, || {
        format!(
            "{}_mass ({} kg) and {}_mass ({} kg) differ by more than a factor {MAX_MASS_RATIO}: the linkage's inertia matrix is \
             then too ill-conditioned to integrate",
            heaviest.0, heaviest.1, lightest.0, lightest.1
        )
    })?;
    for ((name, mass, inertia, length, length_name), (lo, hi)) in links.into_iter().zip(GYRATION) {
        let gyration = (inertia / mass).sqrt();
        check((lo * length..=hi * length).contains(&gyration), || {
            format!(
                "{name}_inertia ({inertia} kg·m²) gives the {name} a radius of gyration √(J/m) = {gyration:e} m outside [{lo}, {hi}] \
                 × {length_name} ({length} m): no {name} of that size has it"
            )
        })?;
    }
    let cube = p.piston_diameter.powi(3);
    let (least, most) = (PISTON_DENSITY.0 * cube, PISTON_DENSITY.1 * cube);
    check((least..=most).contains(&p.piston_mass), || {
        format!(
            "piston_mass ({} kg) must lie within [{}, {}] kg/m³ × piston_diameter³ ([{least}, {most}] kg): a piston's crown, \
             which carries the gas load, weighs more, and a solid tungsten cylinder as long as its diameter less",
            p.piston_mass, PISTON_DENSITY.0, PISTON_DENSITY.1
        )
    })?;
    Ok(())
}

/// Refuses a `friction` above the design's critical coefficient: where the corners slip, Coulomb
/// friction and unilateral contact admit a unique non-negative contact force on every closed set
/// only while `W_N − μ W_NT S` is a P-matrix (every sign pattern S of the slips) — above, the
/// sliding problem of some set has no solution or several (Painlevé's paradox). The FMU refuses
/// such a design rather than change the law: the consistent alternative, an impact without
/// collision (Génot & Brogliato), would make the piston jump where the papers' model slides, and
/// the critical μ of real pistons lies far above the liner's friction. Checked over a revolution
/// (`ANGLES`) with the piston centred and untilted and in each of its touching poses (the vertices
/// of the region its clearance leaves it: centred alone missed one slipping corner's inconsistency
/// off-centre), for single corners, a wall's pair and the diagonal pairs; `W` in the coordinates
/// the crank mode leaves free.
pub fn consistent_friction(linkage: &Linkage, p: &Parameters) -> Result<(), ModelError> {
    if p.friction == 0.0 || inconsistency(linkage, p, p.friction).is_none() {
        return Ok(());
    }
    // The largest μ that passes, by bisection (the failing set grows with μ).
    let (mut lo, mut hi) = (0.0, p.friction);
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if inconsistency(linkage, p, mid).is_none() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let angle = inconsistency(linkage, p, p.friction).unwrap_or_default();
    Err(ModelError(format!(
        "friction ({}) exceeds this design's critical coefficient {lo:.4}: above it, at crank angle {:.1}°, the sliding corners' \
         contact forces have no unique non-negative solution (Painlevé's paradox of Coulomb friction)",
        p.friction,
        angle.to_degrees()
    )))
}

/// The first crank angle at which the slipping contact problem at `mu` is not a P-matrix, with the
/// piston centred or in one of its touching poses (`Linkage::touching_poses`), if any.
fn inconsistency(linkage: &Linkage, p: &Parameters, mu: f64) -> Option<f64> {
    let geometry = SliderCrank { crank_radius: p.crank_radius, rod_length: p.rod_length, pin_offset: p.pin_offset };
    let free = if p.crank_mode == 1 { 1 } else { 0 };
    (0..ANGLES).map(|k| 2.0 * PI * k as f64 / ANGLES as f64).find(|&angle| {
        let centred = Vector3::new(angle, geometry.at(angle).rod_angle, 0.0);
        std::iter::once(centred).chain(linkage.touching_poses(angle)).any(|phi| inconsistent_at(linkage, &phi, free, mu))
    })
}

/// Whether the slipping contact problem at pose `phi` and `mu` fails to be a P-matrix for some set
/// and sign pattern; the first `free` coordinates are the ones the crank mode prescribes.
fn inconsistent_at(linkage: &Linkage, phi: &Vector3<f64>, free: usize, mu: f64) -> bool {
    let sets: [&[usize]; 8] = [&[0], &[1], &[2], &[3], &[0, 1], &[2, 3], &[0, 3], &[1, 2]];
    let ev = linkage.evaluate(phi, &Vector3::zeros(), Loads { gas_force: 0.0, load_torque: 0.0 });
    let tangents = linkage.tangents(phi, &Vector3::zeros());
    let n = 3 - free;
    let mass = DMatrix::from_fn(n, n, |i, j| ev.mass[(i + free, j + free)]);
    let normal = DMatrix::from_fn(4, n, |i, j| ev.gap_jacobian[(i, j + free)]);
    let tangent = DMatrix::from_fn(4, n, |i, j| tangents.jacobian[(i, j + free)]);
    let Some(inverse) = mass.try_inverse() else { return true };
    let (w, t) = (&normal * &inverse * normal.transpose(), &normal * &inverse * tangent.transpose());
    sets.iter().any(|set| {
        (0..1 << set.len()).any(|signs: usize| {
            let a = |r: usize, c: usize| {
                let s = if signs >> c & 1 == 1 { -1.0 } else { 1.0 };
                w[(set[r], set[c])] - mu * s * t[(set[r], set[c])]
            };
            match set.len() {
                1 => a(0, 0) <= 0.0,
                _ => a(0, 0) <= 0.0 || a(1, 1) <= 0.0 || a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0) <= 0.0,
            }
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The default piston has four touching poses at every crank angle: flat against either wall
    /// and tilted across either diagonal, each with two corners on the liner and the other two about
    /// the diametral clearance 2c off it.
    #[test]
    fn touching_poses_put_two_corners_on_the_liner_and_none_outside() {
        let p = Parameters::default();
        let linkage = super::super::crank_train::linkage(&p);
        let clearance = 0.5 * (p.bore - p.piston_diameter);
        for angle in [0.0, 0.7, 2.0, PI, 4.5] {
            let poses = linkage.touching_poses(angle);
            let touching: Vec<Vec<usize>> =
                poses.iter().map(|pose| (0..4).filter(|&i| linkage.gaps(pose)[i] < 1e-12 * p.bore).collect()).collect();
            assert_eq!(touching, [vec![0, 1], vec![0, 3], vec![1, 2], vec![2, 3]], "at {angle} rad");
            for pose in &poses {
                let gaps = linkage.gaps(pose);
                // A tilted piston's projection is narrower: the free corners lie up to 1e-3 beyond 2c.
                assert!(gaps.min() > -1e-15 && gaps.max() < 2.0 * clearance * 1.001, "at {angle} rad: {gaps:?}");
            }
        }
    }
}
