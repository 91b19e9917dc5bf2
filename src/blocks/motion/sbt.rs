//! FB SBT (safe brake test) — manual §4.30; layout ABI-2 §11.15, rules ABI-2 §12.
//!
//! Tests a holding brake in one drive direction. A rising edge of SBT starts TESTING
//! (BrakeValid 0, MaxDuration running, the single-turn position latched); the test runs
//! while SBT = 1 and SBC In = 0 and passes when ActCurrentIq ≥ MinCurrentIq has held
//! continuously for MinDuration with the position never further than MaxPositionDeviation
//! from the latch → TEST-OK (BrakeValid 1, RemainingTime = BrakeTestInterval). A deviation
//! (0x40DA) or MaxDuration (0x40D8) → TEST-FAILED (TestError 1). SBT falling → RUN
//! (BrakeValid 1) after a passed test with time remaining, else SAFE. RemainingTime
//! (seconds) counts down in every running state; reaching 0 outside a test → MONS-ERROR
//! (0x40D9, TestError 1). The functional description wins over the status table where
//! they disagree (ABI-2 §14 row 30). States RUN (1), STOP (2), SAFE (3), ERROR (4) and
//! RESET (5) for the library's faults only, TESTING (16), TEST-OK (17), TEST-FAILED (18),
//! MONS-ERROR (20). Readings: docs/semantics.md BT1–BT8.

#![allow(non_camel_case_types)] // the ABI's names

use crate::base::block::BlockInfo;
use crate::base::block::Private;
use crate::base::bools::{self, edge};
use crate::base::envelope::Block;
use crate::base::header::{param_crc, put_crc_words, F_RESTART_PREV};
use crate::base::reason::rule;
use crate::base::reason::{when, Rule, RuleDef, Unit};
use crate::base::time::elapsed;
use crate::base::types::*;
use crate::blocks::analog::magic;

/// Type tag of FB_SBT (ABI-2 §10.6: sequential in the order of §10.3).
pub const SL_TYPE_SBT: u16 = 73;

/// State TESTING (16; the manual's "4.0").
pub const SL_STATE_SBT_TESTING: u8 = 16;
/// State TEST-OK (17; the manual's "4.1").
pub const SL_STATE_SBT_TEST_OK: u8 = 17;
/// State TEST-FAILED (18; the manual's "4.2", its messages' "FB-State=0x12").
pub const SL_STATE_SBT_TEST_FAILED: u8 = 18;
/// State MONS-ERROR (20; the manual's "5.0", its messages' "FB-State=0x14").
pub const SL_STATE_SBT_MONS_ERROR: u8 = 20;

/// Message: the maximum duration expired without a successful test (Par2 0x12, Par3
/// LatchPosition).
pub const SL_TEXT_SBT_MAX_DURATION: u16 = 0x40D8;
/// Message: the remaining time expired without a new test (Par2 0x14, Par3 LatchPosition).
pub const SL_TEXT_SBT_INTERVAL_EXPIRED: u16 = 0x40D9;
/// Message: the single-turn position exceeds the maximum deviation (Par2 the difference,
/// Par3 MaxPositionDeviation).
pub const SL_TEXT_SBT_POSITION_DEVIATION: u16 = 0x40DA;
/// `nDiag` of a message = its Text ID minus this (ABI-2 §10.4: no diag table).
pub const SL_SBT_DIAG_TEXT_BASE: u16 = 0x4000;

/// `wInputActive` bit of SBT (required).
pub const SL_SBT_ACTIVE_SBT: u16 = 1 << 0;
/// `wInputActive` bit of SBC In (required).
pub const SL_SBT_ACTIVE_SBCIN: u16 = 1 << 1;
/// `wInputActive` bit of SingleturnPos (required).
pub const SL_SBT_ACTIVE_SINGLETURNPOS: u16 = 1 << 8;
/// `wInputActive` bit of ActCurrentIq (required).
pub const SL_SBT_ACTIVE_ACTCURRENTIQ: u16 = 1 << 9;
/// `wInputActive` bit of MinCurrentIq: set = the input, clear = `nMinCurrentIqFix`.
pub const SL_SBT_ACTIVE_MINCURRENTIQ: u16 = 1 << 10;

/// Largest value of the three TIME parameters (ABI-2 §12.9: 4,294,967 s in ms).
pub const SL_SBT_TIME_MAX: u32 = 4_294_967_000;

crate::base::layout::private_struct! {
    /// Private state of FB SBT (80 bytes). Never written by the user.
    SL_SBT_PRIVATE {
        /// Common head (`wAux` bit 0: LastTestResult, bit 1: the test condition held in the
        /// previous call; `tPhase`: the previous running call; `F_RESTART_PREV`: SBT's level).
        stHeader;
        /// Latched `wInputActive`.
        pub wActive: u16,
        /// Text ID of the message of TEST-FAILED / MONS-ERROR.
        pub wText: u16,
        /// Latched tBrakeTestInterval, tMinDuration, tMaxDuration (ms), nMaxPositionDeviation,
        /// nMinCurrentIqFix (pattern).
        pub adwParam: [u32; 5],
        /// Remaining time until the next brake test, ms.
        pub dwRemainingMs: u32,
        /// Time since the test started (MaxDuration), ms, saturating.
        pub dwTestMs: u32,
        /// Time the test condition has held without a break (MinDuration), ms, saturating.
        pub dwHeldMs: u32,
        /// SingleturnPos latched at the start of the test.
        pub dwLatchPos: u32,
        /// The message's parameters 2 and 3.
        pub adwPar: [u32; 2],
        /// Reserved.
        pub aReserved: [u8; 4],
    }
}

crate::base::layout::block_struct! {
    /// FB SBT instance (ABI-2 §11.15). Size: 176 bytes.
    FB_SBT {
        /// Offset 0. SBT: a rising edge starts a brake test (bit 0, required; an invalid byte
        /// reads FALSE without an edge).
        pub bSBT: SL_BOOL,
        /// Offset 1. SBC In: 0 = brake applied, 1 = released (bit 1, required; an invalid byte
        /// reads TRUE, no test credit).
        pub bSBCIn: SL_BOOL,
        /// Offset 2. Reserved, keep 0.
        pub aReserved0: [u8; 14],
        /// Offset 16. FbRun of the owning group: TRUE = the block executes.
        pub bRun: SL_BOOL,
        /// Offset 17. ErrAck of the owning group.
        pub bErrAck: SL_BOOL,
        /// Offset 18. Reserved, keep 0.
        pub aReserved1: [u8; 6],
        /// Offset 24. SingleturnPos: the current safe position (active bit 8, required).
        pub nSingleturnPos: u32,
        /// Offset 28. ActCurrentIq: the torque-forming current of the axis (active bit 9, required).
        pub nActCurrentIq: i32,
        /// Offset 32. MinCurrentIq: the current of the minimum required torque, used while
        /// active bit 10 is set.
        pub nMinCurrentIq: i32,
        /// Offset 36. "BrakeTestInterval" in ms: 1000 to 4,294,967,000, a multiple of 1000.
        pub tBrakeTestInterval: u32,
        /// Offset 40. "MinDuration" in ms: a multiple of 100, at most tMaxDuration.
        pub tMinDuration: u32,
        /// Offset 44. "MaxDuration" in ms: a multiple of 100, at most 4,294,967,000.
        pub tMaxDuration: u32,
        /// Offset 48. "MaxPositionDeviation" in increments.
        pub nMaxPositionDeviation: u32,
        /// Offset 52. Parameter "MinCurrentIq", used while bit 10 is clear.
        pub nMinCurrentIqFix: i32,
        /// Offset 56. Bits 0, 1, 8, 9 required; bit 10 chooses input or parameter.
        pub wInputActive: u16,
        /// Offset 58. Reserved, keep 0.
        pub aReserved2: [u8; 6],
        /// Offset 64 (output base + 0). TestError: TEST-FAILED or MONS-ERROR.
        pub bTestError: SL_BOOL,
        /// Offset 65. BrakeValid: the last test passed and its interval has not expired (RUN,
        /// TEST-OK).
        pub bBrakeValid: SL_BOOL,
        /// Offset 66. Reserved.
        pub aReserved3: [u8; 6],
        /// Offset 72 (analog output base). RemainingTime until the next brake test in
        /// seconds (rounded up); 0 in STOP, ERROR, RESET, MONS-ERROR.
        pub nRemainingTime: u32,
        /// Offset 76. Reserved.
        pub aReserved4: [u8; 4],
    } info [aReserved5, aReserved6] SL_SBT_PRIVATE, "80 bytes":
        "The manual's status value (SL_STATE_*, SL_STATE_SBT_*).",
        "The message's Text ID − 0x4000 (0xD8, 0xD9, 0xDA) + library bits 13-15.",
        "Text ID of the message in TEST-FAILED / MONS-ERROR, 0 = none.", "Message parameter 2.",
        "Message parameter 3."
}

const _: () = {
    use core::mem::{offset_of, size_of};
    assert!(offset_of!(FB_SBT, bSBCIn) == 1 && offset_of!(FB_SBT, bRun) == 16);
    assert!(offset_of!(FB_SBT, nSingleturnPos) == 24 && offset_of!(FB_SBT, nMinCurrentIq) == 32);
    assert!(offset_of!(FB_SBT, tBrakeTestInterval) == 36);
    assert!(offset_of!(FB_SBT, nMinCurrentIqFix) == 52);
    assert!(offset_of!(FB_SBT, wInputActive) == 56 && offset_of!(FB_SBT, bTestError) == 64);
    assert!(offset_of!(FB_SBT, nRemainingTime) == 72 && offset_of!(FB_SBT, nState) == 80);
    assert!(offset_of!(FB_SBT, nDiagTextId) == 84 && offset_of!(FB_SBT, dwDiagPar3) == 92);
    assert!(offset_of!(FB_SBT, stPrivate) == 96);
    assert!(size_of::<SL_SBT_PRIVATE>() == 80 && size_of::<FB_SBT>() == 176);
};

crate::base::block::block_states!(
    /// The states of FB SBT (manual §4.30.2.3, numbers of ABI-2 §11.15).
    SbtState: Run, Stop, Safe, Error, Reset,
    Testing = SL_STATE_SBT_TESTING, "TESTING",
    TestOk = SL_STATE_SBT_TEST_OK, "TEST-OK",
    TestFailed = SL_STATE_SBT_TEST_FAILED, "TEST-FAILED",
    MonsError = SL_STATE_SBT_MONS_ERROR, "MONS-ERROR"
);

/// Type tag, name, states and diag values (the messages, ABI-2 §11.15).
const INFO: BlockInfo = BlockInfo::of::<SbtState>(SL_TYPE_SBT, "SBT").diag_values(&[
        (0, "No diagnostic information"),
        (
            SL_TEXT_SBT_MAX_DURATION - SL_SBT_DIAG_TEXT_BASE,
            "The maximum duration of the brake test has expired without the test being successfully completed.",
        ),
        (
            SL_TEXT_SBT_INTERVAL_EXPIRED - SL_SBT_DIAG_TEXT_BASE,
            "The time remaining for the next brake test has expired and no new brake test has been started.",
        ),
        (
            SL_TEXT_SBT_POSITION_DEVIATION - SL_SBT_DIAG_TEXT_BASE,
            "The single-turn position exceeds the maximum position deviation.",
        ),
    ]);

crate::impl_member!([] FB_SBT {
    info: INFO,
    state: SbtState,
    private: SL_SBT_PRIVATE,
    input: [bSBT, bSBCIn, nSingleturnPos, nActCurrentIq, nMinCurrentIq],
    param: [tBrakeTestInterval, tMinDuration, tMaxDuration, nMaxPositionDeviation,
        nMinCurrentIqFix, wInputActive],
    output: [bTestError, bBrakeValid, nRemainingTime],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

/// Parameters as the user wrote them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SbtParams {
    active: u16,
    values: [u32; 5],
}

/// The four signals every configuration has active (SBT, SBCIn, single-turn position,
/// ActCurrentIq).
const SBT_REQUIRED: u16 = SL_SBT_ACTIVE_SBT
    | SL_SBT_ACTIVE_SBCIN
    | SL_SBT_ACTIVE_SINGLETURNPOS
    | SL_SBT_ACTIVE_ACTCURRENTIQ;
const INTERVAL: usize = 0;
const MIN_DURATION: usize = 1;
const MAX_DURATION: usize = 2;
const MAX_DEVIATION: usize = 3;
const MIN_IQ_FIX: usize = 4;

/// One cycle's inputs after BOOL decoding.
#[derive(Clone, Copy, Debug)]
pub struct SbtIn {
    sbt: bools::Edge,
    /// SBC In: brake released (an invalid byte reads TRUE).
    released: bool,
    pos: u32,
    iq: i32,
    min_iq: i32,
}

/// `wAux` bits.
const LAST_OK: u16 = 1;
const HELD: u16 = 2;

/// The private state a call changes besides the state value.
#[derive(Clone, Copy, Debug)]
struct Progress {
    aux: u16,
    remaining: u32,
    test: u32,
    held: u32,
    latch: u32,
    text: u16,
    par: [u32; 2],
}

/// The distance of two single-turn positions on the circle of 2³² increments.
fn deviation(pos: u32, latch: u32) -> u32 {
    let d = pos.wrapping_sub(latch);
    d.min(d.wrapping_neg())
}

impl Progress {
    /// One call in TESTING (SBT TRUE): the test condition, then deviation, pass, timeout.
    fn check(&mut self, inp: &SbtIn, dt: u32, p: &[u32; 5]) -> u8 {
        self.test = self.test.saturating_add(dt);
        let condition = !inp.released && inp.iq >= inp.min_iq;
        self.held = match (condition, self.aux & HELD != 0) {
            (true, true) => self.held.saturating_add(dt),
            _ => 0,
        };
        self.aux = if condition {
            self.aux | HELD
        } else {
            self.aux & !HELD
        };
        let diff = deviation(inp.pos, self.latch);
        if diff > p[MAX_DEVIATION] {
            self.fail(SL_TEXT_SBT_POSITION_DEVIATION, [diff, p[MAX_DEVIATION]])
        } else if condition && self.held >= p[MIN_DURATION] {
            self.aux |= LAST_OK;
            self.remaining = p[INTERVAL];
            SL_STATE_SBT_TEST_OK
        } else if self.test >= p[MAX_DURATION] {
            let state = u32::from(SL_STATE_SBT_TEST_FAILED);
            self.fail(SL_TEXT_SBT_MAX_DURATION, [state, self.latch])
        } else {
            SL_STATE_SBT_TESTING
        }
    }

    /// TEST-FAILED with its message; the last test is negative.
    fn fail(&mut self, text: u16, par: [u32; 2]) -> u8 {
        self.aux &= !LAST_OK;
        (self.text, self.par) = (text, par);
        SL_STATE_SBT_TEST_FAILED
    }
}

impl Block for FB_SBT {
    const MAGIC: u16 = magic(SL_TYPE_SBT);
    type Params = SbtParams;
    type In = SbtIn;

    #[inline(always)]
    fn live_params(&self) -> SbtParams {
        SbtParams {
            active: self.wInputActive,
            values: [
                self.tBrakeTestInterval,
                self.tMinDuration,
                self.tMaxDuration,
                self.nMaxPositionDeviation,
                self.nMinCurrentIqFix as u32,
            ],
        }
    }
    #[inline(always)]
    fn latched_params(&self) -> SbtParams {
        let p = self.private();
        SbtParams {
            active: p.wActive,
            values: p.adwParam,
        }
    }
    /// ABI-2 §11.15: the four signals active, bit 10 free, nothing else; the interval a
    /// non-zero number of seconds, the durations in tenths, MinDuration ≤ MaxDuration,
    /// all at most SL_SBT_TIME_MAX (semantics BT7). The limits come before the multiples:
    /// SL_SBT_TIME_MAX is itself the largest whole second of the type.
    const RULES: &'static [RuleDef<SbtParams>] = &[
        rule!(no_bits_outside "wInputActive", |p| p.active, SBT_REQUIRED | SL_SBT_ACTIVE_MINCURRENTIQ),
        RuleDef::new("wInputActive", Rule::BitsSet, Unit::Hex, |p| {
            when(
                p.active & SBT_REQUIRED != SBT_REQUIRED,
                p.active,
                SBT_REQUIRED,
            )
        }),
        rule!(not_zero "tBrakeTestInterval" in Ms, |p| p.values[INTERVAL]),
        RuleDef::new("tBrakeTestInterval", Rule::AtMost, Unit::Ms, |p| {
            let t = p.values[INTERVAL];
            when(t > SL_SBT_TIME_MAX, t, SL_SBT_TIME_MAX)
        }),
        RuleDef::new("tMaxDuration", Rule::AtMost, Unit::Ms, |p| {
            let t = p.values[MAX_DURATION];
            when(t > SL_SBT_TIME_MAX, t, SL_SBT_TIME_MAX)
        }),
        RuleDef::new("tBrakeTestInterval", Rule::MultipleOf, Unit::Ms, |p| {
            let t = p.values[INTERVAL];
            when(t % 1000 != 0, t, 1000)
        }),
        RuleDef::new("tMinDuration", Rule::MultipleOf, Unit::Ms, |p| {
            let t = p.values[MIN_DURATION];
            when(t % 100 != 0, t, 100)
        }),
        RuleDef::new("tMaxDuration", Rule::MultipleOf, Unit::Ms, |p| {
            let t = p.values[MAX_DURATION];
            when(t % 100 != 0, t, 100)
        }),
        RuleDef::new(
            "tMinDuration",
            Rule::NotAbove("tMaxDuration"),
            Unit::Ms,
            |p| {
                let (min, max) = (p.values[MIN_DURATION], p.values[MAX_DURATION]);
                when(min > max, min, max)
            },
        ),
    ];
    fn store_params(&mut self, p: &SbtParams) {
        let q = self.private_mut();
        q.wActive = p.active;
        q.adwParam = p.values;
    }
    fn latched_crc(&self) -> u16 {
        let p = self.private();
        let mut words = [p.wActive; 11];
        put_crc_words(&mut words[1..], p.adwParam);
        param_crc(Self::MAGIC, 0, 0, 0, &words)
    }
    /// SBT: an invalid byte reads FALSE without an edge; SBC In: an invalid byte reads
    /// TRUE (brake released: no test credit, ABI-2 §12.7).
    #[inline(always)]
    fn decode(&mut self) -> (SbtIn, bool) {
        let raw = bools::pack([self.bSBT, self.bSBCIn]);
        let min_iq = if self.private().wActive & SL_SBT_ACTIVE_MINCURRENTIQ != 0 {
            self.nMinCurrentIq
        } else {
            self.private().adwParam[MIN_IQ_FIX] as i32
        };
        let sbt_raw = self.bSBT;
        // SBT is this block's start request: its edge memory is the header's Restart bit.
        let sbt = edge(
            sbt_raw,
            &mut self.private_mut().stHeader.nFlags,
            F_RESTART_PREV,
        );
        (
            SbtIn {
                sbt,
                released: (raw.ones | raw.invalid) & 2 != 0,
                pos: self.nSingleturnPos,
                iq: self.nActCurrentIq,
                min_iq,
            },
            raw.invalid != 0,
        )
    }
    /// STOP → run and RESET → run: LastTestResult FALSE, the full interval remaining
    /// (semantics BT1), then this call.
    fn start(&mut self, inp: &SbtIn, now: u32) {
        let p = self.private_mut();
        p.stHeader.nState = SL_STATE_SAFE;
        p.stHeader.wAux = 0;
        p.stHeader.tPhase = now;
        p.dwRemainingMs = p.adwParam[INTERVAL];
        p.wText = 0;
        p.adwPar = [0; 2];
        self.step(inp, now);
    }
    #[inline(always)]
    fn step(&mut self, inp: &SbtIn, now: u32) -> Status {
        let p = *self.private();
        let h = p.stHeader;
        let dt = elapsed(now, h.tPhase);
        let mut g = Progress {
            aux: h.wAux,
            remaining: p.dwRemainingMs.saturating_sub(dt),
            test: p.dwTestMs,
            held: p.dwHeldMs,
            latch: p.dwLatchPos,
            text: p.wText,
            par: p.adwPar,
        };
        let next = match h.nState {
            SL_STATE_SBT_TESTING if inp.sbt.level => g.check(inp, dt, &p.adwParam),
            SL_STATE_SBT_TEST_OK | SL_STATE_SBT_TEST_FAILED if inp.sbt.level => h.nState,
            _ if inp.sbt.rising => {
                (g.test, g.held, g.latch) = (0, 0, inp.pos);
                g.aux &= !HELD;
                g.check(inp, 0, &p.adwParam)
            }
            SL_STATE_SBT_MONS_ERROR => h.nState,
            // Outside a test (SBT FALSE, or a test just ended by its falling edge).
            _ if g.remaining == 0 => {
                g.aux &= !LAST_OK;
                let state = u32::from(SL_STATE_SBT_MONS_ERROR);
                (g.text, g.par) = (SL_TEXT_SBT_INTERVAL_EXPIRED, [state, g.latch]);
                SL_STATE_SBT_MONS_ERROR
            }
            _ if g.aux & LAST_OK != 0 => SL_STATE_RUN,
            _ => SL_STATE_SAFE,
        };
        // BrakeValid switching on is where the latched parameters are verified (C3).
        if self.corrupt_at_switch_on(brake_valid(next) && !brake_valid(h.nState)) {
            return Status::Corrupt;
        }
        let q = self.private_mut();
        q.stHeader.nState = next;
        q.stHeader.wAux = g.aux;
        q.stHeader.tPhase = now;
        q.dwRemainingMs = g.remaining;
        q.dwTestMs = g.test;
        q.dwHeldMs = g.held;
        q.dwLatchPos = g.latch;
        q.wText = g.text;
        q.adwPar = g.par;
        Status::Ok
    }
    // Only the library's faults lead to ERROR; none of them remains: `error_remains` keeps
    // its default (false).
    #[inline(always)]
    fn write_outputs(&mut self) {
        let p = *self.private();
        let h = p.stHeader;
        let (test_error, counting) = match h.nState {
            SL_STATE_SBT_TEST_FAILED => (true, true),
            SL_STATE_SBT_MONS_ERROR => (true, false),
            SL_STATE_RUN | SL_STATE_SAFE | SL_STATE_SBT_TESTING | SL_STATE_SBT_TEST_OK => {
                (false, true)
            }
            _ => (false, false),
        };
        self.bTestError = u8::from(test_error);
        self.bBrakeValid = u8::from(brake_valid(h.nState));
        self.nRemainingTime = if counting {
            p.dwRemainingMs.div_ceil(1000)
        } else {
            0
        };
        self.nState = h.nState;
        let (text, par) = if test_error {
            (p.wText, p.adwPar)
        } else {
            (0, [0; 2])
        };
        self.nDiag = h.wDiag | text.saturating_sub(SL_SBT_DIAG_TEXT_BASE);
        (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) = (text, par[0], par[1]);
    }
}

/// BrakeValid is TRUE in RUN and TEST-OK.
fn brake_valid(state: u8) -> bool {
    state == SL_STATE_RUN || state == SL_STATE_SBT_TEST_OK
}
