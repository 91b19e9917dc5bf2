//! The conformance harness every registered block type gets by being registered (the rows
//! of `safelogic::for_each_block!`): random bytes in every field, the private state
//! included, random time steps and input changes through the C functions → no panic, a
//! documented status, and the safe-state invariants read through the field table; a
//! zeroed instance is valid; the field table agrees with the C header (a C program built
//! from the table, compiled against include/safelogic.h); and at depth, 10,000 sequences
//! from valid configurations per type with the safety invariants after every call.

use safelogic::registry::{block_type, Dir, Kind, BLOCKS};
mod common;
#[path = "common/invariants.rs"]
mod invariants;

use common::Rng;
use invariants::*;
use safelogic::*;
use std::collections::BTreeSet;

macro_rules! harness {
    ($($ty:ty => $init:ident, $cycle:ident;)*) => {
        /// Runs `steps` random calls on every registered type; returns the states reached.
        fn run_all(seed: u64, rounds: usize, steps: usize) -> Vec<(&'static str, BTreeSet<u8>)> {
            let mut reached = Vec::new();
            $({
                let t = block_type(<$ty as safelogic::base::block::Registered>::INFO.tag).unwrap();
                assert_eq!(t.size, std::mem::size_of::<$ty>());
                let mut rng = Rng(seed ^ u64::from(t.info.tag).wrapping_mul(0x9E37_79B9));
                let mut states = BTreeSet::new();
                for round in 0..rounds {
                    // SAFETY: every block struct holds only integer fields (and zero-sized
                    // markers), so every byte pattern is a valid value.
                    let mut fb: $ty = unsafe { std::mem::zeroed() };
                    let bytes = |fb: &mut $ty| -> &mut [u8] {
                        // SAFETY: as above; the slice covers exactly the instance.
                        unsafe { std::slice::from_raw_parts_mut((fb as *mut $ty).cast::<u8>(), std::mem::size_of::<$ty>()) }
                    };
                    // A zeroed instance is a valid, never-initialised one.
                    // SAFETY: a live, exclusively borrowed instance.
                    let rc = unsafe { safelogic::ffi::$cycle(&mut fb, 0) };
                    assert!(rc == SL_OK || rc == SL_E_CONFIG, "{}: zeroed instance gave {rc}", t.info.name);
                    states.insert(check(t, bytes(&mut fb), rc, "zeroed"));
                    // Random bytes everywhere (every other round with a fresh init first).
                    for b in bytes(&mut fb).iter_mut() {
                        *b = rng.next() as u8;
                    }
                    if round % 2 == 0 {
                        // SAFETY: as above.
                        let rc = unsafe { safelogic::ffi::$init(&mut fb) };
                        assert!(rc == SL_OK || rc == SL_E_CONFIG, "{}: init gave {rc}", t.info.name);
                        states.insert(check(t, bytes(&mut fb), rc, "init"));
                    }
                    let mut now = rng.next() as u32;
                    for step in 0..steps {
                        let r = rng.next();
                        // Mostly valid BOOL bytes and small steps, sometimes anything.
                        for f in t.fields.iter().filter(|f| matches!(f.dir, Dir::Input | Dir::Control)) {
                            if rng.next() % 4 == 0 {
                                let o = usize::from(f.offset);
                                let v = rng.next();
                                let bs = bytes(&mut fb);
                                if f.kind == Kind::Bool {
                                    bs[o] = if v % 50 == 0 { v as u8 } else { (v & 1) as u8 };
                                } else {
                                    for (k, b) in bs[o..o + f.kind.size()].iter_mut().enumerate() {
                                        *b = (v >> (8 * k)) as u8;
                                    }
                                }
                            }
                        }
                        if r % 97 == 0 {
                            let bs = bytes(&mut fb);
                            let i = (rng.next() as usize) % bs.len();
                            bs[i] = rng.next() as u8;
                        }
                        now = match r % 100 {
                            0 => now.wrapping_sub(1 + (rng.next() % 1000) as u32),
                            1 => rng.next() as u32,
                            _ => now.wrapping_add((rng.next() % 200) as u32),
                        };
                        // SAFETY: as above.
                        let rc = unsafe { safelogic::ffi::$cycle(&mut fb, now) };
                        states.insert(check(t, bytes(&mut fb), rc, &format!("round {round} step {step}")));
                    }
                }
                reached.push((t.info.name, states));
            })*
            reached
        }
    };
}

safelogic::for_each_twinsafe_block!(harness);

macro_rules! unknown_state {
    ($($ty:ty => $init:ident, $cycle:ident;)*) => {
        /// A sealed private header with a state value the block does not have is corrupt: for
        /// every registered type, every value 0–255 outside its state table.
        #[test]
        fn an_unknown_state_value_is_corrupt() {
            use safelogic::base::envelope::Instance;
            let mut checked = 0;
            $({
                let t = block_type(<$ty as safelogic::base::block::Registered>::INFO.tag).unwrap();
                for state in 0..=255u8 {
                    if t.info.states.iter().any(|(v, _)| *v == state) {
                        continue;
                    }
                    let mut fb = <$ty>::default();
                    FunctionBlock::init(&mut fb);
                    fb.header_mut().nState = state;
                    fb.header_mut().seal();
                    fb.bRun = 1;
                    assert_eq!(FunctionBlock::cycle(&mut fb, 0), SL_E_CORRUPT, "{} state {state}", t.info.name);
                    assert_eq!(fb.nState, SL_STATE_ERROR);
                    assert!(fb.nDiag & SL_DIAG_CORRUPT != 0);
                    checked += 1;
                }
            })*
            assert!(checked > 200 * twinsafe_count(), "{checked} forged states");
        }
    };
}

safelogic::for_each_twinsafe_block!(unknown_state);

#[test]
fn every_registered_type_survives_random_bytes() {
    let reached = run_all(0x5AFE_10C1C, 200, 60);
    assert_eq!(
        reached.len() + sf_run_all(0x5AFE_10C1C, 200, 60).len(),
        BLOCKS.len(),
        "the harness covers every registered type"
    );
    for (name, states) in reached {
        // Random private bytes are corrupt (ERROR); a zeroed or refused instance is STOP.
        assert!(
            states.contains(&SL_STATE_ERROR),
            "{name} never reached ERROR: {states:?}"
        );
        assert!(
            states.contains(&SL_STATE_STOP),
            "{name} never reached STOP: {states:?}"
        );
    }
}

/// The field table against the header: a C program with one static assertion per field,
/// generated from the table and compiled against include/safelogic.h.
#[test]
fn field_tables_agree_with_the_header() {
    let mut c = String::from("#include <stddef.h>\n#include \"safelogic.h\"\n");
    let mut n = 0;
    for t in BLOCKS {
        let s = format!("{}{}", t.struct_prefix(), t.info.name);
        c += &format!(
            "_Static_assert(sizeof({s}) == {}, \"size of {s}\");\n",
            t.size
        );
        for f in t.fields {
            c += &format!(
                "_Static_assert(offsetof({s}, {0}) == {1} && sizeof((({s} *)0)->{0}) == {2}, \"{s}.{0}\");\n",
                f.name,
                f.offset,
                f.kind.size()
            );
            n += 1;
        }
    }
    c += "int main(void) { return 0; }\n";
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let src = dir.join("field_tables.c");
    std::fs::write(&src, c).unwrap();
    let include = concat!(env!("CARGO_MANIFEST_DIR"), "/include");
    let out = std::process::Command::new("cc")
        .args([
            "-std=c11",
            "-Wall",
            "-Werror",
            "-fsyntax-only",
            "-I",
            include,
        ])
        .arg(&src)
        .output()
        .expect("a C compiler (cc) is needed for this test");
    assert!(
        out.status.success(),
        "the field table disagrees with the header:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(n > 300, "{n} fields checked");
}

macro_rules! named_access {
    ($($ty:ty => $init:ident, $cycle:ident;)*) => {
        /// The Rust face reads and writes every field by its field-table name: inputs and
        /// parameters are writable within their type's range, outputs and info data are not,
        /// and a value written reads back.
        #[test]
        fn fields_by_name() {
            $({
                let mut fb = <$ty>::default();
                for f in <$ty as safelogic::base::block::Registered>::FIELDS {
                    let writable = matches!(f.dir, Dir::Input | Dir::Param | Dir::Control);
                    let v: i64 = match f.kind { Kind::Bool => 1, Kind::I16 | Kind::I32 => -2, _ => 2 };
                    assert_eq!(fb.set(f.name, v).is_ok(), writable, "{}", f.name);
                    if writable {
                        assert_eq!(fb.get(f.name), Some(v as i32 as u32), "{}", f.name);
                        let too_big = match f.kind {
                            Kind::Bool => 2,
                            Kind::U8 => 256,
                            Kind::U16 => 65_536,
                            Kind::I16 => 32_768,
                            Kind::U32 => 1 << 32,
                            Kind::I32 => 1 << 31,
                        };
                        assert_eq!(fb.set(f.name, too_big), Err(Status::Config), "{}", f.name);
                    }
                    if f.kind == Kind::Bool && writable {
                        assert_eq!(fb.get_bool(f.name), Some(true));
                    }
                }
                assert_eq!(fb.set("bNoSuchField", 0), Err(Status::Config));
                assert_eq!(fb.get("bNoSuchField"), None);
            })*
        }
    };
}

safelogic::for_each_block!(named_access);

/// Sequences per registered type in the depth test (×`SL_PROP_DEPTH` in a deep run).
const DEPTH_SEQUENCES: usize = 10_000;

macro_rules! depth {
    ($($ty:ty => $init:ident, $cycle:ident;)*) => {
        /// Issue 16 item 4, for every registered type: `sequences` random sequences of 16
        /// calls from valid configurations (found by the library itself: random parameters
        /// until `init` accepts them), mostly valid BOOL bytes, random analog values, bRun
        /// mostly TRUE, ErrAck pulses, time steps up to 100 ms and now and then a clock that
        /// goes back. After every call: `check` (documented status, a state of the block's,
        /// bError exactly in ERROR, every output FALSE/0 in STOP, ERROR, RESET and after a
        /// refusing status) and the same-call response to bRun FALSE (STOP, ERROR or RESET
        /// after the call). Returns, per type, the states reached.
        fn depth_all(sequences: usize) -> Vec<(&'static str, BTreeSet<u8>)> {
            let mut reached = Vec::new();
            $({
                let t = block_type(<$ty as safelogic::base::block::Registered>::INFO.tag).unwrap();
                let mut rng = Rng(0xDE97_0000 ^ u64::from(t.info.tag));
                let bytes = |fb: &mut $ty| -> &mut [u8] {
                    // SAFETY: every block struct holds only integer fields (and zero-sized
                    // markers); the slice covers exactly the instance.
                    unsafe { std::slice::from_raw_parts_mut((fb as *mut $ty).cast::<u8>(), std::mem::size_of::<$ty>()) }
                };
                let put = |bs: &mut [u8], o: u16, size: usize, v: u64| {
                    for (k, b) in bs[usize::from(o)..usize::from(o) + size].iter_mut().enumerate() {
                        *b = (v >> (8 * k)) as u8;
                    }
                };
                // A pool of valid configurations. A type with several bit-set parameters
                // that each admit only a few values (SCALE: wInputActive, wInputNegated,
                // dwOptions) rarely meets them all at once: when the first 400,000 draws
                // did not fill the pool, 400,000 more draw every bit set as 0, one bit or a
                // run of bits.
                let mut pool: Vec<$ty> = Vec::new();
                for attempt in 0..800_000 {
                    if pool.len() == 64 {
                        break;
                    }
                    let bit_sets = attempt >= 400_000;
                    // SAFETY: integer fields only.
                    let mut fb: $ty = unsafe { std::mem::zeroed() };
                    for f in t.fields.iter().filter(|f| f.dir == Dir::Param) {
                        let r = rng.next();
                        // Bit sets (wInputActive …) often as a run of low bits, in the BOOL or
                        // the analog half, now and then in both halves (SLI: bits 0 and 8).
                        let k = (r >> 16) % 8 + 1;
                        let bit_set = f.name.starts_with('w') || f.name.starts_with("dw");
                        let run = (1u64 << k) - 1;
                        let run_of_bits = if (r >> 21) % 4 == 0 {
                            run | run << 8
                        } else {
                            run << (8 * ((r >> 20) & 1))
                        };
                        let v = match r % 4 {
                            _ if bit_set && bit_sets => [0, 1 << ((r >> 24) % 16), run_of_bits][(r % 3) as usize],
                            _ if f.name.starts_with('w') && r % 3 == 0 => run_of_bits,
                            // TIME parameters now and then in whole seconds (SBT's interval
                            // is a multiple of 1000 ms, ABI-2 §11.15).
                            _ if f.name.starts_with('t') && (r >> 40) % 4 == 0 => 1000 * ((r >> 8) % 50),
                            0 => [0u64, 1, 2, 3, 5, 10, 100][(r >> 8) as usize % 7],
                            1 => (r >> 8) & 0xFF,
                            2 => (r >> 8) & 0xFFFF,
                            _ => r >> 8,
                        };
                        put(bytes(&mut fb), f.offset, f.kind.size(), v);
                    }
                    // A value table (LOADSENSING `aRow`, ABI-2 §11.8) is a parameter outside
                    // the field table, right before `nRowCount`: random rows are almost never
                    // ordered, so it gets an ordered one (X increasing; Y1 = WY1 < Y2 = WY2,
                    // valid with and without the Outside option) around the small inputs.
                    if let (Some(count), Some(x)) = (t.field("nRowCount"), t.field("nAnalogInX")) {
                        let w = x.kind.size();
                        let rows = usize::from(SL_LOADSENSING_ROWS_MAX);
                        let base = usize::from(count.offset) - rows * 5 * w;
                        for i in 0..rows {
                            let r = rng.next();
                            let y1 = (r % 6) as u64;
                            let y2 = y1 + 1 + (r >> 8) % 4;
                            for (k, v) in [i as u64, y1, y2, y1, y2].into_iter().enumerate() {
                                put(bytes(&mut fb), ((base + (5 * i + k) * w) as u16), w, v);
                            }
                        }
                    }
                    // Ordered fixed limits (CAMMONITOR, ABI-2 §11.13: seven limits that the
                    // ordering checks want increasing around the circle, with gaps of the
                    // jitter): random values almost never are, so every other draw gets
                    // limits scaled from a drawn MaxPosition and jitter in the mode the drawn
                    // `dwOptions` select (bit 8 = pendulum), the mode's unused ones 0.
                    if let (Some(mx), true) = (t.field("nMaxPosition"), attempt % 2 == 0) {
                        let w = mx.kind.size();
                        let r = rng.next();
                        let m = 2000 + r % if w == 2 { 60_000 } else { 1 << 30 };
                        let j = (r >> 32) % (m / 200 + 1);
                        let opt = t.field("dwOptions").unwrap();
                        let pendulum = read(bytes(&mut fb), opt.offset, opt.kind) & 0x100 != 0;
                        let (lo, hi) = (m / 2 - j - 1 - m / 50, m / 2 + j + 1 + m / 50);
                        let limits: [(&str, u64); 9] = if pendulum {
                            [
                                ("nTDC2UpperLimitFix", j + 1 + m / 100),
                                ("nTDC2LowerLimitFix", 3 * j + 2 + m / 10),
                                ("nBDCLowerLimitFix", lo),
                                ("nBDCUpperLimitFix", hi),
                                ("nTDC1LowerLimitFix", m - 3 * j - 2 - m / 10),
                                ("nTDC1UpperLimitFix", m - j - 1 - m / 100),
                                ("nOverrunMaxFix", 0),
                                ("nAllowedPositionJitter", j),
                                ("nMaxPosition", m),
                            ]
                        } else {
                            [
                                ("nTDC1UpperLimitFix", j + 1 + m / 100),
                                ("nOverrunMaxFix", 3 * j + 2 + m / 10),
                                ("nBDCLowerLimitFix", lo),
                                ("nBDCUpperLimitFix", hi),
                                ("nTDC1LowerLimitFix", m - j - m / 100),
                                ("nTDC2LowerLimitFix", 0),
                                ("nTDC2UpperLimitFix", 0),
                                ("nAllowedPositionJitter", j),
                                ("nMaxPosition", m),
                            ]
                        };
                        for (name, v) in limits {
                            let f = t.field(name).unwrap();
                            put(bytes(&mut fb), f.offset, f.kind.size(), v);
                        }
                    }
                    // SAFETY: a live, exclusively borrowed instance.
                    if unsafe { safelogic::ffi::$init(&mut fb) } == SL_OK {
                        pool.push(fb);
                    }
                }
                assert!(!pool.is_empty(), "{}: no valid configuration found", t.info.name);
                let mut states = BTreeSet::new();
                for seq in 0..sequences {
                    let mut fb = pool[seq % pool.len()];
                    let mut now = rng.next() as u32;
                    for step in 0..16 {
                        let r = rng.next();
                        for f in t.fields.iter().filter(|f| f.dir == Dir::Input) {
                            let v = rng.next();
                            if v % 3 != 0 {
                                continue;
                            }
                            let value = if f.kind == Kind::Bool {
                                if v % 301 == 0 { 2 } else { (v >> 8) & 1 }
                            } else if v % 2 == 0 {
                                (v >> 8) % 8
                            } else {
                                v >> 8
                            };
                            put(bytes(&mut fb), f.offset, f.kind.size(), value);
                        }
                        let run = r % 8 != 0;
                        fb.bRun = u8::from(run);
                        fb.bErrAck = u8::from(r >> 3 & 7 == 0);
                        now = if r >> 6 & 255 == 0 {
                            now.wrapping_sub(1 + (rng.next() % 50) as u32)
                        } else {
                            now.wrapping_add((rng.next() % 101) as u32)
                        };
                        // SAFETY: as above.
                        let rc = unsafe { safelogic::ffi::$cycle(&mut fb, now) };
                        let what = format!("sequence {seq} step {step}");
                        let state = check(t, bytes(&mut fb), rc, &what);
                        if !run {
                            assert!(
                                matches!(state, SL_STATE_STOP | SL_STATE_ERROR | SL_STATE_RESET),
                                "{} {what}: bRun FALSE left state {state}", t.info.name
                            );
                        }
                        states.insert(state);
                    }
                }
                reached.push((t.info.name, states));
            })*
            reached
        }
    };
}

safelogic::for_each_twinsafe_block!(depth);

#[test]
fn every_registered_type_keeps_its_safety_properties_over_10000_sequences() {
    let depth: usize = std::env::var("SL_PROP_DEPTH")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1);
    let reached = depth_all(DEPTH_SEQUENCES * depth);
    assert_eq!(reached.len(), twinsafe_count());
    for (name, states) in reached {
        for s in [SL_STATE_STOP, SL_STATE_ERROR, SL_STATE_RESET] {
            assert!(states.contains(&s), "{name} never reached {s}: {states:?}");
        }
        assert!(
            states
                .iter()
                .any(|s| !matches!(*s, SL_STATE_STOP | SL_STATE_ERROR | SL_STATE_RESET)),
            "{name} never reached a running state: {states:?}"
        );
    }
}

fn twinsafe_count() -> usize {
    BLOCKS
        .iter()
        .filter(|b| {
            safelogic::base::block::family(b.info.tag) == safelogic::base::block::Family::TwinSafe
        })
        .count()
}

/// The factor on the depth run's time steps (0–40 ms): SF_TwoHandControlTypeIII's fixed
/// 500 ms synchronism time is reached in 24 calls only with longer steps.
fn sf_time_scale(name: &str) -> u32 {
    match name {
        "SF_TwoHandControlTypeIII" => 15,
        _ => 1,
    }
}

macro_rules! sf_harness {
    ($($ty:ty => $init:ident, $cycle:ident;)*) => {
        /// Random bytes everywhere (the private state included), random time steps and
        /// input changes through the C functions, for every PLCopen type: `check_sf` after
        /// every call. Returns the DiagCodes reached per type.
        fn sf_run_all(seed: u64, rounds: usize, steps: usize) -> Vec<(&'static str, BTreeSet<u16>)> {
            let mut reached = Vec::new();
            $({
                let t = block_type(<$ty as safelogic::base::block::Registered>::INFO.tag).unwrap();
                assert_eq!(t.size, std::mem::size_of::<$ty>());
                let mut rng = Rng(seed ^ u64::from(t.info.tag).wrapping_mul(0x9E37_79B9));
                let mut codes = BTreeSet::new();
                for round in 0..rounds {
                    // SAFETY: integer fields only: every byte pattern is a valid value.
                    let mut fb: $ty = unsafe { std::mem::zeroed() };
                    let bytes = |fb: &mut $ty| -> &mut [u8] {
                        // SAFETY: as above; the slice covers exactly the instance.
                        unsafe { std::slice::from_raw_parts_mut((fb as *mut $ty).cast::<u8>(), std::mem::size_of::<$ty>()) }
                    };
                    // SAFETY: a live, exclusively borrowed instance.
                    let rc = unsafe { safelogic::ffi::$cycle(&mut fb, 0) };
                    assert_eq!(rc, SL_OK, "{}: zeroed instance", t.info.name);
                    codes.insert(check_sf(t, bytes(&mut fb), rc, "zeroed"));
                    for b in bytes(&mut fb).iter_mut() {
                        *b = rng.next() as u8;
                    }
                    if round % 4 == 1 {
                        // Activated: the random private state is a fault (C3FF), not idle.
                        safelogic::base::sf::SfInstance::set_activate_raw(&mut fb, 1);
                    }
                    if round % 2 == 0 {
                        // SAFETY: as above.
                        let rc = unsafe { safelogic::ffi::$init(&mut fb) };
                        assert!(rc == SL_OK || rc == SL_E_CONFIG, "{}: init gave {rc}", t.info.name);
                        codes.insert(check_sf(t, bytes(&mut fb), rc, "init"));
                    }
                    let mut now = rng.next() as u32;
                    for step in 0..steps {
                        let r = rng.next();
                        for f in t.fields.iter().filter(|f| matches!(f.dir, Dir::Input | Dir::Param)) {
                            if rng.next() % 4 == 0 {
                                let o = usize::from(f.offset);
                                let v = rng.next();
                                let bs = bytes(&mut fb);
                                if f.kind == Kind::Bool {
                                    bs[o] = if v % 50 == 0 { v as u8 } else { (v & 1) as u8 };
                                } else if f.dir == Dir::Param && v % 8 != 0 {
                                    // Mostly a valid profile / small time: states are reached.
                                    bs[o] = (v % 2) as u8;
                                } else {
                                    for (k, b) in bs[o..o + f.kind.size()].iter_mut().enumerate() {
                                        *b = (v >> (8 * k)) as u8;
                                    }
                                }
                            }
                        }
                        if r % 97 == 0 {
                            let bs = bytes(&mut fb);
                            let i = (rng.next() as usize) % bs.len();
                            bs[i] = rng.next() as u8;
                        }
                        now = match r % 100 {
                            0 => now.wrapping_sub(1 + (rng.next() % 1000) as u32),
                            1 => rng.next() as u32,
                            _ => now.wrapping_add((rng.next() % 200) as u32),
                        };
                        // SAFETY: as above.
                        let rc = unsafe { safelogic::ffi::$cycle(&mut fb, now) };
                        codes.insert(check_sf(t, bytes(&mut fb), rc, &format!("round {round} step {step}")));
                    }
                }
                reached.push((t.info.name, codes));
            })*
            reached
        }

        /// A sealed private state whose code is not one of the block's (nor the library's)
        /// is corrupt: the library fault C3FF with Activate TRUE, idle with Activate FALSE.
        #[test]
        fn sf_an_unknown_diag_code_is_corrupt() {
            use safelogic::base::sf::{DiagState, SfBlock, SfInstance};
            let mut checked = 0;
            $({
                let t = block_type(<$ty as safelogic::base::block::Registered>::INFO.tag).unwrap();
                for code in (0..=0xFFFFu16).step_by(7) {
                    if code == 0 || <<$ty as SfBlock>::Diag as DiagState>::decode(code).is_some() {
                        continue;
                    }
                    for activate in [1u8, 0] {
                        let mut fb = <$ty>::default();
                        FunctionBlock::init(&mut fb);
                        let h = &mut fb.sf_private_mut().stHeader;
                        h.wDiag = code;
                        h.nState = SL_STATE_RUN;
                        h.seal();
                        fb.set_activate_raw(activate);
                        assert_eq!(FunctionBlock::cycle(&mut fb, 0), SL_E_CORRUPT, "{} {code:04X}", t.info.name);
                        let expect = if activate == 1 { SL_SF_DIAG_CORRUPT } else { 0 };
                        assert_eq!(fb.DiagCode, expect, "{} {code:04X}", t.info.name);
                        assert_eq!(fb.Error, u8::from(activate == 1));
                        checked += 1;
                    }
                }
            })*
            assert!(checked > 15_000, "{checked} forged codes");
        }

        /// 10,000 random sequences of 24 calls per PLCopen type from valid configurations
        /// (both profiles): `check_sf` after every call. Returns the DiagCodes reached.
        fn sf_depth_all(sequences: usize) -> Vec<(&'static str, BTreeSet<u16>)> {
            let mut reached = Vec::new();
            $({
                let t = block_type(<$ty as safelogic::base::block::Registered>::INFO.tag).unwrap();
                let mut rng = Rng(0xDE97_5F00 ^ u64::from(t.info.tag));
                let bytes = |fb: &mut $ty| -> &mut [u8] {
                    // SAFETY: integer fields only; the slice covers exactly the instance.
                    unsafe { std::slice::from_raw_parts_mut((fb as *mut $ty).cast::<u8>(), std::mem::size_of::<$ty>()) }
                };
                let mut codes = BTreeSet::new();
                for seq in 0..sequences {
                    let mut fb = <$ty>::default();
                    for f in t.fields.iter().filter(|f| f.dir == Dir::Param) {
                        let v = if f.name == "nDiagProfile" {
                            (seq % 2) as i64
                        } else if f.name.starts_with("Trailing") {
                            // SF_ResetButton: at least 100 ms, in either order (C000).
                            (100 + rng.next() % 100) as i64
                        } else if f.name == "TestTime" && seq % 16 == 3 {
                            // SF_TestableSafetySensor: above 150 ms is C000.
                            151
                        } else if f.kind == Kind::Bool {
                            // A BOOL constant (AutoSetMode).
                            (rng.next() % 2) as i64
                        } else {
                            (rng.next() % 60) as i64
                        };
                        fb.set(f.name, v).unwrap();
                    }
                    if FunctionBlock::init(&mut fb) != SL_OK {
                        continue;
                    }
                    let mut now = rng.next() as u32;
                    for step in 0..24 {
                        let r = rng.next();
                        for f in t.fields.iter().filter(|f| f.dir == Dir::Input) {
                            let v = rng.next();
                            // SF_TestableSafetySensor's NoExternalTest is a BOOL constant (a
                            // change is C3FD): drawn once per sequence.
                            let change = if f.name == sf_activate_name(t) {
                                v % 16 == 0
                            } else if f.name == "NoExternalTest" {
                                step == 0
                            } else {
                                v % 3 == 0
                            };
                            if change {
                                let value = if v % 401 == 0 { 2 } else { ((v >> 8) & 1) as u8 };
                                bytes(&mut fb)[usize::from(f.offset)] = value;
                            }
                        }
                        if step == 0 {
                            safelogic::base::sf::SfInstance::set_activate_raw(&mut fb, 1);
                        }
                        now = if r & 255 == 0 {
                            now.wrapping_sub(1 + (rng.next() % 50) as u32)
                        } else {
                            now.wrapping_add((rng.next() % 41) as u32 * sf_time_scale(t.info.name))
                        };
                        // SAFETY: a live, exclusively borrowed instance.
                        let rc = unsafe { safelogic::ffi::$cycle(&mut fb, now) };
                        codes.insert(check_sf(t, bytes(&mut fb), rc, &format!("sequence {seq} step {step}")));
                    }
                }
                reached.push((t.info.name, codes));
            })*
            reached
        }
    };
}

safelogic::for_each_sf_block!(sf_harness);

#[test]
fn every_plcopen_type_survives_random_bytes() {
    for (name, codes) in sf_run_all(0x5F5F_10C1C, 200, 60) {
        for c in [0, SL_SF_DIAG_CORRUPT] {
            assert!(
                codes.contains(&c),
                "{name} never reached {c:04X}: {codes:X?}"
            );
        }
    }
}

/// Every state of every PLCopen type is reached by the random sequences, in both profiles
/// where the block has v1.0 codes (the v1.0-only codes included), and the properties of
/// `check_sf` hold after every call.
#[test]
fn every_plcopen_type_keeps_its_properties_over_10000_sequences() {
    use safelogic::base::sf::DiagState;
    let depth: usize = std::env::var("SL_PROP_DEPTH")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1);
    for (name, codes) in sf_depth_all(DEPTH_SEQUENCES * depth) {
        let t = safelogic::registry::block_type_named(name).unwrap();
        // The v2.01 states: every code of the block's table.
        let table: Vec<u16> = t.info.diag_values.iter().map(|(c, _)| *c).collect();
        let v2 = match name {
            "SF_EmergencyStop" | "SF_ESPE" | "SF_PSE" => {
                <safelogic::blocks::plcopen::restart::RestartState as DiagState>::TABLE
            }
            "SF_Equivalent" | "SF_Antivalent" => {
                <safelogic::blocks::plcopen::pair::PairState as DiagState>::TABLE
            }
            "SF_Guard" => <safelogic::blocks::plcopen::guard::SfGuardState as DiagState>::TABLE,
            "SF_SafetyRequest" => {
                <safelogic::blocks::plcopen::safetyrequest::SafetyRequestState as DiagState>::TABLE
            }
            "SF_OutControl" => {
                <safelogic::blocks::plcopen::outcontrol::OutControlState as DiagState>::TABLE
            }
            "SF_EnableSwitch" => {
                <safelogic::blocks::plcopen::enableswitch::EnableSwitchState as DiagState>::TABLE
            }
            "SF_TwoHandControlTypeII" => {
                <safelogic::blocks::plcopen::twohand::TwoHandIIState as DiagState>::TABLE
            }
            "SF_TwoHandControlTypeIII" => {
                <safelogic::blocks::plcopen::twohand::TwoHandIIIState as DiagState>::TABLE
            }
            "SF_ModeSelector" => {
                <safelogic::blocks::plcopen::modeselector::ModeState as DiagState>::TABLE
            }
            "SF_ResetButton" => {
                <safelogic::blocks::plcopen::resetbutton::ResetButtonState as DiagState>::TABLE
            }
            "SF_EDM" => <safelogic::blocks::plcopen::edm::SfEdmState as DiagState>::TABLE,
            "SF_TestableSafetySensor" => {
                <safelogic::blocks::plcopen::testablesafetysensor::TssState as DiagState>::TABLE
            }
            other => panic!("{other}: no state table named in this test"),
        };
        for (c2, c1, n, _) in v2 {
            assert!(
                codes.contains(c2),
                "{name} never reached {n} ({c2:04X}): {codes:X?}"
            );
            if name != "SF_PSE" {
                assert!(
                    codes.contains(c1),
                    "{name} never reached v1.0 {n} ({c1:04X})"
                );
            }
        }
        assert!(table.iter().all(|c| codes.contains(c) || name == "SF_PSE"));
        assert!(
            codes.contains(&SL_SF_DIAG_CLOCK),
            "{name}: clock fault not reached"
        );
    }
}
