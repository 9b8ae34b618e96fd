//! The event search of one RK4 step: the earliest gap or multiplier crossing, located on the
//! step's quintic extension and confirmed on the RK4 map.

use super::hermite::Hermite5;
use super::implicit::stages_off_path;
use super::rk4::rk4_to;
use super::root_finding::{self, Bracket, Located, Start};
use super::sample::{acceleration, sample, Evaluated, Forces, Sample, Watch};
use super::stepper::StepEnd;
use super::system::friction_of;
use super::{DynamicsError, Evaluation, Stepper, System};
use std::cell::OnceCell;

impl<S: System<N, M>, const N: usize, const M: usize> Stepper<S, N, M> {
    fn tolerance(&self, watch: Watch) -> f64 {
        match watch {
            Watch::Gap => self.options.gap_tolerance,
            Watch::Multiplier | Watch::Stick(_) => self.options.multiplier_tolerance,
            Watch::Slip(_) => self.options.velocity_tolerance,
        }
    }

    /// What the step watches (`Watch::all`); only a frictional system with contacts held has
    /// tangential watches.
    fn watches(&self) -> impl Iterator<Item = (usize, Watch)> + Clone {
        let mu = if self.contacts.held == 0 { None } else { friction_of(&self.system) };
        Watch::all(self.contacts, mu)
    }

    /// The earliest event in the step `self.state → s1`; `middle`: the held contacts' forces at
    /// the step's middle; `unmoved`: the step starts where an event changed nothing, or undid the one
    /// before it (time and contact set as they were before that one).
    pub(super) fn first_event(&self, s1: Evaluated<N, M>, middle: &Forces<M>, unmoved: bool) -> Result<StepEnd<N, M>, DynamicsError> {
        let (sys, s0, contacts) = (&self.system, &self.state, self.contacts);
        let watches = self.watches();
        // Where an event at this instant changed nothing, or undid the one before it, the laws
        // accepted every held watch's value here within their own tolerances, relative to the
        // problem's scale and wider than the search's: one already below −tol is watched for falling
        // as far again, to where the laws decide otherwise, rather than found crossed at once, again
        // and again (a stick 9e-7 N outside its cone, a slip reversed by 9e-9 m/s at a dead centre;
        // a contact released and closed again as sliding at round-off forces: 10⁴ times at one instant).
        let shift = |i: usize, w: Watch| {
            let (g0, tol) = (s0.watched(i, w), self.tolerance(w));
            if unmoved && w != Watch::Gap && g0 < -tol {
                2.0 * g0 + tol
            } else {
                0.0
            }
        };
        let watched = |s: &Sample<N, M>, i: usize, w: Watch| s.watched(i, w) - shift(i, w);
        let step_end = &s1.0;
        let path_middle = stages_off_path(s1.1.as_ref());
        // The step's quintic extensions, of the gaps and of the configuration, built once a scan
        // needs them (most steps scan nothing).
        let (gaps, configuration) = (OnceCell::new(), OnceCell::new());
        let gap_extension = || {
            let e = step_end;
            gaps.get_or_init(|| Hermite5 { t0: s0.t, dt: e.t - s0.t, q0: s0.gap, v0: s0.hd, a0: s0.hdd, q1: e.gap, v1: e.hd, a1: e.hdd })
        };
        let on_dense = |t: f64, i: usize, w: Watch| -> Result<f64, DynamicsError> {
            let e = step_end;
            match w {
                Watch::Gap => Ok(gap_extension().position_of(i, t)),
                Watch::Multiplier | Watch::Slip(_) | Watch::Stick(_) => {
                    let dense = configuration.get_or_init(|| Hermite5 {
                        t0: s0.t,
                        dt: e.t - s0.t,
                        q0: s0.q,
                        v0: s0.v,
                        a0: s0.acc,
                        q1: e.q,
                        v1: e.v,
                        a1: e.acc,
                    });
                    let (q, v) = dense.at(t);
                    // With friction the normal forces depend on the tangential ones: the whole law.
                    if w != Watch::Multiplier || friction_of(sys).is_some() {
                        return Ok(sample(sys, t, q, v, contacts)?.watched(i, w));
                    }
                    let lambda = acceleration(&sys.evaluate(t, &q, &v), t, contacts.held)?.1[i];
                    if lambda.is_finite() {
                        Ok(lambda)
                    } else {
                        Err(DynamicsError::NonFinite { time: t })
                    }
                }
            }
        };
        // ḣᵢ on the gaps' extension, where a dip's bottom is sought.
        let gap_rate = |t: f64, i: usize| -> Result<f64, DynamicsError> { Ok(gap_extension().velocity_of(i, t)) };
        // A located event is checked against the others at its own state; if one of them has
        // already crossed there, the search repeats on the shorter step, to that state (at most M times).
        let mut located: Option<Evaluated<N, M>> = None;
        for _ in 0..=M {
            let mut earliest: Option<(f64, usize, Watch, Start)> = None;
            for (i, w) in watches.clone() {
                let tol = self.tolerance(w);
                let e = located.as_ref().map_or(step_end, |l| &l.0);
                let (g0, g1, lift) = (watched(s0, i, w), watched(e, i, w), shift(i, w));
                // A gap rising at the step's end may have dipped inside it: one falling at the start
                // within reach of the wall, or one rising at the start so slowly against its
                // deceleration that it turns within the step at a height its fall then exceeds.
                let (dt, hd0, hdd0) = (e.t - s0.t, s0.hd[i], s0.hdd[i]);
                let dips = w == Watch::Gap
                    && e.hd[i] > 0.0
                    && ((hd0 < 0.0 && g0.min(g1) < 2.0 * dt * -hd0)
                        || (hd0 >= 0.0 && hdd0 < 0.0 && hd0 < -hdd0 * dt && g0 + hd0 * hd0 / (-2.0 * hdd0) < -hdd0 * dt * dt));
                // A held constraint's force (or slip, or margin to the cone) may dip through zero
                // and back inside the step: the scan below looks wherever the parabola through its
                // values at the ends and the middle comes within the step's own variation of zero
                // (the middle is an RK4 stage, off the motion by that much: a dip of 7 mN the
                // quintic extension shows, and the outputs with it, had a stage value of +16 mN).
                // Where the stages lie far off the path (`stages_off_path`), the quintic extension's
                // middle is read as well.
                let held_dip = w != Watch::Gap && located.is_none() && {
                    let dipping = |gm: f64| lowest(g0, gm, g1) < (g0 - gm).abs() + (gm - g1).abs();
                    dipping(middle.watched(i, w) - lift) || (path_middle && dipping(on_dense(0.5 * (s0.t + step_end.t), i, w)? - lift))
                };
                if g1 >= -tol && !dips && !held_dip {
                    continue;
                }
                let rising = match w {
                    Watch::Gap => s0.hd[i] > 0.0,
                    // A slip the law just started from rest within ε_ḣ: its direction
                    // is that of γ̇, so it grows before it can reverse.
                    Watch::Slip(s) => g0 <= tol && s * self.slip_rate(s0, i) > 0.0,
                    // A held constraint pulling at the start was kept on the trend of its
                    // force (a tie, or a flight below the event resolution): it grows first.
                    Watch::Multiplier => g0 < 0.0,
                    Watch::Stick(_) => false,
                };
                let start = match root_finding::first_crossing(|t| Ok(on_dense(t, i, w)? - lift), (s0.t, g0), (e.t, g1), tol, rising)? {
                    None if dips => root_finding::dip_bottom(|t| on_dense(t, i, w), |t| gap_rate(t, i), (s0.t, g0), e.t, tol)?,
                    found => found,
                };
                let estimate = match start {
                    None => continue,
                    Some(Start::Immediate) => s0.t,
                    Some(Start::Within(br)) => pick(root_finding::illinois(|t| Ok(on_dense(t, i, w)? - lift), br, 0.25 * tol, None)?, w),
                };
                if earliest.is_none_or(|(t, ..)| estimate < t) {
                    earliest = Some((estimate, i, w, start.expect("matched above")));
                }
            }
            let Some((estimate, i, w, start)) = earliest else { return Ok(StepEnd::Clear(located.unwrap_or(s1))) };
            let br = match start {
                Start::Immediate => return Ok(StepEnd::Event { at: (s0.clone(), None), constraint: i }),
                Start::Within(br) => br,
            };
            let (s, ev) = self.locate_on_rk4(br, estimate, (i, w), shift(i, w))?;
            let crossed_before = watches.clone().any(|(j, v)| (j, v) != (i, w) && watched(&s, j, v) < -self.tolerance(v));
            if !crossed_before {
                return Ok(StepEnd::Event { at: (s, Some(ev)), constraint: i });
            }
            located = Some((s, Some(ev)));
        }
        // Only reachable with round-off ties between constraints: take the last located state.
        let end = located.unwrap_or(s1);
        let j = watches.clone().find(|&(j, v)| watched(&end.0, j, v) < 0.0).map_or(0, |(j, _)| j);
        Ok(StepEnd::Event { at: end, constraint: j })
    }

    /// `γ̇ᵢ = J_T q̈ + d_T` at `s`.
    fn slip_rate(&self, s: &Sample<N, M>, i: usize) -> f64 {
        let tangents = self.system.tangents(s.t, &s.q, &s.v);
        (tangents.jacobian.row(i) * s.acc)[0] + tangents.bias[i]
    }

    /// The state where `g_i − shift` crosses zero, on the RK4 map from the step start: Illinois
    /// started at the dense-output estimate (usually accepted at once).
    fn locate_on_rk4(
        &self,
        br: Bracket,
        estimate: f64,
        (i, w): (usize, Watch),
        shift: f64,
    ) -> Result<(Sample<N, M>, Evaluation<N, M>), DynamicsError> {
        let (sys, s0, contacts) = (&self.system, &self.state, self.contacts);
        let tol = self.tolerance(w);
        let mut last: Option<(Sample<N, M>, Evaluation<N, M>)> = None;
        self.count(|c| c.located += 1);
        let locating = |t: f64| {
            self.count(|c| c.locating += 1);
            rk4_to(sys, s0, t, contacts)
        };
        let mut g = |t: f64| -> Result<f64, DynamicsError> {
            let s = locating(t)?;
            let gt = s.0.watched(i, w) - shift;
            last = Some(s);
            Ok(gt)
        };
        let t = pick(root_finding::illinois(&mut g, br, tol, Some(estimate))?, w);
        match last {
            Some(s) if s.0.t == t => Ok(s),
            _ => locating(t),
        }
    }
}

/// The lowest value on `[0, 1]` of the parabola through `(0, g0)`, `(½, gm)`, `(1, g1)`.
fn lowest(g0: f64, gm: f64, g1: f64) -> f64 {
    let (slope, curvature) = (4.0 * gm - 3.0 * g0 - g1, 2.0 * (g0 + g1 - 2.0 * gm));
    let s = -slope / (2.0 * curvature);
    if curvature > 0.0 && s > 0.0 && s < 1.0 {
        g0 + slope * s + curvature * s * s
    } else {
        g0.min(g1)
    }
}

/// The time of a located crossing; a collapsed bracket resolves to its admissible end: before
/// the gap crossing (h ≥ 0), after the others (λ ≤ 0, so the release is real; the slip reversed,
/// the friction cone left).
fn pick(located: Located, w: Watch) -> f64 {
    match (located, w) {
        (Located::Root(t), _) => t,
        (Located::Collapsed(br), Watch::Gap) => br.lo,
        (Located::Collapsed(br), _) => br.hi,
    }
}
