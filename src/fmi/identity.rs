//! Which FMU a copy of the binary belongs to. One cdylib serves every FMU of the crate; the packer stamps
//! each FMU's copy with its name (`package_fmu` rewrites `STAMP`'s payload in the file), so that each
//! FMU's binary refuses the GUIDs of the others, as FMI 2.0 asks of fmi2Instantiate. An unstamped library
//! (linked into tests and benches) serves every FMU by GUID.
#![allow(unsafe_code)]

/// The marker the packer finds the payload by.
pub const MARKER: &[u8; 24] = b"PISTONSLAP-FMU-IDENTITY:";
/// Payload width, bytes: an FMU's name padded with spaces.
pub const PAYLOAD: usize = 16;
/// The payload of an unstamped binary.
const UNSTAMPED: &str = "unstamped";

/// The stamp in the binary: marker, then the payload (unstamped until the packer rewrites it).
#[used]
static STAMP: [u8; 40] = *b"PISTONSLAP-FMU-IDENTITY:unstamped       ";

/// `name` padded to the payload's width; an error when it does not fit.
fn payload(name: &str) -> Result<[u8; PAYLOAD], String> {
    let mut out = [b' '; PAYLOAD];
    out.get_mut(..name.len()).ok_or_else(|| format!("the name {name:?} is longer than {PAYLOAD} bytes"))?.copy_from_slice(name.as_bytes());
    Ok(out)
}

/// The name of the FMU this copy of the binary is stamped with, None when unstamped.
pub fn stamped() -> Option<String> {
    // SAFETY: a read of a static's bytes; volatile so that the value in the file, not the compiler's
    // knowledge of the initializer, decides.
    let stamp = unsafe { std::ptr::read_volatile(&STAMP) };
    let name = String::from_utf8_lossy(&stamp[MARKER.len()..]).trim_end().to_string();
    (name != UNSTAMPED).then_some(name)
}

/// Rewrites the one unstamped stamp in `binary` to the FMU called `name`; an error unless there is exactly one.
pub fn stamp(binary: &mut [u8], name: &str) -> Result<(), String> {
    let (unstamped, name) = (payload(UNSTAMPED)?, payload(name)?);
    let width = MARKER.len() + PAYLOAD;
    let found: Vec<usize> = (0..binary.len().saturating_sub(width - 1))
        .filter(|&i| &binary[i..i + MARKER.len()] == MARKER && binary[i + MARKER.len()..i + width] == unstamped)
        .collect();
    match found[..] {
        [at] => {
            binary[at + MARKER.len()..at + width].copy_from_slice(&name);
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
        assert_eq!(stamped(), None);
        let mut binary = b"....".to_vec();
        binary.extend_from_slice(&STAMP);
        binary.extend_from_slice(b"....");
        stamp(&mut binary, "EngineCycle").unwrap();
        assert_eq!(&binary[4 + MARKER.len()..4 + MARKER.len() + PAYLOAD], b"EngineCycle     ");
        // Stamped already: nothing left to stamp.
        assert!(stamp(&mut binary, "PistonSlap").unwrap_err().contains("0 unstamped"));
        assert!(stamp(&mut binary, "AVeryLongModelName").unwrap_err().contains("longer than 16"));
    }
}
