//! The elastic skirt: the stiff limit is the rigid film, a soft skirt spreads the same load over a
//! wider area at a lower peak, and a compliance matrix from a file deflects the skirt as its numbers
//! say, or is refused by a clear message.

use super::{read_matrix, Compliance, FilmLinear, Skirt, SkirtDesign, SkirtMotion, SkirtProfile};

/// The default engine's skirt (D = 80.08 mm, d = 80 mm, skirt 80 mm, pin 40 mm below its top, 70° per
/// side, a 20/10 µm barrel) with the given compliance.
fn skirt(compliance: Compliance) -> Skirt {
    let mut d = SkirtDesign::new(0.04004, 0.04, 0.08, 0.04, 0.0, 70f64.to_radians(), 0.0088);
    d.profile = SkirtProfile::Parabola { top_drop: 20e-6, bottom_drop: 10e-6 };
    d.compliance = compliance;
    Skirt::new(d).expect("valid design")
}

/// Mid-stroke, pressed toward the thrust side, tilting and sliding up.
const MOTION: SkirtMotion = SkirtMotion { lateral: 20e-6, tilt: 5e-5, lateral_rate: 2e-3, tilt_rate: -0.05, sliding_speed: 10.0 };

/// The thrust side's pressure at the solve's own rates (its map), Pa.
fn pressures(skirt: &Skirt, linear: &FilmLinear) -> Vec<f64> {
    skirt.pressure_map(linear, &linear.at).sides[0].pressure.clone()
}

#[test]
fn a_very_stiff_skirt_is_the_rigid_one() {
    let rigid = skirt(Compliance::Rigid);
    let stiff = skirt(Compliance::Shell { thickness: 3e-3, modulus: 1e30 });
    let (a, b) = (rigid.linearise(&MOTION), stiff.linearise(&MOTION));
    assert_eq!(a.free, b.free);
    let error = (a.gram - b.gram).amax() / a.gram.amax();
    assert!(error < 1e-12, "Γ: {error:e}");
    assert!((a.peak_pressure - b.peak_pressure).abs() < 1e-12 * a.peak_pressure);
    let (la, lb) = (rigid.loads(&MOTION), stiff.loads(&MOTION));
    for (x, y) in [(la.lateral_force, lb.lateral_force), (la.friction_force, lb.friction_force), (la.min_film[0], lb.min_film[0])] {
        assert!((x - y).abs() <= 1e-12 * x.abs(), "{x} against {y}");
    }
}

#[test]
fn a_soft_skirt_carries_the_same_load_wider_at_a_lower_peak() {
    // The same lateral film force on a rigid and on a soft skirt (3 mm of Al–Si; its squeeze rate
    // found by secant): the soft skirt's peak pressure is lower and more of its area carries more than
    // a tenth of its peak (measured at 6.3 kN: 5.26 → 2.66 MPa, 166 → 216 of 216 nodes, 98 µm of
    // deflection).
    let rigid = skirt(Compliance::Rigid);
    let soft = skirt(Compliance::Shell { thickness: 3e-3, modulus: 70e9 });
    let force = |s: &Skirt, rate: f64| {
        let motion = SkirtMotion { lateral_rate: rate, ..MOTION };
        let linear = s.linearise(&motion);
        (s.loads_with(&linear, &motion).film_force, linear)
    };
    let (target, stiff) = force(&rigid, MOTION.lateral_rate);
    let (mut r0, mut r1) = (MOTION.lateral_rate, 2.0 * MOTION.lateral_rate);
    let (mut f0, mut f1) = (force(&soft, r0).0, force(&soft, r1).0);
    for _ in 0..30 {
        if (f1 - target).abs() < 1e-4 * target.abs() {
            break;
        }
        let r2 = r1 + (target - f1) * (r1 - r0) / (f1 - f0);
        (r0, f0, r1) = (r1, f1, r2);
        f1 = force(&soft, r1).0;
    }
    let (load, elastic) = force(&soft, r1);
    assert!((load - target).abs() < 1e-3 * target.abs(), "load {load} against {target}");
    let (p_rigid, p_soft) = (pressures(&rigid, &stiff), pressures(&soft, &elastic));
    let peak = |p: &[f64]| p.iter().fold(0.0_f64, |m, &v| m.max(v));
    let loaded = |p: &[f64]| p.iter().filter(|&&v| v > 0.1 * peak(p)).count();
    let deflection = elastic.deflection[0].iter().fold(0.0_f64, |m, &d| m.max(d));
    eprintln!(
        "load {target:.1} N: peak {:.3e} → {:.3e} Pa, loaded nodes {} → {}, deflection {deflection:e} m, steps {:?}, min film {:?} → {:?}",
        peak(&p_rigid),
        peak(&p_soft),
        loaded(&p_rigid),
        loaded(&p_soft),
        elastic.factorisations,
        rigid.loads_with(&stiff, &stiff.at).min_film,
        soft.loads_with(&elastic, &elastic.at).min_film,
    );
    assert!(peak(&p_soft) < 0.9 * peak(&p_rigid));
    assert!(loaded(&p_soft) > loaded(&p_rigid));
    assert!(deflection > 0.0);
}

/// A compliance file in the system's temporary folder, removed when dropped.
struct TempFile(std::path::PathBuf);

impl TempFile {
    fn new(name: &str, text: &str) -> Self {
        let path = std::env::temp_dir().join(format!("pistonslap_{}_{name}", std::process::id()));
        std::fs::write(&path, text).expect("a temporary file");
        Self(path)
    }

    fn path(&self) -> &str {
        self.0.to_str().expect("a UTF-8 path")
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

#[test]
fn a_compliance_matrix_from_a_file_deflects_each_node_as_its_numbers_say() {
    // A diagonal matrix c·I on the default 12 × 18 grid: each node moves by c times its own load
    // (the film's and asperities' pressure times its cell's area), the relaxation's tolerance apart.
    let (nodes, c) = (12 * 18, 2e-9);
    let text: String = std::iter::once("# a diagonal compliance, m/N\n".to_string())
        .chain(
            (0..nodes).map(|k| (0..nodes).map(|l| if k == l { format!("{c:e}") } else { "0".into() }).collect::<Vec<_>>().join(",") + "\n"),
        )
        .collect();
    let file = TempFile::new("diagonal.csv", &text);
    let matrix = read_matrix(file.path()).expect("a square matrix");
    let soft = skirt(matrix);
    let linear = soft.linearise(&MOTION);
    let map = soft.pressure_map(&linear, &MOTION);
    let d = soft.design();
    let area = d.radius_bore * d.arc / 13.0 * d.length / 19.0;
    let (side, nx) = (&map.sides[0], 14);
    let mut checked = 0;
    for j in 1..=18 {
        for i in 1..=12 {
            let (p, deflection) = (side.pressure[j * nx + i] + side.asperity_pressure[j * nx + i], linear.deflection[0][j * nx + i]);
            let film = side.film[j * nx + i];
            assert!((deflection - c * p * area).abs() <= 2e-3 * film, "node ({i}, {j}): {deflection:e} against {:e}", c * p * area);
            checked += usize::from(p > 0.0);
        }
    }
    assert!(checked > 20 && linear.peak_pressure > 0.0);
}

#[test]
fn a_compliance_of_the_wrong_shape_or_on_too_fine_a_grid_is_refused_by_name() {
    let ragged = TempFile::new("ragged.csv", "1,2\n3\n");
    let message = read_matrix(ragged.path()).unwrap_err().0;
    assert!(message.contains("skirt_compliance_file") && message.contains("line 2 has 1 numbers"), "{message}");
    let oblong = TempFile::new("oblong.csv", "1,2\n3,4\n5,6\n");
    assert!(read_matrix(oblong.path()).unwrap_err().0.contains("must be square"));
    let words = TempFile::new("words.csv", "1,x\n3,4\n");
    assert!(read_matrix(words.path()).unwrap_err().0.contains("\"x\" is not a number"));
    // A square matrix of another grid's size.
    let small = TempFile::new("small.csv", "1,0\n0,1\n");
    let mut design = skirt(Compliance::Rigid).design().clone();
    design.compliance = read_matrix(small.path()).expect("square");
    let message = Skirt::new(design).unwrap_err().0;
    assert!(message.contains("4 entries") && message.contains("216 × 216"), "{message}");
    assert!(read_matrix("/nonexistent/compliance.csv").unwrap_err().0.contains("cannot be read"));
    // A grid too fine for a dense compliance.
    let mut fine = skirt(Compliance::Rigid).design().clone();
    (fine.grid, fine.compliance) = ((64, 64), Compliance::Shell { thickness: 3e-3, modulus: 70e9 });
    assert!(Skirt::new(fine).unwrap_err().0.contains("at most 1024 nodes"));
}
