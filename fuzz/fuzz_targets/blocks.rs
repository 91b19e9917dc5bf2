//! Every registered block type through its C functions: arbitrary struct bytes (the
//! private state included), then a sequence of steps (time step, input bytes, parameter
//! bytes, re-init). The registry's rows (`safelogic::for_each_block!`) make the dispatch,
//! so a new block is fuzzed without touching this file.
//!
//! A first byte >= 0xC0 selects the structured mode instead: a valid configuration of
//! MUTING or TWOHAND built from the input (init must accept it), then bRun TRUE and a walk
//! of input changes and time steps. Their sequences (muting steps MUTING1…MUTING9, the
//! two-hand timing) are long runs of the right input changes that arbitrary struct bytes
//! reach only rarely (issue 16: MUTING 39.6 %, TWOHAND 83.5 % line coverage before).
#![no_main]

use libfuzzer_sys::fuzz_target;
use safelogic::registry::{block_type, BlockType, Dir, Registered};
use safelogic::*;

mod invariants;
use invariants::*;

type Call = unsafe extern "C" fn(*mut u8, u32) -> i32;

macro_rules! table {
    ($($ty:ty => $init:ident, $cycle:ident;)*) => {
        /// (tag, init, cycle) of every registered type.
        fn functions() -> Vec<(u16, InitFn, Call)> {
            vec![$((
                <$ty as Registered>::INFO.tag,
                {
                    unsafe extern "C" fn init(p: *mut u8) -> i32 {
                        // SAFETY: `p` is 8-aligned storage of the type's size.
                        unsafe { safelogic::ffi::$init(p.cast()) }
                    }
                    init
                },
                {
                    unsafe extern "C" fn cycle(p: *mut u8, t: u32) -> i32 {
                        // SAFETY: as above.
                        unsafe { safelogic::ffi::$cycle(p.cast(), t) }
                    }
                    cycle
                },
            )),*]
        }
    };
}
safelogic::for_each_block!(table);

/// Writes a field (by name) of the struct at `p`, in its size.
fn set(p: *mut u8, t: &BlockType, name: &str, v: u32) {
    let f = t
        .field(name)
        .unwrap_or_else(|| panic!("{}: no field {name}", t.info.name));
    let bytes = v.to_ne_bytes();
    for (i, b) in bytes.iter().enumerate().take(f.kind.size()) {
        // SAFETY: the field lies inside the struct (registry test).
        unsafe { *p.add(usize::from(f.offset) + i) = *b };
    }
}

/// A time parameter: 0 half the time, else below `max` (small values are the interesting
/// ones: the walk's time steps are at most a few seconds).
fn time(inp: &mut Input, max: u32) -> u32 {
    let v = u32::from(inp.u16());
    if v & 1 == 0 {
        0
    } else {
        (v >> 1) % (max + 1)
    }
}

/// A valid MUTING configuration (manual §4.8.1, `params_valid`): MutingIn1/2 always, one or
/// both OSSD channels, MutingIn3/4 when parallel, backwards or chosen; discrepancy times
/// only on two-channel pairs, the parallel ones only when parallel.
fn configure_muting(p: *mut u8, t: &BlockType, inp: &mut Input) {
    let o = inp.u8();
    let sequential = o & 1 != 0;
    let backwards = o & 2 != 0;
    let ossd: u32 = match (o >> 5) & 3 {
        1 => 0b0100,
        2 => 0b1000,
        _ => 0b1100,
    };
    let m34 = !sequential || backwards || o & 0x80 != 0;
    let active = 0b11 | ossd | if m34 { 0b11_0000 } else { 0 };
    let options = if sequential {
        SL_OPT_MUTING_SEQUENTIAL
    } else {
        0
    } | if backwards {
        SL_OPT_MUTING_BACKWARDS
    } else {
        0
    } | if o & 4 != 0 {
        SL_OPT_MUTING_OSSD_CHECK_OPTIONAL
    } else {
        0
    } | if o & 8 != 0 { SL_OPT_EDM1 } else { 0 }
        | if o & 16 != 0 { SL_OPT_EDM2 } else { 0 };
    set(p, t, "wInputActive", active);
    set(p, t, "wInputNegated", u32::from(inp.u8() & 0x3F));
    set(p, t, "dwOptions", options);
    let disc12 = time(inp, 3000);
    let disc_ossd = time(inp, 3000);
    let disc34 = time(inp, 3000);
    set(p, t, "tDiscTime12", if sequential { 0 } else { disc12 });
    set(
        p,
        t,
        "tDiscTimeOSSD",
        if ossd == 0b1100 { disc_ossd } else { 0 },
    );
    set(p, t, "tDiscTime34", if sequential { 0 } else { disc34 });
    set(p, t, "tFilterTime", time(inp, 500));
    set(p, t, "tMaxMutingTime", time(inp, 20_000));
    set(p, t, "tMuteDelOutDelay", time(inp, 5_000));
}

/// A valid TWOHAND configuration (manual §4.7.1): one or both channels per group,
/// discrepancy times on two-channel groups, the pair time up to 2500 ms.
fn configure_twohand(p: *mut u8, t: &BlockType, inp: &mut Input) {
    let o = inp.u8();
    let g1: u32 = [0b01, 0b10, 0b11, 0b11][usize::from(o & 3)];
    let g2: u32 = [0b0100, 0b1000, 0b1100, 0b1100][usize::from((o >> 2) & 3)];
    set(p, t, "wInputActive", g1 | g2);
    set(p, t, "wInputNegated", u32::from(inp.u8() & 0x0F));
    let safe_in = if o & 0x10 != 0 {
        SL_OPT_SAFE_INPUTS_AFTER_DISC
    } else {
        0
    };
    set(p, t, "dwOptions", safe_in);
    let disc12 = time(inp, 3000);
    let disc34 = time(inp, 3000);
    set(p, t, "tDiscTime12", if g1 == 0b11 { disc12 } else { 0 });
    set(p, t, "tDiscTime34", if g2 == 0b1100 { disc34 } else { 0 });
    set(p, t, "tDiscTimePairs", time(inp, 2500));
}

/// The structured mode: configure, init (must accept), bRun TRUE, then per step an input
/// change (toggle 0/1, rarely any byte; bit 5 of the step byte: more changes before the
/// cycle) and a time step (0, < 64 ms, < 4 s, or up to ~4.5 min).
fn walk(sel: u8, inp: &mut Input, fns: &[(u16, InitFn, Call)]) {
    let tag = if sel & 1 == 0 {
        SL_TYPE_MUTING
    } else {
        SL_TYPE_TWOHAND
    };
    let &(_, init, cycle) = fns.iter().find(|r| r.0 == tag).unwrap();
    let t = block_type(tag).unwrap();
    let mut store = aligned(t.size);
    let p = store.as_mut_ptr().cast::<u8>();
    let bytes = |p: *mut u8| -> Vec<u8> {
        // SAFETY: `t.size` initialised bytes of the storage.
        unsafe { std::slice::from_raw_parts(p, t.size) }.to_vec()
    };
    if tag == SL_TYPE_MUTING {
        configure_muting(p, t, inp);
    } else {
        configure_twohand(p, t, inp);
    }
    // SAFETY: storage of the type's size, 8-aligned.
    let rc = unsafe { init(p) };
    assert_eq!(rc, SL_OK, "{}: a valid configuration refused", t.info.name);
    check_block(t, &bytes(p), rc);
    set(p, t, "bRun", 1);
    let inputs: Vec<_> = t
        .fields
        .iter()
        .filter(|f| matches!(f.dir, Dir::Input | Dir::Control))
        .collect();
    let mut now = inp.u32();
    while !inp.is_empty() {
        let op = inp.u8();
        let f = inputs[usize::from(op & 0x1F) % inputs.len()];
        let off = usize::from(f.offset);
        // SAFETY: the field lies inside the struct (registry test).
        unsafe {
            let cur = *p.add(off);
            *p.add(off) = if op & 0xC0 == 0xC0 {
                inp.u8()
            } else {
                u8::from(cur == 0)
            };
        }
        if op & 0x20 != 0 {
            continue;
        }
        let tb = inp.u8();
        let dt = u32::from(tb & 0x3F);
        now = now.wrapping_add(match tb >> 6 {
            0 => 0,
            1 => dt,
            2 => dt * 64,
            _ => dt * 4096 + u32::from(inp.u8()),
        });
        // SAFETY: as above.
        let rc = unsafe { cycle(p, now) };
        let b = bytes(p);
        let state = check(t, &b, rc, "walk");
        let out = |name: &str| b[usize::from(t.field(name).unwrap().offset)];
        if tag == SL_TYPE_MUTING {
            // MutingActive exactly in MUTING1…MUTING9, where both outputs stay on.
            let muting = (SL_STATE_MUTING_MUTING1..=SL_STATE_MUTING_MUTING9).contains(&state);
            assert_eq!(out("bMutingActive") == 1, muting, "MUTING: state {state}");
            if muting {
                assert_eq!((out("bMuteOut"), out("bMuteDelOut")), (1, 1));
            }
        } else {
            assert_eq!(
                out("bTwoHandOut") == 1,
                state == SL_STATE_RUN,
                "TWOHAND: state {state}"
            );
        }
    }
    drop(store);
}

type InitFn = unsafe extern "C" fn(*mut u8) -> i32;

fuzz_target!(|data: &[u8]| {
    let fns = functions();
    let mut inp = Input(data);
    let sel = inp.u8();
    if sel >= 0xC0 {
        walk(sel, &mut inp, &fns);
        return;
    }
    let (tag, init, cycle) = fns[usize::from(sel) % fns.len()];
    let t = block_type(tag).unwrap();
    let mut store = aligned(t.size);
    let p = store.as_mut_ptr().cast::<u8>();
    let bytes = |p: *mut u8| -> Vec<u8> {
        // SAFETY: `t.size` initialised bytes of the storage.
        unsafe { std::slice::from_raw_parts(p, t.size) }.to_vec()
    };
    // Arbitrary struct bytes (mode 0: zeroed, 1: zeroed + init, else raw bytes).
    let mode = inp.u8() % 4;
    if mode >= 2 {
        for i in 0..t.size {
            // SAFETY: inside the storage.
            unsafe { *p.add(i) = inp.u8() };
        }
    }
    if mode == 1 || mode == 3 {
        // SAFETY: storage of the type's size, 8-aligned.
        let rc = unsafe { init(p) };
        assert!(
            rc == safelogic::SL_OK || rc == safelogic::SL_E_CONFIG,
            "init: {rc}"
        );
        check_block(t, &bytes(p), rc);
    }
    let inputs: Vec<_> = t
        .fields
        .iter()
        .filter(|f| matches!(f.dir, Dir::Input | Dir::Control))
        .collect();
    let params: Vec<_> = t.fields.iter().filter(|f| f.dir == Dir::Param).collect();
    let mut now = inp.u32();
    while !inp.is_empty() {
        let op = inp.u8();
        match op % 8 {
            // An input or control byte: mostly 0/1, sometimes anything.
            0..=3 if !inputs.is_empty() => {
                let f = inputs[usize::from(inp.u8()) % inputs.len()];
                let v = inp.u8();
                let v = if op & 0x80 == 0 { v & 1 } else { v };
                for i in 0..f.kind.size() {
                    // SAFETY: the field lies inside the struct (registry test).
                    unsafe {
                        *p.add(usize::from(f.offset) + i) = if i == 0 { v } else { inp.u8() }
                    };
                }
            }
            // A parameter word.
            4 if !params.is_empty() => {
                let f = params[usize::from(inp.u8()) % params.len()];
                for i in 0..f.kind.size() {
                    // SAFETY: as above.
                    unsafe { *p.add(usize::from(f.offset) + i) = inp.u8() };
                }
            }
            // Any byte of the struct (private state included).
            5 if op & 0xF0 == 0xF0 => {
                let i = usize::from(inp.u16()) % t.size;
                // SAFETY: inside the storage.
                unsafe { *p.add(i) = inp.u8() };
            }
            6 if op & 0xF0 == 0xF0 => {
                // SAFETY: as above.
                let rc = unsafe { init(p) };
                check_block(t, &bytes(p), rc);
            }
            _ => {}
        }
        // A time step: small mostly, backwards or huge sometimes.
        let dt = inp.u16();
        now = match op >> 5 {
            7 => now.wrapping_add(inp.u32()),
            _ => now.wrapping_add(u32::from(dt % 2048)),
        };
        // SAFETY: as above.
        let rc = unsafe { cycle(p, now) };
        check_block(t, &bytes(p), rc);
    }
    drop(store);
});
