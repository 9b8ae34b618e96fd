//! Seeded random physical designs of the crank train's two families: engines (prescribed crank,
//! the built-in gas pressure) and light sliders of the Flores–Leine–Glocker kind (free crank, no
//! gas). Every design is one a user could type in: lengths, masses and clearances of real
//! mechanisms, restitution anywhere in [0, 1].

use super::output_checks::{self, GAP_TOLERANCE};
use pistonslap::fmus::piston_slap::Mechanism;
use pistonslap::fmus::piston_slap::{InputDerivatives, Inputs, Outputs, Parameters};
use pistonslap::models::{CrankTrain, EngineEvent, EngineEventKind, EngineModel, Roller, StepInputs};
use std::f64::consts::PI;

/// The published parameters mapped onto the crank train (the benchmark file's table), frictionless
/// and without gravity; the slider's centre of mass `com` off the pin.
pub fn flores(com: f64) -> Parameters {
    Parameters {
        crank_mode: 2,
        pressure_source: 1,
        crank_radius: 0.153,
        rod_length: 0.306,
        crank_com: 0.0765,
        rod_com: 0.153,
        piston_com: com,
        crank_mass: 0.038,
        rod_mass: 0.038,
        piston_mass: 0.076,
        crank_inertia: 7.4e-5,
        rod_inertia: 5.9e-4,
        piston_inertia: 2.7e-6,
        piston_diameter: 0.05,
        skirt_length: 0.1,
        pin_height: 0.05,
        bore: 0.052,
        restitution: 0.4,
        damping_main: 0.0,
        damping_crank_pin: 0.0,
        damping_piston_pin: 0.0,
        gravity: 0.0,
        ..Parameters::default()
    }
}

/// SplitMix64: a seeded, portable stream of uniform numbers in [0, 1).
pub struct Random(u64);

impl Random {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }
    pub fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        (z ^ (z >> 31)) as f64 / 2f64.powi(64)
    }
    pub fn between(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

/// A design, the inputs it runs with (their values at the start and their time derivatives, as a host
/// sets them with fmi2SetRealInputDerivatives; zero: held), and how long and in what steps it is run:
/// `step` each, or, `variable`, each drawn from 0.1–3 times `step` (log-uniform, seeded by `step`).
#[derive(Clone, Debug)]
pub struct Design {
    pub params: Parameters,
    pub inputs: Inputs,
    pub derivatives: InputDerivatives,
    pub duration: f64,
    pub step: f64,
    pub variable: bool,
}

impl Design {
    /// The design with its crank speed ramping by up to ±20 % and its gas pressure input by up to ±50 %
    /// over the run, at constant rates drawn from `r`, curvature included (a host's second derivatives),
    /// in communication steps of variable length.
    fn ramped(self, r: &mut Random) -> Self {
        let (u, t) = (&self.inputs, self.duration);
        let [speed_rate, pressure_rate] = [u.crank_speed * r.between(-0.2, 0.2) / t, u.gas_pressure * r.between(-0.5, 0.5) / t];
        let derivatives = InputDerivatives {
            crank_speed: [speed_rate, speed_rate * r.between(-0.1, 0.1) / t],
            gas_pressure: [pressure_rate, 0.0],
            load_torque: [0.0, 0.0],
        };
        Self { derivatives, variable: true, ..self }
    }

    /// The communication points after the start: every `step` up to the first at or past `duration`.
    pub fn points(&self) -> Vec<f64> {
        if !self.variable {
            return (1..=(self.duration / self.step).ceil() as usize).map(|k| k as f64 * self.step).collect();
        }
        let (mut lengths, mut points) = (Random::new(self.step.to_bits()), vec![0.0]);
        while points[points.len() - 1] < self.duration {
            points.push(points[points.len() - 1] + self.step * libm::pow(30.0, lengths.next()) / 10.0);
        }
        points.split_off(1)
    }

    /// The inputs a host sets at time `t`: the start values followed along their derivatives.
    pub fn inputs_at(&self, t: f64) -> Inputs {
        let inputs = self.derivatives.polynomials(&self.inputs, 0.0);
        Inputs { crank_speed: inputs.crank_speed.at(t), gas_pressure: inputs.gas_pressure.at(t), load_torque: inputs.load_torque.at(t) }
    }
}

/// An engine: 600–6000 rpm, 2–12 MPa peak pressure, 10–200 µm clearance, a pin offset up to 2 % of
/// the diameter, the links scaled around the defaults; two four-stroke cycles.
pub fn engine(r: &mut Random) -> Design {
    let d = r.between(0.06, 0.11);
    let skirt = d * r.between(0.5, 1.1);
    let pin_height = skirt * r.between(0.3, 0.7);
    let crank_radius = r.between(0.03, 0.06);
    let piston_mass = r.between(0.2, 1.0);
    let rod_mass = r.between(0.5, 1.5);
    let rod_length = crank_radius * r.between(2.8, 4.5);
    let speed = r.between(600.0, 6000.0) * PI / 30.0;
    let params = Parameters {
        peak_pressure: r.between(2e6, 12e6),
        crank_radius,
        rod_length,
        rod_com: rod_length * r.between(0.6, 0.8),
        piston_com: pin_height * r.between(-0.3, 0.6),
        rod_mass,
        piston_mass,
        rod_inertia: rod_mass * rod_length * rod_length * r.between(0.05, 0.12),
        piston_inertia: piston_mass * (d * d + skirt * skirt) / 12.0 * r.between(0.5, 1.5),
        piston_diameter: d,
        skirt_length: skirt,
        pin_height,
        bore: d + r.between(10e-6, 200e-6),
        pin_offset: d * r.between(-0.02, 0.02),
        restitution: r.next(),
        ..Parameters::default()
    };
    let inputs = Inputs { crank_speed: speed, ..Inputs::default() };
    let step = [1e-3, 1e-4][(r.next() * 2.0) as usize];
    Design { params, inputs, derivatives: InputDerivatives::default(), duration: 2.0 * 4.0 * PI / speed, step, variable: false }
}

/// A light slider of the Flores benchmark's kind: its published links, a free crank started at
/// 50–300 rad/s, no gas, no damping, the slider's centre of mass anywhere from −0.02 to 0.02 m off
/// the pin, 0.1–2 mm clearance each side; 0.1 s.
pub fn slider(r: &mut Random) -> Design {
    let com = r.between(-0.02, 0.02);
    let params = Parameters { bore: 0.05 + 2.0 * r.between(1e-4, 2e-3), restitution: r.next(), ..flores(com) };
    let inputs = Inputs { crank_speed: r.between(50.0, 300.0), gas_pressure: 0.0, load_torque: 0.0 };
    Design {
        params,
        inputs,
        derivatives: InputDerivatives::default(),
        duration: 0.1,
        step: [1e-3, 1e-4][(r.next() * 2.0) as usize],
        variable: false,
    }
}

/// An engine with liner friction μ ∈ [0, 0.3] and a cylinder tilted from the vertical (lateral
/// gravity up to ±9.81 m/s²).
pub fn rubbing_engine(r: &mut Random) -> Design {
    let design = engine(r);
    let params = Parameters { friction: r.between(0.0, 0.3), gravity_lateral: r.between(-9.81, 9.81), ..design.params };
    Design { params, ..design }
}

/// An engine on a lubricated skirt: oil of 2–20 mPa·s, each side 50–90° of arc, a barrel dropping
/// up to 30 µm at either edge, running hot one time in two (`running_temperatures`); the Reynolds grid
/// coarse (6 × 8) to keep the family fast.
pub fn lubricated_engine(r: &mut Random) -> Design {
    let design = engine(r);
    let params = Parameters {
        skirt_model: 2,
        oil_viscosity: r.between(0.002, 0.02),
        skirt_arc: r.between(50.0, 90.0).to_radians(),
        skirt_profile: format!("parabola {:e} {:e}", r.between(0.0, 30e-6), r.between(0.0, 30e-6)),
        skirt_grid_circumferential: 6,
        skirt_grid_axial: 8,
        ..design.params
    };
    Design { params: running_temperatures(r, params), ..design }
}

/// A lubricated engine (`lubricated_engine`) whose film cavitates mass-conserving (`cavitation = 2`).
pub fn mass_conserving_engine(r: &mut Random) -> Design {
    let design = lubricated_engine(r);
    Design { params: Parameters { cavitation: 2, ..design.params }, ..design }
}

/// A lubricated engine (`lubricated_engine`) on the built-in elastic shell (`skirt_compliance = 1`): a
/// wall of 1.5–6 mm and a modulus of 40–200 GPa (from a soft aluminium alloy to steel), the film
/// cavitating mass-conserving one time in two.
pub fn elastic_engine(r: &mut Random) -> Design {
    let design = lubricated_engine(r);
    let params = Parameters {
        skirt_compliance: 1,
        skirt_wall_thickness: r.between(1.5e-3, 6e-3),
        skirt_modulus: r.between(40e9, 200e9),
        cavitation: 1 + i32::from(r.next() < 0.5),
        ..design.params
    };
    Design { params, ..design }
}

/// A mass-conserving engine (`mass_conserving_engine`) fed by a limited oil supply (`oil_supply = 2`)
/// of 0.2–20 µm on the liner: from far below the gaps (a starved skirt) to beyond the clearance.
pub fn limited_supply_engine(r: &mut Random) -> Design {
    let design = mass_conserving_engine(r);
    let liner_oil_film = libm::pow(10.0, r.between(-6.7, -4.7));
    Design { params: Parameters { oil_supply: 2, liner_oil_film, ..design.params }, ..design }
}

/// One time in two, `params` at running temperatures: an aluminium piston (18–24e-6 1/K) in an iron liner
/// (10–12e-6 1/K), the liner 0–100 K above a reference of 0–40 °C, the piston as hot as leaves 10–100 % of
/// the clearance (above or below the liner's temperature as that asks); otherwise as drawn (at the reference).
fn running_temperatures(r: &mut Random, params: Parameters) -> Parameters {
    if r.next() < 0.5 {
        return params;
    }
    let reference_temperature = 273.15 + r.between(0.0, 40.0);
    let (piston_expansion, liner_expansion) = (r.between(18e-6, 24e-6), r.between(10e-6, 12e-6));
    let liner_temperature = reference_temperature + r.between(0.0, 100.0);
    let hot_bore = params.bore * (1.0 + liner_expansion * (liner_temperature - reference_temperature));
    let hot_clearance = (params.bore - params.piston_diameter) * r.between(0.1, 1.0);
    let piston_rise = (hot_bore - hot_clearance - params.piston_diameter) / (params.piston_diameter * piston_expansion);
    Parameters {
        reference_temperature,
        liner_temperature,
        piston_temperature: reference_temperature + piston_rise,
        piston_expansion,
        liner_expansion,
        ..params
    }
}

/// A design of the declared space (`declared`) on a lubricated skirt over the film's own ranges: oil of
/// 0.1 mPa·s – 0.5 Pa·s, each side 10–180° of arc, a barrel dropping up to 3e-4 of the diameter at either
/// edge, ovality up to 2e-4 of it one time in two, roughness 0.05–5 µm with Greenwood–Tripp's ηβσ of
/// 0.001–1 and σ/β of 1e-5–0.1 (the accepted ranges), a composite modulus of
/// 10–300 GPa, boundary friction 0.001–1, a film relaxation of 10 µs – 0.1 ms and a grid of 2–12 × 2–16
/// nodes (coarse, to keep the family fast). Redrawn until the model accepts it.
pub fn lubricated_declared(r: &mut Random) -> Design {
    loop {
        let design = declared(r);
        let d = design.params.piston_diameter;
        let mut params = Parameters {
            skirt_model: 2,
            oil_viscosity: decades(r, 1e-4, 0.5),
            skirt_arc: r.between(10.0, 180.0).to_radians(),
            skirt_profile: format!("parabola {:e} {:e}", r.next() * 3e-4 * d, r.next() * 3e-4 * d),
            skirt_ovality: if r.next() < 0.5 { 0.0 } else { r.next() * 2e-4 * d },
            skirt_roughness: decades(r, 5e-8, 5e-6),
            composite_modulus: decades(r, 1e10, 3e11),
            boundary_friction: decades(r, 1e-3, 1.0),
            film_relaxation: decades(r, 1e-5, 1e-4),
            skirt_grid_circumferential: 2 + (r.next() * 11.0) as i32,
            skirt_grid_axial: 2 + (r.next() * 15.0) as i32,
            ..design.params
        };
        // Greenwood–Tripp's groups ηβσ and σ/β over their accepted ranges (`Roughness::validate`).
        let (group, ratio) = (decades(r, 1e-3, 1.0), decades(r, 1e-5, 0.1));
        params.asperity_radius = params.skirt_roughness / ratio;
        params.asperity_density = group / (params.asperity_radius * params.skirt_roughness);
        if CrankTrain::new(&params, 0.0).is_ok() {
            return Design { params, ..design };
        }
    }
}

/// A light slider with liner friction μ ∈ [0, 0.5] and a start tilting at up to ±1 rad/s.
pub fn rubbing_slider(r: &mut Random) -> Design {
    let design = slider(r);
    let params = Parameters { friction: r.between(0.0, 0.5), piston_tilt_rate_start: r.between(-1.0, 1.0), ..design.params };
    Design { params, ..design }
}

/// Log-uniform over [lo, hi], either end exactly one time in twenty.
fn decades(r: &mut Random, lo: f64, hi: f64) -> f64 {
    match r.next() {
        u if u < 0.05 => lo,
        u if u < 0.1 => hi,
        _ => lo * libm::pow(hi / lo, r.next()),
    }
}

/// A design of the declared space (as `declared` draws it from the same seed), its crank speed and gas
/// pressure inputs ramping (`Design::ramped`, drawn after the design).
pub fn declared_ramped(r: &mut Random) -> Design {
    let design = declared(r);
    design.ramped(r)
}

/// Any design of the declared space (the FMU documentation's "Declared space"): every model option
/// (crank mode, pressure source), 10–9000 rpm, diameters 1 cm – 1 m, clearances from the smallest
/// declared to 1 % of the diameter, rod ratios 1.5–5, masses over four decades within the declared
/// ratio, radii of gyration over the declared span, e and μ to the ends of their ranges, lateral
/// gravity of either sign; the range ends exactly one time in twenty. Redrawn until the model
/// accepts it (above the design's critical μ it is refused), run for up to two cycles or 0.2 s at a
/// communication step drawn from 1e-5–1e-2 s.
pub fn declared(r: &mut Random) -> Design {
    loop {
        let d = decades(r, 0.01, 1.0);
        let skirt = d * r.between(0.3, 1.5);
        let crank_radius = d * r.between(0.3, 1.0);
        let pin_offset = d * r.between(-0.05, 0.05);
        let rod_length = (crank_radius + pin_offset.abs()) * decades(r, 1.5, 5.0);
        let piston_mass = decades(r, 0.01, 100.0);
        let rod_mass = piston_mass * decades(r, 0.1, 10.0);
        let crank_mass = piston_mass * decades(r, 0.1, 1000.0);
        let inertia = |r: &mut Random, m: f64, length: f64, hi: f64| m * (length * decades(r, 0.05, hi)).powi(2);
        let speed = decades(r, 10.0, 9000.0) * PI / 30.0;
        let duration = (2.0 * 4.0 * PI / speed).min(0.2);
        let params = Parameters {
            crank_mode: 1 + (r.next() * 2.0) as i32,
            pressure_source: 1 + (r.next() * 3.0) as i32,
            pressure_trace: concat!(env!("CARGO_MANIFEST_DIR"), "/resources/full_load.csv").into(),
            peak_pressure: decades(r, 1e5, 2e7),
            crank_radius,
            rod_length,
            crank_com: crank_radius * r.between(-0.5, 0.5),
            rod_com: rod_length * r.next(),
            piston_com: skirt * r.between(-0.5, 0.5),
            piston_mass,
            rod_mass,
            crank_mass,
            piston_inertia: inertia(r, piston_mass, d, 1.0),
            rod_inertia: inertia(r, rod_mass, rod_length, 1.0),
            crank_inertia: inertia(r, crank_mass, crank_radius, 100.0),
            piston_diameter: d,
            skirt_length: skirt,
            pin_height: skirt * r.next(),
            bore: d + 2.0 * decades(r, 1e-6, 0.01 * d),
            pin_offset,
            restitution: decades(r, 1e-3, 1.0) * f64::from(r.next() > 0.05),
            friction: decades(r, 1e-3, 1.0) * f64::from(r.next() > 0.3),
            gravity_lateral: if r.next() < 0.5 { 0.0 } else { r.between(-9.81, 9.81) },
            ..Parameters::default()
        };
        let inputs = Inputs { crank_speed: speed, gas_pressure: decades(r, 1e4, 1e7), load_torque: 0.0 };
        let step = decades(r, 1e-5, 1e-2);
        if CrankTrain::new(&params, 0.0).is_ok() {
            return Design { params, inputs, derivatives: InputDerivatives::default(), duration, step, variable: false };
        }
    }
}

/// A declared design with nothing that does work on it: a free crank under no load, no gas, no
/// joint damping, no gravity, so that its kinetic energy changes only by what impacts and sliding
/// friction dissipate (`Finished::energy_balance`). Redrawn until the model accepts it in the free
/// crank mode (the critical μ depends on the mode).
pub fn declared_conservative(r: &mut Random) -> Design {
    loop {
        let design = declared(r);
        let params = Parameters {
            crank_mode: 2,
            pressure_source: 1,
            damping_main: 0.0,
            damping_crank_pin: 0.0,
            damping_piston_pin: 0.0,
            gravity: 0.0,
            gravity_lateral: 0.0,
            ..design.params
        };
        if CrankTrain::new(&params, 0.0).is_ok() {
            let inputs = Inputs { gas_pressure: 0.0, load_torque: 0.0, ..design.inputs };
            return Design { params, inputs, ..design };
        }
    }
}

/// A roller design (model_variant 2, Farahanchi's slider crank): a declared design (`declared`) as
/// `Roller::new` takes it, in communication steps of variable length: its crank turning at the held
/// speed, its walls frictionless and its cylinder vertical, either forcing, its crank-pin damping
/// λ = c₂/(M l² Ω) from 1e-3 to 1 (zero one time in twenty), any crank angle at the start; the
/// clearance `declared` draws (up to 1 % of the diameter) is within the 5 % of the rod length it accepts.
pub fn roller(r: &mut Random) -> Design {
    loop {
        let design = declared(r);
        let p = &design.params;
        let lambda = decades(r, 1e-3, 1.0) * f64::from(r.next() > 0.05);
        let params = Parameters {
            model_variant: 2,
            roller_forcing: 1 + (r.next() * 2.0) as i32,
            crank_mode: 1,
            friction: 0.0,
            gravity_lateral: 0.0,
            damping_crank_pin: lambda * p.piston_mass * p.rod_length * p.rod_length * design.inputs.crank_speed,
            crank_angle_start: r.between(0.0, 2.0 * PI),
            ..p.clone()
        };
        if Roller::new(&params, 0.0).is_ok() {
            return Design { params, variable: true, ..design };
        }
    }
}

/// What a finished run gives: its events, the kinetic energy at its start and end, and the
/// energy friction dissipated in persistent contact, J.
pub struct Finished {
    pub events: Vec<EngineEvent>,
    pub initial_energy: f64,
    pub final_energy: f64,
    pub sliding_friction: f64,
}

impl Finished {
    /// (T(0) − T(end) − dissipated) / T(0): zero for a design without damping, gas or gravity.
    pub fn energy_balance(&self) -> f64 {
        let dissipated: f64 = self.events.iter().map(|e| e.energy_lost).sum::<f64>() + self.sliding_friction;
        (self.initial_energy - self.final_energy - dissipated) / self.initial_energy
    }
}

/// What the outputs `now` after `before` and the step's `events` say against the model, if anything:
/// a corner outside the bore beyond `GAP_TOLERANCE` by the model's own gaps, what the outputs say
/// (`output_checks::contradiction`), an impact on a corner that was not approaching. (An impact's
/// loss is ≥ 0 as a whole, one e for all its corners; where two corners are struck at once each
/// event carries its own share, which the tangential impulses can make negative. The balance
/// counts them all.)
fn contradiction(model: &CrankTrain, params: &Parameters, before: &[f64], now: &[f64], events: &[EngineEvent]) -> Option<String> {
    let gap = model.gaps().min();
    let receding = events.iter().find(|e| e.kind == EngineEventKind::Impact && e.normal_velocity_before < 0.0);
    if gap < -GAP_TOLERANCE {
        Some(format!("a corner {gap:e} m outside the bore"))
    } else {
        output_checks::contradiction(params, before, now)
            .or_else(|| receding.map(|e| format!("an impact on a corner moving off the liner at {} m/s", -e.normal_velocity_before)))
    }
}

/// Whether `model` saved and restored continues to `t_end` as `model` does: the same events and outputs,
/// bit for bit (compared by their printed form, which shows every bit of an f64).
fn continues_after_a_round_trip(model: &CrankTrain, inputs: &StepInputs, t_end: f64) -> Result<(), String> {
    let bytes = postcard::to_allocvec(model).map_err(|e| format!("state not saved: {e}"))?;
    let mut restored: CrankTrain = postcard::from_bytes(&bytes).map_err(|e| format!("state not restored: {e}"))?;
    let mut original = model.clone();
    let continued = |m: &mut CrankTrain| {
        let mut events = Vec::new();
        let result = m.advance_interpolated(inputs, t_end, &mut events).map_err(|e| e.to_string());
        format!("{result:?} {events:?} {:?}", outputs(m))
    };
    let (expected, got) = (continued(&mut original), continued(&mut restored));
    (expected == got).then_some(()).ok_or_else(|| format!("a restored state continues otherwise:\n  {got}\nnot\n  {expected}"))
}

fn outputs(model: &CrankTrain) -> Outputs {
    let mut out = Outputs::default();
    model.write_outputs(&mut out);
    out
}

/// Runs a design to its end through the model's `advance_interpolated`, as an FMU host would, the
/// inputs set at each step's start with their derivatives; halfway, the model's state is saved as an
/// FMU state is (serde, postcard), restored, and must continue bit for bit as the model itself does.
/// The first error as its message.
pub fn run(design: &Design) -> Result<Finished, String> {
    let mut model = CrankTrain::new(&design.params, 0.0).map_err(|e| format!("refused: {e}"))?;
    let mut events = Vec::new();
    model.advance(&design.inputs, 0.0, &mut events).map_err(|e| e.to_string())?;
    let initial_energy = outputs(&model).kinetic_energy;
    let points = design.points();
    let mut before = output_checks::of(&outputs(&model));
    for (k, &t_end) in points.iter().enumerate() {
        let first = events.len();
        let t = if k == 0 { 0.0 } else { points[k - 1] };
        let inputs = design.derivatives.polynomials(&design.inputs_at(t), model.time());
        if k + 1 == points.len().div_ceil(2) {
            continues_after_a_round_trip(&model, &inputs, t_end).map_err(|e| format!("at t = {t} s: {e}"))?;
        }
        model.advance_interpolated(&inputs, t_end, &mut events).map_err(|e| e.to_string())?;
        let now = output_checks::of(&outputs(&model));
        contradiction(&model, &design.params, &before, &now, &events[first..])
            .map_or(Ok(()), |what| Err(format!("at t = {} s: {what}", model.time())))?;
        before = now;
    }
    let end = outputs(&model);
    let sliding_friction = end.friction_energy_total - events.iter().map(|e| e.friction_energy).sum::<f64>();
    Ok(Finished { events, initial_energy, final_energy: end.kinetic_energy, sliding_friction })
}
