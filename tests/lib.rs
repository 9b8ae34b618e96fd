//! The integration tests, one binary with a module per subject: the core on closed-form systems,
//! the crank train and the roller through their public API, the absence of allocation in steps,
//! and the C ABI through a C host.

mod allocation;
mod c_abi;
mod common;
mod core;
mod crank_train;
mod engine_cycle_fmu;
mod fmu_random_designs;
mod roller;
