//! The crank train (variant 1): its crank angle, its energy balance, and Awrejcewicz & Kudra's results.

mod angle;
mod energy;
mod paper;
