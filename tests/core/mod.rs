//! The nonsmooth core on the closed-form systems of `dynamics::testbeds`.

mod adaptive;
mod ball;
mod contact_transitions;
mod corner;
mod coupled;
mod edges;
mod order;
mod rheonomic;
mod slow_approach;
