//! Every registered block type through its C functions: arbitrary struct bytes (the
//! private state included), then a sequence of steps (time step, input bytes, parameter
//! bytes, re-init). The registry's rows (`safelogic::for_each_block!`) make the dispatch,
//! so a new block is fuzzed without touching this file.
#![no_main]

use libfuzzer_sys::fuzz_target;
use safelogic::registry::{block_type, Dir, Registered};

mod invariants;
use invariants::*;

type Call = unsafe extern "C" fn(*mut u8, u32) -> i32;

macro_rules! table {
    ($($ty:ty => $init:ident, $cycle:ident;)*) => {
        /// (tag, init, cycle) of every registered type.
        fn functions() -> Vec<(u16, unsafe extern "C" fn(*mut u8) -> i32, Call)> {
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

fuzz_target!(|data: &[u8]| {
    let fns = functions();
    let mut inp = Input(data);
    let (tag, init, cycle) = fns[usize::from(inp.u8()) % fns.len()];
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
        assert!(rc == safelogic::SL_OK || rc == safelogic::SL_E_CONFIG, "init: {rc}");
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
                    unsafe { *p.add(usize::from(f.offset) + i) = if i == 0 { v } else { inp.u8() } };
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
