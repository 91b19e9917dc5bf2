//! FB SCALE (manual §4.23, ABI-2 §11.6, §12; docs/semantics.md SC1–SC5) in all four integer
//! variants: one test per statement of the manual section, then random sequences against a
//! small model of the block (≥ 10,000 per variant) that assert what they reached.

mod common;

use common::Rng;
use safelogic::base::block::FieldType;
use safelogic::blocks::analog::Analog;
use safelogic::*;

const IN: u16 = SL_SCALE_ACTIVE_ANALOGIN;
const NEG: u16 = SL_SCALE_NEGATE_ANALOGIN;
const DIV_FIRST: u32 = SL_OPT_SCALE_DIVISION_FIRST;

common::analog_outputs!(error: u8, stuck: u8, out: i128);

/// The parameters of one configuration, exact.
#[derive(Clone, Copy, Debug)]
struct Config {
    num: i128,
    den: i128,
    off: i128,
    rounding: u16,
    div_first: bool,
    negate: bool,
    watchdog: u32,
}

const PLAIN: Config = Config {
    num: 1,
    den: 1,
    off: 0,
    rounding: SL_ROUNDING_FLOOR,
    div_first: false,
    negate: false,
    watchdog: 0,
};

/// `a / b` rounded, written independently of the library: floor through Euclidean
/// division, ceil as −floor(−a/b), round half away from zero on the magnitudes.
fn rounded(a: i128, b: i128, rounding: u16) -> i128 {
    let floor = |a: i128, b: i128| {
        if b < 0 {
            (-a).div_euclid(-b)
        } else {
            a.div_euclid(b)
        }
    };
    match rounding {
        SL_ROUNDING_FLOOR => floor(a, b),
        SL_ROUNDING_CEIL => -floor(-a, b),
        _ => {
            let m = (2 * a.abs() + b.abs()) / (2 * b.abs());
            if (a < 0) != (b < 0) {
                -m
            } else {
                m
            }
        }
    }
}

/// The manual's processing order (§4.23.2 AnalogOut), exact, with the diag value of the
/// first step that leaves its range: T32 for negation, product and quotient, the type of
/// the signal for the result.
fn model_scale(
    x: i128,
    c: &Config,
    (lo, hi): (i128, i128),
    (lo32, hi32): (i128, i128),
) -> Result<i128, u16> {
    let t32 = |v: i128, d: u16| {
        if (lo32..=hi32).contains(&v) {
            Ok(v)
        } else {
            Err(d)
        }
    };
    let x = if !c.negate {
        x
    } else if lo < 0 {
        t32(-x, 3)?
    } else {
        x ^ hi
    };
    let v = if c.div_first {
        t32(t32(rounded(x, c.den, c.rounding), 4)? * c.num, 3)?
    } else {
        t32(rounded(t32(x * c.num, 3)?, c.den, c.rounding), 4)?
    };
    let y = v + c.off;
    if y < lo {
        Err(1)
    } else if y > hi {
        Err(2)
    } else {
        Ok(y)
    }
}

macro_rules! scale_tests {
    ($modname:ident, $ty:ty, $t:ty, $t32:ty) => {
        mod $modname {
            use super::*;

            type Fb = $ty;
            crate::common::analog_bounds!($t);
            const LO32: i128 = <$t32 as Analog>::MIN;
            const HI32: i128 = <$t32 as Analog>::MAX;
            const SIGNED: bool = LO < 0;

            fn t32(v: i128) -> $t32 {
                <$t32 as Analog>::narrow(v.clamp(LO32, HI32))
            }
            fn pattern(v: i128) -> u32 {
                t(v).to_bits()
            }

            fn configure(c: &Config) -> Fb {
                let mut fb = Fb::default();
                fb.wInputActive = IN;
                fb.wInputNegated = if c.negate { NEG } else { 0 };
                fb.dwOptions = if c.div_first { DIV_FIRST } else { 0 };
                fb.nNumerator = t32(c.num);
                fb.nDenominator = t32(c.den);
                fb.nOffset = t32(c.off);
                fb.nRounding = c.rounding;
                fb.tWatchdog = c.watchdog;
                fb
            }

            fn new(c: &Config) -> Fb {
                let mut fb = configure(c);
                assert_eq!(fb.init(), SL_OK);
                fb
            }

            fn outputs(f: &Fb) -> Outputs {
                crate::common::read_outputs!(f {
                    error: f.bError,
                    stuck: f.bStuckAtError,
                    out: f.nAnalogOut.wide(),
                })
            }

            fn step(fb: &mut Fb, now: u32, x: i128) -> i32 {
                fb.nAnalogIn = t(x);
                fb.cycle(now)
            }

            /// A block started at `now` with AnalogIn `x`.
            fn running_at(c: &Config, now: u32, x: i128) -> Fb {
                let mut fb = new(c);
                fb.bRun = 1;
                assert_eq!(step(&mut fb, now, x), SL_OK);
                fb
            }

            /// One value through a fresh block: its output in RUN or its diag value.
            fn scaled(c: &Config, x: i128) -> Result<i128, u16> {
                let fb = running_at(c, 0, x);
                let o = outputs(&fb);
                if o.state == SL_STATE_RUN {
                    assert_eq!((o.error, o.diag, o.text, o.par), (0, 0, 0, (0, 0)));
                    Ok(o.out)
                } else {
                    assert_eq!(
                        (o.state, o.error, o.out, o.stuck),
                        (SL_STATE_ERROR, 1, 0, 0)
                    );
                    assert_eq!(o.text, 0x40AF + o.diag, "Text ID of diag value {}", o.diag);
                    assert_eq!(o.par, (pattern(x), 0), "Par2 AnalogIn, Par3 '-'");
                    Err(o.diag)
                }
            }

            /// §4.23.1 "multiply the AnalogIn input with the scaling factor and then
            /// divided before the scaling offset is added"; "Multiplication First …
            /// multiplication (TRUE) or division (FALSE)" (default: multiplication first).
            #[test]
            fn multiplication_first_then_division_then_offset() {
                let c = Config {
                    num: 3,
                    den: 4,
                    off: 5,
                    ..PLAIN
                };
                assert_eq!(scaled(&c, 10), Ok(12), "10·3 = 30, 30÷4 = 7.5 → 7, +5");
                let d = Config {
                    div_first: true,
                    ..c
                };
                assert_eq!(scaled(&d, 10), Ok(11), "10÷4 = 2.5 → 2, ·3 = 6, +5");
                assert_eq!(scaled(&PLAIN, HI), Ok(HI));
                assert_eq!(scaled(&PLAIN, LO), Ok(LO));
                assert_eq!(
                    scaled(
                        &Config {
                            num: 0,
                            off: 7,
                            ..PLAIN
                        },
                        HI
                    ),
                    Ok(7)
                );
            }

            /// §4.23.1 Division Rounding "Floor: Decimal places are truncated; Ceil: The
            /// next higher integer; Round: Commercial rounding (e.g. 2.5 is rounded to 3)";
            /// negative quotients floor/ceil/half away from zero (semantics A2, SC1).
            #[test]
            fn division_rounding() {
                for (rounding, up, half) in [
                    (SL_ROUNDING_FLOOR, 7, 7),
                    (SL_ROUNDING_CEIL, 8, 8),
                    (SL_ROUNDING_ROUND, 8, 8),
                ] {
                    let c = Config {
                        num: 3,
                        den: 4,
                        rounding,
                        ..PLAIN
                    };
                    assert_eq!(scaled(&c, 10), Ok(up), "7.5, rounding {rounding}");
                    assert_eq!(
                        scaled(
                            &Config {
                                num: 1,
                                den: 2,
                                ..c
                            },
                            15
                        ),
                        Ok(half)
                    );
                    assert_eq!(
                        scaled(
                            &Config {
                                num: 1,
                                den: 3,
                                ..c
                            },
                            21
                        ),
                        Ok(7),
                        "exact"
                    );
                }
                let round = Config {
                    num: 1,
                    den: 4,
                    rounding: SL_ROUNDING_ROUND,
                    ..PLAIN
                };
                assert_eq!(scaled(&round, 9), Ok(2), "2.25 → 2");
                assert_eq!(scaled(&round, 10), Ok(3), "2.5 → 3");
                if SIGNED {
                    for (rounding, v) in [
                        (SL_ROUNDING_FLOOR, -8),
                        (SL_ROUNDING_CEIL, -7),
                        (SL_ROUNDING_ROUND, -8),
                    ] {
                        let c = Config {
                            num: 3,
                            den: 4,
                            rounding,
                            ..PLAIN
                        };
                        assert_eq!(scaled(&c, -10), Ok(v), "−7.5, rounding {rounding}");
                        let neg_den = Config {
                            num: -3,
                            den: -4,
                            ..c
                        };
                        assert_eq!(scaled(&neg_den, -10), Ok(v), "−30 ÷ … the same quotient");
                    }
                    let c = Config {
                        num: 1,
                        den: 4,
                        rounding: SL_ROUNDING_ROUND,
                        ..PLAIN
                    };
                    assert_eq!(scaled(&c, -9), Ok(-2), "−2.25 → −2");
                }
            }

            /// §4.23.1 "The AnalogIn input can be negated. For data types INT16 and INT32
            /// this corresponds to multiplication with -1, for data types UINT16 and UINT32
            /// it corresponds to an XOR function with 0xFFFF or 0xFFFFFFFF" — before the
            /// multiplication ("Processing order: AnalogIn negation …").
            #[test]
            fn negation() {
                let c = Config {
                    negate: true,
                    num: 2,
                    ..PLAIN
                };
                if SIGNED {
                    assert_eq!(scaled(&c, 5), Ok(-10));
                    assert_eq!(scaled(&c, -5), Ok(10));
                    assert_eq!(scaled(&Config { num: 1, ..c }, HI), Ok(-HI));
                } else {
                    assert_eq!(
                        scaled(&Config { num: 1, ..c }, 5),
                        Ok(HI - 5),
                        "XOR all ones"
                    );
                    assert_eq!(scaled(&Config { num: 1, ..c }, 0), Ok(HI));
                    assert_eq!(scaled(&Config { num: 1, ..c }, HI), Ok(0));
                }
            }

            /// Negating the smallest signed value: INT gives +32768 (in T32, then AnalogOut
            /// overflow, diag 2); DINT leaves T32 at the "multiplication with -1" (diag 3).
            #[test]
            fn negation_of_the_smallest_value() {
                if !SIGNED {
                    return;
                }
                let c = Config {
                    negate: true,
                    ..PLAIN
                };
                let expected = if HI < HI32 {
                    SL_DIAG_VALUE_OVERFLOW
                } else {
                    SL_DIAG_SCALE_MUL_OVERFLOW
                };
                assert_eq!(scaled(&c, LO), Err(expected));
                let halved = Config {
                    negate: true,
                    den: 2,
                    ..PLAIN
                };
                if HI < HI32 {
                    assert_eq!(scaled(&halved, LO), Ok(-(LO / 2)), "32768 ÷ 2 fits");
                }
            }

            /// §4.23.2 diag 3 / 0x40B2 "A 32-bit overflow occurred during the
            /// multiplication" (Par2 AnalogIn): a product at the end of T32 passes, one
            /// beyond it is diag 3, in either order of the operations.
            #[test]
            fn multiplication_overflow_is_diag_3() {
                let at = Config {
                    num: HI32,
                    den: HI32,
                    ..PLAIN
                };
                assert_eq!(scaled(&at, 1), Ok(1), "1 · MAX32 fits");
                assert_eq!(scaled(&at, 2), Err(SL_DIAG_SCALE_MUL_OVERFLOW));
                if SIGNED {
                    let low = Config {
                        num: LO32 / 2,
                        den: LO32,
                        ..PLAIN
                    };
                    assert_eq!(scaled(&low, 2), Ok(1), "2 · MIN32/2 = MIN32 fits");
                    assert_eq!(scaled(&low, 3), Err(SL_DIAG_SCALE_MUL_OVERFLOW));
                }
                // Division first: the quotient is multiplied.
                let d = Config {
                    div_first: true,
                    num: HI32,
                    den: 2,
                    ..PLAIN
                };
                let one = if HI == HI32 {
                    Ok(HI)
                } else {
                    Err(SL_DIAG_VALUE_OVERFLOW)
                };
                assert_eq!(scaled(&d, 3), one, "3 ÷ 2 → 1, · MAX32");
                assert_eq!(
                    scaled(&d, 4),
                    Err(SL_DIAG_SCALE_MUL_OVERFLOW),
                    "4 ÷ 2 = 2, · MAX32"
                );
            }

            /// §4.23.2 diag 4 / 0x40B3 "A 32-bit overflow occurred during the division due
            /// to rounding": the quotient leaves T32 — only −2³¹ ÷ −1 (signed variants);
            /// with unsigned factors no quotient exceeds its dividend.
            #[test]
            fn division_overflow_is_diag_4() {
                if !SIGNED {
                    return;
                }
                // AnalogIn · Numerator = −2³¹, then ÷ −1.
                let c = Config {
                    num: LO32 / LO,
                    den: -1,
                    ..PLAIN
                };
                assert_eq!(scaled(&c, LO), Err(SL_DIAG_SCALE_DIV_OVERFLOW));
                let next = if HI == HI32 {
                    Ok(HI)
                } else {
                    Err(SL_DIAG_VALUE_OVERFLOW)
                };
                assert_eq!(scaled(&c, LO + 1), next, "one step inside T32");
                if HI == HI32 {
                    let d = Config {
                        div_first: true,
                        den: -1,
                        ..PLAIN
                    };
                    assert_eq!(scaled(&d, LO), Err(SL_DIAG_SCALE_DIV_OVERFLOW));
                }
            }

            /// §4.23.2 diag 1 / 0x40B0 and diag 2 / 0x40B1: the result (with the offset)
            /// below / above the range of AnalogOut; the boundary values themselves pass.
            #[test]
            fn result_range_diag_1_and_2() {
                assert_eq!(scaled(&Config { off: 1, ..PLAIN }, HI - 1), Ok(HI));
                assert_eq!(
                    scaled(&Config { off: 1, ..PLAIN }, HI),
                    Err(SL_DIAG_VALUE_OVERFLOW)
                );
                let off = Config { off: HI32, ..PLAIN };
                assert_eq!(
                    scaled(&off, 1),
                    Err(SL_DIAG_VALUE_OVERFLOW),
                    "offset is T32"
                );
                if SIGNED {
                    assert_eq!(scaled(&Config { off: -1, ..PLAIN }, LO + 1), Ok(LO));
                    assert_eq!(
                        scaled(&Config { off: -1, ..PLAIN }, LO),
                        Err(SL_DIAG_VALUE_UNDERFLOW)
                    );
                } else {
                    // Unsigned factors and offset: the result is never negative.
                    assert_eq!(scaled(&Config { num: 0, ..PLAIN }, HI), Ok(0));
                }
            }

            /// §4.23.2 ERROR: "Error = 1 AnalogOut = 0 StuckAtError = 0"; RESET "If no more
            /// errors are present after an error has occurred and the ErrAck input … is set
            /// to TRUE" (the error remains while the input still computes out of range,
            /// ABI-2 §12.5); RESET: all 0, message cleared; ErrAck FALSE → RUN.
            #[test]
            fn error_remains_while_out_of_range() {
                let c = Config {
                    off: 1,
                    watchdog: 10,
                    ..PLAIN
                };
                let mut fb = running_at(&c, 0, 0);
                assert_eq!(step(&mut fb, 5, HI), SL_OK);
                let o = outputs(&fb);
                assert_eq!(
                    (o.state, o.error, o.out, o.stuck),
                    (SL_STATE_ERROR, 1, 0, 0)
                );
                assert_eq!(
                    (o.diag, o.text, o.par),
                    (2, SL_TEXT_SCALE_OVERFLOW, (pattern(HI), 0))
                );
                fb.bErrAck = 1;
                assert_eq!(step(&mut fb, 6, HI), SL_OK);
                assert_eq!(fb.nState, SL_STATE_ERROR, "still out of range");
                fb.bErrAck = 0;
                step(&mut fb, 7, 3);
                assert_eq!(fb.nState, SL_STATE_ERROR, "acknowledge needs an edge");
                fb.bErrAck = 1;
                assert_eq!(step(&mut fb, 8, 3), SL_OK);
                let r = outputs(&fb);
                assert_eq!(
                    (r.state, r.error, r.out, r.stuck, r.diag, r.text, r.par),
                    (SL_STATE_RESET, 0, 0, 0, 0, 0, (0, 0))
                );
                // Stuck for longer than the watchdog in RESET: nothing shows.
                assert_eq!(step(&mut fb, 100, 3), SL_OK);
                assert_eq!(fb.bStuckAtError, 0);
                fb.bErrAck = 0;
                assert_eq!(step(&mut fb, 101, 3), SL_OK);
                assert_eq!(
                    (fb.nState, fb.nAnalogOut.wide(), fb.bStuckAtError),
                    (SL_STATE_RUN, 4, 0)
                );
                assert_eq!(step(&mut fb, 110, 3), SL_OK);
                assert_eq!(fb.bStuckAtError, 0, "9 ms after RESET → RUN");
                assert_eq!(step(&mut fb, 111, 3), SL_OK);
                assert_eq!(fb.bStuckAtError, 1, "the watchdog restarted at RESET → RUN");
            }

            /// §4.23.2 STOP: "Error = 0 AnalogOut = 0 StuckAtError = 0"; back to RUN when
            /// FbRun is TRUE again.
            #[test]
            fn stop_outputs_zero() {
                let c = Config {
                    off: 9,
                    watchdog: 1,
                    ..PLAIN
                };
                let mut fb = running_at(&c, 0, 1);
                step(&mut fb, 1, 1);
                assert_eq!((fb.nAnalogOut.wide(), fb.bStuckAtError), (10, 1));
                fb.bRun = 0;
                assert_eq!(step(&mut fb, 2, 1), SL_OK);
                let o = outputs(&fb);
                assert_eq!((o.state, o.error, o.out, o.stuck), (SL_STATE_STOP, 0, 0, 0));
                fb.bRun = 1;
                assert_eq!(step(&mut fb, 3, 2), SL_OK);
                assert_eq!(
                    (fb.nState, fb.nAnalogOut.wide(), fb.bStuckAtError),
                    (SL_STATE_RUN, 11, 0)
                );
            }

            /// §4.23.1 watchdog: "the AnalogIn input must have changed within the specified
            /// time. If the input remains unchanged within the specified time, the
            /// StuckAtError output is set to TRUE … not a FB error": just below the time
            /// FALSE, at it TRUE, in RUN with Error FALSE; a change clears it and restarts
            /// the time (semantics SC3).
            #[test]
            fn stuck_at_watchdog_edges() {
                let c = Config {
                    watchdog: 100,
                    ..PLAIN
                };
                let mut fb = running_at(&c, 1000, 7);
                step(&mut fb, 1099, 7);
                assert_eq!(fb.bStuckAtError, 0, "99 ms");
                step(&mut fb, 1100, 7);
                let o = outputs(&fb);
                assert_eq!(
                    (o.stuck, o.state, o.error, o.out, o.diag),
                    (1, SL_STATE_RUN, 0, 7, 0)
                );
                step(&mut fb, 1150, 8);
                assert_eq!(fb.bStuckAtError, 0, "a change clears it");
                step(&mut fb, 1249, 8);
                assert_eq!(fb.bStuckAtError, 0);
                step(&mut fb, 1250, 8);
                assert_eq!(fb.bStuckAtError, 1);
                // A change and back within the time restarts it each time.
                step(&mut fb, 1300, 7);
                step(&mut fb, 1350, 8);
                step(&mut fb, 1449, 8);
                assert_eq!(fb.bStuckAtError, 0);
                // "If the parameter is set to 0, the check is turned off."
                let mut off = running_at(&PLAIN, 0, 7);
                step(&mut off, 60_000, 7);
                assert_eq!(off.bStuckAtError, 0);
            }

            /// ABI §4: the watchdog across the 2^32 ms wrap of tNow, and a StuckAtError that
            /// holds after the elapsed time itself wraps.
            #[test]
            fn stuck_at_across_the_clock_wrap() {
                let c = Config {
                    watchdog: SL_TIME_PARAM_MAX,
                    ..PLAIN
                };
                let t0 = u32::MAX - 30_000;
                let mut fb = running_at(&c, t0, 1);
                step(&mut fb, t0.wrapping_add(SL_TIME_PARAM_MAX - 1), 1);
                assert_eq!(fb.bStuckAtError, 0);
                step(&mut fb, t0.wrapping_add(SL_TIME_PARAM_MAX), 1);
                assert_eq!(fb.bStuckAtError, 1);
                let mut now = t0.wrapping_add(SL_TIME_PARAM_MAX);
                for _ in 0..3 {
                    now = now.wrapping_add(0x7FFF_0000);
                    assert_eq!(step(&mut fb, now, 1), SL_OK);
                }
                assert_eq!(
                    fb.bStuckAtError, 1,
                    "latched, not recomputed from the wrapped time"
                );
            }

            /// ABI-2 §12.8, §12.9, §12.4, §10.5: parameter-only checks at latch time.
            #[test]
            fn configuration_limits() {
                let init = |f: &dyn Fn(&mut Fb)| {
                    let mut fb = configure(&PLAIN);
                    f(&mut fb);
                    fb.init()
                };
                assert_eq!(init(&|_| ()), SL_OK);
                assert_eq!(
                    init(&|f| f.nDenominator = t32(0)),
                    SL_E_CONFIG,
                    "denominator 0"
                );
                assert_eq!(init(&|f| f.nRounding = SL_ROUNDING_ROUND), SL_OK);
                assert_eq!(init(&|f| f.nRounding = 3), SL_E_CONFIG);
                assert_eq!(init(&|f| f.tWatchdog = SL_TIME_PARAM_MAX), SL_OK);
                assert_eq!(init(&|f| f.tWatchdog = SL_TIME_PARAM_MAX + 1), SL_E_CONFIG);
                for bad in [0, 1, IN | 1 << 9, IN | 1] {
                    assert_eq!(
                        init(&|f| f.wInputActive = bad),
                        SL_E_CONFIG,
                        "active {bad:#x}"
                    );
                }
                assert_eq!(init(&|f| f.wInputNegated = NEG), SL_OK);
                for bad in [1, 1 << 9, NEG | 1] {
                    assert_eq!(
                        init(&|f| f.wInputNegated = bad),
                        SL_E_CONFIG,
                        "negated {bad:#x}"
                    );
                }
                assert_eq!(init(&|f| f.dwOptions = DIV_FIRST), SL_OK);
                for bad in [1, 1 << 9, DIV_FIRST | 1 << 31] {
                    assert_eq!(
                        init(&|f| f.dwOptions = bad),
                        SL_E_CONFIG,
                        "options {bad:#x}"
                    );
                }
                // Every value of T32 for the factors (except a zero denominator).
                for v in [LO32, HI32, 1] {
                    let den = if v == 0 { 1 } else { v };
                    assert_eq!(
                        init(&|f| {
                            f.nNumerator = t32(v);
                            f.nOffset = t32(v);
                            f.nDenominator = t32(den)
                        }),
                        SL_OK
                    );
                }
                // A refused configuration stays in STOP with safe outputs.
                let mut fb = configure(&PLAIN);
                fb.nDenominator = t32(0);
                assert_eq!(fb.init(), SL_E_CONFIG);
                fb.bRun = 1;
                assert_eq!(step(&mut fb, 0, 5), SL_E_CONFIG);
                assert_eq!(
                    (fb.nState, fb.nAnalogOut.wide(), fb.bError),
                    (SL_STATE_STOP, 0, 0)
                );
            }

            /// §4.23.2 Diagnostic information: the values 0–4 with the manual's texts.
            #[test]
            fn diag_value_table() {
                let info =
                    safelogic::registry::info(<Fb as safelogic::base::block::Registered>::INFO.tag)
                        .unwrap();
                let values: Vec<u16> = info.diag_values.iter().map(|(v, _)| *v).collect();
                assert_eq!(values, [0, 1, 2, 3, 4]);
                assert!(info.diag_values[3].1.contains("multiplication"));
                assert!(info.diag_values[4].1.contains("division due to rounding"));
                let states: Vec<u8> = info.states.iter().map(|(s, _)| *s).collect();
                assert_eq!(states, [1, 2, 4, 5], "RUN STOP ERROR RESET, no SAFE");
            }

            /// The model of one cycle (manual §4.23 + the envelope's ABI §7 rules).
            struct Model {
                c: Config,
                state: u8,
                out: i128,
                last: i128,
                since: u32,
                stuck: bool,
                diag: u16,
                par: u32,
                ack: bool,
            }

            impl Model {
                fn cycle(&mut self, run: bool, ack: bool, x: i128, now: u32) {
                    let (rising, falling) = (ack && !self.ack, !ack && self.ack);
                    self.ack = ack;
                    let r = model_scale(x, &self.c, (LO, HI), (LO32, HI32));
                    let start = |m: &mut Model| {
                        m.last = x;
                        m.since = now;
                        m.stuck = false;
                        m.state = SL_STATE_RUN;
                        m.run(r, x, now);
                    };
                    match self.state {
                        SL_STATE_STOP if run => start(self),
                        SL_STATE_STOP => {}
                        SL_STATE_ERROR => {
                            if rising && r.is_ok() {
                                self.state = SL_STATE_RESET;
                            }
                        }
                        SL_STATE_RESET => {
                            if falling {
                                if run {
                                    start(self)
                                } else {
                                    self.state = SL_STATE_STOP
                                }
                            }
                        }
                        _ if !run => self.state = SL_STATE_STOP,
                        _ => self.run(r, x, now),
                    }
                }
                fn run(&mut self, r: Result<i128, u16>, x: i128, now: u32) {
                    match r {
                        Ok(v) => {
                            self.out = v;
                            if x != self.last {
                                self.last = x;
                                self.since = now;
                                self.stuck = false;
                            } else if self.c.watchdog != 0
                                && now.wrapping_sub(self.since) >= self.c.watchdog
                            {
                                self.stuck = true;
                            }
                        }
                        Err(d) => {
                            self.state = SL_STATE_ERROR;
                            self.diag = d;
                            self.par = pattern(x);
                        }
                    }
                }
                fn outputs(&self) -> Outputs {
                    let run = self.state == SL_STATE_RUN;
                    let error = self.state == SL_STATE_ERROR;
                    Outputs {
                        error: u8::from(error),
                        stuck: u8::from(run && self.stuck),
                        out: if run { self.out } else { 0 },
                        state: self.state,
                        diag: if error { self.diag } else { 0 },
                        text: if error { 0x40AF + self.diag } else { 0 },
                        par: if error { (self.par, 0) } else { (0, 0) },
                    }
                }
            }

            /// ≥ 10,000 random sequences of valid configurations against the model, cycle by
            /// cycle (factors and inputs near the ends of their ranges so that every diag
            /// value of the variant happens, watchdogs short enough to expire); a labelled
            /// share of invalid configurations checked for SL_E_CONFIG.
            #[test]
            fn random_sequences_against_the_model() {
                let mut rng = Rng(0x5CA1_E001 ^ (HI as u64) ^ (LO32 as u64));
                let (mut reached, mut diags, mut stuck, mut invalid) = (0u32, 0u8, 0u32, 0u32);
                let sequences = common::depth_cases(12_000);
                let near = |rng: &mut Rng, anchors: &[i128], lo: i128, hi: i128| {
                    let a = anchors[(rng.next() % anchors.len() as u64) as usize];
                    (a + (rng.next() % 5) as i128 - 2).clamp(lo, hi)
                };
                for _ in 0..sequences {
                    let r = rng.next();
                    if r % 16 == 0 {
                        invalid += 1;
                        let mut fb = configure(&PLAIN);
                        match r >> 4 & 3 {
                            0 => fb.nDenominator = t32(0),
                            1 => fb.nRounding = 3 + (r >> 8 & 7) as u16,
                            2 => fb.tWatchdog = SL_TIME_PARAM_MAX + 1 + (r >> 8) as u32 % 1000,
                            _ => fb.dwOptions = 1 << (r >> 8 & 7),
                        }
                        assert_eq!(fb.init(), SL_E_CONFIG);
                        fb.bRun = 1;
                        assert_eq!(step(&mut fb, 0, 1), SL_E_CONFIG);
                        assert_eq!(
                            outputs(&fb),
                            Outputs {
                                error: 0,
                                stuck: 0,
                                out: 0,
                                state: SL_STATE_STOP,
                                diag: 0,
                                text: 0,
                                par: (0, 0)
                            }
                        );
                        continue;
                    }
                    let big = [
                        LO32,
                        HI32,
                        0,
                        1,
                        2,
                        3,
                        HI,
                        LO,
                        HI32 / HI.max(1),
                        LO32 / LO.min(-1),
                    ];
                    let mut den = near(
                        &mut rng,
                        &[1, 2, 3, 4, 7, HI32, LO32, LO, HI, -1],
                        LO32,
                        HI32,
                    );
                    let mut num = near(&mut rng, &big, LO32, HI32);
                    if SIGNED && r >> 4 & 15 == 0 {
                        // The one division overflow: AnalogIn · Numerator = −2³¹, ÷ −1.
                        (num, den) = (LO32 / LO, -1);
                    }
                    if den == 0 {
                        den = 1;
                    }
                    let c = Config {
                        num,
                        den,
                        off: near(&mut rng, &[0, 1, HI, LO, HI32, LO32], LO32, HI32),
                        rounding: (rng.next() % 3) as u16,
                        div_first: rng.next() % 2 == 0,
                        negate: rng.next() % 3 == 0,
                        watchdog: [0, 1, 5, 20, 50][(rng.next() % 5) as usize],
                    };
                    let mut fb = new(&c);
                    let mut m = Model {
                        c,
                        state: SL_STATE_STOP,
                        out: 0,
                        last: 0,
                        since: 0,
                        stuck: false,
                        diag: 0,
                        par: 0,
                        ack: false,
                    };
                    let mut now = rng.next() as u32;
                    let mut x = 0;
                    for _ in 0..24 {
                        let r = rng.next();
                        let run = r % 12 != 0;
                        let ack = r >> 4 & 3 == 0;
                        if r >> 8 & 3 == 0 {
                            x = near(&mut rng, &[0, 1, LO, HI, 100, LO / 2, HI / 2], LO, HI);
                        }
                        now = now.wrapping_add((r >> 16) as u32 % 12);
                        fb.bRun = u8::from(run);
                        fb.bErrAck = u8::from(ack);
                        assert_eq!(step(&mut fb, now, x), SL_OK);
                        m.cycle(run, ack, x, now);
                        let o = outputs(&fb);
                        assert_eq!(o, m.outputs(), "{c:?} x {x} now {now}");
                        reached |= 1 << o.state;
                        stuck += u32::from(o.stuck);
                        if o.state == SL_STATE_ERROR {
                            diags |= 1 << o.diag;
                        }
                    }
                }
                crate::common::assert_reached(
                    reached.into(),
                    [SL_STATE_RUN, SL_STATE_STOP, SL_STATE_ERROR, SL_STATE_RESET],
                );
                // Unsigned: no underflow, no quotient overflow.
                let expected = if SIGNED { 0b11110 } else { 0b01100 };
                assert_eq!(diags, expected, "diag values reached {diags:#b}");
                assert!(stuck > 1000, "StuckAtError {stuck}");
                crate::common::assert_invalid_share(invalid, 300, sequences / 8);
            }
        }
    };
}

scale_tests!(int, FB_SCALE_INT, i16, i32);
scale_tests!(uint, FB_SCALE_UINT, u16, u32);
scale_tests!(dint, FB_SCALE_DINT, i32, i32);
scale_tests!(udint, FB_SCALE_UDINT, u32, u32);
