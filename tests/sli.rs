//! FB SLI (manual §4.27, ABI-2 §11.9, §12; docs/semantics.md SI1–SI8) in all four integer
//! variants: one test per statement of the manual section (tests/common/sli.rs, shared with
//! SLI2), what is SLI's alone, then ≥ 10,000 random sequences per variant against a small
//! model that assert the states reached.

mod common;
#[macro_use]
#[path = "common/sli.rs"]
mod sli;

use safelogic::*;

sli_tests_all!(FB_SLI_INT, FB_SLI_UINT, FB_SLI_DINT, FB_SLI_UDINT, false);

/// §4.27.2 "7.0 EXCEEDED If ExceededSupport = TRUE … the FB SLI2 module": SLI has no such
/// parameter, so it has no state 7 (ABI-2 §14 row 14, semantics SI1): its state table ends
/// at RESET and a stored 7 is a corrupt state.
#[test]
fn sli_has_no_exceeded_state() {
    for tag in [
        SL_TYPE_SLI_INT,
        SL_TYPE_SLI_UINT,
        SL_TYPE_SLI_DINT,
        SL_TYPE_SLI_UDINT,
    ] {
        let info = registry::info(tag).unwrap();
        let states: Vec<u8> = info.states.iter().map(|s| s.0).collect();
        assert_eq!(states, [1, 2, 3, 4, 5]);
        assert_eq!(state_name(tag, 7), "?");
        assert_eq!(state_name(tag, 3), "SAFE");
    }
    let mut fb = common::ready(FB_SLI_UINT {
        wInputActive: SL_SLI_ACTIVE,
        nLimitPos: 10,
        nLimitNeg: 10,
        ..Default::default()
    });
    (fb.bRun, fb.bSLI) = (1, 1);
    assert_eq!(fb.cycle(0), SL_OK);
    fb.nState = SL_STATE_SLI2_EXCEEDED;
    fb.stPrivate.stHeader.nState = SL_STATE_SLI2_EXCEEDED;
    assert_eq!(fb.cycle(1), SL_E_CORRUPT);
    assert_eq!(
        (fb.nState, fb.bError, fb.bSLIActive),
        (SL_STATE_ERROR, 1, 0)
    );
}

/// §4.27.2 diag values and the texts behind `sl_diag_text`.
#[test]
fn diag_texts() {
    let info = registry::info(SL_TYPE_SLI_DINT).unwrap();
    let text = |d: u16| {
        let mut buf = [0u8; 96];
        let n = base::diag::diag_text(info, d, &mut buf);
        String::from_utf8(buf[..n].to_vec()).unwrap()
    };
    assert_eq!(text(0), "No diagnostic information");
    assert_eq!(text(1), "Underflow (PositionDiff < -NegLimit)");
    assert_eq!(text(2), "Overflow (PositionDiff > PosLimit)");
    assert_eq!(
        (SL_TEXT_SLI_UNDERFLOW, SL_TEXT_SLI_OVERFLOW),
        (0x40C0, 0x40C1)
    );
}

/// UINT positions: PositionDiff is INT16 (ABI-2 §10.3 TS); a move below the latch is a
/// negative difference, exact.
#[test]
fn unsigned_positions_give_signed_differences() {
    let mut fb = common::ready(FB_SLI_UDINT {
        wInputActive: SL_SLI_ACTIVE,
        nLimitPos: 5,
        nLimitNeg: 5,
        ..Default::default()
    });
    (fb.bRun, fb.bSLI, fb.nPosition) = (1, 1, 3);
    assert_eq!(fb.cycle(0), SL_OK);
    fb.nPosition = 0;
    assert_eq!(fb.cycle(1), SL_OK);
    assert_eq!((fb.nState, fb.nPositionDiff), (SL_STATE_RUN, -3));
}
