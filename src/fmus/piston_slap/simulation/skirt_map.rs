//! The `skirt_map` CSV: the lubricated skirt's film pressure, asperity pressure and film thickness
//! over both sides' grids, written at the first communication point at or after each pass of the
//! crank through `skirt_map_crank_angle`, and overwritten at the next pass (so the file holds the
//! last). One row per point of each side's closed grid (its edges, where the film pressure is zero,
//! included): side by side, then top of the skirt to bottom, then around the side. The time and crank
//! angle of the communication point are in every row, so that the file reads as one table.
//!
//! Not part of the saved state: a restored state's next pass overwrites the file again.

use super::impact_log::degrees_from_firing_tdc;
use crate::fmus::piston_slap::Parameters;
use crate::models::skirt::PressureMap;
use crate::models::{ModelError, CYCLE};
use serde::{Deserialize, Serialize};
use std::fmt::Write as _;

const HEADER: &str = "# crank_angle_deg in [-360, 360) from firing TDC; angle_deg: the point's angle around the bore from the \
major-thrust axis (+x); position: its distance below the skirt's top edge\n\
time,crank_angle_deg,side,angle_deg,position,film_pressure,asperity_pressure,film_thickness\n";

/// Where and at which crank angle the map is written.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SkirtMap {
    path: String,
    /// rad in [0, 4π) from firing TDC.
    angle: f64,
}

impl SkirtMap {
    /// The map `skirt_map` asks for, if any: refused on a dry skirt (no film to map) or a path that
    /// cannot be written (at the start, not at the first pass).
    pub fn of(params: &Parameters) -> Result<Option<Self>, ModelError> {
        if params.skirt_map.is_empty() {
            return Ok(None);
        }
        if params.skirt_model != 2 {
            return Err(ModelError(format!(
                "skirt_map ({:?}) maps the oil film of skirt_model = 2, not of the dry skirt (skirt_model = {})",
                params.skirt_map, params.skirt_model
            )));
        }
        let map = Self { path: params.skirt_map.clone(), angle: params.skirt_map_crank_angle };
        map.save(HEADER)?;
        Ok(Some(map))
    }

    /// Whether the crank passed the map's angle after accumulated crank angle `before`, up to `after`.
    pub fn passed(&self, before: f64, after: f64) -> bool {
        let last = self.angle + ((after - self.angle) / CYCLE).floor() * CYCLE;
        last > before
    }

    /// Overwrites the file with `map` at `time`, accumulated crank angle `crank_angle`.
    pub fn write(&self, time: f64, crank_angle: f64, map: &PressureMap) -> Result<(), ModelError> {
        let degrees = degrees_from_firing_tdc(crank_angle.rem_euclid(CYCLE));
        let mut text = String::from(HEADER);
        for (side, name) in map.sides.iter().zip(["thrust", "antithrust"]) {
            let columns = side.angle.len();
            for (j, position) in side.position.iter().enumerate() {
                for (i, angle) in side.angle.iter().enumerate() {
                    let k = j * columns + i;
                    let (p, a, h) = (side.pressure[k], side.asperity_pressure[k], side.film[k]);
                    // Writing to a String cannot fail.
                    let _ = writeln!(text, "{time},{degrees},{name},{},{position},{p},{a},{h}", angle.to_degrees());
                }
            }
        }
        self.save(&text)
    }

    fn save(&self, text: &str) -> Result<(), ModelError> {
        std::fs::write(&self.path, text).map_err(|e| ModelError(format!("skirt_map: cannot write {:?}: {e}", self.path)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(degrees: f64) -> SkirtMap {
        SkirtMap { path: String::new(), angle: degrees.to_radians() }
    }

    /// A pass is counted in the step whose accumulated crank angle reaches the map's angle of any
    /// cycle, once: at its end exactly, not again from there.
    #[test]
    fn a_pass_is_the_step_that_reaches_the_angle_in_any_cycle() {
        let r = f64::to_radians;
        assert!(at(20.0).passed(r(10.0), r(20.0)));
        assert!(!at(20.0).passed(r(20.0), r(30.0)));
        assert!(at(20.0).passed(r(730.0), r(741.0)));
        assert!(!at(20.0).passed(r(741.0), r(1079.0)));
        assert!(at(700.0).passed(r(719.0), r(1430.0)));
        assert!(at(0.0).passed(r(-1.0), r(0.0)));
    }
}
