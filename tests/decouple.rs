//! FB DECOUPLE (manual §4.6; ABI §9; docs/semantics.md D1–D5, C1–C12): layout, RUN and
//! STOP outputs, used/unused channels, configuration errors, invalid BOOLs, library errors
//! through the envelope, the C functions, group membership, and property tests.

mod common;
use common::state_name;
use common::{aligned_tail, null_refused, offsets, run_steps};

use proptest::prelude::*;
use safelogic::ffi;
use safelogic::group::{self, Member, SL_GROUP_DIAG_COMERROR};
use safelogic::*;
use std::mem::offset_of;

fn dec(active: u16) -> FB_DECOUPLE {
    common::ready(FB_DECOUPLE {
        wInputActive: active,
        ..Default::default()
    })
}

fn set_ins(d: &mut FB_DECOUPLE, v: [u8; 8]) {
    [
        d.bDecIn1, d.bDecIn2, d.bDecIn3, d.bDecIn4, d.bDecIn5, d.bDecIn6, d.bDecIn7, d.bDecIn8,
    ] = v;
}

fn outs(d: &FB_DECOUPLE) -> [u8; 8] {
    [
        d.bDecOut1, d.bDecOut2, d.bDecOut3, d.bDecOut4, d.bDecOut5, d.bDecOut6, d.bDecOut7,
        d.bDecOut8,
    ]
}

#[test]
fn layout_is_the_abi() {
    // ABI §9: bDecIn1…bDecIn8 (8…15), bDecOut1…bDecOut8 (+8…+15).
    offsets!(FB_DECOUPLE;
        bDecIn1 => 8,
        bDecIn2 => 9,
        bDecIn3 => 10,
        bDecIn4 => 11,
        bDecIn5 => 12,
        bDecIn6 => 13,
        bDecIn7 => 14,
        bDecIn8 => 15,
    );
    let base = 24;
    offsets!(FB_DECOUPLE, from base;
        bDecOut1 => 8,
        bDecOut2 => 9,
        bDecOut3 => 10,
        bDecOut4 => 11,
        bDecOut5 => 12,
        bDecOut6 => 13,
        bDecOut7 => 14,
        bDecOut8 => 15,
    );
    offsets!(FB_DECOUPLE; bRun => 16, bErrAck => 17);
    aligned_tail!(FB_DECOUPLE);
}

/// D1: RUN "DcOutX=DcInX" in the same call; STOP "DcOutX=0".
#[test]
fn outputs_follow_inputs_one_to_one_in_run() {
    let mut d = dec(0xFF);
    set_ins(&mut d, [1, 0, 1, 1, 0, 0, 1, 0]);
    assert_eq!(d.cycle(0), SL_OK);
    assert_eq!((d.nState, outs(&d)), (SL_STATE_STOP, [0; 8]));
    d.bRun = 1;
    assert_eq!(d.cycle(1), SL_OK);
    assert_eq!(d.nState, SL_STATE_RUN);
    assert_eq!(outs(&d), [1, 0, 1, 1, 0, 0, 1, 0]);
    for k in 0..8 {
        let mut v = [0u8; 8];
        v[k] = 1;
        set_ins(&mut d, v);
        d.cycle(2 + k as u32);
        assert_eq!(outs(&d), v, "channel {}", k + 1);
    }
    set_ins(&mut d, [0; 8]);
    d.cycle(20);
    assert_eq!(
        (d.nState, outs(&d)),
        (SL_STATE_RUN, [0; 8]),
        "RUN with all FALSE"
    );
    set_ins(&mut d, [1; 8]);
    d.cycle(21);
    assert_eq!(outs(&d), [1; 8]);
    d.bRun = 0;
    d.cycle(22);
    assert_eq!((d.nState, outs(&d)), (SL_STATE_STOP, [0; 8]));
    assert_eq!(d.nDiag, 0, "diag always 0");
}

/// D2: an unused channel's output stays FALSE and its input byte is not read.
#[test]
fn unused_channels() {
    let mut d = dec(0b1000_0001);
    d.bRun = 1;
    set_ins(&mut d, [1, 1, 1, 1, 1, 1, 1, 1]);
    d.cycle(0);
    assert_eq!(outs(&d), [1, 0, 0, 0, 0, 0, 0, 1]);
    set_ins(&mut d, [1, 9, 9, 9, 9, 9, 9, 1]);
    assert_eq!(d.cycle(1), SL_OK);
    assert_eq!(outs(&d), [1, 0, 0, 0, 0, 0, 0, 1]);
}

/// D3: an invalid byte on a used channel is FALSE at its output.
#[test]
fn invalid_bool() {
    let mut d = dec(0b11);
    d.bRun = 1;
    set_ins(&mut d, [2, 1, 0, 0, 0, 0, 0, 0]);
    assert_eq!(d.cycle(0), SL_E_INVALID_BOOL);
    assert_eq!((d.nState, d.bDecOut1, d.bDecOut2), (SL_STATE_RUN, 0, 1));
    set_ins(&mut d, [1, 1, 0, 0, 0, 0, 0, 0]);
    assert_eq!(d.cycle(1), SL_OK);
    assert_eq!(d.bDecOut1, 1);
    d.bErrAck = 0xAA;
    assert_eq!(
        d.cycle(2),
        SL_E_INVALID_BOOL,
        "an invalid ErrAck counts too"
    );
    assert_eq!(d.bDecOut1, 1);
}

/// D2, D4, C6.
#[test]
fn configuration_errors() {
    for active in [0u16, 0x100, 0x1FF] {
        let d = common::refused(
            FB_DECOUPLE {
                wInputActive: active,
                bRun: 1,
                bDecIn1: 1,
                ..Default::default()
            },
            &[0],
        );
        assert_eq!((d.nState, outs(&d)), (SL_STATE_STOP, [0; 8]));
    }
    // A never-initialised instance latches at its first cycle (C2).
    let mut d = FB_DECOUPLE {
        wInputActive: 0b100,
        bRun: 1,
        bDecIn3: 1,
        ..Default::default()
    };
    assert_eq!(d.cycle(0), SL_OK);
    assert_eq!((d.nState, d.bDecOut3), (SL_STATE_RUN, 1));
}

#[test]
fn parameter_change_and_clock_errors() {
    let mut d = dec(0b1);
    #[rustfmt::skip]
    run_steps("changed", &mut d, |d| (d.nState, d.nDiag, d.bDecOut1), &[
        (0, |d| (d.bRun, d.bDecIn1) = (1, 1), SL_OK, Some((SL_STATE_RUN, 0, 1)), ""),
        (1, |d| d.wInputActive = 0b11, SL_E_PARAM_CHANGED, Some((SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 0)), ""),
    ]);
    // With Run FALSE the change is adopted at the next start (C5).
    #[rustfmt::skip]
    run_steps("adopted", &mut d, |d| d.nState, &[
        (2, |d| (d.bRun, d.bErrAck) = (0, 1), SL_OK, Some(SL_STATE_RESET), ""),
        (3, |d| d.bErrAck = 0, SL_OK, Some(SL_STATE_STOP), ""),
    ]);
    #[rustfmt::skip]
    run_steps("started", &mut d, |d| (d.nState, d.bDecOut1, d.bDecOut2), &[
        (4, |d| (d.bRun, d.bDecIn2) = (1, 1), SL_OK, Some((SL_STATE_RUN, 1, 1)), ""),
    ]);
    // Clock.
    assert_eq!(d.cycle(3), SL_E_CLOCK);
    assert_eq!(
        (d.nState, d.nDiag, outs(&d)),
        (SL_STATE_ERROR, SL_DIAG_CLOCK, [0; 8])
    );
    d.bErrAck = 1;
    d.cycle(4);
    d.bErrAck = 0;
    d.cycle(5);
    assert_eq!((d.nState, d.bDecOut1), (SL_STATE_RUN, 1));
}

/// D5: a communication error of the group stops its members: DECOUPLE's outputs go FALSE.
#[test]
fn group_com_error_switches_decouple_off() {
    null_refused!(ffi::sl_decouple_init, ffi::sl_decouple_cycle);
    let mut d = FB_DECOUPLE {
        wInputActive: 0xFF,
        ..Default::default()
    };
    assert_eq!(unsafe { ffi::sl_decouple_init(&mut d) }, SL_OK);
    let mut g = SL_GROUP::default();
    let mut members = [SL_MEMBER::default(); 1];
    let mut links: [SL_LINK; 0] = [];
    common::c_group_init(&mut g, (members.as_mut_ptr(), 1), (std::ptr::null_mut(), 0));
    common::c_add_member(
        &mut g,
        members.as_mut_ptr(),
        SL_TYPE_DECOUPLE,
        std::ptr::addr_of_mut!(d).cast(),
        std::ptr::null_mut(),
    );
    g.bRun = 1;
    set_ins(&mut d, [1; 8]);
    assert_eq!(c_group_cycle!(g, members, links, 0; d), SL_OK);
    assert_eq!(outs(&d), [1; 8]);
    g.bComErrIn = 1;
    c_group_cycle!(g, members, links, 1; d);
    assert_eq!(
        (g.nState, g.nDiag),
        (SL_STATE_ERROR, SL_GROUP_DIAG_COMERROR)
    );
    assert_eq!((d.nState, outs(&d)), (SL_STATE_STOP, [0; 8]));
    assert_eq!(state_name(SL_TYPE_DECOUPLE, SL_STATE_RUN), "RUN");
    assert_eq!(state_name(SL_TYPE_DECOUPLE, SL_STATE_STOP), "STOP");
    assert_eq!(state_name(SL_TYPE_DECOUPLE, SL_STATE_SAFE), "?");
}

#[test]
fn member_offsets() {
    let mut d = dec(1);
    let m: &mut dyn Member = &mut d;
    assert!(m
        .input_mut(offset_of!(FB_DECOUPLE, bDecIn8) as u16)
        .is_some());
    assert!(m
        .input_mut(offset_of!(FB_DECOUPLE, bErrAck) as u16)
        .is_none());
    assert!(m.output(offset_of!(FB_DECOUPLE, bDecOut1) as u16).is_some());
    assert!(m.output(offset_of!(FB_DECOUPLE, bDecIn1) as u16).is_none());
    let _ = group::SL_LINK_BOOL;
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_STOP, SL_STATE_ERROR, SL_STATE_RESET];
    /// In RUN every used output equals its input in the same call (invalid → FALSE), unused
    /// outputs are FALSE; outside RUN every output is FALSE (D1–D3).
    fn outputs_are_the_inputs_in_run_and_false_otherwise(
        active in 1u16..=0xFF,
        steps in proptest::collection::vec(
            (0u8..4, 0u8..3, proptest::array::uniform8(prop_oneof![Just(0u8), Just(1u8), 2u8..=255]), 0u32..50, 0u8..20),
            1..60)
    ) {
        let mut d = dec(active);
        let mut t = 0u32;
        for (run, ack, ins, dt, mode) in steps {
            d.bRun = u8::from(run != 0);
            d.bErrAck = u8::from(ack == 1);
            set_ins(&mut d, ins);
            // Now and then a library error: a parameter change or the clock going back.
            d.wInputActive = if mode == 0 { active ^ 0x100 } else { active };
            t = if mode == 1 { t.wrapping_sub(5) } else { t.wrapping_add(dt) };
            d.cycle(t);
            common::saw(d.nState);
            prop_assert!([SL_STATE_RUN, SL_STATE_STOP, SL_STATE_ERROR, SL_STATE_RESET].contains(&d.nState));
            let o = outs(&d);
            if d.nState == SL_STATE_RUN {
                for k in 0..8 {
                    let expect = u8::from(active & (1 << k) != 0 && ins[k] == 1);
                    prop_assert_eq!(o[k], expect);
                }
            } else {
                prop_assert_eq!(o, [0; 8]);
            }
        }
    }
}
