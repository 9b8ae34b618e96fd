//! Which FMU a copy of the binary belongs to. One cdylib serves both FMUs of the crate; the packer stamps
//! each FMU's copy with its model (`package_fmu` rewrites [`STAMP`]'s payload in the file), so that
//! EngineCycle.fmu's binary refuses PistonSlap's GUID and PistonSlap.fmu's refuses EngineCycle's, as FMI 2.0
//! asks of fmi2Instantiate. An unstamped library (linked into tests and benches) serves both by GUID.
#![allow(unsafe_code)]

/// The marker the packer finds the payload by.
pub const MARKER: &[u8; 24] = b"PISTONSLAP-FMU-IDENTITY:";
/// Payload width, bytes (names padded with spaces).
pub const PAYLOAD: usize = 16;

/// The models a copy of the binary may serve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Identity {
    /// Unstamped: the model whose GUID fmi2Instantiate gets.
    Both,
    PistonSlap,
    EngineCycle,
}

impl Identity {
    /// The payload bytes of this identity.
    pub fn payload(self) -> [u8; PAYLOAD] {
        let name: &[u8] = match self {
            Self::Both => b"both",
            Self::PistonSlap => b"PistonSlap",
            Self::EngineCycle => b"EngineCycle",
        };
        let mut out = [b' '; PAYLOAD];
        out[..name.len()].copy_from_slice(name);
        out
    }

    fn of(payload: &[u8; PAYLOAD]) -> Self {
        [Self::PistonSlap, Self::EngineCycle].into_iter().find(|m| &m.payload() == payload).unwrap_or(Self::Both)
    }
}

/// The stamp in the binary: marker, then the payload (`both` until the packer rewrites it).
#[used]
static STAMP: [u8; 40] = *b"PISTONSLAP-FMU-IDENTITY:both            ";

/// The identity this copy of the binary carries.
pub fn stamped() -> Identity {
    // SAFETY: a read of a static's bytes; volatile so that the value in the file, not the compiler's
    // knowledge of the initializer, decides.
    let stamp = unsafe { std::ptr::read_volatile(&STAMP) };
    let mut payload = [0; PAYLOAD];
    payload.copy_from_slice(&stamp[MARKER.len()..]);
    Identity::of(&payload)
}

/// Rewrites the one unstamped stamp in `binary` to `identity`; an error unless there is exactly one.
pub fn stamp(binary: &mut [u8], identity: Identity) -> Result<(), String> {
    let both = Identity::Both.payload();
    let width = MARKER.len() + PAYLOAD;
    let found: Vec<usize> = (0..binary.len().saturating_sub(width - 1))
        .filter(|&i| &binary[i..i + MARKER.len()] == MARKER && binary[i + MARKER.len()..i + width] == both)
        .collect();
    match found[..] {
        [at] => {
            binary[at + MARKER.len()..at + width].copy_from_slice(&identity.payload());
            Ok(())
        }
        _ => Err(format!("the binary holds {} unstamped identity stamps, not one", found.len())),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_library_is_unstamped_and_a_stamp_is_found_and_rewritten_once() {
        assert_eq!(stamped(), Identity::Both);
        let mut binary = b"....".to_vec();
        binary.extend_from_slice(&STAMP);
        binary.extend_from_slice(b"....");
        stamp(&mut binary, Identity::EngineCycle).unwrap();
        let mut payload = [0; PAYLOAD];
        payload.copy_from_slice(&binary[4 + MARKER.len()..4 + MARKER.len() + PAYLOAD]);
        assert_eq!(Identity::of(&payload), Identity::EngineCycle);
        // Stamped already: nothing left to stamp.
        assert!(stamp(&mut binary, Identity::PistonSlap).unwrap_err().contains("0 unstamped"));
    }
}
