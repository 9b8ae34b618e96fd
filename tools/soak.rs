//! `make soak` (`cargo run --release --example soak [crank cycles] [roller revolutions]`): long runs
//! in release mode, failing on any model error (NaN, unresolved accumulation, event budget — the
//! stepper's guard against a hang) and on a drift of the energy balance, checked every window
//! (an engine cycle, a roller revolution):
//!   E(end) − E(start) = ∫ (P_drive + P_gas − D − F) dt − Σ impact dissipation + Σ impulsive drive work
//! with the terms of `EnergyBalance` (F: liner friction's dissipation rate in persistent contact;
//! an impact's dissipation includes what its friction impulses dissipate). The drive power is the FMU's `crank_torque` output times ω
//! (from the crank row, which the reduced dynamics never use), the gas power is F times the speed
//! of its point of action, D the damping's dissipation, and the impulsive drive work what the
//! held crank (or the roller's moving walls) does through each impact's impulses.
//!
//! 1. Crank train as the FMU runs by default: prescribed crank at 1200 rpm, built-in pressure, e = 0.5.
//! 2. The same with a free crank (crank_mode 2), load and joint damping calibrated to A&K's
//!    efficiency (`EfficiencyTarget`); the drive is then the load torque, and impulses do no work.
//! 3. The prescribed crank again with liner friction μ = 0.1 and a lateral gravity of 9.81 m/s²
//!    (a horizontal cylinder): friction dissipation in sliding and in Newton–Coulomb impacts.
//! 4. The roller variant at 1200 rpm: its 1-DOF system of eq 2.13 (`models/roller/energy.rs`), in
//!    a thread of its own beside 1–3 (it takes longest).
//!
//! Quadrature: the powers are smooth between events. Each window is cut into an even number of
//! intervals (within one RK4 step for the crank train, about four for the roller), integrated by
//! Simpson in pairs. Where the model met an event, copies of the model from the interval's start
//! (which take the same RK4 steps, so meet the event at the same time) give the powers at `δ`
//! before and after it and the midpoints on either side: Simpson up to the event and after it, the
//! trapezoidal rule over the `2δ` across it; a later event in the same interval is handled from
//! the copy after the first, in turn.
//!
//! Tolerance: `TOLERANCE` of the window's scale ∫(|P_drive| + |P_gas| + D) dt + Σ dissipation +
//! |Σ impulsive work|. Measured over short runs: ≈ 1e-9 (prescribed crank), ≈ 3e-7 (free crank),
//! ≈ 7e-7 (roller); halving the roller's grid raises its error 15-fold (Simpson's h⁴), so what is
//! left is quadrature. A missing or wrong term would show well above it: the smallest terms are
//! the crank train's impact dissipation, ≈ 1e-4 of the scale, and its impulsive drive work,
//! ≈ 2e-3 (the roller's impulsive wall work ≈ 7e-4). Not counted: the O(h⁵) velocity projections
//! that keep sliding contacts on their manifold.

use pistonslap::fmus::piston_slap::Mechanism;
use pistonslap::fmus::piston_slap::{Inputs, Parameters};
use pistonslap::models::crank_train::kinematics::SliderCrank;
use pistonslap::models::gas::FourStrokePressure;
use pistonslap::models::{CrankTrain, EfficiencyTarget, EnergyBalance, EngineEvent, Roller};
use std::f64::consts::PI;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// Half-width δ of the piece across an event, relative to the interval it was found in: wide
/// enough for the time a copy meets the event at to fall within it (event location is accurate
/// to a gap of 1e-12), narrow enough for the jump of the powers over it not to count.
const SPLIT: f64 = 1e-5;
/// Least δ, relative to the event's time: the time resolution there, with a margin. Within an
/// accumulation of impacts the intervals left shrink until `SPLIT` of them is below the
/// resolution of the time (≈ 4e-12 s at 2.4e4 s), and a piece across an event would end where it
/// began: the soak then went round the same event for ever (roller, revolution 4.8·10⁵).
const RESOLUTION: f64 = 16.0 * f64::EPSILON;
/// Splits one interval may take (events, or a copy meeting one early): an accumulation of
/// impacts (e = 0.5 halves the speed each time, some 30 before the Zeno guard ends it) fits;
/// beyond, the rest of the interval is taken by the trapezoidal rule.
const DEPTH: u32 = 64;
/// Roller intervals per revolution: about four of the thesis's steps (0.005 rad) each.
const ROLLER_SAMPLES: usize = 320;
/// Crank-train sampling interval, s: the RK4 step in flight.
const CRANK_INTERVAL: f64 = 1e-4;
const TOLERANCE: f64 = 1e-5;

/// Integrands: drive, gas, damping and friction power, and the scale |drive| + |gas| + damping +
/// friction, W.
type Powers = [f64; 5];

fn powers(model: &impl EnergyBalance) -> Powers {
    let p = model.power_flows();
    [p.drive, p.gas, p.damping, p.friction + p.film, p.drive.abs() + p.gas.abs() + p.damping + p.friction + p.film]
}

fn add(total: &mut Powers, part: Powers) {
    total.iter_mut().zip(part).for_each(|(t, p)| *t += p);
}

fn rule(weights: &[f64], at: &[Powers], scale: f64) -> Powers {
    std::array::from_fn(|k| scale * weights.iter().zip(at).map(|(w, p)| w * p[k]).sum::<f64>())
}

fn simpson(a: Powers, middle: Powers, b: Powers, h: f64) -> Powers {
    rule(&[1.0, 4.0, 1.0], &[a, middle, b], h / 6.0)
}

fn trapezoid(a: Powers, b: Powers, h: f64) -> Powers {
    rule(&[1.0, 1.0], &[a, b], h / 2.0)
}

/// The powers of a copy of the model advanced to `t` (a midpoint on the same RK4 step).
fn probe<Mo: Mechanism + EnergyBalance>(mut copy: Mo, inputs: &Inputs, t: f64) -> Result<Powers, String> {
    copy.advance(inputs, t, &mut Vec::new()).map_err(|e| e.0)?;
    Ok(powers(&copy))
}

/// A model advanced with held inputs, the powers at its current time and the events since the window began.
struct Run<Mo> {
    model: Mo,
    inputs: Inputs,
    now: Powers,
    events: Vec<EngineEvent>,
    /// Events split out of their interval, and intervals left to the trapezoidal rule at
    /// `DEPTH`, for the report.
    splits: u64,
    trapezoids: u64,
}

impl<Mo: Mechanism + EnergyBalance> Run<Mo> {
    fn new(model: Mo, inputs: Inputs, t0: f64) -> Result<Self, String> {
        let mut run = Self { model, inputs, now: [0.0; 5], events: Vec::new(), splits: 0, trapezoids: 0 };
        run.model.advance(&run.inputs, t0, &mut run.events).map_err(|e| e.0)?;
        run.now = powers(&run.model);
        Ok(run)
    }

    fn advance(&mut self, t: f64) -> Result<(), String> {
        self.model.advance(&self.inputs, t, &mut self.events).map_err(|e| e.0)
    }

    /// Advances from `t0` to `t1` (`n` intervals, `n` even) and returns ∫ powers dt: Simpson on
    /// pairs of intervals without an event; an interval with one is split at it.
    fn integrate(&mut self, t0: f64, t1: f64, n: usize) -> Result<Powers, String> {
        let h = (t1 - t0) / n as f64;
        let at = |k: usize| if k == n { t1 } else { t0 + k as f64 * h };
        let mut total = [0.0; 5];
        for k in (0..n).step_by(2) {
            let (a, m, b) = (at(k), at(k + 1), at(k + 2));
            let (copy, start, seen) = (self.model.clone(), self.now, self.events.len());
            self.advance(m)?;
            if self.events.len() > seen {
                add(&mut total, self.through_event(a, m, copy, start, seen)?);
                add(&mut total, self.interval(m, b, 0)?);
                continue;
            }
            let (half, middle, seen) = (self.model.clone(), powers(&self.model), self.events.len());
            self.advance(b)?;
            if self.events.len() > seen {
                add(&mut total, simpson(start, probe(copy, &self.inputs, 0.5 * (a + m))?, middle, m - a));
                add(&mut total, self.through_event(m, b, half, middle, seen)?);
                continue;
            }
            self.now = powers(&self.model);
            add(&mut total, simpson(start, middle, self.now, b - a));
        }
        Ok(total)
    }

    /// ∫ over `[a, b]`, which the model has just crossed from `copy` through events (`around_event`).
    fn through_event(&mut self, a: f64, b: f64, copy: Mo, start: Powers, seen: usize) -> Result<Powers, String> {
        let (mut total, rest) = self.around_event(a, b, copy, start, seen, 0)?;
        if let Some((from, depth)) = rest {
            add(&mut total, self.interval(from, b, depth)?);
        }
        Ok(total)
    }

    /// ∫ over `[a, b]` from the model at `a`: Simpson with the midpoint from a copy if no event
    /// happens, else split at each event in turn.
    fn interval(&mut self, mut a: f64, b: f64, mut depth: u32) -> Result<Powers, String> {
        let mut total = [0.0; 5];
        loop {
            let (copy, start, seen) = (self.model.clone(), self.now, self.events.len());
            self.advance(b)?;
            if self.events.len() == seen {
                self.now = powers(&self.model);
                add(&mut total, simpson(start, probe(copy, &self.inputs, 0.5 * (a + b))?, self.now, b - a));
                return Ok(total);
            }
            let (part, rest) = self.around_event(a, b, copy, start, seen, depth)?;
            add(&mut total, part);
            match rest {
                Some((from, next)) => (a, depth) = (from, next),
                None => return Ok(total),
            }
        }
    }

    /// ∫ over `[a, b]`, which the model has just crossed from `copy` (powers `start`) through the
    /// events from `seen` on. Copies advanced from `copy` give the powers just before the first
    /// event and just after it (they take the same RK4 steps up to it, so they meet it at the
    /// same time) and the midpoints: Simpson on either side, the trapezoidal rule over the `2δ`
    /// across it. If more events follow in `[a, b]`, the model becomes the copy just after the
    /// first, and the rest of the interval is left to the caller: `Some((from, depth))`.
    fn around_event(
        &mut self,
        a: f64,
        b: f64,
        copy: Mo,
        start: Powers,
        seen: usize,
        depth: u32,
    ) -> Result<(Powers, Option<(f64, u32)>), String> {
        self.splits += 1;
        let end = powers(&self.model);
        if depth == DEPTH {
            self.trapezoids += 1;
            self.now = end;
            return Ok((trapezoid(start, end, b - a), None));
        }
        let event = self.events[seen].time;
        let more = self.events[seen..].iter().any(|e| e.time > event);
        let delta = (SPLIT * (b - a)).max(RESOLUTION * event.abs());
        let (before, after) = ((event - delta).max(a), (event + delta).min(b));
        let (mut total, mut pre, mut early) = ([0.0; 5], copy, Vec::new());
        if before > a {
            let middle = probe(pre.clone(), &self.inputs, 0.5 * (a + before))?;
            pre.advance(&self.inputs, before, &mut early).map_err(|e| e.0)?;
            total = simpson(start, middle, powers(&pre), before - a);
        }
        if !early.is_empty() {
            // The copy met the event before `before` (a rare slow approach): go on from it.
            self.events.truncate(seen);
            self.events.append(&mut early);
            self.now = powers(&pre);
            self.model = pre;
            return Ok((total, Some((before, depth + 1))));
        }
        let last = powers(&pre);
        if !more && after == b {
            self.now = end;
            add(&mut total, trapezoid(last, end, b - before));
            return Ok((total, None));
        }
        let (mut post, mut met) = (pre, Vec::new());
        post.advance(&self.inputs, after, &mut met).map_err(|e| e.0)?;
        let first = powers(&post);
        add(&mut total, trapezoid(last, first, after - before));
        if more || met.len() != self.events[seen..].len() {
            // More events to come, or the copy met this one other than the model did (outside
            // `2δ`): go on from the copy.
            self.events.truncate(seen);
            self.events.append(&mut met);
            (self.model, self.now) = (post, first);
            return Ok((total, (after < b).then_some((after, depth + 1))));
        }
        self.now = end;
        add(&mut total, simpson(first, probe(post, &self.inputs, 0.5 * (after + b))?, end, b - after));
        Ok((total, None))
    }

    /// One window of the balance: its error relative to the window's scale.
    fn window(&mut self, t0: f64, t1: f64, n: usize) -> Result<f64, String> {
        let (energy, work) = (self.model.mechanical_energy(), self.model.impulse_work());
        self.events.clear();
        let [drive, gas, damping, friction, scale] = self.integrate(t0, t1, n)?;
        let dissipated: f64 = self.events.iter().map(|e| e.energy_lost).sum();
        let impulsive = self.model.impulse_work() - work;
        let error = self.model.mechanical_energy() - energy - (drive + gas - damping - friction - dissipated + impulsive);
        let relative = error / (scale + dissipated + impulsive.abs());
        if !relative.is_finite() || relative.abs() > TOLERANCE {
            return Err(format!(
                "energy balance error {relative:.3e} at t = {t1} s: ΔE {:.6e} J, drive {drive:.6e}, gas {gas:.6e}, \
                 damping {damping:.6e}, friction {friction:.6e}, impacts {dissipated:.6e}, impulsive drive {impulsive:.6e}",
                self.model.mechanical_energy() - energy
            ));
        }
        Ok(relative)
    }
}

/// Runs `windows` windows of `period` s, `n` samples each, with progress output; returns the worst error.
#[allow(clippy::too_many_arguments)]
fn soak<Mo: Mechanism + EnergyBalance>(
    name: &str,
    mut run: Run<Mo>,
    t0: f64,
    windows: u64,
    period: f64,
    n: usize,
    failed: &AtomicBool,
) -> Result<(), String> {
    let (start, mut worst, mut events) = (Instant::now(), 0.0_f64, 0usize);
    for w in 1..=windows {
        if failed.load(Ordering::Relaxed) {
            return Err(format!("{name}: stopped at window {w}, the other part failed"));
        }
        let (from, to) = (t0 + (w - 1) as f64 * period, t0 + w as f64 * period);
        let error = run.window(from, to, n).map_err(|e| format!("{name}, window {w}: {e}"))?;
        worst = worst.max(error.abs());
        events += run.events.len();
        if w % (windows / 20).max(1) == 0 {
            let wall = start.elapsed().as_secs_f64();
            eprintln!(
                "{name}: {w}/{windows}, {wall:.0} s wall (projected {:.0} s), {events} events, {} split, \
                 error {error:.1e} (worst {worst:.2e})",
                wall * windows as f64 / w as f64,
                run.splits
            );
        }
    }
    println!(
        "{name}: {windows} windows, {events} events, worst energy-balance error {worst:.2e} (tolerance {TOLERANCE:e}), \
         {} intervals past {DEPTH} splits, {:.0} s wall",
        run.trapezoids,
        start.elapsed().as_secs_f64()
    );
    Ok(())
}

/// Intervals per window: the first even count whose interval is within the integrator's step.
fn samples(period: f64, step: f64) -> usize {
    let n = (period / step).floor() as usize + 1;
    n + n % 2
}

fn main() -> Result<(), String> {
    let mut args = std::env::args().skip(1).map(|a| a.parse::<f64>().map_err(|e| e.to_string()));
    let cycles = args.next().transpose()?.unwrap_or(1e4) as u64;
    let revolutions = args.next().transpose()?.unwrap_or(1e6) as u64;
    // The roller runs longest: beside the two crank trains, one after the other. The first error
    // stops both.
    let failed = AtomicBool::new(false);
    let stop_on_error = |result: Result<(), String>| {
        if let Err(e) = &result {
            eprintln!("{e}");
            failed.store(true, Ordering::Relaxed);
        }
        result
    };
    std::thread::scope(|scope| {
        let roller = scope.spawn(|| stop_on_error(roller(revolutions, &failed)));
        let cranks = stop_on_error(crank_trains(cycles, &failed));
        let roller = roller.join().map_err(|_| "the roller's thread panicked".to_string())?;
        cranks.and(roller)
    })
}

fn crank_trains(cycles: u64, failed: &AtomicBool) -> Result<(), String> {
    let inputs = Inputs::default();
    let cycle = 4.0 * PI / inputs.crank_speed;
    let n = samples(cycle, CRANK_INTERVAL);
    let params = Parameters::default();
    let prescribed = Run::new(CrankTrain::new(&params, 0.0).map_err(|e| e.0)?, inputs.clone(), 0.0)?;
    soak("crank train, prescribed crank", prescribed, 0.0, cycles, cycle, n, failed)?;

    let rubbing = Parameters { friction: 0.1, gravity_lateral: 9.81, ..Parameters::default() };
    let frictional = Run::new(CrankTrain::new(&rubbing, 0.0).map_err(|e| e.0)?, inputs.clone(), 0.0)?;
    soak("crank train, liner friction", frictional, 0.0, cycles, cycle, n, failed)?;

    let base = Parameters { crank_mode: 2, ..Parameters::default() };
    let geometry = SliderCrank { crank_radius: base.crank_radius, rod_length: base.rod_length, pin_offset: 0.0 };
    let curve = FourStrokePressure::new(base.peak_pressure, base.rod_length / base.crank_radius);
    let area = 0.25 * PI * base.piston_diameter.powi(2);
    let cal = EfficiencyTarget::default().calibrate(&geometry, area, |a| curve.gauge(a)).map_err(|e| e.0)?;
    let params = Parameters { damping_main: cal.damping[0], damping_crank_pin: cal.damping[1], damping_piston_pin: cal.damping[2], ..base };
    let free = Run::new(CrankTrain::new(&params, 0.0).map_err(|e| e.0)?, Inputs { load_torque: cal.load_torque, ..inputs }, 0.0)?;
    soak("crank train, free crank", free, 0.0, cycles, cycle, n, failed)
}

fn roller(revolutions: u64, failed: &AtomicBool) -> Result<(), String> {
    let inputs = Inputs::default();
    let revolution = 2.0 * PI / inputs.crank_speed;
    // The roller takes its crank speed, and so its energy scale, at its first step.
    let first = 1e-3 * revolution;
    let roller = Run::new(Roller::new(&Parameters { model_variant: 2, ..Parameters::default() }, 0.0).map_err(|e| e.0)?, inputs, first)?;
    soak("roller", roller, first, revolutions, revolution, ROLLER_SAMPLES, failed)
}
