//! FB ADD, SUB, MUL, DIV (manual §4.16–§4.19, ABI-2 §11.2, §12; docs/semantics.md A1–A6)
//! in all four integer variants: exact results against an `i128` model, the range errors
//! with diag value and message, DIV rounding and division by zero, ERROR → RESET → RUN.

use safelogic::blocks::analog::arith::*;
mod common;

use common::Rng;
use safelogic::*;

const ACTIVE: u16 = ARITH_ACTIVE;

/// The model: the exact result, or the diag value of the range error.
fn model(op: &str, a: i128, b: i128, rounding: u16, min: i128, max: i128) -> Result<i128, u16> {
    let exact = match op {
        "ADD" => a + b,
        "SUB" => a - b,
        "MUL" => a * b,
        _ if b == 0 => 0,
        _ => {
            // Independent of the library's `divide`: via floor division on rationals.
            let (n, d) = if b < 0 { (-a, -b) } else { (a, b) };
            let floor = n.div_euclid(d);
            let rem = n.rem_euclid(d); // 0 <= rem < d, n = floor*d + rem
            match rounding {
                SL_ROUNDING_FLOOR => floor,
                SL_ROUNDING_CEIL => floor + i128::from(rem != 0),
                _ => {
                    // half away from zero: compare 2*rem with d
                    if 2 * rem > d || (2 * rem == d && floor >= 0) {
                        floor + 1
                    } else {
                        floor
                    }
                }
            }
        }
    };
    if exact < min {
        Err(SL_DIAG_VALUE_UNDERFLOW)
    } else if exact > max {
        Err(SL_DIAG_VALUE_OVERFLOW)
    } else {
        Ok(exact)
    }
}

/// Operands for the variant tests.
trait Operands {
    /// Uniform over the type, or (one time in three) within 8 of MIN, MAX, 0 or ±sqrt(MAX).
    fn value<T: TryFrom<i128> + Copy + Bounded>(&mut self) -> T;
}

impl Operands for Rng {
    fn value<T: TryFrom<i128> + Copy + Bounded>(&mut self) -> T {
        let pick = self.next();
        let v: i128 = if pick % 3 == 0 {
            let anchors = [T::MIN, T::MAX, 0, T::root(), -T::root()];
            anchors[(pick / 3 % 5) as usize] + (self.next() % 17) as i128 - 8
        } else {
            T::MIN + (self.next() as i128).rem_euclid(T::MAX - T::MIN + 1)
        };
        T::try_from(v.clamp(T::MIN, T::MAX)).ok().expect("in range")
    }
}

trait Bounded {
    const MIN: i128;
    const MAX: i128;
    fn root() -> i128 {
        let mut r = 1i128;
        while r * r <= Self::MAX {
            r += 1;
        }
        r
    }
}

macro_rules! bounded {
    ($($t:ty),*) => {$(impl Bounded for $t {
        const MIN: i128 = <$t>::MIN as i128;
        const MAX: i128 = <$t>::MAX as i128;
    })*};
}
bounded!(i16, u16, i32, u32);

macro_rules! variant_tests {
    ($($m:ident: $op:literal, $ty:ty, $t:ty, $div:tt;)*) => {$(
        mod $m {
            use super::*;

            fn block(a: $t, b: $t, rounding: u16) -> $ty {
                let mut fb = <$ty>::default();
                fb.wInputActive = ACTIVE;
                set_rounding(&mut fb, rounding);
                fb.nAnalogIn1 = a;
                fb.nAnalogIn2 = b;
                assert_eq!(fb.init(), SL_OK);
                fb.bRun = 1;
                fb
            }

            #[allow(unused_variables)]
            fn set_rounding(fb: &mut $ty, r: u16) {
                variant_tests!(@round $div, fb, r);
            }

            fn check(a: $t, b: $t, rounding: u16) {
                let mut fb = block(a, b, rounding);
                let rc = fb.cycle(0);
                let expect = model($op, a as i128, b as i128, rounding, <$t>::MIN as i128, <$t>::MAX as i128);
                match expect {
                    Ok(v) => {
                        assert_eq!(rc, SL_OK);
                        assert_eq!(fb.nState, SL_STATE_RUN, "{a} {b}");
                        assert_eq!(fb.nAnalogOut as i128, v, "{} {a} {b} r{rounding}", $op);
                        assert_eq!((fb.bError, fb.nDiag, fb.nDiagTextId), (0, 0, 0));
                    }
                    Err(d) => {
                        assert_eq!(rc, SL_OK);
                        assert_eq!(fb.nState, SL_STATE_ERROR, "{} {a} {b}", $op);
                        assert_eq!((fb.bError, fb.nAnalogOut, fb.nDiag), (1, 0 as $t, d));
                        let text = if d == SL_DIAG_VALUE_UNDERFLOW { 0x4080 } else { 0x4081 };
                        assert_eq!(fb.nDiagTextId, text);
                        assert_eq!(fb.dwDiagPar2, a as i32 as u32, "par 2 = AnalogIn1 (sign-extended)");
                        assert_eq!(fb.dwDiagPar3, b as i32 as u32);
                    }
                }
            }

            #[test]
            fn boundary_values() {
                let edges = [<$t>::MIN, <$t>::MAX, 0 as $t, 1 as $t, <$t>::MIN.wrapping_add(1), <$t>::MAX - 1, (0 as $t).wrapping_sub(1), 2 as $t, <$t>::MAX / 2, <$t>::MIN / 2];
                for a in edges {
                    for b in edges {
                        for r in [SL_ROUNDING_FLOOR, SL_ROUNDING_CEIL, SL_ROUNDING_ROUND] {
                            check(a, b, r);
                        }
                    }
                }
            }

            /// 10,000 random operand pairs (a third of them near the type's edges, so that
            /// both outcomes occur for every operation) against the model; the test asserts
            /// that it reached RUN and ERROR often enough to mean something.
            #[test]
            fn exact_against_the_model() {
                let mut rng = Rng(0x9E37_79B9_7F4A_7C15 ^ (<$t>::MAX as u64) ^ $op.len() as u64);
                let (mut run, mut error) = (0, 0);
                for _ in 0..10_000 {
                    let a = rng.value::<$t>();
                    let b = rng.value::<$t>();
                    let r = (rng.next() % 3) as u16;
                    check(a, b, r);
                    match model($op, a as i128, b as i128, r, <$t>::MIN as i128, <$t>::MAX as i128) {
                        Ok(_) => run += 1,
                        Err(_) => error += 1,
                    }
                }
                // DIV on unsigned types can never overflow: only RUN is reachable there.
                let error_reachable = !($op == "DIV" && <$t>::MIN as i128 == 0);
                assert!(run >= 100, "RUN reached {run} times");
                assert!(!error_reachable || error >= 1, "ERROR reached {error} times");
            }

            /// ERROR is left only through RESET, and only once the inputs compute in range.
            #[test]
            fn error_left_through_reset_once_in_range() {
                // An input pair that is out of range for every operation of this type.
                let (a, b): ($t, $t) = if $op == "DIV" {
                    if <$t>::MIN as i128 == 0 { return; } // unsigned DIV cannot overflow
                    (<$t>::MIN, (0 as $t).wrapping_sub(1))
                } else if $op == "SUB" { (<$t>::MIN, <$t>::MAX) } else { (<$t>::MAX, <$t>::MAX) };
                let mut fb = block(a, b, 0);
                fb.cycle(0);
                assert_eq!(fb.nState, SL_STATE_ERROR);
                // Ack while still out of range: stays in ERROR.
                fb.bErrAck = 1; fb.cycle(1); fb.bErrAck = 0; fb.cycle(2);
                assert_eq!(fb.nState, SL_STATE_ERROR);
                fb.nAnalogIn1 = 1 as $t; fb.nAnalogIn2 = 1 as $t;
                fb.cycle(3);
                assert_eq!(fb.nState, SL_STATE_ERROR, "no acknowledgement yet");
                fb.bErrAck = 1; fb.cycle(4);
                assert_eq!((fb.nState, fb.nDiag, fb.nDiagTextId, fb.bError), (SL_STATE_RESET, 0, 0, 0));
                assert_eq!(fb.nAnalogOut, 0 as $t);
                fb.bErrAck = 0; fb.cycle(5);
                assert_eq!(fb.nState, SL_STATE_RUN);
                fb.bRun = 0; fb.cycle(6);
                assert_eq!((fb.nState, fb.nAnalogOut), (SL_STATE_STOP, 0 as $t));
            }

            #[test]
            fn parameters_are_checked() {
                let mut fb = <$ty>::default();
                for bad in [0u16, 0x0100, 0x0200, 0x0301, 0x0700] {
                    fb.wInputActive = bad;
                    assert_eq!(fb.init(), SL_E_CONFIG, "wInputActive {bad:#x}");
                    fb.bRun = 1;
                    assert_eq!(fb.cycle(0), SL_E_CONFIG);
                    assert_eq!((fb.nState, fb.bError), (SL_STATE_STOP, 0));
                    fb.bRun = 0;
                }
                fb.wInputActive = ACTIVE;
                assert_eq!(fb.init(), SL_OK);
                if $div {
                    set_rounding(&mut fb, 3);
                    assert_eq!(fb.init(), SL_E_CONFIG);
                }
            }
        }
    )*};
    (@round true, $fb:ident, $r:ident) => { $fb.nRounding = $r; };
    (@round false, $fb:ident, $r:ident) => { };
}

variant_tests! {
    add_int: "ADD", FB_ADD_INT, i16, false;
    add_uint: "ADD", FB_ADD_UINT, u16, false;
    add_dint: "ADD", FB_ADD_DINT, i32, false;
    add_udint: "ADD", FB_ADD_UDINT, u32, false;
    sub_int: "SUB", FB_SUB_INT, i16, false;
    sub_uint: "SUB", FB_SUB_UINT, u16, false;
    sub_dint: "SUB", FB_SUB_DINT, i32, false;
    sub_udint: "SUB", FB_SUB_UDINT, u32, false;
    mul_int: "MUL", FB_MUL_INT, i16, false;
    mul_uint: "MUL", FB_MUL_UINT, u16, false;
    mul_dint: "MUL", FB_MUL_DINT, i32, false;
    mul_udint: "MUL", FB_MUL_UDINT, u32, false;
    div_int: "DIV", FB_DIV_INT, i16, true;
    div_uint: "DIV", FB_DIV_UINT, u16, true;
    div_dint: "DIV", FB_DIV_DINT, i32, true;
    div_udint: "DIV", FB_DIV_UDINT, u32, true;
}

/// The manual's samples and the rounding table of docs/semantics.md A2.
#[test]
fn rounding_of_positive_and_negative_quotients() {
    let q = |a: i16, b: i16, r: u16| {
        let mut fb = common::ready(FB_DIV_INT {
            wInputActive: ACTIVE,
            nRounding: r,
            nAnalogIn1: a,
            nAnalogIn2: b,
            bRun: 1,
            ..Default::default()
        });
        fb.cycle(0);
        fb.nAnalogOut
    };
    // 5 / 2 = 2.5; -5 / 2 = -2.5; 7 / 3 = 2.33; -7 / 3 = -2.33
    assert_eq!([q(5, 2, 0), q(5, 2, 1), q(5, 2, 2)], [2, 3, 3]);
    assert_eq!([q(-5, 2, 0), q(-5, 2, 1), q(-5, 2, 2)], [-3, -2, -3]);
    assert_eq!([q(7, 3, 0), q(7, 3, 1), q(7, 3, 2)], [2, 3, 2]);
    assert_eq!([q(-7, 3, 0), q(-7, 3, 1), q(-7, 3, 2)], [-3, -2, -2]);
    assert_eq!([q(5, -2, 0), q(5, -2, 1), q(5, -2, 2)], [-3, -2, -3]);
    // Division by 0: 0, no error.
    assert_eq!(q(123, 0, 2), 0);
}

/// One running call of `$fb` with both inputs active on `(in1, in2)`: it must end in ERROR
/// with `(diag, text id)` and the inputs' bit patterns `(par2, par3)` as the parameters.
macro_rules! range_error {
    ($fb:ident, ($a:expr, $b:expr), $diag:expr, $par:expr) => {{
        let mut fb = common::ready($fb {
            wInputActive: ACTIVE,
            nAnalogIn1: $a,
            nAnalogIn2: $b,
            bRun: 1,
            ..Default::default()
        });
        fb.cycle(0);
        let want = (SL_STATE_ERROR, $diag.0, $diag.1);
        assert_eq!((fb.nState, fb.nDiag, fb.nDiagTextId), want);
        assert_eq!((fb.dwDiagPar2, fb.dwDiagPar3), $par);
    }};
}

/// MIN ÷ −1 is DIV's only overflow.
#[test]
fn min_divided_by_minus_one_overflows() {
    range_error!(
        FB_DIV_DINT,
        (i32::MIN, -1),
        (2, 0x4081),
        (0x8000_0000, 0xFFFF_FFFF)
    );
}

/// SUB on an unsigned type: a negative difference is an underflow.
#[test]
fn unsigned_sub_below_zero_is_an_underflow() {
    range_error!(FB_SUB_UINT, (3, 4), (1, 0x4080), (3, 4));
}

/// The diag value reads as the manual's text.
#[test]
fn diag_text_of_a_value() {
    let info = safelogic::registry::info(SL_TYPE_ADD_INT).expect("registered");
    let mut buf = [0u8; 128];
    let n = safelogic::base::diag::diag_text(info, 2, &mut buf);
    assert_eq!(
        std::str::from_utf8(&buf[..n]).unwrap(),
        "The output AnalogOut has an overflow (is greater than the largest possible value)"
    );
    let n = safelogic::base::diag::diag_text(info, 1 | SL_DIAG_CLOCK, &mut buf);
    assert!(std::str::from_utf8(&buf[..n])
        .unwrap()
        .ends_with("; clock went backwards"));
    assert_eq!(state_name(SL_TYPE_DIV_UDINT, SL_STATE_RESET), "RESET");
}

/// A parameter changed while running is SL_E_PARAM_CHANGED as for every block (C5).
#[test]
fn parameter_change_while_running() {
    let mut fb = common::ready(FB_DIV_UINT {
        wInputActive: ACTIVE,
        nAnalogIn1: 9,
        nAnalogIn2: 2,
        bRun: 1,
        ..Default::default()
    });
    assert_eq!(fb.cycle(0), SL_OK);
    assert_eq!(fb.nAnalogOut, 4);
    fb.nRounding = SL_ROUNDING_CEIL;
    assert_eq!(fb.cycle(1), SL_E_PARAM_CHANGED);
    assert_eq!(
        (fb.nState, fb.nAnalogOut, fb.bError),
        (SL_STATE_ERROR, 0, 1)
    );
}
