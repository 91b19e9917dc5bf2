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

include!(concat!(env!("OUT_DIR"), "/abi/blocks/motion/sbt.rs"));

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
