//! The state machine FB TON (manual §4.12), FB TON2 (§4.13) and FB TOF (§4.14) have in
//! common: one delay timer (`base::time`) that runs while a condition holds. TON and TON2
//! time while the input is TRUE and switch the output on when the delay is reached; TOF
//! times while the input is FALSE and switches the output off when it is reached. Both are
//! the same three phases:
//!
//! | phase | condition | TON / TON2 | TOF |
//! |---|---|---|---|
//! | Idle | does not hold | SAFE (3), out FALSE | RUN (1), out TRUE |
//! | Timing | holds, delay not reached | DELAYIN (9), out FALSE | DELAYOUT (8), out TRUE |
//! | Expired | holds, delay reached | RUN (1), out TRUE | SAFE (3), out FALSE |
//!
//! Idle → Timing starts the timer, Timing → Expired when it is reached, any phase → Idle as
//! soon as the condition fails (same cycle). The start state (after STOP → run and after
//! RESET) is SAFE for all three (TON: Idle, TOF: Expired), so an input already TRUE at
//! start-up counts as a change in the first running cycle (docs/semantics.md T5).
//!
//! Timebases (EL6910, manual §4.12.4, §4.14.4): `tDelay` is in ms; `nTimeBase` (ms) is 1,
//! 10, 100 or 1000, or 0 = automatic (the smallest timebase whose range holds `tDelay`). The
//! delay must be a whole number of timebase steps, at most 60,000 steps, and at least one:
//! anything else is `SL_E_CONFIG` (T1, T2). The running timer always counts exact
//! milliseconds (T3).
//!
//! TON2 additionally keeps the manual's stored "ExpiredTime" (`tElapsed`, T11–T15), which
//! the host persists with `sl_ton2_get_elapsed` and hands back with
//! `sl_ton2_restore_elapsed` after power-up.

use crate::base::header::{crc_words, param_crc, SL_PRIVATE_HEADER};
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/timer.rs"));

/// Private state of FB_TON, FB_TON2 and FB_TOF (64 bytes). Never written by the user.
///
/// Unlike the guard blocks, the timer start carries a complement copy: for TON the timer
/// decides when the output switches ON, so a corrupted start value must not go unnoticed
/// (docs/semantics.md T9). The TON2 stored elapsed time has one as well.
///
/// The latched parameters are kept full width in the order of the live fields (`tDelay`,
/// `nTimeBase`, `wInputActive` | `wInputNegated`, reserved, `dwOptions`), so that the fast
/// path compares them as two 64-bit words (docs/performance.md); the header's `nActive`,
/// `nNegated` and `wOptions` are not used by this family and stay 0.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct SL_TIMER_PRIVATE {
    /// Common head; `tPhase` is the timer start.
    pub stHeader: SL_PRIVATE_HEADER,
    /// Complement of `stHeader.tPhase`.
    pub tPhaseCheck: u32,
    /// Latched `tDelay` in ms.
    pub dwDelay: u32,
    /// Latched `nTimeBase` as written (0 = automatic).
    pub wTimeBase: u16,
    /// Latched `wInputActive`.
    pub wInputActive: u16,
    /// Latched `wInputNegated`.
    pub wInputNegated: u16,
    /// Reserved, 0 (covered by the CRC and the compare with the live parameters).
    pub wReserved: u16,
    /// Latched `dwOptions` (FB_TON2; 0 for the others).
    pub dwOptions: u32,
    /// FB_TON2: the stored elapsed time in ms (the manual's "ExpiredTime" in the FRAM).
    pub tElapsed: u32,
    /// Complement of `tElapsed`.
    pub tElapsedCheck: u32,
    /// Fast-path key and its check word (`base::envelope`).
    pub adwSteady: [u32; 2],
}

const _: () = assert!(core::mem::size_of::<SL_TIMER_PRIVATE>() == 64);

crate::base::envelope::steady_private!(SL_TIMER_PRIVATE, adwSteady, u32);

/// A fresh private area: everything zero except the complement copies.
impl Default for SL_TIMER_PRIVATE {
    fn default() -> Self {
        Self {
            stHeader: SL_PRIVATE_HEADER::default(),
            tPhaseCheck: !0,
            dwDelay: 0,
            wTimeBase: 0,
            wInputActive: 0,
            wInputNegated: 0,
            wReserved: 0,
            dwOptions: 0,
            tElapsed: 0,
            tElapsedCheck: !0,
            adwSteady: [0; 2],
        }
    }
}

impl SL_TIMER_PRIVATE {
    /// Starts the timer as if it had started at `start`.
    #[inline]
    pub(crate) fn set_start(&mut self, start: u32) {
        self.stHeader.tPhase = start;
        self.tPhaseCheck = !start;
    }

    /// Writes the stored elapsed time with its complement.
    #[inline]
    pub(crate) fn set_elapsed(&mut self, ms: u32) {
        self.tElapsed = ms;
        self.tElapsedCheck = !ms;
    }

    /// The stored elapsed time agrees with its complement.
    #[inline]
    pub(crate) fn elapsed_intact(&self) -> bool {
        self.tElapsedCheck == !self.tElapsed
    }

    /// The timer start and the stored elapsed time agree with their complements.
    #[inline]
    pub(crate) fn timers_intact(&self) -> bool {
        // Both differences are all ones exactly when their AND is.
        (self.tPhaseCheck ^ self.stHeader.tPhase) & (self.tElapsedCheck ^ self.tElapsed) == !0
    }

    /// After a failed complement check: a consistent timer start and no stored elapsed time
    /// (a full delay is the safe direction), so the corruption does not remain.
    #[inline]
    pub(crate) fn repair_timers(&mut self) {
        let start = self.stHeader.tPhase;
        self.set_start(start);
        self.set_elapsed(0);
    }
}

/// The timebase a delay is counted in: `base` itself, or for 0 (automatic) the smallest of
/// 1, 10, 100, 1000 ms whose range (60,000 steps) holds `delay`. `None`: no such timebase.
pub const fn time_base(delay: u32, base: u16) -> Option<u32> {
    match base {
        SL_TIMEBASE_AUTO => {
            let mut b = 1u32;
            while b <= SL_TIMEBASE_1000MS as u32 {
                if delay <= SL_TIMER_STEPS_MAX * b {
                    return Some(b);
                }
                b *= 10;
            }
            None
        }
        SL_TIMEBASE_1MS | SL_TIMEBASE_10MS | SL_TIMEBASE_100MS | SL_TIMEBASE_1000MS => {
            Some(base as u32)
        }
        _ => None,
    }
}

/// A valid delay: 1 to 60,000 whole steps of its timebase (docs/semantics.md T1, T2, T4).
pub const fn delay_valid(delay: u32, base: u16) -> bool {
    match time_base(delay, base) {
        Some(b) => delay != 0 && delay % b == 0 && delay / b <= SL_TIMER_STEPS_MAX,
        None => false,
    }
}

/// Timer parameters as the user wrote them.
#[derive(Clone, Copy, Debug, Default, Eq)]
pub struct TimerParams {
    pub delay: u32,
    pub time_base: u16,
    pub active: u16,
    pub negated: u16,
    /// The reserved bytes between `negated` and `options` in the latched copy (0 in the
    /// live parameters): a corrupted one is a corruption, not a parameter change.
    pub reserved: u16,
    pub options: u32,
}

impl TimerParams {
    /// The parameters as two words, in the order of the live fields and of the latched copy
    /// (every bit of every parameter in exactly one place).
    #[inline(always)]
    fn words(&self) -> [u64; 2] {
        [
            u64::from(self.delay) | u64::from(self.time_base) << 32 | u64::from(self.active) << 48,
            u64::from(self.negated)
                | u64::from(self.reserved) << 16
                | u64::from(self.options) << 32,
        ]
    }
}

/// Equal when every parameter is: compared as the two words of `TimerParams::words`, which
/// the compiler reads whole from the live fields and from the latched copy.
impl PartialEq for TimerParams {
    #[inline(always)]
    fn eq(&self, other: &Self) -> bool {
        self.words() == other.words()
    }
}

/// Decoded inputs of one cycle.
#[derive(Clone, Copy, Debug, Default)]
pub struct TimerIn {
    /// Logical value of the timer input (an invalid byte reads FALSE).
    pub input: bool,
    /// TON2: start with the remaining time (option set and Enable exactly TRUE).
    pub remaining: bool,
}

/// What distinguishes TON, TON2 and TOF.
pub trait TimerBlock: crate::base::block::Private<P = SL_TIMER_PRIVATE> {
    /// Type tag stored in the private header.
    const TAG: u16;
    /// TOF: the timer runs while the input is FALSE and the output is on until it expires.
    const OFF_DELAY: bool;
    /// Option bits the block accepts.
    const OPTIONS: u32;
    /// The block keeps the stored elapsed time (TON2).
    const PERSISTS: bool;
    /// The state value of the Timing phase (DELAYIN 9 / DELAYOUT 8).
    const TIMING_STATE: u8;

    fn params(&self) -> TimerParams;
    /// The raw timer input byte and the raw Enable byte (0 for blocks without Enable).
    fn raw(&self) -> (u8, u8);
    /// Writes the output field and info data.
    fn set_outputs(&mut self, out: bool, state: u8, diag: u16);
}

/// The three phases of the shared timer (module comment).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Phase {
    Idle,
    Timing,
    Expired,
}

/// The state value of a phase.
pub(crate) const fn state_of<T: TimerBlock>(p: Phase) -> u8 {
    match (p, T::OFF_DELAY) {
        (Phase::Idle, false) | (Phase::Expired, true) => SL_STATE_SAFE,
        (Phase::Idle, true) | (Phase::Expired, false) => SL_STATE_RUN,
        (Phase::Timing, _) => T::TIMING_STATE,
    }
}

/// The phase of a state value; `None` outside the running states.
pub(crate) fn phase_of<T: TimerBlock>(state: u8) -> Option<Phase> {
    [Phase::Idle, Phase::Timing, Phase::Expired]
        .into_iter()
        .find(|&p| state_of::<T>(p) == state)
}

/// The output in a phase: TON on when expired, TOF on until expired.
pub(crate) const fn output<T: TimerBlock>(p: Phase) -> bool {
    matches!(p, Phase::Expired) != T::OFF_DELAY
}

/// The output in a state value: on in the states of the phases where [`output`] is. One
/// state (TON, TON2): a compare; two (TOF): one bit test of their set, whose shift takes
/// the state value modulo 32 — every state value of a timer is below 32, and no other
/// reaches this test (the envelope refuses it first, docs/semantics.md C13; the fast path
/// serves only the state its key was stored in). Two compares would cost TOF's steady call
/// two instructions more.
#[inline(always)]
pub(crate) fn output_on<T: TimerBlock>(state: u8) -> bool {
    let on = const {
        let p = [Phase::Idle, Phase::Timing, Phase::Expired];
        let mut bits = 0u32;
        let mut i = 0;
        while i < p.len() {
            if output::<T>(p[i]) {
                bits |= 1 << state_of::<T>(p[i]);
            }
            i += 1;
        }
        bits
    };
    if on.is_power_of_two() {
        u32::from(state) == on.trailing_zeros()
    } else {
        on.wrapping_shr(u32::from(state)) & 1 != 0
    }
}

/// CRC of a timer's latched parameters (every bit of them; the header's masks are unused).
pub(crate) fn timer_crc(magic: u16, p: &SL_TIMER_PRIVATE) -> u16 {
    let (d, o) = (p.dwDelay, p.dwOptions);
    param_crc(
        magic,
        0,
        0,
        0,
        &crc_words![
            u32 d, u16 p.wTimeBase, u16 p.wInputActive, u16 p.wInputNegated, u16 p.wReserved, u32 o
        ],
    )
}

/// The struct of FB TON and FB TOF, declared once: they differ in the field names (`$op`
/// "Ton"/"Tof"), the docs of the input, the delay (`$kind` "on"/"off"), the output and the
/// status. build.rs writes every invocation out for cbindgen (`build_support/expand.rs`).
macro_rules! delay_struct {
    ($(#[doc = $doc:literal])* $name:ident: $op:literal, $kind:literal, [$in_doc:literal, $in_doc2:literal],
     $out_doc:literal, $state_doc:literal; $in:ident => $out:ident) => {
        $crate::base::layout::block_struct! {
            $(#[doc = $doc])*
            $name {
                /// Offset 0. Reserved, keep 0.
                pub aReserved0: [u8; 8],
                #[doc = concat!(" Offset 8. ", $op, "In1: ", $in_doc)]
                #[doc = $in_doc2]
                pub $in: SL_BOOL,
                /// Offset 9. Reserved, keep 0.
                pub aReserved1: [u8; 7],
                /// Offset 16. FbRun of the owning group: TRUE = the block executes.
                pub bRun: SL_BOOL,
                /// Offset 17. ErrAck of the owning group.
                pub bErrAck: SL_BOOL,
                /// Offset 18. Reserved, keep 0.
                pub aReserved2: [u8; 2],
                #[doc = concat!(" Offset 20. Switch-", $kind, " delay in ms: 1 to 60,000 steps of the timebase (at most")]
                /// 60,000,000 ms = 60,000 s), a whole number of steps.
                pub tDelay: u32,
                /// Offset 24. Timebase in ms: SL_TIMEBASE_1MS, _10MS, _100MS, _1000MS, or
                /// SL_TIMEBASE_AUTO (0) = the smallest one whose range holds tDelay.
                pub nTimeBase: u16,
                #[doc = concat!(" Offset 26. Bit 0 must be set: ", $op, "In1 is active.")]
                pub wInputActive: u16,
                #[doc = concat!(" Offset 28. Bit 0 set: ", $op, "In1 is a make contact (negated before evaluation).")]
                pub wInputNegated: u16,
                /// Offset 30. Reserved, keep 0.
                pub aReserved3: [u8; 2],
                /// Offset 32 (output base + 0). Reserved (the manual's error output is inactive).
                pub aReserved4: [u8; 1],
                #[doc = concat!(" Offset 33 (output base + 1). ", $op, "Out: TRUE in ", $out_doc, ".")]
                pub $out: SL_BOOL,
                /// Offset 34. Reserved.
                pub aReserved5: [u8; 6],
            } tail 40 41 42 44 48 [aReserved6, aReserved7] $crate::blocks::boolean::timer::SL_TIMER_PRIVATE, 64:
                concat!("(SL_STATE_*", $state_doc, ")"), "Diagnostic bits (only the library bits 13-15)."
        }
    };
}
pub(crate) use delay_struct;

/// The block behind a `delay_struct!`: states (`$states`: those after RESET), info, member
/// and the timer family's impls.
macro_rules! delay_block {
    ($(#[doc = $doc:literal])* $t:ident: $state:ident [$($states:tt)*], $tag:ident, $label:literal;
     magic $magic:literal, off_delay $off:literal, timing $timing:ident; $in:ident => $out:ident) => {
        $crate::base::block::block_states!(
            $(#[doc = $doc])*
            $state: Run, Stop, Safe, Error, Reset, $($states)*
        );

        $crate::impl_member!([] $t {
            info: $crate::base::block::BlockInfo::of::<$state>($tag, $label),
            state: $state,
            private: $crate::blocks::boolean::timer::SL_TIMER_PRIVATE,
            input: [$in],
            param: [tDelay, nTimeBase, wInputActive, wInputNegated],
            output: [$out],
            info_fields: [],
        });

        $crate::blocks::boolean::timer::timer_block!($t {
            tag: $magic,
            off_delay: $off,
            persists: false,
            timing_state: $timing,
            input: $in,
            output: $out,
        });
    };
}
pub(crate) use delay_block;

/// The envelope's view of a block of this family; invoked in the member's own file.
macro_rules! timer_block {
    // A member from its description: the TimerBlock impl from its constants and field
    // names (TON, TOF, TON2 differ in nothing else), then the envelope's Block.
    ($t:ty {
        tag: $tag:expr,
        off_delay: $off:expr,
        persists: $persists:expr,
        timing_state: $timing:expr,
        input: $in:ident,
        output: $out:ident
        $(, enable: $en:ident)?
        $(, options: $opt_field:ident = $opts:expr)?
        $(,)?
    }) => {
        impl $crate::blocks::boolean::timer::TimerBlock for $t {
            const TAG: u16 = $tag;
            const OFF_DELAY: bool = $off;
            const OPTIONS: u32 = 0 $(| $opts)?;
            const PERSISTS: bool = $persists;
            const TIMING_STATE: u8 = $timing;

            fn params(&self) -> $crate::blocks::boolean::timer::TimerParams {
                #[allow(unused_variables)]
                let options = 0;
                $(let options = self.$opt_field;)?
                $crate::blocks::boolean::timer::TimerParams {
                    delay: self.tDelay,
                    time_base: self.nTimeBase,
                    active: self.wInputActive,
                    negated: self.wInputNegated,
                    reserved: 0,
                    options,
                }
            }
            fn raw(&self) -> (u8, u8) {
                #[allow(unused_variables)]
                let enable = 0;
                $(let enable = self.$en;)?
                (self.$in, enable)
            }
            fn set_outputs(&mut self, out: bool, state: u8, diag: u16) {
                self.$out = u8::from(out);
                self.nState = state;
                self.nDiag = diag;
            }
        }
        $crate::blocks::boolean::timer::timer_block!($t);
    };
    ($t:ty) => {
        const _: () = {
            $crate::base::envelope::family_prelude!($crate::blocks::boolean::timer);

        impl $t {
            /// Every rule of the timers; `Block::RULES` leaves the last (options) out for a
            /// timer without `dwOptions`.
            const TIMER_RULES: [$crate::base::reason::RuleDef<TimerParams>; 7] = {
                use $crate::base::reason::{when, Rule, RuleDef, Unit};
                use $crate::blocks::boolean::timer::{time_base, SL_TIMER_STEPS_MAX};
                [
                    $crate::base::reason::rule!(equals "wInputActive", |p| p.active, 1),
                    $crate::base::reason::rule!(no_bits_outside "wInputNegated", |p| p.negated, 1),
                    RuleDef::new("nTimeBase", Rule::OneOf("0, 1, 10, 100, 1000"), Unit::Plain, |p| {
                        when(time_base(0, p.time_base).is_none(), p.time_base, 0)
                    }),
                    $crate::base::reason::rule!(not_zero "tDelay" in Ms, |p| p.delay),
                    RuleDef::new("tDelay", Rule::AtMost, Unit::Ms, |p| {
                        // Automatic: the largest timebase's range.
                        let b = time_base(p.delay, p.time_base).unwrap_or(1000);
                        let max = u64::from(SL_TIMER_STEPS_MAX) * u64::from(b);
                        when(u64::from(p.delay) > max, p.delay, max as i64)
                    }),
                    RuleDef::new("tDelay", Rule::MultipleOf, Unit::Ms, |p| {
                        let b = time_base(p.delay, p.time_base).unwrap_or(1000);
                        when(p.delay % b != 0, p.delay, b)
                    }),
                    $crate::base::reason::rule!(no_bits_outside "dwOptions", |p| p.options, Self::OPTIONS),
                ]
            };
        }

        impl Block for $t {
            const MAGIC: u16 = <$t as TimerBlock>::TAG;
            type Params = TimerParams;
            type In = TimerIn;

            fn live_params(&self) -> TimerParams {
                self.params()
            }

            fn latched_params(&self) -> TimerParams {
                let p = self.private();
                TimerParams {
                    delay: p.dwDelay,
                    time_base: p.wTimeBase,
                    active: p.wInputActive,
                    negated: p.wInputNegated,
                    reserved: p.wReserved,
                    options: p.dwOptions,
                }
            }

            /// One input, active; negation only for it; a delay of 1 to 60,000 whole
            /// timebase steps; known options (the last rule, for TON2, the timer that has
            /// `dwOptions`).
            const RULES: &'static [$crate::base::reason::RuleDef<TimerParams>] =
                if <Self as TimerBlock>::OPTIONS == 0 {
                    Self::TIMER_RULES.split_at(6).0
                } else {
                    &Self::TIMER_RULES
                };

            fn store_params(&mut self, p: &TimerParams) {
                let q = self.private_mut();
                q.dwDelay = p.delay;
                q.wTimeBase = p.time_base;
                q.wInputActive = p.active;
                q.wInputNegated = p.negated;
                q.wReserved = p.reserved;
                q.dwOptions = p.options;
            }

            fn latched_crc(&self) -> u16 {
                timer_crc(Self::MAGIC, self.private())
            }

            fn decode(&mut self) -> (TimerIn, bool) {
                let (raw_in, raw_enable) = self.raw();
                let p = self.private();
                // Narrowing is exact for valid parameters (bit 0 only); an invalid set never
                // runs.
                let (active, negated) = (p.wInputActive as u8, p.wInputNegated as u8);
                let packed = bools::pack([raw_in]);
                let input = bools::logical(packed, active, negated) & 1 != 0;
                // Enable is read only with "Starts with remaining time" (T10).
                let with_remaining = p.dwOptions & SL_OPT_TON2_REMAINING_TIME != 0;
                let inp = TimerIn {
                    input,
                    remaining: with_remaining && bools::is_true(raw_enable),
                };
                let invalid = packed.invalid & active != 0 || (with_remaining && raw_enable > 1);
                (inp, invalid)
            }

            /// The start state is SAFE for all three blocks (T5).
            fn start(&mut self, _inp: &TimerIn, _now: u32) {
                self.private_mut().stHeader.nState = SL_STATE_SAFE;
            }

            fn step(&mut self, inp: &TimerIn, now: u32) -> Status {
                let p = self.private_mut();
                let phase = match phase_of::<Self>(p.stHeader.nState) {
                    Some(ph) if p.timers_intact() => ph,
                    _ => {
                        // A state value this block never takes, or a timer value that fails
                        // its complement: the private state cannot be trusted.
                        p.repair_timers();
                        p.stHeader.enter_error(SL_DIAG_CORRUPT);
                        return Status::Corrupt;
                    }
                };
                let delay = p.dwDelay;
                // TON/TON2 time while the input is TRUE, TOF while it is FALSE.
                let holds = inp.input != Self::OFF_DELAY;
                let next = match phase {
                    _ if !holds => Phase::Idle,
                    Phase::Idle => {
                        // TON2 "Starts with remaining time": the timer starts as if it had
                        // started the stored elapsed time ago (T12).
                        let credit = if inp.remaining { p.tElapsed } else { 0 };
                        if credit > delay {
                            // The manual's global shutdown 0x3510 (T13).
                            p.set_elapsed(0);
                            p.stHeader.enter_error(SL_DIAG_TON2_RESTORE);
                            return Status::Restore;
                        }
                        p.set_start(now.wrapping_sub(credit));
                        Phase::Timing
                    }
                    Phase::Timing if time::reached(now, p.stHeader.tPhase, delay) => Phase::Expired,
                    other => other,
                };
                // The output switches on: verify the latched parameters first (C3).
                if !output::<Self>(phase)
                    && output::<Self>(next)
                    && timer_crc(Self::MAGIC, p) != p.stHeader.wParamCrc
                {
                    p.stHeader.enter_error(SL_DIAG_CORRUPT);
                    return Status::Corrupt;
                }
                if Self::PERSISTS {
                    // The stored elapsed time (T11): kept while Idle, so that a value restored
                    // at power-up survives until the input rises.
                    match (phase, next) {
                        (Phase::Idle, Phase::Idle) => {}
                        (_, Phase::Idle) => p.set_elapsed(0),
                        (_, Phase::Timing) => {
                            p.set_elapsed(time::elapsed(now, p.stHeader.tPhase).min(delay))
                        }
                        (_, Phase::Expired) => p.set_elapsed(delay),
                    }
                }
                p.stHeader.nState = state_of::<Self>(next);
                Status::Ok
            }

            // The timer blocks have no error condition of their own that could remain: a
            // refused elapsed time is discarded when the error is entered.
            // `error_remains` keeps its default (false).

            $crate::base::envelope::steady_hooks!();

            fn write_outputs(&mut self) {
                let h = self.private().stHeader;
                let out = output_on::<Self>(h.nState);
                self.set_outputs(out, h.nState, h.wDiag);
            }
        }

        impl $crate::base::envelope::Steady for $t {
            /// The four bytes the cycle reads (the input, Enable or 0, bRun, bErrAck) as they
            /// are: equal keys mean equal bytes, so a byte that is not a valid BOOL needs no
            /// test of its own. `None` while a timer value fails its complement: the full
            /// cycle reports it.
            #[inline(always)]
            fn steady_key(&self) -> Option<u32> {
                if !self.private().timers_intact() {
                    return None;
                }
                let (input, enable) = self.raw();
                Some(u32::from_le_bytes([input, enable, self.run_raw(), self.errack_raw()]))
            }

            /// The timer does not run.
            #[inline(always)]
            fn quiet(&self) -> bool {
                phase_of::<Self>(self.private().stHeader.nState) != Some(Phase::Timing)
            }

            /// Timing and the delay not reached at `now`: the call keeps Timing and changes
            /// nothing (TON, TOF). Never for TON2: its stored elapsed time follows the clock
            /// in every such call.
            #[inline(always)]
            fn timing_quiet(&self, now: u32) -> bool {
                let p = self.private();
                !Self::PERSISTS
                    && p.stHeader.nState == Self::TIMING_STATE
                    && !time::reached(now, p.stHeader.tPhase, p.dwDelay)
            }

            /// Every call but the one that starts the block leaves a state the same bytes
            /// keep: a phase the condition holds or fails in stays, Timing stays while the
            /// delay is not reached (`timing_quiet` decides that for the stored key), and
            /// the envelope's transitions as for the combinational blocks (`logic.rs`). The
            /// start state is left by the inputs that entered it (T5).
            const IDEMPOTENT: bool = true;
            const START_MOVES_ON: bool = true;

        }
        };
    };
}
pub(crate) use timer_block;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn automatic_time_base_is_the_smallest_that_holds_the_delay() {
        assert_eq!(time_base(1, 0), Some(1));
        assert_eq!(time_base(60_000, 0), Some(1));
        assert_eq!(time_base(60_001, 0), Some(10));
        assert_eq!(time_base(600_000, 0), Some(10));
        assert_eq!(time_base(600_001, 0), Some(100));
        assert_eq!(time_base(6_000_001, 0), Some(1000));
        assert_eq!(time_base(60_000_000, 0), Some(1000));
        assert_eq!(time_base(60_000_001, 0), None);
        assert_eq!(time_base(5, 7), None);
    }

    #[test]
    fn delay_limits_per_time_base() {
        for (base, max) in [(1u16, 60_000u32), (10, 600_000), (100, 6_000_000)] {
            let b = u32::from(base);
            assert!(delay_valid(max, base));
            assert!(delay_valid(b, base));
            assert!(!delay_valid(max + b, base));
            assert!(!delay_valid(0, base));
        }
        assert!(delay_valid(60_000_000, 1000));
        assert!(!delay_valid(60_001_000, 1000));
        assert!(!delay_valid(u32::MAX, 0));
        assert!(!delay_valid(1005, 10));
        assert!(!delay_valid(60_001, 0));
    }

    /// The output's bit test gives, for every state value of each timer, what its phase
    /// gives (the definition: `output` of the phase, off outside the running states).
    #[test]
    fn the_output_of_each_state_is_that_of_its_phase() {
        fn check<T: TimerBlock + crate::base::block::Registered>() {
            let mut on = 0;
            for v in 0..64u8 {
                if T::STATES.has(v) {
                    let phase = phase_of::<T>(v).is_some_and(output::<T>);
                    assert_eq!(output_on::<T>(v), phase, "{} state {v}", T::INFO.name);
                    on += usize::from(phase);
                }
            }
            assert_eq!(on, if T::OFF_DELAY { 2 } else { 1 }, "{}", T::INFO.name);
        }
        check::<crate::blocks::boolean::ton::FB_TON>();
        check::<crate::blocks::boolean::ton2::FB_TON2>();
        check::<crate::blocks::boolean::tof::FB_TOF>();
    }
}
