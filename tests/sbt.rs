//! FB SBT (manual §4.30, ABI-2 §11.15, §12; docs/semantics.md BT1–BT8): one test per
//! statement of the manual section, then random sequences (≥ 10,000) against a small
//! model of the block (absolute 64-bit times, no shared code) that assert what they
//! reached.

mod common;

use common::{run_steps, state_names, Rng, CORE_STATES, CORE_STATE_NAMES};
use safelogic::*;

const ALL: u16 = SL_SBT_ACTIVE_SBT
    | SL_SBT_ACTIVE_SBCIN
    | SL_SBT_ACTIVE_SINGLETURNPOS
    | SL_SBT_ACTIVE_ACTCURRENTIQ;
const TESTING: u8 = SL_STATE_SBT_TESTING;
const TEST_OK: u8 = SL_STATE_SBT_TEST_OK;
const TEST_FAILED: u8 = SL_STATE_SBT_TEST_FAILED;
const MONS_ERROR: u8 = SL_STATE_SBT_MONS_ERROR;

/// Interval 10 s, MinDuration 1 s, MaxDuration 3 s, deviation 10, MinCurrentIq 100.
fn make() -> FB_SBT {
    FB_SBT {
        wInputActive: ALL,
        tBrakeTestInterval: 10_000,
        tMinDuration: 1_000,
        tMaxDuration: 3_000,
        nMaxPositionDeviation: 10,
        nMinCurrentIqFix: 100,
        ..Default::default()
    }
}

/// (state, TestError, BrakeValid, RemainingTime).
fn outs(fb: &FB_SBT) -> Outs {
    (fb.nState, fb.bTestError, fb.bBrakeValid, fb.nRemainingTime)
}

fn message(fb: &FB_SBT) -> Message {
    (fb.nDiag, fb.nDiagTextId, fb.dwDiagPar2, fb.dwDiagPar3)
}

/// Inputs: SBT, SBC In, SingleturnPos, ActCurrentIq.
fn set(fb: &mut FB_SBT, sbt: u8, sbc: u8, pos: u32, iq: i32) {
    fb.bSBT = sbt;
    fb.bSBCIn = sbc;
    fb.nSingleturnPos = pos;
    fb.nActCurrentIq = iq;
}

/// Started at t = 0 (SAFE, full interval).
fn running(fb: FB_SBT) -> FB_SBT {
    let mut fb = fb;
    assert_eq!(fb.init(), SL_OK);
    fb.bRun = 1;
    assert_eq!(fb.cycle(0), SL_OK);
    fb
}

/// Starts a test at `t` with the brake applied and the current at MinCurrentIq, and
/// passes it after MinDuration: TEST-OK at t + 1000.
fn pass_test(fb: &mut FB_SBT, t: u32) {
    set(fb, 1, 0, 1000, 100);
    assert_eq!(fb.cycle(t), SL_OK);
    assert_eq!(fb.nState, TESTING);
    assert_eq!(fb.cycle(t + 1000), SL_OK);
    assert_eq!(fb.nState, TEST_OK);
}

/// BT1: STOP → run gives SAFE (no passed test yet) with RemainingTime = BrakeTestInterval
/// in seconds; STOP shows 0.
#[test]
fn start_is_safe_with_the_full_interval() {
    let mut fb = make();
    assert_eq!(fb.init(), SL_OK);
    assert_eq!(outs(&fb), (SL_STATE_STOP, 0, 0, 0));
    fb.bRun = 1;
    assert_eq!(fb.cycle(0), SL_OK);
    assert_eq!(outs(&fb), (SL_STATE_SAFE, 0, 0, 10));
    fb.bRun = 0;
    assert_eq!(fb.cycle(5), SL_OK);
    assert_eq!(outs(&fb), (SL_STATE_STOP, 0, 0, 0));
}

/// BT2: RemainingTime counts down in seconds, rounded up (10 until 1 s has passed).
#[test]
fn remaining_time_counts_down_in_seconds() {
    let mut fb = running(make());
    for (t, s) in [
        (1, 10),
        (999, 10),
        (1000, 9),
        (1001, 9),
        (9000, 1),
        (9999, 1),
    ] {
        assert_eq!(fb.cycle(t), SL_OK);
        assert_eq!(outs(&fb), (SL_STATE_SAFE, 0, 0, s), "t {t}");
    }
}

/// §4.30.1 "If the test is successful: TestError 0, BrakeValid 1, RemainingTime
/// BrakeTestInterval"; TESTING "BrakeValid = 0"; MinDuration at its edge; SBT falling →
/// RUN with BrakeValid 1 (functional description over the status table, BT3).
#[test]
fn a_successful_test() {
    let mut fb = running(make());
    set(&mut fb, 1, 0, 1000, 100);
    assert_eq!(fb.cycle(2000), SL_OK);
    assert_eq!(outs(&fb), (TESTING, 0, 0, 8));
    assert_eq!(fb.cycle(2999), SL_OK);
    assert_eq!(outs(&fb), (TESTING, 0, 0, 8), "1 ms below MinDuration");
    assert_eq!(fb.cycle(3000), SL_OK);
    assert_eq!(outs(&fb), (TEST_OK, 0, 1, 10), "the interval restarts");
    assert_eq!(message(&fb), (0, 0, 0, 0));
    assert_eq!(fb.cycle(4000), SL_OK);
    assert_eq!(outs(&fb), (TEST_OK, 0, 1, 9));
    fb.bSBT = 0;
    assert_eq!(fb.cycle(4100), SL_OK);
    assert_eq!(outs(&fb), (SL_STATE_RUN, 0, 1, 9));
}

/// "ActCurrentIq is equal to or greater than MinCurrentIq for the duration of
/// MinDuration": one below gives no credit; a dip restarts the duration.
#[test]
fn the_current_must_hold_for_min_duration() {
    let mut fb = running(make());
    set(&mut fb, 1, 0, 0, 99);
    assert_eq!(fb.cycle(0), SL_OK);
    assert_eq!(fb.cycle(1200), SL_OK);
    assert_eq!(fb.nState, TESTING);
    fb.nActCurrentIq = 100;
    assert_eq!(fb.cycle(1300), SL_OK);
    assert_eq!(fb.cycle(1500), SL_OK);
    fb.nActCurrentIq = 99;
    assert_eq!(fb.cycle(1600), SL_OK);
    fb.nActCurrentIq = i32::MAX;
    assert_eq!(fb.cycle(1700), SL_OK);
    assert_eq!(fb.cycle(2699), SL_OK);
    assert_eq!(fb.nState, TESTING);
    assert_eq!(fb.cycle(2700), SL_OK);
    assert_eq!(fb.nState, TEST_OK);
}

/// "As soon as SBT=1 and SBTIn=0" (SBC In, BT4): a released brake restarts MinDuration;
/// an invalid SBC In byte reads TRUE.
#[test]
fn a_released_brake_gives_no_credit() {
    let mut fb = running(make());
    set(&mut fb, 1, 0, 0, 100);
    assert_eq!(fb.cycle(0), SL_OK);
    fb.bSBCIn = 1;
    assert_eq!(fb.cycle(900), SL_OK);
    fb.bSBCIn = 0;
    assert_eq!(fb.cycle(1000), SL_OK);
    assert_eq!(fb.nState, TESTING);
    fb.bSBCIn = 3;
    assert_eq!(fb.cycle(1500), SL_E_INVALID_BOOL);
    fb.bSBCIn = 0;
    assert_eq!(fb.cycle(1600), SL_OK);
    assert_eq!(fb.cycle(2599), SL_OK);
    assert_eq!(fb.nState, TESTING);
    assert_eq!(fb.cycle(2600), SL_OK);
    assert_eq!(fb.nState, TEST_OK);
}

/// 0x40DA "The single-turn position exceeds the maximum position deviation": TEST-FAILED,
/// TestError 1, Par2 = the difference, Par3 = MaxPositionDeviation; the deviation at the
/// limit passes; the difference is taken on the single-turn circle (BT5).
#[test]
fn a_position_deviation_fails_the_test_40da() {
    let mut fb = running(make());
    set(&mut fb, 1, 0, 5, 0);
    assert_eq!(fb.cycle(0), SL_OK);
    fb.nSingleturnPos = 5u32.wrapping_sub(10);
    assert_eq!(fb.cycle(10), SL_OK);
    assert_eq!(
        fb.nState, TESTING,
        "a deviation of exactly MaxPositionDeviation"
    );
    fb.nSingleturnPos = 5u32.wrapping_sub(11);
    assert_eq!(fb.cycle(20), SL_OK);
    assert_eq!(outs(&fb), (TEST_FAILED, 1, 0, 10));
    assert_eq!(message(&fb), (0xDA, 0x40DA, 11, 10));
    fb.bSBT = 0;
    assert_eq!(fb.cycle(30), SL_OK);
    assert_eq!(
        (outs(&fb), message(&fb)),
        ((SL_STATE_SAFE, 0, 0, 10), (0, 0, 0, 0))
    );
}

/// 0x40D8 "The maximum duration of the brake test has expired": TEST-FAILED at exactly
/// MaxDuration, Par2 = 0x12, Par3 = LatchPosition; the failed test drops an earlier pass.
#[test]
fn max_duration_fails_the_test_40d8() {
    let mut fb = running(make());
    pass_test(&mut fb, 0);
    fb.bSBT = 0;
    assert_eq!(fb.cycle(1100), SL_OK);
    assert_eq!(fb.nState, SL_STATE_RUN);
    set(&mut fb, 1, 1, 77, 100);
    assert_eq!(fb.cycle(2000), SL_OK);
    assert_eq!(fb.cycle(4999), SL_OK);
    assert_eq!(fb.nState, TESTING);
    assert_eq!(fb.cycle(5000), SL_OK);
    assert_eq!(outs(&fb), (TEST_FAILED, 1, 0, 6));
    assert_eq!(message(&fb), (0xD8, 0x40D8, 0x12, 77));
    fb.bSBT = 0;
    assert_eq!(fb.cycle(5100), SL_OK);
    assert_eq!(outs(&fb), (SL_STATE_SAFE, 0, 0, 6));
}

/// 0x40D9 "The time remaining for the next brake test has expired": MONS-ERROR exactly at
/// the interval, from RUN or SAFE: TestError 1, BrakeValid 0, RemainingTime 0, Par2 =
/// 0x14, Par3 = LatchPosition; left by a new test.
#[test]
fn an_expired_interval_is_mons_error_40d9() {
    let mut fb = running(make());
    pass_test(&mut fb, 0);
    fb.bSBT = 0;
    assert_eq!(fb.cycle(10_999), SL_OK);
    assert_eq!(outs(&fb), (SL_STATE_RUN, 0, 1, 1));
    assert_eq!(fb.cycle(11_000), SL_OK);
    assert_eq!(outs(&fb), (MONS_ERROR, 1, 0, 0));
    assert_eq!(message(&fb), (0xD9, 0x40D9, 0x14, 1000));
    assert_eq!(fb.cycle(20_000), SL_OK);
    assert_eq!(fb.nState, MONS_ERROR);
    pass_test(&mut fb, 21_000);
    assert_eq!(outs(&fb), (TEST_OK, 0, 1, 10));
    // From SAFE too (no test ever passed).
    let mut fb = running(make());
    assert_eq!(fb.cycle(9_999), SL_OK);
    assert_eq!(fb.nState, SL_STATE_SAFE);
    assert_eq!(fb.cycle(10_000), SL_OK);
    assert_eq!(message(&fb), (0xD9, 0x40D9, 0x14, 0));
}

/// An expiry during a test does not interrupt it; after the test ends by SBT falling,
/// the expired interval is MONS-ERROR at once.
#[test]
fn an_expiry_during_a_failed_test_follows_it() {
    let mut fb = running(make());
    set(&mut fb, 1, 1, 0, 0);
    assert_eq!(fb.cycle(9_000), SL_OK);
    assert_eq!(fb.cycle(10_500), SL_OK);
    assert_eq!(outs(&fb), (TESTING, 0, 0, 0));
    assert_eq!(fb.cycle(12_000), SL_OK);
    assert_eq!(fb.nState, TEST_FAILED);
    fb.bSBT = 0;
    assert_eq!(fb.cycle(12_100), SL_OK);
    assert_eq!(outs(&fb), (MONS_ERROR, 1, 0, 0));
}

/// SBT falling during TESTING aborts the test: back to RUN after an earlier pass with time
/// remaining, else SAFE (BT3).
#[test]
fn an_aborted_test_keeps_the_last_result() {
    let mut fb = running(make());
    set(&mut fb, 1, 0, 0, 0);
    assert_eq!(fb.cycle(100), SL_OK);
    fb.bSBT = 0;
    assert_eq!(fb.cycle(200), SL_OK);
    assert_eq!(fb.nState, SL_STATE_SAFE);
    pass_test(&mut fb, 300);
    fb.bSBT = 0;
    assert_eq!(fb.cycle(1400), SL_OK);
    fb.bSBT = 1;
    assert_eq!(fb.cycle(1500), SL_OK);
    assert_eq!(outs(&fb), (TESTING, 0, 0, 10));
    fb.bSBT = 0;
    assert_eq!(fb.cycle(1600), SL_OK);
    assert_eq!(outs(&fb), (SL_STATE_RUN, 0, 1, 10));
}

/// A test starts on the rising edge of SBT only: held TRUE through STOP → run is no start;
/// an invalid byte reads FALSE and is no edge (the byte after it may be).
#[test]
fn a_test_starts_on_the_rising_edge_only() {
    let mut fb = make();
    assert_eq!(fb.init(), SL_OK);
    #[rustfmt::skip]
    run_steps("SBT edge", &mut fb, |f| f.nState, &[
        (0, |f| set(f, 1, 0, 0, 100), SL_OK, None, ""),
        (10, |f| f.bRun = 1, SL_OK, Some(SL_STATE_SAFE), "held TRUE through STOP: no start"),
        (20, |f| f.bSBT = 0, SL_OK, None, ""),
        (30, |f| f.bSBT = 2, SL_E_INVALID_BOOL, Some(SL_STATE_SAFE), "an invalid byte is no rising edge"),
        (40, |f| f.bSBT = 1, SL_OK, Some(TESTING), ""),
    ]);
}

/// MinCurrentIq from the input with bit 10, from nMinCurrentIqFix without; MinDuration 0
/// passes on the first call that meets the condition.
#[test]
fn min_current_input_or_parameter() {
    let mut p = make();
    p.wInputActive = ALL | SL_SBT_ACTIVE_MINCURRENTIQ;
    p.tMinDuration = 0;
    let mut fb = running(p);
    fb.nMinCurrentIq = -5;
    set(&mut fb, 1, 0, 0, -5);
    assert_eq!(fb.cycle(10), SL_OK);
    assert_eq!(fb.nState, TEST_OK);
    let mut p = make();
    p.tMinDuration = 0;
    let mut fb = running(p);
    fb.nMinCurrentIq = -5;
    set(&mut fb, 1, 0, 0, 99);
    assert_eq!(fb.cycle(10), SL_OK);
    assert_eq!(fb.nState, TESTING);
}

/// BT7: parameters at their limits.
#[test]
fn parameters_at_their_limits() {
    let check = |f: &dyn Fn(&mut FB_SBT), rc: i32| {
        let mut fb = make();
        f(&mut fb);
        assert_eq!(fb.init(), rc);
    };
    check(&|_| {}, SL_OK);
    check(&|f| f.tBrakeTestInterval = 0, SL_E_CONFIG);
    check(&|f| f.tBrakeTestInterval = 999, SL_E_CONFIG);
    check(&|f| f.tBrakeTestInterval = 1000, SL_OK);
    check(&|f| f.tBrakeTestInterval = 1500, SL_E_CONFIG);
    check(&|f| f.tBrakeTestInterval = SL_SBT_TIME_MAX, SL_OK);
    check(&|f| f.tBrakeTestInterval = 28_800_000, SL_OK);
    check(&|f| f.tMinDuration = 1050, SL_E_CONFIG);
    check(&|f| f.tMaxDuration = 3050, SL_E_CONFIG);
    check(&|f| f.tMinDuration = 3000, SL_OK);
    check(&|f| f.tMinDuration = 3100, SL_E_CONFIG);
    check(&|f| (f.tMinDuration, f.tMaxDuration) = (0, 0), SL_OK);
    check(&|f| f.tMaxDuration = SL_SBT_TIME_MAX, SL_OK);
    check(&|f| f.tMaxDuration = SL_SBT_TIME_MAX + 100, SL_E_CONFIG);
    check(
        &|f| f.wInputActive = ALL | SL_SBT_ACTIVE_MINCURRENTIQ,
        SL_OK,
    );
    for bit in [0, 1, 8, 9] {
        check(&|f| f.wInputActive = ALL & !(1 << bit), SL_E_CONFIG);
    }
    for bit in [2, 7, 11, 15] {
        check(&|f| f.wInputActive = ALL | 1 << bit, SL_E_CONFIG);
    }
}

/// ERROR and RESET are the library's: a parameter changed while running → ERROR with all
/// outputs 0; RESET → run starts afresh (SAFE, full interval).
#[test]
fn library_error_and_reset() {
    let mut fb = running(make());
    pass_test(&mut fb, 0);
    fb.tMinDuration = 1100;
    assert_eq!(fb.cycle(1100), SL_E_PARAM_CHANGED);
    assert_eq!(outs(&fb), (SL_STATE_ERROR, 0, 0, 0));
    assert_eq!(message(&fb), (SL_DIAG_PARAM_CHANGED, 0, 0, 0));
    fb.tMinDuration = 1000;
    fb.bErrAck = 1;
    assert_eq!(fb.cycle(1200), SL_OK);
    assert_eq!(outs(&fb), (SL_STATE_RESET, 0, 0, 0));
    fb.bErrAck = 0;
    fb.bSBT = 0;
    assert_eq!(fb.cycle(1300), SL_OK);
    assert_eq!(outs(&fb), (SL_STATE_SAFE, 0, 0, 10));
}

/// State names (ABI-2 §11.15 numbers) and diag texts.
#[test]
fn names_and_texts() {
    let t = registry::block_type(SL_TYPE_SBT).unwrap();
    let names = state_names(&t.info);
    assert_eq!(names[..5], CORE_STATE_NAMES);
    assert_eq!(
        names[5..],
        [
            (16, "TESTING"),
            (17, "TEST-OK"),
            (18, "TEST-FAILED"),
            (20, "MONS-ERROR")
        ]
    );
    let mut out = [0u8; 128];
    let n = base::diag::diag_text(&t.info, 0xDA, &mut out);
    assert_eq!(
        std::str::from_utf8(&out[..n]).unwrap(),
        "The single-turn position exceeds the maximum position deviation."
    );
}

/// (state, TestError, BrakeValid, RemainingTime) and (nDiag, Text ID, Par2, Par3).
type Outs = (u8, u8, u8, u32);
type Message = (u16, u16, u32, u32);

/// The model, on absolute times.
#[derive(Default)]
struct Model {
    interval: u64,
    min: u64,
    max: u64,
    dev: u32,
    min_iq: i32,
    state: u8,
    ack: bool,
    sbt: bool,
    last_ok: bool,
    deadline: u64,
    test_start: u64,
    cond_since: Option<u64>,
    latch: u32,
    message: (u16, u32, u32),
}

impl Model {
    fn start(&mut self, now: u64, inp: (bool, bool, bool, u32, i32)) {
        self.last_ok = false;
        self.deadline = now + self.interval;
        self.state = SL_STATE_SAFE;
        self.step(now, inp);
    }

    fn test(&mut self, now: u64, released: bool, pos: u32, iq: i32) -> u8 {
        let cond = !released && iq >= self.min_iq;
        self.cond_since = if cond {
            Some(self.cond_since.unwrap_or(now))
        } else {
            None
        };
        let d = pos.wrapping_sub(self.latch);
        let dev = d.min(d.wrapping_neg());
        if dev > self.dev {
            self.last_ok = false;
            self.message = (0x40DA, dev, self.dev);
            TEST_FAILED
        } else if self.cond_since.is_some_and(|s| now - s >= self.min) {
            self.last_ok = true;
            self.deadline = now + self.interval;
            TEST_OK
        } else if now - self.test_start >= self.max {
            self.last_ok = false;
            self.message = (0x40D8, 0x12, self.latch);
            TEST_FAILED
        } else {
            TESTING
        }
    }

    fn step(&mut self, now: u64, (sbt, rise, released, pos, iq): (bool, bool, bool, u32, i32)) {
        self.state = match self.state {
            TESTING if sbt => self.test(now, released, pos, iq),
            TEST_OK | TEST_FAILED if sbt => self.state,
            _ if rise => {
                self.test_start = now;
                self.latch = pos;
                self.cond_since = None;
                self.test(now, released, pos, iq)
            }
            MONS_ERROR => MONS_ERROR,
            _ if self.deadline <= now => {
                self.last_ok = false;
                self.message = (0x40D9, 0x14, self.latch);
                MONS_ERROR
            }
            _ if self.last_ok => SL_STATE_RUN,
            _ => SL_STATE_SAFE,
        };
    }

    /// One call: (run, ack, changed parameters, now, SBT, SBC In, pos, iq).
    #[allow(clippy::too_many_arguments)]
    fn call(
        &mut self,
        run: bool,
        ack: bool,
        changed: bool,
        now: u64,
        sbt: bool,
        released: bool,
        pos: u32,
        iq: i32,
    ) {
        let rise = sbt && !self.sbt;
        self.sbt = sbt;
        let (ack_rise, ack_fall) = (ack && !self.ack, !ack && self.ack);
        self.ack = ack;
        let inp = (sbt, rise, released, pos, iq);
        let fault = changed && self.state != SL_STATE_STOP && (run || self.state == SL_STATE_ERROR);
        let mut fresh = false;
        if fault && run {
            if self.state != SL_STATE_ERROR {
                fresh = true;
            }
            self.state = SL_STATE_ERROR;
        }
        match self.state {
            SL_STATE_STOP => {
                if run {
                    self.start(now, inp);
                }
            }
            SL_STATE_ERROR => {
                if ack_rise && !fresh && !(fault && run) {
                    self.state = SL_STATE_RESET;
                }
            }
            SL_STATE_RESET => {
                if ack_fall {
                    if run {
                        self.start(now, inp);
                    } else {
                        self.state = SL_STATE_STOP;
                    }
                }
            }
            _ => {
                if run {
                    self.step(now, inp);
                } else {
                    self.state = SL_STATE_STOP;
                }
            }
        }
    }

    fn shown(&self, now: u64) -> (Outs, Message) {
        let s = self.state;
        let failed = s == TEST_FAILED || s == MONS_ERROR;
        let counting = matches!(
            s,
            SL_STATE_RUN | SL_STATE_SAFE | TESTING | TEST_OK | TEST_FAILED
        );
        let remaining = if counting {
            self.deadline.saturating_sub(now).div_ceil(1000) as u32
        } else {
            0
        };
        let valid = u8::from(s == SL_STATE_RUN || s == TEST_OK);
        let message = if failed {
            let (text, p2, p3) = self.message;
            (text - 0x4000, text, p2, p3)
        } else {
            (0, 0, 0, 0)
        };
        ((s, u8::from(failed), valid, remaining), message)
    }
}

/// ≥ 10,000 random sequences against the model; every state and message is reached.
#[test]
fn random_sequences_match_the_model() {
    let mut rng = Rng(0x0000_5B70_0001);
    let mut reached = std::collections::BTreeSet::new();
    let mut texts = std::collections::BTreeSet::new();
    let mut invalid_calls = 0u32;
    for seq in 0..12_000 {
        let r = rng.next();
        let interval = 1000 * (1 + r % 3);
        let min = 100 * ((r >> 4) % 6);
        let max = min + 100 * ((r >> 8) % 8);
        let dev = ((r >> 12) % 20) as u32;
        let min_iq = ((r >> 20) % 5) as i32 - 2;
        let mut fb = common::ready(FB_SBT {
            wInputActive: ALL,
            tBrakeTestInterval: interval as u32,
            tMinDuration: min as u32,
            tMaxDuration: max as u32,
            nMaxPositionDeviation: dev,
            nMinCurrentIqFix: min_iq,
            ..Default::default()
        });
        let mut model = Model {
            interval,
            min,
            max,
            dev,
            min_iq,
            state: SL_STATE_STOP,
            ..Default::default()
        };
        let t0 = rng.next() as u32;
        let mut now = 0u64;
        let mut pos = rng.next() as u32;
        let latched_max = max as u32;
        for step in 0..40 {
            let r = rng.next();
            now += [0, 1, 50, 99, 100, 250][(r % 6) as usize];
            let bit = |k: u32, n: u64| (r >> k) % n == 0;
            let run = !bit(4, 40);
            let ack = bit(10, 3);
            let sbt = !bit(14, 3);
            let released = bit(18, 6);
            if bit(22, 3) {
                pos = pos.wrapping_add(((r >> 26) % 9) as u32).wrapping_sub(4);
            }
            let iq = ((r >> 32) % 5) as i32 - 2;
            let changed = bit(40, 150) || (fb.tMaxDuration != latched_max && !bit(48, 4));
            fb.tMaxDuration = if changed {
                latched_max + 100
            } else {
                latched_max
            };
            let mut raw = [u8::from(sbt), u8::from(released)];
            // One call in 25 has an invalid byte: SBT reads FALSE (no edge), SBC In TRUE.
            let invalid = bit(56, 25).then_some(((r >> 60) % 2) as usize);
            let (sbt, released) = match invalid {
                Some(i) => {
                    raw[i] = 2 + (r >> 8) as u8 % 254;
                    invalid_calls += 1;
                    if i == 0 {
                        (false, released)
                    } else {
                        (sbt, true)
                    }
                }
                None => (sbt, released),
            };
            set(&mut fb, raw[0], raw[1], pos, iq);
            fb.bRun = u8::from(run);
            fb.bErrAck = u8::from(ack);
            fb.cycle(t0.wrapping_add(now as u32));
            // A parameter change seen in STOP → run is latched: the model follows.
            if model.state == SL_STATE_STOP && run {
                model.max = u64::from(fb.tMaxDuration);
            }
            model.call(
                run,
                ack,
                u64::from(fb.tMaxDuration) != model.max,
                now,
                sbt,
                released,
                pos,
                iq,
            );
            assert_eq!(
                (outs(&fb), message(&fb)),
                {
                    let (o, m) = model.shown(now);
                    (o, (m.0 | (fb.nDiag & 0xE000), m.1, m.2, m.3))
                },
                "sequence {seq} step {step}"
            );
            reached.insert(fb.nState);
            texts.insert(fb.nDiagTextId);
        }
    }
    for s in CORE_STATES
        .into_iter()
        .chain([TESTING, TEST_OK, TEST_FAILED, MONS_ERROR])
    {
        assert!(reached.contains(&s), "never reached {s}: {reached:?}");
    }
    for t in [0x40D8, 0x40D9, 0x40DA] {
        assert!(texts.contains(&t), "never showed {t:#x}: {texts:?}");
    }
    assert!(
        invalid_calls > 10_000,
        "{invalid_calls} calls with an invalid byte"
    );
}
