//! The FMI 2.0 Co-Simulation interface: the only `unsafe` code of the crate.

pub mod description;
