//! The `impact_log` CSV: one row per impact, slide start or release, in SI units, with the crank
//! angle in degrees as well (the last column, so readers of the older columns are unaffected). A first
//! line starting with `#` states the crank-angle conventions: `crank_angle` in rad in [0, 4π), and
//! `crank_angle_deg` as engine people read it, in [−360, 360), both from firing TDC. `energy_lost` is
//! what the normal (restitution) impulse dissipated, as `impact_energy_total` counts it;
//! `friction_energy_lost` the tangential (friction) impulse's share, which `friction_energy_total` counts.
//!
//! The file always holds the events of the trajectory the instance is on: the cursor (bytes written so
//! far) is part of the saved state, and restoring a state cuts the file back to that cursor, so rows
//! of an abandoned future (a host's rejected step) disappear. A digest of what the trajectory wrote
//! is saved too: a state restored over a file another run wrote (a second instance logging to the
//! same path) is refused, not continued below rows that are not its own.

use super::statistics::normal_energy;
use crate::models::{EngineEvent, EngineEventKind, ModelError};
use serde::{Deserialize, Serialize};
use std::fs::{File, OpenOptions};
use std::io::Write;

const HEADER: &str = "# crank_angle [rad] in [0, 4π) and crank_angle_deg [deg] in [-360, 360), both from firing TDC\n\
time,crank_angle,kind,corner,normal_velocity_before,normal_velocity_after,energy_lost,position,crank_angle_deg,friction_energy_lost\n";

/// An open log: its path, the length of what this trajectory has written and its digest.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ImpactLog {
    path: String,
    length: u64,
    digest: u64,
}

/// FNV-1a over `bytes`, continuing from `digest`.
fn fnv1a(digest: u64, bytes: &[u8]) -> u64 {
    bytes.iter().fold(digest, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3))
}

/// FNV-1a's offset basis: the digest of nothing.
const EMPTY: u64 = 0xcbf2_9ce4_8422_2325;

impl ImpactLog {
    /// Creates (or truncates) the file and writes the header.
    pub fn create(path: &str) -> Result<Self, ModelError> {
        let mut log = Self { path: path.to_string(), length: 0, digest: EMPTY };
        let mut file = File::create(path).map_err(|e| log.error("cannot create", e))?;
        file.write_all(HEADER.as_bytes()).map_err(|e| log.error("cannot write", e))?;
        (log.length, log.digest) = (HEADER.len() as u64, fnv1a(EMPTY, HEADER.as_bytes()));
        Ok(log)
    }

    /// Appends one row per event; on failure the file is cut back and the cursor is unchanged.
    pub fn append(&mut self, events: &[EngineEvent]) -> Result<(), ModelError> {
        if events.is_empty() {
            return Ok(());
        }
        let rows: String = events.iter().map(row).collect();
        let mut file = OpenOptions::new().write(true).open(&self.path).map_err(|e| self.error("cannot open", e))?;
        file.set_len(self.length).map_err(|e| self.error("cannot truncate", e))?;
        let written = std::io::Seek::seek(&mut file, std::io::SeekFrom::Start(self.length)).and_then(|_| file.write_all(rows.as_bytes()));
        match written {
            Ok(()) => {
                (self.length, self.digest) = (self.length + rows.len() as u64, fnv1a(self.digest, rows.as_bytes()));
                Ok(())
            }
            Err(e) => {
                // Best effort: the cursor did not move, a later append cuts the file back anyway.
                let _ = file.set_len(self.length);
                Err(self.error("cannot write", e))
            }
        }
    }

    /// The file the log writes.
    pub fn path(&self) -> &str {
        &self.path
    }

    /// Cuts the file back to this cursor (after a state restore). A file shorter than the cursor, or
    /// whose rows up to it are not the ones this trajectory wrote, was written by someone else: refused.
    pub fn rewind(&self) -> Result<(), ModelError> {
        let mut file = OpenOptions::new().read(true).write(true).open(&self.path).map_err(|e| self.error("cannot open", e))?;
        let actual = file.metadata().map_err(|e| self.error("cannot inspect", e))?.len();
        if actual < self.length {
            return Err(ModelError(format!(
                "impact_log {:?} holds {actual} bytes, fewer than the {} of the restored state",
                self.path, self.length
            )));
        }
        let mut written = Vec::new();
        std::io::Read::read_to_end(&mut std::io::Read::take(&mut file, self.length), &mut written)
            .map_err(|e| self.error("cannot read", e))?;
        if fnv1a(EMPTY, &written) != self.digest {
            return Err(ModelError(format!(
                "impact_log {:?} does not hold the rows of the restored state (another run wrote it)",
                self.path
            )));
        }
        file.set_len(self.length).map_err(|e| self.error("cannot truncate", e))
    }

    fn error(&self, what: &str, e: std::io::Error) -> ModelError {
        ModelError(format!("impact_log: {what} {:?}: {e}", self.path))
    }
}

/// One CSV row; floats in Rust's shortest round-trip form, so the file reproduces the values exactly.
fn row(e: &EngineEvent) -> String {
    let kind = match e.kind {
        EngineEventKind::Impact => "impact",
        EngineEventKind::Slide => "slide",
        EngineEventKind::Release => "release",
        EngineEventKind::Stick => "stick",
        EngineEventKind::Slip => "slip",
    };
    format!(
        "{},{},{kind},{},{},{},{},{},{},{}\n",
        e.time,
        e.crank_angle,
        e.corner,
        e.normal_velocity_before,
        e.normal_velocity_after,
        normal_energy(e),
        e.position,
        degrees_from_firing_tdc(e.crank_angle),
        e.friction_energy
    )
}

/// The crank angle `phase` ∈ [0, 4π) from firing TDC in degrees in [−360, 360): the cycle centred on firing TDC.
pub(super) fn degrees_from_firing_tdc(phase: f64) -> f64 {
    let degrees = phase.to_degrees();
    if degrees >= 360.0 {
        degrees - 720.0
    } else {
        degrees
    }
}
