//! Landings: the piston's arrivals on a wall after it left the other, however the wall carries it
//! (corners, asperities or film), with what engineers read of each: the crank angle, the leading
//! skirt end, the kinetic energy of lateral motion and tilt at the start and its largest value during
//! the approach, the energy the landing took from that motion, the peak wall load and its rise rate.
//!
//! A landing starts at the first impact or slide of a corner on the other wall than the one carrying
//! the piston (exact, from the event rows). Where no event says so, the other wall's load coming to
//! exceed the carrying wall's (taken linearly between two communication points) says that the side
//! changed: the piston, at rest across the bore then, is pushed over and lands on the new wall's
//! film, which takes its energy gradually; the landing starts where the lateral motion's kinetic
//! energy peaks between the crossing and the wall's peak load (the communication point of that
//! peak). The first arrival after the start only sets the carrying wall. A landing lasts from its side
//! change (the impact, or the crossing) to the next. Its loss is its impacts' losses on its wall (normal
//! and friction), and for a landing on the film the drop of the lateral kinetic energy from the start
//! to its least value before the wall's load peaks: what the film took of the arrival, not the
//! work it goes on taking from the side force that presses the piston into it. On a dry skirt the
//! loss is the sum of its impacts' `energy_lost`. Loads and their rise rates are read at the
//! communication points.
//!
//! Cycles are centred on firing TDC (−360° to 360°). A landing counts in the cycle it starts in; a
//! cycle is complete once the crank is past it and its last landing has ended.

use super::csv_log::{CsvLog, Rows};
use crate::fmus::piston_slap::Outputs;
use crate::models::numerics::floor_to_i64;
use crate::models::{EngineEvent, EngineEventKind, ModelError, CYCLE};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// A wall: 0 anti-thrust (−D/2, corners K1, K2), 1 major thrust (+D/2, K3, K4).
type Wall = usize;

fn wall_of(corner: u8) -> Wall {
    usize::from(corner > 2)
}

/// The cycle centred on firing TDC that an accumulated crank angle lies in.
fn cycle_of(angle: f64) -> i64 {
    floor_to_i64((angle + 0.5 * CYCLE) / CYCLE)
}

/// An accumulated crank angle as rad in [−2π, 2π) from firing TDC.
pub fn from_firing_tdc(angle: f64) -> f64 {
    (angle + 2.0 * PI).rem_euclid(CYCLE) - 2.0 * PI
}

/// What a landing is read from at one instant.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
struct Point {
    /// s, and rad accumulated.
    time: f64,
    angle: f64,
    /// N, [anti-thrust, thrust].
    loads: [f64; 2],
    /// J, `lateral_kinetic_energy`.
    kinetic: f64,
    /// m, the skirt top's lateral position less the bottom's.
    lean: f64,
}

impl Point {
    fn of(time: f64, o: &Outputs) -> Self {
        Self {
            time,
            angle: o.crank_angle,
            loads: [o.liner_force_antithrust, o.liner_force_thrust],
            kinetic: o.lateral_kinetic_energy,
            lean: o.skirt_top_lateral - o.skirt_bottom_lateral,
        }
    }

    /// The point a fraction `s` of the way to `to`.
    fn toward(&self, to: &Self, s: f64) -> Self {
        let at = |a: f64, b: f64| a + (b - a) * s;
        Self {
            time: at(self.time, to.time),
            angle: at(self.angle, to.angle),
            loads: [at(self.loads[0], to.loads[0]), at(self.loads[1], to.loads[1])],
            kinetic: at(self.kinetic, to.kinetic),
            lean: at(self.lean, to.lean),
        }
    }
}

/// One landing, its figures so far (final once it ended).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Landing {
    /// s: its start.
    time: f64,
    /// rad, accumulated: its start.
    angle: f64,
    wall: Wall,
    /// Whether the skirt's top end leads (is nearer the wall) at the start.
    top_leads: bool,
    /// J, lateral kinetic energy at the start.
    kinetic: f64,
    /// J, its largest value during the approach.
    approach: f64,
    /// J, its impacts' losses.
    impact_loss: f64,
    /// J, the lateral kinetic energy's least value after the start, up to the wall's load peak.
    settling: f64,
    /// J, the energy it took from the lateral motion and tilt (set when it ends).
    loss: f64,
    /// N, the wall's peak load, and rad (accumulated) where.
    peak: f64,
    peak_angle: f64,
    /// N/s, its peak rise rate.
    peak_rate: f64,
    /// Impacts on its wall.
    impacts: i32,
    /// s, where it ended (the next landing's side change).
    end: f64,
    /// Found by the loads' crossing: the point of the largest lateral kinetic energy since, and the
    /// least after it, which become the start and the settled energy where the wall's load peaks.
    arrival: Option<(Point, f64)>,
}

impl Landing {
    fn start(at: &Point, wall: Wall, top_leads: bool, kinetic: f64, approach: f64) -> Self {
        Self {
            time: at.time,
            angle: at.angle,
            wall,
            top_leads,
            kinetic,
            approach: approach.max(kinetic),
            settling: kinetic,
            peak_angle: at.angle,
            ..Self::default()
        }
    }
}

/// Whether the skirt's top end is the nearer to `wall` at `p`.
fn leads(p: &Point, wall: Wall) -> bool {
    if wall == 1 {
        p.lean > 0.0
    } else {
        p.lean < 0.0
    }
}

/// The landing figures of one cycle, per wall [anti-thrust, thrust]: landings, the largest's energy,
/// loss and crank angle (rad from firing TDC), the peak load and rise rate.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
struct CycleFigures {
    landings: [i32; 2],
    energy: [f64; 2],
    loss: [f64; 2],
    angle: [f64; 2],
    peak: [f64; 2],
    rate: [f64; 2],
}

impl CycleFigures {
    fn add(&mut self, l: &Landing) {
        let w = l.wall;
        self.landings[w] = self.landings[w].saturating_add(1);
        if self.landings[w] == 1 || l.kinetic > self.energy[w] {
            (self.energy[w], self.loss[w], self.angle[w]) = (l.kinetic, l.loss, from_firing_tdc(l.angle));
        }
    }

    fn load(&mut self, loads: [f64; 2], rates: [f64; 2]) {
        for w in 0..2 {
            self.peak[w] = self.peak[w].max(loads[w]);
            self.rate[w] = self.rate[w].max(rates[w]);
        }
    }
}

/// The landing detector's state: the carrying wall, the landing in progress, the cycles' figures.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Landings {
    /// The last communication point (none before the first).
    last: Option<Point>,
    /// The wall carrying the piston, none before the first arrival.
    wall: Option<Wall>,
    current: Option<Landing>,
    /// The point of the largest lateral kinetic energy since the landing in progress last peaked in load.
    approach: Option<Point>,
    /// The cycle whose figures are being gathered, its figures, and the loads of the points past it
    /// while its last landing is still in progress.
    cycle: i64,
    open: CycleFigures,
    next: CycleFigures,
    /// The last completed cycle's figures.
    completed: CycleFigures,
}

impl Landings {
    /// Takes the point `(time, outputs)` as the last, without a step (the start, or a state prepared again).
    pub fn seat(&mut self, time: f64, outputs: &Outputs) {
        let now = Point::of(time, outputs);
        if self.last.is_none() {
            self.cycle = cycle_of(now.angle);
        }
        self.last = Some(now);
        self.approach = Some(now);
    }

    /// Takes in one communication step: its `events`, and the point `(time, outputs)` it ends at
    /// (the model's outputs written). Landings that end in it are pushed onto `ended`.
    pub fn record(&mut self, events: &[EngineEvent], time: f64, outputs: &Outputs, ended: &mut Vec<Landing>) {
        let now = Point::of(time, outputs);
        let last = self.last.unwrap_or(now);
        let mut landed = false;
        for e in events.iter().filter(|e| matches!(e.kind, EngineEventKind::Impact | EngineEventKind::Slide)) {
            let wall = wall_of(e.corner);
            if self.wall.is_some_and(|w| w != wall) {
                let s = if now.time > last.time { (e.time - last.time) / (now.time - last.time) } else { 1.0 };
                let at = Point { time: e.time, angle: e.cycle as f64 * CYCLE + e.crank_angle, ..last.toward(&now, s.clamp(0.0, 1.0)) };
                self.land(&at, wall, e.corner % 2 == 1, e.lateral_kinetic_energy, ended);
                landed = true;
            }
            self.wall = Some(wall);
            if let Some(l) = self.current.as_mut().filter(|l| l.wall == wall && e.kind == EngineEventKind::Impact) {
                l.impact_loss += e.energy_lost;
                l.impacts = l.impacts.saturating_add(1);
            }
        }
        // Where no event landed: the other wall's load exceeding the carrying wall's.
        let loaded = |p: &Point| (p.loads[0] != p.loads[1]).then(|| usize::from(p.loads[1] > p.loads[0]));
        match (self.wall, loaded(&now)) {
            (None, wall) => self.wall = self.wall.or(wall),
            (Some(w), Some(other)) if other != w && !landed => {
                // Where the loads' difference crosses zero, linearly between the points.
                let d = |p: &Point| p.loads[other] - p.loads[w];
                let s = if d(&last) < 0.0 { d(&last) / (d(&last) - d(&now)) } else { 0.0 };
                let at = last.toward(&now, s);
                self.land(&at, other, leads(&at, other), at.kinetic, ended);
                if let Some(l) = self.current.as_mut() {
                    l.arrival = Some((at, at.kinetic));
                }
                self.wall = Some(other);
            }
            _ => {}
        }
        self.take_point(&last, &now);
    }

    /// Every wall named is one of the two (a restored state's too).
    pub fn check(&self) -> Result<(), ModelError> {
        let walls = [self.wall, self.current.map(|l| l.wall)];
        match walls.into_iter().flatten().find(|&w| w > 1) {
            Some(w) => Err(ModelError(format!("landing on wall {w}: the walls are 0 (anti-thrust) and 1 (thrust)"))),
            None => Ok(()),
        }
    }

    /// Ends the landing in progress at `at` and starts one on `wall` there.
    fn land(&mut self, at: &Point, wall: Wall, top_leads: bool, kinetic: f64, ended: &mut Vec<Landing>) {
        if let Some(mut l) = self.current.take() {
            // Found by the loads, the landing took what its arrival's kinetic energy lost.
            let cushioned = if l.arrival.is_some() { l.kinetic - l.settling } else { 0.0 };
            l.loss = l.impact_loss + cushioned;
            l.end = at.time;
            self.finish(&l);
            ended.push(l);
        }
        let approach = self.approach.map_or(0.0, |a| a.kinetic);
        self.current = Some(Landing::start(at, wall, top_leads, kinetic, approach));
        self.approach = None;
    }

    /// Counts an ended landing in its cycle, completing the cycles before it.
    fn finish(&mut self, l: &Landing) {
        self.complete_before(cycle_of(l.angle));
        if cycle_of(l.angle) == self.cycle {
            self.open.add(l);
        }
    }

    /// Completes the cycles before `cycle`: the gathered one's figures become the completed ones,
    /// those of cycles passed without points are zero.
    fn complete_before(&mut self, cycle: i64) {
        while self.cycle < cycle {
            self.completed = std::mem::replace(&mut self.open, std::mem::take(&mut self.next));
            self.cycle += 1;
        }
    }

    /// The step from `last` to `now`: the landing in progress's peak load and rise rate, the cycles'
    /// loads, the approach, and the cycles the crank has passed whose last landing has ended.
    fn take_point(&mut self, last: &Point, now: &Point) {
        let dt = now.time - last.time;
        let rates: [f64; 2] = std::array::from_fn(|w| if dt > 0.0 { (now.loads[w] - last.loads[w]) / dt } else { 0.0 });
        if self.approach.is_none_or(|a| now.kinetic > a.kinetic) {
            self.approach = Some(*now);
        }
        if let Some(l) = self.current.as_mut() {
            if let Some((largest, least)) = l.arrival.as_mut() {
                if now.kinetic > largest.kinetic {
                    (*largest, *least) = (*now, now.kinetic);
                } else {
                    *least = least.min(now.kinetic);
                }
            }
            l.peak_rate = l.peak_rate.max(rates[l.wall]);
            if now.loads[l.wall] > l.peak {
                (l.peak, l.peak_angle) = (now.loads[l.wall], now.angle);
                self.approach = Some(*now);
                // On the film the landing starts where the arrival's kinetic energy peaked before the load did.
                if let Some((at, least)) = l.arrival {
                    (l.time, l.angle, l.kinetic, l.top_leads) = (at.time, at.angle, at.kinetic, leads(&at, l.wall));
                    (l.approach, l.settling) = (l.approach.max(at.kinetic), least);
                }
            }
        }
        let cycle = cycle_of(now.angle);
        let waiting = self.current.is_some_and(|l| cycle_of(l.angle) <= self.cycle);
        if !waiting {
            self.complete_before(cycle);
        }
        if cycle == self.cycle { &mut self.open } else { &mut self.next }.load(now.loads, rates);
        self.last = Some(*now);
    }

    /// Writes the last completed cycle's figures.
    pub fn write(&self, out: &mut Outputs) {
        let c = &self.completed;
        [out.cycle_landings_antithrust, out.cycle_landings_thrust] = c.landings;
        [out.cycle_landing_energy_antithrust, out.cycle_landing_energy_thrust] = c.energy;
        [out.cycle_landing_loss_antithrust, out.cycle_landing_loss_thrust] = c.loss;
        [out.cycle_landing_crank_angle_antithrust, out.cycle_landing_crank_angle_thrust] = c.angle;
        [out.cycle_max_liner_force_antithrust, out.cycle_max_liner_force_thrust] = c.peak;
        [out.cycle_max_liner_force_rate_antithrust, out.cycle_max_liner_force_rate_thrust] = c.rate;
    }
}

/// The landing log's rows: one per ended landing.
#[derive(Clone, Debug, PartialEq)]
pub struct Landed;

impl Rows for Landed {
    type Row = Landing;
    const PARAMETER: &'static str = "landing_log";
    const HEADER: &'static str = "# SI units; crank angles [rad] in [-2π, 2π) from firing TDC; kinetic energies of the piston's lateral motion and tilt\n\
time,crank_angle,wall,leading_end,kinetic_energy,max_approach_kinetic_energy,energy_loss,peak_force,peak_force_crank_angle,peak_force_rate,impacts,end_time\n";

    fn row(l: &Landing) -> String {
        format!(
            "{},{},{},{},{},{},{},{},{},{},{},{}\n",
            l.time,
            from_firing_tdc(l.angle),
            ["antithrust", "thrust"][l.wall],
            if l.top_leads { "top" } else { "bottom" },
            l.kinetic,
            l.approach,
            l.loss,
            l.peak,
            from_firing_tdc(l.peak_angle),
            l.peak_rate,
            l.impacts,
            l.end
        )
    }
}

/// The open landing log.
pub type LandingLog = CsvLog<Landed>;
