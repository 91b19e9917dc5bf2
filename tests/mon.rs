//! FB MON — every statement of manual §4.5 (and the PLC interface text
//! fb-mon-plc-interface.txt) as a cycle-by-cycle test.
//!
//! References: "§4.5.x" = twinsafe-logic-fb-manual.txt; "PLC" = fb-mon-plc-interface.txt;
//! "ABI §n" = shared/design/ABI.md; "Cn"/"Gn" = rows of docs/semantics.md. Expected
//! outputs per state are the manual's state table (§4.5.2), encoded in `common::table`.

mod common;
use common::*;
use safelogic::*;

const MANUAL: u32 = SL_OPT_MANUAL_RESTART;
const FT: u32 = SL_OPT_FUNCTION_TEST;
/// Secure1 and Secure2 active (wInputActive bits 4, 5).
const SEC: u16 = 0b11_0000;

// ---------------------------------------------------------------------------------------
// States and their outputs (§4.5.2 status table)
// ---------------------------------------------------------------------------------------

/// ABI §4 "init does not modify any VAR_INPUT field"; C1 power-up image.
#[test]
fn init_writes_power_up_image_and_leaves_inputs_untouched() {
    let mut fb = mon(0b11 | SEC, MANUAL | SL_OPT_EDM2);
    fb.tDiscTime12 = 100;
    fb.tDiscTimeSecure12 = 30;
    fb.tMonDelOutDelay = 400;
    fb.tEDM2ResetTime = 10;
    fb.wInputNegated = 0b10_0000;
    fb.bSecure2 = 0;
    fb.bRestart = 1;
    fb.bErrAck = 1;
    fb.bError = 1;
    fb.bMonOut = 1;
    fb.bMonDelOut = 1;
    fb.nState = SL_STATE_RUN;
    fb.nDiag = 0x1234;
    let before = fb;
    assert_eq!(fb.init(), SL_OK);
    expect(&fb, SL_STATE_STOP);
    assert_eq!(fb.nDiag, 0);
    let mut inputs_only = fb;
    inputs_only.bError = before.bError;
    inputs_only.bMonOut = before.bMonOut;
    inputs_only.bMonDelOut = before.bMonDelOut;
    inputs_only.aReserved4 = before.aReserved4;
    inputs_only.nState = before.nState;
    inputs_only.aReserved5 = before.aReserved5;
    inputs_only.nDiag = before.nDiag;
    inputs_only.aReserved6 = before.aReserved6;
    inputs_only.stPrivate = before.stPrivate;
    assert_eq!(inputs_only, before, "init modified a VAR_INPUT field");
}

/// §4.5.2 STOP: "If the input FbRun=FALSE, the FB MON module assumes the STOP state.
/// Error=0 MonOut=0 MonDelOut=0".
#[test]
fn stop_state_while_run_is_false() {
    for opts in [0, MANUAL, FT, MANUAL | FT] {
        let mut fb = mon(0b1111 | SEC, opts);
        fb.bRun = 0;
        let mut s = Sim::new(fb, T0);
        for _ in 0..5 {
            s.step(10, SL_STATE_STOP);
        }
    }
}

/// §4.5.2 Restart "Manual restart not active: ... Both starting and exiting the safe state
/// is carried out automatically"; G12: STOP → SAFE, RUN one cycle later; §4.5.2 RUN
/// "Error=0 MonOut=1 MonDelOut=1".
#[test]
fn automatic_restart_start_up_goes_safe_then_run() {
    let mut s = Sim::new(mon(0b1, 0), T0);
    s.start_up(SL_STATE_SAFE);
    s.step(1, SL_STATE_RUN);
    s.step(1000, SL_STATE_RUN);
}

/// §4.5.1 "In case of an inactive restart the safe state is exited once the MonIn or
/// Secure inputs no longer request the safe state"; G3.
#[test]
fn automatic_restart_leaves_safe_when_the_request_ends() {
    let mut s = mon_running(mon(0b11, 0));
    s.fb.bMonIn2 = 0;
    s.step(1, SL_STATE_SAFE);
    s.step(100, SL_STATE_SAFE);
    s.fb.bMonIn2 = 1;
    s.step(1, SL_STATE_RUN);
}

/// §4.5.2 Restart "Manual restart not active: This input is not used"; START "This state
/// can only be assumed if manual restart is active"; C7 (Restart byte not read).
#[test]
fn automatic_restart_ignores_the_restart_input() {
    let mut s = mon_running(mon(0b1, 0));
    s.fb.bMonIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bRestart = 1;
    s.step(1, SL_STATE_SAFE);
    s.fb.bMonIn1 = 1;
    s.step(1, SL_STATE_RUN); // never START
    s.fb.bRestart = 0;
    s.step(1, SL_STATE_RUN);
    s.fb.bRestart = 0x55; // invalid, but not read without manual restart
    s.step(1, SL_STATE_RUN);
}

/// §4.5.1 "If the restart is deactivated, FB MON remains in the safe state if the EDM
/// inputs do not have the signal state 1" and NOTICE "FB MON only reports an EDM error if
/// manual restart is active"; G3; ABI §8.
#[test]
fn automatic_restart_with_edm_false_stays_safe_without_error() {
    for (opts, x) in [(SL_OPT_EDM1, 1), (SL_OPT_EDM2, 2)] {
        let mut s = mon_running(mon(0b1, opts));
        s.fb.bMonIn1 = 0;
        s.step(1, SL_STATE_SAFE);
        s.fb.set_edm(x, 0);
        s.fb.bMonIn1 = 1;
        s.fb.bRestart = 1; // not used
        for _ in 0..10 {
            s.step(100, SL_STATE_SAFE);
        }
        s.fb.set_edm(x, 1);
        s.step(1, SL_STATE_RUN);
    }
}

/// G12/§4.5.2 Restart with manual restart: "When starting the FB ... the signal sequence
/// 0->1->0 must be detected"; START "Error=0 MonOut=0 MonDelOut=0".
#[test]
fn manual_restart_start_up_requires_the_restart_sequence() {
    let mut s = Sim::new(mon(0b1111, MANUAL), T0);
    s.start_up(SL_STATE_SAFE);
    for _ in 0..10 {
        s.step(100, SL_STATE_SAFE);
    }
    s.fb.bRestart = 1;
    s.step(1, SL_STATE_START);
    s.step(1000, SL_STATE_START);
    s.fb.bRestart = 0;
    s.step(1, SL_STATE_RUN);
}

/// §4.5.2 Restart "or if an input has requested the safe state, the signal sequence
/// 0->1->0 must be detected at the restart input".
#[test]
fn manual_restart_after_a_request_requires_the_restart_sequence() {
    let mut s = mon_running(mon(0b1111, MANUAL));
    s.fb.bMonIn3 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bMonIn3 = 1;
    s.step(1, SL_STATE_SAFE);
    s.step(1000, SL_STATE_SAFE);
    s.restart();
}

/// §4.5.4 "If all active MonIn inputs ... are TRUE and the Restart signal changes from FALSE
/// to TRUE, the Start state is assumed"; G1: a request in START → SAFE.
#[test]
fn manual_restart_request_in_start_falls_back_to_safe() {
    let mut s = Sim::new(mon(0b11, MANUAL), T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.bRestart = 1;
    s.step(1, SL_STATE_START);
    s.fb.bMonIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bRestart = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bMonIn1 = 1;
    s.step(1, SL_STATE_SAFE);
}

/// §4.5.1 "When an input requests the safe state, the MonOut output immediately switches to
/// the safe state"; §4.5.2 SAFE (delay 0, G10). Each of the four MonIn inputs.
#[test]
fn each_monin_input_requests_the_safe_state_immediately() {
    for i in 0..4 {
        for opts in [0, MANUAL] {
            let mut s = mon_running(mon(0b1111, opts));
            s.fb.set_in(i, 0);
            s.step(1, SL_STATE_SAFE);
            s.step(100, SL_STATE_SAFE);
        }
    }
}

/// §4.5.1 "Each of the four inputs can be parameterized as break contact (0 requests the
/// safe state) or make contact (1 requests the safe state)".
#[test]
fn make_contact_monin_requests_the_safe_state_at_one() {
    let mut fb = mon(0b101, 0);
    fb.wInputNegated = 0b100;
    fb.bMonIn3 = 0;
    let mut s = mon_running(fb);
    s.fb.bMonIn3 = 1;
    s.step(1, SL_STATE_SAFE);
    s.fb.bMonIn3 = 0;
    s.step(1, SL_STATE_RUN);
}

/// ABI §7 "Inactive inputs are ignored".
#[test]
fn inactive_monin_inputs_are_ignored() {
    let mut s = mon_running(mon(0b0100, 0));
    for i in [0, 1, 3, SECURE1, SECURE2] {
        s.fb.set_in(i, 0);
        s.step(1, SL_STATE_RUN);
    }
}

/// §4.5.2 DELAYOUT "Error=0 MonOut=0 MonDelOut=1"; §4.5.1 "the MonDelOut output switches
/// after a configurable delay"; ABI §7 Timers.
#[test]
fn delayout_state_and_delayed_output() {
    let mut fb = mon(0b1, 0);
    fb.tMonDelOutDelay = 300;
    let mut s = mon_running(fb);
    let ta = s.t + 1;
    s.fb.bMonIn1 = 0;
    assert_eq!(s.at(ta), SL_OK);
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.at(ta + 299);
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.at(ta + 300);
    expect(&s.fb, SL_STATE_SAFE);
}

/// G10: DELAYOUT runs to the end of the delay even if the request disappears; then SAFE,
/// and an automatic MON goes SAFE → RUN.
#[test]
fn delayout_runs_to_the_end_then_automatic_restart_resumes() {
    let mut fb = mon(0b1, 0);
    fb.tMonDelOutDelay = 100;
    let mut s = mon_running(fb);
    let ta = s.t + 1;
    s.fb.bMonIn1 = 0;
    s.at(ta);
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.fb.bMonIn1 = 1;
    s.at(ta + 1);
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.at(ta + 99);
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.at(ta + 100);
    expect(&s.fb, SL_STATE_SAFE);
    s.step(1, SL_STATE_RUN);
}

/// G10: restart edges in DELAYOUT are ignored (manual restart).
#[test]
fn delayout_ignores_restart_edges() {
    let mut fb = mon(0b1, MANUAL);
    fb.tMonDelOutDelay = 100;
    let mut s = mon_running(fb);
    s.fb.bMonIn1 = 0;
    s.step(1, SL_STATE_DELAYOUT);
    s.fb.bMonIn1 = 1;
    s.fb.bRestart = 1;
    s.step(10, SL_STATE_DELAYOUT);
    s.fb.bRestart = 0;
    s.step(10, SL_STATE_DELAYOUT);
    s.step(79, SL_STATE_DELAYOUT);
    s.step(1, SL_STATE_SAFE);
    s.step(10, SL_STATE_SAFE);
    s.restart();
}

/// §4.5.2 DELAYOUT "This state can only be assumed if the Output Delay time ... is not
/// equal to 0"; G10.
#[test]
fn delay_zero_switches_both_outputs_off_at_once() {
    let mut s = mon_running(mon(0b1, 0));
    s.fb.bMonIn1 = 0;
    s.step(1, SL_STATE_SAFE);
}

/// DELAYOUT timer started just before the 2^32 wrap (ABI §4).
#[test]
fn output_delay_started_just_before_the_wrap() {
    let mut fb = mon(0b1, 0);
    fb.tMonDelOutDelay = 1000;
    let mut s = mon_running_at(fb, u32::MAX - 100);
    let ta = u32::MAX - 1;
    s.fb.bMonIn1 = 0;
    s.at(ta);
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.at(997); // 999 ms
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.at(998); // 1000 ms
    expect(&s.fb, SL_STATE_SAFE);
}

// ---------------------------------------------------------------------------------------
// Secure inputs (§4.5.1, §4.5.2 Secure1/2 and SAFE, PLC bSecure1, ABI §8, G8)
// ---------------------------------------------------------------------------------------

/// G8 / ABI §8 ("and" reading): with both Secure inputs active and both TRUE the MonIn
/// inputs are ignored ("the inputs MonIn(x) are ignored if Secure1 is 1").
#[test]
fn secure_bypass_with_every_active_secure_input_true() {
    let mut s = mon_running(mon(0b11 | SEC, 0));
    s.fb.bMonIn1 = 0;
    s.step(1, SL_STATE_RUN);
    s.fb.bMonIn2 = 0;
    s.step(100, SL_STATE_RUN);
    s.fb.bMonIn1 = 1;
    s.fb.bMonIn2 = 1;
    s.step(1, SL_STATE_RUN);
}

/// G8 rejects the "or" reading of the PLC text ("ignored as long as bSecure1 and/or
/// bSecure2 are 1"): one of two active Secure inputs TRUE does not bypass — "one Secure
/// channel alone cannot bypass" (§4.5.2 SAFE "at least one of the active MonIn inputs and at
/// least one of the active Secure inputs has requested the safe state").
#[test]
fn secure_one_of_two_true_does_not_bypass() {
    for (s1, s2) in [(1u8, 0u8), (0, 1)] {
        let mut s = mon_running(mon(0b1 | SEC, 0));
        s.fb.bSecure1 = s1;
        s.fb.bSecure2 = s2;
        s.step(1, SL_STATE_RUN); // MonIn TRUE: nothing requests
        s.fb.bMonIn1 = 0;
        s.step(1, SL_STATE_SAFE);
    }
}

/// G8: with a single active Secure input, that input TRUE bypasses (every active Secure
/// input TRUE).
#[test]
fn secure_single_active_input_true_bypasses() {
    for (bit, idx) in [(0b01_0000u16, SECURE1), (0b10_0000, SECURE2)] {
        let mut fb = mon(0b1 | bit, 0);
        fb.set_in(idx, 1);
        let mut s = mon_running(fb);
        s.fb.bMonIn1 = 0;
        s.step(1, SL_STATE_RUN);
        s.fb.set_in(idx, 0);
        s.step(1, SL_STATE_SAFE);
    }
}

/// §4.5.2 Secure1 "Parameterized as make contact: the inputs MonIn(x) are ignored if
/// Secure1 is 0".
#[test]
fn secure_make_contacts_bypass_at_zero() {
    let mut fb = mon(0b1 | SEC, 0);
    fb.wInputNegated = SEC;
    fb.bSecure1 = 1;
    fb.bSecure2 = 1; // make contacts at 1: no bypass
    let mut s = mon_running(fb);
    s.fb.bMonIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bMonIn1 = 1;
    s.step(1, SL_STATE_RUN);
    s.fb.bSecure1 = 0;
    s.fb.bSecure2 = 0; // bypass
    s.step(1, SL_STATE_RUN);
    s.fb.bMonIn1 = 0;
    s.step(1, SL_STATE_RUN);
}

/// G8 "Without active Secure inputs there is no bypass": Secure bytes of inactive inputs are
/// ignored.
#[test]
fn inactive_secure_inputs_do_not_bypass() {
    let mut fb = mon(0b1, 0);
    fb.bSecure1 = 1;
    fb.bSecure2 = 1;
    let mut s = mon_running(fb);
    s.fb.bMonIn1 = 0;
    s.step(1, SL_STATE_SAFE);
}

/// ABI §8: the Secure inputs only bypass; Secure FALSE (no bypass) with every MonIn TRUE
/// requests nothing — RUN (automatic start-up included).
#[test]
fn secure_inputs_false_with_monin_true_runs() {
    let mut fb = mon(0b11 | SEC, 0);
    fb.bSecure1 = 0;
    fb.bSecure2 = 0;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.step(1, SL_STATE_RUN);
    s.step(1000, SL_STATE_RUN);
}

/// §4.5.2 SAFE; G8: a bypassed MonIn requesting the safe state switches the outputs off
/// immediately when the bypass ends.
#[test]
fn end_of_bypass_switches_off_immediately() {
    let mut s = mon_running(mon(0b1 | SEC, 0));
    s.fb.bMonIn1 = 0;
    s.step(1, SL_STATE_RUN);
    s.fb.bSecure2 = 0;
    s.step(1, SL_STATE_SAFE);
}

/// G8 "The restart conditions use the same request (a bypassed MonIn does not prevent
/// START)".
#[test]
fn bypassed_monin_does_not_prevent_the_restart() {
    let mut fb = mon(0b1 | SEC, MANUAL);
    fb.bMonIn1 = 0;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.restart();
}

/// C7: an invalid Secure byte is logical FALSE (a safety input requesting the safe state)
/// whatever its negation: it cannot bypass.
#[test]
fn invalid_secure_byte_does_not_bypass() {
    for negated in [0, SEC] {
        let mut fb = mon(0b1 | SEC, 0);
        fb.wInputNegated = negated;
        let good = u8::from(negated == 0); // logical TRUE
        fb.bSecure1 = good;
        fb.bSecure2 = good;
        let mut s = mon_running(fb);
        s.fb.bMonIn1 = 0;
        s.step(1, SL_STATE_RUN);
        s.fb.bSecure1 = 2;
        assert_eq!(s.adv(1), SL_E_INVALID_BOOL);
        expect(&s.fb, SL_STATE_SAFE);
    }
}

// ---------------------------------------------------------------------------------------
// Discrepancy and diag bits 0, 1, 2, 8, 9, 10 (§4.5.1 pairs, §4.5.2 diag table, G14)
// ---------------------------------------------------------------------------------------

/// §4.5.2 diag: bit 0 "input group 1", bit 1 "input group 2", bit 2 "Secure input group";
/// with "Safe Inputs after Disc Error" bits 8, 9, 10 in addition (G5). Delay 0: ERROR
/// directly.
#[test]
fn discrepancy_diag_bits_of_the_three_pairs() {
    for safe_inputs in [false, true] {
        let opts = if safe_inputs {
            SL_OPT_SAFE_INPUTS_AFTER_DISC
        } else {
            0
        };
        for k in 0..3usize {
            let mut fb = mon(0b1111 | SEC, opts);
            match k {
                0 => fb.tDiscTime12 = 40,
                1 => fb.tDiscTime34 = 40,
                _ => fb.tDiscTimeSecure12 = 40,
            }
            let mut s = mon_running(fb);
            // MonIn pairs: bypassed by the Secure inputs; Secure pair: MonIn all TRUE.
            // Either way nothing requests the safe state and MON stays in RUN.
            s.fb.set_in(2 * k + 1, 0);
            s.step(1, SL_STATE_RUN);
            s.step(39, SL_STATE_RUN);
            s.step(1, SL_STATE_ERROR);
            let bit = 1u16 << k;
            let want = if safe_inputs { bit | (bit << 8) } else { bit };
            assert_eq!(s.fb.nDiag, want, "pair {k}, safe inputs {safe_inputs}");
        }
    }
}

/// As above without Secure inputs: a MonIn pair discrepancy requests the safe state and
/// fails at exactly the limit (ABI §7 Timers, G14).
#[test]
fn discrepancy_just_below_and_exactly_at_the_limit() {
    let mut fb = mon(0b1111, MANUAL);
    fb.tDiscTime34 = 250;
    let mut s = mon_running(fb);
    // just below: 249 ms, then agree
    let t1 = s.t + 1;
    s.fb.bMonIn3 = 0;
    s.at(t1);
    expect(&s.fb, SL_STATE_SAFE);
    s.at(t1 + 249);
    expect(&s.fb, SL_STATE_SAFE);
    s.fb.bMonIn4 = 0;
    s.at(t1 + 249);
    expect(&s.fb, SL_STATE_SAFE);
    s.at(t1 + 10_000);
    expect(&s.fb, SL_STATE_SAFE);
    // exactly at the limit
    let t2 = t1 + 10_001;
    s.fb.bMonIn3 = 1;
    s.at(t2);
    expect(&s.fb, SL_STATE_SAFE);
    s.at(t2 + 249);
    expect(&s.fb, SL_STATE_SAFE);
    s.at(t2 + 250);
    expect_error(&s.fb, SL_DIAG_DISC2);
}

/// G7 / §4.5.2 ERRORDELAY only from RUN/DELAYOUT: a discrepancy error in SAFE goes to ERROR
/// directly even with an output delay.
#[test]
fn discrepancy_in_safe_goes_to_error_even_with_a_delay() {
    let mut fb = mon(0b11, MANUAL);
    fb.tDiscTime12 = 50;
    fb.tMonDelOutDelay = 500;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.bMonIn2 = 0;
    s.step(1, SL_STATE_SAFE);
    s.step(50, SL_STATE_ERROR);
    assert_eq!(s.fb.nDiag, SL_DIAG_DISC1);
}

/// Discrepancy timer started just before the wrap (ABI §4).
#[test]
fn discrepancy_timer_started_just_before_the_wrap() {
    let mut fb = mon(0b11, 0);
    fb.tDiscTime12 = 20;
    let mut s = mon_running_at(fb, u32::MAX - 50);
    s.fb.bMonIn1 = 0;
    s.at(u32::MAX - 4);
    expect(&s.fb, SL_STATE_SAFE);
    s.at(14); // 19 ms
    expect(&s.fb, SL_STATE_SAFE);
    s.at(15); // 20 ms
    expect_error(&s.fb, SL_DIAG_DISC1);
}

// ---------------------------------------------------------------------------------------
// ERRORDELAY (§4.5.2 state 7, G7)
// ---------------------------------------------------------------------------------------

/// §4.5.2 ERRORDELAY "if a discrepancy error occurs in the RUN state (DiscError=TRUE), but
/// the delay time for the MonDelOut output has not yet expired ... Error=0 MonOut=0
/// MonDelOut=1"; G7: ERROR when the delay has elapsed since the error; G15: diag shows the
/// bits in ERRORDELAY. Here a Secure-pair discrepancy in RUN (MonIn TRUE: no request).
#[test]
fn errordelay_from_run_on_a_secure_pair_discrepancy() {
    let mut fb = mon(0b1 | SEC, 0);
    fb.tDiscTimeSecure12 = 50;
    fb.tMonDelOutDelay = 200;
    let mut s = mon_running(fb);
    let t1 = s.t + 1;
    s.fb.bSecure2 = 0;
    s.at(t1);
    expect(&s.fb, SL_STATE_RUN);
    s.at(t1 + 49);
    expect(&s.fb, SL_STATE_RUN);
    assert_eq!(s.at(t1 + 50), SL_OK);
    expect(&s.fb, SL_STATE_ERRORDELAY);
    assert_eq!(s.fb.nDiag, SL_DIAG_DISC3);
    s.at(t1 + 50 + 199);
    expect(&s.fb, SL_STATE_ERRORDELAY);
    assert_eq!(s.fb.nDiag, SL_DIAG_DISC3);
    s.at(t1 + 50 + 200);
    expect_error(&s.fb, SL_DIAG_DISC3);
}

/// G7 in RUN with a bypassed MonIn pair discrepancy; with "Safe Inputs after Disc Error"
/// the diag shows bits 0 and 8 already in ERRORDELAY.
#[test]
fn errordelay_from_run_on_a_bypassed_monin_pair_discrepancy() {
    let mut fb = mon(0b11 | SEC, SL_OPT_SAFE_INPUTS_AFTER_DISC);
    fb.tDiscTime12 = 100;
    fb.tMonDelOutDelay = 300;
    let mut s = mon_running(fb);
    let t1 = s.t + 1;
    s.fb.bMonIn1 = 0;
    s.at(t1);
    expect(&s.fb, SL_STATE_RUN);
    s.at(t1 + 100);
    expect(&s.fb, SL_STATE_ERRORDELAY);
    assert_eq!(s.fb.nDiag, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
    s.at(t1 + 399);
    expect(&s.fb, SL_STATE_ERRORDELAY);
    s.at(t1 + 400);
    expect_error(&s.fb, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
}

/// G7 "In DELAYOUT a discrepancy error → ERRORDELAY keeping the running delay (MonDelOut
/// never stays on longer than one delay after the first reason to switch off)".
#[test]
fn errordelay_from_delayout_keeps_the_running_delay() {
    let mut fb = mon(0b11, 0);
    fb.tDiscTime12 = 100;
    fb.tMonDelOutDelay = 300;
    let mut s = mon_running(fb);
    let t1 = s.t + 1;
    s.fb.bMonIn1 = 0;
    s.at(t1);
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.at(t1 + 99);
    expect(&s.fb, SL_STATE_DELAYOUT);
    s.at(t1 + 100);
    expect(&s.fb, SL_STATE_ERRORDELAY);
    assert_eq!(s.fb.nDiag, SL_DIAG_DISC1);
    s.at(t1 + 299);
    expect(&s.fb, SL_STATE_ERRORDELAY);
    s.at(t1 + 300);
    expect_error(&s.fb, SL_DIAG_DISC1);
}

/// §4.5.2 ERRORDELAY "This state can only be assumed if the Output Delay time ... is not
/// equal to 0": with delay 0 the same discrepancy goes to ERROR directly.
#[test]
fn no_errordelay_without_an_output_delay() {
    let mut fb = mon(0b1 | SEC, 0);
    fb.tDiscTimeSecure12 = 50;
    let mut s = mon_running(fb);
    s.fb.bSecure1 = 0;
    s.step(1, SL_STATE_RUN);
    s.step(50, SL_STATE_ERROR);
    assert_eq!(s.fb.nDiag, SL_DIAG_DISC3);
}

/// G7 "An EDM error goes to ERROR directly" (EDM reset time in RUN with an output delay).
#[test]
fn edm_error_in_run_goes_to_error_directly_not_errordelay() {
    let mut fb = mon(0b1, SL_OPT_EDM1);
    fb.tEDM1ResetTime = 50;
    fb.tMonDelOutDelay = 300;
    let mut s = mon_running(fb);
    let tr = s.t;
    s.at(tr + 49);
    expect(&s.fb, SL_STATE_RUN);
    s.at(tr + 50);
    expect_error(&s.fb, SL_DIAG_EDM1);
}

/// G7 "bRun FALSE in ERRORDELAY → ERROR"; C9: ERROR persists with bRun FALSE.
#[test]
fn run_false_in_errordelay_gives_error() {
    let mut fb = mon(0b1 | SEC, 0);
    fb.tDiscTimeSecure12 = 10;
    fb.tMonDelOutDelay = 1000;
    let mut s = mon_running(fb);
    s.fb.bSecure1 = 0;
    s.step(1, SL_STATE_RUN);
    s.step(10, SL_STATE_ERRORDELAY);
    s.fb.bRun = 0;
    s.adv(1);
    expect_error(&s.fb, SL_DIAG_DISC3);
    s.adv(5000);
    expect_error(&s.fb, SL_DIAG_DISC3);
}

/// ERRORDELAY's delay started just before the wrap.
#[test]
fn errordelay_started_just_before_the_wrap() {
    let mut fb = mon(0b1 | SEC, 0);
    fb.tDiscTimeSecure12 = 10;
    fb.tMonDelOutDelay = 100;
    let mut s = mon_running_at(fb, u32::MAX - 200);
    s.fb.bSecure1 = 0;
    s.at(u32::MAX - 60);
    expect(&s.fb, SL_STATE_RUN);
    s.at(u32::MAX - 50); // error at MAX - 50
    expect(&s.fb, SL_STATE_ERRORDELAY);
    s.at(48); // 99 ms
    expect(&s.fb, SL_STATE_ERRORDELAY);
    s.at(49); // 100 ms
    expect_error(&s.fb, SL_DIAG_DISC3);
}

// ---------------------------------------------------------------------------------------
// Manual function test (§4.5.1, §4.5.2 FUNCTEST, G9)
// ---------------------------------------------------------------------------------------

/// §4.5.1 "The safe state must have been requested at least once on each active MonIn input
/// after starting the FB MON if the manual function test is active, before an edge of the
/// restart input reacts"; §4.5.2 FUNCTEST "Error=0 MonOut=0 MonDelOut=0"; G9.
#[test]
fn function_test_with_manual_restart() {
    let mut s = Sim::new(mon(0b1111, MANUAL | FT), T0);
    s.start_up(SL_STATE_FUNCTEST);
    // restart edges are ignored in FUNCTEST
    s.fb.bRestart = 1;
    s.step(1, SL_STATE_FUNCTEST);
    s.fb.bRestart = 0;
    s.step(1, SL_STATE_FUNCTEST);
    for i in 0..3 {
        s.fb.set_in(i, 0);
        s.step(1, SL_STATE_FUNCTEST);
        s.fb.set_in(i, 1);
        s.step(1, SL_STATE_FUNCTEST);
    }
    // the last input completes the test: SAFE (G9), where the restart rules apply
    s.fb.bMonIn4 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bMonIn4 = 1;
    s.step(1, SL_STATE_SAFE);
    s.step(100, SL_STATE_SAFE);
    s.restart();
}

/// G9: an input never tested keeps FUNCTEST; restart sequences do nothing.
#[test]
fn function_test_with_an_untested_input_stays_in_functest() {
    let mut s = Sim::new(mon(0b1111, MANUAL | FT), T0);
    s.start_up(SL_STATE_FUNCTEST);
    for i in [0, 1, 3] {
        s.fb.set_in(i, 0);
        s.step(1, SL_STATE_FUNCTEST);
        s.fb.set_in(i, 1);
        s.step(1, SL_STATE_FUNCTEST);
    }
    for _ in 0..5 {
        s.fb.bRestart = 1;
        s.step(10, SL_STATE_FUNCTEST);
        s.fb.bRestart = 0;
        s.step(10, SL_STATE_FUNCTEST);
    }
}

/// G9: "Allowed with manual and automatic restart": after the test, SAFE → RUN by itself.
#[test]
fn function_test_with_automatic_restart() {
    let mut s = Sim::new(mon(0b11, FT), T0);
    s.start_up(SL_STATE_FUNCTEST);
    s.step(10, SL_STATE_FUNCTEST); // nothing requests, but the test is not done
    s.fb.bMonIn1 = 0;
    s.fb.bMonIn2 = 0; // both channels at once
    s.step(1, SL_STATE_SAFE);
    s.fb.bMonIn1 = 1;
    s.fb.bMonIn2 = 1;
    s.step(1, SL_STATE_RUN);
}

/// G9: only active MonIn inputs take part.
#[test]
fn function_test_requires_only_active_monin_inputs() {
    let mut s = Sim::new(mon(0b0010, FT), T0);
    s.start_up(SL_STATE_FUNCTEST);
    s.fb.bMonIn2 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bMonIn2 = 1;
    s.step(1, SL_STATE_RUN);
}

/// G9 "the start state is FUNCTEST ... after every RESET"; G14: discrepancy monitoring runs
/// in FUNCTEST.
#[test]
fn function_test_again_after_reset() {
    let mut fb = mon(0b11, MANUAL | FT);
    fb.tDiscTime12 = 50;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_FUNCTEST);
    s.fb.bMonIn1 = 0;
    s.step(1, SL_STATE_FUNCTEST);
    s.step(50, SL_STATE_ERROR);
    assert_eq!(s.fb.nDiag, SL_DIAG_DISC1);
    s.fb.bMonIn1 = 1;
    s.step(1, SL_STATE_ERROR);
    s.acknowledge(SL_STATE_FUNCTEST);
    s.fb.bMonIn1 = 0;
    s.fb.bMonIn2 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bMonIn1 = 1;
    s.fb.bMonIn2 = 1;
    s.step(1, SL_STATE_SAFE);
    s.restart();
}

/// G9: FUNCTEST again after STOP → run.
#[test]
fn function_test_again_after_stop() {
    let mut s = Sim::new(mon(0b1, FT), T0);
    s.start_up(SL_STATE_FUNCTEST);
    s.fb.bMonIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.fb.bMonIn1 = 1;
    s.step(1, SL_STATE_RUN);
    s.fb.bRun = 0;
    s.step(1, SL_STATE_STOP);
    s.start_up(SL_STATE_FUNCTEST);
    s.step(10, SL_STATE_FUNCTEST);
}

// ---------------------------------------------------------------------------------------
// EDM (§4.5.1, §4.5.2 EDM1/EDM2, ABI §7) — diag bits 4, 5
// ---------------------------------------------------------------------------------------

/// §4.5.1 "If Restart is enabled, the FB MON assumes the error state (FB Error) and sets the
/// Error output to 1 if the EDM inputs do not have the signal state TRUE"; §4.5.2 diag bits
/// 4 / 5.
#[test]
fn manual_restart_edm_false_at_restart_is_an_edm_error() {
    for (x, diag) in [(1, SL_DIAG_EDM1), (2, SL_DIAG_EDM2)] {
        let mut fb = mon(0b1, MANUAL | SL_OPT_EDM1 | SL_OPT_EDM2);
        fb.set_edm(x, 0);
        let mut s = Sim::new(fb, T0);
        s.start_up(SL_STATE_SAFE);
        s.fb.bRestart = 1;
        s.adv(1);
        expect_error(&s.fb, diag);
    }
}

/// §4.5.5: "If this value is not equal to 0, the timer is started when the output MonOut is
/// activated. If the EDM input does not switch to FALSE within this time, a function block
/// error is set and the outputs are switched off."
#[test]
fn edm_reset_time_expires_when_edm_stays_true() {
    for (opts, x, diag) in [
        (MANUAL | SL_OPT_EDM1, 1, SL_DIAG_EDM1),
        (SL_OPT_EDM2, 2, SL_DIAG_EDM2),
    ] {
        let mut fb = mon(0b1, opts);
        if x == 1 {
            fb.tEDM1ResetTime = 80;
        } else {
            fb.tEDM2ResetTime = 80;
        }
        let mut s = mon_running(fb);
        let tr = s.t;
        s.at(tr + 79);
        expect(&s.fb, SL_STATE_RUN);
        s.at(tr + 80);
        expect_error(&s.fb, diag);
    }
}

/// §4.5.5 satisfied when the EDM switches to FALSE in time; "switched off by entering 0".
#[test]
fn edm_reset_time_satisfied_or_off() {
    let mut fb = mon(0b1, SL_OPT_EDM1 | SL_OPT_EDM2);
    fb.tEDM1ResetTime = 80;
    let mut s = mon_running(fb);
    let tr = s.t;
    s.fb.bEDM1 = 0;
    s.at(tr + 79);
    expect(&s.fb, SL_STATE_RUN);
    s.at(tr + 10_000); // EDM2 has reset time 0: never checked
    expect(&s.fb, SL_STATE_RUN);
}

// ---------------------------------------------------------------------------------------
// Restart samples 1-3 (§4.5.4) — manual restart, EDM active
// ---------------------------------------------------------------------------------------

/// §4.5.4 Sample 1: "an event is triggered via MonIn and subsequent acknowledgement of the
/// MON function block via the Restart input. At least one of the EDM inputs is active."
#[test]
fn sample1_monin_event_then_restart() {
    let mut fb = mon(0b11, MANUAL | SL_OPT_EDM1);
    fb.tDiscTime12 = 50;
    let mut s = mon_running(fb);
    s.fb.bEDM1 = 0;
    s.step(10, SL_STATE_RUN);
    s.fb.bMonIn1 = 0;
    s.fb.bMonIn2 = 0;
    s.step(10, SL_STATE_SAFE);
    s.fb.bEDM1 = 1;
    s.step(10, SL_STATE_SAFE);
    s.fb.bMonIn1 = 1;
    s.fb.bMonIn2 = 1;
    s.step(10, SL_STATE_SAFE);
    s.step(10, SL_STATE_SAFE);
    s.fb.bRestart = 1;
    s.step(10, SL_STATE_START);
    s.fb.bRestart = 0;
    s.step(10, SL_STATE_RUN);
    s.fb.bEDM1 = 0;
    s.step(10, SL_STATE_RUN);
}

/// §4.5.4 Sample 2: "the rising edge of the Restart occurs before the rising edge of the
/// MonIn inputs. The Start state (FB state 6) is only assumed if both signals are TRUE. The
/// output is enabled with the falling edge at the Restart input."
#[test]
fn sample2_restart_rises_before_the_monin_inputs() {
    let mut fb = mon(0b11, MANUAL | SL_OPT_EDM1 | SL_OPT_EDM2);
    fb.tDiscTime12 = 50;
    let mut s = mon_running(fb);
    s.fb.bMonIn1 = 0;
    s.fb.bMonIn2 = 0;
    s.step(10, SL_STATE_SAFE);
    s.fb.bRestart = 1;
    s.step(10, SL_STATE_SAFE);
    s.step(10, SL_STATE_SAFE);
    s.fb.bMonIn1 = 1;
    s.fb.bMonIn2 = 1;
    s.step(10, SL_STATE_START);
    s.fb.bRestart = 0;
    s.step(10, SL_STATE_RUN);
}

/// §4.5.4 Sample 3: "the Restart is set to TRUE before the MonIn event takes place. With the
/// falling edge of the MonIn input, the EDM signal is immediately checked due to the Restart
/// input signal. This immediately leads to an EDM error" (G2: from the next cycle).
#[test]
fn sample3_restart_held_before_the_monin_event_gives_edm_error() {
    let mut fb = mon(0b1, MANUAL | SL_OPT_EDM2);
    fb.tMonDelOutDelay = 0;
    let mut s = mon_running(fb);
    s.fb.bEDM2 = 0;
    s.fb.bRestart = 1;
    s.step(10, SL_STATE_RUN);
    s.fb.bMonIn1 = 0;
    s.step(1, SL_STATE_SAFE);
    s.adv(1);
    expect_error(&s.fb, SL_DIAG_EDM2);
}

/// G2 "The restart EDM check runs in SAFE, START and FUNCTEST (outputs all off) whenever
/// Restart is TRUE" (manual restart).
#[test]
fn edm_is_checked_in_functest_when_restart_is_true() {
    let mut fb = mon(0b1, MANUAL | FT | SL_OPT_EDM1);
    fb.bEDM1 = 0;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_FUNCTEST);
    s.step(10, SL_STATE_FUNCTEST); // Restart FALSE: no check
    s.fb.bRestart = 1;
    s.adv(10);
    expect_error(&s.fb, SL_DIAG_EDM1);
}

/// G3: without manual restart there is no restart EDM check in FUNCTEST either.
#[test]
fn automatic_restart_has_no_edm_check_in_functest() {
    let mut fb = mon(0b1, FT | SL_OPT_EDM1);
    fb.bEDM1 = 0;
    fb.bRestart = 1;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_FUNCTEST);
    s.step(10, SL_STATE_FUNCTEST);
    s.fb.bMonIn1 = 0;
    s.step(10, SL_STATE_SAFE);
    s.fb.bMonIn1 = 1;
    s.step(10, SL_STATE_SAFE); // EDM1 FALSE: stays SAFE, no error
    s.fb.bEDM1 = 1;
    s.step(10, SL_STATE_RUN);
}
