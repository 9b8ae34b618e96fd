//! The built-in shell's compliance against the closed forms of its two limits.

use super::shell::{Cells, Points, ShellPanel, POISSON};

/// A panel's deflection at its centre per unit force spread over a centred cell of the given widths.
fn centre(panel: &ShellPanel, width: (f64, f64), modes: (usize, usize)) -> f64 {
    let (x, y) = ([0.5 * panel.axial], [0.5 * panel.around]);
    let points = Points { axial: &x, around: &y };
    let cells = Cells { axial: &x, around: &y, width };
    panel.compliance(&points, &cells, modes)[0]
}

#[test]
fn a_flat_panel_is_navier_s_simply_supported_plate() {
    // Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells (2nd ed.), simply supported square
    // plate of side a: a central point load P deflects its centre by 0.01160 P a²/D (Table 23), a
    // uniform load q by 0.00406 q a⁴/D (Table 8).
    let plate = ShellPanel { axial: 0.2, around: 0.2, radius: f64::INFINITY, thickness: 2e-3, modulus: 70e9, poisson: POISSON };
    let (a, d) = (plate.axial, plate.rigidity());
    let point = centre(&plate, (a * 1e-4, a * 1e-4), (400, 400)) * d / (a * a);
    assert!((point / 0.01160 - 1.0).abs() < 0.01, "point load: {point} P a²/D");
    let uniform = centre(&plate, (a, a), (60, 60)) * d * a * a / a.powi(4);
    assert!((uniform / 0.00406 - 1.0).abs() < 0.005, "uniform load: {uniform} q a⁴/D");
}

#[test]
fn a_ring_load_on_a_long_wide_panel_is_the_cylinder_s() {
    // Young & Budynas, Roark's Formulas for Stress and Strain (7th ed.), Table 13.2 case 15 (after
    // Hetényi, Beams on Elastic Foundation): a long thin cylinder under a radial line load w (N/m)
    // round a circumference deflects by w R² λ / (2 E t) under it, λ⁴ = 3 (1 − ν²) / (R² t²). A panel
    // many decay lengths 1/λ long and wide, the load a narrow band across its whole width, is that
    // cylinder at its centre; the width takes the longer of the two (the edges round the panel reach
    // farther: at 40/λ wide the centre deflects 0.16 of the cylinder's, at 200/λ to 1e-4).
    let (radius, thickness, modulus) = (0.1, 2e-3, 70e9);
    let lambda = libm::pow(3.0 * (1.0 - POISSON * POISSON) / (radius * radius * thickness * thickness), 0.25);
    let (length, span) = (40.0 / lambda, 200.0 / lambda);
    let panel = ShellPanel { axial: length, around: span, radius, thickness, modulus, poisson: POISSON };
    let width = (0.02 / lambda, span);
    // A force F over the band is a line load F / span.
    let w = centre(&panel, width, (400, 2000)) * span;
    let roark = radius * radius * lambda / (2.0 * modulus * thickness);
    assert!((w / roark - 1.0).abs() < 0.02, "ring load: {w:e} m per N/m against {roark:e}");
}
