//! Hostile input through the C ABI from a seeded generator (reproducible; the seed is in each
//! failure message): fmi2DeSerializeFMUstate with mutations of valid serialized states, and the
//! setters with arbitrary value references, values and byte strings. No call may panic (fmi2Fatal) or
//! crash; each either refuses (fmi2Error and a message) or succeeds, and what it accepted is a state
//! that can be read back, re-serialized, restored and stepped without fmi2Fatal or a silent NaN.
#![allow(unsafe_code)]

use super::*;
use crate::fmi::state_bytes::{self, Envelope};

/// xorshift64*: small, fast and the same on every platform.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len())]
    }
    fn bytes(&mut self, n: usize) -> Vec<u8> {
        (0..n).map(|_| self.next() as u8).collect()
    }
}

/// Values that break careless code: non-finite, extreme, subnormal, signed zero, and random bits
/// (which include NaNs with payloads).
fn real(rng: &mut Rng) -> f64 {
    let special = [
        f64::NAN,
        -f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::MAX,
        f64::MIN,
        1e300,
        -1e300,
        f64::MIN_POSITIVE,
        5e-324,
        -0.0,
        0.0,
        1.0,
        -1.0,
        1e-12,
    ];
    match rng.below(3) {
        0 => rng.pick(&special),
        1 => f64::from_bits(rng.next()),
        _ => (rng.next() as f64 / u64::MAX as f64 - 0.5) * 10f64.powi(rng.below(12) as i32 - 4),
    }
}

fn integer(rng: &mut Rng) -> i32 {
    match rng.below(3) {
        0 => rng.pick(&[i32::MIN, i32::MAX, 0, 1, 2, 3, -1]),
        _ => rng.next() as i32,
    }
}

/// Any value reference: mostly real ones, sometimes just past the table or anywhere.
fn value_reference(rng: &mut Rng) -> u32 {
    match rng.below(5) {
        0 => rng.next() as u32,
        1 => VARIABLES.len() as u32 + rng.below(3) as u32,
        _ => rng.below(VARIABLES.len()) as u32,
    }
}

/// One random change of `bytes`; `other` lends material for splices.
fn mutate(rng: &mut Rng, bytes: &mut Vec<u8>, other: &[u8]) {
    let at = rng.below(bytes.len() + 1);
    let last = bytes.len().saturating_sub(1);
    match rng.below(9) {
        0 if !bytes.is_empty() => bytes[at.min(last)] ^= 1 << rng.below(8),
        1 if !bytes.is_empty() => bytes[at.min(last)] = rng.pick(&[0, 1, 0x7f, 0x80, 0xff]),
        2 => {
            // An 8-byte field (f64, length or enum tag) overwritten with an extreme value.
            let word = match rng.below(2) {
                0 => real(rng).to_bits(),
                _ => rng.pick(&[u64::MAX, 1 << 40, 1 << 32, u32::MAX as u64, 0, 1, 2, 3]),
            };
            for (k, b) in word.to_le_bytes().into_iter().enumerate() {
                if let Some(x) = bytes.get_mut(at + k) {
                    *x = b;
                }
            }
        }
        3 => bytes.truncate(at),
        4 => {
            let n = rng.below(64);
            bytes.extend(rng.bytes(n));
        }
        5 => {
            let n = rng.below(16) + 1;
            let noise = rng.bytes(n);
            bytes.splice(at..at, noise);
        }
        6 => {
            let end = (at + rng.below(16) + 1).min(bytes.len());
            bytes.drain(at..end);
        }
        _ => {
            // Splice: a piece of another valid state (or of this one) over or into this one.
            let from = rng.below(other.len());
            let piece = &other[from..(from + rng.below(32) + 1).min(other.len())];
            let end = if rng.below(2) == 0 { (at + piece.len()).min(bytes.len()) } else { at };
            bytes.splice(at..end, piece.iter().copied());
        }
    }
}

/// Valid serialized states of the shipped engine in several phases and both variants.
fn valid_states() -> Vec<Vec<u8>> {
    let mut states = Vec::new();
    for variant in [1, 2] {
        let host = Host::<ModelVariant>::new();
        assert_eq!(host.set_integer("model_variant", variant), Status::Ok);
        let mut save = || {
            let state = host.get_state();
            states.push(host.serialize(state));
            host.free_state(state);
        };
        save();
        assert_eq!(host.setup(0.0, None), Status::Ok);
        assert_eq!(host.enter(), Status::Ok);
        assert_eq!(host.exit(), Status::Ok);
        host.run(0.0, 0.05, 1e-3);
        save();
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        assert_eq!(unsafe { functions::terminate::<ModelVariant>(Function::fmi2Terminate, host.c) }, Status::Ok);
        save();
    }
    states
}

/// The FMU's time, when it is stepping.
fn time<E: Model>(host: &Host<E>) -> Option<f64> {
    let mut t = f64::NAN;
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    let status = unsafe { functions::get_real_status::<E>(Function::fmi2GetRealStatus, host.c, FMI2_LAST_SUCCESSFUL_TIME, &mut t) };
    (status == Status::Ok).then_some(t)
}

/// A step from wherever the instance is: refused or done, never fatal; done means finite outputs.
fn step_checked<E: Model>(host: &Host<E>, case: &str) {
    let Some(t) = time(host) else { return };
    let status = host.step(t, 1e-3);
    assert!(matches!(status, Status::Ok | Status::Error), "{case}: step {status:?} {:?}", host.messages());
    if status == Status::Ok {
        for v in VARIABLES.iter().filter(|v| v.kind == description::Kind::Real) {
            let x = host.real(v.name);
            assert!(x.is_finite(), "{case}: {} = {x} after an accepted step", v.name);
        }
    }
}

/// Deserializes `bytes`; what is accepted must re-serialize to the same bytes, restore, and step.
/// Returns whether it was accepted.
fn deserialize_checked(host: &Host<ModelVariant>, victim: &Host<ModelVariant>, bytes: &[u8], case: &str) -> bool {
    let logged = host.messages().len();
    let (status, state) = host.deserialize(bytes);
    match status {
        Status::Error => {
            assert!(state.is_null(), "{case}");
            assert_eq!(host.messages().len(), logged + 1, "{case}: a refusal says why");
            false
        }
        Status::Ok => {
            assert_eq!(host.serialize(state), bytes, "{case}: an accepted state re-serializes");
            let status = victim.set_state(state);
            assert!(matches!(status, Status::Ok | Status::Error), "{case}: set {status:?}");
            if status == Status::Ok {
                step_checked(victim, case);
            }
            host.free_state(state);
            true
        }
        other => panic!("{case}: fmi2DeSerializeFMUstate returned {other:?}: {:?}", host.messages()),
    }
}

/// Returns (cases, accepted).
fn fuzz_deserialize(seed: u64, cases: usize) -> (usize, usize) {
    let mut rng = Rng(seed);
    let bases = valid_states();
    let host = Host::<ModelVariant>::new();
    let victim = Host::<ModelVariant>::new();
    let mut accepted = 0;
    for case in 0..cases {
        let label = format!("seed {seed} case {case}");
        let (base, other) = (&bases[rng.below(bases.len())], &bases[rng.below(bases.len())]);
        let mutations = 1 + rng.below(4);
        if rng.below(4) == 0 {
            // The envelope itself: any change is caught (magic, version, GUID, length, CRC-32).
            let mut bytes = base.clone();
            for _ in 0..mutations {
                mutate(&mut rng, &mut bytes, other);
            }
            if bytes != *base {
                assert!(!deserialize_checked(&host, &victim, &bytes, &label), "{label}: corrupted envelope accepted");
            }
        } else {
            // The payload, resealed with a valid envelope: what postcard and the model must withstand.
            let mut payload = state_bytes::open(base, &Envelope::of::<ModelVariant>()).unwrap().to_vec();
            let other = state_bytes::open(other, &Envelope::of::<ModelVariant>()).unwrap();
            for _ in 0..mutations {
                mutate(&mut rng, &mut payload, other);
            }
            let bytes = state_bytes::seal(&payload, &Envelope::of::<ModelVariant>()).unwrap();
            accepted += usize::from(deserialize_checked(&host, &victim, &bytes, &label));
        }
        if case % 256 == 0 {
            host.log.lock().unwrap().clear();
        }
    }
    (cases, accepted)
}

/// A fresh instance of the shipped engine in Instantiated, InitializationMode or StepComplete, and
/// whether its variables can be read (all but Instantiated).
fn instance(rng: &mut Rng) -> (Host<ModelVariant>, bool) {
    let host = Host::<ModelVariant>::new();
    assert_eq!(host.set_integer("model_variant", rng.pick(&[1, 2])), Status::Ok);
    let depth = rng.below(3);
    if depth >= 1 {
        assert_eq!(host.setup(0.0, None), Status::Ok);
        assert_eq!(host.enter(), Status::Ok);
    }
    if depth == 2 {
        assert_eq!(host.exit(), Status::Ok);
    }
    (host, depth >= 1)
}

/// One fmi2Set* call with random references and values; on fmi2OK every value reads back as set.
fn set_checked(rng: &mut Rng, host: &Host<ModelVariant>, read_back: bool, case: &str) {
    let n = rng.below(4);
    let vrs: Vec<u32> = (0..n).map(|_| value_reference(rng)).collect();
    let logged = host.messages().len();
    let kind = rng.below(4);
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    let (status, expected): (Status, Vec<String>) = unsafe {
        match kind {
            0 => {
                let values: Vec<f64> = (0..n).map(|_| real(rng)).collect();
                let status = functions::set_real::<ModelVariant>(Function::fmi2SetReal, host.c, vrs.as_ptr(), n, values.as_ptr());
                (status, values.iter().map(|x| x.to_bits().to_string()).collect())
            }
            1 => {
                let values: Vec<i32> = (0..n).map(|_| integer(rng)).collect();
                let status = functions::set_integer::<ModelVariant>(Function::fmi2SetInteger, host.c, vrs.as_ptr(), n, values.as_ptr());
                (status, values.iter().map(i32::to_string).collect())
            }
            2 => {
                let values: Vec<c_int> = (0..n).map(|_| rng.next() as c_int).collect();
                let status = functions::set_boolean::<ModelVariant>(Function::fmi2SetBoolean, host.c, vrs.as_ptr(), n, values.as_ptr());
                assert!(n == 0 || status == Status::Error, "{case}: PistonSlap has no Boolean");
                (status, Vec::new())
            }
            _ => {
                // Arbitrary bytes up to a NUL: mostly invalid UTF-8, sometimes ASCII paths. A string
                // that is accepted could name a file, so it is reset before initialization ends.
                let strings: Vec<Vec<u8>> = (0..n)
                    .map(|_| {
                        let len = rng.below(40);
                        let mut s = match rng.below(2) {
                            0 => rng.bytes(len),
                            _ => (0..len).map(|_| b'a' + rng.below(26) as u8).collect(),
                        };
                        s.push(0);
                        s
                    })
                    .collect();
                let pointers: Vec<*const c_char> = strings.iter().map(|s| s.as_ptr() as *const c_char).collect();
                let status = functions::set_string::<ModelVariant>(Function::fmi2SetString, host.c, vrs.as_ptr(), n, pointers.as_ptr());
                let shown = strings.iter().map(|s| CStr::from_bytes_until_nul(s).unwrap().to_string_lossy().into_owned());
                (status, shown.collect())
            }
        }
    };
    match status {
        Status::Error => assert_eq!(host.messages().len(), logged + 1, "{case}: a refusal says why"),
        Status::Ok if read_back => {
            // The last value set for a reference is the one it holds.
            for (k, &vr) in vrs.iter().enumerate() {
                if vrs[k + 1..].contains(&vr) {
                    continue;
                }
                let v = crate::fmus::piston_slap::variable(vr).expect("accepted references exist");
                let now = match v.kind {
                    description::Kind::Real => host.real(v.name).to_bits().to_string(),
                    description::Kind::Integer => host.integer(v.name).to_string(),
                    description::Kind::String => string(host, vr),
                };
                assert_eq!(now, expected[k], "{case}: {} reads back", v.name);
            }
        }
        Status::Ok => {}
        other => panic!("{case}: set returned {other:?}: {:?}", host.messages()),
    }
}

fn string(host: &Host<ModelVariant>, vr: u32) -> String {
    let mut s: fmi2String = null();
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    assert_eq!(unsafe { functions::get_string::<ModelVariant>(Function::fmi2GetString, host.c, &vr, 1, &mut s) }, Status::Ok);
    // SAFETY: a NUL-terminated string the FMU returned, valid until its next call.
    unsafe { CStr::from_ptr(s) }.to_string_lossy().into_owned()
}

/// Returns the number of setter calls made.
fn fuzz_setters(seed: u64, cases: usize) -> usize {
    let mut rng = Rng(seed);
    let mut case = 0;
    while case < cases {
        let (host, readable) = instance(&mut rng);
        for _ in 0..32 {
            set_checked(&mut rng, &host, readable, &format!("seed {seed} case {case}"));
            case += 1;
        }
        // Whatever was accepted must initialize or be refused by name, then step or be refused. An
        // accepted random log or map path would name a file it writes: cleared first (refused once
        // fixed, in step mode).
        let label = format!("seed {seed} after case {case}");
        let cleared = ["impact_log", "landing_log", "skirt_map"].map(|name| {
            // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
            unsafe { functions::set_string::<ModelVariant>(Function::fmi2SetString, host.c, &vr(name), 1, &c"".as_ptr()) }
        });
        let _ = (host.setup(0.0, None), host.enter());
        let status = host.exit();
        assert!(matches!(status, Status::Ok | Status::Error), "{label}: exit {status:?}");
        assert!(cleared.iter().all(|&c| c == Status::Ok) || time(&host).is_some(), "{label}");
        step_checked(&host, &label);
    }
    case
}

const SEED: u64 = 0x005E_ED0F_F1A5_C0DE;

/// 1.1·10⁵ cases in an optimized build (`make test` runs `cargo test --release`: a few seconds); a
/// tenth of them in a debug build, which is about 20 times slower.
const CASES: usize = if cfg!(debug_assertions) { 11_000 } else { 110_000 };

#[test]
fn hostile_state_bytes_are_refused_or_give_a_working_state() {
    let start = std::time::Instant::now();
    let (cases, accepted) = fuzz_deserialize(SEED, CASES * 7 / 11);
    println!("fmi2DeSerializeFMUstate: {cases} cases, {accepted} accepted, {:?}", start.elapsed());
}

#[test]
fn hostile_setter_calls_are_refused_or_read_back() {
    let start = std::time::Instant::now();
    let cases = fuzz_setters(SEED ^ 1, CASES * 4 / 11);
    println!("fmi2Set*: {cases} cases, {:?}", start.elapsed());
}
