//! No heap allocation inside a step. A global allocator that counts, per thread, the
//! allocations of steady-state steps of both engine models: through their `advance` (the core's
//! step loop, events included), through `Simulation::step` and through the exported fmi2DoStep.

use crate::common::fmu_host::{vr, Host};
use pistonslap::fmus::piston_slap::simulation::Simulation;
use pistonslap::fmus::piston_slap::Mechanism;
use pistonslap::fmus::piston_slap::{Inputs, Parameters};
use pistonslap::models::{CrankTrain, Roller};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    /// Per thread, so that the tests of this binary, run in parallel, do not count each other's.
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

// SAFETY: forwards every call to the system allocator unchanged; it only counts.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.with(|n| n.set(n.get() + 1));
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.with(|n| n.set(n.get() + 1));
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static COUNTING: Counting = Counting;

/// Allocations made by `f`.
fn allocations(f: impl FnOnce()) -> usize {
    let before = ALLOCATIONS.with(Cell::get);
    f();
    ALLOCATIONS.with(Cell::get) - before
}

/// Two 0.1 s engine cycles (1200 rpm) of 1 ms steps to warm up, then one measured: the events
/// repeat from cycle to cycle, so the warm-up has grown the event lists to what a step needs.
const STEP: f64 = 1e-3;
const WARM_UP: usize = 200;
const MEASURED: usize = 100;

fn roller() -> Parameters {
    Parameters { model_variant: 2, ..Parameters::default() }
}

/// Allocations and events of the measured steps of model `M`'s `advance`, the event list reused
/// as a host of the model would.
fn advance<M: Mechanism>(params: &Parameters) -> (usize, usize) {
    let (inputs, mut events) = (Inputs::default(), Vec::new());
    let mut model = M::new(params, 0.0).expect("default parameters");
    let mut step = |k: usize| {
        events.clear();
        model.advance(&inputs, k as f64 * STEP, &mut events).expect("step");
        events.len()
    };
    for k in 1..=WARM_UP {
        step(k);
    }
    let mut count = 0;
    let n = allocations(|| (WARM_UP + 1..=WARM_UP + MEASURED).for_each(|k| count += step(k)));
    (n, count)
}

#[test]
fn the_core_steps_of_both_models_allocate_nothing() {
    for (what, (n, events)) in [("crank train", advance::<CrankTrain>(&Parameters::default())), ("roller", advance::<Roller>(&roller()))] {
        assert!(events > MEASURED / 2, "{what}: the measured steps must have events, got {events}");
        assert_eq!(n, 0, "{what}: {n} allocations in {MEASURED} steps with {events} events");
    }
}

/// `Simulation::step` (all or nothing) advances the model in place, with a copy to fall back on,
/// and lends each step the event list of the step before last: once the lists have grown to the
/// most events a step has had, it allocates nothing either (without an impact log, whose rows are
/// written as text).
#[test]
fn a_simulation_step_allocates_nothing() {
    for params in [Parameters::default(), roller()] {
        let inputs = Inputs::default();
        let mut sim: Simulation = Simulation::new(&params, 0.0).expect("default parameters");
        for k in 1..=WARM_UP {
            sim.step(&inputs, k as f64 * STEP).expect("step");
        }
        let mut events = 0;
        let n = allocations(|| {
            for k in WARM_UP + 1..=WARM_UP + MEASURED {
                sim.step(&inputs, k as f64 * STEP).expect("step");
                events += sim.step_events().len();
            }
        });
        assert!(events > MEASURED / 2, "variant {}: the measured steps must have events, got {events}", params.model_variant);
        assert_eq!(n, 0, "variant {}: {n} allocations in {MEASURED} steps with {events} events", params.model_variant);
    }
}

/// fmi2DoStep adds argument checks and the event log messages, which are written only when
/// logEvents is on: it allocates nothing either, nor does a host's fmi2GetReal.
#[test]
fn fmi2_do_step_allocates_nothing() {
    for variant in [1, 2] {
        let host = Host::new(&[("model_variant", variant)], &[]);
        let refs = [vr("max_impact_velocity_in_step"), vr("side_force")];
        let mut out = [0.0; 2];
        for k in 0..WARM_UP {
            host.step(k as f64 * STEP, STEP, &refs, &mut out);
        }
        let mut with_impacts = 0;
        let n = allocations(|| {
            for k in WARM_UP..WARM_UP + MEASURED {
                host.step(k as f64 * STEP, STEP, &refs, &mut out);
                with_impacts += usize::from(out[0] > 0.0);
            }
        });
        assert!(with_impacts > 10, "variant {variant}: the measured steps must have impacts, {with_impacts} had");
        assert_eq!(n, 0, "variant {variant}: {n} allocations in {MEASURED} steps, {with_impacts} with impacts");
    }
}
