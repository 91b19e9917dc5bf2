//! FB XOR (manual §4.34; ABI §9; docs/semantics.md X1–X5, C1–C12): layout, every state,
//! every output, configuration errors, invalid BOOLs, library errors through the envelope,
//! the C functions, group membership, and property tests.

mod common;
use common::state_name;
use common::{aligned_tail, null_refused, offsets, run_steps};

use proptest::prelude::*;
use safelogic::ffi;
use safelogic::group::{self, Member};
use safelogic::*;
use std::mem::offset_of;

fn xor(active: u16) -> FB_XOR {
    common::ready(FB_XOR {
        wInputActive: active,
        ..Default::default()
    })
}

/// Sets input 1 / input 2 of XOR function y (1-based).
fn set(x: &mut FB_XOR, y: usize, a: u8, b: u8) {
    let (p1, p2) = pair_mut(x, y);
    *p1 = a;
    *p2 = b;
}

/// XOR1 alone, its inputs (a, b), running since the call at `t0` with XorOut1 TRUE.
fn running_xor1(a: u8, b: u8, t0: u32) -> FB_XOR {
    let mut x = xor(0b1);
    set(&mut x, 1, a, b);
    x.bRun = 1;
    assert_eq!(x.cycle(t0), SL_OK);
    assert_eq!(x.bXorOut1, 1);
    x
}

fn pair_mut(x: &mut FB_XOR, y: usize) -> (&mut u8, &mut u8) {
    match y {
        1 => (&mut x.bXor1In1, &mut x.bXor2In1),
        2 => (&mut x.bXor1In2, &mut x.bXor2In2),
        3 => (&mut x.bXor1In3, &mut x.bXor2In3),
        4 => (&mut x.bXor1In4, &mut x.bXor2In4),
        5 => (&mut x.bXor1In5, &mut x.bXor2In5),
        6 => (&mut x.bXor1In6, &mut x.bXor2In6),
        7 => (&mut x.bXor1In7, &mut x.bXor2In7),
        8 => (&mut x.bXor1In8, &mut x.bXor2In8),
        _ => panic!("no XOR function {y}"),
    }
}

fn outs(x: &FB_XOR) -> [u8; 8] {
    [
        x.bXorOut1, x.bXorOut2, x.bXorOut3, x.bXorOut4, x.bXorOut5, x.bXorOut6, x.bXorOut7,
        x.bXorOut8,
    ]
}

#[test]
fn layout_is_the_abi() {
    // ABI §9: bXor1In1 (0), bXor2In1 (1), bXor1In2 (2) … bXor2In8 (15); outputs at +8…+15.
    offsets!(FB_XOR;
        bXor1In1 => 0,
        bXor2In1 => 1,
        bXor1In2 => 2,
        bXor2In2 => 3,
        bXor1In5 => 8,
        bXor1In8 => 14,
        bXor2In8 => 15,
        bRun => 16,
        bErrAck => 17,
    );
    let base = 24;
    assert_eq!(base % 8, 0);
    offsets!(FB_XOR, from base;
        bXorOut1 => 8,
        bXorOut2 => 9,
        bXorOut3 => 10,
        bXorOut4 => 11,
        bXorOut5 => 12,
        bXorOut6 => 13,
        bXorOut7 => 14,
        bXorOut8 => 15,
    );
    aligned_tail!(FB_XOR);
}

#[test]
fn init_gives_the_power_up_image_and_leaves_inputs_alone() {
    let mut x = FB_XOR {
        wInputActive: 0xFF,
        bRun: 1,
        bXor1In1: 1,
        bXorOut3: 1,
        nState: 9,
        ..Default::default()
    };
    let inputs_before = (x.bXor1In1, x.bRun, x.wInputActive);
    assert_eq!(x.init(), SL_OK);
    assert_eq!((x.bXor1In1, x.bRun, x.wInputActive), inputs_before);
    assert_eq!(outs(&x), [0; 8]);
    assert_eq!((x.nState, x.nDiag), (SL_STATE_STOP, 0));
}

/// X1: "XorOutY = (Xor1InY XOR Xor2InY) AND FB Input Active(Y)", every function, every
/// input combination, with the response in the same call (X4).
#[test]
fn every_function_computes_xor_in_the_same_call() {
    let mut x = xor(0xFF);
    x.bRun = 1;
    let mut t = 0;
    for y in 1..=8 {
        for (a, b, expect) in [(0, 0, 0), (0, 1, 1), (1, 0, 1), (1, 1, 0)] {
            set(&mut x, y, a, b);
            assert_eq!(x.cycle(t), SL_OK);
            t += 10;
            assert_eq!(x.nState, SL_STATE_RUN);
            let o = outs(&x);
            assert_eq!(o[y - 1], expect, "XOR{y} with {a}, {b}");
            // Every other function still shows its own inputs (here the last setting 1,1 → 0
            // for earlier functions, 0,0 → 0 for later ones).
            for (k, &v) in o.iter().enumerate() {
                if k != y - 1 {
                    assert_eq!(v, 0, "XOR{} unaffected", k + 1);
                }
            }
        }
    }
}

#[test]
fn stop_to_run_in_the_call_run_rises() {
    let mut x = xor(0b1);
    set(&mut x, 1, 1, 0);
    assert_eq!(x.cycle(0), SL_OK);
    assert_eq!(
        (x.nState, x.bXorOut1),
        (SL_STATE_STOP, 0),
        "STOP: XorOutY = 0"
    );
    x.bRun = 1;
    assert_eq!(x.cycle(1), SL_OK);
    assert_eq!((x.nState, x.bXorOut1), (SL_STATE_RUN, 1));
    // RUN with equal inputs: still RUN (XOR has no SAFE state), output FALSE.
    set(&mut x, 1, 1, 1);
    x.cycle(2);
    assert_eq!((x.nState, x.bXorOut1), (SL_STATE_RUN, 0));
    set(&mut x, 1, 0, 1);
    x.cycle(3);
    assert_eq!(x.bXorOut1, 1);
    // FbRun FALSE: STOP, every output FALSE in the same call.
    x.bRun = 0;
    x.cycle(4);
    assert_eq!((x.nState, outs(&x)), (SL_STATE_STOP, [0; 8]));
}

/// X1: an inactive function's output is FALSE whatever its inputs, and its bytes are not read.
#[test]
fn inactive_functions_are_false_and_unread() {
    let mut x = xor(0b0000_0101); // XOR1 and XOR3
    x.bRun = 1;
    for y in 1..=8 {
        set(&mut x, y, 1, 0);
    }
    assert_eq!(x.cycle(0), SL_OK);
    assert_eq!(outs(&x), [1, 0, 1, 0, 0, 0, 0, 0]);
    set(&mut x, 2, 7, 0xFF);
    assert_eq!(x.cycle(1), SL_OK, "invalid bytes of an inactive function");
    assert_eq!(outs(&x), [1, 0, 1, 0, 0, 0, 0, 0]);
}

/// X3: an invalid byte makes its function's output FALSE whatever the other input.
#[test]
fn invalid_bool_switches_its_function_off() {
    let mut x = xor(0b11);
    x.bRun = 1;
    set(&mut x, 1, 2, 1);
    set(&mut x, 2, 1, 0);
    assert_eq!(x.cycle(0), SL_E_INVALID_BOOL);
    assert_eq!(x.nState, SL_STATE_RUN);
    assert_eq!((x.bXorOut1, x.bXorOut2), (0, 1), "only XOR1 is affected");
    set(&mut x, 1, 0, 0x80);
    assert_eq!(x.cycle(1), SL_E_INVALID_BOOL);
    assert_eq!(x.bXorOut1, 0);
    set(&mut x, 1, 0xFF, 0xFF);
    assert_eq!(x.cycle(2), SL_E_INVALID_BOOL);
    assert_eq!(x.bXorOut1, 0);
    set(&mut x, 1, 0, 1);
    assert_eq!(x.cycle(3), SL_OK);
    assert_eq!(x.bXorOut1, 1, "valid again: computed again");
}

#[test]
fn invalid_run_reads_false() {
    let mut x = running_xor1(1, 0, 0);
    x.bRun = 3;
    assert_eq!(x.cycle(1), SL_E_INVALID_BOOL);
    assert_eq!((x.nState, x.bXorOut1), (SL_STATE_STOP, 0));
}

/// X1, C6: at least one active function, no bits beyond XOR8, no negation.
#[test]
fn configuration_errors() {
    for active in [0u16, 0x100, 0x8001, 0xFFFF] {
        let mut x = common::refused(
            FB_XOR {
                wInputActive: active,
                ..Default::default()
            },
            &[],
        );
        assert_eq!((x.nState, outs(&x)), (SL_STATE_STOP, [0; 8]));
        x.bRun = 1;
        set(&mut x, 1, 1, 0);
        for t in 0..3 {
            assert_eq!(x.cycle(t), SL_E_CONFIG);
            assert_eq!((x.nState, outs(&x)), (SL_STATE_STOP, [0; 8]));
        }
        // Fixed in STOP: latched at the next STOP → run.
        x.bRun = 0;
        x.wInputActive = 1;
        assert_eq!(x.cycle(10), SL_E_CONFIG, "still the latched invalid set");
        x.bRun = 1;
        assert_eq!(x.cycle(11), SL_OK);
        assert_eq!((x.nState, x.bXorOut1), (SL_STATE_RUN, 1));
    }
    for active in [1u16, 0x80, 0xFF] {
        assert_eq!(
            FB_XOR {
                wInputActive: active,
                ..Default::default()
            }
            .init(),
            SL_OK
        );
    }
}

/// C5: a parameter changed while running is an error (nState 4, outputs FALSE), left only
/// through RESET.
#[test]
fn parameter_change_while_running() {
    let mut x = xor(0b11);
    x.bRun = 1;
    set(&mut x, 1, 1, 0);
    let all = |x: &FB_XOR| (x.nState, x.nDiag, outs(x));
    #[rustfmt::skip]
    run_steps("running", &mut x, |x| x.bXorOut1, &[(0, |_| {}, SL_OK, Some(1), "")]);
    #[rustfmt::skip]
    run_steps("changed", &mut x, all, &[
        (1, |x| x.wInputActive = 0b111, SL_E_PARAM_CHANGED, Some((SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, [0; 8])), ""),
    ]);
    #[rustfmt::skip]
    run_steps("no acknowledgement", &mut x, |x| x.nState, &[
        // The change remains: no acknowledgement.
        (2, |x| x.bErrAck = 1, SL_E_PARAM_CHANGED, Some(SL_STATE_ERROR), ""),
        (3, |x| (x.bErrAck, x.wInputActive) = (0, 0b11), SL_OK, Some(SL_STATE_ERROR), ""),
    ]);
    #[rustfmt::skip]
    run_steps("acknowledged", &mut x, all, &[(4, |x| x.bErrAck = 1, SL_OK, Some((SL_STATE_RESET, 0, [0; 8])), "")]);
    #[rustfmt::skip]
    run_steps("RUN again", &mut x, |x| (x.nState, x.bXorOut1), &[
        (5, |x| x.bErrAck = 0, SL_OK, Some((SL_STATE_RUN, 1)), ""),
    ]);
}

#[test]
fn parameter_change_in_stop_is_latched_at_start() {
    let mut x = xor(0b1);
    set(&mut x, 2, 1, 0);
    x.wInputActive = 0b10;
    assert_eq!(x.cycle(0), SL_OK);
    x.bRun = 1;
    assert_eq!(x.cycle(1), SL_OK);
    assert_eq!((x.bXorOut1, x.bXorOut2), (0, 1));
}

/// C4: the clock going backwards is ERROR (diag bit 14) in every state; one ErrAck edge.
#[test]
fn clock_backwards() {
    let mut x = running_xor1(0, 1, 1000);
    assert_eq!(x.cycle(999), SL_E_CLOCK);
    assert_eq!(
        (x.nState, x.nDiag, x.bXorOut1),
        (SL_STATE_ERROR, SL_DIAG_CLOCK, 0)
    );
    x.bErrAck = 1;
    assert_eq!(x.cycle(1000), SL_OK);
    assert_eq!(x.nState, SL_STATE_RESET);
    x.bErrAck = 0;
    x.cycle(1001);
    assert_eq!((x.nState, x.bXorOut1), (SL_STATE_RUN, 1));
    // In STOP as well.
    x.bRun = 0;
    x.cycle(1002);
    assert_eq!(x.cycle(1), SL_E_CLOCK);
    assert_eq!(x.nState, SL_STATE_ERROR);
}

/// C8: an ErrAck already TRUE when the error occurred does not acknowledge it.
#[test]
fn errack_held_through_the_error_needs_a_new_edge() {
    let mut x = xor(0b1);
    #[rustfmt::skip]
    run_steps("ErrAck held", &mut x, |x| x.nState, &[
        (100, |x| (x.bRun, x.bErrAck) = (1, 1), SL_OK, None, ""),
        (50, |_| {}, SL_E_CLOCK, None, ""),
        (51, |_| {}, SL_OK, Some(SL_STATE_ERROR), ""),
        (52, |x| x.bErrAck = 0, SL_OK, Some(SL_STATE_ERROR), ""),
        (53, |x| x.bErrAck = 1, SL_OK, Some(SL_STATE_RESET), ""),
        // RESET left to STOP when Run is FALSE (C9).
        (54, |x| (x.bRun, x.bErrAck) = (0, 0), SL_OK, Some(SL_STATE_STOP), ""),
    ]);
}

#[test]
fn corrupt_private_state() {
    let mut x = xor(0b1);
    x.bRun = 1;
    set(&mut x, 1, 1, 0);
    x.cycle(0);
    x.stPrivate.stHeader.wAux ^= 1;
    assert_eq!(x.cycle(1), SL_E_CORRUPT);
    assert_eq!((x.nState, x.bXorOut1), (SL_STATE_ERROR, 0));
    assert_eq!(x.nDiag & SL_DIAG_CORRUPT, SL_DIAG_CORRUPT);
}

#[test]
fn c_functions_state_names_and_group_membership() {
    null_refused!(ffi::sl_xor_init, ffi::sl_xor_cycle);
    let mut x = FB_XOR {
        wInputActive: 1,
        bXor1In1: 1,
        ..Default::default()
    };
    assert_eq!(unsafe { ffi::sl_xor_init(&mut x) }, SL_OK);
    x.bRun = 1;
    assert_eq!(unsafe { ffi::sl_xor_cycle(&mut x, 5) }, SL_OK);
    assert_eq!(x.bXorOut1, 1);
    assert_eq!(state_name(SL_TYPE_XOR, SL_STATE_RUN), "RUN");
    assert_eq!(state_name(SL_TYPE_XOR, SL_STATE_STOP), "STOP");
    assert_eq!(state_name(SL_TYPE_XOR, SL_STATE_ERROR), "ERROR");
    assert_eq!(state_name(SL_TYPE_XOR, SL_STATE_RESET), "RESET");
    assert_eq!(
        state_name(SL_TYPE_XOR, SL_STATE_SAFE),
        "?",
        "XOR has no SAFE state"
    );

    // Through the C group API: the type tag reaches the block (member_dyn).
    let mut g = SL_GROUP::default();
    let mut members = [SL_MEMBER::default(); 2];
    let mut links = [SL_LINK::default(); 1];
    let mut y = common::ready(FB_XOR {
        wInputActive: 1,
        ..Default::default()
    });
    common::c_group_init(&mut g, (members.as_mut_ptr(), 2), (links.as_mut_ptr(), 1));
    let mut idx = 0xFFFF;
    common::c_add_member(
        &mut g,
        members.as_mut_ptr(),
        SL_TYPE_XOR,
        std::ptr::addr_of_mut!(x).cast(),
        &mut idx,
    );
    assert_eq!(idx, 0);
    common::c_add_member(
        &mut g,
        members.as_mut_ptr(),
        SL_TYPE_XOR,
        std::ptr::addr_of_mut!(y).cast(),
        &mut idx,
    );
    // XorOut1 of member 0 feeds Xor1In1 of member 1.
    let (src, dst) = (offset_of!(FB_XOR, bXorOut1), offset_of!(FB_XOR, bXor1In1));
    common::c_add_link(&mut g, &mut members, &mut links, (0, src), (1, dst));
    g.bRun = 1;
    x.bXor1In1 = 1;
    assert_eq!(c_group_cycle!(g, members, links, 10; x, y), SL_OK);
    assert_eq!((x.nState, y.nState), (SL_STATE_RUN, SL_STATE_RUN));
    assert_eq!((x.bXorOut1, y.bXorOut1), (1, 1));
    x.bXor2In1 = 1;
    c_group_cycle!(g, members, links, 11; x, y);
    assert_eq!((x.bXorOut1, y.bXorOut1), (0, 0));
    assert_eq!(g.bFbRun, 1, "both members in RUN");
}

#[test]
fn member_offsets() {
    let mut x = xor(1);
    x.bXor2In8 = 1;
    let m: &mut dyn Member = &mut x;
    assert!(m.input_mut(offset_of!(FB_XOR, bXor1In1) as u16).is_some());
    assert_eq!(m.input_mut(15).map(|b| *b), Some(1));
    assert!(m.input_mut(offset_of!(FB_XOR, bRun) as u16).is_none());
    assert!(m.output(offset_of!(FB_XOR, bXorOut8) as u16).is_some());
    assert!(m.output(offset_of!(FB_XOR, nState) as u16).is_none());
    let _ = group::SL_LINK_BOOL;
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_STOP, SL_STATE_ERROR, SL_STATE_RESET];
    /// Outputs are TRUE only in RUN; in RUN every output is XOR of its valid inputs AND
    /// active, in the same call (X1, X3, X4).
    fn outputs_follow_the_formula_and_are_false_outside_run(
        active in 1u16..=0xFF,
        steps in proptest::collection::vec(
            (0u8..4, 0u8..3, proptest::collection::vec(prop_oneof![Just(0u8), Just(1u8), Just(2u8)], 16), 0u32..50, any::<bool>()),
            1..60)
    ) {
        let mut x = xor(active);
        let mut t = 0u32;
        for (run, ack, ins, dt, clock_back) in steps {
            x.bRun = u8::from(run != 0);
            x.bErrAck = u8::from(ack == 1);
            for y in 1..=8 {
                set(&mut x, y, ins[2 * (y - 1)], ins[2 * (y - 1) + 1]);
            }
            t = if clock_back && dt == 7 { t.wrapping_sub(1) } else { t.wrapping_add(dt) };
            let rc = x.cycle(t);
            common::saw(x.nState);
            prop_assert!([SL_STATE_RUN, SL_STATE_STOP, SL_STATE_ERROR, SL_STATE_RESET].contains(&x.nState));
            let o = outs(&x);
            if x.nState != SL_STATE_RUN {
                prop_assert_eq!(o, [0; 8]);
            } else {
                let mut invalid = false;
                for y in 0..8 {
                    let (a, b) = (ins[2 * y], ins[2 * y + 1]);
                    let on = active & (1 << y) != 0;
                    invalid |= on && (a > 1 || b > 1);
                    let expect = u8::from(on && a <= 1 && b <= 1 && a != b);
                    prop_assert_eq!(o[y], expect);
                }
                prop_assert_eq!(rc == SL_E_INVALID_BOOL, invalid);
            }
            prop_assert!(o.iter().all(|&v| v <= 1));
        }
    }
}
