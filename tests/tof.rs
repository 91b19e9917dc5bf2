//! FB TOF (manual §4.14 incl. the EL6910 timebases §4.14.4; docs/semantics.md rows T*):
//! every state and output value, the switch-off delay exactly at its limit per timebase,
//! timebase validation, wrapping time, clock errors, parameter changes, invalid BOOLs,
//! STOP switching off at once.

mod common;
use common::{aligned_tail, null_refused, offsets, run_steps};

use proptest::prelude::*;
use safelogic::base::member::Member;
use safelogic::ffi;
use safelogic::*;
use std::mem::offset_of;

fn tof(delay: u32, base: u16) -> FB_TOF {
    common::ready(FB_TOF {
        tDelay: delay,
        nTimeBase: base,
        wInputActive: 1,
        ..Default::default()
    })
}

/// A TOF in RUN (input TRUE, output TRUE) after calls at `t` and `t + 1`.
fn in_run(delay: u32, base: u16, t: u32) -> FB_TOF {
    let mut f = tof(delay, base);
    f.bRun = 1;
    f.bTofIn1 = 1;
    assert_eq!(f.cycle(t), SL_OK);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0));
    assert_eq!(f.cycle(t.wrapping_add(1)), SL_OK);
    assert_eq!(st(&f), (SL_STATE_RUN, 1));
    f
}

fn st(f: &FB_TOF) -> (u8, u8) {
    (f.nState, f.bTofOut)
}

#[test]
fn layout_matches_the_abi() {
    offsets!(FB_TOF; bTofIn1 => 8, bRun => 16, bErrAck => 17);
    assert_eq!(offset_of!(FB_TOF, bTofOut) % 8, 1, "output base + 1");
    aligned_tail!(FB_TOF);
}

#[test]
fn power_up_is_stop_with_the_output_false() {
    let mut f = common::ready(FB_TOF {
        tDelay: 100,
        wInputActive: 1,
        bTofIn1: 1,
        bTofOut: 1,
        ..Default::default()
    });
    assert_eq!((f.nState, f.bTofOut, f.nDiag), (SL_STATE_STOP, 0, 0));
    assert_eq!(f.cycle(0), SL_OK);
    assert_eq!(st(&f), (SL_STATE_STOP, 0), "bRun FALSE");
}

/// T5, T7: SAFE at start-up; RUN while the input is TRUE; DELAYOUT keeps the output on;
/// SAFE exactly when the delay is reached.
#[test]
fn every_state_and_output() {
    let mut f = tof(100, 0);
    f.bRun = 1;
    f.cycle(0);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0), "input FALSE at start: SAFE");
    f.cycle(10);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0));
    f.bTofIn1 = 1;
    f.cycle(20);
    assert_eq!(st(&f), (SL_STATE_RUN, 1), "input TRUE: on at once");
    f.bTofIn1 = 0;
    f.cycle(30);
    assert_eq!(st(&f), (SL_STATE_DELAYOUT, 1), "off delay starts at 30");
    f.cycle(129);
    assert_eq!(st(&f), (SL_STATE_DELAYOUT, 1));
    f.cycle(130);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0), "off after exactly 100 ms");
    f.cycle(5000);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0));
    assert_eq!(f.nDiag, 0);
}

/// T7: TRUE again before the delay has elapsed keeps the output on and discards the delay.
#[test]
fn input_true_again_keeps_the_output_on() {
    let mut f = in_run(100, 1, 0);
    f.bTofIn1 = 0;
    f.cycle(10);
    f.cycle(100);
    assert_eq!(st(&f), (SL_STATE_DELAYOUT, 1));
    f.bTofIn1 = 1;
    f.cycle(105);
    assert_eq!(st(&f), (SL_STATE_RUN, 1));
    f.bTofIn1 = 0;
    f.cycle(106);
    f.cycle(205);
    assert_eq!(st(&f), (SL_STATE_DELAYOUT, 1), "a fresh delay from 106");
    f.cycle(206);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0));
    // The input TRUE in the cycle the delay is reached wins.
    let mut f = in_run(50, 0, 0);
    f.bTofIn1 = 0;
    f.cycle(2);
    f.bTofIn1 = 1;
    f.cycle(52);
    assert_eq!(st(&f), (SL_STATE_RUN, 1));
}

/// T5: an input TRUE at start-up switches the output on in the first call after STOP →
/// SAFE (the call that leaves STOP only enters SAFE).
#[test]
fn input_true_at_start_up() {
    let mut f = tof(100, 0);
    f.bTofIn1 = 1;
    f.bRun = 1;
    f.cycle(0);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0));
    f.cycle(1);
    assert_eq!(st(&f), (SL_STATE_RUN, 1));
}

/// T7, ABI §7 Run: bRun FALSE switches the output off at once, from RUN and from
/// DELAYOUT (the off delay does not apply to a stop).
#[test]
fn stop_switches_off_at_once() {
    for delayout in [false, true] {
        let mut f = in_run(1000, 0, 0);
        if delayout {
            f.bTofIn1 = 0;
            f.cycle(5);
            assert_eq!(st(&f), (SL_STATE_DELAYOUT, 1));
        }
        f.bRun = 0;
        assert_eq!(f.cycle(6), SL_OK);
        assert_eq!(st(&f), (SL_STATE_STOP, 0));
        // Restart: SAFE first, RUN when the input is TRUE.
        f.bRun = 1;
        f.bTofIn1 = 1;
        f.cycle(7);
        assert_eq!(st(&f), (SL_STATE_SAFE, 0));
        f.cycle(8);
        assert_eq!(st(&f), (SL_STATE_RUN, 1));
    }
}

#[test]
fn negated_input_is_a_make_contact() {
    let mut f = common::ready(FB_TOF {
        tDelay: 10,
        wInputActive: 1,
        wInputNegated: 1,
        bRun: 1,
        ..Default::default()
    });
    f.cycle(0);
    f.cycle(1);
    assert_eq!(st(&f), (SL_STATE_RUN, 1), "raw FALSE negated is TRUE");
    f.bTofIn1 = 1;
    f.cycle(2);
    assert_eq!(st(&f), (SL_STATE_DELAYOUT, 1));
    f.cycle(12);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0));
}

/// ABI §2, T8: an invalid byte reads FALSE: in RUN the off delay starts (the output stays
/// on for the delay), in SAFE the output stays off; the call returns SL_E_INVALID_BOOL.
#[test]
fn invalid_bool() {
    for negated in [0u16, 1] {
        let mut f = common::ready(FB_TOF {
            tDelay: 10,
            wInputActive: 1,
            wInputNegated: negated,
            bRun: 1,
            ..Default::default()
        });
        f.bTofIn1 = u8::from(negated == 0);
        f.cycle(0);
        f.cycle(1);
        assert_eq!(st(&f), (SL_STATE_RUN, 1));
        f.bTofIn1 = 2;
        assert_eq!(f.cycle(2), SL_E_INVALID_BOOL);
        assert_eq!(st(&f), (SL_STATE_DELAYOUT, 1));
        assert_eq!(f.cycle(12), SL_E_INVALID_BOOL);
        assert_eq!(st(&f), (SL_STATE_SAFE, 0));
        f.bTofIn1 = 0x80;
        assert_eq!(f.cycle(13), SL_E_INVALID_BOOL);
        assert_eq!(st(&f), (SL_STATE_SAFE, 0), "never switches on");
    }
}

/// The output goes off exactly `delay` ms after the input fell, not one ms earlier.
fn off_exactly_after(delay: u32, base: u16, t0: u32) {
    let mut f = in_run(delay, base, t0);
    f.bTofIn1 = 0;
    let start = t0.wrapping_add(2);
    assert_eq!(f.cycle(start), SL_OK);
    let (during, after) = ((SL_STATE_DELAYOUT, 1), (SL_STATE_SAFE, 0));
    common::timer::walk_delay(&mut f, st, (start, delay, base), during, after);
}

/// T1, T3: every timebase, just below and at the limit, up to 60,000 s.
#[test]
fn delays_at_and_below_the_limit_of_every_time_base() {
    common::timer::at_and_below_the_limits(|delay, base| off_exactly_after(delay, base, 100));
    off_exactly_after(SL_TIMER_DELAY_MAX, SL_TIMEBASE_AUTO, u32::MAX - 7);
}

/// C6, T1, T2, T4.
#[test]
fn config_errors() {
    let bad = [
        (60_001u32, 1u16, 1u16, 0u16),
        (600_010, 10, 1, 0),
        (6_000_100, 100, 1, 0),
        (60_001_000, 1000, 1, 0),
        (60_000_001, 0, 1, 0),
        (u32::MAX, 0, 1, 0),
        (1005, 10, 1, 0),
        (60_001, 0, 1, 0),
        (0, 0, 1, 0),
        (1000, 3, 1, 0),
        (1000, 10_000, 1, 0),
        (1000, u16::MAX, 1, 0),
        (100, 0, 0, 0),
        (100, 0, 0b11, 0),
        (100, 0, 1, 0b10),
    ];
    for (delay, base, active, negated) in bad {
        let f = common::refused(
            FB_TOF {
                tDelay: delay,
                nTimeBase: base,
                wInputActive: active,
                wInputNegated: negated,
                bTofIn1: 1,
                bRun: 1,
                ..Default::default()
            },
            &[0, 1],
        );
        assert_eq!(st(&f), (SL_STATE_STOP, 0));
    }
}

#[test]
fn time_wraps_across_2_pow_32() {
    for t0 in [u32::MAX - 60, u32::MAX - 2, u32::MAX - 101] {
        let mut f = in_run(100, 0, t0);
        f.bTofIn1 = 0;
        let s = t0.wrapping_add(2);
        f.cycle(s);
        f.cycle(s.wrapping_add(99));
        assert_eq!(st(&f), (SL_STATE_DELAYOUT, 1));
        f.cycle(s.wrapping_add(100));
        assert_eq!(st(&f), (SL_STATE_SAFE, 0));
    }
}

/// SL_E_CLOCK in DELAYOUT: ERROR switches the output off at once.
#[test]
fn clock_backwards() {
    let mut f = in_run(100, 0, 1000);
    let diag = |f: &FB_TOF| (f.nState, f.bTofOut, f.nDiag);
    #[rustfmt::skip]
    run_steps("clock backwards", &mut f, diag, &[
        (1010, |f| f.bTofIn1 = 0, SL_OK, Some((SL_STATE_DELAYOUT, 1, 0)), ""),
        (1009, |_| {}, SL_E_CLOCK, Some((SL_STATE_ERROR, 0, SL_DIAG_CLOCK)), ""),
    ]);
    #[rustfmt::skip]
    run_steps("acknowledged", &mut f, st, &[
        (1011, |f| f.bErrAck = 1, SL_OK, Some((SL_STATE_RESET, 0)), ""),
        (1012, |f| (f.bErrAck, f.bTofIn1) = (0, 1), SL_OK, Some((SL_STATE_SAFE, 0)), ""),
        (1013, |_| {}, SL_OK, Some((SL_STATE_RUN, 1)), ""),
    ]);
}

/// C5: a changed parameter while running → ERROR (output off at once, also in DELAYOUT).
#[test]
fn parameter_change_while_running() {
    let mut f = in_run(100, 0, 0);
    let diag = |f: &FB_TOF| (f.nState, f.bTofOut, f.nDiag);
    #[rustfmt::skip]
    run_steps("changed", &mut f, diag, &[
        (5, |f| f.bTofIn1 = 0, SL_OK, None, ""),
        (6, |f| f.tDelay = 200, SL_E_PARAM_CHANGED, Some((SL_STATE_ERROR, 0, SL_DIAG_PARAM_CHANGED)), ""),
    ]);
    // Stop, then the new delay is latched and acknowledged.
    #[rustfmt::skip]
    run_steps("stopped", &mut f, |f| f.nState, &[
        (7, |f| (f.bRun, f.bErrAck) = (0, 1), SL_OK, Some(SL_STATE_RESET), ""),
        (8, |f| f.bErrAck = 0, SL_OK, Some(SL_STATE_STOP), ""),
    ]);
    #[rustfmt::skip]
    run_steps("restarted", &mut f, st, &[
        (9, |f| (f.bRun, f.bTofIn1) = (1, 1), SL_OK, None, ""),
        (10, |_| {}, SL_OK, None, ""),
        (11, |f| f.bTofIn1 = 0, SL_OK, None, ""),
        (210, |_| {}, SL_OK, Some((SL_STATE_DELAYOUT, 1)), ""),
        (211, |_| {}, SL_OK, Some((SL_STATE_SAFE, 0)), "the new 200 ms delay"),
    ]);
}

/// T9: a corrupted timer start in DELAYOUT is found before it can prolong the output.
#[test]
fn corrupted_timer_start_is_detected() {
    let mut f = in_run(100, 0, 0);
    #[rustfmt::skip]
    run_steps("corrupted", &mut f, |f| (f.nState, f.bTofOut, f.nDiag), &[
        (10, |f| f.bTofIn1 = 0, SL_OK, None, ""),
        (50, |f| f.stPrivate.stHeader.tPhase = 90, SL_E_CORRUPT, Some((SL_STATE_ERROR, 0, SL_DIAG_CORRUPT)), ""),
    ]);
}

#[test]
fn c_functions_registry_and_member() {
    let mut f = FB_TOF {
        tDelay: 10,
        wInputActive: 1,
        bRun: 1,
        bTofIn1: 1,
        ..Default::default()
    };
    assert_eq!(unsafe { ffi::sl_tof_init(&mut f) }, SL_OK);
    null_refused!(ffi::sl_tof_init, ffi::sl_tof_cycle);
    assert_eq!(unsafe { ffi::sl_tof_cycle(&mut f, 0) }, SL_OK);
    assert_eq!(unsafe { ffi::sl_tof_cycle(&mut f, 1) }, SL_OK);
    assert_eq!(st(&f), (SL_STATE_RUN, 1));
    for (s, n) in [(8, "DELAYOUT"), (1, "RUN"), (3, "SAFE"), (9, "?")] {
        assert_eq!(common::state_str(SL_TYPE_TOF, s), n, "state {s}");
    }
    let m: &mut dyn Member = &mut f;
    assert!(m.input_mut(offset_of!(FB_TOF, bTofIn1) as u16).is_some());
    assert_eq!(m.output(offset_of!(FB_TOF, bTofOut) as u16), Some(1));
    assert_eq!(SL_TYPE_TOF, 15);
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_DELAYOUT, SL_STATE_SAFE, SL_STATE_STOP];
    /// No output TRUE in STOP/ERROR/RESET; FALSE at once when bRun is FALSE; a running TOF
    /// switches its output off only after the input has been FALSE in every call for at
    /// least tDelay; an input TRUE in a running state switches it on in the same call.
    fn output_off_only_after_the_input_was_false_for_the_delay(
        delay in 1u32..200,
        negated in 0u16..2,
        t0 in any::<u32>(),
        steps in proptest::collection::vec((0u32..120, 0u8..4, 0u8..8, 0u8..4), 1..200)
    ) {
        let mut f = FB_TOF { tDelay: delay, wInputActive: 1, wInputNegated: negated, ..Default::default() };
        prop_assert_eq!(f.init(), SL_OK);
        let mut t = t0;
        let mut false_since: Option<u32> = None;
        let mut prev = (f.nState, f.bTofOut);
        for (dt, input, run, ack) in steps {
            t = t.wrapping_add(dt);
            f.bTofIn1 = match input { 0 => 0, 1 => 1, 2 => 3, _ => 0xFE };
            f.bRun = u8::from(run != 0);
            f.bErrAck = u8::from(ack == 0);
            let status = f.cycle(t);
            common::saw(f.nState);
            prop_assert!(status == SL_OK || status == SL_E_INVALID_BOOL, "status {}", status);
            let logical = f.bTofIn1 <= 1 && (f.bTofIn1 == 1) != (negated == 1);
            if logical {
                false_since = None;
            } else {
                false_since.get_or_insert(t);
            }
            if matches!(f.nState, SL_STATE_STOP | SL_STATE_ERROR | SL_STATE_RESET) {
                prop_assert_eq!(f.bTofOut, 0);
            }
            if f.bRun == 0 {
                prop_assert_eq!(st(&f), (SL_STATE_STOP, 0), "FALSE at once in STOP");
            }
            if f.bTofOut == 1 {
                prop_assert!(matches!(f.nState, SL_STATE_RUN | SL_STATE_DELAYOUT));
            }
            let running = |s: u8| matches!(s, SL_STATE_RUN | SL_STATE_DELAYOUT | SL_STATE_SAFE);
            if prev.1 == 1 && f.bTofOut == 0 && f.bRun == 1 {
                prop_assert_eq!(f.nState, SL_STATE_SAFE);
                let s = false_since.expect("switched off with the input TRUE");
                prop_assert!(t.wrapping_sub(s) >= delay, "off after {} < {}", t.wrapping_sub(s), delay);
            }
            if f.bRun == 1 && running(prev.0) && logical {
                prop_assert_eq!(st(&f), (SL_STATE_RUN, 1), "input TRUE: on in the same call");
            }
            prev = (f.nState, f.bTofOut);
        }
    }
}
