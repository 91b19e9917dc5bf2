//! FB TON (manual §4.12 incl. the EL6910 timebases §4.12.4; docs/semantics.md rows T*):
//! every state and output value, the delay exactly at its limit per timebase, timebase
//! validation, wrapping time, clock errors, parameter changes, invalid BOOLs, corruption.

mod common;
use common::{aligned_tail, null_refused, offsets};

use proptest::prelude::*;
use safelogic::base::member::Member;
use safelogic::ffi;
use safelogic::*;
use std::mem::offset_of;

const DELAYIN: u8 = SL_STATE_TON_DELAYIN;

fn ton(delay: u32, base: u16) -> FB_TON {
    common::ready(FB_TON {
        tDelay: delay,
        nTimeBase: base,
        wInputActive: 1,
        ..Default::default()
    })
}

/// A TON that is running (SAFE) with bRun TRUE after one call at `t`.
fn running(delay: u32, base: u16, t: u32) -> FB_TON {
    let mut f = ton(delay, base);
    f.bRun = 1;
    assert_eq!(f.cycle(t), SL_OK);
    assert_eq!(f.nState, SL_STATE_SAFE);
    f
}

fn st(f: &FB_TON) -> (u8, u8) {
    (f.nState, f.bTonOut)
}

#[test]
fn layout_matches_the_abi() {
    offsets!(FB_TON; bTonIn1 => 8, bRun => 16, bErrAck => 17);
    assert_eq!(offset_of!(FB_TON, bTonOut) % 8, 1, "output base + 1");
    aligned_tail!(FB_TON);
    assert!(std::mem::size_of::<SL_TIMER_PRIVATE>() <= 64);
}

#[test]
fn power_up_is_stop_with_the_output_false() {
    let mut f = FB_TON {
        tDelay: 100,
        wInputActive: 1,
        bTonIn1: 1,
        ..Default::default()
    };
    f.bTonOut = 1;
    f.nState = 77;
    assert_eq!(f.init(), SL_OK);
    assert_eq!((f.nState, f.bTonOut, f.nDiag), (SL_STATE_STOP, 0, 0));
    assert_eq!(f.bTonIn1, 1, "init does not touch inputs");
    // bRun FALSE: STOP whatever the input.
    assert_eq!(f.cycle(0), SL_OK);
    assert_eq!(st(&f), (SL_STATE_STOP, 0));
}

/// T5, T6: SAFE → DELAYIN starts the timer; RUN exactly when the delay is reached.
#[test]
fn every_state_and_output() {
    let mut f = running(100, 0, 1000);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0));
    f.cycle(1010);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0), "input FALSE stays SAFE");
    f.bTonIn1 = 1;
    f.cycle(1020);
    assert_eq!(st(&f), (DELAYIN, 0), "timer starts at 1020");
    f.cycle(1119);
    assert_eq!(st(&f), (DELAYIN, 0), "99 ms");
    f.cycle(1120);
    assert_eq!(st(&f), (SL_STATE_RUN, 1), "reached at 100 ms");
    f.cycle(5000);
    assert_eq!(st(&f), (SL_STATE_RUN, 1));
    // Input FALSE: output off in the same call.
    f.bTonIn1 = 0;
    f.cycle(5001);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0));
    assert_eq!(f.nDiag, 0);
}

/// T6: the output is not activated if the input falls before the delay; a new rising edge
/// restarts the delay from scratch.
#[test]
fn input_dropping_before_the_delay_discards_it() {
    let mut f = running(100, 1, 0);
    f.bTonIn1 = 1;
    f.cycle(10);
    f.cycle(90);
    assert_eq!(st(&f), (DELAYIN, 0));
    f.bTonIn1 = 0;
    f.cycle(95);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0));
    f.bTonIn1 = 1;
    f.cycle(96);
    assert_eq!(st(&f), (DELAYIN, 0));
    f.cycle(195);
    assert_eq!(st(&f), (DELAYIN, 0), "measured from 96, not from 10");
    f.cycle(196);
    assert_eq!(st(&f), (SL_STATE_RUN, 1));
}

/// T6: the input falling in the very cycle the delay is reached wins.
#[test]
fn input_false_at_the_reaching_cycle_keeps_the_output_off() {
    let mut f = running(50, 0, 0);
    f.bTonIn1 = 1;
    f.cycle(0);
    f.bTonIn1 = 0;
    f.cycle(50);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0));
}

/// T5: an input already TRUE at start-up starts the timer in the first running cycle
/// after STOP → SAFE.
#[test]
fn input_true_at_start_up() {
    let mut f = ton(100, 0);
    f.bTonIn1 = 1;
    f.bRun = 1;
    assert_eq!(f.cycle(0), SL_OK);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0));
    f.cycle(10);
    assert_eq!(st(&f), (DELAYIN, 0));
    f.cycle(109);
    assert_eq!(st(&f), (DELAYIN, 0));
    f.cycle(110);
    assert_eq!(st(&f), (SL_STATE_RUN, 1));
}

/// ABI §7 Run: bRun FALSE → STOP with the output FALSE at once, from every state; the
/// delay starts from scratch after the restart.
#[test]
fn run_false_stops_at_once() {
    for state in [SL_STATE_SAFE, DELAYIN, SL_STATE_RUN] {
        let mut f = running(100, 0, 0);
        f.bTonIn1 = 1;
        f.cycle(1);
        if state == SL_STATE_RUN {
            f.cycle(101);
        }
        if state == SL_STATE_SAFE {
            f.bTonIn1 = 0;
            f.cycle(2);
        }
        assert_eq!(f.nState, state);
        f.bRun = 0;
        assert_eq!(f.cycle(102), SL_OK);
        assert_eq!(st(&f), (SL_STATE_STOP, 0));
        f.bRun = 1;
        f.bTonIn1 = 1;
        f.cycle(103);
        assert_eq!(st(&f), (SL_STATE_SAFE, 0));
        f.cycle(104);
        assert_eq!(st(&f), (DELAYIN, 0));
        f.cycle(203);
        assert_eq!(st(&f), (DELAYIN, 0));
        f.cycle(204);
        assert_eq!(st(&f), (SL_STATE_RUN, 1));
    }
}

#[test]
fn negated_input_is_a_make_contact() {
    let mut f = common::ready(FB_TON {
        tDelay: 10,
        wInputActive: 1,
        wInputNegated: 1,
        bTonIn1: 1,
        bRun: 1,
        ..Default::default()
    });
    f.cycle(0);
    f.cycle(1);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0), "raw TRUE negated is FALSE");
    f.bTonIn1 = 0;
    f.cycle(2);
    f.cycle(12);
    assert_eq!(st(&f), (SL_STATE_RUN, 1));
}

/// ABI §2, C7, T8: an invalid input byte reads FALSE (also when negated), the cycle
/// finishes, the call returns SL_E_INVALID_BOOL.
#[test]
fn invalid_bool() {
    for negated in [0u16, 1] {
        let mut f = common::ready(FB_TON {
            tDelay: 10,
            wInputActive: 1,
            wInputNegated: negated,
            bRun: 1,
            ..Default::default()
        });
        let on = u8::from(negated == 0);
        f.bTonIn1 = on;
        f.cycle(0);
        f.cycle(1);
        f.cycle(11);
        assert_eq!(st(&f), (SL_STATE_RUN, 1));
        f.bTonIn1 = 2;
        assert_eq!(f.cycle(12), SL_E_INVALID_BOOL);
        assert_eq!(st(&f), (SL_STATE_SAFE, 0));
        f.bTonIn1 = 0xFF;
        assert_eq!(f.cycle(13), SL_E_INVALID_BOOL);
        assert_eq!(f.cycle(100), SL_E_INVALID_BOOL);
        assert_eq!(st(&f), (SL_STATE_SAFE, 0), "never reaches DELAYIN");
    }
    // Invalid bRun reads FALSE; invalid ErrAck is reported too.
    let mut f = running(10, 0, 0);
    f.bRun = 3;
    assert_eq!(f.cycle(1), SL_E_INVALID_BOOL);
    assert_eq!(st(&f), (SL_STATE_STOP, 0));
    f.bRun = 1;
    f.bErrAck = 9;
    assert_eq!(f.cycle(2), SL_E_INVALID_BOOL);
    assert_eq!(f.nState, SL_STATE_SAFE);
}

/// Runs a TON with `delay` and `base`: the output comes on exactly `delay` ms after the
/// timer started, not one ms earlier.
fn output_exactly_after(delay: u32, base: u16, t0: u32) {
    let mut f = running(delay, base, t0);
    f.bTonIn1 = 1;
    let start = t0.wrapping_add(1);
    assert_eq!(f.cycle(start), SL_OK);
    let run = (SL_STATE_RUN, 1);
    common::timer::walk_delay(&mut f, st, (start, delay, base), (DELAYIN, 0), run);
}

/// T1, T3: every timebase, the delay just below and at its limit; also at 60,000 s.
#[test]
fn delays_at_and_below_the_limit_of_every_time_base() {
    common::timer::at_and_below_the_limits(|delay, base| output_exactly_after(delay, base, 5));
    assert_eq!(SL_TIMER_DELAY_MAX, 60_000_000);
    output_exactly_after(SL_TIMER_DELAY_MAX, SL_TIMEBASE_AUTO, u32::MAX - 1000);
    output_exactly_after(1, SL_TIMEBASE_AUTO, 0);
}

fn init_status(delay: u32, base: u16, active: u16, negated: u16) -> FB_TON {
    let mut f = FB_TON {
        tDelay: delay,
        nTimeBase: base,
        wInputActive: active,
        wInputNegated: negated,
        bTonIn1: 1,
        ..Default::default()
    };
    f.bTonOut = 1;
    let status = f.init();
    assert_eq!(
        status, SL_E_CONFIG,
        "delay {delay} base {base} active {active} negated {negated}"
    );
    assert_eq!(st(&f), (SL_STATE_STOP, 0));
    f
}

/// C6, T1, T2, T4: delays above 60,000 steps (and above 60,000 s), not a whole number of
/// steps, zero; unknown timebases; input masks.
#[test]
fn config_errors() {
    for (base, max) in common::timer::BASE_LIMITS {
        init_status(max + u32::from(base), base, 1, 0);
        init_status(max + 1, base, 1, 0);
    }
    init_status(60_000_001, 0, 1, 0);
    init_status(60_001_000, 0, 1, 0);
    init_status(u32::MAX, 0, 1, 0);
    // Not a whole number of timebase steps.
    init_status(1005, 10, 1, 0);
    init_status(150, 100, 1, 0);
    init_status(2500, 1000, 1, 0);
    init_status(60_001, 0, 1, 0); // automatic: timebase 10 ms
    init_status(600_050, 0, 1, 0); // automatic: timebase 100 ms
    init_status(6_000_500, 0, 1, 0); // automatic: timebase 1000 ms
    init_status(6_000_100, 0, 1, 0); // automatic: timebase 1000 ms
    init_status(5, 10, 1, 0); // below one step
    init_status(0, 0, 1, 0);
    init_status(0, 1, 1, 0);
    for base in [2u16, 5, 50, 500, 999, 1001, 2000, 10_000, u16::MAX] {
        init_status(1000, base, 1, 0);
    }
    init_status(100, 0, 0, 0);
    init_status(100, 0, 0b11, 0);
    init_status(100, 0, 0b10, 0);
    init_status(100, 0, 1, 0b10);
    init_status(100, 0, 1, 0x8001);

    // An invalid configuration stays in STOP and every call says so, also with bRun TRUE.
    let mut f = init_status(1005, 10, 1, 0);
    f.bRun = 1;
    for t in 0..5 {
        assert_eq!(f.cycle(t), SL_E_CONFIG);
        assert_eq!(st(&f), (SL_STATE_STOP, 0));
    }
    // Fixing it (in STOP) takes effect at the next STOP → run.
    f.tDelay = 1000;
    assert_eq!(f.cycle(10), SL_OK);
    assert_eq!(f.nState, SL_STATE_SAFE);
    // Valid multiples are accepted.
    for (d, b) in [
        (1010, 10),
        (600_000, 0),
        (60_010, 0),
        (6_001_000, 0),
        (7_000, 1000),
    ] {
        let mut g = FB_TON {
            tDelay: d,
            nTimeBase: b,
            wInputActive: 1,
            ..Default::default()
        };
        assert_eq!(g.init(), SL_OK, "{d} {b}");
    }
}

/// ABI §4: tNow wraps at 2^32; the delay keeps its length across the wrap.
#[test]
fn time_wraps_across_2_pow_32() {
    for t0 in [u32::MAX - 50, u32::MAX, u32::MAX - 99, u32::MAX - 100] {
        let mut f = running(100, 0, t0.wrapping_sub(1));
        f.bTonIn1 = 1;
        f.cycle(t0);
        assert_eq!(f.nState, DELAYIN);
        assert_eq!(f.cycle(t0.wrapping_add(99)), SL_OK);
        assert_eq!(st(&f), (DELAYIN, 0));
        assert_eq!(f.cycle(t0.wrapping_add(100)), SL_OK);
        assert_eq!(st(&f), (SL_STATE_RUN, 1));
    }
}

/// ABI §5 SL_E_CLOCK, C4: the clock going backwards in DELAYIN or RUN → ERROR, output
/// FALSE, diag bit 14; one ErrAck sequence leaves it; SAFE again, a fresh delay.
#[test]
fn clock_backwards() {
    for in_run in [false, true] {
        let mut f = running(100, 0, 1000);
        f.bTonIn1 = 1;
        f.cycle(1001);
        if in_run {
            f.cycle(1101);
            assert_eq!(st(&f), (SL_STATE_RUN, 1));
        }
        assert_eq!(f.cycle(900), SL_E_CLOCK);
        assert_eq!(st(&f), (SL_STATE_ERROR, 0));
        assert_eq!(f.nDiag, SL_DIAG_CLOCK);
        assert_eq!(f.cycle(901), SL_OK);
        assert_eq!(st(&f), (SL_STATE_ERROR, 0));
        f.bErrAck = 1;
        f.cycle(902);
        assert_eq!((st(&f), f.nDiag), ((SL_STATE_RESET, 0), 0));
        f.bErrAck = 0;
        f.cycle(903);
        assert_eq!(st(&f), (SL_STATE_SAFE, 0));
        f.cycle(904);
        assert_eq!(st(&f), (DELAYIN, 0));
        f.cycle(1003);
        assert_eq!(st(&f), (DELAYIN, 0));
        f.cycle(1004);
        assert_eq!(st(&f), (SL_STATE_RUN, 1));
    }
    // Also in STOP (C4), and 2^31 exactly is backwards.
    let mut f = ton(100, 0);
    f.cycle(0x8000_0000);
    assert_eq!(f.cycle(0), SL_E_CLOCK);
    assert_eq!(f.nState, SL_STATE_ERROR);
}

/// C5: a parameter changed while running → ERROR with diag bit 13; in STOP it is adopted
/// at the next STOP → run.
#[test]
fn parameter_change_while_running() {
    type Change = fn(&mut FB_TON);
    let changes: [Change; 4] = [
        |f| f.tDelay = 200,
        |f| f.nTimeBase = 10,
        |f| f.wInputNegated = 1,
        |f| f.wInputActive = 3,
    ];
    for change in changes {
        let mut f = running(100, 0, 0);
        f.bTonIn1 = 1;
        f.cycle(1);
        let saved = f;
        change(&mut f);
        assert_eq!(f.cycle(2), SL_E_PARAM_CHANGED);
        assert_eq!(st(&f), (SL_STATE_ERROR, 0));
        assert_eq!(f.nDiag, SL_DIAG_PARAM_CHANGED);
        // The condition remains while bRun is TRUE: no acknowledgement.
        f.bErrAck = 1;
        assert_eq!(f.cycle(3), SL_E_PARAM_CHANGED);
        f.bErrAck = 0;
        f.cycle(4);
        assert_eq!(f.nState, SL_STATE_ERROR);
        // Restoring the old value clears it.
        f.tDelay = saved.tDelay;
        f.nTimeBase = saved.nTimeBase;
        f.wInputNegated = saved.wInputNegated;
        f.wInputActive = saved.wInputActive;
        f.bErrAck = 1;
        assert_eq!(f.cycle(5), SL_OK);
        assert_eq!(f.nState, SL_STATE_RESET);
    }
    // In STOP the change is latched at the next start.
    let mut f = running(100, 0, 0);
    f.bRun = 0;
    f.cycle(1);
    f.tDelay = 30;
    assert_eq!(f.cycle(2), SL_OK);
    f.bRun = 1;
    f.bTonIn1 = 1;
    f.cycle(3);
    f.cycle(4);
    f.cycle(33);
    assert_eq!(st(&f), (DELAYIN, 0));
    f.cycle(34);
    assert_eq!(st(&f), (SL_STATE_RUN, 1), "the new 30 ms delay");
}

/// C3, T9: the timer start, the state and the latched delay are checked; a corrupted
/// instance goes to ERROR (diag bit 15) and can be acknowledged.
#[test]
fn corruption_is_detected() {
    type Corrupt = fn(&mut FB_TON);
    let corruptions: [Corrupt; 5] = [
        |f| f.stPrivate.tPhaseCheck ^= 4,
        |f| f.stPrivate.stHeader.tPhase = f.stPrivate.stHeader.tPhase.wrapping_sub(1000),
        |f| f.stPrivate.stHeader.nState = SL_STATE_RUN,
        |f| f.stPrivate.dwDelay = 1,
        |f| f.stPrivate.stHeader.wMagic ^= 1,
    ];
    for corrupt in corruptions {
        let mut f = running(100, 0, 0);
        f.bTonIn1 = 1;
        f.cycle(1);
        assert_eq!(f.nState, DELAYIN);
        corrupt(&mut f);
        assert_eq!(f.cycle(2), SL_E_CORRUPT);
        assert_eq!(st(&f), (SL_STATE_ERROR, 0));
        assert_ne!(f.nDiag & SL_DIAG_CORRUPT, 0);
        f.bErrAck = 1;
        f.cycle(3);
        assert_eq!(f.nState, SL_STATE_RESET);
        f.bErrAck = 0;
        f.cycle(4);
        f.cycle(5);
        assert_eq!(f.nState, DELAYIN);
        f.cycle(105);
        assert_eq!(st(&f), (SL_STATE_RUN, 1), "repaired: a full delay again");
    }
    // A corrupted parameter CRC is found before the output switches on.
    let mut f = running(100, 0, 0);
    f.bTonIn1 = 1;
    f.cycle(1);
    f.stPrivate.stHeader.wParamCrc ^= 1;
    assert_eq!(f.cycle(50), SL_OK);
    assert_eq!(f.cycle(101), SL_E_CORRUPT);
    assert_eq!(st(&f), (SL_STATE_ERROR, 0));
}

/// C3: every bit of the latched copy (kept full width in the order of the live fields,
/// with the reserved word and the options between them) is checked: a flipped bit is
/// SL_E_CORRUPT, not a parameter change, whether the block is timing (DELAYIN) or steady in
/// RUN (the call the fast path would serve).
#[test]
fn every_bit_of_the_latched_copy_is_checked() {
    type Flip = fn(&mut SL_TIMER_PRIVATE, u32);
    let fields: [(&str, u32, Flip); 6] = [
        ("dwDelay", 32, |p, b| p.dwDelay ^= 1 << b),
        ("wTimeBase", 16, |p, b| p.wTimeBase ^= 1 << b),
        ("wInputActive", 16, |p, b| p.wInputActive ^= 1 << b),
        ("wInputNegated", 16, |p, b| p.wInputNegated ^= 1 << b),
        ("wReserved", 16, |p, b| p.wReserved ^= 1 << b),
        ("dwOptions", 32, |p, b| p.dwOptions ^= 1 << b),
    ];
    for (name, bits, flip) in fields {
        for bit in 0..bits {
            for steady in [false, true] {
                let mut f = running(100, 0, 0);
                f.bTonIn1 = 1;
                f.cycle(1);
                if steady {
                    f.cycle(101);
                    f.cycle(102);
                    assert_eq!(st(&f), (SL_STATE_RUN, 1));
                }
                flip(&mut f.stPrivate, bit);
                assert_eq!(
                    f.cycle(103),
                    SL_E_CORRUPT,
                    "{name} bit {bit}, steady {steady}"
                );
                assert_eq!(st(&f), (SL_STATE_ERROR, 0));
                assert_ne!(f.nDiag & SL_DIAG_CORRUPT, 0);
            }
        }
    }
}

/// C2: a never-initialised (zeroed) instance is initialised by its first cycle.
#[test]
fn zeroed_instance_initialises_itself() {
    let mut f = FB_TON {
        tDelay: 20,
        wInputActive: 1,
        bRun: 1,
        bTonIn1: 1,
        ..Default::default()
    };
    assert_eq!(f.cycle(0), SL_OK);
    assert_eq!(f.nState, SL_STATE_SAFE);
    f.cycle(1);
    f.cycle(21);
    assert_eq!(st(&f), (SL_STATE_RUN, 1));
}

#[test]
fn c_functions_registry_and_member() {
    let mut f = FB_TON {
        tDelay: 10,
        wInputActive: 1,
        ..Default::default()
    };
    assert_eq!(unsafe { ffi::sl_ton_init(&mut f) }, SL_OK);
    null_refused!(ffi::sl_ton_init, ffi::sl_ton_cycle);
    f.bRun = 1;
    f.bTonIn1 = 1;
    assert_eq!(unsafe { ffi::sl_ton_cycle(&mut f, 0) }, SL_OK);
    assert_eq!(unsafe { ffi::sl_ton_cycle(&mut f, 1) }, SL_OK);
    assert_eq!(unsafe { ffi::sl_ton_cycle(&mut f, 11) }, SL_OK);
    assert_eq!(st(&f), (SL_STATE_RUN, 1));
    for (s, n) in [
        (9, "DELAYIN"),
        (1, "RUN"),
        (3, "SAFE"),
        (4, "ERROR"),
        (8, "?"),
    ] {
        assert_eq!(common::state_str(SL_TYPE_TON, s), n, "state {s}");
    }
    // Member view: the linkable input and output.
    let m: &mut dyn Member = &mut f;
    assert!(m.input_mut(offset_of!(FB_TON, bTonIn1) as u16).is_some());
    assert!(m.input_mut(offset_of!(FB_TON, bRun) as u16).is_none());
    assert_eq!(m.output(offset_of!(FB_TON, bTonOut) as u16), Some(1));
    assert_eq!(SL_TYPE_TON, 13);
}

/// Groups: a TON added by type tag through the C ABI, fed by a link from an AND.
#[test]
fn ton_in_a_group() {
    let mut a = common::ready(FB_AND {
        wInputActive: 0b11,
        bAndIn1: 1,
        bAndIn2: 1,
        ..Default::default()
    });
    let mut f = ton(50, 0);
    let mut g = SL_GROUP::default();
    let mut members = [SL_MEMBER::default(); 2];
    let mut links = [SL_LINK::default(); 1];
    common::c_group_init(&mut g, (members.as_mut_ptr(), 2), (links.as_mut_ptr(), 1));
    for (ty, p) in [
        (SL_TYPE_AND, std::ptr::addr_of_mut!(a).cast()),
        (SL_TYPE_TON, std::ptr::addr_of_mut!(f).cast()),
    ] {
        common::c_add_member(&mut g, members.as_mut_ptr(), ty, p, std::ptr::null_mut());
    }
    let (src, dst) = (offset_of!(FB_AND, bAndOut), offset_of!(FB_TON, bTonIn1));
    common::c_add_link(&mut g, &mut members, &mut links, (0, src), (1, dst));
    g.bRun = 1;
    let mut cyc =
        |t| unsafe { ffi::sl_group_cycle(&mut g, members.as_mut_ptr(), links.as_mut_ptr(), t) };
    for t in [0, 1, 2, 51] {
        assert_eq!(cyc(t), SL_OK);
    }
    assert_eq!(cyc(52), SL_OK);
    assert_eq!((f.nState, f.bTonOut), (SL_STATE_RUN, 1));
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_TON_DELAYIN, SL_STATE_SAFE, SL_STATE_STOP];
    /// No output TRUE in STOP/ERROR/RESET; TonOut TRUE only in RUN and only after the input
    /// has been logically TRUE (with bRun TRUE) in every call for at least tDelay.
    fn output_only_after_the_input_was_true_for_the_delay(
        delay in 1u32..200,
        negated in 0u16..2,
        t0 in any::<u32>(),
        steps in proptest::collection::vec((0u32..120, 0u8..4, 0u8..8, 0u8..4), 1..200)
    ) {
        let mut f = FB_TON { tDelay: delay, wInputActive: 1, wInputNegated: negated, ..Default::default() };
        prop_assert_eq!(f.init(), SL_OK);
        let mut t = t0;
        let mut streak: Option<u32> = None;
        for (dt, input, run, ack) in steps {
            t = t.wrapping_add(dt);
            // 0/1 valid, 2/3 invalid bytes.
            f.bTonIn1 = match input { 0 => 0, 1 => 1, 2 => 2, _ => 0xFF };
            f.bRun = u8::from(run != 0);
            f.bErrAck = u8::from(ack == 0);
            let status = f.cycle(t);
            common::saw(f.nState);
            prop_assert!(status == SL_OK || status == SL_E_INVALID_BOOL, "status {}", status);
            let logical = f.bTonIn1 <= 1 && (f.bTonIn1 == 1) != (negated == 1);
            if logical && f.bRun == 1 {
                streak.get_or_insert(t);
            } else {
                streak = None;
            }
            if matches!(f.nState, SL_STATE_STOP | SL_STATE_ERROR | SL_STATE_RESET) {
                prop_assert_eq!(f.bTonOut, 0);
            }
            if f.bTonOut == 1 {
                prop_assert_eq!(f.nState, SL_STATE_RUN);
                let s = streak.expect("output TRUE without the input TRUE");
                prop_assert!(t.wrapping_sub(s) >= delay, "on after {} < {}", t.wrapping_sub(s), delay);
            }
            prop_assert!(f.nState != SL_STATE_ERROR, "no error source in this sequence");
        }
    }
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_TON_DELAYIN];
    /// Liveness: with the input held TRUE and bRun TRUE, the output comes on at the first
    /// call at least tDelay after the timer started (the call after start-up).
    fn output_on_exactly_when_the_delay_is_reached(
        delay in 1u32..5000,
        t0 in any::<u32>(),
        dts in proptest::collection::vec(1u32..700, 1..60)
    ) {
        let mut f = running(delay, 0, t0);
        f.bTonIn1 = 1;
        let mut t = t0.wrapping_add(1);
        f.cycle(t);
        common::saw(f.nState);
        let start = t;
        for dt in dts {
            t = t.wrapping_add(dt);
            f.cycle(t);
            common::saw(f.nState);
            let due = t.wrapping_sub(start) >= delay;
            prop_assert_eq!(f.bTonOut, u8::from(due));
            prop_assert_eq!(f.nState, if due { SL_STATE_RUN } else { DELAYIN });
        }
    }
}
