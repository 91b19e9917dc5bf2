//! FB LIMIT (manual §4.21, ABI-2 §11.4, §12; docs/semantics.md L1–L4) in all four integer
//! variants: one test per statement of the manual section, then random sequences against a
//! small model of the block (≥ 10,000 per variant) that assert what they reached.

mod common;

use common::{Rng, CORE_STATES};
use safelogic::blocks::analog::Analog;
use safelogic::*;

const IN: u16 = SL_LIMIT_ACTIVE_ANALOGIN;
const MIN_IN: u16 = SL_LIMIT_ACTIVE_MINVALUE;
const MAX_IN: u16 = SL_LIMIT_ACTIVE_MAXVALUE;

/// The four variants under one roof: values given as `i128`, stored as the variant's type
/// (a wrapper per variant dereferences to the library's struct).
macro_rules! variant {
    ($name:ident, $ty:ty, $t:ty) => {
        crate::common::analog_wrapper!($name, $ty, $t);
        impl $name {
            fn new(active: u16, min: i128, max: i128) -> Self {
                let mut fb = <$ty>::default();
                fb.wInputActive = active;
                fb.nMinimumValue = Self::t(min);
                fb.nMaximumValue = Self::t(max);
                Self(fb)
            }
            fn set_inputs(&mut self, v: i128, min: i128, max: i128) {
                self.0.nAnalogIn = Self::t(v);
                self.0.nMinValue = Self::t(min);
                self.0.nMaxValue = Self::t(max);
            }
            fn outputs(&self) -> Outputs {
                let f = &self.0;
                crate::common::read_outputs!(f {
                    error: f.bError,
                    in_limit: f.bInLimit,
                    below: f.bBelowMin,
                    above: f.bAboveMax,
                })
            }
        }
    };
}

variant!(LInt, FB_LIMIT_INT, i16);
variant!(LUint, FB_LIMIT_UINT, u16);
variant!(LDint, FB_LIMIT_DINT, i32);
variant!(LUdint, FB_LIMIT_UDINT, u32);

common::analog_outputs!(error: u8, in_limit: u8, below: u8, above: u8);

/// The shared test body, instantiated once per variant.
macro_rules! limit_tests {
    ($modname:ident, $v:ident, $t:ty) => {
        mod $modname {
            use super::*;

            type T = $t;
            const LO: i128 = T::MIN as i128;
            const HI: i128 = T::MAX as i128;

            fn pattern(v: i128) -> u32 {
                (v as T).to_bits_for_test()
            }

            fn running(active: u16, min: i128, max: i128, v: i128) -> $v {
                let mut fb = $v::new(active, min, max);
                assert_eq!(fb.init(), SL_OK);
                fb.set_inputs(v, 0, 0);
                fb.control(1, 0);
                assert_eq!(fb.cycle(0), SL_OK);
                fb
            }

            /// §4.21.2 RUN: "greater than or equal to MinValue and less than or equal to
            /// MaxValue": Error=0 InLimit=1 BelowMin=0 AboveMax=0 — both bounds inclusive.
            #[test]
            fn run_within_the_limits_bounds_inclusive() {
                let (min, max) = (LO.max(-100) + 10, HI.min(1000) - 10);
                for v in [min, min + 1, (min + max) / 2, max - 1, max] {
                    let fb = running(IN, min, max, v);
                    let o = fb.outputs();
                    assert_eq!(
                        (o.state, o.error, o.in_limit, o.below, o.above),
                        (1, 0, 1, 0, 0),
                        "{v}"
                    );
                    assert_eq!((o.diag, o.text, o.par), (0, 0, (0, 0)));
                    assert_eq!(fb.state_name(), "RUN");
                }
            }

            /// §4.21.2 SAFE: "AnalogIn is less than MinValue or greater than MaxValue":
            /// InLimit=0 BelowMin=(AnalogIn<MinValue) AboveMax=(AnalogIn>MaxValue).
            #[test]
            fn safe_below_and_above() {
                let (min, max) = (LO.max(-100) + 10, HI.min(1000) - 10);
                for (v, below, above) in [(min - 1, 1, 0), (LO, 1, 0), (max + 1, 0, 1), (HI, 0, 1)]
                {
                    let fb = running(IN, min, max, v);
                    let o = fb.outputs();
                    assert_eq!(
                        (o.state, o.error, o.in_limit, o.below, o.above),
                        (3, 0, 0, below, above),
                        "{v}"
                    );
                    assert_eq!(fb.state_name(), "SAFE");
                }
            }

            /// Both directions are automatic: SAFE → RUN → SAFE without an acknowledgement.
            #[test]
            fn safe_and_run_follow_the_input() {
                let mut fb = running(IN, LO, LO + 5, LO + 6);
                assert_eq!(fb.outputs().state, SL_STATE_SAFE);
                fb.set_inputs(LO + 5, 0, 0);
                assert_eq!(fb.cycle(1), SL_OK);
                assert_eq!(fb.outputs().in_limit, 1);
                fb.set_inputs(LO + 6, 0, 0);
                assert_eq!(fb.cycle(2), SL_OK);
                assert_eq!((fb.outputs().state, fb.outputs().above), (SL_STATE_SAFE, 1));
            }

            /// §4.21.2 STOP: "If the input FbRun=FALSE … Error=0 InLimit=0 BelowMin=0
            /// AboveMax=0".
            #[test]
            fn stop_outputs_false() {
                for v in [LO, HI] {
                    let mut fb = running(IN, LO, HI, v);
                    assert_eq!(fb.outputs().in_limit, 1);
                    fb.control(0, 0);
                    assert_eq!(fb.cycle(1), SL_OK);
                    let o = fb.outputs();
                    assert_eq!(
                        (o.state, o.error, o.in_limit, o.below, o.above),
                        (2, 0, 0, 0, 0)
                    );
                }
            }

            /// §4.21.3 "Either the FB inputs MinValue and MaxValue or the parameters Minimum
            /// Value and Maximum Value can be used. If the FB inputs are active, they are used."
            #[test]
            fn input_or_parameter() {
                // Parameters 10..20, inputs 30..40.
                let mut fb = $v::new(IN, 10, 20);
                assert_eq!(fb.init(), SL_OK);
                fb.control(1, 0);
                fb.set_inputs(35, 30, 40);
                assert_eq!(fb.cycle(0), SL_OK);
                assert_eq!(
                    fb.outputs().above,
                    1,
                    "parameters used while the inputs are inactive"
                );
                for (active, v, inside) in [
                    (IN | MIN_IN | MAX_IN, 35, true),
                    (IN | MIN_IN | MAX_IN, 15, false),
                    (IN | MIN_IN, 15, false), // Min from the input (30) > Max from the parameter (20)
                    (IN | MAX_IN, 35, true),  // Min 10 from the parameter, Max 40 from the input
                    (IN | MAX_IN, 5, false),
                ] {
                    let mut fb = $v::new(active, 10, 20);
                    assert_eq!(fb.init(), SL_OK);
                    fb.control(1, 0);
                    fb.set_inputs(v, 30, 40);
                    assert_eq!(fb.cycle(0), SL_OK);
                    assert_eq!(fb.outputs().in_limit == 1, inside, "{active:#x} {v}");
                }
            }

            /// Diag value 1 "MinValue is greater than MaxValue", message 0x4090 with
            /// Parameter 2 = MinValue, Parameter 3 = MaxValue (ABI-2 §10.4 patterns); the
            /// error remains while Min > Max; then ErrAck → RESET → the limits decide again.
            #[test]
            fn min_above_max_from_inputs_is_error_0x4090() {
                let min = if LO < 0 { -5 } else { 7 };
                let max = min - 1;
                let mut fb = $v::new(IN | MIN_IN | MAX_IN, 0, 0);
                assert_eq!(fb.init(), SL_OK);
                fb.control(1, 0);
                fb.set_inputs(min, min, max);
                assert_eq!(fb.cycle(0), SL_OK);
                let o = fb.outputs();
                assert_eq!(
                    (o.state, o.error, o.in_limit, o.below, o.above),
                    (4, 1, 0, 0, 0)
                );
                assert_eq!(
                    (o.diag, o.text),
                    (SL_DIAG_LIMIT_MIN_ABOVE_MAX, SL_TEXT_LIMIT_MIN_ABOVE_MAX)
                );
                assert_eq!(o.par, (pattern(min), pattern(max)));
                assert!(fb.is_error());
                // ErrAck while Min > Max remains: still ERROR, message kept.
                fb.control(1, 1);
                assert_eq!(fb.cycle(1), SL_OK);
                fb.control(1, 0);
                assert_eq!(fb.cycle(2), SL_OK);
                assert_eq!(fb.outputs(), o);
                // Limits fixed: the ErrAck rising edge → RESET (diag and message cleared) …
                fb.set_inputs(min, min, min);
                fb.control(1, 1);
                assert_eq!(fb.cycle(3), SL_OK);
                let r = fb.outputs();
                assert_eq!(
                    (r.state, r.error, r.in_limit, r.diag, r.text, r.par),
                    (5, 0, 0, 0, 0, (0, 0))
                );
                // … and its falling edge → the limits decide (Min = Max = AnalogIn: RUN).
                fb.control(1, 0);
                assert_eq!(fb.cycle(4), SL_OK);
                assert_eq!((fb.outputs().state, fb.outputs().in_limit), (1, 1));
            }

            /// Min > Max from the parameters alone is a parameter check (ABI-2 §12.8,
            /// semantics L2): SL_E_CONFIG, the block stays in STOP with its outputs FALSE.
            #[test]
            fn min_above_max_from_parameters_is_config() {
                let mut fb = $v::new(IN, 8, 7);
                assert_eq!(fb.init(), SL_E_CONFIG);
                fb.control(1, 0);
                fb.set_inputs(7, 0, 0);
                assert_eq!(fb.cycle(0), SL_E_CONFIG);
                let o = fb.outputs();
                assert_eq!(
                    (o.state, o.error, o.in_limit, o.below, o.above),
                    (2, 0, 0, 0, 0)
                );
                // Equal limits are valid: a one-value window.
                let mut fb = $v::new(IN, 7, 7);
                assert_eq!(fb.init(), SL_OK);
            }

            /// ABI-2 §10.5: AnalogIn (bit 8) is required; bits other than 8–10 are refused.
            #[test]
            fn active_bits() {
                for bad in [
                    0,
                    MIN_IN | MAX_IN,
                    IN | 1,
                    IN | 0x80,
                    IN | 1 << 11,
                    IN | 0x8000,
                ] {
                    let mut fb = $v::new(bad, LO, HI);
                    assert_eq!(fb.init(), SL_E_CONFIG, "{bad:#x}");
                }
                for good in [IN, IN | MIN_IN, IN | MAX_IN, IN | MIN_IN | MAX_IN] {
                    let mut fb = $v::new(good, LO, HI);
                    assert_eq!(fb.init(), SL_OK, "{good:#x}");
                }
            }

            /// ABI §7: a parameter changed while running is SL_E_PARAM_CHANGED → ERROR.
            #[test]
            fn parameter_change_while_running() {
                let mut fb = running(IN, LO, HI, 0.max(LO));
                fb.0.nMaximumValue = $v::t(HI - 1);
                assert_eq!(fb.cycle(1), SL_E_PARAM_CHANGED);
                assert_eq!(
                    (
                        fb.outputs().state,
                        fb.outputs().error,
                        fb.outputs().in_limit
                    ),
                    (4, 1, 0)
                );
            }

            /// The model of one cycle (manual §4.21.2 + the envelope's ABI §7 rules).
            struct Model {
                state: u8,
                ack: bool,
                side: (u8, u8),
                par: (u32, u32),
            }

            impl Model {
                fn classify(&mut self, v: i128, min: i128, max: i128) {
                    if min > max {
                        self.state = SL_STATE_ERROR;
                        self.par = (pattern(min), pattern(max));
                    } else if min <= v && v <= max {
                        self.state = SL_STATE_RUN;
                    } else {
                        self.state = SL_STATE_SAFE;
                        self.side = (u8::from(v < min), u8::from(v > max));
                    }
                }
                fn cycle(&mut self, run: bool, ack: bool, v: i128, min: i128, max: i128) {
                    let (rising, falling) = (ack && !self.ack, !ack && self.ack);
                    self.ack = ack;
                    match self.state {
                        SL_STATE_STOP => {
                            if run {
                                self.classify(v, min, max)
                            }
                        }
                        SL_STATE_ERROR => {
                            if rising && min <= max {
                                self.state = SL_STATE_RESET;
                            }
                        }
                        SL_STATE_RESET => {
                            if falling {
                                if run {
                                    self.classify(v, min, max)
                                } else {
                                    self.state = SL_STATE_STOP
                                }
                            }
                        }
                        _ => {
                            if run {
                                self.classify(v, min, max)
                            } else {
                                self.state = SL_STATE_STOP
                            }
                        }
                    }
                }
                fn outputs(&self) -> Outputs {
                    let s = self.state;
                    let error = s == SL_STATE_ERROR;
                    let safe = s == SL_STATE_SAFE;
                    Outputs {
                        error: u8::from(error),
                        in_limit: u8::from(s == SL_STATE_RUN),
                        below: if safe { self.side.0 } else { 0 },
                        above: if safe { self.side.1 } else { 0 },
                        state: s,
                        diag: if error {
                            SL_DIAG_LIMIT_MIN_ABOVE_MAX
                        } else {
                            0
                        },
                        text: if error {
                            SL_TEXT_LIMIT_MIN_ABOVE_MAX
                        } else {
                            0
                        },
                        par: if error { self.par } else { (0, 0) },
                    }
                }
            }

            fn value(rng: &mut Rng, anchors: &[i128]) -> i128 {
                if rng.next() % 2 == 0 {
                    let a = anchors[(rng.next() % anchors.len() as u64) as usize];
                    (a + (rng.next() % 5) as i128 - 2).clamp(LO, HI)
                } else {
                    LO + (rng.next() as i128).rem_euclid(HI - LO + 1)
                }
            }

            /// ≥ 10,000 random sequences of valid configurations against the model, cycle
            /// by cycle; a labelled share of invalid configurations (Min > Max in the
            /// parameters) checked for SL_E_CONFIG and FALSE outputs. Asserts the reach.
            #[test]
            fn random_sequences_against_the_model() {
                let mut rng = Rng(0x11A1_7000 ^ (HI as u64));
                let (mut reached, mut below, mut above, mut invalid) = (0u32, 0, 0, 0);
                const SEQUENCES: u32 = 12_000;
                for _ in 0..SEQUENCES {
                    let active =
                        IN | [0, MIN_IN, MAX_IN, MIN_IN | MAX_IN][(rng.next() % 4) as usize];
                    let centre = value(&mut rng, &[LO, HI, 0.max(LO), (LO + HI) / 2]);
                    let mut pmin = value(&mut rng, &[centre, LO]);
                    let mut pmax = value(&mut rng, &[centre, HI]);
                    let config_error = active & (MIN_IN | MAX_IN) == 0 && pmin > pmax;
                    if config_error && rng.next() % 8 != 0 {
                        // Mostly valid: swap into order; one in eight stays invalid.
                        (pmin, pmax) = (pmax, pmin);
                    }
                    let invalid_config = active & (MIN_IN | MAX_IN) == 0 && pmin > pmax;
                    let mut fb = $v::new(active, pmin, pmax);
                    let rc = fb.init();
                    if invalid_config {
                        invalid += 1;
                        assert_eq!(rc, SL_E_CONFIG);
                        fb.control(1, 0);
                        fb.set_inputs(centre, pmin, pmax);
                        assert_eq!(fb.cycle(0), SL_E_CONFIG);
                        let o = fb.outputs();
                        assert_eq!(
                            (o.state, o.error, o.in_limit, o.below, o.above),
                            (2, 0, 0, 0, 0)
                        );
                        continue;
                    }
                    assert_eq!(rc, SL_OK);
                    let mut m = Model {
                        state: SL_STATE_STOP,
                        ack: false,
                        side: (0, 0),
                        par: (0, 0),
                    };
                    let (mut imin, mut imax) =
                        (value(&mut rng, &[centre]), value(&mut rng, &[centre]));
                    for t in 0..16u32 {
                        let r = rng.next();
                        let run = r % 8 != 0;
                        let ack = r >> 3 & 3 == 0;
                        if r >> 5 & 3 == 0 {
                            imin = value(&mut rng, &[centre, imax]);
                        }
                        if r >> 7 & 3 == 0 {
                            imax = value(&mut rng, &[centre, imin]);
                        }
                        let v = value(&mut rng, &[centre, imin, imax, pmin, pmax]);
                        fb.control(u8::from(run), u8::from(ack));
                        fb.set_inputs(v, imin, imax);
                        assert_eq!(fb.cycle(t), SL_OK);
                        let min = if active & MIN_IN != 0 { imin } else { pmin };
                        let max = if active & MAX_IN != 0 { imax } else { pmax };
                        m.cycle(run, ack, v, min, max);
                        assert_eq!(
                            fb.outputs(),
                            m.outputs(),
                            "t {t}: v {v} min {min} max {max} active {active:#x}"
                        );
                        reached |= 1 << m.state;
                        below += u32::from(fb.outputs().below);
                        above += u32::from(fb.outputs().above);
                    }
                }
                crate::common::assert_reached(reached.into(), CORE_STATES);
                assert!(
                    below > 1000 && above > 1000,
                    "BelowMin {below}, AboveMax {above}"
                );
                crate::common::assert_invalid_share(invalid, 50, SEQUENCES / 4);
            }
        }
    };
}

/// `to_bits` of the library's field types, as the ABI-2 §10.4 pattern.
trait Bits {
    fn to_bits_for_test(self) -> u32;
}
macro_rules! bits {
    ($($t:ty),*) => {$(impl Bits for $t {
        fn to_bits_for_test(self) -> u32 {
            self as i64 as u32
        }
    })*};
}
bits!(i16, u16, i32, u32);

limit_tests!(int, LInt, i16);
limit_tests!(uint, LUint, u16);
limit_tests!(dint, LDint, i32);
limit_tests!(udint, LUdint, u32);
