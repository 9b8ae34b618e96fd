//! The skirt's axial profile: how far the piston's radius falls below its nominal d/2 along the skirt.

use crate::models::ModelError;
use std::fmt;
use std::str::FromStr;

/// Radial drop of the skirt below d/2 against the axial position u, m, measured from the skirt's top
/// edge (u = 0) down toward its bottom edge (u = skirt length).
///
/// Text form (the FMU's String parameter `skirt_profile`), either
/// - `parabola TOP BOTTOM`: the barrel through drop TOP at u = 0 and BOTTOM at u = length whose vertex
///   touches d/2 (drop 0) in between; `parabola 0 0` is a straight skirt; or
/// - a table `u1:d1, u2:d2, ...` of at least two points with u strictly increasing, linearly
///   interpolated and held at the end values beyond the first and last u.
///
/// All numbers in metres, finite, drops and positions ≥ 0; whitespace is free.
#[derive(Clone, Debug, PartialEq)]
pub enum SkirtProfile {
    /// The barrel, by its drops at the top and bottom edges, m.
    Parabola {
        /// m, at u = 0.
        top_drop: f64,
        /// m, at u = skirt length.
        bottom_drop: f64,
    },
    /// (u, drop) points, m, u strictly increasing.
    Table(Vec<(f64, f64)>),
}

impl Default for SkirtProfile {
    /// A straight skirt: the papers' rigid cylinder.
    fn default() -> Self {
        Self::Parabola { top_drop: 0.0, bottom_drop: 0.0 }
    }
}

impl SkirtProfile {
    /// The drop at `u` (m from the top edge) on a skirt of `length`, m.
    pub fn drop(&self, u: f64, length: f64) -> f64 {
        match self {
            Self::Parabola { top_drop, bottom_drop } => {
                let (a, b) = (top_drop.sqrt(), bottom_drop.sqrt());
                if a + b == 0.0 {
                    return 0.0;
                }
                // drop = k (u − u0)², k = ((√top + √bottom)/L)², vertex u0 = L √top/(√top + √bottom).
                let slope = (a + b) / length;
                let t = slope * u - a;
                t * t
            }
            Self::Table(points) => {
                let last = points.len() - 1;
                if u <= points[0].0 {
                    return points[0].1;
                }
                if u >= points[last].0 {
                    return points[last].1;
                }
                let k = points.partition_point(|&(x, _)| x <= u);
                let ((u0, d0), (u1, d1)) = (points[k - 1], points[k]);
                d0 + (d1 - d0) * (u - u0) / (u1 - u0)
            }
        }
    }

    /// Checks the numbers the text grammar demands of a profile built in code as well.
    pub fn validate(&self) -> Result<(), ModelError> {
        let bad = |what: String| Err(ModelError(format!("skirt_profile: {what}")));
        match self {
            Self::Parabola { top_drop, bottom_drop } => {
                for (name, v) in [("top drop", top_drop), ("bottom drop", bottom_drop)] {
                    if !(v.is_finite() && *v >= 0.0) {
                        return bad(format!("{name} {v} m must be finite and ≥ 0"));
                    }
                }
            }
            Self::Table(points) => {
                if points.len() < 2 {
                    return bad(format!("a table needs at least two points, got {}", points.len()));
                }
                for (i, &(u, d)) in points.iter().enumerate() {
                    if !(u.is_finite() && u >= 0.0 && d.is_finite() && d >= 0.0) {
                        return bad(format!("point {} ({u}:{d}) must have finite position and drop ≥ 0", i + 1));
                    }
                    if i > 0 && u <= points[i - 1].0 {
                        return bad(format!("point {} at {u} m does not follow {} m: positions must increase", i + 1, points[i - 1].0));
                    }
                }
            }
        }
        Ok(())
    }
}

fn number(text: &str, what: &str) -> Result<f64, ModelError> {
    text.trim().parse::<f64>().map_err(|_| ModelError(format!("skirt_profile: {what} '{}' is not a number", text.trim())))
}

impl FromStr for SkirtProfile {
    type Err = ModelError;

    fn from_str(text: &str) -> Result<Self, ModelError> {
        let text = text.trim();
        let profile = if let Some(rest) = text.strip_prefix("parabola") {
            let words: Vec<&str> = rest.split_whitespace().collect();
            if words.len() != 2 {
                return Err(ModelError(format!("skirt_profile: 'parabola' takes two drops (top, bottom, m), got {}", words.len())));
            }
            Self::Parabola { top_drop: number(words[0], "top drop")?, bottom_drop: number(words[1], "bottom drop")? }
        } else {
            let points = text
                .split(',')
                .enumerate()
                .map(|(i, item)| match item.split_once(':') {
                    Some((u, d)) => Ok((number(u, "position")?, number(d, "drop")?)),
                    None => Err(ModelError(format!(
                        "skirt_profile: item {} '{}' is not position:drop (or start the text with 'parabola')",
                        i + 1,
                        item.trim()
                    ))),
                })
                .collect::<Result<Vec<_>, _>>()?;
            Self::Table(points)
        };
        profile.validate()?;
        Ok(profile)
    }
}

impl fmt::Display for SkirtProfile {
    /// The text form [`FromStr`] reads back to the same profile.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Parabola { top_drop, bottom_drop } => write!(f, "parabola {top_drop:e} {bottom_drop:e}"),
            Self::Table(points) => {
                let items: Vec<String> = points.iter().map(|(u, d)| format!("{u:e}:{d:e}")).collect();
                f.write_str(&items.join(", "))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_both_forms_and_round_trips() {
        let p: SkirtProfile = "parabola 20e-6 10e-6".parse().expect("parabola");
        assert_eq!(p, SkirtProfile::Parabola { top_drop: 20e-6, bottom_drop: 10e-6 });
        let t: SkirtProfile = " 0:30e-6, 0.01 : 5e-6,0.05:0 ".parse().expect("table");
        assert_eq!(t, SkirtProfile::Table(vec![(0.0, 30e-6), (0.01, 5e-6), (0.05, 0.0)]));
        for q in [p, t] {
            assert_eq!(q.to_string().parse::<SkirtProfile>().expect("round trip"), q);
        }
    }

    #[test]
    fn parabola_passes_its_drops_and_touches_zero() {
        let p = SkirtProfile::Parabola { top_drop: 20e-6, bottom_drop: 5e-6 };
        let l = 0.06;
        assert!((p.drop(0.0, l) - 20e-6).abs() < 1e-18 && (p.drop(l, l) - 5e-6).abs() < 1e-18);
        // Vertex at u0 = L·√20/(√20 + √5) = 2L/3.
        assert!(p.drop(2.0 * l / 3.0, l).abs() < 1e-20);
        let t = SkirtProfile::Table(vec![(0.0, 30e-6), (0.01, 10e-6)]);
        assert_eq!((t.drop(-1.0, l), t.drop(0.005, l), t.drop(1.0, l)), (30e-6, 20e-6, 10e-6));
    }

    #[test]
    fn refuses_bad_text_naming_the_fault() {
        for (text, fault) in [
            ("parabola 1e-6", "two drops"),
            ("parabola x 1e-6", "'x' is not a number"),
            ("parabola -1e-6 0", "≥ 0"),
            ("0:1e-6", "at least two points"),
            ("0:1e-6, 0.01", "item 2"),
            ("0:1e-6, 0:2e-6", "must increase"),
            ("0:1e-6, 0.01:nan", "finite"),
        ] {
            let e = text.parse::<SkirtProfile>().expect_err(text);
            assert!(e.0.starts_with("skirt_profile: ") && e.0.contains(fault), "{text}: {}", e.0);
        }
    }
}
