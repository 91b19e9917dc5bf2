//! FB ESTOP — every statement of manual §4.4 as a cycle-by-cycle test.
//!
//! References: "§4.4.x" = twinsafe-logic-fb-manual.txt; "ABI §n" = shared/design/ABI.md;
//! "Cn"/"Gn" = rows of docs/semantics.md. Expected outputs per state are the manual's
//! state table (§4.4.2), encoded once in `common::table`.

mod common;
use common::*;
use safelogic::*;

fn set_disc(fb: &mut FB_ESTOP, pair: usize, t: u32) {
    match pair {
        0 => fb.tDiscTime12 = t,
        1 => fb.tDiscTime34 = t,
        2 => fb.tDiscTime56 = t,
        3 => fb.tDiscTime78 = t,
        _ => unreachable!(),
    }
}

// ---------------------------------------------------------------------------------------
// States and their outputs (§4.4.2 status table)
// ---------------------------------------------------------------------------------------

/// ABI §4 "init does not modify any VAR_INPUT field"; C1: init writes the power-up image
/// (all outputs FALSE, nState STOP, nDiag 0).
#[test]
fn init_writes_power_up_image_and_leaves_inputs_untouched() {
    let mut fb = estop(0b11);
    fb.tDiscTime12 = 100;
    fb.tEStopDelOutDelay = 250;
    fb.dwOptions = SL_OPT_EDM1;
    fb.tEDM1ResetTime = 40;
    fb.bRestart = 1;
    fb.bErrAck = 1;
    fb.wInputNegated = 0b100;
    // stale output bytes that init must overwrite
    fb.bError = 1;
    fb.bEStopOut = 1;
    fb.bEStopDelOut = 1;
    fb.nState = SL_STATE_RUN;
    fb.nDiag = 0xFFFF;
    let before = fb;
    assert_eq!(fb.init(), SL_OK);
    expect(&fb, SL_STATE_STOP);
    assert_eq!(fb.nDiag, 0);
    let mut inputs_only = fb;
    inputs_only.bError = before.bError;
    inputs_only.bEStopOut = before.bEStopOut;
    inputs_only.bEStopDelOut = before.bEStopDelOut;
    inputs_only.aReserved2 = before.aReserved2;
    inputs_only.nState = before.nState;
    inputs_only.aReserved3 = before.aReserved3;
    inputs_only.nDiag = before.nDiag;
    inputs_only.aReserved4 = before.aReserved4;
    inputs_only.stPrivate = before.stPrivate;
    assert_eq!(inputs_only, before, "init modified a VAR_INPUT field");
}

/// §4.4.2 STOP: "If the input FbRun=FALSE, the FB ESTOP module assumes the STOP state.
/// Error=0 EStopOut=0 EStopDelOut=0" (also with every input TRUE).
#[test]
fn stop_state_while_run_is_false() {
    let mut fb = estop(0xFF);
    fb.bRun = 0;
    let mut s = Sim::new(fb, T0);
    for _ in 0..5 {
        s.step(10, SL_STATE_STOP);
    }
    // Restart sequence has no effect in STOP
    s.fb.bRestart = 1;
    s.step(10, SL_STATE_STOP);
    s.fb.bRestart = 0;
    s.step(10, SL_STATE_STOP);
}

/// §4.4.2 Restart ("During start-up ... a falling edge must be detected at the Restart
/// input before the safe state of the outputs is canceled"), G12, C12: STOP → SAFE (3) in
/// one call, START (6) while Restart is TRUE, RUN (1) on the falling edge.
#[test]
fn start_up_goes_safe_then_start_then_run() {
    let mut s = Sim::new(estop(0b1), T0);
    s.start_up(SL_STATE_SAFE);
    for _ in 0..20 {
        s.step(10, SL_STATE_SAFE); // no restart, no output
    }
    s.fb.bRestart = 1;
    s.step(10, SL_STATE_START);
    s.step(500, SL_STATE_START); // held: no time monitoring of the restart signal (§4.4.1)
    s.fb.bRestart = 0;
    s.step(10, SL_STATE_RUN);
    assert_eq!(s.fb.nDiag, 0);
    s.step(10_000, SL_STATE_RUN);
}

/// G12: "A Restart held TRUE through start-up leads to START, the falling edge to RUN."
#[test]
fn restart_held_through_start_up_leads_to_start_then_run() {
    let mut fb = estop(0b1);
    fb.bRun = 0;
    fb.bRestart = 1;
    let mut s = Sim::new(fb, T0);
    s.step(1, SL_STATE_STOP);
    s.fb.bRun = 1;
    s.step(1, SL_STATE_SAFE);
    s.step(1, SL_STATE_START);
    s.fb.bRestart = 0;
    s.step(1, SL_STATE_RUN);
}

/// §4.4.2 RUN: "no error and no active EStopIn input requests a safe state ...
/// Error=0 EStopOut=1 EStopDelOut=1".
#[test]
fn run_state_outputs() {
    let mut s = estop_running(estop(0xFF));
    expect(&s.fb, SL_STATE_RUN);
    s.step(1, SL_STATE_RUN);
}

/// §4.4.1 "The first output (EStopOut) goes immediately ... into the safe state once an
/// input requests the safe state"; §4.4.2 SAFE "as long as at least one of the active
/// EStopIn inputs has requested the safe state" (delay 0: G10, straight to SAFE). Every one
/// of the eight inputs, as a single channel.
#[test]
fn each_of_the_eight_inputs_requests_the_safe_state_immediately() {
    for i in 0..8 {
        let mut s = estop_running(estop(1 << i));
        s.fb.set_in(i, 0);
        s.step(1, SL_STATE_SAFE);
        s.step(100, SL_STATE_SAFE);
        // input released: stays SAFE until a restart (§4.4.1)
        s.fb.set_in(i, 1);
        s.step(1, SL_STATE_SAFE);
        s.step(1000, SL_STATE_SAFE);
        s.restart();
    }
}

/// §4.4.2 SAFE with all eight inputs active: any single one requests the safe state.
#[test]
fn any_active_input_of_eight_requests_the_safe_state() {
    for i in 0..8 {
        let mut s = estop_running(estop(0xFF));
        s.fb.set_in(i, 0);
        s.step(1, SL_STATE_SAFE);
    }
}

/// §4.4.1 "Each of the eight inputs can be parameterized as break contact (0 requests the
/// safe state) or make contact (1 request the safe state)"; ABI §7 Signals.
#[test]
fn make_contact_input_requests_the_safe_state_at_one() {
    let mut fb = estop(0b11);
    fb.wInputNegated = 0b10; // EStopIn2 make contact
    fb.bEStopIn2 = 0;
    let mut s = estop_running(fb);
    s.fb.bEStopIn2 = 1;
    s.step(1, SL_STATE_SAFE);
    s.fb.bEStopIn2 = 0;
    s.step(1, SL_STATE_SAFE);
    s.restart();
    // break contact EStopIn1 still requests at 0
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_SAFE);
}

/// ABI §7 Signals "Inactive inputs are ignored"; §4.4.3 "In the default state all inputs
/// are disabled".
#[test]
fn inactive_inputs_are_ignored() {
    let mut s = estop_running(estop(0b1000_0000)); // only EStopIn8 active
    for i in 0..7 {
        s.fb.set_in(i, 0);
        s.step(1, SL_STATE_RUN);
    }
    for i in 0..7 {
        s.fb.set_in(i, 1);
        s.step(1, SL_STATE_RUN);
    }
}

/// §4.4.4 "If all active EStop-In inputs ... are TRUE and the Restart signal changes from
/// FALSE to TRUE, the Start state is assumed": one input still requesting keeps SAFE.
#[test]
fn restart_while_an_input_requests_stays_safe() {
    let mut fb = estop(0b1111);
    fb.bEStopIn3 = 0;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.bRestart = 1;
    s.step(1, SL_STATE_SAFE);
    s.fb.bRestart = 0;
    s.step(1, SL_STATE_SAFE);
    s.step(1, SL_STATE_SAFE);
}

/// G1: in START a safe-state request → SAFE; the later falling edge does not enable
/// (§4.4.4 "The detection of a change of the Restart signal from TRUE to FALSE triggers a
/// check whether all active EStop-In inputs are still TRUE").
#[test]
fn request_during_start_falls_back_to_safe_and_falling_edge_does_not_enable() {
    let mut s = Sim::new(estop(0b11), T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.bRestart = 1;
    s.step(1, SL_STATE_START);
    s.fb.bEStopIn2 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bRestart = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bEStopIn2 = 1;
    s.step(1, SL_STATE_SAFE);
    s.step(1, SL_STATE_SAFE);
}

/// §4.4.4: the request and the falling edge in the same cycle: the check at the falling
/// edge fails, the output is not enabled.
#[test]
fn request_in_the_cycle_of_the_falling_edge_does_not_enable() {
    let mut s = Sim::new(estop(0b1), T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.bRestart = 1;
    s.step(1, SL_STATE_START);
    s.fb.bRestart = 0;
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bEStopIn1 = 1;
    s.step(1, SL_STATE_SAFE);
}

/// §4.4.1 "a rising and falling edge must be detected at the Restart input": a Restart held
/// TRUE never enables; only its falling edge does.
#[test]
fn restart_held_true_never_enables() {
    let mut s = Sim::new(estop(0b1), T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.bRestart = 1;
    for _ in 0..50 {
        s.step(100, SL_STATE_START);
    }
    s.fb.bRestart = 0;
    s.step(1, SL_STATE_RUN);
}

/// G11: `SL_OPT_MANUAL_RESTART` is accepted for ESTOP and changes nothing (ESTOP always
/// restarts manually).
#[test]
fn manual_restart_option_is_accepted_and_changes_nothing() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_MANUAL_RESTART;
    let mut s = estop_running(fb);
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bEStopIn1 = 1;
    s.step(1, SL_STATE_SAFE);
    s.step(1, SL_STATE_SAFE);
    s.restart();
}

/// §4.4.2 DELAYOUT: "at least one of the active EStopIn inputs has requested the safe
/// state, but the delay time for the EStopDelOut output has not yet expired. Error=0
/// EStopOut=0 EStopDelOut=1"; ABI §7 Timers: reached at the first cycle with
/// tNow - t0 >= T.
#[test]
fn delayout_state_and_delayed_output() {
    let mut fb = estop(0b1);
    fb.tEStopDelOutDelay = 100;
    let mut s = estop_running(fb);
    let ta = s.t + 5;
    s.fb.bEStopIn1 = 0;
    assert_eq!(s.at(ta), SL_OK);
    expect(&s.fb, SL_STATE_DELAYOUT);
    assert_eq!(s.at(ta + 50), SL_OK);
    expect(&s.fb, SL_STATE_DELAYOUT);
    assert_eq!(s.at(ta + 99), SL_OK);
    expect(&s.fb, SL_STATE_DELAYOUT);
    assert_eq!(s.at(ta + 100), SL_OK);
    expect(&s.fb, SL_STATE_SAFE);
}

/// G10: DELAYOUT runs to the end of the delay even if the request disappears; restart
/// edges in DELAYOUT are ignored; afterwards SAFE needs a restart.
#[test]
fn delayout_runs_to_the_end_and_ignores_restart_edges() {
    let mut fb = estop(0b1);
    fb.tEStopDelOutDelay = 100;
    let mut s = estop_running(fb);
    let ta = s.t + 1;
    s.fb.bEStopIn1 = 0;
    s.at(ta);
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.fb.bEStopIn1 = 1;
    s.at(ta + 10);
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.fb.bRestart = 1;
    s.at(ta + 20);
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.fb.bRestart = 0;
    s.at(ta + 30);
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.at(ta + 99);
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.at(ta + 100);
    expect(&s.fb, SL_STATE_SAFE);
    s.step(100, SL_STATE_SAFE);
    s.restart();
}

/// G10: with delay 0 RUN goes straight to SAFE (EStopDelOut off in the same cycle).
#[test]
fn delay_zero_switches_both_outputs_off_at_once() {
    let mut s = estop_running(estop(0b1));
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_SAFE);
}

/// §4.4.2 ERROR "Error=1 EStopOut=0 EStopDelOut=0", RESET "Error=0 EStopOut=0
/// EStopDelOut=0"; ABI §7: falling ErrAck leaves RESET for the start state (SAFE, G12).
#[test]
fn error_and_reset_states_outputs() {
    let mut fb = estop(0b11);
    fb.tDiscTime12 = 20;
    let mut s = estop_running(fb);
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.step(20, SL_STATE_ERROR);
    assert_eq!(s.fb.nDiag, SL_DIAG_DISC1);
    s.fb.bEStopIn1 = 1;
    s.step(1, SL_STATE_ERROR);
    s.acknowledge(SL_STATE_SAFE);
    s.step(10, SL_STATE_SAFE); // restart still required
    s.restart();
}

// ---------------------------------------------------------------------------------------
// Discrepancy (§4.4.1 pairs, ABI §7 Pairs/Timers, G14) and diag bits 0-3, 8-11 (§4.4.2)
// ---------------------------------------------------------------------------------------

/// §4.4.2 diag bits 0..3 "Discrepancy error input group 1..4"; without "Safe Inputs after
/// Disc Error" only bit k (G5). Both channels of each pair tried.
#[test]
fn discrepancy_of_pair_k_sets_diag_bit_k() {
    for k in 0..4 {
        for ch in 0..2 {
            let mut fb = estop(0b11 << (2 * k));
            set_disc(&mut fb, k, 100);
            let mut s = estop_running(fb);
            s.fb.set_in(2 * k + ch, 0);
            s.step(1, SL_STATE_SAFE);
            s.step(99, SL_STATE_SAFE);
            s.step(1, SL_STATE_ERROR);
            assert_eq!(s.fb.nDiag, 1 << k, "pair {k} channel {ch}");
        }
    }
}

/// §4.4.2 diag bits 8..11 "Discrepancy error input group k with activated option 'Safe
/// Inputs after Disc Error' (set in addition to bit k)"; G5.
#[test]
fn discrepancy_with_safe_inputs_option_sets_bit_8_plus_k_in_addition() {
    for k in 0..4 {
        let mut fb = estop(0b11 << (2 * k));
        set_disc(&mut fb, k, 30);
        fb.dwOptions = SL_OPT_SAFE_INPUTS_AFTER_DISC;
        let mut s = estop_running(fb);
        s.fb.set_in(2 * k + 1, 0);
        s.step(1, SL_STATE_SAFE);
        s.step(30, SL_STATE_ERROR);
        assert_eq!(s.fb.nDiag, (1 << k) | (1 << (8 + k)), "pair {k}");
    }
}

/// G14: two pairs reaching their discrepancy time in the same cycle both show their bits.
#[test]
fn two_pairs_failing_together_show_both_bits() {
    let mut fb = estop(0xFF);
    fb.tDiscTime12 = 50;
    fb.tDiscTime78 = 50;
    let mut s = estop_running(fb);
    s.fb.bEStopIn1 = 0;
    s.fb.bEStopIn8 = 0;
    s.step(1, SL_STATE_SAFE);
    s.step(50, SL_STATE_ERROR);
    assert_eq!(s.fb.nDiag, SL_DIAG_DISC1 | SL_DIAG_DISC4);
}

/// ABI §7 Pairs "may differ for less than the discrepancy time"; G14: differing for T-1 ms
/// and then agreeing is no error.
#[test]
fn discrepancy_just_below_the_limit_is_no_error() {
    let mut fb = estop(0b11);
    fb.tDiscTime12 = 100;
    let mut s = estop_running(fb);
    let t1 = s.t + 1;
    s.fb.bEStopIn1 = 0;
    s.at(t1);
    expect(&s.fb, SL_STATE_SAFE);
    s.at(t1 + 99);
    expect(&s.fb, SL_STATE_SAFE);
    s.fb.bEStopIn2 = 0; // both channels agree at t1 + 99
    s.at(t1 + 99);
    expect(&s.fb, SL_STATE_SAFE);
    s.at(t1 + 100_000);
    expect(&s.fb, SL_STATE_SAFE);
    assert_eq!(s.fb.nDiag, 0);
    s.fb.bEStopIn1 = 1;
    s.fb.bEStopIn2 = 1;
    s.step(1, SL_STATE_SAFE);
    s.restart();
}

/// ABI §7 "when they have differed continuously for the full time the block enters
/// ERROR"; Timers: the first cycle with tNow - t0 >= T; G14.
#[test]
fn discrepancy_exactly_at_the_limit_is_an_error() {
    let mut fb = estop(0b11);
    fb.tDiscTime12 = 100;
    let mut s = estop_running(fb);
    let t1 = s.t + 1;
    s.fb.bEStopIn2 = 0;
    s.at(t1);
    expect(&s.fb, SL_STATE_SAFE);
    s.at(t1 + 99);
    expect(&s.fb, SL_STATE_SAFE);
    assert_eq!(s.at(t1 + 100), SL_OK);
    expect_error(&s.fb, SL_DIAG_DISC1);
}

/// G14: a cycle in which the channels agree stops the timer; a new discrepancy starts
/// from scratch.
#[test]
fn discrepancy_timer_restarts_after_the_pair_agrees() {
    let mut fb = estop(0b11);
    fb.tDiscTime12 = 100;
    let mut s = estop_running(fb);
    let t1 = s.t + 1;
    s.fb.bEStopIn1 = 0;
    s.at(t1);
    s.fb.bEStopIn2 = 0;
    s.at(t1 + 99); // agree
    expect(&s.fb, SL_STATE_SAFE);
    s.fb.bEStopIn2 = 1;
    s.at(t1 + 100); // differ again: timer starts at t1 + 100
    expect(&s.fb, SL_STATE_SAFE);
    s.at(t1 + 199);
    expect(&s.fb, SL_STATE_SAFE);
    s.at(t1 + 200);
    expect_error(&s.fb, SL_DIAG_DISC1);
}

/// ABI §7 Pairs: the logical values (raw XOR negation) are compared: an antivalent pair
/// (break + make contact) agrees at raw 1/0 and differs at raw 0/0.
#[test]
fn discrepancy_compares_logical_values_of_a_negated_pair() {
    let mut fb = estop(0b11);
    fb.wInputNegated = 0b10;
    fb.bEStopIn2 = 0;
    fb.tDiscTime12 = 50;
    let mut s = estop_running(fb);
    // both request the safe state together: raw 0 / 1 — no discrepancy
    s.fb.bEStopIn1 = 0;
    s.fb.bEStopIn2 = 1;
    s.step(1, SL_STATE_SAFE);
    s.step(500, SL_STATE_SAFE);
    // raw 0 / 0: logical FALSE / TRUE — discrepancy
    s.fb.bEStopIn2 = 0;
    s.step(1, SL_STATE_SAFE);
    s.step(49, SL_STATE_SAFE);
    s.step(1, SL_STATE_ERROR);
    assert_eq!(s.fb.nDiag, SL_DIAG_DISC1);
}

/// §4.4.2 EStopIn2: "If the discrepancy time is not equal 0, the 1st and 2nd input channel
/// are considered to be the 1st input pair": time 0 = two single channels, no monitoring.
#[test]
fn discrepancy_time_zero_means_two_single_channels() {
    let mut s = estop_running(estop(0b11));
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.step(60_000, SL_STATE_SAFE);
    s.step(60_000, SL_STATE_SAFE);
    assert_eq!(s.fb.nDiag, 0);
}

/// G14: monitoring runs in SAFE too (before any restart).
#[test]
fn discrepancy_is_monitored_in_safe() {
    let mut fb = estop(0b11);
    fb.tDiscTime12 = 100;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.step(1, SL_STATE_SAFE);
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.step(99, SL_STATE_SAFE);
    s.step(1, SL_STATE_ERROR);
    assert_eq!(s.fb.nDiag, SL_DIAG_DISC1);
}

/// G14: no monitoring in STOP.
#[test]
fn discrepancy_is_not_monitored_in_stop() {
    let mut fb = estop(0b11);
    fb.tDiscTime12 = 100;
    fb.bRun = 0;
    fb.bEStopIn1 = 0;
    let mut s = Sim::new(fb, T0);
    for _ in 0..10 {
        s.step(100, SL_STATE_STOP);
    }
}

/// G7: "ESTOP has no ERRORDELAY: its errors switch both outputs off at once" (§4.4.1 "In
/// the FB error state, the outputs assume the safe state 0, only the Error output is 1").
#[test]
fn discrepancy_error_in_delayout_switches_the_delayed_output_off_at_once() {
    let mut fb = estop(0b11);
    fb.tDiscTime12 = 100;
    fb.tEStopDelOutDelay = 1000;
    let mut s = estop_running(fb);
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_DELAYOUT);
    s.step(99, SL_STATE_DELAYOUT);
    s.step(1, SL_STATE_ERROR);
    assert_eq!(s.fb.nDiag, SL_DIAG_DISC1);
}

// ---------------------------------------------------------------------------------------
// Time wrapping (ABI §4: "tNow ... may wrap at 2^32; all time arithmetic is wrapping")
// ---------------------------------------------------------------------------------------

/// DELAYOUT timer started 50 ms before the wrap.
#[test]
fn output_delay_started_just_before_the_wrap() {
    let mut fb = estop(0b1);
    fb.tEStopDelOutDelay = 100;
    let mut s = estop_running_at(fb, u32::MAX - 1000);
    let ta = u32::MAX - 49;
    s.fb.bEStopIn1 = 0;
    assert_eq!(s.at(ta), SL_OK);
    expect(&s.fb, SL_STATE_DELAYOUT);
    assert_eq!(s.at(u32::MAX), SL_OK);
    expect(&s.fb, SL_STATE_DELAYOUT);
    assert_eq!(s.at(49), SL_OK); // 99 ms elapsed
    expect(&s.fb, SL_STATE_DELAYOUT);
    assert_eq!(s.at(50), SL_OK); // 100 ms elapsed
    expect(&s.fb, SL_STATE_SAFE);
}

/// Discrepancy timer started 10 ms before the wrap.
#[test]
fn discrepancy_timer_started_just_before_the_wrap() {
    let mut fb = estop(0b11);
    fb.tDiscTime12 = 100;
    let mut s = estop_running_at(fb, u32::MAX - 500);
    let t1 = u32::MAX - 9;
    s.fb.bEStopIn1 = 0;
    assert_eq!(s.at(t1), SL_OK);
    expect(&s.fb, SL_STATE_SAFE);
    assert_eq!(s.at(0), SL_OK);
    expect(&s.fb, SL_STATE_SAFE);
    assert_eq!(s.at(89), SL_OK); // 99 ms
    expect(&s.fb, SL_STATE_SAFE);
    assert_eq!(s.at(90), SL_OK); // 100 ms
    expect_error(&s.fb, SL_DIAG_DISC1);
}

/// EDM reset time started 1 ms before the wrap (§4.4.5, G6).
#[test]
fn edm_reset_time_started_just_before_the_wrap() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1;
    fb.tEDM1ResetTime = 50;
    let mut s = estop_running_at(fb, u32::MAX - 4); // RUN entered at u32::MAX - 1
    let tr = s.t;
    assert_eq!(tr, u32::MAX - 1);
    assert_eq!(s.at(tr.wrapping_add(49)), SL_OK);
    expect(&s.fb, SL_STATE_RUN);
    assert_eq!(s.at(tr.wrapping_add(50)), SL_OK);
    expect_error(&s.fb, SL_DIAG_EDM1);
}

/// Restart sequence and RUN across the wrap: a large, valid forward step is no error.
#[test]
fn running_across_the_wrap_stays_in_run() {
    let mut s = estop_running_at(estop(0b11), u32::MAX - 2);
    for _ in 0..10 {
        s.step(1, SL_STATE_RUN);
    }
    s.step(0x7FFF_0000, SL_STATE_RUN);
}

// ---------------------------------------------------------------------------------------
// EDM with the restart (§4.4.1, §4.4.2 EDM1/EDM2, §4.4.4, ABI §7, G2) — diag bits 4, 5
// ---------------------------------------------------------------------------------------

/// §4.4.1 "The EDM inputs are checked as soon as the FB changes to the START status. If the
/// EDM inputs then do not have the signal state 1, the FB ESTOP enters the error state";
/// §4.4.2 diag bit 4 / 5 "EDM monitoring error EDM1 / EDM2".
#[test]
fn edm_false_when_restart_is_pressed_is_an_edm_error() {
    for (opts, edm_false, diag) in [
        (SL_OPT_EDM1, [0u8, 1], SL_DIAG_EDM1),
        (SL_OPT_EDM2, [1, 0], SL_DIAG_EDM2),
        (SL_OPT_EDM1 | SL_OPT_EDM2, [0, 1], SL_DIAG_EDM1),
        (SL_OPT_EDM1 | SL_OPT_EDM2, [1, 0], SL_DIAG_EDM2),
        (
            SL_OPT_EDM1 | SL_OPT_EDM2,
            [0, 0],
            SL_DIAG_EDM1 | SL_DIAG_EDM2,
        ),
    ] {
        let mut fb = estop(0b1);
        fb.dwOptions = opts;
        fb.bEDM1 = edm_false[0];
        fb.bEDM2 = edm_false[1];
        let mut s = Sim::new(fb, T0);
        s.start_up(SL_STATE_SAFE);
        s.step(1, SL_STATE_SAFE); // Restart FALSE: nothing checked yet
        s.fb.bRestart = 1;
        assert_eq!(s.adv(1), SL_OK);
        expect_error(&s.fb, diag);
    }
}

/// §4.4.2 EDM1: "the safe state of the outputs will only be exited during restart, when the
/// EDM1 supplies the 1 signal"; G2: an EDM going FALSE while in START is an EDM error.
#[test]
fn edm_going_false_in_start_is_an_edm_error() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1 | SL_OPT_EDM2;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.bRestart = 1;
    s.step(1, SL_STATE_START);
    s.fb.bEDM2 = 0;
    s.adv(1);
    expect_error(&s.fb, SL_DIAG_EDM2);
}

/// §4.4.4 "The detection of a change of the Restart signal from TRUE to FALSE triggers a
/// check whether ... the EDM signal is still TRUE"; G2 "and at the falling edge in START".
#[test]
fn edm_false_at_the_falling_edge_is_an_edm_error_not_run() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.bRestart = 1;
    s.step(1, SL_STATE_START);
    s.fb.bRestart = 0;
    s.fb.bEDM1 = 0;
    s.adv(1);
    expect_error(&s.fb, SL_DIAG_EDM1);
}

/// G2: the check runs whenever Restart is TRUE; with Restart FALSE an EDM that is still
/// FALSE after switching off is no error (the contactor may release later, sample 1).
#[test]
fn edm_false_in_safe_without_restart_is_no_error() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1 | SL_OPT_EDM2;
    fb.bEDM1 = 0;
    fb.bEDM2 = 0;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    for _ in 0..10 {
        s.step(100, SL_STATE_SAFE);
    }
}

/// ABI §7 "every active EDM input must be TRUE": an inactive EDM is not checked.
#[test]
fn inactive_edm_is_not_checked() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1;
    fb.bEDM2 = 0;
    let mut s = estop_running(fb);
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bEStopIn1 = 1;
    s.step(1, SL_STATE_SAFE);
    s.restart();
}

/// G4: an EDM error remains while the EDM reads FALSE (a welded contactor keeps the error);
/// acknowledgement works once it reads TRUE.
#[test]
fn edm_error_remains_while_edm_is_false() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1;
    fb.bEDM1 = 0;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.bRestart = 1;
    s.adv(1);
    expect_error(&s.fb, SL_DIAG_EDM1);
    s.fb.bRestart = 0;
    s.fb.bErrAck = 1;
    s.adv(1);
    expect_error(&s.fb, SL_DIAG_EDM1);
    s.fb.bErrAck = 0;
    s.adv(1);
    expect_error(&s.fb, SL_DIAG_EDM1);
    s.fb.bEDM1 = 1;
    s.adv(1);
    expect_error(&s.fb, SL_DIAG_EDM1);
    s.acknowledge(SL_STATE_SAFE);
    s.restart();
}

// ---------------------------------------------------------------------------------------
// Restart samples 1-4 (§4.4.4)
// ---------------------------------------------------------------------------------------

/// §4.4.4 Sample 1: emergency stop via EStopIn, then acknowledgement via Restart; EDM
/// inputs active (contactor feedback TRUE while released).
#[test]
fn sample1_estop_then_restart_with_edm() {
    let mut fb = estop(0b11);
    fb.tDiscTime12 = 50;
    fb.dwOptions = SL_OPT_EDM1 | SL_OPT_EDM2;
    let mut s = estop_running(fb);
    // contactors pull in
    s.fb.bEDM1 = 0;
    s.fb.bEDM2 = 0;
    s.step(10, SL_STATE_RUN);
    // emergency stop: both channels open
    s.fb.bEStopIn1 = 0;
    s.fb.bEStopIn2 = 0;
    s.step(10, SL_STATE_SAFE);
    // contactors release
    s.fb.bEDM1 = 1;
    s.fb.bEDM2 = 1;
    s.step(10, SL_STATE_SAFE);
    // e-stop unlocked
    s.fb.bEStopIn1 = 1;
    s.fb.bEStopIn2 = 1;
    s.step(10, SL_STATE_SAFE);
    s.step(10, SL_STATE_SAFE);
    // Restart FALSE -> TRUE: START
    s.fb.bRestart = 1;
    s.step(10, SL_STATE_START);
    s.step(10, SL_STATE_START);
    // Restart TRUE -> FALSE: inputs and EDM still TRUE -> output enabled
    s.fb.bRestart = 0;
    s.step(10, SL_STATE_RUN);
    s.fb.bEDM1 = 0;
    s.fb.bEDM2 = 0;
    s.step(10, SL_STATE_RUN);
    assert_eq!(s.fb.nDiag, 0);
}

/// §4.4.4 Sample 2: the Restart rises before the EStop inputs; "The Start state (FB state
/// 6) is only assumed if both signals are TRUE. The output is enabled when the Restart
/// input changes from TRUE to FALSE." (G1: START on the Restart level.)
#[test]
fn sample2_restart_rises_before_the_estop_inputs() {
    let mut fb = estop(0b11);
    fb.tDiscTime12 = 50;
    fb.dwOptions = SL_OPT_EDM1;
    let mut s = estop_running(fb);
    s.fb.bEDM1 = 0;
    s.step(10, SL_STATE_RUN);
    s.fb.bEStopIn1 = 0;
    s.fb.bEStopIn2 = 0;
    s.step(10, SL_STATE_SAFE);
    s.fb.bEDM1 = 1;
    s.step(10, SL_STATE_SAFE);
    // Restart rises while the e-stop still requests the safe state
    s.fb.bRestart = 1;
    s.step(10, SL_STATE_SAFE);
    s.step(10, SL_STATE_SAFE);
    // EStop inputs become TRUE while Restart is TRUE: START
    s.fb.bEStopIn1 = 1;
    s.fb.bEStopIn2 = 1;
    s.step(10, SL_STATE_START);
    s.fb.bRestart = 0;
    s.step(10, SL_STATE_RUN);
}

/// §4.4.4 Sample 3: Restart TRUE before the emergency stop; "the EDM signal is checked
/// immediately when the EStop-In input changes from TRUE to FALSE. This immediately leads to
/// an EDM error" — G2: the check runs from the cycle after the outputs went off.
#[test]
fn sample3_restart_held_before_estop_gives_edm_error() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1;
    let mut s = estop_running(fb);
    s.fb.bEDM1 = 0; // contactor closed
    s.step(10, SL_STATE_RUN);
    s.fb.bRestart = 1; // Restart pressed (stuck) while running: no effect in RUN
    s.step(10, SL_STATE_RUN);
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_SAFE); // outputs off in the same cycle
    assert_eq!(s.adv(1), SL_OK); // contactor feedback still FALSE
    expect_error(&s.fb, SL_DIAG_EDM1);
}

/// Sample 3 with EDM2 and a delayed output: G2 "In DELAYOUT the check does not run";
/// it runs from the cycle after EStopDelOut went off.
#[test]
fn sample3_with_output_delay_checks_after_the_delayed_output_is_off() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1 | SL_OPT_EDM2;
    fb.tEStopDelOutDelay = 100;
    let mut s = estop_running(fb);
    s.fb.bEDM1 = 0;
    s.fb.bEDM2 = 0;
    s.fb.bRestart = 1;
    s.step(10, SL_STATE_RUN);
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_DELAYOUT);
    s.fb.bEDM1 = 1; // K1 released, K2 (delayed) still closed
    s.step(50, SL_STATE_DELAYOUT);
    s.step(49, SL_STATE_DELAYOUT);
    s.step(1, SL_STATE_SAFE);
    s.adv(1);
    expect_error(&s.fb, SL_DIAG_EDM2);
}

/// Sample 3 counterpart: the contactor has released by the next cycle — no error; the held
/// Restart leads to START once the e-stop is released (G1 level) and the falling edge
/// enables.
#[test]
fn sample3_contactor_released_in_time_is_no_error() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1;
    let mut s = estop_running(fb);
    s.fb.bEDM1 = 0;
    s.fb.bRestart = 1;
    s.step(10, SL_STATE_RUN);
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bEDM1 = 1;
    s.step(1, SL_STATE_SAFE);
    s.step(10, SL_STATE_SAFE);
    s.fb.bEStopIn1 = 1;
    s.step(10, SL_STATE_START);
    s.fb.bRestart = 0;
    s.step(10, SL_STATE_RUN);
}

/// §4.4.4 Sample 4: without EDM "the time when the change from FALSE to TRUE may occur at
/// the Restart input is not monitored. This may also be the case before the emergency stop
/// event. In this case the FB output is enabled when the Restart input changes from TRUE to
/// FALSE."
#[test]
fn sample4_without_edm_restart_before_estop_enables_on_falling_edge() {
    let mut s = estop_running(estop(0b11));
    s.fb.bRestart = 1;
    s.step(10, SL_STATE_RUN);
    s.fb.bEStopIn1 = 0;
    s.fb.bEStopIn2 = 0;
    s.step(10, SL_STATE_SAFE);
    s.step(10, SL_STATE_SAFE);
    s.fb.bEStopIn1 = 1;
    s.fb.bEStopIn2 = 1;
    s.step(10, SL_STATE_START);
    s.step(1000, SL_STATE_START);
    s.fb.bRestart = 0;
    s.step(10, SL_STATE_RUN);
}

// ---------------------------------------------------------------------------------------
// EL6910 EDM reset time (§4.4.5, G6)
// ---------------------------------------------------------------------------------------

/// §4.4.5 "the timer is started when the output EStopOut is activated. If the EDM input
/// does not switch to FALSE within this time, a function block error is set and the
/// outputs are switched off"; ABI §7 Timers.
#[test]
fn edm1_reset_time_expires_when_edm_stays_true() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1;
    fb.tEDM1ResetTime = 50;
    let mut s = estop_running(fb);
    let tr = s.t; // EStopOut switched on here
    assert_eq!(s.at(tr + 10), SL_OK);
    expect(&s.fb, SL_STATE_RUN);
    assert_eq!(s.at(tr + 49), SL_OK);
    expect(&s.fb, SL_STATE_RUN);
    assert_eq!(s.at(tr + 50), SL_OK);
    expect_error(&s.fb, SL_DIAG_EDM1);
}

/// §4.4.5 for EDM2 (diag bit 5).
#[test]
fn edm2_reset_time_expires_when_edm_stays_true() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1 | SL_OPT_EDM2;
    fb.tEDM2ResetTime = 200;
    let mut s = estop_running(fb);
    let tr = s.t;
    s.fb.bEDM1 = 0;
    s.at(tr + 10);
    expect(&s.fb, SL_STATE_RUN);
    s.at(tr + 199);
    expect(&s.fb, SL_STATE_RUN);
    s.at(tr + 200);
    expect_error(&s.fb, SL_DIAG_EDM2);
}

/// §4.4.5: EDM switching to FALSE within the time satisfies the check; G6: later changes
/// in RUN are not monitored.
#[test]
fn edm_reset_time_satisfied_when_edm_goes_false_in_time() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1 | SL_OPT_EDM2;
    fb.tEDM1ResetTime = 50;
    fb.tEDM2ResetTime = 50;
    let mut s = estop_running(fb);
    let tr = s.t;
    s.fb.bEDM1 = 0;
    s.fb.bEDM2 = 0;
    s.at(tr + 49);
    expect(&s.fb, SL_STATE_RUN);
    s.at(tr + 50);
    expect(&s.fb, SL_STATE_RUN);
    s.at(tr + 5000);
    expect(&s.fb, SL_STATE_RUN);
    s.fb.bEDM1 = 1;
    s.fb.bEDM2 = 1;
    s.at(tr + 6000);
    expect(&s.fb, SL_STATE_RUN);
}

/// §4.4.5 "This function can be switched off by entering 0 as Reset Time".
#[test]
fn edm_reset_time_zero_is_off() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1 | SL_OPT_EDM2;
    let mut s = estop_running(fb);
    s.step(60_000, SL_STATE_RUN);
}

/// G6: "The check only runs in RUN: leaving RUN (a safe-state request) ends it."
#[test]
fn edm_reset_time_check_ends_when_leaving_run() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1;
    fb.tEDM1ResetTime = 50;
    let mut s = estop_running(fb);
    let tr = s.t;
    s.fb.bEStopIn1 = 0;
    s.at(tr + 10);
    expect(&s.fb, SL_STATE_SAFE);
    s.at(tr + 50);
    expect(&s.fb, SL_STATE_SAFE);
    s.at(tr + 500);
    expect(&s.fb, SL_STATE_SAFE);
}

/// G6: "On entering RUN every active EDMx with a non-zero reset time is armed" — again at
/// every switch-on.
#[test]
fn edm_reset_time_is_armed_again_at_every_switch_on() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1;
    fb.tEDM1ResetTime = 50;
    let mut s = estop_running(fb);
    s.fb.bEDM1 = 0;
    s.step(10, SL_STATE_RUN);
    s.fb.bEStopIn1 = 0;
    s.step(10, SL_STATE_SAFE);
    s.fb.bEDM1 = 1;
    s.fb.bEStopIn1 = 1;
    s.step(10, SL_STATE_SAFE);
    s.restart();
    let tr = s.t;
    s.at(tr + 49);
    expect(&s.fb, SL_STATE_RUN);
    s.at(tr + 50);
    expect_error(&s.fb, SL_DIAG_EDM1);
}

/// G4: an EDM reset-time error (EDM stays TRUE) can be acknowledged: the EDM reads TRUE.
#[test]
fn edm_reset_time_error_is_acknowledgeable() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1;
    fb.tEDM1ResetTime = 20;
    let mut s = estop_running(fb);
    s.step(20, SL_STATE_ERROR);
    assert_eq!(s.fb.nDiag, SL_DIAG_EDM1);
    s.acknowledge(SL_STATE_SAFE);
}

// ---------------------------------------------------------------------------------------
// More restart / EDM / discrepancy details
// ---------------------------------------------------------------------------------------

/// G1: the outputs are enabled only by the falling edge *in START*; a Restart released in
/// SAFE (START never reached because the e-stop still requested) does not enable, even if
/// the request ends in the same cycle.
#[test]
fn restart_falling_edge_outside_start_does_not_enable() {
    let mut s = estop_running(estop(0b1));
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bRestart = 1;
    s.step(1, SL_STATE_SAFE);
    s.fb.bRestart = 0;
    s.fb.bEStopIn1 = 1;
    s.step(1, SL_STATE_SAFE);
    s.step(1, SL_STATE_SAFE);
    s.restart();
}

/// ABI §7 "While the block's outputs are in the safe state and bRestart is TRUE, every
/// active EDM input must be TRUE" (G2: in SAFE whenever Restart is TRUE) — also while the
/// e-stop still requests the safe state (sample 2 with a contactor that did not release).
#[test]
fn restart_pressed_during_the_estop_with_edm_false_is_an_edm_error() {
    let mut fb = estop(0b1);
    fb.dwOptions = SL_OPT_EDM1;
    let mut s = estop_running(fb);
    s.fb.bEDM1 = 0;
    s.step(10, SL_STATE_RUN);
    s.fb.bEStopIn1 = 0;
    s.step(10, SL_STATE_SAFE);
    s.step(10, SL_STATE_SAFE); // Restart FALSE: no check
    s.fb.bRestart = 1;
    s.adv(10);
    expect_error(&s.fb, SL_DIAG_EDM1);
}

/// G14 "it starts from scratch after STOP→run": time spent differing before a STOP does
/// not count afterwards.
#[test]
fn discrepancy_timer_starts_from_scratch_after_stop() {
    let mut fb = estop(0b11);
    fb.tDiscTime12 = 100;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.bEStopIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.step(90, SL_STATE_SAFE);
    s.fb.bRun = 0;
    s.step(1, SL_STATE_STOP);
    s.step(5, SL_STATE_STOP);
    let t2 = s.t + 1;
    s.fb.bRun = 1;
    s.at(t2);
    expect(&s.fb, SL_STATE_SAFE);
    // 1 ms cycles; whether the STOP→run call itself starts the timer (error at t2 + 100)
    // or the next one (t2 + 101) is left open by G14 — both count from the restart
    while s.t != t2 + 99 {
        s.step(1, SL_STATE_SAFE);
    }
    s.adv(2);
    expect_error(&s.fb, SL_DIAG_DISC1);
}

/// G14 "it starts from scratch ... after RESET".
#[test]
fn discrepancy_timer_starts_from_scratch_after_reset() {
    let mut fb = estop(0b1111);
    fb.tDiscTime12 = 100;
    fb.tDiscTime34 = 100;
    let mut s = estop_running(fb);
    // pair 2 fails; pair 1 is differing for 60 ms when the error is acknowledged
    s.fb.bEStopIn3 = 0;
    s.step(1, SL_STATE_SAFE);
    s.step(100, SL_STATE_ERROR);
    assert_eq!(s.fb.nDiag, SL_DIAG_DISC2);
    s.fb.bEStopIn3 = 1;
    s.fb.bEStopIn1 = 0;
    s.adv(1);
    s.fb.bErrAck = 1;
    s.step(59, SL_STATE_RESET);
    s.fb.bErrAck = 0;
    let t2 = s.t + 1;
    s.at(t2);
    expect(&s.fb, SL_STATE_SAFE);
    // 1 ms cycles (see discrepancy_timer_starts_from_scratch_after_stop)
    while s.t != t2 + 99 {
        s.step(1, SL_STATE_SAFE);
    }
    s.adv(2);
    expect_error(&s.fb, SL_DIAG_DISC1);
}
