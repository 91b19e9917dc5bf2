//! Why a block refuses: `sl_reason_text` (docs/c-integration.md "Reasons"), the Text IDs a
//! parameter-only check shows in STOP with the diag value that goes with them
//! (docs/semantics.md C15), the manual's LOADSENSING example table (LS5) and the PLCopen
//! defaults of SF_ResetButton and SF_Antivalent (PO12). Every rule of every block is
//! covered by the C-level corpus (project/tests/bad_input/c_rules.toml).

use safelogic::ffi::{
    sl_reason_text, sl_sf_antivalent_cycle, sl_sf_antivalent_defaults, sl_sf_antivalent_init,
    sl_sf_resetbutton_cycle, sl_sf_resetbutton_defaults, sl_sf_resetbutton_init,
};
use safelogic::*;
use std::ffi::c_void;

mod common;
use common::FIG_132;

/// The sentence `sl_reason_text` writes for the block at `p` (asserting SL_OK).
fn reason<B>(tag: u16, p: &B) -> String {
    let mut buf = [0xAAu8; 300];
    // SAFETY: a live block of the type the tag names; a buffer of its length.
    let rc = unsafe {
        sl_reason_text(
            tag,
            (p as *const B).cast::<c_void>(),
            buf.as_mut_ptr().cast(),
            buf.len(),
        )
    };
    assert_eq!(rc, SL_OK);
    std::ffi::CStr::from_bytes_until_nul(&buf)
        .unwrap()
        .to_str()
        .unwrap()
        .to_string()
}

#[test]
fn limit_min_above_max_from_the_parameters_shows_0x4090_with_its_values() {
    let mut fb = FB_LIMIT_INT {
        wInputActive: SL_LIMIT_ACTIVE_ANALOGIN,
        nMinimumValue: -5,
        nMaximumValue: -7,
        ..Default::default()
    };
    assert_eq!(fb.init(), SL_E_CONFIG);
    assert_eq!(fb.nState, SL_STATE_STOP);
    assert_eq!(
        (fb.nDiag, fb.nDiagTextId, fb.dwDiagPar2, fb.dwDiagPar3),
        (
            SL_DIAG_LIMIT_MIN_ABOVE_MAX,
            SL_TEXT_LIMIT_MIN_ABOVE_MAX,
            -5i32 as u32,
            -7i32 as u32
        )
    );
    assert_eq!(
        reason(SL_TYPE_LIMIT_INT, &fb),
        "LIMIT_INT: nMinimumValue (-5) must be <= nMaximumValue (-7) [Text ID 0x4090]"
    );
    // A cycle in STOP keeps showing it; valid parameters clear it at the next latch.
    fb.bRun = 1;
    assert_eq!(fb.cycle(1), SL_E_CONFIG);
    assert_eq!((fb.nDiag, fb.nDiagTextId), (1, 0x4090));
    fb.bRun = 0;
    fb.cycle(2);
    fb.nMaximumValue = 7;
    fb.bRun = 1;
    assert_eq!(fb.cycle(3), SL_OK);
    assert_eq!((fb.nDiag, fb.nDiagTextId, fb.dwDiagPar2), (0, 0, 0));
    assert_eq!(reason(SL_TYPE_LIMIT_INT, &fb), "LIMIT_INT: no refusal");

    let mut fb = FB_LIMIT_UDINT {
        wInputActive: SL_LIMIT_ACTIVE_ANALOGIN,
        nMinimumValue: 4_000_000_000,
        nMaximumValue: 3,
        ..Default::default()
    };
    assert_eq!(fb.init(), SL_E_CONFIG);
    assert_eq!(
        (fb.nDiag, fb.nDiagTextId, fb.dwDiagPar2, fb.dwDiagPar3),
        (1, 0x4090, 4_000_000_000, 3)
    );
}

#[test]
fn an_error_with_valid_parameters_is_told_by_its_latched_diag() {
    // Min > Max from the inputs: the manual's ERROR, not a refusal of the parameters.
    let mut fb = FB_LIMIT_INT {
        wInputActive: SL_LIMIT_ACTIVE_ANALOGIN | SL_LIMIT_ACTIVE_MINVALUE,
        nMinValue: 9,
        nMaximumValue: 3,
        bRun: 1,
        ..Default::default()
    };
    assert_eq!(fb.init(), SL_OK);
    assert_eq!(fb.cycle(1), SL_OK);
    assert_eq!(fb.nState, SL_STATE_ERROR);
    assert_eq!(
        reason(SL_TYPE_LIMIT_INT, &fb),
        "LIMIT_INT: ERROR: MinValue is greater than MaxValue [Text ID 0x4090, Par2 9, Par3 3]"
    );
}

/// A valid excentric CAMMONITOR_UINT (M 1000, J 10) with one fixed value moved.
fn cammonitor(tdc1_ll: u16) -> FB_CAMMONITOR_UINT {
    FB_CAMMONITOR_UINT {
        wInputActive: SL_CAMMONITOR_ACTIVE_RESET | SL_CAMMONITOR_ACTIVE_POSITION,
        tStopDetectionTime: 100,
        nAllowedPositionJitter: 10,
        nMaxPosition: 1000,
        nTDC1LowerLimitFix: tdc1_ll,
        nTDC1UpperLimitFix: 50,
        nBDCLowerLimitFix: 300,
        nBDCUpperLimitFix: 700,
        nOverrunMaxFix: 100,
        ..Default::default()
    }
}

#[test]
fn cammonitor_and_slp_refused_in_stop_show_the_diag_value_of_their_text_id() {
    assert_eq!(cammonitor(900).init(), SL_OK);
    let mut fb = cammonitor(995);
    assert_eq!(fb.init(), SL_E_CONFIG);
    assert_eq!(fb.nState, SL_STATE_STOP);
    assert_eq!(
        (fb.nDiagTextId, fb.dwDiagPar2, fb.dwDiagPar3),
        (SL_TEXT_CAMMONITOR_TDC1LL_MAX, 1005, 1000)
    );
    // The same relation as in ERROR: nDiag = Text ID - 0x4000.
    assert_eq!(fb.nDiag, fb.nDiagTextId - 0x4000);
    assert_eq!(
        reason(SL_TYPE_CAMMONITOR_UINT, &fb),
        "CAMMONITOR_UINT: nTDC1LowerLimitFix: TDC1LowerLimit + AllowedPositionJitter must be \
         <= MaxPosition (Par2 1005, Par3 1000) [Text ID 0x4015]"
    );

    let mut slp = FB_SLP {
        wInputActive: SL_SLP_ACTIVE_SAFEPOSVALID
            | SL_SLP_ACTIVE_SINGLETURNPOS
            | SL_SLP_ACTIVE_MULTITURNPOS,
        nMultiturnPosLLFix: 5,
        ..Default::default()
    };
    assert_eq!(slp.init(), SL_E_CONFIG);
    assert_eq!(slp.nDiagTextId, SL_TEXT_SLP_MULTITURN_LL_ABOVE_UL);
    assert_eq!(slp.nDiag, SL_DIAG_SLP_MULTITURN_LL_ABOVE_UL);
}

fn loadsensing(table: &[[i16; 5]; 25]) -> FB_LOADSENSING_INT {
    let mut fb = FB_LOADSENSING_INT {
        wInputActive: SL_LOADSENSING_ACTIVE_ANALOGINX | SL_LOADSENSING_ACTIVE_ANALOGINY,
        nRowCount: 25,
        ..Default::default()
    };
    for (row, v) in fb.aRow.iter_mut().zip(table) {
        (row.nX, row.nY1, row.nY2, row.nWY1, row.nWY2) = (v[0], v[1], v[2], v[3], v[4]);
    }
    fb
}

#[test]
fn the_manuals_loadsensing_table_is_refused_by_row_1_and_its_rule() {
    // Row 1 breaks the formula the same section states (Y1 <= WY1 < WY2 <= Y2): -80 > -100.
    let mut fb = loadsensing(&FIG_132);
    assert_eq!(fb.init(), SL_E_CONFIG);
    assert_eq!(fb.nState, SL_STATE_STOP);
    assert_eq!((fb.bValid, fb.bWarning), (0, 0));
    assert_eq!(
        reason(SL_TYPE_LOADSENSING_INT, &fb),
        "LOADSENSING_INT row 1: nWY2 (-80) must be <= nY2 (-100) [reason 0xE00B]"
    );
    // With row 1's WY2 mirrored (-120, 20 inside Y2 as WY1 is inside Y1) every row holds.
    let mut fixed = FIG_132;
    fixed[0][4] = -120;
    let mut fb = loadsensing(&fixed);
    assert_eq!(fb.init(), SL_OK);
    assert_eq!(
        reason(SL_TYPE_LOADSENSING_INT, &fb),
        "LOADSENSING_INT: no refusal"
    );
    // And it evaluates: AnalogInX -12 uses row 4 (X -15), AnalogInY 50 lies within 0..100.
    (fb.nAnalogInX, fb.nAnalogInY, fb.bRun) = (-12, 50, 1);
    assert_eq!(fb.cycle(1), SL_OK);
    assert_eq!(fb.bValid, 1);
}

#[test]
fn the_brief_examples_read_as_sentences() {
    let fb = FB_TWOHAND {
        wInputActive: 0b0101,
        tDiscTimePairs: 3000,
        ..Default::default()
    };
    assert_eq!(
        reason(SL_TYPE_TWOHAND, &fb),
        "TWOHAND: tDiscTimePairs (3000 ms) must be <= 2500 ms [reason 0xE001]"
    );
}

#[test]
fn sl_reason_text_refuses_bad_pointers_and_truncates() {
    let fb = FB_TWOHAND::default();
    let p = (&fb as *const FB_TWOHAND).cast::<c_void>();
    let mut buf = [0xAAu8; 16];
    // SAFETY: every pointer is NULL, misaligned on purpose (never read), or live.
    unsafe {
        assert_eq!(
            sl_reason_text(SL_TYPE_TWOHAND, p, std::ptr::null_mut(), 5),
            SL_E_NULL
        );
        assert_eq!(
            sl_reason_text(SL_TYPE_TWOHAND, p, std::ptr::null_mut(), 0),
            SL_E_NULL
        );
        assert_eq!(
            sl_reason_text(SL_TYPE_TWOHAND, p, buf.as_mut_ptr().cast(), 0),
            SL_OK
        );
        assert_eq!(buf[0], 0xAA, "nothing written with nLen 0");
        let b = buf.as_mut_ptr().cast();
        assert_eq!(sl_reason_text(999, p, b, buf.len()), SL_E_CONFIG);
        assert_eq!(buf[0], 0);
        assert_eq!(
            sl_reason_text(SL_TYPE_TWOHAND, std::ptr::null(), b, 16),
            SL_E_NULL
        );
        assert_eq!(buf[0], 0);
        let odd = p.cast::<u8>().add(1).cast::<c_void>();
        assert_eq!(sl_reason_text(SL_TYPE_TWOHAND, odd, b, 16), SL_E_ALIGNMENT);
        assert_eq!(sl_reason_text(SL_TYPE_TWOHAND, p, b, 16), SL_OK);
    }
    // 15 bytes of the sentence and the NUL.
    assert_eq!(&buf[..16], b"TWOHAND: wInput\0");
}

#[test]
fn the_plcopen_defaults_are_written_on_request_and_zero_stays_not_configured() {
    // Zeroed: TrailingMinimum 0 is the block's parameter error at activation.
    let mut zero = SF_ResetButton::default();
    // SAFETY: live, exclusively borrowed blocks (here and below).
    unsafe {
        assert_eq!(sl_sf_resetbutton_init(&mut zero), SL_OK);
        zero.ResetRequested = 1;
        sl_sf_resetbutton_cycle(&mut zero, 1);
    }
    assert_eq!((zero.DiagCode, zero.Error), (0xC000, 1));
    assert_eq!(
        reason(SL_TYPE_SF_RESETBUTTON, &zero),
        "SF_ResetButton: TrailingMinimum (0 ms) must be >= 100 ms [reason 0xE002]"
    );

    // An output left over is overwritten: the whole struct is the defaults.
    let mut rb = SF_ResetButton {
        DiagCode: 7,
        ..Default::default()
    };
    unsafe {
        assert_eq!(sl_sf_resetbutton_defaults(&mut rb), SL_OK);
        assert_eq!(
            (
                rb.ResetRequested,
                rb.TrailingMinimum,
                rb.TrailingMaximum,
                rb.DiagCode
            ),
            (1, 350, 2000, 0)
        );
        assert_eq!(sl_sf_resetbutton_init(&mut rb), SL_OK);
        sl_sf_resetbutton_cycle(&mut rb, 1);
        assert_eq!(sl_sf_resetbutton_defaults(std::ptr::null_mut()), SL_E_NULL);
    }
    // Activated by ResetRequested TRUE, waiting for the button.
    assert_eq!((rb.DiagCode, rb.Error, rb.Ready), (0x83E2, 0, 1));

    let mut av = SF_Antivalent::default();
    unsafe {
        assert_eq!(sl_sf_antivalent_defaults(&mut av), SL_OK);
        assert_eq!((av.S_ChannelNO, av.S_ChannelNC, av.Activate), (1, 0, 0));
        assert_eq!(sl_sf_antivalent_init(&mut av), SL_OK);
        av.Activate = 1;
        sl_sf_antivalent_cycle(&mut av, 1);
        assert_eq!(sl_sf_antivalent_defaults(std::ptr::null_mut()), SL_E_NULL);
    }
    assert_eq!(av.Error, 0);
}
