//! TwinSAFE group (manual §3.1, §3.1.1.2, §3.2.5; docs/semantics.md rows GR*): group states
//! and outputs, error propagation in both execution orders, acknowledgement, links, storage.

mod common;
use common::{link, new_group};

use proptest::prelude::*;
use safelogic::group::{self, Member, SL_GROUP_STATE_START, SL_GROUP_STATE_STOPERROR};
use safelogic::group::{
    SL_GROUP_DIAG_COMERROR, SL_GROUP_DIAG_FBERROR, SL_GROUP_DIAG_MODULEERROR,
    SL_GROUP_DIAG_RESTARTERROR,
};
use safelogic::*;
use std::mem::offset_of;

fn estop_pair() -> FB_ESTOP {
    common::ready(FB_ESTOP {
        wInputActive: 0b11,
        tDiscTime12: 50,
        bEStopIn1: 1,
        bEStopIn2: 1,
        ..Default::default()
    })
}

fn mon_auto() -> FB_MON {
    common::ready(FB_MON {
        wInputActive: 0b11,
        tDiscTime12: 50,
        bMonIn1: 1,
        bMonIn2: 1,
        ..Default::default()
    })
}

fn and2() -> FB_AND {
    common::ready(FB_AND {
        wInputActive: 0b11,
        ..Default::default()
    })
}

const AND_IN1: u16 = offset_of!(FB_AND, bAndIn1) as u16;
const AND_IN2: u16 = offset_of!(FB_AND, bAndIn2) as u16;
const AND_OUT: u16 = offset_of!(FB_AND, bAndOut) as u16;
const ESTOP_OUT: u16 = offset_of!(FB_ESTOP, bEStopOut) as u16;
const MON_OUT: u16 = offset_of!(FB_MON, bMonOut) as u16;

#[test]
fn stop_run_and_outputs() {
    let (mut e, mut m) = (estop_pair(), mon_auto());
    let mut g = new_group(2, 0);
    let mut ms: [&mut dyn Member; 2] = [&mut e, &mut m];
    assert_eq!(group::cycle(&mut g, &mut ms[..], &[], 0), SL_OK);
    assert_eq!(g.nState, SL_STATE_STOP);
    assert_eq!((g.bInRun, g.bFbRun, g.bFbErr), (0, 0, 0));
    assert_eq!(ms[0].state(), SL_STATE_STOP);
    g.bRun = 1;
    group::cycle(&mut g, &mut ms[..], &[], 1);
    assert_eq!(g.nState, SL_STATE_RUN);
    assert_eq!(g.bInRun, 1);
    // ESTOP waits for its restart: FbRun says "all FBs in RUN" and they are not.
    assert_eq!(g.bFbRun, 0);
    group::cycle(&mut g, &mut ms[..], &[], 2);
    assert_eq!(
        ms[1].state(),
        SL_STATE_RUN,
        "MON with automatic restart runs"
    );
    // Run FALSE stops every member.
    g.bRun = 0;
    group::cycle(&mut g, &mut ms[..], &[], 3);
    assert_eq!(g.nState, SL_STATE_STOP);
    assert_eq!(
        (ms[0].state(), ms[1].state()),
        (SL_STATE_STOP, SL_STATE_STOP)
    );
    assert_eq!(ms[1].output(MON_OUT), Some(0));
}

/// A discrepancy error in one member stops the whole group in the same cycle, whichever
/// member fails, including members that ran earlier in that cycle.
fn propagate(failing_first: bool) {
    let (mut e, mut m) = (estop_pair(), mon_auto());
    let mut g = new_group(2, 0);
    g.bRun = 1;
    {
        let mut ms: [&mut dyn Member; 2] = if failing_first {
            [&mut m, &mut e]
        } else {
            [&mut e, &mut m]
        };
        for t in 0..3 {
            group::cycle(&mut g, &mut ms[..], &[], t);
        }
    }
    // Bring ESTOP to RUN with its restart sequence.
    e.bRestart = 1;
    {
        let mut ms: [&mut dyn Member; 2] = if failing_first {
            [&mut m, &mut e]
        } else {
            [&mut e, &mut m]
        };
        group::cycle(&mut g, &mut ms[..], &[], 3);
    }
    e.bRestart = 0;
    {
        let mut ms: [&mut dyn Member; 2] = if failing_first {
            [&mut m, &mut e]
        } else {
            [&mut e, &mut m]
        };
        group::cycle(&mut g, &mut ms[..], &[], 4);
    }
    assert_eq!((e.nState, m.nState), (SL_STATE_RUN, SL_STATE_RUN));
    assert_eq!(g.bFbRun, 1);
    // MON pair discrepancy: error after 50 ms.
    m.bMonIn2 = 0;
    let mut t = 5;
    loop {
        let mut ms: [&mut dyn Member; 2] = if failing_first {
            [&mut m, &mut e]
        } else {
            [&mut e, &mut m]
        };
        group::cycle(&mut g, &mut ms[..], &[], t);
        if g.nState == SL_STATE_ERROR {
            break;
        }
        assert_eq!(
            ms[if failing_first { 1 } else { 0 }].output(ESTOP_OUT),
            Some(1)
        );
        t += 1;
        assert!(t < 100);
    }
    assert_eq!(
        t, 55,
        "error exactly when the 50 ms discrepancy time is reached"
    );
    assert_eq!(m.nState, SL_STATE_ERROR);
    assert_eq!(
        e.nState, SL_STATE_STOP,
        "the other member is stopped in the same group cycle"
    );
    assert_eq!((e.bEStopOut, e.bEStopDelOut), (0, 0));
    assert_eq!((g.bFbErr, g.bInRun, g.bFbRun), (1, 0, 0));
    assert_eq!(g.nDiag, SL_GROUP_DIAG_FBERROR);
    assert_eq!(g.nFailedMember, if failing_first { 0 } else { 1 });
}

#[test]
fn error_propagates_from_a_later_member() {
    propagate(false);
}

#[test]
fn error_propagates_from_an_earlier_member() {
    propagate(true);
}

#[test]
fn acknowledgement_waits_for_the_error_condition_and_needs_an_edge() {
    let mut m = mon_auto();
    let mut g = new_group(1, 0);
    g.bRun = 1;
    let mut ms: [&mut dyn Member; 1] = [&mut m];
    for t in 0..3 {
        group::cycle(&mut g, &mut ms[..], &[], t);
    }
    m.bMonIn2 = 0;
    let mut ms: [&mut dyn Member; 1] = [&mut m];
    for t in 3..60 {
        group::cycle(&mut g, &mut ms[..], &[], t);
    }
    assert_eq!(g.nState, SL_STATE_ERROR);
    // ErrAck while the pair still differs: nothing.
    g.bErrAck = 1;
    group::cycle(&mut g, &mut ms[..], &[], 60);
    assert_eq!(g.nState, SL_STATE_ERROR);
    g.bErrAck = 0;
    group::cycle(&mut g, &mut ms[..], &[], 61);
    m.bMonIn2 = 1;
    let mut ms: [&mut dyn Member; 1] = [&mut m];
    // ErrAck held TRUE from before does not count: a new rising edge is needed.
    group::cycle(&mut g, &mut ms[..], &[], 62);
    assert_eq!(g.nState, SL_STATE_ERROR);
    g.bErrAck = 1;
    group::cycle(&mut g, &mut ms[..], &[], 63);
    assert_eq!(
        g.nState, SL_STATE_RESET,
        "member and group acknowledged by the same edge"
    );
    assert_eq!(ms[0].state(), SL_STATE_RESET);
    assert_eq!((g.bFbErr, g.nDiag), (0, 0));
    g.bErrAck = 0;
    group::cycle(&mut g, &mut ms[..], &[], 64);
    assert_eq!(g.nState, SL_STATE_RUN);
    group::cycle(&mut g, &mut ms[..], &[], 65);
    assert_eq!(
        ms[0].state(),
        SL_STATE_RUN,
        "MON restarts automatically, as its own rules say"
    );
}

#[test]
fn module_fault_and_com_error() {
    let mut a = and2();
    let mut g = new_group(1, 0);
    g.bRun = 1;
    let mut ms: [&mut dyn Member; 1] = [&mut a];
    group::cycle(&mut g, &mut ms[..], &[], 0);
    g.bModuleFault = 1;
    group::cycle(&mut g, &mut ms[..], &[], 1);
    assert_eq!(
        (g.nState, g.nDiag, g.bOtherErr),
        (SL_STATE_ERROR, SL_GROUP_DIAG_MODULEERROR, 1)
    );
    g.bComErrIn = 1;
    group::cycle(&mut g, &mut ms[..], &[], 2);
    assert_eq!(
        g.nDiag, SL_GROUP_DIAG_MODULEERROR,
        "the first cause stays the diag value"
    );
    assert_eq!(g.bComErr, 1);
    g.bModuleFault = 0;
    g.bComErrIn = 0;
    g.bErrAck = 1;
    group::cycle(&mut g, &mut ms[..], &[], 3);
    assert_eq!((g.nState, g.bOtherErr, g.bComErr), (SL_STATE_RESET, 0, 0));
    g.bErrAck = 0;
    g.bComErrIn = 1;
    group::cycle(&mut g, &mut ms[..], &[], 4);
    assert_eq!(
        (g.nState, g.nDiag),
        (SL_STATE_ERROR, SL_GROUP_DIAG_COMERROR)
    );
}

#[test]
fn startup_and_stoperror_with_connections() {
    let mut g = SL_GROUP {
        bConnections: 1,
        ..Default::default()
    };
    assert_eq!(group::init(&mut g, 0, 0), SL_OK);
    assert_eq!(g.nState, SL_GROUP_STATE_STOPERROR);
    let mut ms: [&mut dyn Member; 0] = [];
    g.bRun = 1;
    group::cycle(&mut g, &mut ms[..], &[], 0);
    assert_eq!(
        (g.nState, g.nDiag),
        (SL_STATE_ERROR, SL_GROUP_DIAG_RESTARTERROR)
    );
    g.bErrAck = 1;
    g.bComStartupIn = 1;
    group::cycle(&mut g, &mut ms[..], &[], 1);
    assert_eq!(g.nState, SL_STATE_RESET);
    g.bErrAck = 0;
    group::cycle(&mut g, &mut ms[..], &[], 2);
    assert_eq!(
        (g.nState, g.bComStartup, g.bInRun),
        (SL_GROUP_STATE_START, 1, 0)
    );
    g.bComStartupIn = 0;
    group::cycle(&mut g, &mut ms[..], &[], 3);
    assert_eq!(g.nState, SL_STATE_RUN);
}

/// ESTOP and MON feed an AND. A link from an earlier member carries this cycle's value; a
/// link from a later member carries the previous cycle's value.
#[test]
fn link_order_decides_which_cycle_a_value_is_from() {
    for and_first in [false, true] {
        let (mut e, mut m, mut a) = (estop_pair(), mon_auto(), and2());
        e.tDiscTime12 = 0;
        e.wInputActive = 0b1;
        assert_eq!(e.init(), SL_OK);
        let mut g = new_group(3, 4);
        let mut links = [SL_LINK::default(); 4];
        let (ie, im, ia) = if and_first { (1, 2, 0) } else { (0, 1, 2) };
        {
            let mut ms: [&mut dyn Member; 3] = if and_first {
                [&mut a, &mut e, &mut m]
            } else {
                [&mut e, &mut m, &mut a]
            };
            assert_eq!(
                group::add_link(
                    &mut g,
                    &mut ms[..],
                    &mut links,
                    link(ie, ESTOP_OUT, ia, AND_IN1)
                ),
                SL_OK
            );
            assert_eq!(
                group::add_link(
                    &mut g,
                    &mut ms[..],
                    &mut links,
                    link(im, MON_OUT, ia, AND_IN2)
                ),
                SL_OK
            );
            g.bRun = 1;
            for t in 0..3 {
                group::cycle(&mut g, &mut ms[..], &links[..2], t);
            }
        }
        e.bRestart = 1;
        {
            let mut ms: [&mut dyn Member; 3] = if and_first {
                [&mut a, &mut e, &mut m]
            } else {
                [&mut e, &mut m, &mut a]
            };
            group::cycle(&mut g, &mut ms[..], &links[..2], 3);
        }
        e.bRestart = 0;
        {
            let mut ms: [&mut dyn Member; 3] = if and_first {
                [&mut a, &mut e, &mut m]
            } else {
                [&mut e, &mut m, &mut a]
            };
            group::cycle(&mut g, &mut ms[..], &links[..2], 4);
            assert_eq!(ms[ie as usize].output(ESTOP_OUT), Some(1));
            let expected_now = if and_first { 0 } else { 1 };
            assert_eq!(ms[ia as usize].output(AND_OUT), Some(expected_now));
            group::cycle(&mut g, &mut ms[..], &links[..2], 5);
            assert_eq!(ms[ia as usize].output(AND_OUT), Some(1));
        }
    }
}

#[test]
fn invalid_links_and_full_storage_are_rejected() {
    let (mut e, mut a) = (estop_pair(), and2());
    let mut g = new_group(2, 2);
    let mut links = [SL_LINK::default(); 2];
    let mut ms: [&mut dyn Member; 2] = [&mut e, &mut a];
    // An input as source, an output as destination, bRun as destination, a member outside.
    let bad = [
        link(0, offset_of!(FB_ESTOP, bEStopIn1) as u16, 1, AND_IN1),
        link(0, ESTOP_OUT, 1, AND_OUT),
        link(0, ESTOP_OUT, 1, offset_of!(FB_AND, bRun) as u16),
        link(0, ESTOP_OUT, 2, AND_IN1),
        link(0, ESTOP_OUT + 100, 1, AND_IN1),
    ];
    for l in bad {
        assert_eq!(
            group::add_link(&mut g, &mut ms[..], &mut links, l),
            SL_E_CONFIG,
            "{l:?}"
        );
    }
    assert_eq!(
        group::add_link(
            &mut g,
            &mut ms[..],
            &mut links,
            link(0, ESTOP_OUT, 1, AND_IN1)
        ),
        SL_OK
    );
    assert_eq!(
        group::add_link(
            &mut g,
            &mut ms[..],
            &mut links,
            link(0, ESTOP_OUT, 1, AND_IN1)
        ),
        SL_E_CONFIG,
        "an input is linked once"
    );
    assert_eq!(
        group::add_link(
            &mut g,
            &mut ms[..],
            &mut links,
            link(0, ESTOP_OUT, 1, AND_IN2)
        ),
        SL_OK
    );
    assert_eq!(
        group::add_link(&mut g, &mut ms[..], &mut links, link(0, ESTOP_OUT, 0, 8)),
        SL_E_FULL
    );
    assert_eq!(group::reserve_member(&mut g), Err(SL_E_FULL));
    assert_eq!(g.nLinks, 2);
}

#[test]
fn corrupt_group_private_state_is_reported() {
    let mut g = new_group(0, 0);
    g.stPrivate.dwMembers ^= 0x10;
    let mut ms: [&mut dyn Member; 0] = [];
    assert_eq!(group::cycle(&mut g, &mut ms[..], &[], 0), SL_E_CORRUPT);
    assert_eq!((g.nState, g.bInRun), (SL_STATE_ERROR, 0));
}

#[test]
fn invalid_group_input_bytes() {
    let mut a = and2();
    let mut g = new_group(1, 0);
    let mut ms: [&mut dyn Member; 1] = [&mut a];
    g.bRun = 7;
    assert_eq!(group::cycle(&mut g, &mut ms[..], &[], 0), SL_E_INVALID_BOOL);
    assert_eq!(g.nState, SL_STATE_STOP, "an invalid Run reads FALSE");
    g.bRun = 1;
    g.bModuleFault = 9;
    assert_eq!(group::cycle(&mut g, &mut ms[..], &[], 1), SL_E_INVALID_BOOL);
    assert_eq!(
        g.nState, SL_STATE_ERROR,
        "an invalid ModuleFault reads as a fault"
    );
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_STOP, SL_STATE_ERROR, SL_STATE_RESET];
    /// No member output is TRUE at the end of a group cycle in which the group is not in RUN.
    fn no_member_output_while_group_not_running(
        steps in proptest::collection::vec((0u8..3, 0u8..3, 0u8..3, any::<u8>(), 0u32..40), 1..120)
    ) {
        let (mut e, mut m, mut a) = (estop_pair(), mon_auto(), and2());
        let mut g = new_group(3, 2);
        let mut links = [SL_LINK::default(); 2];
        {
            let mut ms: [&mut dyn Member; 3] = [&mut e, &mut m, &mut a];
            prop_assert_eq!(group::add_link(&mut g, &mut ms[..], &mut links, link(0, ESTOP_OUT, 2, AND_IN1)), SL_OK);
            prop_assert_eq!(group::add_link(&mut g, &mut ms[..], &mut links, link(1, MON_OUT, 2, AND_IN2)), SL_OK);
        }
        let mut t = 0u32;
        for (run, ack, fault, ins, dt) in steps {
            g.bRun = u8::from(run != 0);
            g.bErrAck = u8::from(ack == 1);
            g.bModuleFault = u8::from(fault == 2);
            e.bEStopIn1 = ins & 1;
            e.bEStopIn2 = (ins >> 1) & 1;
            e.bRestart = (ins >> 2) & 1;
            m.bMonIn1 = (ins >> 3) & 1;
            m.bMonIn2 = (ins >> 4) & 1;
            t = t.wrapping_add(dt);
            let mut ms: [&mut dyn Member; 3] = [&mut e, &mut m, &mut a];
            group::cycle(&mut g, &mut ms[..], &links, t);
            common::saw(g.nState);
            if g.nState != SL_STATE_RUN {
                prop_assert_eq!(ms[0].output(ESTOP_OUT), Some(0));
                prop_assert_eq!(ms[0].output(offset_of!(FB_ESTOP, bEStopDelOut) as u16), Some(0));
                prop_assert_eq!(ms[1].output(MON_OUT), Some(0));
                prop_assert_eq!(ms[1].output(offset_of!(FB_MON, bMonDelOut) as u16), Some(0));
                prop_assert_eq!(ms[2].output(AND_OUT), Some(0));
                prop_assert_eq!(g.bInRun, 0);
            }
            let member_error = ms.iter().any(|x| x.state() == SL_STATE_ERROR);
            // FbErr: a member is in ERROR, or the group's error had a member cause.
            if member_error {
                prop_assert_eq!(g.bFbErr, 1);
                prop_assert_eq!(g.nState, SL_STATE_ERROR);
            }
            if g.bFbErr == 1 {
                prop_assert!(member_error || g.nState == SL_STATE_ERROR);
            }
        }
    }
}

#[test]
fn start_state_value() {
    assert_eq!(SL_GROUP_STATE_START, 6);
    assert_eq!(SL_GROUP_STATE_STOPERROR, 7);
}

#[test]
fn diag_text_names_the_bits() {
    let mut buf = [0i8; 128];
    let rc = unsafe {
        safelogic::ffi::sl_diag_text(
            SL_TYPE_ESTOP,
            SL_DIAG_DISC1 | SL_DIAG_EDM1 | SL_DIAG_CLOCK,
            buf.as_mut_ptr().cast(),
            buf.len(),
        )
    };
    assert_eq!(rc, SL_OK);
    let text = c_text(&buf);
    assert_eq!(
        text,
        "discrepancy error input group 1; EDM monitoring error EDM1; clock went backwards"
    );
    let mut small = [0x55i8; 8];
    assert_eq!(
        unsafe {
            safelogic::ffi::sl_diag_text(
                SL_TYPE_ESTOP,
                SL_DIAG_DISC1,
                small.as_mut_ptr().cast(),
                small.len(),
            )
        },
        SL_OK
    );
    assert_eq!(
        c_text(&small),
        "discrep",
        "truncated to the buffer, NUL included"
    );
    assert_eq!(
        unsafe { safelogic::ffi::sl_diag_text(999, 1, buf.as_mut_ptr().cast(), buf.len()) },
        SL_E_CONFIG
    );
    assert_eq!(
        unsafe { safelogic::ffi::sl_diag_text(SL_TYPE_AND, 0, std::ptr::null_mut(), 10) },
        SL_E_NULL
    );
    assert_eq!(
        unsafe {
            safelogic::ffi::sl_diag_text(SL_TYPE_AND, 1 << 6, buf.as_mut_ptr().cast(), buf.len())
        },
        SL_OK
    );
    assert_eq!(c_text(&buf), "bit 6");
    fn c_text(b: &[i8]) -> String {
        let bytes: Vec<u8> = b.iter().map(|&c| c as u8).take_while(|&c| c != 0).collect();
        String::from_utf8(bytes).unwrap()
    }
}

/// C3: a corrupted latched parameter copy is found when an output of a combinational block
/// is about to switch on.
#[test]
fn logic_block_verifies_its_parameters_before_switching_on() {
    let mut a = and2();
    a.bRun = 1;
    assert_eq!(a.cycle(0), SL_OK);
    assert_eq!(a.nState, SL_STATE_SAFE);
    // Flip the latched negation mask and its CRC stays stale; the live field is flipped too,
    // so the live/latched comparison alone cannot see it.
    a.stPrivate.stHeader.nNegated ^= 0b01;
    a.wInputNegated ^= 0b01;
    a.bAndIn1 = 0;
    a.bAndIn2 = 1;
    assert_eq!(a.cycle(1), SL_E_CORRUPT);
    assert_eq!((a.nState, a.bAndOut), (SL_STATE_ERROR, 0));
    assert_eq!(a.nDiag & SL_DIAG_CORRUPT, SL_DIAG_CORRUPT);
}

/// GR6: OtherErr and ComErr show the fault input now *or* a module / communication cause of
/// the current group error: they stay TRUE after the input clears, until the error is
/// acknowledged.
#[test]
fn other_err_and_com_err_stay_set_until_the_error_is_acknowledged() {
    for com in [false, true] {
        let mut a = and2();
        let mut g = new_group(1, 0);
        g.bRun = 1;
        let mut ms: [&mut dyn Member; 1] = [&mut a];
        group::cycle(&mut g, &mut ms[..], &[], 0);
        assert_eq!(g.nState, SL_STATE_RUN);
        let set = |g: &mut SL_GROUP, v: u8| {
            if com {
                g.bComErrIn = v;
            } else {
                g.bModuleFault = v;
            }
        };
        let shown = |g: &SL_GROUP| if com { g.bComErr } else { g.bOtherErr };
        set(&mut g, 1);
        group::cycle(&mut g, &mut ms[..], &[], 1);
        assert_eq!((g.nState, shown(&g)), (SL_STATE_ERROR, 1));
        set(&mut g, 0);
        for t in 2..5 {
            assert_eq!(group::cycle(&mut g, &mut ms[..], &[], t), SL_OK);
            assert_eq!(
                (g.nState, shown(&g)),
                (SL_STATE_ERROR, 1),
                "cause of the current error, com={com}"
            );
            assert_eq!(
                (g.bComErr, g.bOtherErr, g.bFbErr),
                (u8::from(com), u8::from(!com), 0),
                "only the error's own cause shows"
            );
        }
        g.bErrAck = 1;
        group::cycle(&mut g, &mut ms[..], &[], 5);
        assert_eq!((g.nState, shown(&g)), (SL_STATE_RESET, 0));
        // In STOP a fault input only shows while it is there (GR7): nothing is latched.
        g.bErrAck = 0;
        g.bRun = 0;
        group::cycle(&mut g, &mut ms[..], &[], 6);
        assert_eq!(g.nState, SL_STATE_STOP);
        set(&mut g, 1);
        group::cycle(&mut g, &mut ms[..], &[], 7);
        assert_eq!((g.nState, shown(&g)), (SL_STATE_STOP, 1));
        set(&mut g, 0);
        group::cycle(&mut g, &mut ms[..], &[], 8);
        assert_eq!((g.nState, shown(&g)), (SL_STATE_STOP, 0));
    }
}

/// GR6: FbErr is a member in ERROR now *or* a member cause of the current group error: the
/// member acknowledged while the group's error is held by a module fault leaves FbErr TRUE.
/// GR5: `nFailedMember` names the failed member until the acknowledgement, 0xFFFF before
/// and after.
#[test]
fn fb_err_and_failed_member_stay_until_the_group_error_is_acknowledged() {
    let (mut a, mut m) = (and2(), mon_auto());
    let mut g = new_group(2, 0);
    assert_eq!(g.nFailedMember, group::SL_NO_MEMBER, "right after init");
    g.bRun = 1;
    let mut ms: [&mut dyn Member; 2] = [&mut a, &mut m];
    for t in 0..3 {
        group::cycle(&mut g, &mut ms[..], &[], t);
        assert_eq!(g.nFailedMember, group::SL_NO_MEMBER, "no error yet, t={t}");
    }
    assert_eq!(g.nState, SL_STATE_RUN);
    m.bMonIn2 = 0;
    let mut ms: [&mut dyn Member; 2] = [&mut a, &mut m];
    let mut t = 3;
    while g.nState != SL_STATE_ERROR {
        group::cycle(&mut g, &mut ms[..], &[], t);
        t += 1;
        assert!(t < 100);
    }
    assert_eq!(
        (g.bFbErr, g.nFailedMember, g.nDiag),
        (1, 1, SL_GROUP_DIAG_FBERROR)
    );
    // The pair agrees again; a module fault now holds the group's error.
    m.bMonIn2 = 1;
    let mut ms: [&mut dyn Member; 2] = [&mut a, &mut m];
    g.bModuleFault = 1;
    for _ in 0..2 {
        group::cycle(&mut g, &mut ms[..], &[], t);
        t += 1;
        assert_eq!(
            (g.nState, g.bFbErr, g.nFailedMember),
            (SL_STATE_ERROR, 1, 1),
            "one cycle later and more"
        );
    }
    g.bErrAck = 1;
    group::cycle(&mut g, &mut ms[..], &[], t);
    assert_eq!(ms[1].state(), SL_STATE_RESET, "the member took the edge");
    assert_eq!(g.nState, SL_STATE_ERROR, "the module fault holds the group");
    assert_eq!(
        (g.bFbErr, g.nFailedMember, g.nDiag),
        (1, 1, SL_GROUP_DIAG_FBERROR),
        "a member cause of the current error"
    );
    g.bErrAck = 0;
    group::cycle(&mut g, &mut ms[..], &[], t + 1);
    assert_eq!(ms[1].state(), SL_STATE_STOP);
    assert_eq!(
        (g.nState, g.bFbErr, g.nFailedMember),
        (SL_STATE_ERROR, 1, 1)
    );
    g.bModuleFault = 0;
    g.bErrAck = 1;
    group::cycle(&mut g, &mut ms[..], &[], t + 2);
    assert_eq!(
        (g.nState, g.bFbErr, g.nFailedMember, g.nDiag),
        (SL_STATE_RESET, 0, group::SL_NO_MEMBER, 0)
    );
}

/// GR14 / ABI §3.6: every word of the group's private state is under its complement, and the
/// magic is checked besides: a flipped bit whose complement was not updated (counts still in
/// range) and a wrong magic with matching complements are both SL_E_CORRUPT, ERROR, outputs
/// FALSE.
#[test]
fn every_private_word_of_the_group_is_checked() {
    type Forge = fn(&mut SL_GROUP_PRIVATE);
    let forge: [(&str, Forge); 4] = [
        ("diag word", |p| p.dwDiag ^= 1),
        ("state bits", |p| p.dwCtrl ^= 1 << 17),
        ("member count below the capacity", |p| p.dwMembers ^= 1),
        ("magic with matching complement", |p| {
            p.dwCtrl ^= 1;
            p.adwCheck[0] = !p.dwCtrl;
        }),
    ];
    for (what, f) in forge {
        let mut a = and2();
        let mut g = new_group(1, 0);
        g.bRun = 1;
        let mut ms: [&mut dyn Member; 1] = [&mut a];
        assert_eq!(group::cycle(&mut g, &mut ms[..], &[], 0), SL_OK);
        assert_eq!(g.nState, SL_STATE_RUN, "{what}");
        f(&mut g.stPrivate);
        assert_eq!(
            group::cycle(&mut g, &mut ms[..], &[], 1),
            SL_E_CORRUPT,
            "{what}"
        );
        assert_eq!(
            (g.nState, g.bInRun, g.bFbRun),
            (SL_STATE_ERROR, 0, 0),
            "{what}"
        );
    }
}

#[test]
fn only_the_groups_own_link_count_is_applied() {
    // A link table longer than the group's link count: the entries after the count (never
    // added, never checked) are not applied, whatever they hold.
    let (mut e, mut a) = (estop_pair(), and2());
    a.bAndIn2 = 1;
    let mut g = new_group(2, 2);
    let mut links = [SL_LINK::default(); 2];
    let mut ms: [&mut dyn Member; 2] = [&mut e, &mut a];
    assert_eq!(
        group::add_link(
            &mut g,
            &mut ms[..],
            &mut links,
            link(0, ESTOP_OUT, 1, AND_IN1)
        ),
        SL_OK
    );
    assert_eq!(g.nLinks, 1);
    links[1] = link(0, ESTOP_OUT, 1, AND_IN2);
    g.bRun = 1;
    for t in 0..3 {
        assert_eq!(group::cycle(&mut g, &mut ms[..], &links, t), SL_OK);
        assert_eq!(ms[0].output(ESTOP_OUT), Some(0));
    }
    assert_eq!(a.bAndIn2, 1, "the link after the count was applied");
}

/// A Rust caller's tables get no sealed schedule (the member slice has no entry checks to
/// seal): every cycle checks every link, so a link changed after many cycles is found in
/// the next one (a mutation-testing finding: with a schedule for the slice, the changed link
/// would have been copied unchecked).
#[test]
fn a_link_changed_after_many_cycles_is_found() {
    let (mut e, mut a) = (estop_pair(), and2());
    let mut g = new_group(2, 2);
    let mut links = [SL_LINK::default(); 2];
    let mut ms: [&mut dyn Member; 2] = [&mut e, &mut a];
    assert_eq!(
        group::add_link(
            &mut g,
            &mut ms[..],
            &mut links,
            link(0, ESTOP_OUT, 1, AND_IN1)
        ),
        SL_OK
    );
    g.bRun = 1;
    for t in 0..5 {
        assert_eq!(group::cycle(&mut g, &mut ms[..], &links, t), SL_OK);
    }
    assert_eq!(g.nState, SL_STATE_RUN);
    links[0].nDstOffset = AND_IN2;
    assert_eq!(group::cycle(&mut g, &mut ms[..], &links, 5), SL_E_CORRUPT);
    assert_eq!(g.nState, SL_STATE_ERROR);
    assert_eq!((g.bInRun, g.bFbRun), (0, 0));
}

/// A block has no SafeData: an RXBIT link from it or a TXBIT link into it is refused, and
/// an RXBIT link from it forged with a valid check (and a link count to match) moves
/// nothing (mutation-testing findings: a block that claimed SafeData bits, or a block's
/// received bit read as 0 or 1).
#[test]
fn safedata_bit_links_need_a_connection() {
    let (mut e, mut a) = (estop_pair(), and2());
    let mut g = new_group(2, 2);
    let mut links = [SL_LINK::default(); 2];
    let mut ms: [&mut dyn Member; 2] = [&mut e, &mut a];
    let rx = SL_LINK {
        nKind: group::SL_LINK_RXBIT,
        ..link(0, 0, 1, AND_IN1)
    };
    let tx = SL_LINK {
        nKind: group::SL_LINK_TXBIT,
        ..link(0, ESTOP_OUT, 1, 0)
    };
    for l in [rx, tx] {
        assert_eq!(
            group::add_link(&mut g, &mut ms[..], &mut links, l),
            SL_E_CONFIG
        );
    }
    assert_eq!(g.nLinks, 0);
    let forged = [SL_LINK {
        aReserved: group::link_check(&rx, 0, 1),
        ..rx
    }];
    let w = 1 | g.stPrivate.dwLinks & 0xFFFF_0000;
    g.stPrivate.dwLinks = w;
    g.stPrivate.adwCheck[3] = !w;
    for (level, t0) in [(0, 0), (1, 10)] {
        *ms[1].input_mut(AND_IN1).unwrap() = level;
        for t in t0..t0 + 3 {
            assert_eq!(group::cycle(&mut g, &mut ms[..], &forged, t), SL_OK);
        }
        assert_eq!(
            *ms[1].input_mut(AND_IN1).unwrap(),
            level,
            "an RXBIT link from a block wrote its input"
        );
    }
}

/// Members and links are added in STOP or STOPERROR only: a running group refuses both and
/// changes nothing; a group in STOPERROR (one with connections) takes them
/// (mutation-testing findings: the STOPERROR half of each state test).
#[test]
fn members_and_links_are_added_in_stop_or_stoperror_only() {
    let (mut e, mut a) = (estop_pair(), and2());
    let mut g = SL_GROUP::default();
    assert_eq!(group::init(&mut g, 3, 2), SL_OK);
    for i in 0..2 {
        assert_eq!(group::reserve_member(&mut g), Ok(i));
    }
    let mut links = [SL_LINK::default(); 2];
    let mut ms: [&mut dyn Member; 2] = [&mut e, &mut a];
    g.bRun = 1;
    assert_eq!(group::cycle(&mut g, &mut ms[..], &links, 0), SL_OK);
    assert_eq!(g.nState, SL_STATE_RUN);
    assert_eq!(group::reserve_member(&mut g), Err(SL_E_CONFIG));
    let l = link(0, ESTOP_OUT, 1, AND_IN1);
    assert_eq!(
        group::add_link(&mut g, &mut ms[..], &mut links, l),
        SL_E_CONFIG
    );
    assert_eq!((g.nMembers, g.nLinks), (2, 0));
    assert_eq!(links, [SL_LINK::default(); 2]);

    let mut g = SL_GROUP {
        bConnections: 1,
        ..Default::default()
    };
    assert_eq!(group::init(&mut g, 3, 2), SL_OK);
    assert_eq!(g.nState, group::SL_GROUP_STATE_STOPERROR);
    for i in 0..2 {
        assert_eq!(group::reserve_member(&mut g), Ok(i));
    }
    assert_eq!(group::add_link(&mut g, &mut ms[..], &mut links, l), SL_OK);
    assert_eq!((g.nMembers, g.nLinks), (2, 1));
}

/// A link needs room in the group's capacity and in the caller's slice, and both ends among
/// the group's members, even when the caller's member slice is longer (mutation-testing
/// findings).
#[test]
fn a_link_needs_room_and_members_of_the_group() {
    let (mut e, mut a, mut b) = (estop_pair(), and2(), and2());
    let mut ms: [&mut dyn Member; 3] = [&mut e, &mut a, &mut b];
    let l1 = link(0, ESTOP_OUT, 1, AND_IN1);
    let l2 = link(0, ESTOP_OUT, 1, AND_IN2);
    // Capacity 1, slice of 2.
    let mut g = new_group(2, 1);
    let mut links = [SL_LINK::default(); 2];
    assert_eq!(group::add_link(&mut g, &mut ms[..], &mut links, l1), SL_OK);
    assert_eq!(
        group::add_link(&mut g, &mut ms[..], &mut links, l2),
        SL_E_FULL
    );
    assert_eq!(links[1], SL_LINK::default());
    // Capacity 2, slice of 1.
    let mut g = new_group(2, 2);
    let mut short = [SL_LINK::default(); 1];
    assert_eq!(group::add_link(&mut g, &mut ms[..], &mut short, l1), SL_OK);
    assert_eq!(
        group::add_link(&mut g, &mut ms[..], &mut short, l2),
        SL_E_FULL
    );
    // Member 2 is in the slice, not in the group (2 members).
    let mut g = new_group(2, 2);
    let mut links = [SL_LINK::default(); 2];
    for l in [link(0, ESTOP_OUT, 2, AND_IN1), link(2, AND_OUT, 1, AND_IN1)] {
        assert_eq!(
            group::add_link(&mut g, &mut ms[..], &mut links, l),
            SL_E_CONFIG
        );
    }
    assert_eq!(g.nLinks, 0);
}

/// A stand-in FSoE connection for the group's start-up rule: reports start-up while
/// `startup`, and records the bRun of every run.
struct StartingConn {
    startup: bool,
    runs: Vec<u8>,
}

impl Member for StartingConn {
    fn drive(&mut self, _run: u8, _ack: u8) {}
    fn execute(&mut self, _now: u32) -> safelogic::Status {
        safelogic::Status::Ok
    }
    fn state(&self) -> u8 {
        SL_STATE_STOP
    }
    fn fields(&self) -> &'static [safelogic::base::block::Field] {
        &[]
    }
    fn input_mut(&mut self, _offset: u16) -> Option<&mut u8> {
        None
    }
    fn output(&self, _offset: u16) -> Option<u8> {
        None
    }
    fn output_bits(&self, _offset: u16) -> Option<u32> {
        None
    }
    fn set_input_bits(&mut self, _offset: u16, _bits: u32) -> bool {
        false
    }
    fn field_bits(&self, _offset: u16) -> Option<u32> {
        None
    }
    fn set_param_bits(&mut self, _offset: u16, _bits: u32) -> bool {
        false
    }
    fn run_in_group(&mut self, run: u8, _ack: u8, _now: u32, _w: &mut group::Wiring) -> group::Ran {
        self.runs.push(run);
        group::Ran {
            status: safelogic::Status::Ok,
            state: SL_STATE_STOP,
            conn: Some(group::ConnReport {
                startup: self.startup,
                ..Default::default()
            }),
        }
    }
}

/// A connection that reported start-up in the previous cycle starts the next one in START
/// (ABI-2 §13): it runs once, with bRun FALSE. Only the cycle in which the group first
/// learns of the start-up runs it with bRun TRUE and then stops it again (a
/// mutation-testing finding: without the remembered start-up every cycle ran it twice).
#[test]
fn a_starting_connection_runs_once_a_cycle_in_start() {
    let mut c = StartingConn {
        startup: true,
        runs: Vec::new(),
    };
    let mut a = and2();
    let mut g = new_group(2, 0);
    g.bRun = 1;
    let mut ms: [&mut dyn Member; 2] = [&mut c, &mut a];
    assert_eq!(group::cycle(&mut g, &mut ms[..], &[], 0), SL_OK);
    assert_eq!(g.nState, SL_GROUP_STATE_START);
    for t in 1..4 {
        assert_eq!(group::cycle(&mut g, &mut ms[..], &[], t), SL_OK);
        assert_eq!(g.nState, SL_GROUP_STATE_START);
    }
    assert_eq!(c.runs, [1, 0, 0, 0, 0]);
}

/// A stand-in FSoE connection with 16 SafeData bits each way and one BOOL input at byte 0,
/// for the link rules that need one.
struct BitConn {
    input: u8,
}

const BIT_CONN_FIELDS: &[safelogic::base::block::Field] = &[safelogic::base::block::Field {
    name: "bIn",
    offset: 0,
    kind: safelogic::base::block::Kind::Bool,
    dir: safelogic::base::block::Dir::Input,
}];

impl Member for BitConn {
    fn drive(&mut self, _run: u8, _ack: u8) {}
    fn execute(&mut self, _now: u32) -> safelogic::Status {
        safelogic::Status::Ok
    }
    fn state(&self) -> u8 {
        SL_STATE_RUN
    }
    fn fields(&self) -> &'static [safelogic::base::block::Field] {
        BIT_CONN_FIELDS
    }
    fn input_mut(&mut self, offset: u16) -> Option<&mut u8> {
        (offset == 0).then_some(&mut self.input)
    }
    fn output(&self, _offset: u16) -> Option<u8> {
        None
    }
    fn output_bits(&self, _offset: u16) -> Option<u32> {
        None
    }
    fn set_input_bits(&mut self, offset: u16, bits: u32) -> bool {
        let ok = offset == 0;
        if ok {
            self.input = bits as u8;
        }
        ok
    }
    fn field_bits(&self, offset: u16) -> Option<u32> {
        (offset == 0).then_some(u32::from(self.input))
    }
    fn set_param_bits(&mut self, _offset: u16, _bits: u32) -> bool {
        false
    }
    fn safe_data_bits(&self) -> (u16, u16) {
        (16, 16)
    }
}

/// A TXBIT link names a bit, every other link a byte: a BOOL link into byte 0 of a
/// connection and a TXBIT link into its bit 0 are different destinations (both accepted),
/// while a second link into either is refused (a mutation-testing finding: the comparison
/// of the two kinds).
#[test]
fn a_bit_and_a_byte_of_a_connection_are_different_destinations() {
    let mut e = estop_pair();
    let mut c = BitConn { input: 0 };
    let mut g = new_group(2, 4);
    let mut links = [SL_LINK::default(); 4];
    let mut ms: [&mut dyn Member; 2] = [&mut e, &mut c];
    let byte = link(0, ESTOP_OUT, 1, 0);
    let bit = SL_LINK {
        nKind: group::SL_LINK_TXBIT,
        ..byte
    };
    for l in [byte, bit] {
        assert_eq!(group::add_link(&mut g, &mut ms[..], &mut links, l), SL_OK);
    }
    for l in [byte, bit] {
        assert_eq!(
            group::add_link(&mut g, &mut ms[..], &mut links, l),
            SL_E_CONFIG
        );
    }
    assert_eq!(g.nLinks, 2);
}

/// The group's own state rules where only the guard decides (mutation-testing findings):
/// STOPERROR waits for bRun before it becomes the restart error; RESET waits for ErrAck to
/// fall, however long it is held.
#[test]
fn stoperror_waits_for_run_and_reset_for_errack_to_fall() {
    let mut a = and2();
    let mut g = SL_GROUP {
        bConnections: 1,
        ..Default::default()
    };
    assert_eq!(group::init(&mut g, 1, 0), SL_OK);
    assert_eq!(group::reserve_member(&mut g), Ok(0));
    let mut ms: [&mut dyn Member; 1] = [&mut a];
    for t in 0..3 {
        group::cycle(&mut g, &mut ms[..], &[], t);
        assert_eq!(
            (g.nState, g.nDiag),
            (SL_GROUP_STATE_STOPERROR, 0),
            "no bRun yet"
        );
    }
    g.bRun = 1;
    group::cycle(&mut g, &mut ms[..], &[], 3);
    assert_eq!(g.nState, SL_STATE_ERROR, "the restart error");
    g.bErrAck = 1;
    group::cycle(&mut g, &mut ms[..], &[], 4);
    assert_eq!(g.nState, SL_STATE_RESET);
    for t in 5..8 {
        group::cycle(&mut g, &mut ms[..], &[], t);
        assert_eq!(g.nState, SL_STATE_RESET, "ErrAck held");
    }
    g.bErrAck = 0;
    group::cycle(&mut g, &mut ms[..], &[], 8);
    assert_eq!(g.nState, SL_STATE_RUN);
}

/// FbRun says every member is in RUN: a group without members never sets it, though it is
/// in RUN itself (a mutation-testing finding).
#[test]
fn an_empty_group_in_run_has_no_fb_run() {
    let mut g = new_group(0, 0);
    let mut none: [&mut dyn Member; 0] = [];
    g.bRun = 1;
    for t in 0..3 {
        assert_eq!(group::cycle(&mut g, &mut none[..], &[], t), SL_OK);
        assert_eq!((g.nState, g.bInRun, g.bFbRun), (SL_STATE_RUN, 1, 0));
    }
}

/// (bRun, bComStartupIn, the state a member or link fault leaves): a fault stops a running
/// (RUN) or starting (START) group and leaves a stopped one in STOP.
const STOPS_RUNNING_AND_STARTING: [(u8, u8, u8); 3] = [
    (1, 1, SL_STATE_ERROR),
    (1, 0, SL_STATE_ERROR),
    (0, 0, SL_STATE_STOP),
];

/// A member in ERROR stops the group in RUN and in START (FBERROR, the member's index), and
/// leaves a stopped group in STOP (mutation-testing findings: the START half of the guard).
#[test]
fn a_member_error_stops_a_running_or_starting_group_only() {
    for (run, startup, want) in STOPS_RUNNING_AND_STARTING {
        let mut e = estop_pair();
        let mut g = new_group(1, 0);
        let mut ms: [&mut dyn Member; 1] = [&mut e];
        (g.bRun, g.bComStartupIn) = (run, startup);
        assert_eq!(group::cycle(&mut g, &mut ms[..], &[], 0), SL_OK);
        let before = g.nState;
        assert_eq!(
            before,
            match (run, startup) {
                (1, 1) => SL_GROUP_STATE_START,
                (1, _) => SL_STATE_RUN,
                _ => SL_STATE_STOP,
            }
        );
        e.stPrivate.stHeader.wDiag ^= 0x0100;
        let mut ms: [&mut dyn Member; 1] = [&mut e];
        assert_eq!(group::cycle(&mut g, &mut ms[..], &[], 10), SL_E_CORRUPT);
        assert_eq!(g.nState, want, "from state {before}");
        if want == SL_STATE_ERROR {
            assert_eq!(
                (g.nDiag, g.nFailedMember),
                (group::SL_GROUP_DIAG_FBERROR, 0)
            );
        }
    }
}

/// A link that no member consumed (links out of destination order, each with a valid check)
/// stops a running or starting group (FBERROR, SL_E_CORRUPT) and leaves a stopped one in
/// STOP (a mutation-testing finding: the START half of the guard).
#[test]
fn an_unconsumed_link_stops_a_running_or_starting_group_only() {
    for (run, startup, want) in STOPS_RUNNING_AND_STARTING {
        let (mut e, mut a) = (estop_pair(), and2());
        let mut g = new_group(2, 2);
        let mut ms: [&mut dyn Member; 2] = [&mut e, &mut a];
        (g.bRun, g.bComStartupIn) = (run, startup);
        assert_eq!(group::cycle(&mut g, &mut ms[..], &[], 0), SL_OK);
        // Destination 1 before destination 0: member 0 finds no link of its own at the
        // head, so the second link is never consumed.
        let mut links = [link(0, ESTOP_OUT, 1, AND_IN1), link(1, AND_OUT, 0, 0)];
        for (i, l) in links.iter_mut().enumerate() {
            l.aReserved = group::link_check(l, i, 2);
        }
        let w = 2 | g.stPrivate.dwLinks & 0xFFFF_0000;
        g.stPrivate.dwLinks = w;
        g.stPrivate.adwCheck[3] = !w;
        let rc = group::cycle(&mut g, &mut ms[..], &links, 10);
        assert_eq!(rc, SL_E_CORRUPT, "run {run} startup {startup}");
        assert_eq!(g.nState, want, "run {run} startup {startup}");
    }
}
