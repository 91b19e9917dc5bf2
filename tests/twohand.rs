//! FB TWOHAND (manual §4.7; ABI §3, §5, §7, §9; docs/semantics.md rows H1–H14 and C1–C12):
//! layout, configuration, every state and output, the re-trigger rule, pair discrepancy,
//! the window between the groups, the two-hand error, "Safe Inputs after Disc Error",
//! acknowledgement, invalid BOOLs, the envelope errors, the C functions, property tests.
//! Expected values come from the manual, the ABI and semantics.md.

mod common;
use common::{aligned_tail, null_refused, offsets, output_base};

use proptest::prelude::*;
use safelogic::group::{self, Member};
use safelogic::*;
use std::mem::{offset_of, size_of};

const ONE: u8 = SL_STATE_TWOHAND_1BUTTON;
const TWO: u8 = SL_STATE_TWOHAND_2BUTTON;
const REL: u8 = SL_STATE_TWOHAND_RELEASE;

/// Single-channel groups: TwoHand1 (group 1) and TwoHand3 (group 2).
const SINGLE: u16 = 0b0101;
/// Two-channel groups: all four inputs.
const DUAL: u16 = 0b1111;
/// Input bits that actuate both groups / group 1 / group 2 for SINGLE and DUAL (no negation).
const G1: u8 = 0b0011;
const G2: u8 = 0b1100;

#[derive(Clone, Copy, Default)]
struct Cfg {
    active: u16,
    negated: u16,
    d12: u32,
    d34: u32,
    pairs: u32,
    options: u32,
}

fn cfg(active: u16) -> Cfg {
    Cfg {
        active,
        ..Default::default()
    }
}

fn build(c: Cfg) -> FB_TWOHAND {
    FB_TWOHAND {
        wInputActive: c.active,
        wInputNegated: c.negated,
        tDiscTime12: c.d12,
        tDiscTime34: c.d34,
        tDiscTimePairs: c.pairs,
        dwOptions: c.options,
        ..Default::default()
    }
}

fn twohand(c: Cfg) -> FB_TWOHAND {
    let mut b = build(c);
    assert_eq!(b.init(), SL_OK);
    b
}

/// Sets TwoHand1..4 from bits 0..3 (bytes 0/1).
fn set(b: &mut FB_TWOHAND, bits: u8) {
    b.bTwoHand1 = bits & 1;
    b.bTwoHand2 = (bits >> 1) & 1;
    b.bTwoHand3 = (bits >> 2) & 1;
    b.bTwoHand4 = (bits >> 3) & 1;
}

/// (nState, bError, bTwoHandOut).
fn st(b: &FB_TWOHAND) -> (u8, u8, u8) {
    (b.nState, b.bError, b.bTwoHandOut)
}

/// A started block (bRun TRUE, STOP → SAFE at `t`) with every input released.
fn started(c: Cfg, t: u32) -> FB_TWOHAND {
    let mut b = twohand(c);
    b.bRun = 1;
    assert_eq!(b.cycle(t), SL_OK);
    assert_eq!(st(&b), (SL_STATE_SAFE, 0, 0));
    b
}

/// RUN through SAFE → 1BUTTON → RUN at t+1, t+2.
fn running(c: Cfg, t: u32) -> FB_TWOHAND {
    let mut b = started(c, t);
    set(&mut b, G1);
    b.cycle(t + 1);
    assert_eq!(st(&b), (ONE, 0, 0));
    set(&mut b, G1 | G2);
    b.cycle(t + 2);
    assert_eq!(st(&b), (SL_STATE_RUN, 0, 1));
    b
}

fn assert_error(b: &FB_TWOHAND, diag: u16) {
    // §4.7.2 ERROR: Error=1 TwoHandOut=0.
    assert_eq!(st(b), (SL_STATE_ERROR, 1, 0));
    assert_eq!(b.nDiag, diag);
}

#[test]
fn layout_matches_the_abi() {
    offsets!(FB_TWOHAND; bTwoHand1 => 8, bTwoHand4 => 11, bRun => 16, bErrAck => 17);
    let base = output_base!(FB_TWOHAND);
    offsets!(FB_TWOHAND, from base; bTwoHandOut => 1);
    aligned_tail!(FB_TWOHAND);
    assert!(size_of::<SL_TWOHAND_PRIVATE>() <= 64);
    assert_eq!(SL_TYPE_TWOHAND, 8);
    assert_eq!((ONE, TWO, REL), (11, 12, 13));
}

#[test]
fn init_gives_the_power_up_image_and_keeps_the_inputs() {
    let mut b = build(cfg(SINGLE));
    b.bTwoHand1 = 1;
    b.bRun = 1;
    b.bTwoHandOut = 1;
    b.bError = 1;
    b.nDiag = 3;
    assert_eq!(b.init(), SL_OK);
    assert_eq!((st(&b), b.nDiag), ((SL_STATE_STOP, 0, 0), 0));
    assert_eq!((b.bTwoHand1, b.bRun, b.wInputActive), (1, 1, SINGLE));
}

#[test]
fn configuration_errors() {
    // H2, H3, C6.
    let bad = [
        cfg(0),
        cfg(0b0011),
        cfg(0b1100),
        cfg(0b0001),
        cfg(SINGLE | 0b1_0000),
        Cfg {
            negated: 0b1_0000,
            ..cfg(SINGLE)
        },
        Cfg {
            d12: 10,
            ..cfg(SINGLE)
        },
        Cfg {
            d34: 10,
            ..cfg(0b0111)
        },
        Cfg {
            d12: SL_TIME_PARAM_MAX + 1,
            ..cfg(DUAL)
        },
        Cfg {
            d34: SL_TIME_PARAM_MAX + 1,
            ..cfg(DUAL)
        },
        Cfg {
            pairs: 2501,
            ..cfg(SINGLE)
        },
        Cfg {
            options: SL_OPT_EDM1,
            ..cfg(SINGLE)
        },
        Cfg {
            options: SL_OPT_MANUAL_RESTART,
            ..cfg(SINGLE)
        },
        Cfg {
            options: 1 << 8,
            ..cfg(SINGLE)
        },
    ];
    for c in bad {
        let mut b = build(c);
        assert_eq!(b.init(), SL_E_CONFIG, "{:#x}", c.active);
        assert_eq!(st(&b), (SL_STATE_STOP, 0, 0));
        b.bRun = 1;
        set(&mut b, 0b1111);
        assert_eq!(b.cycle(0), SL_E_CONFIG);
        assert_eq!(b.cycle(1), SL_E_CONFIG);
        assert_eq!(st(&b), (SL_STATE_STOP, 0, 0));
    }
    let good = [
        cfg(SINGLE),
        cfg(0b1010),
        cfg(0b0110),
        Cfg {
            pairs: SL_TWOHAND_PAIRS_TIME_MAX,
            d12: SL_TIME_PARAM_MAX,
            d34: 1,
            options: SL_OPT_SAFE_INPUTS_AFTER_DISC,
            ..cfg(DUAL)
        },
        // C6: negation bits of inactive inputs are ignored.
        Cfg {
            negated: 0b1010,
            ..cfg(SINGLE)
        },
    ];
    for c in good {
        assert_eq!(build(c).init(), SL_OK);
    }
}

#[test]
fn stop_while_run_is_false() {
    let mut b = twohand(cfg(SINGLE));
    set(&mut b, 0b0101);
    for t in 0..3 {
        assert_eq!(b.cycle(t), SL_OK);
        assert_eq!(st(&b), (SL_STATE_STOP, 0, 0));
    }
    // From RUN and from 1BUTTON: STOP with the output off in the same call.
    let mut b = running(cfg(SINGLE), 0);
    b.bRun = 0;
    b.cycle(5);
    assert_eq!(st(&b), (SL_STATE_STOP, 0, 0));
    let mut b = started(cfg(SINGLE), 0);
    set(&mut b, G1);
    b.cycle(1);
    b.bRun = 0;
    b.cycle(2);
    assert_eq!(st(&b), (SL_STATE_STOP, 0, 0));
}

#[test]
fn start_state_depends_on_the_inputs() {
    // H5: released -> SAFE; a held button -> RELEASE until everything is let go.
    let b = started(cfg(SINGLE), 0);
    assert_eq!(b.nDiag, 0);
    let mut b = twohand(cfg(SINGLE));
    set(&mut b, G1 | G2);
    b.bRun = 1;
    b.cycle(0);
    assert_eq!(st(&b), (REL, 0, 0));
    b.cycle(1);
    assert_eq!(
        st(&b),
        (REL, 0, 0),
        "both groups held through start-up: no output"
    );
    set(&mut b, G2);
    b.cycle(2);
    assert_eq!(st(&b), (REL, 0, 0));
    set(&mut b, 0);
    b.cycle(3);
    assert_eq!(st(&b), (SL_STATE_SAFE, 0, 0));
}

#[test]
fn one_button_then_two_buttons_then_release() {
    // §4.7.2 state table, single-channel groups.
    let mut b = started(cfg(SINGLE), 0);
    set(&mut b, 0b0001);
    b.cycle(1);
    assert_eq!(st(&b), (ONE, 0, 0), "1BUTTON: Error=0 TwoHandOut=0");
    b.cycle(50);
    assert_eq!(st(&b), (ONE, 0, 0));
    set(&mut b, 0b0101);
    b.cycle(51);
    assert_eq!(st(&b), (SL_STATE_RUN, 0, 1), "RUN: Error=0 TwoHandOut=1");
    b.cycle(900);
    assert_eq!(st(&b), (SL_STATE_RUN, 0, 1));
    // H12: one group released -> RELEASE at once.
    set(&mut b, 0b0100);
    b.cycle(901);
    assert_eq!(st(&b), (REL, 0, 0), "RELEASE: Error=0 TwoHandOut=0");
    // §4.7.1 re-trigger rule: pressing again without releasing both does nothing.
    set(&mut b, 0b0101);
    b.cycle(902);
    assert_eq!(st(&b), (REL, 0, 0));
    set(&mut b, 0b0001);
    b.cycle(903);
    assert_eq!(st(&b), (REL, 0, 0));
    set(&mut b, 0);
    b.cycle(904);
    assert_eq!(
        st(&b),
        (SL_STATE_SAFE, 0, 0),
        "SAFE: all active inputs FALSE"
    );
    // 2BUTTON path.
    set(&mut b, 0b0100);
    b.cycle(905);
    assert_eq!(st(&b), (TWO, 0, 0));
    set(&mut b, 0b0101);
    b.cycle(906);
    assert_eq!(st(&b), (SL_STATE_RUN, 0, 1));
    // Both released in one call: RELEASE, then SAFE (H12).
    set(&mut b, 0);
    b.cycle(907);
    assert_eq!(st(&b), (REL, 0, 0));
    b.cycle(908);
    assert_eq!(st(&b), (SL_STATE_SAFE, 0, 0));
}

#[test]
fn simultaneous_actuation_passes_through_one_button() {
    // H8.
    let mut b = started(
        Cfg {
            pairs: 1,
            ..cfg(SINGLE)
        },
        0,
    );
    set(&mut b, 0b0101);
    b.cycle(10);
    assert_eq!(st(&b), (ONE, 0, 0));
    b.cycle(20);
    assert_eq!(
        st(&b),
        (SL_STATE_RUN, 0, 1),
        "within any window: both came at once"
    );
}

#[test]
fn two_channel_group_is_actuated_only_with_both_channels() {
    // H1.
    let mut b = started(cfg(DUAL), 0);
    set(&mut b, 0b0001);
    b.cycle(1);
    assert_eq!(st(&b), (SL_STATE_SAFE, 0, 0));
    set(&mut b, 0b0111);
    b.cycle(2);
    assert_eq!(
        st(&b),
        (ONE, 0, 0),
        "group 2 only half pressed keeps 1BUTTON"
    );
    b.cycle(3);
    assert_eq!(st(&b), (ONE, 0, 0));
    set(&mut b, 0b1111);
    b.cycle(4);
    assert_eq!(st(&b), (SL_STATE_RUN, 0, 1));
    // One channel of group 2 drops: RUN -> RELEASE.
    set(&mut b, 0b0111);
    b.cycle(5);
    assert_eq!(st(&b), (REL, 0, 0));
    // One channel still TRUE: not released (H6).
    set(&mut b, 0b0010);
    b.cycle(6);
    assert_eq!(st(&b), (REL, 0, 0));
    set(&mut b, 0);
    b.cycle(7);
    assert_eq!(st(&b), (SL_STATE_SAFE, 0, 0));
}

#[test]
fn make_contacts_are_negated() {
    // §4.7.1 "Each input can be configured as break contact (NC) or make contact (NO)":
    // channel 2 of each group negated (NC + NO buttons).
    let c = Cfg {
        negated: 0b1010,
        ..cfg(DUAL)
    };
    let mut b = twohand(c);
    // Raw released image: NC open (0) ... logical FALSE; NO closed (1) ... logical FALSE.
    set(&mut b, 0b1010);
    b.bRun = 1;
    b.cycle(0);
    assert_eq!(st(&b), (SL_STATE_SAFE, 0, 0));
    // Group 1 pressed: raw 1, 0.
    set(&mut b, 0b1001);
    b.cycle(1);
    assert_eq!(st(&b), (ONE, 0, 0));
    set(&mut b, 0b0101);
    b.cycle(2);
    assert_eq!(st(&b), (SL_STATE_RUN, 0, 1));
    // All raw bytes 0: the make contacts read TRUE -> not released, not actuated.
    set(&mut b, 0);
    b.cycle(3);
    assert_eq!(st(&b), (REL, 0, 0));
    b.cycle(4);
    assert_eq!(st(&b), (REL, 0, 0));
    set(&mut b, 0b1010);
    b.cycle(5);
    assert_eq!(st(&b), (SL_STATE_SAFE, 0, 0));
}

#[test]
fn second_group_without_the_first_is_the_two_hand_error() {
    // H10, diag bit 6.
    let mut b = started(cfg(SINGLE), 0);
    set(&mut b, 0b0001);
    b.cycle(1);
    assert_eq!(b.nState, ONE);
    set(&mut b, 0b0100);
    assert_eq!(b.cycle(2), SL_OK);
    assert_error(&b, SL_DIAG_TWOHAND_ERROR);
    // The same from 2BUTTON.
    let mut b = started(cfg(DUAL), 0);
    set(&mut b, G2);
    b.cycle(1);
    assert_eq!(b.nState, TWO);
    set(&mut b, G1 | 0b0100);
    b.cycle(2);
    assert_error(&b, SL_DIAG_TWOHAND_ERROR);
    // H13: nothing remains; the next ErrAck edge acknowledges, start state RELEASE (H5).
    b.bErrAck = 1;
    b.cycle(3);
    assert_eq!((st(&b), b.nDiag), ((SL_STATE_RESET, 0, 0), 0));
    b.bErrAck = 0;
    b.cycle(4);
    assert_eq!(st(&b), (REL, 0, 0));
}

#[test]
fn letting_go_of_the_first_group_starts_over() {
    // H9: everything released -> SAFE.
    let mut b = started(cfg(DUAL), 0);
    set(&mut b, G1);
    b.cycle(1);
    set(&mut b, 0);
    b.cycle(2);
    assert_eq!(st(&b), (SL_STATE_SAFE, 0, 0));
    // First group partly released -> RELEASE; then the second group alone: no error, no
    // output (the first group was let go in an earlier call).
    set(&mut b, G1);
    b.cycle(3);
    assert_eq!(b.nState, ONE);
    set(&mut b, 0b0001);
    b.cycle(4);
    assert_eq!(st(&b), (REL, 0, 0));
    set(&mut b, 0b0001 | G2);
    b.cycle(5);
    assert_eq!(st(&b), (REL, 0, 0));
    set(&mut b, G1 | G2);
    b.cycle(6);
    assert_eq!(st(&b), (REL, 0, 0), "RUN only from 1BUTTON/2BUTTON");
}

#[test]
fn window_between_the_groups_just_below_and_at_the_limit() {
    // H11: second group 1 ms before the window ends: RUN.
    let c = Cfg {
        pairs: 500,
        ..cfg(SINGLE)
    };
    let mut b = started(c, 0);
    set(&mut b, 0b0001);
    b.cycle(1000);
    b.cycle(1499);
    assert_eq!(b.nState, ONE);
    set(&mut b, 0b0101);
    b.cycle(1499);
    assert_eq!(st(&b), (SL_STATE_RUN, 0, 1));
    // At the limit, still waiting: ERROR bit 2.
    let mut b = started(c, 0);
    set(&mut b, 0b0100);
    b.cycle(1000);
    assert_eq!(b.nState, TWO);
    b.cycle(1499);
    assert_eq!(b.nState, TWO);
    assert_eq!(b.cycle(1500), SL_OK);
    assert_error(&b, SL_DIAG_TWOHAND_PAIRS);
    // The second group in the very call the window is reached: RUN.
    let mut b = started(c, 0);
    set(&mut b, 0b0001);
    b.cycle(1000);
    set(&mut b, 0b0101);
    b.cycle(1500);
    assert_eq!(st(&b), (SL_STATE_RUN, 0, 1));
    // The maximum window.
    let mut b = started(
        Cfg {
            pairs: 2500,
            ..cfg(SINGLE)
        },
        0,
    );
    set(&mut b, 0b0001);
    b.cycle(10);
    b.cycle(2509);
    assert_eq!(b.nState, ONE);
    b.cycle(2510);
    assert_error(&b, SL_DIAG_TWOHAND_PAIRS);
}

#[test]
fn window_is_measured_from_the_first_actuation_only() {
    // H9/H11: a flicker of the waiting group's second channel ends 1BUTTON, so a new
    // attempt (after a full release) gets a new window.
    let c = Cfg {
        pairs: 100,
        ..cfg(DUAL)
    };
    let mut b = started(c, 0);
    set(&mut b, G1);
    b.cycle(10);
    assert_eq!(b.nState, ONE);
    set(&mut b, 0b0001);
    b.cycle(60);
    assert_eq!(st(&b), (REL, 0, 0));
    set(&mut b, 0);
    b.cycle(70);
    assert_eq!(b.nState, SL_STATE_SAFE);
    set(&mut b, G1);
    b.cycle(200);
    b.cycle(299);
    assert_eq!(b.nState, ONE, "window counted from 200, not from 10");
    set(&mut b, G1 | G2);
    b.cycle(299);
    assert_eq!(st(&b), (SL_STATE_RUN, 0, 1));
    // Releasing after RUN is never timed.
    let c = Cfg {
        pairs: 100,
        ..cfg(SINGLE)
    };
    let mut b = running(c, 0);
    set(&mut b, 0b0001);
    b.cycle(10);
    assert_eq!(b.nState, REL);
    for t in (100..10_000).step_by(500) {
        assert_eq!(b.cycle(t), SL_OK);
        assert_eq!(st(&b), (REL, 0, 0));
    }
    // Window 0: waiting is not timed.
    let mut b = started(cfg(SINGLE), 0);
    set(&mut b, 0b0001);
    for t in (1..100_000).step_by(9_999) {
        b.cycle(t);
        assert_eq!(st(&b), (ONE, 0, 0));
    }
}

#[test]
fn pair_discrepancy_just_below_and_at_the_limit() {
    // H7: pair 1 with tDiscTime12 = 100.
    let c = Cfg {
        d12: 100,
        d34: 100,
        ..cfg(DUAL)
    };
    let mut b = started(c, 0);
    set(&mut b, 0b0001);
    b.cycle(1000);
    b.cycle(1099);
    assert_eq!(b.nState, SL_STATE_SAFE);
    set(&mut b, 0b0011);
    b.cycle(1099);
    assert_eq!(b.nState, ONE, "second channel followed in time");
    // Pair 2 differs for the full time while waiting: ERROR bit 1.
    set(&mut b, 0b1011);
    b.cycle(2000);
    b.cycle(2099);
    assert_eq!(b.nState, ONE);
    assert_eq!(b.cycle(2100), SL_OK);
    assert_error(&b, SL_DIAG_DISC2);
}

#[test]
fn pair_discrepancy_in_run_and_release() {
    let c = Cfg {
        d12: 30,
        ..cfg(DUAL)
    };
    let mut b = running(c, 0);
    // A channel of group 1 drops: the output goes off at once, the error follows.
    set(&mut b, 0b1110);
    b.cycle(10);
    assert_eq!(st(&b), (REL, 0, 0));
    b.cycle(39);
    assert_eq!(st(&b), (REL, 0, 0));
    b.cycle(40);
    assert_error(&b, SL_DIAG_DISC1);
}

#[test]
fn pair_discrepancy_with_safe_inputs_after_disc_error() {
    // H4: bits 8/9 in addition to 0/1; H13: both channels FALSE together before the ack.
    let c = Cfg {
        d12: 10,
        options: SL_OPT_SAFE_INPUTS_AFTER_DISC,
        ..cfg(DUAL)
    };
    let mut b = started(c, 0);
    set(&mut b, 0b0010);
    b.cycle(1);
    b.cycle(11);
    assert_error(&b, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
    // The pair agrees (both TRUE): not enough.
    set(&mut b, 0b0011);
    b.cycle(12);
    b.bErrAck = 1;
    b.cycle(13);
    assert_eq!(b.nState, SL_STATE_ERROR);
    b.bErrAck = 0;
    // Both FALSE in one call, then TRUE again: the latch holds, the ack works.
    set(&mut b, 0);
    b.cycle(14);
    set(&mut b, 0b0011);
    b.cycle(15);
    b.bErrAck = 1;
    b.cycle(16);
    assert_eq!(b.nState, SL_STATE_RESET);
    b.bErrAck = 0;
    b.cycle(17);
    assert_eq!(
        st(&b),
        (REL, 0, 0),
        "group 1 held through the acknowledgement"
    );

    // Pair 2 with the option: bits 1 and 9.
    let c = Cfg {
        d34: 10,
        options: SL_OPT_SAFE_INPUTS_AFTER_DISC,
        ..cfg(DUAL)
    };
    let mut b = started(c, 0);
    set(&mut b, 0b0100);
    b.cycle(1);
    b.cycle(11);
    assert_error(&b, SL_DIAG_DISC2 | SL_DIAG_SAFE_IN_DISC2);
}

#[test]
fn pair_discrepancy_ack_without_the_option() {
    // G4/H13: the channels must agree now.
    let c = Cfg {
        d12: 10,
        ..cfg(DUAL)
    };
    let mut b = started(c, 0);
    set(&mut b, 0b0001);
    b.cycle(1);
    b.cycle(11);
    assert_error(&b, SL_DIAG_DISC1);
    b.bErrAck = 1;
    b.cycle(12);
    assert_eq!(b.nState, SL_STATE_ERROR, "still differing");
    b.bErrAck = 0;
    set(&mut b, 0b0011);
    b.cycle(13);
    b.bErrAck = 1;
    b.cycle(14);
    assert_eq!((st(&b), b.nDiag), ((SL_STATE_RESET, 0, 0), 0));
    b.bErrAck = 0;
    set(&mut b, 0);
    b.cycle(15);
    assert_eq!(st(&b), (SL_STATE_SAFE, 0, 0));
    // Discrepancy monitoring restarts from scratch after RESET (G14).
    set(&mut b, 0b0001);
    b.cycle(16);
    b.cycle(25);
    assert_eq!(b.nState, SL_STATE_SAFE);
    b.cycle(26);
    assert_error(&b, SL_DIAG_DISC1);
}

#[test]
fn window_error_ack_with_and_without_the_option() {
    // Without the option nothing remains (H13): ack with group 1 still held, then RELEASE.
    let c = Cfg {
        pairs: 20,
        ..cfg(SINGLE)
    };
    let mut b = started(c, 0);
    set(&mut b, 0b0001);
    b.cycle(1);
    b.cycle(21);
    assert_error(&b, SL_DIAG_TWOHAND_PAIRS);
    b.bErrAck = 1;
    b.cycle(22);
    assert_eq!(b.nState, SL_STATE_RESET);
    b.bErrAck = 0;
    b.cycle(23);
    assert_eq!(st(&b), (REL, 0, 0));

    // With the option: bit 10 too, and every active input released once before the ack.
    let c = Cfg {
        pairs: 20,
        options: SL_OPT_SAFE_INPUTS_AFTER_DISC,
        ..cfg(SINGLE)
    };
    let mut b = started(c, 0);
    set(&mut b, 0b0001);
    b.cycle(1);
    b.cycle(21);
    assert_error(&b, SL_DIAG_TWOHAND_PAIRS | SL_DIAG_TWOHAND_SAFE_IN_PAIRS);
    b.bErrAck = 1;
    b.cycle(22);
    assert_eq!(b.nState, SL_STATE_ERROR, "group 1 never released");
    b.bErrAck = 0;
    set(&mut b, 0);
    b.cycle(23);
    set(&mut b, 0b0101);
    b.cycle(24);
    b.bErrAck = 1;
    b.cycle(25);
    assert_eq!(b.nState, SL_STATE_RESET, "released once since the error");
    b.bErrAck = 0;
    b.cycle(26);
    assert_eq!(st(&b), (REL, 0, 0), "both held: RELEASE, no output (H5)");
}

#[test]
fn invalid_input_bytes() {
    // ABI §2 / H6: an invalid active byte never actuates, never releases.
    let mut b = started(cfg(SINGLE), 0);
    b.bTwoHand1 = 2;
    assert_eq!(b.cycle(1), SL_E_INVALID_BOOL);
    assert_eq!(st(&b), (SL_STATE_SAFE, 0, 0));
    // Inactive input bytes are not read.
    b.bTwoHand1 = 0;
    b.bTwoHand2 = 0xFF;
    assert_eq!(b.cycle(2), SL_OK);
    // In RUN: the group is no longer actuated -> RELEASE, output off in the same call.
    let mut b = running(cfg(SINGLE), 0);
    b.bTwoHand3 = 9;
    assert_eq!(b.cycle(5), SL_E_INVALID_BOOL);
    assert_eq!(st(&b), (REL, 0, 0));
    // RELEASE: the other input FALSE, the invalid one is not a release.
    b.bTwoHand1 = 0;
    b.cycle(6);
    assert_eq!(st(&b), (REL, 0, 0));
    b.bTwoHand3 = 0;
    assert_eq!(b.cycle(7), SL_OK);
    assert_eq!(st(&b), (SL_STATE_SAFE, 0, 0));
    // A make contact with an invalid byte is not actuated either.
    let c = Cfg {
        negated: 0b0001,
        ..cfg(SINGLE)
    };
    let mut b = twohand(c);
    b.bTwoHand1 = 1;
    b.bRun = 1;
    b.cycle(0);
    assert_eq!(b.nState, SL_STATE_SAFE);
    b.bTwoHand1 = 5;
    b.bTwoHand3 = 1;
    b.cycle(1);
    assert_eq!(st(&b), (TWO, 0, 0));
    b.cycle(2);
    assert_eq!(st(&b), (TWO, 0, 0), "invalid make contact is not actuated");
    // Run and ErrAck bytes.
    b.bRun = 4;
    assert_eq!(b.cycle(3), SL_E_INVALID_BOOL);
    assert_eq!(st(&b), (SL_STATE_STOP, 0, 0));
}

#[test]
fn invalid_byte_keeps_a_pair_error() {
    // H13: a failed pair with an invalid byte cannot be shown to agree.
    let c = Cfg {
        d12: 10,
        ..cfg(DUAL)
    };
    let mut b = started(c, 0);
    set(&mut b, 0b0001);
    b.cycle(1);
    b.cycle(11);
    assert_error(&b, SL_DIAG_DISC1);
    set(&mut b, 0);
    b.bTwoHand2 = 3;
    b.bErrAck = 1;
    assert_eq!(b.cycle(12), SL_E_INVALID_BOOL);
    assert_eq!(b.nState, SL_STATE_ERROR);
    b.bErrAck = 0;
    b.bTwoHand2 = 0;
    b.cycle(13);
    b.bErrAck = 1;
    b.cycle(14);
    assert_eq!(b.nState, SL_STATE_RESET);
}

#[test]
fn parameter_change_while_running_is_an_error() {
    // C5.
    let mut b = running(cfg(SINGLE), 0);
    b.tDiscTimePairs = 100;
    assert_eq!(b.cycle(5), SL_E_PARAM_CHANGED);
    assert_error(&b, SL_DIAG_PARAM_CHANGED);
    // Also outside RUN, e.g. in 1BUTTON, and for the negation bits.
    let mut b = started(cfg(SINGLE), 0);
    set(&mut b, 0b0001);
    b.cycle(1);
    b.wInputNegated = 0b0100;
    assert_eq!(b.cycle(2), SL_E_PARAM_CHANGED);
    assert_eq!(b.nState, SL_STATE_ERROR);
    // In STOP a change is adopted at the next start.
    let mut b = running(cfg(SINGLE), 0);
    b.bRun = 0;
    b.cycle(5);
    b.wInputActive = DUAL;
    b.tDiscTime12 = 20;
    assert_eq!(b.cycle(6), SL_OK);
    b.bRun = 1;
    set(&mut b, 0);
    assert_eq!(b.cycle(7), SL_OK);
    set(&mut b, 0b0001);
    b.cycle(8);
    b.cycle(28);
    assert_error(&b, SL_DIAG_DISC1);
}

#[test]
fn clock_going_backwards_is_an_error() {
    // C4.
    let mut b = running(cfg(SINGLE), 500);
    assert_eq!(b.cycle(400), SL_E_CLOCK);
    assert_error(&b, SL_DIAG_CLOCK);
    b.bErrAck = 1;
    assert_eq!(b.cycle(401), SL_OK);
    assert_eq!(b.nState, SL_STATE_RESET);
    b.bErrAck = 0;
    b.cycle(402);
    assert_eq!(st(&b), (REL, 0, 0), "buttons still held after RESET (H5)");
}

#[test]
fn corrupted_private_state_is_detected() {
    let mut b = running(cfg(SINGLE), 0);
    b.stPrivate.stHeader.nState = ONE;
    assert_eq!(b.cycle(5), SL_E_CORRUPT);
    assert_error(&b, SL_DIAG_CORRUPT);
    // A sealed but impossible state value.
    let mut b = running(cfg(SINGLE), 0);
    let h = &mut b.stPrivate.stHeader;
    h.nState = SL_STATE_START;
    h.seal();
    assert_eq!(b.cycle(5), SL_E_CORRUPT);
    assert_error(&b, SL_DIAG_CORRUPT);
    // A changed latched time (CRC mismatch on the next parameter comparison).
    let mut b = started(cfg(SINGLE), 0);
    b.stPrivate.awTime[2] = 9;
    assert_eq!(b.cycle(1), SL_E_CORRUPT);
    assert_eq!(b.nState, SL_STATE_ERROR);
}

#[test]
fn a_never_initialised_instance_initialises_on_its_first_cycle() {
    let mut b = build(cfg(SINGLE));
    b.bRun = 1;
    assert_eq!(b.cycle(0), SL_OK);
    assert_eq!(st(&b), (SL_STATE_SAFE, 0, 0));
}

#[test]
fn c_functions() {
    let mut b = build(cfg(SINGLE));
    assert_eq!(unsafe { ffi::sl_twohand_init(&mut b) }, SL_OK);
    b.bRun = 1;
    assert_eq!(unsafe { ffi::sl_twohand_cycle(&mut b, 0) }, SL_OK);
    b.bTwoHand1 = 1;
    b.bTwoHand3 = 1;
    unsafe { ffi::sl_twohand_cycle(&mut b, 1) };
    unsafe { ffi::sl_twohand_cycle(&mut b, 2) };
    assert_eq!(st(&b), (SL_STATE_RUN, 0, 1));
    null_refused!(ffi::sl_twohand_init, ffi::sl_twohand_cycle);
    let info = safelogic::registry::info(SL_TYPE_TWOHAND).unwrap();
    assert_eq!(info.name, "TWOHAND");
    let states: Vec<(u8, &str)> = info.states.to_vec();
    assert_eq!(
        states,
        [
            (1, "RUN\0"),
            (2, "STOP\0"),
            (3, "SAFE\0"),
            (4, "ERROR\0"),
            (5, "RESET\0"),
            (11, "1BUTTON\0"),
            (12, "2BUTTON\0"),
            (13, "RELEASE\0")
        ]
    );
    for (v, n) in info.states {
        assert_eq!(ffi::sl_state_str(SL_TYPE_TWOHAND, *v), n.as_ptr().cast());
    }
    let text = |d: u16| common::diag_text(SL_TYPE_TWOHAND, d);
    // §4.7.2 diag table: bits 0, 1, 2, 6, 8, 9, 10 have texts; others are library or "bit n".
    assert_eq!(text(SL_DIAG_DISC1), "discrepancy error input pair 1");
    assert_eq!(text(SL_DIAG_DISC2), "discrepancy error input pair 2");
    assert_eq!(
        text(SL_DIAG_TWOHAND_PAIRS),
        "discrepancy error between the two input pairs"
    );
    assert!(text(SL_DIAG_TWOHAND_ERROR).starts_with("two-hand error"));
    assert!(text(SL_DIAG_SAFE_IN_DISC1).contains("Safe Inputs after Disc Error"));
    assert!(text(SL_DIAG_SAFE_IN_DISC2).contains("Safe Inputs after Disc Error"));
    assert!(text(SL_DIAG_TWOHAND_SAFE_IN_PAIRS).contains("Safe Inputs after Disc Error"));
    assert_eq!(text(1 << 3), "bit 3");
    assert_eq!(text(1 << 4), "bit 4");
    assert_eq!(
        (
            SL_DIAG_TWOHAND_PAIRS,
            SL_DIAG_TWOHAND_ERROR,
            SL_DIAG_TWOHAND_SAFE_IN_PAIRS
        ),
        (1 << 2, 1 << 6, 1 << 10)
    );
}

#[test]
fn twohand_error_stops_the_group_and_members_dispatch_by_tag() {
    let mut th = twohand(cfg(SINGLE));
    let mut o = common::ready(FB_OPMODE {
        wInputActive: 0b11,
        bOpIn1: 1,
        ..Default::default()
    });
    let mut g = common::new_group(2, 1);
    let mut links = [SL_LINK::default(); 1];
    // TwoHandOut -> OpIn2: a link into another block's input.
    let l = common::link(
        1,
        offset_of!(FB_TWOHAND, bTwoHandOut) as u16,
        0,
        offset_of!(FB_OPMODE, bOpIn2) as u16,
    );
    {
        let mut ms: [&mut dyn Member; 2] = [&mut o, &mut th];
        assert_eq!(group::add_link(&mut g, &mut ms[..], &mut links, l), SL_OK);
        g.bRun = 1;
        for t in 0..3 {
            group::cycle(&mut g, &mut ms[..], &links, t);
        }
    }
    assert_eq!((o.nState, o.bOpOut1), (SL_STATE_RUN, 1));
    // Two-hand error in the later member: the earlier member stops in the same group cycle.
    th.bTwoHand1 = 1;
    {
        let mut ms: [&mut dyn Member; 2] = [&mut o, &mut th];
        group::cycle(&mut g, &mut ms[..], &links, 3);
    }
    th.bTwoHand1 = 0;
    th.bTwoHand3 = 1;
    {
        let mut ms: [&mut dyn Member; 2] = [&mut o, &mut th];
        group::cycle(&mut g, &mut ms[..], &links, 4);
    }
    assert_eq!(
        (th.nState, th.nDiag),
        (SL_STATE_ERROR, SL_DIAG_TWOHAND_ERROR)
    );
    assert_eq!((g.nState, g.nFailedMember), (SL_STATE_ERROR, 1));
    assert_eq!((o.nState, o.bOpOut1), (SL_STATE_STOP, 0));

    let mut members = [SL_MEMBER::default(); 1];
    let mut g2 = SL_GROUP::default();
    common::c_group_init(
        &mut g2,
        (members.as_mut_ptr(), 1),
        (std::ptr::null_mut(), 0),
    );
    let mut th2 = twohand(cfg(SINGLE));
    assert_eq!(
        unsafe {
            ffi::sl_group_add_member(
                &mut g2,
                members.as_mut_ptr(),
                SL_TYPE_TWOHAND,
                (&mut th2 as *mut FB_TWOHAND).cast(),
                std::ptr::null_mut(),
            )
        },
        SL_OK
    );
}

/// Logical value of input i from its raw byte (None: invalid).
fn logical(raw: u8, negated: bool) -> Option<bool> {
    (raw <= 1).then_some((raw == 1) ^ negated)
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_SAFE, SL_STATE_STOP];
    /// §4.7.2 outputs per state; TwoHandOut TRUE only while both groups are actuated (in
    /// the same call); after each output period the output comes back only after a call
    /// in which every active input was released (§4.7.1 re-trigger rule, H5, H6).
    fn output_only_with_both_groups_and_after_a_full_release(
        active in (0u16..16).prop_filter("both groups", |a| a & 0b11 != 0 && a & 0b1100 != 0),
        negated in 0u16..16,
        d12 in prop_oneof![Just(0u32), 1u32..60],
        d34 in prop_oneof![Just(0u32), 1u32..60],
        pairs in prop_oneof![Just(0u32), 1u32..200],
        safe_in in any::<bool>(),
        steps in proptest::collection::vec(
            (
                prop_oneof![8 => Just(1u8), 1 => Just(0u8), 1 => Just(2u8)],
                0u8..2,
                [
                    prop_oneof![6 => 0u8..2, 1 => 2u8..=255],
                    prop_oneof![6 => 0u8..2, 1 => 2u8..=255],
                    prop_oneof![6 => 0u8..2, 1 => 2u8..=255],
                    prop_oneof![6 => 0u8..2, 1 => 2u8..=255],
                ],
                0u32..30,
            ),
            1..200,
        ),
    ) {
        let c = Cfg {
            active,
            negated,
            d12: if active & 0b11 == 0b11 { d12 } else { 0 },
            d34: if active & 0b1100 == 0b1100 { d34 } else { 0 },
            pairs,
            options: if safe_in { SL_OPT_SAFE_INPUTS_AFTER_DISC } else { 0 },
        };
        let mut b = twohand(c);
        let mut t = 0u32;
        let mut prev_out = 0u8;
        let mut released_since_out = false;
        for (run, ack, bytes, dt) in steps {
            b.bRun = run;
            b.bErrAck = ack;
            b.bTwoHand1 = bytes[0];
            b.bTwoHand2 = bytes[1];
            b.bTwoHand3 = bytes[2];
            b.bTwoHand4 = bytes[3];
            t = t.wrapping_add(dt);
            let rc = b.cycle(t);
            common::saw(b.nState);
            prop_assert!(matches!(rc, SL_OK | SL_E_INVALID_BOOL), "rc {}", rc);
            prop_assert!(
                [1, 2, 3, 4, 5, ONE, TWO, REL].contains(&b.nState),
                "state {}", b.nState
            );
            prop_assert!(b.bTwoHandOut <= 1 && b.bError <= 1);
            prop_assert_eq!(b.bError, u8::from(b.nState == SL_STATE_ERROR));
            prop_assert_eq!(b.bTwoHandOut, u8::from(b.nState == SL_STATE_RUN));
            if b.nState != SL_STATE_ERROR {
                prop_assert_eq!(b.nDiag, 0);
            }
            // Both groups actuated, from the raw bytes and the parameters.
            let lv: Vec<Option<bool>> = (0..4)
                .map(|i| logical(bytes[i], negated & (1 << i) != 0))
                .collect();
            let is_active = |i: usize| active & (1 << i) != 0;
            let group_on = |g: [usize; 2]| g.iter().all(|&i| !is_active(i) || lv[i] == Some(true));
            let all_released = (0..4).all(|i| !is_active(i) || lv[i] == Some(false));
            if b.bTwoHandOut == 1 {
                prop_assert!(group_on([0, 1]) && group_on([2, 3]), "output without both groups");
                prop_assert_eq!(run, 1);
                if prev_out == 0 {
                    prop_assert!(released_since_out, "output again without a full release");
                    released_since_out = false;
                }
            }
            if run == 1 && all_released && b.bTwoHandOut == 0 {
                released_since_out = true;
            }
            prev_out = b.bTwoHandOut;
        }
    }
}
