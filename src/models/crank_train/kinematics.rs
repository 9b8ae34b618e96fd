//! Exact kinematics of the rigid (zero-clearance) slider crank with a wrist-pin offset.
//!
//! Angles as in A&K eq 25 and ARCHITECTURE.md §3: each link's direction is `(−sin φ, cos φ)`, so
//! `x_O3 = −l1 sin φ1 − l2 sin φ2`, `y_O3 = l1 cos φ1 + l2 cos φ2` (A&K eq 57 times l1) and φ1 = 0 is
//! top dead centre. With the piston centred and untilted the pin runs on the line `x_O3 = a`
//! (`a` = pin offset), hence `sin φ2 = −(a + l1 sin φ1)/l2`.

use serde::{Deserialize, Serialize};

/// Crank radius `l1`, rod length `l2` and pin offset `a` of a slider crank, in metres.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SliderCrank {
    /// l1.
    pub crank_radius: f64,
    /// l2.
    pub rod_length: f64,
    /// a, the pin's lateral offset from the crank axis' line.
    pub pin_offset: f64,
}

/// Rod angle and pin position, with their first and second derivatives with respect to φ1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SliderCrankState {
    /// φ2.
    pub rod_angle: f64,
    /// dφ2/dφ1.
    pub rod_rate: f64,
    /// d²φ2/dφ1².
    pub rod_curvature: f64,
    /// y_O3, m.
    pub pin_axial: f64,
    /// dy_O3/dφ1, m/rad.
    pub pin_axial_rate: f64,
}

impl SliderCrank {
    /// The state at crank angle φ1; requires `l1 + |a| < l2` (checked where parameters are accepted).
    pub fn at(&self, crank_angle: f64) -> SliderCrankState {
        let (l1, l2, a) = (self.crank_radius, self.rod_length, self.pin_offset);
        let (s1, c1) = libm::sincos(crank_angle);
        // l2 sin φ2 = −(a + l1 sin φ1), differentiated once and twice in φ1.
        let s2 = -(a + l1 * s1) / l2;
        let c2 = (1.0 - s2 * s2).sqrt();
        let rod_rate = -l1 * c1 / (l2 * c2);
        // l2 (cos φ2 φ2'' − sin φ2 φ2'²) = l1 sin φ1.
        let rod_curvature = (l1 * s1 + l2 * s2 * rod_rate * rod_rate) / (l2 * c2);
        SliderCrankState {
            rod_angle: libm::asin(s2),
            rod_rate,
            rod_curvature,
            pin_axial: l1 * c1 + l2 * c2,
            pin_axial_rate: -l1 * s1 - l2 * s2 * rod_rate,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const GEOMETRY: SliderCrank = SliderCrank { crank_radius: 0.04, rod_length: 0.15, pin_offset: 0.003 };

    #[test]
    fn pin_stays_on_its_line_and_derivatives_match_differences() {
        let step = 1e-5;
        for k in 0..50 {
            let phi = -7.0 + 0.29 * k as f64;
            let s = GEOMETRY.at(phi);
            let x_pin = -0.04 * libm::sin(phi) - 0.15 * libm::sin(s.rod_angle);
            assert!((x_pin - 0.003).abs() < 1e-15, "x_O3 = {x_pin}");
            let (plus, minus) = (GEOMETRY.at(phi + step), GEOMETRY.at(phi - step));
            let rate = (plus.rod_angle - minus.rod_angle) / (2.0 * step);
            let curvature = (plus.rod_rate - minus.rod_rate) / (2.0 * step);
            let axial_rate = (plus.pin_axial - minus.pin_axial) / (2.0 * step);
            assert!((rate - s.rod_rate).abs() < 1e-8);
            assert!((curvature - s.rod_curvature).abs() < 1e-7);
            assert!((axial_rate - s.pin_axial_rate).abs() < 1e-9);
        }
    }

    #[test]
    fn stroke_without_offset_is_twice_the_crank_radius() {
        let centred = SliderCrank { pin_offset: 0.0, ..GEOMETRY };
        let (top, bottom) = (centred.at(0.0), centred.at(std::f64::consts::PI));
        assert!((top.pin_axial - 0.19).abs() < 1e-15);
        assert!((bottom.pin_axial - 0.11).abs() < 1e-15);
    }
}
