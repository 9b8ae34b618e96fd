//! The byte form of a serialized FMU state (fmi2SerializeFMUstate), safe code:
//!
//! | bytes | content |
//! |---|---|
//! | 8 | magic: the FMU's state tag (`Model::STATE_TAG`, e.g. `PSLAPSTA`, `ENGCYSTA`) |
//! | 4 | format version (u32 LE) |
//! | 2 + n | GUID length (u16 LE) and GUID (UTF-8) of the model description that wrote it |
//! | 8 | payload length (u64 LE) |
//! | m | payload: the state in postcard's format (serde; f64 as its 8 IEEE bytes, so a state restores bit-identically) |
//! | 4 | CRC-32 (IEEE) of everything before it |
//!
//! Decoding checks each field in this order and names the first that is wrong: foreign, truncated
//! or corrupted bytes are an error, never a crash.

use serde::{de::DeserializeOwned, Serialize};

/// Bump when the layout of the saved state changes (4: the magic is the FMU's own state tag; 5: the
/// lubricated skirt, the absorbed work in the stepper's samples, the events' velocities; 6: the contract structs' fields in the variable tables' order; 7: the stepper without a locator choice; 8: the skirt map's file and crank angle; 9: the lubricated skirt's film solved for the current step, as the motion it was solved at; 10: the motions of the film's last two solves and of the step it is carried to; 11: four absorbed channels in the samples, the walls' film impulses beside the work; 12: whether the held contacts' motion is projected off the film's implicit inertia; 13: the landings; 14: eight reported channels in the samples, the drive's, the gas's and the damping's among them, and the asperities' energy where they start; 15: the running temperatures' parameters, the running clearance in the outputs and the crank train; 16: the channels in the order implicit, film, skirt friction, walls, drive, gas, damping, and the film's relaxation work in the outputs; 17: the cavitation condition, and each saved film solve's time and fill fraction; 18: the wetted fraction in the outputs; 19: the oil supply's parameters, each saved film solve's liner oil and the oil left on the liner in the outputs).
pub const FORMAT_VERSION: u32 = 19;

/// Whose state the bytes hold: the FMU's magic and name, and the GUID of its model description.
pub struct Envelope<'a> {
    pub magic: [u8; 8],
    pub name: &'a str,
    pub guid: &'a str,
}

impl Envelope<'static> {
    /// The envelope of model `E`'s states.
    pub fn of<E: super::Model>() -> Self {
        Self { magic: E::STATE_TAG.to_le_bytes(), name: E::NAME, guid: E::DESCRIPTION.guid }
    }
}

/// The state in its envelope, the payload encoded once, straight after the header.
pub fn encode<T: Serialize>(state: &T, to: &Envelope) -> Result<Vec<u8>, String> {
    let mut out = header(to)?;
    let length_at = out.len();
    out.extend_from_slice(&0u64.to_le_bytes());
    let mut out = postcard::to_extend(state, out).map_err(|e| format!("cannot encode the state: {e}"))?;
    let payload_len = (out.len() - length_at - 8) as u64;
    out[length_at..length_at + 8].copy_from_slice(&payload_len.to_le_bytes());
    Ok(sealed(out))
}

/// The state in `bytes`, whose payload must be exactly the encoding of the state it decodes to:
/// postcard reads lengths and integers written in more bytes than needed, and would otherwise
/// accept a state that does not re-serialize to its own bytes.
pub fn decode<T: Serialize + DeserializeOwned>(bytes: &[u8], to: &Envelope) -> Result<T, String> {
    let payload = open(bytes, to)?;
    let (state, rest) = postcard::take_from_bytes(payload).map_err(|e| format!("cannot decode the state: {e}"))?;
    if !rest.is_empty() {
        return Err(format!("cannot decode the state: {} trailing bytes", rest.len()));
    }
    if postcard::to_allocvec(&state).map_err(|e| format!("cannot encode the state: {e}"))? != payload {
        return Err("cannot decode the state: the payload is not in its canonical encoding".into());
    }
    Ok(state)
}

/// Magic, format version and GUID.
fn header(to: &Envelope) -> Result<Vec<u8>, String> {
    let guid = to.guid;
    let guid_len = u16::try_from(guid.len()).map_err(|_| "GUID too long".to_string())?;
    let mut out = Vec::new();
    out.extend_from_slice(&to.magic);
    out.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
    out.extend_from_slice(&guid_len.to_le_bytes());
    out.extend_from_slice(guid.as_bytes());
    Ok(out)
}

/// `body` with its CRC appended.
fn sealed(mut body: Vec<u8>) -> Vec<u8> {
    let crc = crc32(&body);
    body.extend_from_slice(&crc.to_le_bytes());
    body
}

/// Wraps a payload in the envelope.
#[cfg(test)]
pub fn seal(payload: &[u8], to: &Envelope) -> Result<Vec<u8>, String> {
    let mut out = header(to)?;
    out.extend_from_slice(&(payload.len() as u64).to_le_bytes());
    out.extend_from_slice(payload);
    Ok(sealed(out))
}

/// Checks the envelope and returns its payload.
pub fn open<'a>(bytes: &'a [u8], to: &Envelope) -> Result<&'a [u8], String> {
    let mut r = Reader(bytes);
    if r.take(to.magic.len())? != to.magic {
        return Err(format!("not a state of {} (wrong magic)", to.name));
    }
    let guid = to.guid;
    let version = u32::from_le_bytes(r.array()?);
    if version != FORMAT_VERSION {
        return Err(format!("state format version {version}, this FMU reads {FORMAT_VERSION}"));
    }
    let guid_len = u16::from_le_bytes(r.array()?);
    let written_by = r.take(usize::from(guid_len))?;
    if written_by != guid.as_bytes() {
        let shown = String::from_utf8_lossy(written_by);
        return Err(format!("state written by a model with GUID {shown}, this FMU is {guid}"));
    }
    let payload_len = u64::from_le_bytes(r.array()?);
    let expected = r.0.len().checked_sub(4);
    if expected.map(|n| n as u64) != Some(payload_len) {
        return Err(format!("payload length {payload_len} does not match the {} bytes given", bytes.len()));
    }
    let body_len = bytes.len() - 4;
    let crc = u32::from_le_bytes(bytes[body_len..].try_into().map_err(|_| "truncated".to_string())?);
    if crc32(&bytes[..body_len]) != crc {
        return Err("checksum mismatch: the state bytes are corrupted".into());
    }
    Ok(&r.0[..r.0.len() - 4])
}

struct Reader<'a>(&'a [u8]);

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize) -> Result<&'a [u8], String> {
        if n > self.0.len() {
            return Err(format!("truncated state: {} bytes", self.0.len()));
        }
        let (head, tail) = self.0.split_at(n);
        self.0 = tail;
        Ok(head)
    }
    fn array<const N: usize>(&mut self) -> Result<[u8; N], String> {
        let mut a = [0; N];
        a.copy_from_slice(self.take(N)?);
        Ok(a)
    }
}

/// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320): detects every single-bit flip and every
/// burst up to 32 bits.
fn crc32(bytes: &[u8]) -> u32 {
    const TABLE: [u32; 256] = {
        let mut table = [0u32; 256];
        let mut i = 0;
        while i < 256 {
            let mut c = i as u32;
            let mut k = 0;
            while k < 8 {
                c = if c & 1 != 0 { 0xEDB8_8320 ^ (c >> 1) } else { c >> 1 };
                k += 1;
            }
            table[i] = c;
            i += 1;
        }
        table
    };
    !bytes.iter().fold(!0u32, |c, &b| TABLE[((c ^ u32::from(b)) & 0xff) as usize] ^ (c >> 8))
}

#[cfg(test)]
mod tests {
    use super::*;

    const TO: Envelope = Envelope { magic: *b"TESTSTAT", name: "Test", guid: "{test}" };

    fn sample() -> Vec<u8> {
        encode(&(vec![0.1f64, -2.5, 1e-9], "log.csv".to_string(), Some(3u8)), &TO).unwrap()
    }

    type Sample = (Vec<f64>, String, Option<u8>);

    #[test]
    fn crc32_of_the_standard_check_string() {
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
    }

    #[test]
    fn round_trip() {
        let back: Sample = decode(&sample(), &TO).unwrap();
        assert_eq!(back, (vec![0.1, -2.5, 1e-9], "log.csv".to_string(), Some(3)));
    }

    #[test]
    fn every_truncation_every_bit_flip_and_a_foreign_guid_are_refused() {
        let bytes = sample();
        for n in 0..bytes.len() {
            assert!(decode::<Sample>(&bytes[..n], &TO).is_err(), "prefix {n}");
        }
        for i in 0..bytes.len() * 8 {
            let mut flipped = bytes.clone();
            flipped[i / 8] ^= 1 << (i % 8);
            assert!(decode::<Sample>(&flipped, &TO).is_err(), "bit {i}");
        }
        let err = decode::<Sample>(&bytes, &Envelope { guid: "{other}", ..TO }).unwrap_err();
        assert!(err.contains("GUID"), "{err}");
        let err = decode::<Sample>(&bytes, &Envelope { magic: *b"OTHERFMU", name: "Other", ..TO }).unwrap_err();
        assert!(err.contains("not a state of Other"), "{err}");
    }

    #[test]
    fn random_bytes_are_refused() {
        // xorshift: deterministic noise of many lengths, some starting with the right magic.
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        for len in 0..400 {
            let mut noise: Vec<u8> = (0..len)
                .map(|_| {
                    x ^= x << 13;
                    x ^= x >> 7;
                    x ^= x << 17;
                    x as u8
                })
                .collect();
            if len % 2 == 0 && len >= 8 {
                noise[..8].copy_from_slice(&TO.magic);
            }
            assert!(decode::<Sample>(&noise, &TO).is_err());
        }
    }
}
