//! The root finders of event detection and location: a watched function `g` (a gap `hᵢ` of a
//! free constraint, a multiplier `λᵢ` of a sliding one, with friction its slip or its margin to
//! the friction cone) crossing from positive to below `−tol` within a step, found by a scan of the
//! step and located by Illinois.

/// An interval with `g(lo) > 0` and `g(hi) < 0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Bracket {
    pub lo: f64,
    pub g_lo: f64,
    pub hi: f64,
    pub g_hi: f64,
}

impl Bracket {
    /// No float lies strictly between the ends.
    fn collapsed(&self) -> bool {
        let mid = self.lo + 0.5 * (self.hi - self.lo);
        mid <= self.lo || mid >= self.hi
    }

    fn shrink(&mut self, t: f64, g: f64) {
        if g > 0.0 {
            (self.lo, self.g_lo) = (t, g);
        } else {
            (self.hi, self.g_hi) = (t, g);
        }
    }
}

/// Where a crossing starts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Start {
    /// `g` is already at zero at the step start and goes below `−tol`: the event is now.
    Immediate,
    Within(Bracket),
}

/// The result of a root search: a time with `|g| ≤ tol`, or a bracket that shrank to adjacent
/// floats first (a very steep `g`); the caller picks the admissible end.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Located {
    Root(f64),
    Collapsed(Bracket),
}

/// Samples per step when scanning the dense output for the first crossing.
const SCAN_SAMPLES: usize = 8;
const MAX_ITERATIONS: usize = 200;

/// The first sub-interval of `[t0, t1]` where `g` goes from above `tol` to below `−tol`, scanning
/// `SCAN_SAMPLES` points of the dense output: this finds the earliest of several roots and a
/// crossing-and-return inside one step (a grazing dip) that the end values alone would miss.
/// `rising`: `g` is within `tol` of zero at `t0` but increasing (a constraint closed and
/// separating, e.g. just after an impact, or a slip just started from rest); a crossing then lies
/// after `t0` even if the first sample is below `−tol` (a flight or a slip shorter than a sample),
/// so the sample interval is halved towards `t0` until `g` is above `tol` there. Without this the
/// event would be reported at `t0`, where there is nothing to resolve, again and again.
pub(crate) fn first_crossing<E>(
    mut g: impl FnMut(f64) -> Result<f64, E>,
    (t0, g0): (f64, f64),
    (t1, g1): (f64, f64),
    tol: f64,
    rising: bool,
) -> Result<Option<Start>, E> {
    let mut positive = (g0 > tol).then_some((t0, g0));
    for k in 1..=SCAN_SAMPLES {
        let (mut t, mut gt) = if k == SCAN_SAMPLES {
            (t1, g1)
        } else {
            let t = t0 + (t1 - t0) * k as f64 / SCAN_SAMPLES as f64;
            (t, g(t)?)
        };
        if gt < -tol && positive.is_none() && rising {
            // `(t, gt)` stays the earliest point found below `−tol`: if `g` never rises above `tol`,
            // the crossing starts at `t0` after all.
            let mut mid = t;
            for _ in 0..MAX_ITERATIONS {
                mid = t0 + 0.5 * (mid - t0);
                if mid <= t0 {
                    break;
                }
                let g_mid = g(mid)?;
                if g_mid > tol {
                    return Ok(Some(Start::Within(Bracket { lo: mid, g_lo: g_mid, hi: t, g_hi: gt })));
                }
                if g_mid < -tol {
                    (t, gt) = (mid, g_mid);
                }
            }
        }
        if gt < -tol {
            return Ok(Some(match positive {
                Some((lo, g_lo)) => Start::Within(Bracket { lo, g_lo, hi: t, g_hi: gt }),
                None => Start::Immediate,
            }));
        }
        if gt > tol {
            positive = Some((t, gt));
        }
    }
    Ok(None)
}

/// A dip between the scan's samples that `first_crossing` steps over (every sample above `−tol`,
/// the part below narrower than a sample interval: a gap whose fall turns within a fraction
/// of a step, e.g. in a rattle at e = 1): the dip's bottom, where the rate `dg` turns from
/// negative to positive between two samples, located on `dg`; if `g` is below `−tol` there, the
/// crossing before it, from the last point above `tol` (a sample, or the top of a rise between
/// samples where `dg` turns from positive to negative), the start if there is none.
pub(crate) fn dip_bottom<E>(
    mut g: impl FnMut(f64) -> Result<f64, E>,
    mut dg: impl FnMut(f64) -> Result<f64, E>,
    (t0, g0): (f64, f64),
    t1: f64,
    tol: f64,
) -> Result<Option<Start>, E> {
    let mut positive = (g0 > tol).then_some((t0, g0));
    let (mut lo, mut dg_lo) = (t0, dg(t0)?);
    for k in 1..=SCAN_SAMPLES {
        let t = if k == SCAN_SAMPLES { t1 } else { t0 + (t1 - t0) * k as f64 / SCAN_SAMPLES as f64 };
        let dg_t = dg(t)?;
        if (dg_lo < 0.0) != (dg_t < 0.0) {
            // A turning point: the root of the rate (its sign made falling for Illinois's bracket).
            let sign = if dg_lo < 0.0 { -1.0 } else { 1.0 };
            let br = Bracket { lo, g_lo: sign * dg_lo, hi: t, g_hi: sign * dg_t };
            let turn = match illinois(|t| Ok(sign * dg(t)?), br, 0.0, None)? {
                Located::Root(t) => t,
                Located::Collapsed(br) => br.lo,
            };
            let g_turn = g(turn)?;
            if dg_lo < 0.0 && g_turn < -tol {
                return Ok(Some(match positive {
                    Some((lo, g_lo)) => Start::Within(Bracket { lo, g_lo, hi: turn, g_hi: g_turn }),
                    None => Start::Immediate,
                }));
            }
            if dg_lo >= 0.0 && g_turn > tol {
                positive = Some((turn, g_turn));
            }
        }
        let g_t = g(t)?;
        if g_t > tol {
            positive = Some((t, g_t));
        }
        (lo, dg_lo) = (t, dg_t);
    }
    Ok(None)
}

/// Illinois (regula falsi with halving of a twice-retained end), optionally starting from a
/// good `guess`. Superlinear, and never leaves the bracket.
pub(crate) fn illinois<E>(
    mut g: impl FnMut(f64) -> Result<f64, E>,
    mut br: Bracket,
    tol: f64,
    mut guess: Option<f64>,
) -> Result<Located, E> {
    // +1: lo was kept last time, −1: hi was kept.
    let mut kept = 0i8;
    for _ in 0..MAX_ITERATIONS {
        if br.collapsed() {
            break;
        }
        // A secant that rounds onto an end (one end's g far smaller than the other's) puts the
        // root within an ulp of that end: the float next to it, not bisection, which would take
        // some forty halvings to get there.
        let secant = (br.lo * br.g_hi - br.hi * br.g_lo) / (br.g_hi - br.g_lo);
        let t = match guess.take() {
            Some(t) if t > br.lo && t < br.hi => t,
            _ if secant > br.lo && secant < br.hi => secant,
            _ if secant <= br.lo => br.lo.next_up(),
            _ if secant >= br.hi => br.hi.next_down(),
            _ => br.lo + 0.5 * (br.hi - br.lo),
        };
        let gt = g(t)?;
        if gt.abs() <= tol {
            return Ok(Located::Root(t));
        }
        if gt > 0.0 {
            if kept == -1 {
                br.g_hi *= 0.5;
            }
            kept = -1;
        } else {
            if kept == 1 {
                br.g_lo *= 0.5;
            }
            kept = 1;
        }
        br.shrink(t, gt);
    }
    Ok(Located::Collapsed(br))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::convert::Infallible;

    fn run(f: impl Fn(f64) -> f64, locate: impl Fn(&dyn Fn(f64) -> Result<f64, Infallible>, Bracket) -> Located) -> (f64, usize) {
        let calls = std::cell::Cell::new(0);
        let g = |t: f64| {
            calls.set(calls.get() + 1);
            Ok(f(t))
        };
        let br = Bracket { lo: 0.0, g_lo: f(0.0), hi: 1.0, g_hi: f(1.0) };
        match locate(&g, br) {
            Located::Root(t) => (t, calls.get()),
            Located::Collapsed(b) => (b.lo, calls.get()),
        }
    }

    /// Illinois hits the root of a cubic to the tolerance in fewer than 15 calls, where bisection
    /// (the paper's step halving) needs log₂(1/1e-13) ≈ 43 to narrow the unit bracket as far.
    #[test]
    fn illinois_locates_a_known_root() {
        let f = |t: f64| (0.3 - t) * (1.0 + t * t);
        let (t, calls) = run(f, |g, br| illinois(g, br, 1e-13, None).unwrap());
        assert!((t - 0.3).abs() < 1e-12);
        assert!(calls < 15, "illinois {calls} calls");
    }

    /// A root within an ulp of the bracket's end, where `g` is far smaller than at the other
    /// end, so that the secant rounds onto the end (a release on the RK4 map): the float next to
    /// it at once, not some fifty bisections.
    #[test]
    fn a_secant_rounding_onto_an_end_tries_the_next_float() {
        let f = |t: f64| if t < 1.0 { 1.0 - t } else { -1e-17 };
        let calls = std::cell::Cell::new(0);
        let g = |t: f64| {
            calls.set(calls.get() + 1);
            Ok::<_, Infallible>(f(t))
        };
        let located = illinois(g, Bracket { lo: 0.0, g_lo: 1.0, hi: 1.0, g_hi: f(1.0) }, 1e-20, None).unwrap();
        assert_eq!(located, Located::Collapsed(Bracket { lo: 1.0_f64.next_down(), g_lo: f(1.0_f64.next_down()), hi: 1.0, g_hi: -1e-17 }));
        assert_eq!(calls.get(), 1);
    }

    #[test]
    fn scan_finds_a_dip_inside_the_step() {
        let f = |t: f64| (t - 0.5) * (t - 0.5) - 0.01; // negative on (0.4, 0.6)
        let found = first_crossing(|t| Ok::<_, Infallible>(f(t)), (0.0, f(0.0)), (1.0, f(1.0)), 1e-12, false).unwrap();
        match found {
            Some(Start::Within(b)) => assert!(b.lo < 0.4 && b.hi > 0.4 && b.hi <= 0.6),
            other => panic!("{other:?}"),
        }
    }

    /// A dip narrower than a sample interval between two samples above zero (the minimum −1e-9
    /// at t = 0.2 + 1e-3, half a sample from both): the scan steps over it, the bottom search
    /// finds it, bracketed from the sample before.
    #[test]
    fn the_bottom_search_finds_a_dip_the_samples_step_over() {
        let (c, depth, width) = (0.2 + 1e-3, 1e-9, 1e-3);
        let f = |t: f64| depth * ((t - c) * (t - c) / (width * width) - 1.0);
        let df = |t: f64| depth * 2.0 * (t - c) / (width * width);
        let (g, dg) = (|t| Ok::<_, Infallible>(f(t)), |t| Ok::<_, Infallible>(df(t)));
        assert_eq!(first_crossing(g, (0.0, f(0.0)), (1.0, f(1.0)), 1e-12, false).unwrap(), None);
        match dip_bottom(g, dg, (0.0, f(0.0)), 1.0, 1e-12).unwrap() {
            Some(Start::Within(b)) => assert!(b.lo == 0.125 && (b.hi - c).abs() < 1e-12 && b.g_hi < -0.99e-9, "{b:?}"),
            other => panic!("{other:?}"),
        }
        // A dip that stays above −tol is none.
        let shallow = |t: f64| f(t) + depth - 1e-13;
        assert_eq!(dip_bottom(|t| Ok::<_, Infallible>(shallow(t)), dg, (0.0, shallow(0.0)), 1.0, 1e-12).unwrap(), None);
    }

    /// A gap at zero and rising at the start whose flight ends before the first sample: the
    /// crossing is found after the start, not reported as immediate.
    #[test]
    fn scan_finds_a_short_flight_after_a_closed_start() {
        let f = |t: f64| t * (0.01 - t); // 0 at t = 0, rising, back below zero after t = 0.01
        let found = first_crossing(|t| Ok::<_, Infallible>(f(t)), (0.0, 0.0), (1.0, f(1.0)), 1e-12, true).unwrap();
        match found {
            Some(Start::Within(b)) => assert!(b.lo > 0.0 && b.lo < 0.01 && b.hi > 0.01, "{b:?}"),
            other => panic!("{other:?}"),
        }
        let without = first_crossing(|t| Ok::<_, Infallible>(f(t)), (0.0, 0.0), (1.0, f(1.0)), 1e-12, false).unwrap();
        assert_eq!(without, Some(Start::Immediate));
    }

    /// The same flight from a start just above zero but within the tolerance (where an impact
    /// leaves a contact): the start is no end of the bracket, or Illinois would accept a "root"
    /// next to it (|g| ≤ tol there) and the stepper would inch on by such non-events.
    #[test]
    fn a_start_within_the_tolerance_is_not_a_bracket_end() {
        let f = |t: f64| 3e-14 + t * (0.01 - t);
        let found = first_crossing(|t| Ok::<_, Infallible>(f(t)), (0.0, f(0.0)), (1.0, f(1.0)), 1e-12, true).unwrap();
        match found {
            Some(Start::Within(b)) => assert!(b.lo > 0.0 && b.g_lo > 1e-12 && b.hi > 0.01, "{b:?}"),
            other => panic!("{other:?}"),
        }
    }

    /// Rising at the start but turning back before it lifts beyond the tolerance (apex 2.5e-13
    /// above zero), then below it: no bracket to locate, so the crossing is at the start, not
    /// missed.
    #[test]
    fn a_rise_below_the_tolerance_then_a_fall_is_a_crossing_at_the_start() {
        let f = |t: f64| 1e-6 * t - 1.0 * t * t;
        let found = first_crossing(|t| Ok::<_, Infallible>(f(t)), (0.0, f(0.0)), (1e-5, f(1e-5)), 1e-12, true).unwrap();
        assert_eq!(found, Some(Start::Immediate));
    }
}
