//! Shared helpers for the FB_ESTOP / FB_MON integration tests.
//!
//! Every expected value in the tests comes from the manual (`shared/spec/
//! twinsafe-logic-fb-manual.txt` §4.4 / §4.5), `shared/design/ABI.md` and
//! `docs/semantics.md` (rows C1–C12, G1–G15); this module only encodes the manual's state
//! tables and drives the blocks.
#![allow(dead_code, non_snake_case)]

use safelogic::*;

/// A heap value owned through the raw pointer of its box (freed on drop), for tests whose
/// group keeps pointers into it across library calls: the pointers handed to the library
/// and the test's own field accesses all derive from this one pointer ([`Self::ptr`]), so
/// neither invalidates the other (Miri, Stacked and Tree Borrows). Field access goes
/// through `Deref` / `DerefMut`, a borrow that ends before the next library call.
pub struct RawBox<T>(*mut T);

impl<T> RawBox<T> {
    pub fn new(value: T) -> Self {
        Self(Box::into_raw(Box::new(value)))
    }
    /// The pointer every other pointer into the value is derived from.
    pub fn ptr(&self) -> *mut T {
        self.0
    }
}

impl<T> Drop for RawBox<T> {
    fn drop(&mut self) {
        // SAFETY: the pointer of the box made in `new`, dropped once.
        drop(unsafe { Box::from_raw(self.0) });
    }
}

impl<T> std::ops::Deref for RawBox<T> {
    type Target = T;
    fn deref(&self) -> &T {
        // SAFETY: a live box (freed only on drop); no library call runs while the borrow
        // lives.
        unsafe { &*self.0 }
    }
}

impl<T> std::ops::DerefMut for RawBox<T> {
    fn deref_mut(&mut self) -> &mut T {
        // SAFETY: as in `deref`.
        unsafe { &mut *self.0 }
    }
}

/// A start time far away from 0 so that "earlier" times exist.
pub const T0: u32 = 10_000;

/// Every status code the ABI documents (ABI §5 and semantics C11).
pub const DOCUMENTED_STATUS: [i32; 9] = [
    SL_OK,
    SL_E_NULL,
    SL_E_CONFIG,
    SL_E_PARAM_CHANGED,
    SL_E_CORRUPT,
    SL_E_INVALID_BOOL,
    SL_E_CLOCK,
    SL_E_INTERNAL,
    SL_E_ALIGNMENT,
];

/// States of FB ESTOP (manual §4.4.2 status table).
pub const ESTOP_STATES: [u8; 7] = [1, 2, 3, 4, 5, 6, 8];
/// States of FB MON (manual §4.5.2 status table).
pub const MON_STATES: [u8; 9] = [1, 2, 3, 4, 5, 6, 7, 8, 9];

/// Outputs [Error, Out, DelOut] of a state exactly as the manual's state tables list them
/// (§4.4.2 and §4.5.2; ERRORDELAY and FUNCTEST only exist for MON).
pub fn table(state: u8) -> [u8; 3] {
    match state {
        SL_STATE_RUN => [0, 1, 1],
        SL_STATE_STOP => [0, 0, 0],
        SL_STATE_SAFE => [0, 0, 0],
        SL_STATE_ERROR => [1, 0, 0],
        SL_STATE_RESET => [0, 0, 0],
        SL_STATE_START => [0, 0, 0],
        SL_STATE_ERRORDELAY => [0, 0, 1],
        SL_STATE_DELAYOUT => [0, 0, 1],
        SL_STATE_FUNCTEST => [0, 0, 0],
        s => panic!("state {s} has no row in the manual's state tables"),
    }
}

/// Uniform access to the two guard blocks.
pub trait Guard: FunctionBlock + Clone + std::fmt::Debug {
    fn state(&self) -> u8;
    fn diag(&self) -> u16;
    /// [Error, EStopOut/MonOut, EStopDelOut/MonDelOut]
    fn outs(&self) -> [u8; 3];
    fn set_restart(&mut self, v: u8);
    fn set_run(&mut self, v: u8);
    fn set_errack(&mut self, v: u8);
    fn set_edm(&mut self, x: usize, v: u8);
    /// Raw byte of safety input `i` (0-based, in the order of the wInputActive bits).
    fn set_in(&mut self, i: usize, v: u8);
    fn get_in(&self, i: usize) -> u8;
    fn restart(&self) -> u8;
}

/// [`Guard`] for a guard block: its outputs [Error, `$out`, `$del`] and the accessor `$input`
/// of its safety inputs.
macro_rules! guard {
    ($fb:ty, $out:ident, $del:ident, $input:ident) => {
        impl Guard for $fb {
            fn state(&self) -> u8 {
                self.nState
            }
            fn diag(&self) -> u16 {
                self.nDiag
            }
            fn outs(&self) -> [u8; 3] {
                [self.bError, self.$out, self.$del]
            }
            fn set_restart(&mut self, v: u8) {
                self.bRestart = v;
            }
            fn set_run(&mut self, v: u8) {
                self.bRun = v;
            }
            fn set_errack(&mut self, v: u8) {
                self.bErrAck = v;
            }
            fn set_edm(&mut self, x: usize, v: u8) {
                match x {
                    1 => self.bEDM1 = v,
                    2 => self.bEDM2 = v,
                    _ => panic!("EDM{x}"),
                }
            }
            fn set_in(&mut self, i: usize, v: u8) {
                *$input(self, i) = v;
            }
            fn get_in(&self, i: usize) -> u8 {
                let mut c = *self;
                *$input(&mut c, i)
            }
            fn restart(&self) -> u8 {
                self.bRestart
            }
        }
    };
}

guard!(FB_ESTOP, bEStopOut, bEStopDelOut, estop_in);
guard!(FB_MON, bMonOut, bMonDelOut, mon_in);

fn estop_in(fb: &mut FB_ESTOP, i: usize) -> &mut u8 {
    nth_in(
        [
            &mut fb.bEStopIn1,
            &mut fb.bEStopIn2,
            &mut fb.bEStopIn3,
            &mut fb.bEStopIn4,
            &mut fb.bEStopIn5,
            &mut fb.bEStopIn6,
            &mut fb.bEStopIn7,
            &mut fb.bEStopIn8,
        ],
        i,
        "ESTOP",
    )
}

/// Safety input `i` of a block whose inputs are `ins` (a panic past the end names the block).
fn nth_in<'a, const N: usize>(ins: [&'a mut u8; N], i: usize, block: &str) -> &'a mut u8 {
    ins.into_iter()
        .nth(i)
        .unwrap_or_else(|| panic!("{block} has no safety input {i}"))
}

/// MonIn1…MonIn4, then Secure1, Secure2.
fn mon_in(fb: &mut FB_MON, i: usize) -> &mut u8 {
    nth_in(
        [
            &mut fb.bMonIn1,
            &mut fb.bMonIn2,
            &mut fb.bMonIn3,
            &mut fb.bMonIn4,
            &mut fb.bSecure1,
            &mut fb.bSecure2,
        ],
        i,
        "MON",
    )
}

/// Index of Secure1 / Secure2 in the MON input order (wInputActive bits 4, 5).
pub const SECURE1: usize = 4;
pub const SECURE2: usize = 5;

/// An FB_ESTOP with `active` inputs as break contacts, all of them TRUE (no request),
/// EDM bytes TRUE (contactors released), bRun TRUE, everything else zero.
pub fn estop(active: u16) -> FB_ESTOP {
    closed(
        FB_ESTOP {
            wInputActive: active,
            bRun: 1,
            bEDM1: 1,
            bEDM2: 1,
            ..Default::default()
        },
        active,
        8,
    )
}

/// An FB_MON with `active` inputs (bits 0-3 MonIn, 4-5 Secure) as break contacts, all TRUE,
/// EDM bytes TRUE, bRun TRUE, `options` as given.
pub fn mon(active: u16, options: u32) -> FB_MON {
    closed(
        FB_MON {
            wInputActive: active,
            dwOptions: options,
            bRun: 1,
            bEDM1: 1,
            bEDM2: 1,
            ..Default::default()
        },
        active,
        6,
    )
}

/// `fb` with each of its `n` safety inputs TRUE where `active` has the input's bit.
fn closed<B: Guard>(mut fb: B, active: u16, n: usize) -> B {
    for i in 0..n {
        fb.set_in(i, u8::from(active & (1 << i) != 0));
    }
    fb
}

/// `fb` after its `init` accepted the parameters (SL_OK, semantics C1).
#[track_caller]
pub fn ready<B: FunctionBlock + std::fmt::Debug>(mut fb: B) -> B {
    assert_eq!(fb.init(), SL_OK, "init refused the parameters: {fb:?}");
    fb
}

/// `fb` after its `init` refused the parameters (SL_E_CONFIG) and every call at `times`
/// returned SL_E_CONFIG too; a failure shows the block.
#[track_caller]
pub fn refused<B: FunctionBlock + std::fmt::Debug>(mut fb: B, times: &[u32]) -> B {
    assert_eq!(
        fb.init(),
        SL_E_CONFIG,
        "init accepted the parameters: {fb:?}"
    );
    for &t in times {
        assert_eq!(fb.cycle(t), SL_E_CONFIG, "call at {t}: {fb:?}");
    }
    fb
}

/// A group (Rust API) with tables for `members` and `links`, its `members` slots reserved
/// in order.
#[track_caller]
pub fn new_group(members: usize, links: u16) -> SL_GROUP {
    let mut g = SL_GROUP::default();
    assert_eq!(safelogic::group::init(&mut g, members as u16, links), SL_OK);
    for i in 0..members {
        assert_eq!(safelogic::group::reserve_member(&mut g), Ok(i as u16));
    }
    g
}

/// A BOOL link from member `src` at offset `so` to member `dst` at offset `d`.
pub fn link(src: u16, so: u16, dst: u16, d: u16) -> SL_LINK {
    SL_LINK {
        nSrcMember: src,
        nSrcOffset: so,
        nDstMember: dst,
        nDstOffset: d,
        ..Default::default()
    }
}

/// One row of a step table: the call's time, the inputs set before it, the status it must
/// return, the outputs it must leave (`None`: not checked in this row) and what it shows.
pub type Row<B, O> = (u32, fn(&mut B), i32, Option<O>, &'static str);

/// Runs a step table on `fb`: each row sets its inputs, calls the block at its time and
/// checks the status and the outputs (`outs`). A failure names the table, the row's index
/// and time, and its note.
#[track_caller]
pub fn run_steps<B: FunctionBlock, O: PartialEq + std::fmt::Debug>(
    name: &str,
    fb: &mut B,
    outs: impl Fn(&B) -> O,
    rows: &[Row<B, O>],
) {
    for (k, (t, set, rc, want, note)) in rows.iter().enumerate() {
        set(fb);
        assert_eq!(fb.cycle(*t), *rc, "{name} row {k} (t {t}): status; {note}");
        if let Some(want) = want {
            assert_eq!(&outs(fb), want, "{name} row {k} (t {t}): {note}");
        }
    }
}

/// A block and its clock.
#[derive(Debug, Clone)]
pub struct Sim<B> {
    pub fb: B,
    pub t: u32,
}

impl<B: Guard> Sim<B> {
    /// `init` must accept the parameters (SL_OK, power-up image, semantics C1).
    #[track_caller]
    pub fn new(mut fb: B, t: u32) -> Self {
        assert_eq!(fb.init(), SL_OK, "init rejected the parameters: {fb:?}");
        expect(&fb, SL_STATE_STOP);
        Sim { fb, t }
    }

    /// One call at the current time.
    pub fn cyc(&mut self) -> i32 {
        self.fb.cycle(self.t)
    }

    /// Advances the clock by `dt` ms (wrapping) and calls once.
    pub fn adv(&mut self, dt: u32) -> i32 {
        self.t = self.t.wrapping_add(dt);
        self.fb.cycle(self.t)
    }

    /// Advances by `dt`, asserts SL_OK and the state (with the state table's outputs).
    #[track_caller]
    pub fn step(&mut self, dt: u32, state: u8) {
        let rc = self.adv(dt);
        assert_eq!(
            rc,
            SL_OK,
            "status at t={} (state {})",
            self.t,
            self.fb.state()
        );
        expect(&self.fb, state);
    }

    /// Advances to the absolute time `t` (forward, wrapping) and calls once.
    pub fn at(&mut self, t: u32) -> i32 {
        self.t = t;
        self.fb.cycle(t)
    }

    /// STOP → run (G12): bRun is TRUE, one call leaves STOP for `start_state`.
    #[track_caller]
    pub fn start_up(&mut self, start_state: u8) {
        self.fb.set_run(1);
        self.step(1, start_state);
    }

    /// The manual restart sequence (ABI §7 Restart, G1): Restart TRUE → START, Restart
    /// FALSE (falling edge) → RUN.
    #[track_caller]
    pub fn restart(&mut self) {
        self.fb.set_restart(1);
        self.step(1, SL_STATE_START);
        self.fb.set_restart(0);
        self.step(1, SL_STATE_RUN);
    }

    /// ErrAck rising edge (→ RESET) and falling edge (→ `after`), semantics C8/C9.
    #[track_caller]
    pub fn acknowledge(&mut self, after: u8) {
        self.fb.set_errack(1);
        self.step(1, SL_STATE_RESET);
        assert_eq!(self.fb.diag(), 0, "nDiag is cleared on ERROR -> RESET (C9)");
        self.fb.set_errack(0);
        self.step(1, after);
    }
}

/// ESTOP brought to RUN: init, STOP → SAFE, Restart sequence (G12).
#[track_caller]
pub fn estop_running(fb: FB_ESTOP) -> Sim<FB_ESTOP> {
    estop_running_at(fb, T0)
}

/// As [`estop_running`], starting the clock at `t0` (RUN is entered at `t0 + 3`).
#[track_caller]
pub fn estop_running_at(fb: FB_ESTOP, t0: u32) -> Sim<FB_ESTOP> {
    let mut s = Sim::new(fb, t0);
    s.start_up(SL_STATE_SAFE);
    s.restart();
    s
}

/// MON brought to RUN: with manual restart via the Restart sequence, otherwise by itself
/// one call after STOP → SAFE (G12). Not for MON with the function test.
#[track_caller]
pub fn mon_running(fb: FB_MON) -> Sim<FB_MON> {
    mon_running_at(fb, T0)
}

/// As [`mon_running`], starting the clock at `t0`.
#[track_caller]
pub fn mon_running_at(fb: FB_MON, t0: u32) -> Sim<FB_MON> {
    assert_eq!(fb.dwOptions & SL_OPT_FUNCTION_TEST, 0);
    let manual = fb.dwOptions & SL_OPT_MANUAL_RESTART != 0;
    let mut s = Sim::new(fb, t0);
    s.start_up(SL_STATE_SAFE);
    if manual {
        s.restart();
    } else {
        s.step(1, SL_STATE_RUN);
    }
    s
}

/// Asserts the state and that the outputs are exactly the state table's row.
#[track_caller]
pub fn expect<B: Guard>(fb: &B, state: u8) {
    assert_eq!(fb.state(), state, "nState (diag {:#06x})", fb.diag());
    assert_eq!(
        fb.outs(),
        table(state),
        "outputs [Error, Out, DelOut] in state {state}"
    );
}

/// Asserts ERROR with exactly these diag bits.
#[track_caller]
pub fn expect_error<B: Guard>(fb: &B, diag: u16) {
    expect(fb, SL_STATE_ERROR);
    assert_eq!(fb.diag(), diag, "nDiag in ERROR");
}

/// xorshift64*: a small deterministic generator for random tests (reproducible failures
/// without a seed file).
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
}

thread_local! {
    /// The states the cases of the running property reported (bit n: state n).
    static REACHED: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

/// Records that the block under test is in `state` (call it after every cycle of a
/// property's case).
pub fn saw(state: u8) {
    REACHED.with(|r| r.set(r.get() | 1u64 << state.min(63)));
}

/// Runs a property with proptest's runner (shrinking included) and asserts that its cases
/// together reached every state of `reach` (issue 12: a random test proves its reach).
/// Syntax as `proptest!` for one test, with the case count and the required states first:
/// `property! { cases: 256, reach: [SL_STATE_RUN, SL_STATE_ERROR]; fn name(a in 0u8..4) { … } }`
// Every test crate includes this module; not all of them have a property.
#[allow(unused_macros)]
macro_rules! property {
    (cases: $cases:expr, reach: [$($state:expr),* $(,)?];
     $(#[doc = $doc:literal])*
     fn $name:ident($($arg:pat in $strategy:expr),* $(,)?) $body:block) => {
        $(#[doc = $doc])*
        #[test]
        fn $name() {
            use proptest::test_runner::{Config, TestRunner};
            let cases = $cases;
            // prop_assume! rejections scale with the case count.
            let mut runner = TestRunner::new(Config {
                cases,
                max_global_rejects: cases,
                ..Config::default()
            });
            let before = $crate::common::reached_reset();
            let result = runner.run(&($($strategy,)*), |($($arg,)*)| {
                $body
                Ok(())
            });
            if let Err(e) = result {
                panic!("{}: {}", stringify!($name), e);
            }
            let reached = $crate::common::reached_reset();
            let _ = before;
            for s in [$($state),*] {
                assert!(
                    reached & 1u64 << s != 0,
                    "{}: state {} never reached (reached {:#b})",
                    stringify!($name),
                    s,
                    reached
                );
            }
        }
    };
}
#[allow(unused_imports)]
pub(crate) use property;

/// ABI §9 layout: `offsets!(FB_X; bIn1 => 8, bRun => 16)` asserts each field at its offset;
/// `offsets!(FB_X, from base; bOut => 1)` each field at its distance from `base`. A failure
/// names the block and the field.
// Every test crate includes this module; not all of them check a layout.
#[allow(unused_macros)]
macro_rules! offsets {
    ($t:ty; $($f:ident => $n:expr),* $(,)?) => {
        $(assert_eq!(
            std::mem::offset_of!($t, $f),
            $n,
            concat!(stringify!($t), ".", stringify!($f))
        );)*
    };
    ($t:ty, from $base:ident; $($f:ident => $n:expr),* $(,)?) => {
        $(assert_eq!(
            std::mem::offset_of!($t, $f) - $base,
            $n,
            concat!(stringify!($t), ".", stringify!($f), " from the output base")
        );)*
    };
}
#[allow(unused_imports)]
pub(crate) use offsets;

/// ABI §9: the offset of `bError`, the base of the outputs, a multiple of 8 bytes.
// Every test crate includes this module; not all of them check a layout.
#[allow(unused_macros)]
macro_rules! output_base {
    ($t:ty) => {{
        let base = std::mem::offset_of!($t, bError);
        assert_eq!(base % 8, 0, concat!("output base of ", stringify!($t)));
        base
    }};
}
#[allow(unused_imports)]
pub(crate) use output_base;

/// In an analog test module: `LO` and `HI`, the bounds of the value type `$t`, and `t(v)`,
/// `v` clamped into it (the caller has `Analog` in scope).
// Every test crate includes this module; not all of them test an analog block.
#[allow(unused_macros)]
macro_rules! analog_bounds {
    ($t:ty) => {
        const LO: i128 = <$t as Analog>::MIN;
        const HI: i128 = <$t as Analog>::MAX;

        fn t(v: i128) -> $t {
            <$t as Analog>::narrow(v.clamp(LO, HI))
        }
    };
}
#[allow(unused_imports)]
pub(crate) use analog_bounds;

/// Every state of `states` was reached: bit `1 << s` of `reached` is set for each.
#[track_caller]
pub fn assert_reached(reached: u64, states: impl IntoIterator<Item = u8>) {
    for s in states {
        assert!(
            reached & 1 << s != 0,
            "state {s} never reached ({reached:#b})"
        );
    }
}

/// The number of random sequences with an invalid configuration lies strictly between `lo`
/// and `hi`: enough to reach the error paths, few enough to leave the rest valid.
#[track_caller]
pub fn assert_invalid_share(invalid: u32, lo: u32, hi: u32) {
    assert!(invalid > lo && invalid < hi, "invalid share {invalid}");
}

/// `struct Outputs`: everything an analog block shows, its own outputs (given) followed by
/// the diagnostics every one of them has (state, DiagCode, text id, the two parameters).
// Every test crate includes this module; only the analog ones declare their outputs.
#[allow(unused_macros)]
macro_rules! analog_outputs {
    ($($field:ident: $ty:ty),* $(,)?) => {
        /// Everything the block shows.
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        struct Outputs {
            $($field: $ty,)*
            state: u8,
            diag: u16,
            text: u16,
            par: (u32, u32),
        }
    };
}
#[allow(unused_imports)]
pub(crate) use analog_outputs;

/// The [`analog_outputs`] of block `$f`: the given fields, then its diagnostics.
#[allow(unused_macros)]
macro_rules! read_outputs {
    ($f:ident { $($field:ident: $e:expr),* $(,)? }) => {
        Outputs {
            $($field: $e,)*
            state: $f.nState,
            diag: $f.nDiag,
            text: $f.nDiagTextId,
            par: ($f.dwDiagPar2, $f.dwDiagPar3),
        }
    };
}
#[allow(unused_imports)]
pub(crate) use read_outputs;

/// The one-field wrapper `$name` of an analog variant `$ty` (value type `$t`): it
/// dereferences to the block, sets `bRun` / `bErrAck` with `control`, and stores test values
/// given as `i128` with `t` (clamped to the type's range).
#[allow(unused_macros)]
macro_rules! analog_wrapper {
    ($name:ident, $ty:ty, $t:ty) => {
        #[derive(Clone, Copy, Default)]
        struct $name($ty);
        impl $name {
            fn control(&mut self, run: u8, ack: u8) {
                self.0.bRun = run;
                self.0.bErrAck = ack;
            }
            fn t(v: i128) -> $t {
                <$t as Analog>::narrow(v.clamp(<$t as Analog>::MIN, <$t as Analog>::MAX))
            }
        }
        crate::common::deref_to!($name, $ty);
    };
}
#[allow(unused_imports)]
pub(crate) use analog_wrapper;

/// `Deref` / `DerefMut` of the one-field wrapper `$name` to its block `$ty`.
// Every test crate includes this module; not all of them wrap a block.
#[allow(unused_macros)]
macro_rules! deref_to {
    ($name:ident, $ty:ty) => {
        impl std::ops::Deref for $name {
            type Target = $ty;
            fn deref(&self) -> &$ty {
                &self.0
            }
        }
        impl std::ops::DerefMut for $name {
            fn deref_mut(&mut self) -> &mut $ty {
                &mut self.0
            }
        }
    };
}
#[allow(unused_imports)]
pub(crate) use deref_to;

/// ABI §5: a block's C `init` and `cycle` refuse a NULL block with SL_E_NULL.
// Every test crate includes this module; not all of them call the C functions.
#[allow(unused_macros)]
macro_rules! null_refused {
    ($init:path, $cycle:path) => {
        // SAFETY: NULL is what the functions must refuse; they dereference nothing.
        assert_eq!(
            unsafe { $init(std::ptr::null_mut()) },
            SL_E_NULL,
            stringify!($init)
        );
        // SAFETY: as above.
        assert_eq!(
            unsafe { $cycle(std::ptr::null_mut(), 0) },
            SL_E_NULL,
            stringify!($cycle)
        );
    };
}
#[allow(unused_imports)]
pub(crate) use null_refused;

/// ABI §9: the private state `stPrivate` and the block's size are multiples of 8 bytes.
// Every test crate includes this module; not all of them check a layout.
#[allow(unused_macros)]
macro_rules! aligned_tail {
    ($t:ty) => {
        assert_eq!(std::mem::offset_of!($t, stPrivate) % 8, 0, stringify!($t));
        assert_eq!(std::mem::size_of::<$t>() % 8, 0, stringify!($t));
    };
}
#[allow(unused_imports)]
pub(crate) use aligned_tail;

/// The states recorded since the last call, and a fresh start.
pub fn reached_reset() -> u64 {
    REACHED.with(|r| r.replace(0))
}

/// `n` property cases, times `SL_PROP_DEPTH` (default 1) for a deep run. Under Miri
/// (tools/deep-check.sh: an interpreter, some thousand times slower) a hundredth: the
/// stable command runs the full count.
pub fn depth_cases(n: u32) -> u32 {
    if cfg!(miri) {
        return (n / 100).max(1);
    }
    let depth: u32 = std::env::var("SL_PROP_DEPTH")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1);
    n.saturating_mul(depth.max(1))
}

pub mod cgroup;
pub mod fsoe;
pub mod plcopen;
pub mod timer;

/// The text `sl_diag_text` writes for `code` of block type `ty` (the call must return SL_OK).
#[track_caller]
pub fn diag_text(ty: u16, code: u16) -> String {
    let mut buf = [0 as std::ffi::c_char; 512];
    // SAFETY: a writable buffer of the stated length.
    let rc = unsafe { safelogic::ffi::sl_diag_text(ty, code, buf.as_mut_ptr(), buf.len()) };
    assert_eq!(rc, SL_OK, "sl_diag_text({ty}, {code:#06x})");
    // SAFETY: NUL-terminated by the call.
    unsafe { std::ffi::CStr::from_ptr(buf.as_ptr()) }
        .to_str()
        .unwrap()
        .to_string()
}

/// The states every TwinSAFE block has (RUN, STOP, SAFE, ERROR, RESET); a block's own follow.
pub const CORE_STATES: [u8; 5] = [
    SL_STATE_RUN,
    SL_STATE_STOP,
    SL_STATE_SAFE,
    SL_STATE_ERROR,
    SL_STATE_RESET,
];

/// The text `sl_state_str` returns for `state` of block type `ty`.
pub fn state_str(ty: u16, state: u8) -> &'static str {
    // SAFETY: sl_state_str returns a static NUL-terminated string for every input.
    unsafe { std::ffi::CStr::from_ptr(safelogic::ffi::sl_state_str(ty, state)) }
        .to_str()
        .unwrap()
}

/// Name of a state through the C function `sl_state_str`.
pub fn state_name(ty: u16, state: u8) -> &'static str {
    let p = safelogic::ffi::sl_state_str(ty, state);
    safelogic::registry::info(ty)
        .and_then(|b| b.states.iter().find(|(_, n)| n.as_ptr().cast() == p))
        .map_or("?", |(_, n)| n.trim_end_matches('\0'))
}

/// `sl_group_init` on the test's own tables, each given with its number of entries (must
/// return SL_OK).
#[track_caller]
pub fn c_group_init(
    g: &mut SL_GROUP,
    (ms, n): (*mut SL_MEMBER, u16),
    (ls, m): (*mut SL_LINK, u16),
) {
    // SAFETY: the test's own group and tables, holding at least the stated counts.
    assert_eq!(
        unsafe { safelogic::ffi::sl_group_init(g, ms, n, ls, m) },
        SL_OK,
        "sl_group_init"
    );
}

/// `sl_group_add_member` of the block at `block` as type `ty`, its index into `idx` unless
/// NULL (must return SL_OK).
#[track_caller]
pub fn c_add_member(
    g: &mut SL_GROUP,
    members: *mut SL_MEMBER,
    ty: u16,
    block: *mut std::ffi::c_void,
    idx: *mut u16,
) {
    // SAFETY: the test's own group and member table; `block` is a live block of type `ty`.
    let rc = unsafe { safelogic::ffi::sl_group_add_member(g, members, ty, block, idx) };
    assert_eq!(rc, SL_OK, "sl_group_add_member type {ty}");
}

/// `sl_group_add_link` from member `src` at `so` to member `dst` at `d` (must return SL_OK).
#[track_caller]
pub fn c_add_link(
    g: &mut SL_GROUP,
    members: &mut [SL_MEMBER],
    links: &mut [SL_LINK],
    (src, so): (u16, usize),
    (dst, d): (u16, usize),
) {
    let (ms, ls) = (members.as_mut_ptr(), links.as_mut_ptr());
    // SAFETY: the test's own group and tables.
    let rc = unsafe { safelogic::ffi::sl_group_add_link(g, ms, ls, src, so as u16, dst, d as u16) };
    assert_eq!(rc, SL_OK, "sl_group_add_link {src}@{so} -> {dst}@{d}");
}

/// One group cycle through the C API. The member table gets fresh pointers to the blocks
/// first: the test writes the blocks directly between calls, which ends the validity of
/// pointers taken before (no `unsafe` here, and nothing the compiler may reorder).
#[macro_export]
macro_rules! c_group_cycle {
    ($g:expr, $members:expr, $links:expr, $t:expr; $($b:ident),+) => {{
        let mut i = 0;
        $(
            $members[i].pBlock = std::ptr::addr_of_mut!($b).cast();
            i += 1;
        )+
        let _ = i;
        let (g, members, links, t) = (&mut $g, $members.as_mut_ptr(), $links.as_mut_ptr(), $t);
        // SAFETY: the group, its member table (with fresh block pointers) and its link table
        // are the test's own, alive for the call.
        unsafe { safelogic::ffi::sl_group_cycle(g, members, links, t) }
    }};
}

/// Names of [`CORE_STATES`] as every registry row spells them.
pub const CORE_STATE_NAMES: [(u8, &str); 5] = [
    (1, "RUN"),
    (2, "STOP"),
    (3, "SAFE"),
    (4, "ERROR"),
    (5, "RESET"),
];

/// A registry row's states with their names (NUL terminator removed), in the row's order.
pub fn state_names(info: &safelogic::registry::BlockInfo) -> Vec<(u8, &'static str)> {
    info.states
        .iter()
        .map(|(v, n)| (*v, n.trim_end_matches('\0')))
        .collect()
}

/// The manual's LOADSENSING table (§4.25.3, Fig. 132), as printed.
pub const FIG_132: [[i16; 5]; 25] = [
    [-30, -200, -100, -180, -80],
    [-25, -100, -50, -90, -60],
    [-20, -50, 0, -40, -10],
    [-15, 0, 100, 10, 90],
    [-10, 100, 200, 110, 190],
    [-5, 200, 300, 210, 290],
    [0, 300, 400, 310, 390],
    [5, 400, 500, 410, 490],
    [10, 500, 600, 510, 590],
    [15, 600, 700, 610, 690],
    [20, 700, 800, 710, 790],
    [25, 800, 900, 810, 890],
    [30, 900, 1000, 910, 990],
    [35, 1000, 1100, 1010, 1090],
    [40, 1100, 1200, 1110, 1190],
    [45, 1200, 1300, 1210, 1290],
    [50, 1300, 1400, 1310, 1390],
    [60, 1400, 1500, 1410, 1490],
    [80, 1500, 1600, 1510, 1590],
    [100, 1600, 1700, 1610, 1690],
    [140, 1700, 1800, 1710, 1790],
    [180, 1800, 2000, 1810, 1990],
    [250, 2000, 3000, 2010, 2990],
    [500, 3000, 4000, 3010, 3990],
    [1000, 4000, 5000, 4010, 4990],
];
