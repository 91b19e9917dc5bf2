//! The cycle envelope every block runs in (ABI §4, §5, §7): integrity check of the private
//! state, clock check, parameter latching and change detection, Run → STOP, ERROR → RESET
//! with ErrAck edges, the status code. The block itself only supplies its running states.
//!
//! The steady-state fast path (docs/performance.md): a block whose cycle reads only BOOL
//! bytes keeps, beside its private state, the key of the input bytes of the last call that
//! changed nothing (a fixed point of the full cycle in a state without a running timer).
//! A call with the same key, an intact private header, a clock that did not go backwards and
//! parameters equal to the latched ones would compute the same again: it only advances
//! `tLast` and rewrites the outputs. Every other call runs the full cycle and records
//! whether it was such a fixed point.

use super::bools::{edge, is_false, is_true};
use super::header::{F_CFG_INVALID, F_ERRACK_PREV, F_RESET_HELD, F_TIME_VALID, SL_PRIVATE_HEADER};
use super::time;
use crate::types::*;

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
pub trait Block: Instance + crate::registry::Registered {
    /// Type tag stored in the private header.
    const MAGIC: u16;
    /// The block's parameters as the user wrote them (wide types).
    type Params: PartialEq + Copy;
    /// Inputs of one cycle after BOOL decoding.
    type In;

    /// The live parameter fields.
    fn live_params(&self) -> Self::Params;
    /// The latched copy, widened.
    fn latched_params(&self) -> Self::Params;
    /// Parameter validation (manual limits, ABI §5 SL_E_CONFIG).
    fn params_valid(p: &Self::Params) -> bool;
    /// Writes the latched copy (narrowing; only meaningful for valid parameters).
    fn store_params(&mut self, p: &Self::Params);
    /// CRC of the latched copy.
    fn latched_crc(&self) -> u16;
    /// The latched copy still matches its CRC: checked where an output is about to switch
    /// on (docs/semantics.md C3), never on every cycle (the CRC costs more than a cycle).
    fn params_intact(&self) -> bool {
        self.latched_crc() == self.header().wParamCrc
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
    /// In ERROR: does a block-specific error condition remain (ABI §7 "Errors")?
    fn error_remains(&mut self, inp: &Self::In) -> bool;
    /// In RESET once ErrAck has fallen, bRun TRUE: may the block start now? A block that
    /// may not holds RESET and starts in the first call in which it may while ErrAck stays
    /// FALSE (FB SLI: "should only exit the RESET state if ErrAck=FALSE and SLI=FALSE").
    fn may_leave_reset(&self, _inp: &Self::In) -> bool {
        true
    }
    /// Writes the VAR_OUTPUT and info fields from the private state.
    fn write_outputs(&mut self);

    /// The key of this call for the fast path: bit i is BOOL byte i of every byte the cycle
    /// reads (inputs, bRun, bErrAck). `None` for a block without a fast path and whenever one
    /// of those bytes is neither 0 nor 1.
    #[inline(always)]
    fn steady_key(&self) -> Option<u16> {
        None
    }
    /// The last fixed-point call stored `key` (never for a block that is not steady).
    #[inline(always)]
    fn holds_key(&self, _key: u16) -> bool {
        false
    }
    /// Stores the key of a fixed-point call, or forgets it (`None`). Whatever changes the
    /// private state outside [`cycle`] forgets it.
    #[inline(always)]
    fn store_key(&mut self, _key: Option<u16>) {}
    /// The full cycle, recording whether it was a fixed point for `key` ([`settle`]).
    /// Out of line, as the fast path's `settle` is: the C function and the group's call of
    /// the block share one copy.
    #[inline(never)]
    fn settle(&mut self, _key: Option<u16>, now: u32) -> Status
    where
        Self: Sized,
    {
        full_cycle(self, now)
    }
    /// No running timer: the outcome of a call depends on the time only through the clock
    /// check. Only asked of blocks with a fast path.
    #[inline(always)]
    fn quiet(&self) -> bool {
        false
    }
    /// A key bit no key of the block has: set in a key stored in a timing state (below).
    /// Only meaningful for a block whose `timing_quiet` can be true.
    const TIMED_KEY: u16 = 0;
    /// A timer runs that is not reached at `now`, and a call that leaves the state as it is
    /// changes nothing else either (TON, TOF while timing): the outcome of a call at `now`
    /// depends on the time only through the clock check and this test. Asked by the full
    /// cycle of a fixed point that is not quiet, and by the fast path of a call whose key
    /// was stored in such a state.
    #[inline(always)]
    fn timing_quiet(&self, _now: u32) -> bool {
        false
    }
}

/// A private state with a fast-path key slot.
pub trait SteadyPrivate: Copy + PartialEq {
    /// The common head.
    fn head_mut(&mut self) -> &mut SL_PRIVATE_HEADER;
    /// The slot holds `key` with its check copy (one compare of the whole slot).
    fn holds(&self, key: u16) -> bool;
    /// Stores a key with its check copy, or clears the slot (`None`).
    fn set_key(&mut self, key: Option<u16>);
}

/// Implements [`SteadyPrivate`] for a private struct whose key slot is `$slot: [$w; 2]`
/// (key and complement; a key too wide for `$w` is never stored).
macro_rules! steady_private {
    ($p:ty, $slot:ident, $w:ty) => {
        impl $crate::prim::envelope::SteadyPrivate for $p {
            #[inline(always)]
            fn head_mut(&mut self) -> &mut $crate::prim::header::SL_PRIVATE_HEADER {
                &mut self.stHeader
            }
            #[inline(always)]
            fn holds(&self, key: u16) -> bool {
                <$w>::try_from(key).is_ok_and(|k| self.$slot == [k, !k])
            }
            #[inline(always)]
            fn set_key(&mut self, key: Option<u16>) {
                self.$slot = match key.and_then(|k| <$w>::try_from(k).ok()) {
                    Some(k) => [k, !k],
                    None => [0, 0],
                };
            }
        }
    };
}
pub(crate) use steady_private;

/// The fast-path methods of a family's `Block` impl whose private state is a
/// [`SteadyPrivate`] (the family supplies `steady_key` and `quiet`).
macro_rules! steady_hooks {
    () => {
        #[inline(always)]
        fn holds_key(&self, key: u16) -> bool {
            $crate::prim::envelope::SteadyPrivate::holds(self.private(), key)
        }
        #[inline(always)]
        fn store_key(&mut self, key: Option<u16>) {
            $crate::prim::envelope::SteadyPrivate::set_key(self.private_mut(), key)
        }
        #[inline(always)]
        fn settle(&mut self, key: Option<u16>, now: u32) -> Status {
            $crate::prim::envelope::settle(self, key, now)
        }
    };
}
pub(crate) use steady_hooks;

/// The private state without what a fast call changes (`tLast`) and without the key slot.
#[inline(always)]
fn fixed_part<P: SteadyPrivate>(p: &P) -> P {
    let mut v = *p;
    v.head_mut().tLast = 0;
    v.set_key(None);
    v
}

/// [`Block::settle`] of a block with a fast path: the full cycle, then the key stored when
/// the call returned SL_OK, left the private state as it found it (but for `tLast`) and no
/// timer runs; forgotten otherwise. Kept out of line: the fast path in [`cycle`] is then a
/// small leaf function.
#[inline(never)]
pub fn settle<B, P>(fb: &mut B, key: Option<u16>, now: u32) -> Status
where
    B: Block + crate::registry::Private<P = P>,
    P: SteadyPrivate,
{
    let Some(key) = key else {
        let status = full_cycle(fb, now);
        fb.private_mut().set_key(None);
        return status;
    };
    let before = fixed_part(fb.private());
    let status = full_cycle(fb, now);
    let fixed = status == Status::Ok && fixed_part(fb.private()) == before;
    let stored = if !fixed {
        None
    } else if fb.quiet() {
        Some(key)
    } else if fb.timing_quiet(now) {
        Some(key | B::TIMED_KEY)
    } else {
        None
    };
    fb.private_mut().set_key(stored);
    status
}

/// Latches the live parameters into the private copy; returns whether they are valid.
fn latch<B: Block>(fb: &mut B) -> bool {
    let p = fb.live_params();
    let ok = B::params_valid(&p);
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
    match fast(fb, now) {
        Ok(()) => (Status::Ok, true),
        Err(key) => (fb.settle(key, now), false),
    }
}

/// The fast path alone: `Ok` when it served the call (`SL_OK`), else the call's key for
/// [`Block::settle`], which must then run. Split from [`cycle`] so that the C boundary can
/// keep the fast path a leaf and reach the full cycle through an out-of-line call.
#[inline(always)]
pub fn fast<B: Block>(fb: &mut B, now: u32) -> Result<(), Option<u16>> {
    let key = fb.steady_key();
    if let Some(k) = key {
        // A key stored in a timing state carries TIMED_KEY: a call with the plain key never
        // reaches the timing test, so the blocks' quiet states pay nothing for it.
        let served = if fb.holds_key(k) {
            unchanged(fb, now)
        } else {
            fb.holds_key(k | B::TIMED_KEY) && unchanged(fb, now) && fb.timing_quiet(now)
        };
        if served {
            fb.header_mut().tLast = now;
            fb.write_outputs();
            return Ok(());
        }
    }
    Err(key)
}

/// What the fast path checks besides the key: the private header is intact, the clock did
/// not go backwards, the live parameters are the latched ones.
#[inline(always)]
fn unchanged<B: Block>(fb: &B, now: u32) -> bool {
    let h = fb.header();
    h.intact(B::MAGIC)
        && !time::went_backwards(now, h.tLast)
        && fb.live_params() == fb.latched_params()
}

/// The full cycle only, keeping the fast-path key as [`cycle`] does (the reference the
/// fast path is tested against).
#[doc(hidden)]
pub fn cycle_full<B: Block>(fb: &mut B, now: u32) -> Status {
    let key = fb.steady_key();
    fb.settle(key, now)
}

/// The full cycle (ABI §4, §5, §7).
#[inline(always)]
fn full_cycle<B: Block>(fb: &mut B, now: u32) -> Status {
    let mut status = Status::Ok;
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
    status
}

/// Forces the instance into ERROR with safe outputs after an internal fault (used by the
/// C boundary when it catches a panic).
pub fn force_error<B: Block>(fb: &mut B) {
    if !fb.header().intact(B::MAGIC) {
        power_up(fb, SL_STATE_ERROR, SL_DIAG_CORRUPT);
    }
    fb.store_key(None);
    fb.header_mut().enter_error(SL_DIAG_CORRUPT);
    fb.write_outputs();
    fb.header_mut().seal();
}
