//! FB SLI2 (manual §4.28 with §4.27, ABI-2 §11.10, §12; docs/semantics.md SI1–SI8) in all
//! four integer variants: every statement of §4.27 (tests/common/sli.rs, shared with SLI)
//! with the options off, then what SLI2 adds — BelowMin/AboveMax, EXCEEDED with
//! ExceededSupport, the modular difference with OverflowAllowed, the option bits — and
//! ≥ 10,000 random sequences per variant (all option combinations) against the model.

mod common;
#[macro_use]
#[path = "common/sli.rs"]
mod sli;

use safelogic::*;
use sli::{call, make, outs};

sli_tests_all!(FB_SLI2_INT, FB_SLI2_UINT, FB_SLI2_DINT, FB_SLI2_UDINT, true);

const EXC: u32 = SL_OPT_SLI2_EXCEEDED_SUPPORT;
const WRAP: u32 = SL_OPT_SLI2_OVERFLOW_ALLOWED;

fn latched<B: FunctionBlock + Default>(pos: u32, neg: u32, options: u32, latch: i128) -> B {
    let (mut fb, rc) = make::<B>(pos, neg, options);
    assert_eq!(rc, SL_OK);
    assert_eq!(call(&mut fb, 0, 0, latch, 1, 0), SL_OK);
    assert_eq!(call(&mut fb, 1, 1, latch, 1, 0), SL_OK);
    assert_eq!(outs(&fb).state, SL_STATE_RUN);
    fb
}

/// §4.28.2.3 EXCEEDED "If ExceededSupport = TRUE and PositionDiff < NegLimit (underflow) or
/// PositionDiff > PosLimit (overflow) in the RUN state … Error = 0 SLIActive = 0 BelowMin =
/// Underflow AboveMax = Overflow PositionDiff = Position - LatchPosition".
#[test]
fn exceeded_instead_of_error() {
    let mut fb = latched::<FB_SLI2_DINT>(10, 20, EXC, 1000);
    assert_eq!(call(&mut fb, 2, 1, 1011, 1, 0), SL_OK);
    let o = outs(&fb);
    assert_eq!(
        (o.state, o.error, o.active, o.below, o.above, o.diff),
        (7, 0, 0, 0, 1, 11)
    );
    assert_eq!((o.diag, o.text, o.par), (0, 0, (0, 0)));
    assert_eq!(fb.state_name(), "EXCEEDED");
    // The difference stays live in EXCEEDED, the side with it.
    assert_eq!(call(&mut fb, 3, 1, 979, 1, 0), SL_OK);
    let o = outs(&fb);
    assert_eq!((o.state, o.below, o.above, o.diff), (7, 1, 0, -21));
    // Back inside: still EXCEEDED (left only by SLI FALSE), neither side.
    assert_eq!(call(&mut fb, 4, 1, 1000, 1, 0), SL_OK);
    let o = outs(&fb);
    assert_eq!(
        (o.state, o.active, o.below, o.above, o.diff),
        (7, 0, 0, 0, 0)
    );
    // ErrAck does nothing in EXCEEDED.
    assert_eq!(call(&mut fb, 5, 1, 1000, 1, 1), SL_OK);
    assert_eq!(call(&mut fb, 6, 1, 1000, 1, 0), SL_OK);
    assert_eq!(outs(&fb).state, 7);
    // SLI FALSE → SAFE; a new edge → RUN.
    assert_eq!(call(&mut fb, 7, 0, 1000, 1, 0), SL_OK);
    let o = outs(&fb);
    assert_eq!(
        (o.state, o.below, o.above, o.diff),
        (SL_STATE_SAFE, 0, 0, 0)
    );
    assert_eq!(call(&mut fb, 8, 1, 5000, 1, 0), SL_OK);
    assert_eq!((outs(&fb).state, outs(&fb).diff), (SL_STATE_RUN, 0));
}

/// EXCEEDED → bRun FALSE → STOP with every output 0.
#[test]
fn exceeded_stops_with_run() {
    let mut fb = latched::<FB_SLI2_INT>(1, 1, EXC, 0);
    assert_eq!(call(&mut fb, 2, 1, -2, 1, 0), SL_OK);
    assert_eq!(outs(&fb).below, 1);
    assert_eq!(call(&mut fb, 3, 1, -2, 0, 0), SL_OK);
    let o = outs(&fb);
    assert_eq!(
        (o.state, o.below, o.above, o.diff),
        (SL_STATE_STOP, 0, 0, 0)
    );
}

/// PositionDiff in EXCEEDED saturates to INT16/INT32 (ABI-2 §11.10, semantics SI7).
#[test]
fn exceeded_difference_saturates_to_the_output_type() {
    let mut fb = latched::<FB_SLI2_UINT>(10, 10, EXC, 0);
    assert_eq!(call(&mut fb, 2, 1, 65_535, 1, 0), SL_OK);
    assert_eq!(
        (outs(&fb).state, outs(&fb).diff, outs(&fb).above),
        (7, 32_767, 1)
    );
    let mut fb = latched::<FB_SLI2_UDINT>(10, 10, EXC, u32::MAX as i128);
    assert_eq!(call(&mut fb, 2, 1, 0, 1, 0), SL_OK);
    assert_eq!((outs(&fb).diff, outs(&fb).below), (i64::from(i32::MIN), 1));
    let mut fb = latched::<FB_SLI2_INT>(10, 10, EXC, -32_768);
    assert_eq!(call(&mut fb, 2, 1, 32_767, 1, 0), SL_OK);
    assert_eq!(outs(&fb).diff, 32_767);
}

/// BelowMin/AboveMax are 0 in every state but EXCEEDED (§4.28.2.3 status table), also
/// without ExceededSupport (ERROR).
#[test]
fn below_and_above_only_in_exceeded() {
    let mut fb = latched::<FB_SLI2_DINT>(10, 10, 0, 0);
    assert_eq!(call(&mut fb, 2, 1, 11, 1, 0), SL_OK);
    let o = outs(&fb);
    assert_eq!(
        (o.state, o.error, o.below, o.above, o.diag),
        (4, 1, 0, 0, 2)
    );
    assert_eq!(o.text, u32::from(SL_TEXT_SLI_OVERFLOW));
}

/// OverflowAllowed (semantics SI6): the difference modulo 2^W in the signed range — a
/// wrap of the position counter is a short move. Without it the exact difference.
#[test]
fn overflow_allowed_takes_the_short_way_round() {
    let mut fb = latched::<FB_SLI2_UINT>(10, 10, WRAP, 65_530);
    assert_eq!(call(&mut fb, 2, 1, 3, 1, 0), SL_OK);
    assert_eq!((outs(&fb).state, outs(&fb).diff), (SL_STATE_RUN, 9));
    assert_eq!(call(&mut fb, 3, 1, 65_525, 1, 0), SL_OK);
    assert_eq!((outs(&fb).state, outs(&fb).diff), (SL_STATE_RUN, -5));
    let mut fb = latched::<FB_SLI2_UINT>(10, 10, 0, 65_530);
    assert_eq!(call(&mut fb, 2, 1, 3, 1, 0), SL_OK);
    assert_eq!((outs(&fb).state, outs(&fb).diag), (SL_STATE_ERROR, 1));
    let mut fb = latched::<FB_SLI2_INT>(10, 10, WRAP, 32_767);
    assert_eq!(call(&mut fb, 2, 1, -32_768, 1, 0), SL_OK);
    assert_eq!(outs(&fb).diff, 1);
    let mut fb = latched::<FB_SLI2_UDINT>(10, 10, WRAP, 2);
    assert_eq!(call(&mut fb, 2, 1, u32::MAX as i128, 1, 0), SL_OK);
    assert_eq!(outs(&fb).diff, -3);
    let mut fb = latched::<FB_SLI2_DINT>(10, 10, WRAP | EXC, i32::MIN as i128);
    assert_eq!(call(&mut fb, 2, 1, i32::MAX as i128, 1, 0), SL_OK);
    assert_eq!((outs(&fb).diff, outs(&fb).state), (-1, SL_STATE_RUN));
    // Half the circle away: the most negative difference, beyond any limit.
    assert_eq!(call(&mut fb, 3, 1, 0, 1, 0), SL_OK);
    assert_eq!(
        (outs(&fb).state, outs(&fb).below, outs(&fb).diff),
        (7, 1, i64::from(i32::MIN))
    );
}

/// Only bits 8 and 9 of `dwOptions` exist (ABI-2 §11.10); any other is SL_E_CONFIG.
#[test]
fn unknown_option_bits_are_config_errors() {
    for o in [0, WRAP, EXC, WRAP | EXC] {
        assert_eq!(make::<FB_SLI2_INT>(1, 1, o).1, SL_OK);
    }
    for o in [1, 1 << 7, 1 << 10, 1 << 31, 0xFFFF_FFFF] {
        assert_eq!(make::<FB_SLI2_INT>(1, 1, o).1, SL_E_CONFIG, "{o:#x}");
    }
}

/// An option changed while running is a parameter change (ABI §5, semantics C5).
#[test]
fn option_change_while_running_is_an_error() {
    let mut fb = latched::<FB_SLI2_UDINT>(10, 10, 0, 50);
    fb.set("dwOptions", i64::from(EXC)).unwrap();
    assert_eq!(call(&mut fb, 2, 1, 50, 1, 0), SL_E_PARAM_CHANGED);
    assert_eq!(outs(&fb).state, SL_STATE_ERROR);
}

/// The state table of SLI2 (§4.28.2.3) and its name.
#[test]
fn states_and_names() {
    for tag in [
        SL_TYPE_SLI2_INT,
        SL_TYPE_SLI2_UINT,
        SL_TYPE_SLI2_DINT,
        SL_TYPE_SLI2_UDINT,
    ] {
        let states: Vec<u8> = registry::info(tag)
            .unwrap()
            .states
            .iter()
            .map(|s| s.0)
            .collect();
        assert_eq!(states, [1, 2, 3, 4, 5, 7]);
        assert_eq!(state_name(tag, 7), "EXCEEDED");
    }
    assert_eq!(Sli2State::Exceeded as u8, 7);
}
