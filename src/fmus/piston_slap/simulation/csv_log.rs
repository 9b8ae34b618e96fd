//! A CSV file a run appends rows to (the impact log, the landing log): one row per record, in SI
//! units, floats in Rust's shortest round-trip form.
//!
//! The file always holds the rows of the trajectory the instance is on: the cursor (bytes written so
//! far) is part of the saved state, and restoring a state cuts the file back to that cursor, so rows
//! of an abandoned future (a host's rejected step) disappear. A digest of what the trajectory wrote
//! is saved too: a state restored over a file another run wrote (a second instance logging to the
//! same path) is refused, not continued below rows that are not its own.

use crate::models::ModelError;
use serde::{Deserialize, Serialize};
use std::fs::{File, OpenOptions};
use std::io::Write;
use std::marker::PhantomData;

/// What a log holds: its parameter's name, its header and how a record becomes a row.
pub trait Rows {
    /// One record.
    type Row;
    /// The parameter naming the file (in messages).
    const PARAMETER: &'static str;
    /// The header, ending in a newline.
    const HEADER: &'static str;
    /// One row, ending in a newline.
    fn row(record: &Self::Row) -> String;
}

/// An open log: its path, the length of what this trajectory has written and its digest.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CsvLog<R: Rows> {
    path: String,
    length: u64,
    digest: u64,
    #[serde(skip)]
    rows: PhantomData<R>,
}

/// FNV-1a over `bytes`, continuing from `digest`.
fn fnv1a(digest: u64, bytes: &[u8]) -> u64 {
    bytes.iter().fold(digest, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3))
}

/// FNV-1a's offset basis: the digest of nothing.
const EMPTY: u64 = 0xcbf2_9ce4_8422_2325;

impl<R: Rows> CsvLog<R> {
    /// Creates (or truncates) the file and writes the header.
    pub fn create(path: &str) -> Result<Self, ModelError> {
        let mut log = Self { path: path.to_string(), length: 0, digest: EMPTY, rows: PhantomData };
        let mut file = File::create(path).map_err(|e| log.error("cannot create", e))?;
        file.write_all(R::HEADER.as_bytes()).map_err(|e| log.error("cannot write", e))?;
        (log.length, log.digest) = (R::HEADER.len() as u64, fnv1a(EMPTY, R::HEADER.as_bytes()));
        Ok(log)
    }

    /// Appends one row per event; on failure the file is cut back and the cursor is unchanged.
    pub fn append(&mut self, rows: &[R::Row]) -> Result<(), ModelError> {
        if rows.is_empty() {
            return Ok(());
        }
        let rows: String = rows.iter().map(R::row).collect();
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

    /// Where the log stands: its cursor and digest.
    pub fn mark(&self) -> (u64, u64) {
        (self.length, self.digest)
    }

    /// Goes back to `mark`, cutting what was written since (best effort: a later append cuts it too).
    pub fn unwind(&mut self, (length, digest): (u64, u64)) {
        if let Ok(file) = OpenOptions::new().write(true).open(&self.path) {
            let _ = file.set_len(length);
        }
        (self.length, self.digest) = (length, digest);
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
                "{} {:?} holds {actual} bytes, fewer than the {} of the restored state",
                R::PARAMETER,
                self.path,
                self.length
            )));
        }
        let mut written = Vec::new();
        std::io::Read::read_to_end(&mut std::io::Read::take(&mut file, self.length), &mut written)
            .map_err(|e| self.error("cannot read", e))?;
        if fnv1a(EMPTY, &written) != self.digest {
            return Err(ModelError(format!(
                "{} {:?} does not hold the rows of the restored state (another run wrote it)",
                R::PARAMETER,
                self.path
            )));
        }
        file.set_len(self.length).map_err(|e| self.error("cannot truncate", e))
    }

    fn error(&self, what: &str, e: std::io::Error) -> ModelError {
        ModelError(format!("{}: {what} {:?}: {e}", R::PARAMETER, self.path))
    }
}
