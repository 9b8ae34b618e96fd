//! Each FMU of the library in its own room: its binding to the FMI layer ([`crate::fmi::Model`]), its run
//! façade, its variable table and its package. The registry below is the one list the exported fmi2*
//! symbols ([`exports`], written by the layer's `fmi::exports!`) and the packer go through; `fmi/` names no FMU.

use crate::fmi::exports;

pub mod engine_cycle;
pub mod piston_slap;
#[cfg(test)]
pub mod toy;

/// The registry: the rooms of the FMUs this library serves, each exporting `Fmu` (the type the FMI layer
/// runs) and `PACKAGE`. `$callback!([rooms…] args…)`. An unstamped library's fmi2Instantiate tries their GUIDs
/// in this order; the last takes the instances and GUIDs no other claims, and its own checks refuse them.
/// Adding an FMU: its room, and its name here (tests add the toy room, `toy/`, the same way).
#[cfg(not(test))]
macro_rules! registry {
    ($callback:ident!($($args:tt)*)) => {
        $callback! { [engine_cycle, piston_slap] $($args)* }
    };
}
#[cfg(test)]
macro_rules! registry {
    ($callback:ident!($($args:tt)*)) => {
        $callback! { [toy, engine_cycle, piston_slap] $($args)* }
    };
}

registry!(exports!());

#[cfg(not(test))]
macro_rules! packages {
    ([$($room:ident),*]) => {
        &[$(&$room::PACKAGE),*]
    };
}

/// The packaging facts of every shipped FMU.
#[cfg(not(test))]
pub const PACKAGES: &[&crate::fmi::Package] = registry!(packages!());
