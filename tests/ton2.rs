//! FB TON2 (manual §4.13; docs/semantics.md rows T10–T17): TON behaviour, Enable and
//! "Starts with remaining time", the stored elapsed time, its persistence by the host across
//! a simulated power cycle through the C API, the global-shutdown case (SL_E_RESTORE, diag
//! bit 12), restore sequencing and the integrity checks of the stored value.

mod common;
use common::{aligned_tail, null_refused, offsets};

use proptest::prelude::*;
use safelogic::base::member::Member;
use safelogic::ffi;
use safelogic::*;
use std::ffi::CStr;
use std::mem::offset_of;

const DELAYIN: u8 = SL_STATE_TON2_DELAYIN;
const REMAINING: u32 = SL_OPT_TON2_REMAINING_TIME;

fn params(delay: u32, options: u32) -> FB_TON2 {
    FB_TON2 {
        tDelay: delay,
        wInputActive: 1,
        dwOptions: options,
        ..Default::default()
    }
}

fn ton2(delay: u32, options: u32) -> FB_TON2 {
    let mut f = params(delay, options);
    assert_eq!(unsafe { ffi::sl_ton2_init(&mut f) }, SL_OK);
    f
}

fn st(f: &FB_TON2) -> (u8, u8) {
    (f.nState, f.bTonOut)
}

/// The stored elapsed time through the C API.
fn elapsed(f: &FB_TON2) -> u32 {
    let mut e = 0xDEAD_BEEF;
    assert_eq!(unsafe { ffi::sl_ton2_get_elapsed(f, &mut e) }, SL_OK);
    e
}

fn cyc(f: &mut FB_TON2, t: u32) -> i32 {
    unsafe { ffi::sl_ton2_cycle(f, t) }
}

/// Runs a step table of C calls: (time, expected (state, output), note) rows; the status is
/// not checked (the rows' callers check it where it matters). A failure names the row, its
/// time and its note.
#[track_caller]
fn calls(f: &mut FB_TON2, rows: &[(u32, (u8, u8), &str)]) {
    for (k, &(t, want, note)) in rows.iter().enumerate() {
        cyc(f, t);
        assert_eq!(st(f), want, "row {k} (t {t}): {note}");
    }
}

#[test]
fn layout_matches_the_abi() {
    offsets!(FB_TON2; bTonIn1 => 8, bEnable => 9, bRun => 16, bErrAck => 17);
    assert_eq!(offset_of!(FB_TON2, bTonOut) % 8, 1, "output base + 1");
    aligned_tail!(FB_TON2);
    assert_eq!(SL_OPT_TON2_REMAINING_TIME, 1 << 8);
    assert_eq!((SL_TYPE_TON2, SL_E_RESTORE), (14, -10));
    assert_eq!(SL_DIAG_TON2_RESTORE, 1 << 12);
}

/// Without the option TON2 is a TON: Enable is not read (an invalid Enable byte is not
/// even reported), a restored value is never used.
#[test]
fn without_the_option_it_is_a_ton() {
    let mut f = ton2(100, 0);
    assert_eq!(unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 60) }, SL_OK);
    f.bRun = 1;
    f.bEnable = 7;
    assert_eq!(cyc(&mut f, 0), SL_OK);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0));
    f.bTonIn1 = 1;
    assert_eq!(cyc(&mut f, 1), SL_OK);
    assert_eq!(st(&f), (DELAYIN, 0));
    cyc(&mut f, 100);
    assert_eq!(
        st(&f),
        (DELAYIN, 0),
        "full delay: the stored 60 ms are not used"
    );
    cyc(&mut f, 101);
    assert_eq!(st(&f), (SL_STATE_RUN, 1));
    f.bTonIn1 = 0;
    cyc(&mut f, 102);
    assert_eq!(st(&f), (SL_STATE_SAFE, 0));
}

/// T11: what the stored elapsed time holds in every state.
#[test]
fn stored_elapsed_time_in_every_state() {
    let mut f = ton2(1000, REMAINING);
    assert_eq!(elapsed(&f), 0, "power-up");
    f.bRun = 1;
    cyc(&mut f, 0);
    assert_eq!((f.nState, elapsed(&f)), (SL_STATE_SAFE, 0));
    f.bTonIn1 = 1;
    cyc(&mut f, 10);
    assert_eq!((f.nState, elapsed(&f)), (DELAYIN, 0), "timer starts at 10");
    cyc(&mut f, 410);
    assert_eq!((f.nState, elapsed(&f)), (DELAYIN, 400));
    cyc(&mut f, 1009);
    assert_eq!((f.nState, elapsed(&f)), (DELAYIN, 999));
    cyc(&mut f, 1010);
    assert_eq!(
        (st(&f), elapsed(&f)),
        ((SL_STATE_RUN, 1), 1000),
        "expired: tDelay"
    );
    cyc(&mut f, 99_999);
    assert_eq!(elapsed(&f), 1000);
    // The input falling discards the time.
    f.bTonIn1 = 0;
    cyc(&mut f, 100_000);
    assert_eq!((st(&f), elapsed(&f)), ((SL_STATE_SAFE, 0), 0));
    f.bTonIn1 = 1;
    cyc(&mut f, 100_001);
    cyc(&mut f, 100_301);
    assert_eq!(elapsed(&f), 300);
    f.bTonIn1 = 0;
    cyc(&mut f, 100_302);
    assert_eq!(elapsed(&f), 0, "aborted in DELAYIN");
    // STOP keeps it (T11): a group stop is a power cycle for the block.
    f.bTonIn1 = 1;
    cyc(&mut f, 100_303);
    cyc(&mut f, 100_503);
    f.bRun = 0;
    cyc(&mut f, 100_600);
    assert_eq!((st(&f), elapsed(&f)), ((SL_STATE_STOP, 0), 200));
    // ERROR keeps it as well.
    f.bRun = 1;
    f.bEnable = 1;
    cyc(&mut f, 100_601);
    cyc(&mut f, 100_602);
    assert_eq!((f.nState, elapsed(&f)), (DELAYIN, 200), "continued");
    cyc(&mut f, 100_652);
    assert_eq!(elapsed(&f), 250);
    assert_eq!(cyc(&mut f, 100_000), SL_E_CLOCK);
    assert_eq!((st(&f), elapsed(&f)), ((SL_STATE_ERROR, 0), 250));
}

/// T12: with the option, Enable TRUE when TonIn rises starts the delay with the remaining
/// time; Enable FALSE starts it with tDelay; Enable is read only at the rising edge.
#[test]
fn enable_selects_the_remaining_time_at_the_rising_edge() {
    for enable in [0u8, 1] {
        let mut f = ton2(1000, REMAINING);
        assert_eq!(unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 400) }, SL_OK);
        assert_eq!(elapsed(&f), 400);
        f.bRun = 1;
        f.bEnable = enable;
        cyc(&mut f, 0);
        f.bTonIn1 = 1;
        cyc(&mut f, 5);
        assert_eq!(st(&f), (DELAYIN, 0));
        assert_eq!(elapsed(&f), if enable == 1 { 400 } else { 0 });
        // Enable changing while the timer runs changes nothing.
        f.bEnable = 1 - enable;
        let due = if enable == 1 { 5 + 600 } else { 5 + 1000 };
        cyc(&mut f, due - 1);
        assert_eq!(st(&f), (DELAYIN, 0), "enable {enable}");
        cyc(&mut f, due);
        assert_eq!(st(&f), (SL_STATE_RUN, 1), "enable {enable}");
    }
}

/// The power cycle: 35 s into a 120 s delay the power fails; the host persisted
/// the elapsed time, restores it after power-up, and TonOut comes on after the remaining
/// 85 s (the manual's timing diagram, Fig. 83). All through the C API.
#[test]
fn persist_and_restore_across_a_power_cycle() {
    let mut nvram: u32 = 0;
    let mut f = ton2(120_000, REMAINING);
    f.bRun = 1;
    f.bEnable = 1;
    assert_eq!(cyc(&mut f, 1_000), SL_OK);
    f.bTonIn1 = 1;
    let mut t = 1_000;
    while t <= 36_000 {
        t += 100;
        assert_eq!(cyc(&mut f, t), SL_OK);
        // The host persists the value after every cycle.
        assert_eq!(unsafe { ffi::sl_ton2_get_elapsed(&f, &mut nvram) }, SL_OK);
    }
    assert_eq!(f.nState, DELAYIN);
    assert_eq!(nvram, 35_000);

    // Power cycle: the RAM is gone (a fresh, zeroed instance); the clock restarts anywhere.
    f = params(120_000, REMAINING);
    assert_eq!(unsafe { ffi::sl_ton2_init(&mut f) }, SL_OK);
    assert_eq!(
        unsafe { ffi::sl_ton2_restore_elapsed(&mut f, nvram) },
        SL_OK
    );
    let persist = |f: &FB_TON2, nvram: &mut u32| {
        assert_eq!(unsafe { ffi::sl_ton2_get_elapsed(f, nvram) }, SL_OK);
    };
    persist(&f, &mut nvram);
    assert_eq!(
        nvram, 35_000,
        "persisting right after the restore keeps the value"
    );
    // The logic starts; the connections deliver TonIn FALSE for a while (T11: the stored
    // value survives SAFE with the input FALSE).
    let t0 = u32::MAX - 20_000;
    f.bRun = 1;
    f.bEnable = 1;
    let mut t = t0;
    for _ in 0..50 {
        assert_eq!(cyc(&mut f, t), SL_OK);
        persist(&f, &mut nvram);
        t = t.wrapping_add(100);
    }
    assert_eq!((st(&f), nvram), ((SL_STATE_SAFE, 0), 35_000));
    f.bTonIn1 = 1;
    assert_eq!(cyc(&mut f, t), SL_OK);
    let start = t;
    assert_eq!(f.nState, DELAYIN);
    // 85 s remain, across the 2^32 wrap of tNow.
    cyc(&mut f, start.wrapping_add(84_999));
    persist(&f, &mut nvram);
    assert_eq!((st(&f), nvram), ((DELAYIN, 0), 119_999));
    cyc(&mut f, start.wrapping_add(85_000));
    persist(&f, &mut nvram);
    assert_eq!((st(&f), nvram), ((SL_STATE_RUN, 1), 120_000));
}

/// T12: a timer that had expired before the power cycle (stored = tDelay) continues with
/// remaining time 0: DELAYIN for one call, then RUN.
#[test]
fn restored_full_delay_means_no_remaining_time() {
    let mut f = ton2(5_000, REMAINING);
    assert_eq!(
        unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 5_000) },
        SL_OK
    );
    f.bRun = 1;
    f.bEnable = 1;
    f.bTonIn1 = 1;
    calls(
        &mut f,
        &[
            (0, (SL_STATE_SAFE, 0), ""),
            (1, (DELAYIN, 0), ""),
            (2, (SL_STATE_RUN, 1), ""),
        ],
    );
}

/// T13: a restored value greater than tDelay is the manual's global shutdown (0x3510): the
/// restore call puts the block into ERROR with diag bit 12 and returns SL_E_RESTORE; the
/// value is discarded, one ErrAck sequence leaves the error, the next delay is a full one.
#[test]
fn restored_value_above_the_delay_is_refused() {
    let mut f = ton2(1_000, REMAINING);
    assert_eq!(
        unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 1_001) },
        SL_E_RESTORE
    );
    assert_eq!(st(&f), (SL_STATE_ERROR, 0));
    assert_eq!(f.nDiag, SL_DIAG_TON2_RESTORE);
    assert_eq!(elapsed(&f), 0, "discarded");
    let text = unsafe { CStr::from_ptr(ffi::sl_status_str(SL_E_RESTORE)) };
    assert!(text.to_str().unwrap().starts_with("SL_E_RESTORE"));
    let diag = common::diag_text(SL_TYPE_TON2, f.nDiag);
    assert!(diag.contains("0x3510"), "{diag}");
    // ERROR also with bRun FALSE; acknowledged, then STOP → run as usual.
    f.bRun = 1;
    f.bEnable = 1;
    f.bTonIn1 = 1;
    assert_eq!(cyc(&mut f, 0), SL_OK);
    assert_eq!(st(&f), (SL_STATE_ERROR, 0));
    f.bErrAck = 1;
    cyc(&mut f, 1);
    assert_eq!((f.nState, f.nDiag), (SL_STATE_RESET, 0));
    f.bErrAck = 0;
    cyc(&mut f, 2);
    assert_eq!(f.nState, SL_STATE_SAFE);
    cyc(&mut f, 3);
    assert_eq!(f.nState, DELAYIN);
    calls(
        &mut f,
        &[
            (1_002, (DELAYIN, 0), "full delay"),
            (1_003, (SL_STATE_RUN, 1), ""),
        ],
    );
}

/// T13: the manual's check at the rising edge: a stored value accepted against the delay
/// latched at init, then a shorter tDelay latched at STOP → run: TonIn rising with Enable
/// TRUE → ERROR, SL_E_RESTORE from the cycle. With Enable FALSE there is no error.
#[test]
fn stored_value_above_a_newly_latched_delay_is_the_global_shutdown_case() {
    for enable in [1u8, 0] {
        let mut f = ton2(120_000, REMAINING);
        assert_eq!(
            unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 50_000) },
            SL_OK
        );
        f.tDelay = 30_000; // changed in STOP: latched at STOP → run
        f.bRun = 1;
        f.bEnable = enable;
        assert_eq!(cyc(&mut f, 0), SL_OK);
        assert_eq!(f.nState, SL_STATE_SAFE);
        assert_eq!(cyc(&mut f, 1), SL_OK, "TonIn FALSE: the value is not used");
        f.bTonIn1 = 1;
        if enable == 1 {
            assert_eq!(cyc(&mut f, 2), SL_E_RESTORE);
            assert_eq!(st(&f), (SL_STATE_ERROR, 0));
            assert_eq!(f.nDiag, SL_DIAG_TON2_RESTORE);
            assert_eq!(elapsed(&f), 0);
            f.bErrAck = 1;
            cyc(&mut f, 3);
            f.bErrAck = 0;
            cyc(&mut f, 4);
            assert_eq!(f.nState, SL_STATE_SAFE);
            assert_eq!(
                cyc(&mut f, 5),
                SL_OK,
                "the discarded value cannot fail again"
            );
            assert_eq!(f.nState, DELAYIN);
        } else {
            assert_eq!(cyc(&mut f, 2), SL_OK);
            assert_eq!((f.nState, elapsed(&f)), (DELAYIN, 0));
            cyc(&mut f, 30_002);
            assert_eq!(st(&f), (SL_STATE_RUN, 1));
        }
    }
}

/// T14: the restore is for power-up: outside STOP it is refused with SL_E_RESTORE and the
/// block enters ERROR (a host sequencing error; the safe direction).
#[test]
fn restore_outside_stop_is_refused() {
    for target in [
        SL_STATE_SAFE,
        DELAYIN,
        SL_STATE_RUN,
        SL_STATE_ERROR,
        SL_STATE_RESET,
    ] {
        let mut f = ton2(100, REMAINING);
        f.bRun = 1;
        cyc(&mut f, 0);
        f.bTonIn1 = 1;
        match target {
            SL_STATE_SAFE => f.bTonIn1 = 0,
            DELAYIN => {
                cyc(&mut f, 1);
            }
            SL_STATE_RUN => {
                cyc(&mut f, 1);
                cyc(&mut f, 101);
            }
            _ => {
                cyc(&mut f, 1);
                assert_eq!(cyc(&mut f, 0), SL_E_CLOCK);
                if target == SL_STATE_RESET {
                    f.bErrAck = 1;
                    cyc(&mut f, 2);
                }
            }
        }
        assert_eq!(f.nState, target);
        assert_eq!(
            unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 10) },
            SL_E_RESTORE
        );
        assert_eq!(st(&f), (SL_STATE_ERROR, 0));
        assert_ne!(f.nDiag & SL_DIAG_TON2_RESTORE, 0);
        assert_eq!(elapsed(&f), 0);
    }
    // In STOP after a run (a stopped group) it is allowed.
    let mut f = ton2(100, REMAINING);
    f.bRun = 1;
    cyc(&mut f, 0);
    f.bRun = 0;
    cyc(&mut f, 1);
    assert_eq!(unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 100) }, SL_OK);
    assert_eq!(
        unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 0) },
        SL_OK,
        "repeatable"
    );
    assert_eq!(f.nState, SL_STATE_STOP);
}

/// T14: invalid latched parameters → SL_E_CONFIG, nothing stored; a never-initialised
/// instance is initialised first; NULL pointers.
#[test]
fn restore_preconditions() {
    let mut f = params(0, REMAINING);
    assert_eq!(unsafe { ffi::sl_ton2_init(&mut f) }, SL_E_CONFIG);
    assert_eq!(
        unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 0) },
        SL_E_CONFIG
    );
    assert_eq!((f.nState, elapsed(&f)), (SL_STATE_STOP, 0));
    // Never initialised, valid parameters: initialised and stored.
    let mut f = params(500, REMAINING);
    assert_eq!(elapsed(&f), 0, "never initialised: 0");
    assert_eq!(unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 200) }, SL_OK);
    assert_eq!((f.nState, elapsed(&f)), (SL_STATE_STOP, 200));
    // Never initialised, invalid parameters.
    let mut f = params(500, 1 << 9);
    assert_eq!(
        unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 200) },
        SL_E_CONFIG
    );
    assert_eq!(f.nState, SL_STATE_STOP);
    // Pointers.
    let mut e = 0u32;
    assert_eq!(
        unsafe { ffi::sl_ton2_restore_elapsed(std::ptr::null_mut(), 1) },
        SL_E_NULL
    );
    assert_eq!(
        unsafe { ffi::sl_ton2_get_elapsed(std::ptr::null(), &mut e) },
        SL_E_NULL
    );
    assert_eq!(
        unsafe { ffi::sl_ton2_get_elapsed(&f, std::ptr::null_mut()) },
        SL_E_NULL
    );
    let words = [0u32; 2];
    let misaligned = (words.as_ptr() as *mut u8).wrapping_add(1).cast::<u32>();
    assert_eq!(
        unsafe { ffi::sl_ton2_get_elapsed(&f, misaligned) },
        SL_E_ALIGNMENT
    );
}

/// T15: the stored value is protected by its complement: a corrupted value is never
/// handed to the host, never used, and puts the block into ERROR (diag bit 15).
#[test]
fn corrupted_stored_value_is_detected() {
    // get: SL_E_CORRUPT, nothing written.
    let mut f = ton2(1000, REMAINING);
    assert_eq!(unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 300) }, SL_OK);
    f.stPrivate.tElapsed = 900;
    let mut e = 7u32;
    assert_eq!(
        unsafe { ffi::sl_ton2_get_elapsed(&f, &mut e) },
        SL_E_CORRUPT
    );
    assert_eq!(e, 7);
    // restore: SL_E_CORRUPT, ERROR, the value repaired to 0.
    assert_eq!(
        unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 100) },
        SL_E_CORRUPT
    );
    assert_eq!(st(&f), (SL_STATE_ERROR, 0));
    assert_eq!(f.nDiag, SL_DIAG_CORRUPT);
    assert_eq!(elapsed(&f), 0);
    // cycle: SL_E_CORRUPT before the value is used.
    let mut f = ton2(1000, REMAINING);
    assert_eq!(unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 300) }, SL_OK);
    f.stPrivate.tElapsedCheck ^= 1 << 20;
    f.bRun = 1;
    f.bEnable = 1;
    f.bTonIn1 = 1;
    assert_eq!(cyc(&mut f, 0), SL_OK, "STOP → SAFE does not use it");
    assert_eq!(cyc(&mut f, 1), SL_E_CORRUPT);
    assert_eq!(st(&f), (SL_STATE_ERROR, 0));
    assert_eq!(elapsed(&f), 0);
    f.bErrAck = 1;
    cyc(&mut f, 2);
    f.bErrAck = 0;
    cyc(&mut f, 3);
    cyc(&mut f, 4);
    assert_eq!(
        (f.nState, elapsed(&f)),
        (DELAYIN, 0),
        "full delay after the repair"
    );
    // A corrupted head: get refuses, cycle → ERROR.
    let mut f = ton2(1000, REMAINING);
    f.stPrivate.stHeader.wMagic ^= 0x100;
    assert_eq!(
        unsafe { ffi::sl_ton2_get_elapsed(&f, &mut e) },
        SL_E_CORRUPT
    );
    assert_eq!(
        unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 1) },
        SL_E_CORRUPT
    );
    assert_eq!(f.nState, SL_STATE_ERROR);
    // A corrupted latched delay: restore refuses (CRC).
    let mut f = ton2(1000, REMAINING);
    f.stPrivate.dwDelay = 5000;
    assert_eq!(
        unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 4000) },
        SL_E_CORRUPT
    );
    assert_eq!(f.nState, SL_STATE_ERROR);
}

/// T10: Enable is read only with the option; an invalid Enable byte reads FALSE (full
/// delay) and is reported; Enable is not part of the input masks.
#[test]
fn enable_byte_and_masks() {
    let mut f = ton2(100, REMAINING);
    assert_eq!(unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 90) }, SL_OK);
    f.bRun = 1;
    f.bEnable = 2;
    assert_eq!(cyc(&mut f, 0), SL_E_INVALID_BOOL);
    f.bTonIn1 = 1;
    assert_eq!(cyc(&mut f, 1), SL_E_INVALID_BOOL);
    assert_eq!(
        (f.nState, elapsed(&f)),
        (DELAYIN, 0),
        "invalid Enable: full delay"
    );
    f.bEnable = 0;
    calls(
        &mut f,
        &[(100, (DELAYIN, 0), ""), (101, (SL_STATE_RUN, 1), "")],
    );
    for (active, negated, options) in [(0b11u16, 0u16, REMAINING), (1, 0b10, 0), (1, 0, 1)] {
        let mut f = FB_TON2 {
            tDelay: 100,
            wInputActive: active,
            wInputNegated: negated,
            dwOptions: options,
            ..Default::default()
        };
        assert_eq!(unsafe { ffi::sl_ton2_init(&mut f) }, SL_E_CONFIG);
    }
    // Negated TonIn1 with the remaining time.
    let mut f = FB_TON2 {
        tDelay: 100,
        wInputActive: 1,
        wInputNegated: 1,
        dwOptions: REMAINING,
        bTonIn1: 1,
        bEnable: 1,
        bRun: 1,
        ..Default::default()
    };
    assert_eq!(unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 40) }, SL_OK);
    cyc(&mut f, 0);
    cyc(&mut f, 1);
    assert_eq!(f.nState, SL_STATE_SAFE);
    f.bTonIn1 = 0;
    cyc(&mut f, 2);
    calls(
        &mut f,
        &[(61, (DELAYIN, 0), ""), (62, (SL_STATE_RUN, 1), "")],
    );
}

/// The timebases and limits of TON apply to TON2 (T1): 60,000 s with remaining time.
#[test]
fn time_bases_and_limits() {
    for (delay, base, ok) in [
        (60_000_000u32, 1000u16, true),
        (60_000_000, 0, true),
        (60_001_000, 1000, false),
        (60_000_001, 0, false),
        (1005, 10, false),
        (1000, 7, false),
        (0, 0, false),
    ] {
        let mut f = FB_TON2 {
            tDelay: delay,
            nTimeBase: base,
            wInputActive: 1,
            dwOptions: REMAINING,
            ..Default::default()
        };
        let expected = if ok { SL_OK } else { SL_E_CONFIG };
        assert_eq!(
            unsafe { ffi::sl_ton2_init(&mut f) },
            expected,
            "{delay} {base}"
        );
    }
    let mut f = ton2(SL_TIMER_DELAY_MAX, REMAINING);
    assert_eq!(
        unsafe { ffi::sl_ton2_restore_elapsed(&mut f, SL_TIMER_DELAY_MAX - 1) },
        SL_OK
    );
    f.bRun = 1;
    f.bEnable = 1;
    f.bTonIn1 = 1;
    cyc(&mut f, 0);
    calls(
        &mut f,
        &[
            (10, (DELAYIN, 0), ""),
            (11, (SL_STATE_RUN, 1), "1 ms remained"),
        ],
    );
}

/// Parameter change while running (C5) keeps the stored value; the group's view.
#[test]
fn parameter_change_registry_and_member() {
    let mut f = ton2(1000, REMAINING);
    f.bRun = 1;
    cyc(&mut f, 0);
    f.bTonIn1 = 1;
    cyc(&mut f, 1);
    cyc(&mut f, 301);
    f.dwOptions = 0;
    assert_eq!(cyc(&mut f, 302), SL_E_PARAM_CHANGED);
    assert_eq!(
        (st(&f), f.nDiag),
        ((SL_STATE_ERROR, 0), SL_DIAG_PARAM_CHANGED)
    );
    assert_eq!(elapsed(&f), 300);
    for (s, n) in [(9, "DELAYIN"), (2, "STOP")] {
        assert_eq!(common::state_str(SL_TYPE_TON2, s), n, "state {s}");
    }
    let m: &mut dyn Member = &mut f;
    assert!(m.input_mut(offset_of!(FB_TON2, bTonIn1) as u16).is_some());
    assert!(m.input_mut(offset_of!(FB_TON2, bEnable) as u16).is_some());
    assert_eq!(m.output(offset_of!(FB_TON2, bTonOut) as u16), Some(0));
    null_refused!(ffi::sl_ton2_init, ffi::sl_ton2_cycle);
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_TON2_DELAYIN, SL_STATE_SAFE, SL_STATE_STOP];
    /// No output TRUE in STOP/ERROR/RESET; TonOut TRUE only in RUN; the stored elapsed time
    /// never exceeds tDelay and equals it in RUN. Without the option, TonOut TRUE only after
    /// the input was TRUE in every call for tDelay. With it, the credit is bounded: TonOut
    /// TRUE only when the restored value R (until the first abort) plus the time the input
    /// was TRUE with bRun TRUE since the last abort reaches tDelay (an abort: the input not
    /// TRUE while the block times or runs).
    fn output_and_stored_value(
        delay in 1u32..200,
        option in any::<bool>(),
        restored_frac in 0u32..=100,
        t0 in any::<u32>(),
        steps in proptest::collection::vec((0u32..120, 0u8..4, 0u8..8, 0u8..4, 0u8..3), 1..200)
    ) {
        let mut f = params(delay, if option { REMAINING } else { 0 });
        prop_assert_eq!(unsafe { ffi::sl_ton2_init(&mut f) }, SL_OK);
        let restored = delay * restored_frac / 100;
        prop_assert_eq!(unsafe { ffi::sl_ton2_restore_elapsed(&mut f, restored) }, SL_OK);
        let mut t = t0;
        // Upper bound of the block's credit: R plus closed streaks since the last abort.
        let mut credit = u64::from(if option { restored } else { 0 });
        let mut streak: Option<(u32, u32)> = None; // (first call, last call)
        for (dt, input, run, ack, enable) in steps {
            let prev_state = f.nState;
            t = t.wrapping_add(dt);
            f.bTonIn1 = match input { 0 => 0, 1 => 1, 2 => 2, _ => 0xFF };
            f.bRun = u8::from(run != 0);
            f.bErrAck = u8::from(ack == 0);
            f.bEnable = enable;
            let status = cyc(&mut f, t);
            common::saw(f.nState);
            prop_assert!(status == SL_OK || status == SL_E_INVALID_BOOL, "status {}", status);
            if f.bTonIn1 == 1 && f.bRun == 1 {
                let s = streak.map_or(t, |(s, _)| s);
                streak = Some((s, t));
            } else {
                if let Some((s, last)) = streak.take() {
                    credit += u64::from(last.wrapping_sub(s));
                }
                if f.bRun == 1 && matches!(prev_state, SL_STATE_RUN | DELAYIN) {
                    credit = 0;
                }
            }
            let e = elapsed(&f);
            prop_assert!(e <= delay);
            if matches!(f.nState, SL_STATE_STOP | SL_STATE_ERROR | SL_STATE_RESET) {
                prop_assert_eq!(f.bTonOut, 0);
            }
            if f.bTonOut == 1 {
                prop_assert_eq!(f.nState, SL_STATE_RUN);
                prop_assert_eq!(e, delay);
                let (s, _) = streak.expect("output TRUE without the input TRUE");
                let now_streak = u64::from(t.wrapping_sub(s));
                if option {
                    prop_assert!(credit + now_streak >= u64::from(delay),
                        "on with credit {} + {} < {}", credit, now_streak, delay);
                } else {
                    prop_assert!(now_streak >= u64::from(delay));
                }
            }
            prop_assert!(f.nState != SL_STATE_ERROR, "no error source in this sequence");
        }
    }
}

/// T13: the block's ERROR is the library's global shutdown: the group enters ERROR
/// (FBERROR) as soon as it runs, and every member is stopped.
#[test]
fn refused_restore_stops_the_group() {
    use safelogic::group::{self, SL_GROUP_DIAG_FBERROR};
    let mut tof = common::ready(FB_TOF {
        tDelay: 1000,
        wInputActive: 1,
        bTofIn1: 1,
        ..Default::default()
    });
    let mut f = ton2(1000, REMAINING);
    let mut g = common::new_group(2, 0);
    assert_eq!(
        unsafe { ffi::sl_ton2_restore_elapsed(&mut f, 5000) },
        SL_E_RESTORE
    );
    g.bRun = 1;
    let mut ms: [&mut dyn Member; 2] = [&mut tof, &mut f];
    group::cycle(&mut g, &mut ms[..], &[], 0);
    assert_eq!((g.nState, g.nDiag), (SL_STATE_ERROR, SL_GROUP_DIAG_FBERROR));
    assert_eq!(g.nFailedMember, 1);
    assert_eq!(ms[0].state(), SL_STATE_STOP);
    assert_eq!(ms[0].output(offset_of!(FB_TOF, bTofOut) as u16), Some(0));
    // One ErrAck sequence restarts the group; TON2 starts with a full delay.
    g.bErrAck = 1;
    group::cycle(&mut g, &mut ms[..], &[], 1);
    assert_eq!(g.nState, SL_STATE_RESET);
    g.bErrAck = 0;
    group::cycle(&mut g, &mut ms[..], &[], 2);
    assert_eq!(g.nState, SL_STATE_RUN);
}
