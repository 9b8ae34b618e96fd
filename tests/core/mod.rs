//! The nonsmooth core on the closed-form systems of `tests/common/testbeds.rs`.

mod absorbing;
mod adaptive;
mod ball;
mod communication_points;
mod contact_transitions;
mod corner;
mod coupled;
mod edges;
mod friction;
mod order;
mod rheonomic;
mod slow_approach;
