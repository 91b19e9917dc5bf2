//! The cycle envelope every block runs in (ABI §4, §5, §7): integrity check of the private
//! state, clock check, parameter latching and change detection, Run → STOP, ERROR → RESET
//! with ErrAck edges, the status code. The block itself only supplies its running states.
//!
//! The steady-state fast path (docs/performance.md): a block whose cycle reads only BOOL
//! bytes and parameters keeps, beside its private state, the key of the bytes read by the
//! last call that left a state those bytes keep (a fixed point of the full cycle, or any
//! SL_OK call of an idempotent block, in a state without a running timer): a window over
//! all of them, the bytes themselves side by side (the timers), or the BOOL bytes gathered
//! into bits, bound to the control word of that state. A call with the same key in the same
//! state, an intact private header, a clock that did not go backwards and parameters equal
//! to the latched ones would compute the same again: it only advances `tLast` and rewrites
//! the outputs. Every other call runs the full cycle and records whether it left such a
//! state.

use super::bools::{edge, is_false, is_true};
use super::header::{F_CFG_INVALID, F_ERRACK_PREV, F_RESET_HELD, F_TIME_VALID, SL_PRIVATE_HEADER};
use super::reason::{self, RuleDef};
use super::time;
use crate::base::types::*;

/// What every block struct has under the same names (`stPrivate.stHeader`, `bRun`,
/// `bErrAck`); implemented for each block by `impl_member!`.
pub trait Instance {
    fn header(&self) -> &SL_PRIVATE_HEADER;
    fn header_mut(&mut self) -> &mut SL_PRIVATE_HEADER;
    /// Zeroes the whole private area.
    fn clear_private(&mut self);
    fn run_raw(&self) -> u8;
    fn errack_raw(&self) -> u8;
}

/// What a block supplies to the envelope.
pub trait Block: Instance + crate::base::block::Registered {
    /// Type tag stored in the private header.
    const MAGIC: u16;
    /// The block's parameters as the user wrote them (wide types).
    type Params: PartialEq + Copy + 'static;
    /// Inputs of one cycle after BOOL decoding.
    type In;

    /// The live parameter fields.
    fn live_params(&self) -> Self::Params;
    /// The latched copy, widened.
    fn latched_params(&self) -> Self::Params;
    /// The parameter rules (manual limits, ABI §5 SL_E_CONFIG), in the order they are
    /// checked: a configuration that breaks one is refused with the first it breaks.
    const RULES: &'static [RuleDef<Self::Params>];
    /// Writes the latched copy (narrowing; only meaningful for valid parameters).
    fn store_params(&mut self, p: &Self::Params);
    /// CRC of the latched copy.
    fn latched_crc(&self) -> u16;
    /// The latched copy still matches its CRC: checked where an output is about to switch
    /// on (docs/semantics.md C3), never on every cycle (the CRC costs more than a cycle).
    fn params_intact(&self) -> bool {
        self.latched_crc() == self.header().wParamCrc
    }
    /// Where an output switches on (`switching_on`), the latched parameters are verified
    /// (docs/semantics.md C3): when they no longer match their CRC the block enters ERROR
    /// with `SL_DIAG_CORRUPT` and this returns `true` (the caller returns `Status::Corrupt`).
    /// [`Self::corrupt_at_switch_on`] for an output that switches on with RUN: it switches
    /// on when `on` and the block is not in RUN yet.
    #[inline(always)]
    fn corrupt_entering_run(&mut self, on: bool) -> bool {
        let entering = on && self.header().nState != SL_STATE_RUN;
        self.corrupt_at_switch_on(entering)
    }
    #[inline(always)]
    fn corrupt_at_switch_on(&mut self, switching_on: bool) -> bool {
        let corrupt = switching_on && !self.params_intact();
        if corrupt {
            self.header_mut().enter_error(SL_DIAG_CORRUPT);
        }
        corrupt
    }

    /// Reads the input bytes, updates the block's edge memories, and tells whether a byte
    /// was an invalid BOOL.
    fn decode(&mut self) -> (Self::In, bool);
    /// Enters the block's start state (after STOP → run and after RESET), seeing this
    /// cycle's inputs.
    fn start(&mut self, inp: &Self::In, now: u32);
    /// One cycle in a running state (not STOP, ERROR, RESET) with bRun TRUE; returns
    /// `SL_OK` or the status of an integrity failure it found.
    fn step(&mut self, inp: &Self::In, now: u32) -> Status;
    /// bRun went FALSE in a running state.
    fn stop(&mut self) {
        self.header_mut().nState = SL_STATE_STOP;
    }
    /// In ERROR: does a block-specific error condition remain (ABI §7 "Errors")? Default:
    /// none (the block's errors are events, or faults of the library only).
    #[inline(always)]
    fn error_remains(&mut self, _inp: &Self::In) -> bool {
        false
    }
    /// In RESET once ErrAck has fallen, bRun TRUE: may the block start now? A block that
    /// may not holds RESET and starts in the first call in which it may while ErrAck stays
    /// FALSE (FB SLI: "should only exit the RESET state if ErrAck=FALSE and SLI=FALSE").
    fn may_leave_reset(&self, _inp: &Self::In) -> bool {
        true
    }
    /// Writes the VAR_OUTPUT and info fields from the private state.
    fn write_outputs(&mut self);

    /// The fast path (`fast`): whether it served the call. Only a block with a fast path
    /// ([`Steady`], `steady_hooks!`) has one.
    #[inline(always)]
    fn fast(&mut self, _now: u32) -> bool {
        false
    }
    /// The full cycle; for a block with a fast path it also records whether the call was a
    /// fixed point ([`settle`]). Out of line: the C function and the group's call of the
    /// block share one copy, and the fast path stays a small leaf function.
    #[inline(never)]
    fn settle(&mut self, now: u32) -> Status
    where
        Self: Sized,
    {
        full_cycle(self, now).0
    }
    /// Forgets a stored fast-path key: whatever changes the private state outside [`cycle`]
    /// calls it.
    #[inline(always)]
    fn forget_key(&mut self) {}
}

/// A fast-path key: what the cycle of a steady block reads from its struct, compared whole.
pub trait SteadyKey: Copy + PartialEq {
    /// The check word of a key stored in a quiet state: its complement.
    fn complement(self) -> Self;
    /// The check word of a key stored in a timing state: the key XOR [`TIMED`] (a pattern
    /// that is neither 0 nor all ones, so a quiet slot and a timed slot differ in half the
    /// bits of the check word, and a zeroed slot holds no key).
    fn timed(self) -> Self;
    /// The key as stored, bound to the control word (state, flags, diag) of the state it
    /// was stored in: the control word XOR-ed into its low bits.
    fn bind(self, ctrl: u32) -> Self;
}

/// The timed slot's pattern ([`SteadyKey::timed`]).
pub const TIMED: u64 = 0x5A5A_5A5A_5A5A_5A5A;

/// A key in one word: the BOOL bytes gathered into bits (`bools::key`, u16) or the bytes
/// themselves side by side (u32).
macro_rules! scalar_key {
    ($($w:ty),+) => {$(
        impl SteadyKey for $w {
            #[inline(always)]
            fn complement(self) -> Self {
                !self
            }
            #[inline(always)]
            fn timed(self) -> Self {
                self ^ TIMED as $w
            }
            #[inline(always)]
            fn bind(self, ctrl: u32) -> Self {
                self ^ ctrl as $w
            }
        }
    )+};
}
scalar_key!(u16, u32);

impl<const N: usize> SteadyKey for [u64; N] {
    #[inline(always)]
    fn complement(self) -> Self {
        self.map(|w| !w)
    }
    #[inline(always)]
    fn timed(self) -> Self {
        self.map(|w| w ^ TIMED)
    }
    #[inline(always)]
    fn bind(mut self, ctrl: u32) -> Self {
        self[0] ^= u64::from(ctrl);
        self
    }
}

/// A private state with a fast-path slot: a key and its check word.
pub trait SteadyPrivate: Copy + PartialEq {
    type Key: SteadyKey;
    /// The common head.
    fn head_mut(&mut self) -> &mut SL_PRIVATE_HEADER;
    /// The slot: the stored key and its check word.
    fn slot(&self) -> [Self::Key; 2];
    /// Writes the slot (all zero: no key).
    fn set_slot(&mut self, slot: Option<[Self::Key; 2]>);
}

/// Implements [`SteadyPrivate`] for a private struct whose slot is `$slot`: `[$w; 2]` for a
/// key in one word (key, check), `[u8; 4]` for a gathered key in a reserved word (`bytes
/// u16`), `[u32; 4N]` for a window of N words (key words, then check words, each as two
/// halves, low first: the C and PLC types have no 64-bit integer).
macro_rules! steady_private {
    ($p:ty, $slot:ident, $w:ty) => {
        impl $crate::base::envelope::SteadyPrivate for $p {
            type Key = $w;
            #[inline(always)]
            fn head_mut(&mut self) -> &mut $crate::base::header::SL_PRIVATE_HEADER {
                &mut self.stHeader
            }
            /// Read as two loads (a copy of the array would be one wide load, then split).
            #[inline(always)]
            fn slot(&self) -> [$w; 2] {
                [self.$slot[0], self.$slot[1]]
            }
            #[inline(always)]
            fn set_slot(&mut self, slot: Option<[$w; 2]>) {
                self.$slot = slot.unwrap_or_default();
            }
        }
    };
    // A gathered key (u16) in a reserved `[u8; 4]` of the private part: the key in bytes
    // 0-1, its check word in bytes 2-3, little-endian (the field keeps its name and size).
    ($p:ty, $slot:ident, bytes u16) => {
        impl $crate::base::envelope::SteadyPrivate for $p {
            type Key = u16;
            #[inline(always)]
            fn head_mut(&mut self) -> &mut $crate::base::header::SL_PRIVATE_HEADER {
                &mut self.stHeader
            }
            #[inline(always)]
            fn slot(&self) -> [u16; 2] {
                let [a, b, c, d] = self.$slot;
                [u16::from_le_bytes([a, b]), u16::from_le_bytes([c, d])]
            }
            #[inline(always)]
            fn set_slot(&mut self, slot: Option<[u16; 2]>) {
                let [key, check] = slot.unwrap_or_default();
                let [a, b] = key.to_le_bytes();
                let [c, d] = check.to_le_bytes();
                self.$slot = [a, b, c, d];
            }
        }
    };
    ($p:ty, $slot:ident, window $n:literal) => {
        impl $crate::base::envelope::SteadyPrivate for $p {
            type Key = [u64; $n];
            #[inline(always)]
            fn head_mut(&mut self) -> &mut $crate::base::header::SL_PRIVATE_HEADER {
                &mut self.stHeader
            }
            #[inline(always)]
            fn slot(&self) -> [[u64; $n]; 2] {
                let s = &self.$slot;
                let word = |i: usize| u64::from(s[2 * i]) | u64::from(s[2 * i + 1]) << 32;
                [
                    core::array::from_fn(|i| word(i)),
                    core::array::from_fn(|i| word($n + i)),
                ]
            }
            #[inline(always)]
            fn set_slot(&mut self, slot: Option<[[u64; $n]; 2]>) {
                let [key, check] = slot.unwrap_or_default();
                self.$slot = core::array::from_fn(|i| {
                    let w = if i < 2 * $n {
                        key[i / 2]
                    } else {
                        check[i / 2 - $n]
                    };
                    (w >> (32 * (i % 2))) as u32
                });
            }
        }
    };
}
pub(crate) use steady_private;

/// What a block with a fast path supplies besides [`Block`].
pub trait Steady: Block + crate::base::block::Private<P: SteadyPrivate> {
    /// The key of this call: the bytes the cycle reads from the struct besides the
    /// parameters (its inputs, `bRun`, `bErrAck`), or `None` when this call cannot have one
    /// (a gathered key's byte that is neither 0 nor 1).
    fn steady_key(&self) -> Option<KeyOf<Self>>;
    /// No running timer: the outcome of a call depends on the time only through the clock
    /// check.
    fn quiet(&self) -> bool;
    /// A timer runs that is not reached at `now`, and a call that leaves the state as it is
    /// changes nothing else either (TON, TOF while timing): the outcome of a call at `now`
    /// depends on the time only through the clock check and this test. Asked after a full
    /// cycle that left a state its key keeps and that is not quiet, and by the fast path of
    /// a call whose key was stored in such a state. Only an idempotent block's `settle`
    /// stores a key in such a state (the fixed-point test asks `quiet` before the cycle).
    #[inline(always)]
    fn timing_quiet(&self, _now: u32) -> bool {
        false
    }
    /// The full cycle is idempotent: in every state, a call that returns SL_OK leaves a
    /// state that a call with the same key leaves as it is (but for `tLast`), with SL_OK
    /// and the same outputs. True for the blocks whose next state is a function of the
    /// inputs, or holds, the same way from every state (the combinational blocks, the
    /// flip-flops; the timers but for their start call, [`START_MOVES_ON`](Self::START_MOVES_ON));
    /// not for a block that steps through states under steady inputs (ESTOP, MON).
    /// [`settle`] then stores the key of every such call without comparing the state before
    /// and after (`tests/fast_path.rs` probes the claim after every call).
    const IDEMPOTENT: bool = false;
    /// An [`IDEMPOTENT`](Self::IDEMPOTENT) block whose start state (STOP → run, RESET →
    /// run) may be left by the inputs that entered it: idempotent in every call but the
    /// one that starts the block, which stores no key (the timers: TON started with its
    /// input TRUE times from the next call, docs/semantics.md T5).
    const START_MOVES_ON: bool = false;
}

/// The key type of a block with a fast path.
pub type KeyOf<B> = <<B as crate::base::block::Private>::P as SteadyPrivate>::Key;

/// The fast-path methods of a family's `Block` impl whose private state is a
/// [`SteadyPrivate`] (the family implements [`Steady`]).
macro_rules! steady_hooks {
    () => {
        #[inline(always)]
        fn fast(&mut self, now: u32) -> bool {
            $crate::base::envelope::fast(self, now)
        }
        #[inline(never)]
        fn settle(&mut self, now: u32) -> Status {
            $crate::base::envelope::settle(self, now)
        }
        #[inline(always)]
        fn forget_key(&mut self) {
            $crate::base::envelope::SteadyPrivate::set_slot(self.private_mut(), None)
        }
    };
}
pub(crate) use steady_hooks;

/// A field of a key window (`window!`): its value as an integer and its size in bytes.
pub trait WindowField {
    fn bits(&self) -> (u64, u32);
}

impl WindowField for u8 {
    #[inline(always)]
    fn bits(&self) -> (u64, u32) {
        (u64::from(*self), 1)
    }
}

impl<const N: usize> WindowField for [u8; N] {
    #[inline(always)]
    fn bits(&self) -> (u64, u32) {
        let v = self
            .iter()
            .rev()
            .fold(0u64, |v, &b| v.wrapping_shl(8) | u64::from(b));
        (v, N as u32)
    }
}

/// The key of a window: the listed fields, which tile a range of the struct from byte 8 in
/// order (every input and control byte lies there; `tests/fast_path.rs` checks that every
/// bit of the range reaches the key and that every input and control field lies in it), as
/// N little-endian words (at most 8·N bytes; the rest zero). Built as shifts and ORs of
/// adjacent fields, which the compiler merges into plain loads.
macro_rules! window {
    ($s:ident, $n:literal: $($f:ident),+ $(,)?) => {{
        let mut words = [0u64; $n];
        let mut at = 0u32;
        $(
            let (v, len) = $crate::base::envelope::WindowField::bits(&$s.$f);
            words[(at / 8) as usize % $n] |= v.wrapping_shl(8 * (at % 8));
            at += len;
        )+
        // That the fields tile the range exactly is checked by tests/fast_path.rs.
        let _ = at;
        words
    }};
}
pub(crate) use window;

/// [`Block::settle`] of a block with a fast path: the full cycle, then this call's key
/// stored when the call returned SL_OK, left the private state as it found it (but for
/// `tLast`; for an [`IDEMPOTENT`](Steady::IDEMPOTENT) block every such call does) and no
/// timer runs (check word: the complement) or a timer runs that is not reached
/// (`timing_quiet`; check word: the key XOR [`TIMED`]); the slot cleared otherwise.
/// Kept out of line: the fast path in [`cycle`] is then a small leaf function.
#[inline(never)]
pub fn settle<B: Steady>(fb: &mut B, now: u32) -> Status {
    if B::IDEMPOTENT {
        // No copy and no compare: the state this call leaves is one its key keeps.
        let (status, began) = full_cycle(fb, now);
        let key = if status == Status::Ok && !(B::START_MOVES_ON && began) {
            fb.steady_key()
        } else {
            None
        };
        let slot = key.and_then(|key| slot_of(fb, key, now));
        fb.private_mut().set_slot(slot);
        return status;
    }
    // A state that is not quiet cannot be a fixed point that stores a key either (a fixed
    // point leaves the state as it was, and the blocks that take this test have no
    // `timing_quiet`): no key, no copy to compare with then.
    let key = if fb.quiet() { fb.steady_key() } else { None };
    let Some(key) = key else {
        let status = full_cycle(fb, now).0;
        fb.private_mut().set_slot(None);
        return status;
    };
    let mut before = *fb.private();
    let status = full_cycle(fb, now).0;
    // What a fast call changes (`tLast`) and the slot are not compared: they are taken from
    // the state after the cycle into the copy, which is then compared with the state in
    // place, field by field. A second copy would read the bytes the cycle has just written
    // with wide loads, which wait until those stores reach the cache (docs/performance.md:
    // a random-input AND call 25.7 -> 15.1 ns).
    let t_last = fb.header().tLast;
    let after = fb.private();
    before.head_mut().tLast = t_last;
    before.set_slot(Some(after.slot()));
    let fixed = status == Status::Ok && before == *after;
    let slot = if fixed { slot_of(fb, key, now) } else { None };
    fb.private_mut().set_slot(slot);
    status
}

/// The slot for `key` after a call that left a state its key keeps: the key bound to the
/// control word of that state ([`SteadyKey::bind`]), and its check word when no timer runs
/// (the complement of the key) or a timer runs that is not reached at `now` (the key XOR
/// [`TIMED`]); `None` otherwise.
#[inline(always)]
fn slot_of<B: Steady>(fb: &B, key: KeyOf<B>, now: u32) -> Option<[KeyOf<B>; 2]> {
    // The control word as the cycle's seal has just stored it, complemented: one read of
    // that store (the fields one by one would be read as one word that waits for them).
    let bound = key.bind(!fb.header().dwCtrlCheck);
    if fb.quiet() {
        Some([bound, key.complement()])
    } else if fb.timing_quiet(now) {
        Some([bound, key.timed()])
    } else {
        None
    }
}

/// Latches the live parameters into the private copy; returns whether they are valid.
fn latch<B: Block>(fb: &mut B) -> bool {
    let p = fb.live_params();
    let ok = reason::check(B::RULES, &p).is_none();
    fb.store_params(&p);
    let crc = fb.latched_crc();
    let h = fb.header_mut();
    h.wParamCrc = crc;
    h.set_flag(F_CFG_INVALID, !ok);
    ok
}

/// Power-up: a fresh private state in STOP with the parameters latched (ABI §4 `init`).
fn power_up<B: Block>(fb: &mut B, state: u8, diag: u16) -> bool {
    fb.clear_private();
    fb.header_mut().wMagic = B::MAGIC;
    let ok = latch(fb);
    let h = fb.header_mut();
    h.nState = state;
    h.wDiag = diag;
    ok
}

/// `sl_<name>_init`: validate and latch parameters, reset to power-up (STOP, outputs safe).
/// Never touches a VAR_INPUT field.
pub fn init<B: Block>(fb: &mut B) -> Status {
    let ok = power_up(fb, SL_STATE_STOP, 0);
    fb.write_outputs();
    fb.header_mut().seal();
    if ok {
        Status::Ok
    } else {
        Status::Config
    }
}

/// `sl_<name>_cycle`: one task cycle at time `now` (ms, wrapping).
#[inline(always)]
pub fn cycle<B: Block>(fb: &mut B, now: u32) -> Status {
    cycle_traced(fb, now).0
}

/// [`cycle`], also telling whether the fast path served the call (for the tests that pin
/// the fast path to the full one).
#[doc(hidden)]
#[inline(always)]
pub fn cycle_traced<B: Block>(fb: &mut B, now: u32) -> (Status, bool) {
    if fb.fast(now) {
        (Status::Ok, true)
    } else {
        (fb.settle(now), false)
    }
}

/// The fast path alone: whether it served the call (`SL_OK`); [`Block::settle`] must run
/// when it did not. Split from [`cycle`] so that the C boundary can keep the fast path a
/// leaf and reach the full cycle through an out-of-line call.
#[inline(always)]
pub fn fast<B: Steady>(fb: &mut B, now: u32) -> bool {
    let Some(key) = fb.steady_key() else {
        return false;
    };
    let [stored, check] = fb.private().slot();
    // The stored key is bound to the control word of the state it was stored in, its check
    // word is not (`slot_of`): the check word pins the key, the stored key then pins the
    // control word, so a state written behind the library's back, even with its
    // complement, is never served (the full cycle decides it; a value the block does not
    // have is SL_E_CORRUPT there, docs/semantics.md C13). A key stored in a timing state
    // has another check word: a call that finds the quiet one never reaches the timing
    // test, so the quiet states pay nothing for it. The two check words differ by
    // !TIMED, 0xA5 in the state byte: a quiet slot matched as a timed one would need a
    // state value that differs from the stored one in bit 7, and every state value is
    // below 64 (`StateSet`), so it can never be the timing state.
    let served = stored == key.bind(fb.header().ctrl())
        && (check == key.complement() || check == key.timed() && fb.timing_quiet(now))
        && unchanged(fb, now);
    if served {
        fb.header_mut().tLast = now;
        fb.write_outputs();
    }
    served
}

/// What the fast path checks besides the key: the private header is intact, the clock did
/// not go backwards, the live parameters are the latched ones (the compare that also checks
/// the latched copy in the private state, with its CRC where an output switches on).
#[inline(always)]
fn unchanged<B: Steady>(fb: &B, now: u32) -> bool {
    let h = fb.header();
    h.intact(B::MAGIC)
        && !time::went_backwards(now, h.tLast)
        && fb.live_params() == fb.latched_params()
}

/// The full cycle only, keeping the fast-path slot as [`cycle`] does (the reference the
/// fast path is tested against).
#[doc(hidden)]
pub fn cycle_full<B: Block>(fb: &mut B, now: u32) -> Status {
    fb.settle(now)
}

/// The full cycle (ABI §4, §5, §7); also whether it started the block (entered its start
/// state from STOP or RESET).
#[inline(always)]
fn full_cycle<B: Block>(fb: &mut B, now: u32) -> (Status, bool) {
    let mut status = Status::Ok;
    let mut began = false;
    // An error entered in this call cannot be acknowledged in the same call.
    let mut fresh_error = false;

    // The cheap check first; only a failing one asks whether the area is merely unused.
    // A state value the block does not have is a corruption like a broken complement:
    // decided here, once for every block (the blocks' own matches never see one).
    if !fb.header().intact(B::MAGIC) || !B::STATES.has(fb.header().nState) {
        if fb.header().is_zero() {
            power_up(fb, SL_STATE_STOP, 0);
        } else {
            power_up(fb, SL_STATE_ERROR, SL_DIAG_CORRUPT);
            status = Status::Corrupt;
            fresh_error = true;
        }
    }

    let h = fb.header_mut();
    if h.flag(F_TIME_VALID) && time::went_backwards(now, h.tLast) {
        h.enter_error(SL_DIAG_CLOCK);
        status = status.worst(Status::Clock);
        fresh_error = true;
    }
    h.tLast = now;
    h.set_flag(F_TIME_VALID, true);

    let run_raw = fb.run_raw();
    let run = is_true(run_raw);
    let ack_raw = fb.errack_raw();
    let ack = edge(ack_raw, &mut fb.header_mut().nFlags, F_ERRACK_PREV);
    // STOP → run latches the parameters before the inputs are decoded with them.
    let started = fb.header().nState == SL_STATE_STOP && run && latch(fb);
    let (inp, invalid_in) = fb.decode();
    let invalid = invalid_in || run_raw > 1 || ack_raw > 1;

    // A parameter differing from the latched copy is reported at any time other than STOP
    // (ABI §5, §7, docs/semantics.md C5). While the block runs or is about to run it is a
    // fault (ERROR, diag bit 13) that blocks the acknowledgement. A block in ERROR with
    // bRun FALSE keeps reporting it (SL_E_PARAM_CHANGED, bit 13) but may be acknowledged:
    // RESET and STOP follow, and the next STOP → run latches the new values. A block that
    // bRun FALSE sends towards STOP (running states, RESET) is on its way to that latch.
    let state = fb.header().nState;
    let param_fault = state != SL_STATE_STOP
        && (run || state == SL_STATE_ERROR)
        && fb.live_params() != fb.latched_params();
    if param_fault {
        if fb.latched_crc() != fb.header().wParamCrc {
            fresh_error = true;
            power_up(fb, SL_STATE_ERROR, SL_DIAG_CORRUPT);
            status = status.worst(Status::Corrupt);
        } else if run {
            fresh_error = true;
            fb.header_mut().enter_error(SL_DIAG_PARAM_CHANGED);
            status = status.worst(Status::ParamChanged);
        } else {
            fb.header_mut().wDiag |= SL_DIAG_PARAM_CHANGED;
        }
    }

    match fb.header().nState {
        SL_STATE_STOP => {
            if started {
                fb.start(&inp, now);
                began = true;
            }
        }
        SL_STATE_ERROR => {
            let remains = fb.error_remains(&inp) || (param_fault && run);
            if ack.rising && !fresh_error && !remains {
                let h = fb.header_mut();
                h.nState = SL_STATE_RESET;
                h.wDiag = 0;
                h.set_flag(F_RESET_HELD, false);
            }
        }
        SL_STATE_RESET => {
            // ErrAck fell in this call, or fell earlier while the block held RESET.
            let held = fb.header().flag(F_RESET_HELD);
            if ack.falling || (held && is_false(ack_raw)) {
                let start = run && !fb.header().flag(F_CFG_INVALID);
                if start && !fb.may_leave_reset(&inp) {
                    fb.header_mut().set_flag(F_RESET_HELD, true);
                } else {
                    fb.header_mut().set_flag(F_RESET_HELD, false);
                    if start {
                        fb.start(&inp, now);
                        began = true;
                    } else {
                        fb.header_mut().nState = SL_STATE_STOP;
                    }
                }
            }
        }
        _ => {
            if run {
                status = status.worst(fb.step(&inp, now));
            } else {
                fb.stop();
            }
        }
    }

    let h = fb.header();
    // The pending change of a block that stays in ERROR with bRun FALSE (the call that
    // acknowledges it to RESET returns as usual).
    if param_fault && h.nState == SL_STATE_ERROR {
        status = status.worst(Status::ParamChanged);
    }
    if h.flag(F_CFG_INVALID) && h.nState == SL_STATE_STOP {
        status = status.worst(Status::Config);
    }
    if invalid {
        status = status.worst(Status::InvalidBool);
    }
    fb.write_outputs();
    fb.header_mut().seal();
    (status, began)
}

/// Forces the instance into ERROR with safe outputs after an internal fault (used by the
/// C boundary when it catches a panic).
pub fn force_error<B: Block>(fb: &mut B) {
    if !fb.header().intact(B::MAGIC) {
        power_up(fb, SL_STATE_ERROR, SL_DIAG_CORRUPT);
    }
    fb.forget_key();
    fb.header_mut().enter_error(SL_DIAG_CORRUPT);
    fb.write_outputs();
    fb.header_mut().seal();
}

/// The parameter plumbing of a [`Block`] whose latched copy keeps each parameter as the
/// user wrote it, inside its `impl Block`: `type Params`, `live_params` (from the struct's
/// fields: a field, `[a, b]` an array of fields, `bits [a, b]` an array of analog fields as
/// 32-bit patterns), `latched_params` and `store_params` (a field of the private state):
/// `params_map!(SpeedParams { interval: tTimeInterval => tInterval, … });`.
macro_rules! params_map {
    (@live $s:ident bits [$($f:ident),+]) => { [$($s.$f.to_bits()),+] };
    (@live $s:ident [$($f:ident),+]) => { [$($s.$f),+] };
    (@live $s:ident $f:ident) => { $s.$f };
    ($params:ident { $($name:ident: $live:tt $([$($more:tt)*])? => $($latched:ident).+),+ $(,)? }) => {
        type Params = $params;
        #[inline(always)]
        fn live_params(&self) -> $params {
            $params {
                $($name: $crate::base::envelope::params_map!(@live self $live $([$($more)*])?)),+
            }
        }
        #[inline(always)]
        fn latched_params(&self) -> $params {
            let p = self.private();
            $params {
                $($name: p.$($latched).+),+
            }
        }
        fn store_params(&mut self, p: &$params) {
            let q = self.private_mut();
            $(q.$($latched).+ = p.$name;)+
        }
    };
}
pub(crate) use params_map;

/// The names a family's `Block` impl uses, for its expansion in a member's file.
macro_rules! family_prelude {
    ($family:path) => {
        use $crate::base::block::Private;
        #[allow(unused_imports)]
        use $crate::base::envelope::{Block, Instance};
        use $crate::base::types::*;
        #[allow(unused_imports)]
        use $crate::base::{
            bools, bools::Edge, edm, edm::Edm, header::*, pair, restart, restart::Restart, time,
        };
        use $family::*;
    };
}
pub(crate) use family_prelude;
