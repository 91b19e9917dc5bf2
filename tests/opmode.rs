//! FB OPMODE (manual §4.3; ABI §3, §5, §7, §9; docs/semantics.md rows O1–O12 and C1–C12):
//! layout, configuration, every state and output, the mode-change discrepancy time, the
//! restart samples of §4.3.4, invalid BOOLs, the envelope errors, the C functions, and
//! property tests. Expected values come from the manual, the ABI and semantics.md.

mod common;
use common::{aligned_tail, null_refused, offsets, output_base};

use proptest::prelude::*;
use safelogic::group::{self, Member};
use safelogic::*;
use std::mem::{offset_of, size_of};

const ALL: u16 = 0xFF;

fn opmode(active: u16, disc: u32, options: u32) -> FB_OPMODE {
    common::ready(FB_OPMODE {
        wInputActive: active,
        tDiscTime: disc,
        dwOptions: options,
        ..Default::default()
    })
}

/// Sets OpIn1..8 from bit 0..7 of `bits` (bytes 0/1).
fn set(b: &mut FB_OPMODE, bits: u8) {
    for (i, r) in ins(b).into_iter().enumerate() {
        *r = (bits >> i) & 1;
    }
}

fn ins(b: &mut FB_OPMODE) -> [&mut u8; 8] {
    [
        &mut b.bOpIn1,
        &mut b.bOpIn2,
        &mut b.bOpIn3,
        &mut b.bOpIn4,
        &mut b.bOpIn5,
        &mut b.bOpIn6,
        &mut b.bOpIn7,
        &mut b.bOpIn8,
    ]
}

/// OpOut1..8 as bits 0..7 (each byte must be 0 or 1).
fn outs(b: &FB_OPMODE) -> u8 {
    let o = [
        b.bOpOut1, b.bOpOut2, b.bOpOut3, b.bOpOut4, b.bOpOut5, b.bOpOut6, b.bOpOut7, b.bOpOut8,
    ];
    o.iter().enumerate().fold(0, |m, (i, &v)| {
        assert!(v <= 1, "output byte {v}");
        m | (v << i)
    })
}

/// Runs a block in automatic mode into RUN with mode `bits` at `t` (two calls: STOP → SAFE,
/// SAFE → RUN, O7).
fn running_auto(active: u16, disc: u32, bits: u8, t: u32) -> FB_OPMODE {
    let mut b = opmode(active, disc, 0);
    set(&mut b, bits);
    b.bRun = 1;
    assert_eq!(b.cycle(t), SL_OK);
    assert_eq!(b.nState, SL_STATE_SAFE);
    assert_eq!(b.cycle(t + 1), SL_OK);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, bits));
    b
}

/// Manual restart: RUN with mode `bits` through the restart sequence, ending at `t + 3`.
fn running_manual(active: u16, disc: u32, bits: u8, t: u32) -> FB_OPMODE {
    let mut b = opmode(active, disc, SL_OPT_MANUAL_RESTART);
    set(&mut b, bits);
    b.bRun = 1;
    b.cycle(t);
    b.cycle(t + 1);
    assert_eq!(b.nState, SL_STATE_SAFE, "start-up needs a restart (§4.3.2)");
    b.bRestart = 1;
    b.cycle(t + 2);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_START, 0));
    b.bRestart = 0;
    b.cycle(t + 3);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, bits));
    b
}

fn assert_error(b: &FB_OPMODE, diag: u16) {
    assert_eq!(b.nState, SL_STATE_ERROR);
    assert_eq!((b.bError, outs(b)), (1, 0), "ERROR: Error=1 OpOutX=0");
    assert_eq!(b.nDiag, diag);
}

#[test]
fn layout_matches_the_abi() {
    // ABI §9: inputs at the manual's offsets, outputs at base + 0 and + 8 … + 15.
    offsets!(FB_OPMODE; bRestart => 0, bOpIn1 => 8, bOpIn8 => 15, bRun => 16, bErrAck => 17);
    let base = output_base!(FB_OPMODE);
    offsets!(FB_OPMODE, from base; bOpOut1 => 8, bOpOut8 => 15);
    aligned_tail!(FB_OPMODE);
    assert!(size_of::<SL_OPMODE_PRIVATE>() <= 64);
    assert_eq!(SL_TYPE_OPMODE, 7);
}

#[test]
fn init_gives_the_power_up_image_and_keeps_the_inputs() {
    let mut b = FB_OPMODE {
        wInputActive: 0b11,
        bOpIn1: 1,
        bRestart: 1,
        bRun: 1,
        bOpOut2: 1,
        bError: 1,
        nState: 9,
        nDiag: 7,
        ..Default::default()
    };
    let before = b;
    assert_eq!(b.init(), SL_OK);
    // C1: outputs FALSE, STOP, diag 0; ABI §4: no VAR_INPUT touched.
    assert_eq!(
        (b.bError, outs(&b), b.nState, b.nDiag),
        (0, 0, SL_STATE_STOP, 0)
    );
    assert_eq!(
        (b.bOpIn1, b.bRestart, b.bRun, b.wInputActive),
        (
            before.bOpIn1,
            before.bRestart,
            before.bRun,
            before.wInputActive
        )
    );
}

#[test]
fn configuration_errors() {
    // O2: at least two active inputs (§4.3.1 NOTICE), bits 0-7 only, tDiscTime <= 65535,
    // only SL_OPT_MANUAL_RESTART.
    let bad = [
        (0u16, 0u32, 0u32),
        (0b1, 0, 0),
        (0b1000_0000, 0, 0),
        (0x1FF, 0, 0),
        (0x100 | 0b1, 0, 0),
        (0b11, SL_TIME_PARAM_MAX + 1, 0),
        (0b11, 0, SL_OPT_EDM1),
        (0b11, 0, SL_OPT_FUNCTION_TEST),
        (0b11, 0, SL_OPT_SAFE_INPUTS_AFTER_DISC),
        (0b11, 0, 1 << 8),
    ];
    for (active, disc, options) in bad {
        let mut b = common::refused(
            FB_OPMODE {
                wInputActive: active,
                tDiscTime: disc,
                dwOptions: options,
                ..Default::default()
            },
            &[],
        );
        assert_eq!((b.nState, outs(&b), b.bError), (SL_STATE_STOP, 0, 0));
        // C6: every call returns SL_E_CONFIG, the block stays in STOP even with bRun TRUE.
        b.bRun = 1;
        b.bOpIn1 = 1;
        assert_eq!(b.cycle(0), SL_E_CONFIG);
        assert_eq!(b.cycle(1), SL_E_CONFIG);
        assert_eq!((b.nState, outs(&b)), (SL_STATE_STOP, 0));
    }
    let good = [
        (0b11u16, 0u32, 0u32),
        (0b1000_0001, SL_TIME_PARAM_MAX, SL_OPT_MANUAL_RESTART),
        (0xFF, 1, 0),
    ];
    for (active, disc, options) in good {
        common::ready(FB_OPMODE {
            wInputActive: active,
            tDiscTime: disc,
            dwOptions: options,
            ..Default::default()
        });
    }
}

#[test]
fn invalid_parameters_are_fixed_in_stop_and_latched_at_the_next_start() {
    let mut b = common::refused(
        FB_OPMODE {
            wInputActive: 0b1,
            ..Default::default()
        },
        &[],
    );
    b.bRun = 1;
    assert_eq!(b.cycle(0), SL_E_CONFIG);
    b.bRun = 0;
    b.wInputActive = 0b11;
    b.bOpIn2 = 1;
    assert_eq!(b.cycle(1), SL_E_CONFIG, "latched set still invalid in STOP");
    b.bRun = 1;
    assert_eq!(b.cycle(2), SL_OK, "STOP -> run latches the new parameters");
    assert_eq!(b.nState, SL_STATE_SAFE);
    b.cycle(3);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b10));
}

#[test]
fn stop_while_run_is_false() {
    let mut b = opmode(ALL, 0, 0);
    set(&mut b, 0b1);
    for t in 0..3 {
        assert_eq!(b.cycle(t), SL_OK);
        // §4.3.2 STOP: Error=0 OpOutX=0.
        assert_eq!((b.nState, b.bError, outs(&b)), (SL_STATE_STOP, 0, 0));
    }
}

#[test]
fn exactly_one_input_selects_its_output() {
    // §4.3.1, §4.3.2 RUN "OpOutX=OpInX"; O1.
    for x in 0..8 {
        let b = running_auto(ALL, 0, 1 << x, 100);
        assert_eq!(b.bError, 0);
        assert_eq!(b.nDiag, 0);
    }
}

#[test]
fn none_or_more_than_one_input_gives_safe() {
    // §4.3.2 SAFE "if not exactly one input OpInX is TRUE": Error=0, OpOutX=0.
    let mut b = running_auto(ALL, 0, 0b100, 0);
    for sel in [0u8, 0b11, 0b1010_0000, 0xFF, 0b101] {
        set(&mut b, sel);
        assert_eq!(b.cycle(10), SL_OK);
        assert_eq!(
            (b.nState, b.bError, outs(&b)),
            (SL_STATE_SAFE, 0, 0),
            "{sel:#b}"
        );
    }
    set(&mut b, 0b100_0000);
    b.cycle(11);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b100_0000));
}

#[test]
fn inactive_inputs_are_ignored() {
    // O1: input 3 is not active; its TRUE neither selects nor counts as a second mode.
    let mut b = running_auto(0b11, 0, 0b01, 0);
    set(&mut b, 0b101);
    b.cycle(5);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b001));
    set(&mut b, 0b100);
    b.cycle(6);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    // An invalid byte on an inactive input is not read (C7).
    b.bOpIn5 = 7;
    b.bOpIn2 = 1;
    assert_eq!(b.cycle(7), SL_OK);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b010));
}

#[test]
fn automatic_mode_follows_a_direct_change_in_the_same_call() {
    // O9 without manual restart.
    let mut b = running_auto(ALL, 0, 0b1, 0);
    set(&mut b, 0b1000);
    b.cycle(5);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b1000));
    // Through "none" it goes via SAFE and back to RUN without a restart.
    set(&mut b, 0);
    b.cycle(6);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    set(&mut b, 0b1);
    b.cycle(7);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b1));
}

#[test]
fn automatic_mode_ignores_the_restart_input() {
    // O10: Restart not read without the option; no START, no SL_E_INVALID_BOOL for it.
    let mut b = opmode(ALL, 0, 0);
    set(&mut b, 0b1);
    b.bRun = 1;
    b.bRestart = 1;
    b.cycle(0);
    assert_eq!(b.cycle(1), SL_OK);
    assert_eq!(b.nState, SL_STATE_RUN);
    b.bRestart = 0x55;
    assert_eq!(b.cycle(2), SL_OK);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b1));
}

#[test]
fn run_false_stops_and_outputs_go_off_at_once() {
    let mut b = running_auto(ALL, 0, 0b10, 0);
    b.bRun = 0;
    assert_eq!(b.cycle(5), SL_OK);
    assert_eq!((b.nState, outs(&b), b.bError), (SL_STATE_STOP, 0, 0));
    // Restart from STOP: SAFE first, then RUN (O7).
    b.bRun = 1;
    b.cycle(6);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    b.cycle(7);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b10));
}

#[test]
fn mode_change_discrepancy_just_below_and_at_the_limit() {
    // O3: no mode for less than tDiscTime is fine ...
    let mut b = running_auto(ALL, 100, 0b1, 0);
    set(&mut b, 0);
    b.cycle(1000);
    assert_eq!(b.nState, SL_STATE_SAFE);
    b.cycle(1099);
    assert_eq!(b.nState, SL_STATE_SAFE);
    set(&mut b, 0b10);
    assert_eq!(b.cycle(1099), SL_OK);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b10));
    // ... the full tDiscTime is an error, diag bit 0.
    set(&mut b, 0);
    b.cycle(2000);
    b.cycle(2099);
    assert_eq!(b.nState, SL_STATE_SAFE);
    assert_eq!(b.cycle(2100), SL_OK);
    assert_error(&b, SL_DIAG_OPMODE_DISC);
}

#[test]
fn more_than_one_mode_is_timed_as_well() {
    let mut b = running_auto(ALL, 50, 0b1, 0);
    set(&mut b, 0b11);
    b.cycle(10);
    b.cycle(30);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    // A switch from "two" to "none" does not restart the timer: both are not one mode.
    set(&mut b, 0);
    b.cycle(40);
    b.cycle(59);
    assert_eq!(b.nState, SL_STATE_SAFE);
    b.cycle(60);
    assert_error(&b, SL_DIAG_OPMODE_DISC);
}

#[test]
fn direct_change_starts_no_timer_and_zero_switches_monitoring_off() {
    // O4: X -> Y directly, nothing timed.
    let mut b = running_auto(ALL, 10, 0b1, 0);
    for (i, t) in (100..200).step_by(20).enumerate() {
        set(&mut b, 1 << (i % 8));
        b.cycle(t);
        assert_eq!(b.nState, SL_STATE_RUN);
    }
    // O3: tDiscTime 0 = no monitoring, however long no mode is selected.
    let mut b = running_auto(ALL, 0, 0b1, 0);
    set(&mut b, 0);
    for t in (10..1_000_000).step_by(99_999) {
        assert_eq!(b.cycle(t), SL_OK);
        assert_eq!(b.nState, SL_STATE_SAFE);
    }
}

#[test]
fn no_mode_at_start_up_is_timed_from_the_first_running_call() {
    // O3, O7: STOP -> SAFE at t=0; the timer starts in the next call (t=5).
    let mut b = opmode(ALL, 100, 0);
    b.bRun = 1;
    b.cycle(0);
    b.cycle(5);
    b.cycle(104);
    assert_eq!(b.nState, SL_STATE_SAFE);
    b.cycle(105);
    assert_error(&b, SL_DIAG_OPMODE_DISC);
}

#[test]
fn discrepancy_timer_works_across_the_clock_wrap() {
    let t0 = u32::MAX - 20;
    let mut b = running_auto(ALL, 40, 0b1, t0);
    set(&mut b, 0);
    b.cycle(t0.wrapping_add(5));
    b.cycle(t0.wrapping_add(44));
    assert_eq!(b.nState, SL_STATE_SAFE);
    assert_eq!(b.cycle(t0.wrapping_add(45)), SL_OK);
    assert_error(&b, SL_DIAG_OPMODE_DISC);
}

#[test]
fn discrepancy_error_is_acknowledged_only_with_one_mode_selected() {
    let mut b = running_auto(ALL, 20, 0b1, 0);
    set(&mut b, 0);
    b.cycle(10);
    b.cycle(30);
    assert_error(&b, SL_DIAG_OPMODE_DISC);
    // O6: ErrAck while no mode is selected: consumed, nothing happens (C8).
    b.bErrAck = 1;
    b.cycle(31);
    assert_error(&b, SL_DIAG_OPMODE_DISC);
    set(&mut b, 0b100);
    b.cycle(32);
    assert_error(&b, SL_DIAG_OPMODE_DISC);
    assert_eq!(
        outs(&b),
        0,
        "no output in ERROR even with a valid selection"
    );
    b.bErrAck = 0;
    b.cycle(33);
    assert_error(&b, SL_DIAG_OPMODE_DISC);
    b.bErrAck = 1;
    b.cycle(34);
    // §4.3.2 RESET: Error=0 OpOutX=0; C9: diag cleared.
    assert_eq!(
        (b.nState, b.bError, outs(&b), b.nDiag),
        (SL_STATE_RESET, 0, 0, 0)
    );
    b.cycle(35);
    assert_eq!(
        b.nState, SL_STATE_RESET,
        "RESET is left on the falling edge"
    );
    b.bErrAck = 0;
    b.cycle(36);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    b.cycle(37);
    assert_eq!((b.nState, outs(&b), b.bError), (SL_STATE_RUN, 0b100, 0));
}

#[test]
fn two_modes_keep_the_error_and_an_ack_with_run_false_goes_to_stop() {
    let mut b = running_auto(0b11, 5, 0b1, 0);
    set(&mut b, 0b11);
    b.cycle(1);
    b.cycle(6);
    assert_error(&b, SL_DIAG_OPMODE_DISC);
    b.bErrAck = 1;
    b.cycle(7);
    assert_eq!(
        b.nState, SL_STATE_ERROR,
        "two modes: the error remains (O6)"
    );
    b.bErrAck = 0;
    b.cycle(8);
    // Run FALSE: ERROR stays until acknowledged (ABI §7).
    b.bRun = 0;
    set(&mut b, 0b10);
    b.cycle(9);
    assert_eq!(b.nState, SL_STATE_ERROR);
    b.bErrAck = 1;
    b.cycle(10);
    assert_eq!(b.nState, SL_STATE_RESET);
    b.bErrAck = 0;
    b.cycle(11);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_STOP, 0));
}

#[test]
fn manual_restart_sample_1_change_of_mode_then_restart() {
    // §4.3.4 sample 1: mode change, then acknowledgement through the Restart input.
    let mut b = running_manual(ALL, 0, 0b1, 0);
    set(&mut b, 0);
    b.cycle(10);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    set(&mut b, 0b10);
    b.cycle(11);
    assert_eq!(
        (b.nState, outs(&b)),
        (SL_STATE_SAFE, 0),
        "a new mode needs the restart"
    );
    b.cycle(500);
    assert_eq!(b.nState, SL_STATE_SAFE);
    b.bRestart = 1;
    b.cycle(501);
    // §4.3.2 START: Error=0 OpOutX=0.
    assert_eq!((b.nState, b.bError, outs(&b)), (SL_STATE_START, 0, 0));
    b.cycle(900);
    assert_eq!(b.nState, SL_STATE_START, "no time monitoring of Restart");
    b.bRestart = 0;
    b.cycle(901);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b10));
}

#[test]
fn manual_restart_sample_2_restart_before_the_mode_change() {
    // §4.3.4 sample 2.
    let mut b = running_manual(ALL, 0, 0b1, 0);
    b.bRestart = 1;
    b.cycle(10);
    assert_eq!(
        (b.nState, outs(&b)),
        (SL_STATE_RUN, 0b1),
        "Restart in RUN is ignored (O9)"
    );
    set(&mut b, 0);
    b.cycle(11);
    assert_eq!(
        (b.nState, outs(&b)),
        (SL_STATE_SAFE, 0),
        "OpIn1 TRUE -> FALSE: state 3"
    );
    set(&mut b, 0b10);
    b.cycle(12);
    assert_eq!(
        (b.nState, outs(&b)),
        (SL_STATE_START, 0),
        "OpIn2 TRUE with Restart already TRUE: state 6"
    );
    b.bRestart = 0;
    b.cycle(13);
    assert_eq!(
        (b.nState, outs(&b)),
        (SL_STATE_RUN, 0b10),
        "falling edge: OpOut2"
    );
}

#[test]
fn manual_restart_needs_a_restart_at_start_up_and_holds_through_it() {
    let mut b = opmode(ALL, 0, SL_OPT_MANUAL_RESTART);
    set(&mut b, 0b1);
    b.bRun = 1;
    b.cycle(0);
    for t in 1..5 {
        b.cycle(t);
        assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    }
    // O12: a Restart held through start-up leads to START, its falling edge to RUN.
    let mut b = opmode(ALL, 0, SL_OPT_MANUAL_RESTART);
    set(&mut b, 0b1);
    b.bRun = 1;
    b.bRestart = 1;
    b.cycle(0);
    assert_eq!(b.nState, SL_STATE_SAFE);
    b.cycle(1);
    assert_eq!(b.nState, SL_STATE_START);
    b.bRestart = 0;
    b.cycle(2);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b1));
}

#[test]
fn restart_without_a_single_mode_does_nothing() {
    // §4.3.4: START only "If exactly one OpIn input is TRUE and the Restart signal is TRUE".
    let mut b = opmode(ALL, 0, SL_OPT_MANUAL_RESTART);
    b.bRun = 1;
    b.cycle(0);
    for (t, sel) in [(1u32, 0u8), (3, 0b11)] {
        set(&mut b, sel);
        b.bRestart = 1;
        b.cycle(t);
        assert_eq!(b.nState, SL_STATE_SAFE);
        b.bRestart = 0;
        b.cycle(t + 1);
        assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    }
}

#[test]
fn start_confirms_only_the_mode_selected_when_it_was_entered() {
    // O8: START with mode 1, the selection changes to mode 2: back to SAFE, and the falling
    // edge enables nothing.
    let mut b = opmode(ALL, 0, SL_OPT_MANUAL_RESTART);
    set(&mut b, 0b1);
    b.bRun = 1;
    b.cycle(0);
    b.bRestart = 1;
    b.cycle(1);
    assert_eq!(b.nState, SL_STATE_START);
    set(&mut b, 0b10);
    b.bRestart = 0;
    b.cycle(2);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    // Mode lost in START, Restart still held: SAFE; the mode back: START again.
    b.bRestart = 1;
    b.cycle(3);
    assert_eq!(b.nState, SL_STATE_START);
    set(&mut b, 0);
    b.cycle(4);
    assert_eq!(b.nState, SL_STATE_SAFE);
    set(&mut b, 0b10);
    b.cycle(5);
    assert_eq!(b.nState, SL_STATE_START);
    // Two modes at the falling edge: no output (§4.3.4 "still logical 1" check).
    set(&mut b, 0b110);
    b.bRestart = 0;
    b.cycle(6);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
}

#[test]
fn manual_restart_direct_change_of_mode_switches_off() {
    // O9: with manual restart, even X -> Y without an intermediate state needs a restart.
    let mut b = running_manual(ALL, 0, 0b1, 0);
    set(&mut b, 0b1000_0000);
    b.cycle(10);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    // Back to the old mode: still a restart (§4.3.2 Restart: "when all outputs are switched
    // to the safe state").
    set(&mut b, 0b1);
    b.cycle(11);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    b.bRestart = 1;
    b.cycle(12);
    b.bRestart = 0;
    b.cycle(13);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b1));
}

#[test]
fn manual_restart_after_an_error_and_reset() {
    let mut b = running_manual(ALL, 10, 0b1, 0);
    set(&mut b, 0);
    b.cycle(20);
    b.cycle(30);
    assert_error(&b, SL_DIAG_OPMODE_DISC);
    set(&mut b, 0b1);
    b.bErrAck = 1;
    b.cycle(31);
    assert_eq!(b.nState, SL_STATE_RESET);
    b.bErrAck = 0;
    b.cycle(32);
    b.cycle(33);
    assert_eq!(
        (b.nState, outs(&b)),
        (SL_STATE_SAFE, 0),
        "after RESET the restart is needed again"
    );
    b.bRestart = 1;
    b.cycle(34);
    b.bRestart = 0;
    b.cycle(35);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b1));
}

#[test]
fn discrepancy_timer_runs_in_start_too() {
    // O3: START with a lost mode falls back to SAFE, and the intermediate state is timed.
    let mut b = opmode(ALL, 30, SL_OPT_MANUAL_RESTART);
    set(&mut b, 0b1);
    b.bRun = 1;
    b.cycle(0);
    b.bRestart = 1;
    b.cycle(1);
    assert_eq!(b.nState, SL_STATE_START);
    set(&mut b, 0);
    b.cycle(2);
    b.cycle(31);
    assert_eq!(b.nState, SL_STATE_SAFE);
    b.cycle(32);
    assert_error(&b, SL_DIAG_OPMODE_DISC);
}

#[test]
fn invalid_mode_input_byte_means_no_mode() {
    // O5: invalid active byte -> no mode selected, outputs FALSE, SL_E_INVALID_BOOL.
    let mut b = running_auto(ALL, 0, 0b1, 0);
    b.bOpIn2 = 2;
    assert_eq!(b.cycle(5), SL_E_INVALID_BOOL);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    // The invalid byte on the selected input itself: also SAFE.
    b.bOpIn2 = 0;
    b.cycle(6);
    assert_eq!(b.nState, SL_STATE_RUN);
    b.bOpIn1 = 0xFF;
    assert_eq!(b.cycle(7), SL_E_INVALID_BOOL);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    // And it is timed like "no mode".
    let mut b = running_auto(ALL, 10, 0b1, 0);
    b.bOpIn3 = 9;
    b.cycle(100);
    b.cycle(109);
    assert_eq!(b.nState, SL_STATE_SAFE);
    assert_eq!(b.cycle(110), SL_E_INVALID_BOOL);
    assert_error(&b, SL_DIAG_OPMODE_DISC);
}

#[test]
fn invalid_restart_byte_never_enables() {
    // C7: an invalid Restart reads FALSE without an edge: START -> SAFE, no output.
    let mut b = opmode(ALL, 0, SL_OPT_MANUAL_RESTART);
    set(&mut b, 0b1);
    b.bRun = 1;
    b.cycle(0);
    b.bRestart = 1;
    b.cycle(1);
    assert_eq!(b.nState, SL_STATE_START);
    b.bRestart = 2;
    assert_eq!(b.cycle(2), SL_E_INVALID_BOOL);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
    b.bRestart = 0;
    assert_eq!(b.cycle(3), SL_OK);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_SAFE, 0));
}

#[test]
fn invalid_run_and_errack_bytes() {
    let mut b = running_auto(ALL, 0, 0b1, 0);
    b.bRun = 3;
    assert_eq!(b.cycle(5), SL_E_INVALID_BOOL);
    assert_eq!(
        (b.nState, outs(&b)),
        (SL_STATE_STOP, 0),
        "invalid Run reads FALSE"
    );
    b.bRun = 1;
    b.bErrAck = 0x80;
    assert_eq!(b.cycle(6), SL_E_INVALID_BOOL);
}

#[test]
fn parameter_change_while_running_is_an_error() {
    // C5: ABI §5 SL_E_PARAM_CHANGED, ERROR, diag bit 13.
    let mut b = running_auto(ALL, 0, 0b1, 0);
    b.tDiscTime = 5;
    assert_eq!(b.cycle(5), SL_E_PARAM_CHANGED);
    assert_error(&b, SL_DIAG_PARAM_CHANGED);
    b.bErrAck = 1;
    assert_eq!(
        b.cycle(6),
        SL_E_PARAM_CHANGED,
        "the mismatch remains while running"
    );
    assert_eq!(b.nState, SL_STATE_ERROR);
    // Restoring the old value clears the condition; a new edge acknowledges.
    b.tDiscTime = 0;
    b.bErrAck = 0;
    assert_eq!(b.cycle(7), SL_OK);
    b.bErrAck = 1;
    b.cycle(8);
    assert_eq!(b.nState, SL_STATE_RESET);

    // In STOP (bRun FALSE) a change is adopted at the next start.
    let mut b = running_auto(ALL, 0, 0b1, 0);
    b.bRun = 0;
    b.cycle(5);
    b.dwOptions = SL_OPT_MANUAL_RESTART;
    assert_eq!(b.cycle(6), SL_OK);
    b.bRun = 1;
    assert_eq!(b.cycle(7), SL_OK);
    b.cycle(8);
    assert_eq!(
        b.nState, SL_STATE_SAFE,
        "the new option (manual restart) is in force"
    );
    // Active bits change in STOP too.
    b.wInputActive = 0b11;
    b.bRun = 0;
    b.cycle(9);
    b.bRun = 1;
    assert_eq!(b.cycle(10), SL_OK);
}

#[test]
fn clock_going_backwards_is_an_error_in_every_state() {
    // C4: SL_E_CLOCK, ERROR, diag bit 14; one acknowledgement clears it.
    let mut b = running_auto(ALL, 0, 0b1, 1000);
    assert_eq!(b.cycle(999), SL_E_CLOCK);
    assert_error(&b, SL_DIAG_CLOCK);
    b.bErrAck = 1;
    assert_eq!(b.cycle(1000), SL_OK);
    assert_eq!(b.nState, SL_STATE_RESET);
    // In STOP as well.
    let mut b = opmode(ALL, 0, 0);
    b.cycle(100);
    assert_eq!(b.cycle(50), SL_E_CLOCK);
    assert_eq!((b.nState, b.bError), (SL_STATE_ERROR, 1));
}

#[test]
fn corrupted_private_state_is_detected() {
    let mut b = running_auto(ALL, 0, 0b1, 0);
    // The latched mode without its complement copy.
    b.stPrivate.stHeader.wAux ^= 0b11;
    assert_eq!(b.cycle(5), SL_E_CORRUPT);
    assert_error(&b, SL_DIAG_CORRUPT);

    // A consistently sealed but impossible latched mode (two bits) in RUN.
    let mut b = running_auto(ALL, 0, 0b1, 0);
    let h = &mut b.stPrivate.stHeader;
    h.wAux |= 0b10;
    h.wAuxCheck = !h.wAux;
    assert_eq!(b.cycle(5), SL_E_CORRUPT);
    assert_error(&b, SL_DIAG_CORRUPT);

    // A changed latched parameter copy (CRC mismatch).
    let mut b = running_auto(ALL, 0, 0b1, 0);
    b.stPrivate.wDiscTime = 7;
    assert_eq!(b.cycle(5), SL_E_CORRUPT);
    assert_eq!(b.nState, SL_STATE_ERROR);
}

#[test]
fn a_never_initialised_instance_initialises_on_its_first_cycle() {
    // C2.
    let mut b = FB_OPMODE {
        wInputActive: 0b11,
        bOpIn1: 1,
        bRun: 1,
        ..Default::default()
    };
    assert_eq!(b.cycle(0), SL_OK);
    assert_eq!(b.nState, SL_STATE_SAFE);
    b.cycle(1);
    assert_eq!((b.nState, outs(&b)), (SL_STATE_RUN, 0b1));
}

#[test]
fn c_functions() {
    let mut b = FB_OPMODE {
        wInputActive: 0b11,
        ..Default::default()
    };
    assert_eq!(unsafe { ffi::sl_opmode_init(&mut b) }, SL_OK);
    b.bRun = 1;
    b.bOpIn2 = 1;
    assert_eq!(unsafe { ffi::sl_opmode_cycle(&mut b, 0) }, SL_OK);
    assert_eq!(unsafe { ffi::sl_opmode_cycle(&mut b, 1) }, SL_OK);
    assert_eq!((b.nState, b.bOpOut2), (SL_STATE_RUN, 1));
    null_refused!(ffi::sl_opmode_init, ffi::sl_opmode_cycle);
    // sl_state_str returns the registry's static names (§4.3.2 states 1-6).
    let info = safelogic::registry::info(SL_TYPE_OPMODE).unwrap();
    let names: Vec<&str> = info.states.iter().map(|(_, n)| *n).collect();
    assert_eq!(
        names,
        ["RUN\0", "STOP\0", "SAFE\0", "ERROR\0", "RESET\0", "START\0"]
    );
    for (v, n) in info.states {
        assert_eq!(ffi::sl_state_str(SL_TYPE_OPMODE, *v), n.as_ptr().cast());
    }
    assert_eq!(info.name, "OPMODE");
    assert_eq!(
        common::diag_text(SL_TYPE_OPMODE, SL_DIAG_OPMODE_DISC),
        "discrepancy monitoring error"
    );
}

#[test]
fn opmode_as_a_group_member_with_links() {
    // OpOut1 -> AndIn1: the mode output enables a downstream AND in the same group cycle.
    let mut o = opmode(0b11, 10, 0);
    set(&mut o, 0b1);
    let mut a = common::ready(FB_AND {
        wInputActive: 0b11,
        bAndIn2: 1,
        ..Default::default()
    });
    let mut g = common::new_group(2, 1);
    let mut links = [SL_LINK::default(); 1];
    let l = common::link(
        0,
        offset_of!(FB_OPMODE, bOpOut1) as u16,
        1,
        offset_of!(FB_AND, bAndIn1) as u16,
    );
    {
        let mut ms: [&mut dyn Member; 2] = [&mut o, &mut a];
        assert_eq!(group::add_link(&mut g, &mut ms[..], &mut links, l), SL_OK);
        g.bRun = 1;
        for t in 0..3 {
            group::cycle(&mut g, &mut ms[..], &links, t);
        }
        assert_eq!(ms[1].output(offset_of!(FB_AND, bAndOut) as u16), Some(1));
    }
    // A discrepancy error of OPMODE stops the group.
    set(&mut o, 0);
    let mut t = 3;
    loop {
        let mut ms: [&mut dyn Member; 2] = [&mut o, &mut a];
        group::cycle(&mut g, &mut ms[..], &links, t);
        if g.nState == SL_STATE_ERROR {
            break;
        }
        t += 1;
        assert!(t < 100);
    }
    assert_eq!(t, 13, "10 ms after the mode was lost at t=3");
    assert_eq!(
        (o.nState, o.bError, a.nState, a.bAndOut),
        (SL_STATE_ERROR, 1, SL_STATE_STOP, 0)
    );
    // The member table through the C dispatch knows the type tag.
    let mut members = [SL_MEMBER::default(); 1];
    let mut g2 = SL_GROUP::default();
    common::c_group_init(
        &mut g2,
        (members.as_mut_ptr(), 1),
        (std::ptr::null_mut(), 0),
    );
    let mut o2 = opmode(0b11, 0, 0);
    assert_eq!(
        unsafe {
            ffi::sl_group_add_member(
                &mut g2,
                members.as_mut_ptr(),
                SL_TYPE_OPMODE,
                (&mut o2 as *mut FB_OPMODE).cast(),
                std::ptr::null_mut(),
            )
        },
        SL_OK
    );
}

/// One random call: Run, ErrAck, Restart, the eight input bytes (mostly 0/1, sometimes
/// invalid), time step.
fn step_strategy() -> impl Strategy<Value = (u8, u8, u8, [u8; 8], u32)> {
    let byte = prop_oneof![8 => 0u8..2, 1 => 2u8..=255];
    (
        prop_oneof![6 => Just(1u8), 1 => Just(0u8)],
        0u8..2,
        prop_oneof![4 => 0u8..2, 1 => Just(7u8)],
        [
            byte.clone(),
            byte.clone(),
            byte.clone(),
            byte.clone(),
            byte.clone(),
            byte.clone(),
            byte.clone(),
            byte,
        ],
        0u32..40,
    )
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_SAFE, SL_STATE_STOP, SL_STATE_ERROR];
    /// Manual §4.3.2 outputs per state; at most one output ever; an output is TRUE only in
    /// RUN and only while its input is the single valid selected mode (same call, O1, O5).
    fn outputs_follow_the_state_table(
        active in (0u16..256).prop_filter("two inputs", |a| a.count_ones() >= 2),
        disc in prop_oneof![Just(0u32), 1u32..120],
        manual in any::<bool>(),
        steps in proptest::collection::vec(step_strategy(), 1..150),
    ) {
        let options = if manual { SL_OPT_MANUAL_RESTART } else { 0 };
        let mut b = opmode(active, disc, options);
        let mut t = 0u32;
        for (run, ack, restart, bytes, dt) in steps {
            b.bRun = run;
            b.bErrAck = ack;
            b.bRestart = restart;
            for (r, v) in ins(&mut b).into_iter().zip(bytes) {
                *r = v;
            }
            t = t.wrapping_add(dt);
            let rc = b.cycle(t);
            common::saw(b.nState);
            prop_assert!(matches!(rc, SL_OK | SL_E_INVALID_BOOL), "rc {}", rc);
            prop_assert!((1..=6).contains(&b.nState), "state {}", b.nState);
            let o = outs(&b);
            prop_assert!(o.count_ones() <= 1, "two outputs: {:#b}", o);
            prop_assert_eq!(b.bError, u8::from(b.nState == SL_STATE_ERROR));
            if b.nState != SL_STATE_RUN {
                prop_assert_eq!(o, 0);
            }
            if b.nState != SL_STATE_ERROR {
                prop_assert_eq!(b.nDiag, 0);
            }
            if !manual {
                prop_assert!(b.nState != SL_STATE_START);
            }
            if o != 0 {
                // The output's input is the one active input that reads 1; every other
                // active input reads exactly 0.
                for (i, &v) in bytes.iter().enumerate() {
                    if active & (1 << i) != 0 {
                        prop_assert_eq!(v, u8::from(o == 1 << i), "input {}", i + 1);
                    }
                }
                prop_assert_eq!(run, 1);
            }
        }
    }
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_START];
    /// With manual restart an output only switches on in a call with a falling Restart
    /// edge (0 after 1), and never switches from one mode directly to another.
    fn manual_restart_enables_only_on_a_falling_edge(
        active in (0u16..256).prop_filter("two inputs", |a| a.count_ones() >= 2),
        steps in proptest::collection::vec(step_strategy(), 1..150),
    ) {
        let mut b = opmode(active, 0, SL_OPT_MANUAL_RESTART);
        let (mut t, mut prev_out, mut prev_restart) = (0u32, 0u8, 0u8);
        for (run, ack, restart, bytes, dt) in steps {
            b.bRun = run;
            b.bErrAck = ack;
            b.bRestart = restart;
            for (r, v) in ins(&mut b).into_iter().zip(bytes) {
                *r = v;
            }
            t = t.wrapping_add(dt);
            b.cycle(t);
            common::saw(b.nState);
            let o = outs(&b);
            if o != 0 && o != prev_out {
                prop_assert_eq!(prev_out, 0, "mode changed without passing the safe state");
                prop_assert!(prev_restart == 1 && restart == 0, "output on without a falling edge");
            }
            prev_out = o;
            prev_restart = restart;
        }
    }
}
