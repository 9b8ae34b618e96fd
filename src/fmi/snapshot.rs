//! What an `fmi2FMUstate` points to: a tagged copy of an instance's core, with its serialized bytes
//! encoded once, and the conversions of the host's state pointers to it.
#![allow(unsafe_code)]

use super::instance::{Core, Model, Outcome, Refusal};
use super::pointers::out;
use super::types::*;

/// What an `fmi2FMUstate` points to, tagged with [`Model::STATE_TAG`] likewise.
#[repr(C)]
pub(super) struct Snapshot<E: Model> {
    pub(super) tag: u64,
    pub(super) core: Core<E>,
    /// The serialized form, encoded once for fmi2SerializedFMUstateSize and fmi2SerializeFMUstate.
    bytes: Option<Vec<u8>>,
}

impl<E: Model> Snapshot<E> {
    pub(super) fn new(core: Core<E>) -> Self {
        Self { tag: E::STATE_TAG, core, bytes: None }
    }

    pub(super) fn bytes(&mut self) -> Outcome<&[u8]> {
        match &mut self.bytes {
            Some(bytes) => Ok(bytes),
            slot @ None => Ok(slot.insert(self.core.serialize()?)),
        }
    }
}

/// # Safety
/// `state` is NULL, an FMU state made by this model's functions, or memory readable as one.
pub(super) unsafe fn snapshot<'a, E: Model>(state: fmi2FMUstate) -> Outcome<&'a mut Snapshot<E>> {
    // SAFETY: NULL is checked by `as_ref`; `Snapshot` is `repr(C)` with the tag first, which tells ours
    // from freed, foreign or another model's memory before the rest is read.
    match unsafe { (state as *const u64).as_ref() } {
        None => Err(Refusal::error("FMUstate is NULL")),
        Some(&tag) if tag != E::STATE_TAG => Err(Refusal::error("FMUstate was not made by this FMU (or is freed)")),
        // SAFETY: tagged as this model's snapshot.
        Some(_) => Ok(unsafe { &mut *(state as *mut Snapshot<E>) }),
    }
}

/// Stores `core` in `*state`: into the FMU state already there, or a new one when it is NULL.
///
/// # Safety
/// `state` is NULL or points to an `fmi2FMUstate` as [`snapshot`] takes it.
pub(super) unsafe fn store<E: Model>(state: *mut fmi2FMUstate, core: Core<E>) -> Outcome {
    // SAFETY: the caller's contract.
    let state = unsafe { out(state, "FMUstate pointer")? };
    if state.is_null() {
        *state = Box::into_raw(Box::new(Snapshot::new(core))) as fmi2FMUstate;
    } else {
        // SAFETY: the caller's contract.
        *unsafe { snapshot::<E>(*state)? } = Snapshot::new(core);
    }
    Ok(())
}
