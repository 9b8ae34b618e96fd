//! The skirt's geometry against the crank train's corners, its symmetry and signs, the damping against
//! finite differences of the loads, the film's power balance, and its grid convergence.

use super::{Skirt, SkirtDesign, SkirtMotion, SkirtProfile};
use std::time::Instant;

/// The crank train's default geometry (DESIGN.md §4: D = 80.08 mm, d = 80 mm, skirt 80 mm, pin 40 mm
/// below its top) with a 70° arc per side, hot oil of 10 mPa·s and a 20/10 µm barrel.
fn design(grid: (usize, usize)) -> SkirtDesign {
    let mut d = SkirtDesign::new(0.04004, 0.04, 0.08, 0.04, 0.0, 70f64.to_radians(), 0.01);
    d.profile = SkirtProfile::Parabola { top_drop: 20e-6, bottom_drop: 10e-6 };
    d.grid = grid;
    d
}

/// Mid-stroke, pressed toward the thrust side, tilting and sliding up.
const MOTION: SkirtMotion = SkirtMotion { lateral: 25e-6, tilt: 2e-4, lateral_rate: 0.02, tilt_rate: -0.5, sliding_speed: 10.0 };

#[test]
fn probe() {
    for g in [(8, 12), (12, 18), (16, 24), (24, 36), (32, 48), (64, 96)] {
        let skirt = Skirt::new(design(g)).unwrap();
        let start = Instant::now();
        let l = skirt.loads(&MOTION);
        let t = start.elapsed().as_secs_f64();
        println!(
            "{g:?} {:.2} us  F {:.6} M {:.6} fric {:.6} shear {:.4} sq {:.4} D {:.5e} {:.5e} {:.5e} min {:?}",
            t * 1e6,
            l.lateral_force,
            l.moment,
            l.friction_force,
            l.shear_power,
            l.squeeze_power,
            l.damping[(0, 0)],
            l.damping[(0, 1)],
            l.damping[(1, 1)],
            l.min_film
        );
    }
}
