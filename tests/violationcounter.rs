//! FB VIOLATIONCOUNTER (manual §4.33, ABI-2 §11.12; docs/semantics.md V1–V4) in its UINT and
//! UDINT variants: one test per statement of the manual section, then random sequences
//! against a small model of the block (≥ 10,000 per variant) that assert what they reached.

mod common;

use common::Rng;
use safelogic::blocks::analog::Analog;
use safelogic::*;

const ACTIVE: u16 = SL_VIOLATIONCOUNTER_ACTIVE;

macro_rules! violation_tests {
    ($modname:ident, $ty:ty, $t:ty) => {
        mod $modname {
            use super::*;

            type Fb = $ty;
            const HI: i128 = <$t as Analog>::MAX;

            fn new(inc: i128, dec: i128, limit: i128, negated: u16) -> Fb {
                let mut fb = Fb::default();
                fb.wInputActive = ACTIVE;
                fb.wInputNegated = negated;
                fb.nIncrementError = inc as $t;
                fb.nDecrementNoError = dec as $t;
                fb.nCounterLimit = limit as $t;
                fb
            }

            /// (InputOK, ActViolationCnt, nState) after one call with Input / Enable.
            fn call(fb: &mut Fb, t: u32, input: u8, enable: u8) -> (u8, i128, u8) {
                (fb.bInput, fb.bEnable) = (input, enable);
                assert_eq!(fb.cycle(t), SL_OK);
                (fb.bInputOK, fb.nActViolationCnt.wide(), fb.nState)
            }

            fn running(inc: i128, dec: i128, limit: i128) -> Fb {
                let mut fb = new(inc, dec, limit, 0);
                assert_eq!(fb.init(), SL_OK);
                fb.bRun = 1;
                fb
            }

            /// Counts once (4 per error), leaves RUN at t=1 through `leave` (which checks the
            /// cleared outputs), then checks the next error counts from 0 (`why`).
            fn left_and_counted_from_zero(leave: impl FnOnce(&mut Fb), why: &str) {
                let mut fb = running(4, 1, 100);
                call(&mut fb, 0, 0, 1);
                leave(&mut fb);
                assert_eq!(call(&mut fb, 2, 0, 1), (1, 4, SL_STATE_RUN), "{why}");
            }

            /// §4.33.1 "If the input is TRUE …, the error counter is decremented by the value
            /// Decrement No Error; if the input is FALSE …, the error counter is incremented
            /// by Increment Error. InputOK is set to FALSE when the error counter reaches the
            /// Counter Limit." — every call, at 0 and the type's maximum saturating (V1).
            #[test]
            fn weighted_counting_and_limit() {
                let mut fb = running(3, 1, 7);
                assert_eq!(call(&mut fb, 0, 0, 1), (1, 3, SL_STATE_RUN));
                assert_eq!(call(&mut fb, 1, 0, 1), (1, 6, SL_STATE_RUN));
                assert_eq!(call(&mut fb, 2, 1, 1), (1, 5, SL_STATE_RUN));
                assert_eq!(call(&mut fb, 3, 0, 1), (0, 8, SL_STATE_SAFE), "8 ≥ 7");
                assert_eq!(
                    call(&mut fb, 4, 1, 1),
                    (0, 7, SL_STATE_SAFE),
                    "reaches the limit: still FALSE"
                );
                assert_eq!(call(&mut fb, 5, 1, 1), (1, 6, SL_STATE_RUN));
                for t in 6..20 {
                    call(&mut fb, t, 1, 1);
                }
                assert_eq!(call(&mut fb, 20, 1, 1), (1, 0, SL_STATE_RUN), "not below 0");
                let mut fb = running(HI - 1, 0, HI);
                call(&mut fb, 0, 0, 1);
                assert_eq!(
                    call(&mut fb, 1, 0, 1),
                    (0, HI, SL_STATE_SAFE),
                    "saturates at the maximum"
                );
                assert_eq!(call(&mut fb, 2, 0, 1), (0, HI, SL_STATE_SAFE));
            }

            /// "Input negated: TRUE - counter is incremented FALSE - counter is decremented".
            #[test]
            fn negated_input() {
                let mut fb = new(2, 1, 100, 1);
                assert_eq!(fb.init(), SL_OK);
                fb.bRun = 1;
                assert_eq!(call(&mut fb, 0, 1, 1).1, 2);
                assert_eq!(call(&mut fb, 1, 0, 1).1, 1);
            }

            /// §4.33.2 START "If the input Enable=FALSE …: InputOK=0 ActViolationCnt = 0";
            /// the counter restarts from 0 (V2).
            #[test]
            fn enable_false_is_start() {
                left_and_counted_from_zero(
                    |fb| {
                        assert_eq!(call(fb, 1, 0, 0), (0, 0, SL_STATE_START));
                        assert_eq!(fb.state_name(), "START");
                    },
                    "from 0, counted at once",
                );
            }

            /// §4.33.2 STOP "If the input FbRun=FALSE …: InputOK=0 ActViolationCnt = 0".
            #[test]
            fn stop() {
                left_and_counted_from_zero(
                    |fb| {
                        fb.bRun = 0;
                        assert_eq!(call(fb, 1, 0, 1), (0, 0, SL_STATE_STOP));
                        fb.bRun = 1;
                    },
                    "a start counts from 0",
                );
            }

            /// ABI-2 §11.12: both inputs active, only Input negatable, Counter Limit 0 refused.
            #[test]
            fn configuration() {
                for (active, negated, limit) in [
                    (1, 0, 5),
                    (2, 0, 5),
                    (7, 0, 5),
                    (3, 2, 5),
                    (3, 0x100, 5),
                    (3, 0, 0),
                ] {
                    let mut fb = new(1, 1, limit, negated);
                    fb.wInputActive = active;
                    assert_eq!(fb.init(), SL_E_CONFIG, "{active:#x} {negated:#x} {limit}");
                    fb.bRun = 1;
                    (fb.bInput, fb.bEnable) = (1, 1);
                    assert_eq!(fb.cycle(0), SL_E_CONFIG);
                    assert_eq!((fb.bInputOK, fb.nState), (0, SL_STATE_STOP));
                }
                let mut fb = new(0, 0, 1, 1);
                assert_eq!(fb.init(), SL_OK, "increments of 0 are valid");
            }

            /// An invalid Input byte is a violation (logical FALSE) whatever its negation; an
            /// invalid Enable reads FALSE (ABI §2).
            #[test]
            fn invalid_bytes() {
                for negated in [0, 1] {
                    let mut fb = new(5, 1, 100, negated);
                    assert_eq!(fb.init(), SL_OK);
                    fb.bRun = 1;
                    (fb.bInput, fb.bEnable) = (2, 1);
                    assert_eq!(fb.cycle(0), SL_E_INVALID_BOOL);
                    assert_eq!(fb.nActViolationCnt.wide(), 5);
                    (fb.bInput, fb.bEnable) = (1 - negated as u8, 0xFF);
                    assert_eq!(fb.cycle(1), SL_E_INVALID_BOOL);
                    assert_eq!((fb.nState, fb.nActViolationCnt.wide()), (SL_STATE_START, 0));
                }
            }

            /// A parameter changed while counting: SL_E_PARAM_CHANGED, ERROR (InputOK FALSE),
            /// acknowledged to RESET and restarted from 0.
            #[test]
            fn library_error_and_acknowledgement() {
                let mut fb = running(2, 1, 100);
                call(&mut fb, 0, 0, 1);
                fb.nCounterLimit = 99;
                (fb.bInput, fb.bEnable) = (0, 1);
                assert_eq!(fb.cycle(1), SL_E_PARAM_CHANGED);
                assert_eq!(
                    (fb.bInputOK, fb.nActViolationCnt.wide(), fb.nState),
                    (0, 0, SL_STATE_ERROR)
                );
                fb.nCounterLimit = 100;
                fb.bErrAck = 1;
                assert_eq!(call(&mut fb, 2, 0, 1), (0, 0, SL_STATE_RESET));
                fb.bErrAck = 0;
                assert_eq!(call(&mut fb, 3, 0, 1), (1, 2, SL_STATE_RUN));
            }

            /// ≥ 10,000 random sequences against the model, cycle by cycle; a labelled share
            /// of invalid configurations (Counter Limit 0, extra bits) checked for SL_E_CONFIG.
            #[test]
            fn random_sequences_against_the_model() {
                let mut rng = Rng(0x51_0C47 ^ (HI as u64));
                let (mut reached, mut saturated, mut invalid) = (0u32, 0, 0);
                const SEQUENCES: u32 = 12_000;
                for _ in 0..SEQUENCES {
                    let r = rng.next();
                    let pick = |rng: &mut Rng| match rng.next() % 4 {
                        0 => (rng.next() % 4) as i128,
                        1 => HI - (rng.next() % 4) as i128,
                        2 => (rng.next() as i128).rem_euclid(HI + 1),
                        _ => (rng.next() % 40) as i128,
                    };
                    let (inc, dec) = (pick(&mut rng), pick(&mut rng));
                    let mut limit = pick(&mut rng);
                    let negated = (r >> 1 & 1) as u16;
                    if r % 16 == 0 {
                        invalid += 1;
                        let mut fb = new(inc, dec, 0, negated);
                        if r >> 4 & 1 == 0 {
                            fb.wInputNegated |= 2;
                            fb.nCounterLimit = 1;
                        }
                        assert_eq!(fb.init(), SL_E_CONFIG);
                        fb.bRun = 1;
                        assert_eq!(fb.cycle(0), SL_E_CONFIG);
                        assert_eq!((fb.bInputOK, fb.nState), (0, SL_STATE_STOP));
                        continue;
                    }
                    limit = limit.max(1);
                    let mut fb = new(inc, dec, limit, negated);
                    assert_eq!(fb.init(), SL_OK);
                    let (mut state, mut count) = (SL_STATE_STOP, 0i128);
                    for t in 0..24u32 {
                        let r = rng.next();
                        let run = r % 12 != 0;
                        let enable = r >> 4 & 7 != 0;
                        let input = r >> 7 & 1 == 1;
                        fb.bRun = u8::from(run);
                        let (ok, act, st) = call(&mut fb, t, u8::from(input), u8::from(enable));
                        // The model.
                        if !run {
                            state = SL_STATE_STOP;
                        } else if !enable {
                            state = SL_STATE_START;
                            count = 0;
                        } else {
                            if state == SL_STATE_STOP {
                                count = 0;
                            }
                            count = if input != (negated == 1) {
                                (count - dec).max(0)
                            } else {
                                (count + inc).min(HI)
                            };
                            state = if count < limit {
                                SL_STATE_RUN
                            } else {
                                SL_STATE_SAFE
                            };
                        }
                        let counting = state == SL_STATE_RUN || state == SL_STATE_SAFE;
                        let want = (
                            u8::from(state == SL_STATE_RUN),
                            if counting { count } else { 0 },
                            state,
                        );
                        assert_eq!(
                            (ok, act, st),
                            want,
                            "t {t} inc {inc} dec {dec} limit {limit} neg {negated}"
                        );
                        reached |= 1 << st;
                        saturated += u32::from(counting && count == HI);
                    }
                }
                crate::common::assert_reached(
                    reached.into(),
                    [SL_STATE_RUN, SL_STATE_STOP, SL_STATE_SAFE, SL_STATE_START],
                );
                assert!(
                    saturated > 100,
                    "saturation at the maximum reached {saturated} times"
                );
                crate::common::assert_invalid_share(invalid, 300, SEQUENCES / 8);
            }
        }
    };
}

violation_tests!(uint, FB_VIOLATIONCOUNTER_UINT, u16);
violation_tests!(udint, FB_VIOLATIONCOUNTER_UDINT, u32);
