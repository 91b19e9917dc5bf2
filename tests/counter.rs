//! FB COUNTER (manual §4.22, ABI-2 §11.5, §12; docs/semantics.md K1–K4) in all four integer
//! variants: one test per statement of the manual section, then random sequences against a
//! small model of the block (≥ 10,000 per variant) that assert what they reached.

mod common;

use common::Rng;
use safelogic::blocks::analog::Analog;
use safelogic::*;

const ALL: u16 = SL_COUNTER_ACTIVE_INPUTS;

common::analog_outputs!(error: u8, out: u8, zero: u8, act: i128);

macro_rules! counter_tests {
    ($modname:ident, $ty:ty, $t:ty) => {
        mod $modname {
            use super::*;

            type Fb = $ty;
            crate::common::analog_bounds!($t);

            fn pattern(v: i128) -> u32 {
                t(v) as i64 as u32
            }

            fn new(active: u16, preset: i128, limit: i128) -> Fb {
                let mut fb = Fb::default();
                fb.wInputActive = active;
                fb.nPresetValue = t(preset);
                fb.nCounterLimit = t(limit);
                assert_eq!(
                    fb.init(),
                    if active & !ALL == 0 {
                        SL_OK
                    } else {
                        SL_E_CONFIG
                    }
                );
                fb
            }

            fn outputs(f: &Fb) -> Outputs {
                crate::common::read_outputs!(f {
                    error: f.bError,
                    out: f.bCounterOut,
                    zero: f.bCounterZero,
                    act: f.nActValue.wide(),
                })
            }

            /// Drives the inputs for one cycle.
            fn step(fb: &mut Fb, t: u32, (reset, up, down): (u8, u8, u8)) -> i32 {
                (fb.bReset, fb.bCountUp, fb.bCountDown) = (reset, up, down);
                fb.cycle(t)
            }

            /// A block running from 0 (Reset FALSE at the start).
            fn running(preset: i128, limit: i128) -> Fb {
                let mut fb = new(ALL, preset, limit);
                fb.bRun = 1;
                assert_eq!(step(&mut fb, 0, (0, 0, 0)), SL_OK);
                assert_eq!((fb.nState, fb.nActValue.wide()), (SL_STATE_RUN, 0));
                fb
            }

            /// Counts `n` rising edges of CountUp (n > 0) or CountDown (n < 0).
            fn count(fb: &mut Fb, t: &mut u32, n: i128) {
                let pulse = if n > 0 { (0, 1, 0) } else { (0, 0, 1) };
                for _ in 0..n.abs() {
                    *t += 1;
                    assert_eq!(step(fb, *t, pulse), SL_OK);
                    *t += 1;
                    assert_eq!(step(fb, *t, (0, 0, 0)), SL_OK);
                }
            }

            /// §4.22.1 "A logical 1 signal at the input Reset causes the internal counter
            /// value to be set to the value that is parameterized via Preset Value": a level,
            /// edges do not count while it is TRUE.
            #[test]
            fn reset_sets_the_preset_while_true() {
                let preset = if LO < 0 { -7 } else { 7 };
                let mut fb = running(preset, 100);
                assert_eq!(step(&mut fb, 1, (1, 0, 0)), SL_OK);
                assert_eq!(fb.nActValue.wide(), preset);
                assert_eq!(step(&mut fb, 2, (1, 1, 0)), SL_OK);
                assert_eq!(fb.nActValue.wide(), preset, "Reset TRUE dominates CountUp");
                assert_eq!(step(&mut fb, 3, (0, 0, 0)), SL_OK);
                assert_eq!(step(&mut fb, 4, (0, 1, 0)), SL_OK);
                assert_eq!(fb.nActValue.wide(), preset + 1);
            }

            /// §4.22.2 RUN: "increments … if a rising edge is detected at the input CountUp
            /// and decrements it if a rising edge is detected at the input CountDown (this
            /// means that ActValue remains unchanged if both … detect a rising edge)".
            #[test]
            fn edges_count_levels_do_not() {
                let mut fb = running(0, 100);
                let mut t = 0;
                count(&mut fb, &mut t, 3);
                assert_eq!(fb.nActValue.wide(), 3);
                // A held TRUE is one edge only.
                for _ in 0..5 {
                    t += 1;
                    step(&mut fb, t, (0, 1, 0));
                }
                assert_eq!(fb.nActValue.wide(), 4);
                step(&mut fb, t + 1, (0, 0, 0));
                count(&mut fb, &mut t, -2);
                assert_eq!(fb.nActValue.wide(), 2);
                // Both rising in one cycle: unchanged.
                step(&mut fb, t + 10, (0, 1, 1));
                assert_eq!(fb.nActValue.wide(), 2);
            }

            /// §4.22.2 "CounterOut = (ActValue >= CounterLimit) CounterZero = (ActValue == 0)".
            #[test]
            fn counter_out_and_zero() {
                let mut fb = running(0, 3);
                assert_eq!((fb.bCounterOut, fb.bCounterZero), (0, 1));
                let mut t = 0;
                count(&mut fb, &mut t, 2);
                assert_eq!((fb.bCounterOut, fb.bCounterZero), (0, 0));
                count(&mut fb, &mut t, 1);
                assert_eq!((fb.bCounterOut, fb.bCounterZero), (1, 0));
                count(&mut fb, &mut t, 1);
                assert_eq!(fb.bCounterOut, 1, "above the limit");
                let mut fb = running(0, 0);
                assert_eq!(
                    (fb.bCounterOut, fb.bCounterZero),
                    (1, 1),
                    "limit 0 reached at 0"
                );
                if LO < 0 {
                    let mut t = 0;
                    count(&mut fb, &mut t, -1);
                    assert_eq!(
                        (fb.nActValue.wide(), fb.bCounterOut, fb.bCounterZero),
                        (-1, 0, 0)
                    );
                }
            }

            /// §4.22.2 ERROR "checking the value range …": Error=1 CounterOut=0 CounterZero=0
            /// ActValue=0; diag 2 / 0x40B9 above the maximum (Par 2 ActValue, Par 3 the
            /// largest value); the error is an event: the next ErrAck edge acknowledges.
            #[test]
            fn overflow_is_error_0x40b9() {
                let mut fb = running(HI, HI);
                assert_eq!(step(&mut fb, 1, (1, 0, 0)), SL_OK);
                assert_eq!(step(&mut fb, 2, (0, 0, 0)), SL_OK);
                assert_eq!((fb.nActValue.wide(), fb.bCounterOut), (HI, 1));
                assert_eq!(step(&mut fb, 3, (0, 1, 0)), SL_OK);
                let o = outputs(&fb);
                assert_eq!(
                    (o.state, o.error, o.out, o.zero, o.act),
                    (SL_STATE_ERROR, 1, 0, 0, 0)
                );
                assert_eq!(
                    (o.diag, o.text),
                    (SL_DIAG_VALUE_OVERFLOW, SL_TEXT_COUNTER_OVERFLOW)
                );
                assert_eq!(o.par, (pattern(HI), pattern(HI)));
                // ErrAck rising → RESET (all 0, message cleared), falling → RUN from 0.
                fb.bErrAck = 1;
                assert_eq!(step(&mut fb, 4, (0, 0, 0)), SL_OK);
                let r = outputs(&fb);
                assert_eq!(
                    (r.state, r.error, r.act, r.diag, r.text, r.par),
                    (SL_STATE_RESET, 0, 0, 0, 0, (0, 0))
                );
                fb.bErrAck = 0;
                assert_eq!(step(&mut fb, 5, (0, 0, 0)), SL_OK);
                assert_eq!(
                    (fb.nState, fb.nActValue.wide(), fb.bCounterZero),
                    (SL_STATE_RUN, 0, 1)
                );
            }

            /// Diag 1 / 0x40B8 below the minimum (UINT/UDINT: below 0).
            #[test]
            fn underflow_is_error_0x40b8() {
                let mut fb = running(LO, 0);
                assert_eq!(step(&mut fb, 1, (1, 0, 0)), SL_OK);
                assert_eq!(step(&mut fb, 2, (0, 0, 0)), SL_OK);
                assert_eq!(fb.nActValue.wide(), LO);
                assert_eq!(step(&mut fb, 3, (0, 0, 1)), SL_OK);
                let o = outputs(&fb);
                assert_eq!((o.state, o.error, o.act), (SL_STATE_ERROR, 1, 0));
                assert_eq!(
                    (o.diag, o.text),
                    (SL_DIAG_VALUE_UNDERFLOW, SL_TEXT_COUNTER_UNDERFLOW)
                );
                assert_eq!(o.par, (pattern(LO), pattern(LO)));
                assert!(fb.is_error());
            }

            /// §4.22.1 "If the TwinSAFE group is started (Run=1) and the Reset input is TRUE,
            /// the output ActValue is set to PresetValue. When the group is stopped, ActValue
            /// is set to 0." Started with Reset FALSE: 0 (semantics K2).
            #[test]
            fn start_and_stop_values() {
                let mut fb = running(5, 100);
                let mut t = 0;
                count(&mut fb, &mut t, 2);
                fb.bRun = 0;
                assert_eq!(step(&mut fb, 100, (0, 0, 0)), SL_OK);
                let o = outputs(&fb);
                assert_eq!(
                    (o.state, o.error, o.out, o.zero, o.act),
                    (SL_STATE_STOP, 0, 0, 0, 0)
                );
                fb.bRun = 1;
                assert_eq!(step(&mut fb, 101, (1, 0, 0)), SL_OK);
                assert_eq!((fb.nState, fb.nActValue.wide()), (SL_STATE_RUN, 5));
                fb.bRun = 0;
                step(&mut fb, 102, (0, 0, 0));
                fb.bRun = 1;
                assert_eq!(step(&mut fb, 103, (0, 0, 0)), SL_OK);
                assert_eq!(fb.nActValue.wide(), 0);
            }

            /// ABI-2 §11.5 "An input already TRUE at that call is not an edge".
            #[test]
            fn input_true_at_the_start_is_no_edge() {
                let mut fb = new(ALL, 0, 100);
                fb.bRun = 1;
                assert_eq!(step(&mut fb, 0, (0, 1, 0)), SL_OK);
                assert_eq!(fb.nActValue.wide(), 0);
                assert_eq!(step(&mut fb, 1, (0, 1, 0)), SL_OK);
                assert_eq!(fb.nActValue.wide(), 0, "held, no edge");
                step(&mut fb, 2, (0, 0, 0));
                step(&mut fb, 3, (0, 1, 0));
                assert_eq!(fb.nActValue.wide(), 1);
            }

            /// ABI-2 §11.5: bits 0–2 only; an inactive input reads FALSE.
            #[test]
            fn active_bits_and_inactive_inputs() {
                for bad in [1 << 3, 0x100, 0x8000 | 1] {
                    new(bad, 0, 1);
                }
                let mut fb = new(0b010, 9, 100); // CountUp only
                fb.bRun = 1;
                assert_eq!(step(&mut fb, 0, (1, 0, 0)), SL_OK);
                assert_eq!(fb.nActValue.wide(), 0, "inactive Reset reads FALSE");
                step(&mut fb, 1, (1, 1, 1));
                assert_eq!(fb.nActValue.wide(), 1, "inactive CountDown reads FALSE");
            }

            /// ABI §2, ABI-2 §12.7: an invalid byte reads FALSE, makes no edge, and the call
            /// returns SL_E_INVALID_BOOL.
            #[test]
            fn invalid_bytes() {
                let mut fb = running(3, 100);
                assert_eq!(step(&mut fb, 1, (0, 2, 0)), SL_E_INVALID_BOOL);
                assert_eq!(fb.nActValue.wide(), 0);
                assert_eq!(step(&mut fb, 2, (0xFF, 0, 0)), SL_E_INVALID_BOOL);
                assert_eq!(fb.nActValue.wide(), 0, "an invalid Reset is no Reset");
                assert_eq!(step(&mut fb, 3, (0, 1, 0)), SL_OK);
                assert_eq!(fb.nActValue.wide(), 1);
            }

            /// The model of one cycle (manual §4.22.2 + the envelope's ABI §7 rules).
            struct Model {
                state: u8,
                count: i128,
                prev: (bool, bool, bool),
                par: (u32, u32),
                diag: u16,
            }

            impl Model {
                fn cycle(
                    &mut self,
                    run: bool,
                    ack: bool,
                    (reset, up, down): (bool, bool, bool),
                    preset: i128,
                ) {
                    let rising_up = up && !self.prev.0;
                    let rising_down = down && !self.prev.1;
                    let (ack_rising, ack_falling) = (ack && !self.prev.2, !ack && self.prev.2);
                    self.prev = (up, down, ack);
                    let start = |m: &mut Model| {
                        m.count = if reset { preset } else { 0 };
                        m.state = SL_STATE_RUN;
                    };
                    match self.state {
                        SL_STATE_STOP if run => start(self),
                        SL_STATE_STOP => {}
                        SL_STATE_ERROR => {
                            if ack_rising {
                                self.state = SL_STATE_RESET;
                            }
                        }
                        SL_STATE_RESET => {
                            if ack_falling {
                                if run {
                                    start(self)
                                } else {
                                    self.state = SL_STATE_STOP
                                }
                            }
                        }
                        _ if !run => self.state = SL_STATE_STOP,
                        _ => {
                            let next = if reset {
                                preset
                            } else {
                                self.count + i128::from(rising_up) - i128::from(rising_down)
                            };
                            if !(LO..=HI).contains(&next) {
                                let bound = if next < LO { LO } else { HI };
                                self.par = (pattern(self.count), pattern(bound));
                                self.diag = if next < LO { 1 } else { 2 };
                                self.count = 0;
                                self.state = SL_STATE_ERROR;
                            } else {
                                self.count = next;
                            }
                        }
                    }
                }
                fn outputs(&self, limit: i128) -> Outputs {
                    let run = self.state == SL_STATE_RUN;
                    let error = self.state == SL_STATE_ERROR;
                    Outputs {
                        error: u8::from(error),
                        out: u8::from(run && self.count >= limit),
                        zero: u8::from(run && self.count == 0),
                        act: if run { self.count } else { 0 },
                        state: self.state,
                        diag: if error { self.diag } else { 0 },
                        text: if error { 0x40B7 + self.diag } else { 0 },
                        par: if error { self.par } else { (0, 0) },
                    }
                }
            }

            /// ≥ 10,000 random sequences of valid configurations against the model, cycle by
            /// cycle (presets and limits near the ends of the range so that both range errors
            /// happen); a labelled share of invalid active masks checked for SL_E_CONFIG.
            #[test]
            fn random_sequences_against_the_model() {
                let mut rng = Rng(0xC0C0_0001 ^ (HI as u64));
                let (mut reached, mut out, mut zero, mut diags, mut invalid) = (0u32, 0, 0, 0u8, 0);
                const SEQUENCES: u32 = 12_000;
                for _ in 0..SEQUENCES {
                    let r = rng.next();
                    if r % 16 == 0 {
                        // The invalid share: a bit beyond 0–2.
                        invalid += 1;
                        let mut fb = new(ALL | 8 << (r >> 4 & 7), 0, 0);
                        fb.bRun = 1;
                        assert_eq!(step(&mut fb, 0, (0, 1, 0)), SL_E_CONFIG);
                        assert_eq!(outputs(&fb).state, SL_STATE_STOP);
                        assert_eq!((fb.bCounterOut, fb.bCounterZero, fb.bError), (0, 0, 0));
                        continue;
                    }
                    let active = if r >> 8 & 3 == 0 {
                        (r >> 10 & 7) as u16
                    } else {
                        ALL
                    };
                    let near = |rng: &mut Rng| {
                        let anchors = [LO, HI, 0, 1, LO + 2, HI - 2];
                        let a = anchors[(rng.next() % 6) as usize];
                        (a + (rng.next() % 5) as i128 - 2).clamp(LO, HI)
                    };
                    let preset = near(&mut rng);
                    let limit = near(&mut rng);
                    let mut fb = new(active, preset, limit);
                    let mut m = Model {
                        state: SL_STATE_STOP,
                        count: 0,
                        prev: (false, false, false),
                        par: (0, 0),
                        diag: 0,
                    };
                    for t in 0..24u32 {
                        let r = rng.next();
                        let run = r % 10 != 0;
                        let ack = r >> 4 & 7 == 0;
                        let raw = (
                            (r >> 8 & 15 == 0) as u8,
                            (r >> 12 & 1) as u8,
                            (r >> 13 & 1) as u8,
                        );
                        fb.bRun = u8::from(run);
                        fb.bErrAck = u8::from(ack);
                        assert_eq!(step(&mut fb, t, raw), SL_OK);
                        let level = |bit: u16, v: u8| active & bit != 0 && v == 1;
                        m.cycle(
                            run,
                            ack,
                            (level(1, raw.0), level(2, raw.1), level(4, raw.2)),
                            preset,
                        );
                        let o = outputs(&fb);
                        assert_eq!(
                            o,
                            m.outputs(limit),
                            "t {t} preset {preset} limit {limit} active {active:#x}"
                        );
                        reached |= 1 << o.state;
                        out += u32::from(o.out);
                        zero += u32::from(o.zero);
                        if o.state == SL_STATE_ERROR {
                            diags |= 1 << o.diag;
                        }
                    }
                }
                crate::common::assert_reached(
                    reached.into(),
                    [SL_STATE_RUN, SL_STATE_STOP, SL_STATE_ERROR, SL_STATE_RESET],
                );
                assert_eq!(diags, 0b110, "both range errors reached");
                assert!(
                    out > 1000 && zero > 1000,
                    "CounterOut {out}, CounterZero {zero}"
                );
                crate::common::assert_invalid_share(invalid, 300, SEQUENCES / 8);
            }
        }
    };
}

counter_tests!(int, FB_COUNTER_INT, i16);
counter_tests!(uint, FB_COUNTER_UINT, u16);
counter_tests!(dint, FB_COUNTER_DINT, i32);
counter_tests!(udint, FB_COUNTER_UDINT, u32);

/// C3 (semantics): the latched parameter copy is verified where the outputs start to carry
/// values. A copy corrupted while the block is in ERROR — the live field changed alike, so
/// the live/latched comparison cannot see it — is found when the acknowledgement restarts
/// the block (RESET → RUN needs no new latch): ERROR with diag bit 15, outputs FALSE.
#[test]
fn corrupted_latched_copy_is_found_when_the_acknowledgement_restarts() {
    let mut fb = common::ready(FB_COUNTER_INT {
        wInputActive: ALL,
        nPresetValue: 5,
        nCounterLimit: 10,
        ..Default::default()
    });
    fb.bRun = 1;
    assert_eq!(fb.cycle(100), SL_OK);
    assert_eq!(fb.nState, SL_STATE_RUN);
    assert_eq!(fb.cycle(90), SL_E_CLOCK);
    assert_eq!(fb.nState, SL_STATE_ERROR);
    fb.stPrivate.adwParam[0] ^= 1;
    fb.nPresetValue ^= 1;
    fb.bErrAck = 1;
    assert_eq!(fb.cycle(91), SL_OK);
    assert_eq!(fb.nState, SL_STATE_RESET);
    fb.bErrAck = 0;
    fb.cycle(92);
    assert_eq!(
        fb.nState, SL_STATE_ERROR,
        "the stale CRC is found at the restart"
    );
    assert_eq!(fb.nDiag & SL_DIAG_CORRUPT, SL_DIAG_CORRUPT);
    assert_eq!((fb.bError, fb.bCounterOut), (1, 0));
}
