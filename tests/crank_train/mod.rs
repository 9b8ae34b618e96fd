//! The crank train (variant 1): its crank angle, its energy balance, Awrejcewicz & Kudra's results,
//! the Flores benchmark, and seeded random designs.

mod angle;
mod books;
mod energy;
mod flores_benchmark;
mod liner_impulse;
mod lubricated;
mod paper;
mod random_designs;
