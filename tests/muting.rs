//! FB MUTING (manual §4.8, EL6910 extensions §4.8.4; docs/semantics.md rows M1–M22 and the
//! step table): every state and its outputs, every diag bit, the sequential and parallel
//! sequences forwards and backwards, sequence violations at each step, filter time, maximum
//! muting time, discrepancy monitoring, DELAYOUT with a discrepancy error arriving during it,
//! EDM, Enable, the EL6910 options, configuration errors, invalid BOOLs, envelope errors.

mod common;
use common::{aligned_tail, null_refused, offsets, output_base};

use proptest::prelude::*;
use safelogic::group::{self, Member};
use safelogic::*;
use std::mem::offset_of;

// ---------------------------------------------------------------------------------------
// Harness

/// Pattern bits of the sequence as in the docs' step table: M1, M2, F (field interrupted),
/// M3, M4.
const M1: u8 = 1 << 0;
const M2: u8 = 1 << 1;
const F: u8 = 1 << 2;
const M3: u8 = 1 << 3;
const M4: u8 = 1 << 4;

/// The docs' sequential step table (M1): the pattern of each state MUTING1…MUTING9, with
/// position 0 and 10 = RUN.
const TABLE: [u8; 11] = [
    0,
    M1,
    M1 | M2,
    M1 | M2 | F,
    M1 | M2 | F | M3,
    M1 | M2 | F | M3 | M4,
    M2 | F | M3 | M4,
    F | M3 | M4,
    M3 | M4,
    M4,
    0,
];

const ALL_INPUTS: u16 = 0x3F;

fn state_of(pos: usize) -> u8 {
    match pos {
        0 | 10 => SL_STATE_RUN,
        p => SL_STATE_MUTING_MUTING1 - 1 + p as u8,
    }
}

/// Test bench: the block, the time, and helpers that set patterns.
struct Bench {
    fb: FB_MUTING,
    t: u32,
}

impl Bench {
    fn new(active: u16, options: u32) -> Self {
        let fb = FB_MUTING {
            wInputActive: active,
            dwOptions: options,
            bMutingEnable: 1,
            bEDM1: 1,
            bEDM2: 1,
            ..Default::default()
        };
        Self { fb, t: 1000 }
    }

    fn sequential() -> Self {
        Self::new(ALL_INPUTS, SL_OPT_MUTING_SEQUENTIAL)
    }

    fn parallel() -> Self {
        let mut b = Self::new(ALL_INPUTS, 0);
        b.fb.tDiscTime12 = 50;
        b.fb.tDiscTime34 = 50;
        b.fb.tDiscTimeOSSD = 50;
        b
    }

    /// Sets the inputs from a pattern (field clear = both OSSD TRUE).
    fn set(&mut self, p: u8) {
        let f = &mut self.fb;
        f.bMutingIn1 = u8::from(p & M1 != 0);
        f.bMutingIn2 = u8::from(p & M2 != 0);
        f.bMutingIn3 = u8::from(p & M3 != 0);
        f.bMutingIn4 = u8::from(p & M4 != 0);
        f.bOSSDIn1 = u8::from(p & F == 0);
        f.bOSSDIn2 = u8::from(p & F == 0);
    }

    /// Sets a parallel pattern: M1 stands for group A (MutingIn1 and 2), M3 for group B.
    fn set_groups(&mut self, p: u8) {
        let a = if p & M1 != 0 { M1 | M2 } else { 0 };
        let b = if p & M3 != 0 { M3 | M4 } else { 0 };
        self.set(a | b | (p & F));
    }

    /// One cycle `dt` ms after the previous one.
    fn step(&mut self, dt: u32) -> i32 {
        self.t = self.t.wrapping_add(dt);
        self.fb.cycle(self.t)
    }

    fn cycle(&mut self) -> i32 {
        self.step(1)
    }

    /// Init, bRun TRUE, field clear, sensors idle: STOP → SAFE → RUN.
    fn start(&mut self) {
        assert_eq!(self.fb.init(), SL_OK);
        self.set(0);
        self.fb.bRun = 1;
        assert_eq!(self.cycle(), SL_OK);
        assert_eq!(self.fb.nState, SL_STATE_SAFE);
        assert_eq!(self.cycle(), SL_OK);
        assert_eq!(self.fb.nState, SL_STATE_RUN);
    }

    /// (bError, bMutingActive, bMuteOut, bMuteDelOut)
    fn outputs(&self) -> (u8, u8, u8, u8) {
        (
            self.fb.bError,
            self.fb.bMutingActive,
            self.fb.bMuteOut,
            self.fb.bMuteDelOut,
        )
    }

    fn expect(&self, state: u8, outputs: (u8, u8, u8, u8)) {
        assert_eq!(self.fb.nState, state, "state at t={}", self.t);
        assert_eq!(self.outputs(), outputs, "outputs in state {state}");
    }

    fn ack(&mut self) {
        self.fb.bErrAck = 1;
        assert_eq!(self.cycle(), SL_OK);
        assert_eq!(self.fb.nState, SL_STATE_RESET);
        self.fb.bErrAck = 0;
        assert_eq!(self.cycle(), SL_OK);
    }
}

const RUN_OUT: (u8, u8, u8, u8) = (0, 0, 1, 1);
const MUTING_OUT: (u8, u8, u8, u8) = (0, 1, 1, 1);
const OFF: (u8, u8, u8, u8) = (0, 0, 0, 0);
const DELAY_OUT: (u8, u8, u8, u8) = (0, 0, 0, 1);
const ERROR_OUT: (u8, u8, u8, u8) = (1, 0, 0, 0);

fn mirror(p: u8) -> u8 {
    ((p & M1) << 4) | ((p & M2) << 2) | (p & F) | ((p & M3) >> 2) | ((p & M4) >> 4)
}

/// Runs a sequence of (pattern, expected state) from RUN and checks the outputs.
fn run_sequence(b: &mut Bench, steps: &[(u8, u8)], groups: bool) {
    for &(p, state) in steps {
        if groups {
            b.set_groups(p);
        } else {
            b.set(p);
        }
        assert_eq!(b.cycle(), SL_OK);
        let out = if state == SL_STATE_RUN {
            RUN_OUT
        } else {
            MUTING_OUT
        };
        b.expect(state, out);
        assert_eq!(b.fb.nDiag, 0);
        // A second cycle with the same pattern stays.
        assert_eq!(b.cycle(), SL_OK);
        b.expect(state, out);
    }
}

// ---------------------------------------------------------------------------------------
// Constants, layout, registry

#[test]
fn abi_numbers() {
    assert_eq!(SL_TYPE_MUTING, 9);
    assert_eq!(SL_OPT_MUTING_SEQUENTIAL, 1 << 8);
    assert_eq!(SL_OPT_MUTING_BACKWARDS, 1 << 9);
    assert_eq!(SL_OPT_MUTING_OSSD_CHECK_OPTIONAL, 1 << 10);
    assert_eq!(SL_DIAG_MUTING_SEQUENCE, 1 << 6);
    assert_eq!(SL_DIAG_MUTING_MAX_TIME, 1 << 7);
    let states = [
        SL_STATE_MUTING_MUTING1,
        SL_STATE_MUTING_MUTING2,
        SL_STATE_MUTING_MUTING3,
        SL_STATE_MUTING_MUTING4,
        SL_STATE_MUTING_MUTING5,
        SL_STATE_MUTING_MUTING6,
        SL_STATE_MUTING_MUTING7,
        SL_STATE_MUTING_MUTING8,
        SL_STATE_MUTING_MUTING9,
    ];
    assert_eq!(states, [9, 10, 11, 12, 13, 14, 15, 16, 17]);
    offsets!(FB_MUTING;
        bMutingEnable => 0,
        bEDM1 => 1,
        bEDM2 => 2,
        bMutingIn1 => 8,
        bMutingIn2 => 9,
        bOSSDIn1 => 10,
        bOSSDIn2 => 11,
        bMutingIn3 => 12,
        bMutingIn4 => 13,
    );
    let base = output_base!(FB_MUTING);
    offsets!(FB_MUTING, from base; bMutingActive => 1, bMuteOut => 2, bMuteDelOut => 3);
    aligned_tail!(FB_MUTING);
    assert!(std::mem::size_of::<SL_MUTING_PRIVATE>() <= 96);
}

#[test]
fn state_names_and_diag_texts() {
    // The registry behind sl_state_str.
    let info = safelogic::registry::info(SL_TYPE_MUTING).expect("MUTING is registered");
    assert_eq!(info.name, "MUTING");
    let name = |s: u8| {
        info.states
            .iter()
            .find(|(v, _)| *v == s)
            .map_or("?".to_string(), |(_, n)| {
                n.trim_end_matches('\0').to_string()
            })
    };
    let expected = [
        (1, "RUN"),
        (2, "STOP"),
        (3, "SAFE"),
        (4, "ERROR"),
        (5, "RESET"),
        (8, "DELAYOUT"),
        (9, "MUTING1"),
        (13, "MUTING5"),
        (17, "MUTING9"),
        (6, "?"),
        (7, "?"),
        (18, "?"),
    ];
    for (s, n) in expected {
        assert_eq!(name(s), n, "state {s}");
    }
    let all = 0b0000_0111_1111_0111u16;
    assert_eq!(
        common::diag_text(SL_TYPE_MUTING, all),
        "discrepancy error in muting input group 1; discrepancy error in the OSSD input group; \
         discrepancy error in muting input group 2; EDM monitoring error EDM1; EDM monitoring \
         error EDM2; muting sequence was violated; maximum muting time was exceeded; \
         discrepancy error in muting input group 1 was not yet reset; discrepancy error in \
         OSSD input group was not yet reset; discrepancy error in muting input group 2 was not \
         yet reset"
    );
}

// ---------------------------------------------------------------------------------------
// Power-up, start, every state and its outputs

#[test]
fn init_is_the_power_up_image_and_keeps_inputs() {
    let mut b = Bench::sequential();
    b.set(M1 | F);
    b.fb.bOSSDIn2 = 7;
    b.fb.bErrAck = 1;
    b.fb.bError = 1;
    b.fb.bMuteOut = 1;
    b.fb.nState = 77;
    let before = b.fb;
    assert_eq!(b.fb.init(), SL_OK);
    b.expect(SL_STATE_STOP, OFF);
    assert_eq!(b.fb.nDiag, 0);
    let mut inputs_after = b.fb;
    inputs_after.bError = before.bError;
    inputs_after.bMuteOut = before.bMuteOut;
    inputs_after.nState = before.nState;
    inputs_after.stPrivate = before.stPrivate;
    assert_eq!(
        inputs_after, before,
        "init writes only outputs, info and private"
    );
}

#[test]
fn never_initialised_instance_starts_on_first_cycle() {
    let mut b = Bench::sequential();
    b.set(0);
    assert_eq!(b.cycle(), SL_OK);
    b.expect(SL_STATE_STOP, OFF);
    b.fb.bRun = 1;
    b.cycle();
    b.expect(SL_STATE_SAFE, OFF);
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
}

/// M11: automatic start, SAFE until the field is clear.
#[test]
fn start_waits_for_the_field() {
    let mut b = Bench::sequential();
    assert_eq!(b.fb.init(), SL_OK);
    b.set(F);
    b.fb.bRun = 1;
    b.cycle();
    b.expect(SL_STATE_SAFE, OFF);
    for _ in 0..5 {
        b.cycle();
        b.expect(SL_STATE_SAFE, OFF);
    }
    b.fb.bOSSDIn1 = 1;
    b.cycle();
    b.expect(SL_STATE_SAFE, OFF);
    b.set(0);
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
    // Run FALSE: STOP with everything off.
    b.fb.bRun = 0;
    b.cycle();
    b.expect(SL_STATE_STOP, OFF);
}

/// Every state with its outputs (M19), in one run.
#[test]
fn every_state_and_its_outputs() {
    let mut b = Bench::sequential();
    b.fb.tMuteDelOutDelay = 100;
    assert_eq!(b.fb.init(), SL_OK);
    b.expect(SL_STATE_STOP, OFF);
    b.set(0);
    b.fb.bRun = 1;
    b.cycle();
    b.expect(SL_STATE_SAFE, OFF);
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
    for (pos, &pat) in TABLE.iter().enumerate().take(10).skip(1) {
        b.set(pat);
        b.cycle();
        b.expect(state_of(pos), MUTING_OUT);
    }
    b.set(0);
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
    b.fb.bMutingEnable = 0;
    b.set(F);
    b.cycle();
    b.expect(SL_STATE_DELAYOUT, DELAY_OUT);
    b.step(100);
    b.expect(SL_STATE_SAFE, OFF);
    b.set(0);
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
    b.fb.bMutingEnable = 1;
    b.set(M2);
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_MUTING_SEQUENCE);
    b.set(0);
    b.fb.bErrAck = 1;
    b.cycle();
    b.expect(SL_STATE_RESET, OFF);
    assert_eq!(b.fb.nDiag, 0);
    b.fb.bErrAck = 0;
    b.cycle();
    b.expect(SL_STATE_SAFE, OFF);
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
}

// ---------------------------------------------------------------------------------------
// Sequences (step table M1, M2)

#[test]
fn sequential_forwards_full_sequence() {
    let mut b = Bench::sequential();
    b.start();
    let steps: Vec<(u8, u8)> = (1..=10).map(|p| (TABLE[p], state_of(p))).collect();
    run_sequence(&mut b, &steps, false);
    // A second sequence right after the first.
    run_sequence(&mut b, &steps, false);
}

#[test]
fn sequential_backwards_with_the_option() {
    let mut b = Bench::new(
        ALL_INPUTS,
        SL_OPT_MUTING_SEQUENTIAL | SL_OPT_MUTING_BACKWARDS,
    );
    b.start();
    let back: Vec<(u8, u8)> = (1..=10).map(|p| (mirror(TABLE[p]), state_of(p))).collect();
    run_sequence(&mut b, &back, false);
    // Forwards still works, and the direction is chosen anew by each sequence.
    let fwd: Vec<(u8, u8)> = (1..=10).map(|p| (TABLE[p], state_of(p))).collect();
    run_sequence(&mut b, &fwd, false);
    run_sequence(&mut b, &back, false);
}

/// M5: without the option, M4 first is a violation; with it, a forward sequence cannot
/// continue backwards.
#[test]
fn backwards_needs_the_option_and_keeps_its_direction() {
    let mut b = Bench::sequential();
    b.start();
    b.set(M4);
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_MUTING_SEQUENCE);

    let mut b = Bench::new(
        ALL_INPUTS,
        SL_OPT_MUTING_SEQUENTIAL | SL_OPT_MUTING_BACKWARDS,
    );
    b.start();
    b.set(M4);
    b.cycle();
    b.expect(SL_STATE_MUTING_MUTING1, MUTING_OUT);
    // The forward second step (M1, M2) is wrong in a backward sequence.
    b.set(M4 | M1);
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_MUTING_SEQUENCE);
}

#[test]
fn parallel_forwards_full_sequence() {
    let mut b = Bench::parallel();
    b.start();
    let steps = [
        (M1, SL_STATE_MUTING_MUTING2),
        (M1 | F, SL_STATE_MUTING_MUTING3),
        (M1 | F | M3, SL_STATE_MUTING_MUTING5),
        (F | M3, SL_STATE_MUTING_MUTING6),
        (M3, SL_STATE_MUTING_MUTING8),
        (0, SL_STATE_RUN),
    ];
    run_sequence(&mut b, &steps, true);
    run_sequence(&mut b, &steps, true);
}

/// M4: a group switches when both channels have switched on, and counts as released when
/// the first channel releases; the channels in between stay within the discrepancy time.
#[test]
fn parallel_groups_switch_channel_by_channel() {
    let mut b = Bench::parallel();
    b.start();
    b.set(M1);
    b.step(10);
    b.expect(SL_STATE_RUN, RUN_OUT);
    b.set(M1 | M2);
    b.step(10);
    b.expect(SL_STATE_MUTING_MUTING2, MUTING_OUT);
    b.set(M1 | M2 | F);
    b.step(10);
    b.expect(SL_STATE_MUTING_MUTING3, MUTING_OUT);
    // One OSSD channel first: already "interrupted"; the second follows.
    b.set(M1 | M2 | F | M4);
    b.step(10);
    b.expect(SL_STATE_MUTING_MUTING3, MUTING_OUT);
    b.set(M1 | M2 | F | M3 | M4);
    b.step(10);
    b.expect(SL_STATE_MUTING_MUTING5, MUTING_OUT);
    b.set(M1 | F | M3 | M4);
    b.step(10);
    b.expect(SL_STATE_MUTING_MUTING6, MUTING_OUT);
    b.set(F | M3 | M4);
    b.step(10);
    b.expect(SL_STATE_MUTING_MUTING6, MUTING_OUT);
    // The field clears channel by channel: clear only with both.
    b.fb.bOSSDIn1 = 1;
    b.step(10);
    b.expect(SL_STATE_MUTING_MUTING6, MUTING_OUT);
    b.fb.bOSSDIn2 = 1;
    b.step(10);
    b.expect(SL_STATE_MUTING_MUTING8, MUTING_OUT);
    b.set(M3);
    b.step(10);
    b.expect(SL_STATE_RUN, RUN_OUT);
    b.set(0);
    b.step(10);
    b.expect(SL_STATE_RUN, RUN_OUT);
    assert_eq!(b.fb.nDiag, 0);
}

#[test]
fn parallel_backwards_with_the_option() {
    let mut b = Bench::parallel();
    b.fb.dwOptions = SL_OPT_MUTING_BACKWARDS;
    b.start();
    let steps = [
        (M3, SL_STATE_MUTING_MUTING2),
        (M3 | F, SL_STATE_MUTING_MUTING3),
        (M3 | F | M1, SL_STATE_MUTING_MUTING5),
        (F | M1, SL_STATE_MUTING_MUTING6),
        (M1, SL_STATE_MUTING_MUTING8),
        (0, SL_STATE_RUN),
    ];
    run_sequence(&mut b, &steps, true);
    // Without the option group B first is a violation.
    let mut b = Bench::parallel();
    b.start();
    b.set_groups(M3);
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_MUTING_SEQUENCE);
}

/// M3: from every position of the sequential table (RUN included), every single change
/// other than the next step is a violation; the next step advances.
#[test]
fn sequential_violation_at_each_step() {
    for pos in 0..=9 {
        for bit in [M1, M2, F, M3, M4] {
            let mut b = Bench::sequential();
            b.start();
            for (p, &pat) in TABLE.iter().enumerate().take(pos + 1).skip(1) {
                b.set(pat);
                b.cycle();
                assert_eq!(b.fb.nState, state_of(p));
            }
            let changed = TABLE[pos] ^ bit;
            b.set(changed);
            assert_eq!(b.cycle(), SL_OK);
            if changed == TABLE[pos + 1] {
                b.expect(
                    state_of(pos + 1),
                    if pos + 1 == 10 { RUN_OUT } else { MUTING_OUT },
                );
            } else {
                b.expect(SL_STATE_ERROR, ERROR_OUT);
                assert_eq!(
                    b.fb.nDiag, SL_DIAG_MUTING_SEQUENCE,
                    "pos {pos} change {bit:#x}"
                );
            }
        }
        // Two changes in one cycle, even the next two steps, are a violation.
        if pos <= 8 {
            let mut b = Bench::sequential();
            b.start();
            for &pat in TABLE.iter().take(pos + 1).skip(1) {
                b.set(pat);
                b.cycle();
            }
            b.set(TABLE[pos + 2]);
            b.cycle();
            assert_eq!(
                (b.fb.nState, b.fb.nDiag),
                (SL_STATE_ERROR, SL_DIAG_MUTING_SEQUENCE),
                "skip from {pos}"
            );
        }
    }
}

/// M3, M4: violations at each parallel step (group changes out of order).
#[test]
fn parallel_violation_at_each_step() {
    // Group-level patterns of the parallel sequence: A = M1, B = M3.
    let seq = [0, M1, M1 | F, M1 | F | M3, F | M3, M3, 0];
    for pos in 0..seq.len() - 1 {
        for bit in [M1, F, M3] {
            let mut b = Bench::parallel();
            b.start();
            for &p in seq.iter().take(pos + 1).skip(1) {
                b.set_groups(p);
                b.cycle();
            }
            let changed = seq[pos] ^ bit;
            b.set_groups(changed);
            b.cycle();
            if changed == seq[pos + 1] {
                assert_ne!(b.fb.nState, SL_STATE_ERROR, "pos {pos} bit {bit}");
            } else {
                assert_eq!(
                    (b.fb.nState, b.fb.nDiag),
                    (SL_STATE_ERROR, SL_DIAG_MUTING_SEQUENCE),
                    "pos {pos} change {bit:#x}"
                );
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// Enable (M6, M7)

#[test]
fn enable_false_the_field_decides_alone() {
    let mut b = Bench::sequential();
    b.start();
    b.fb.bMutingEnable = 0;
    // Muting sensors are ignored.
    for p in [M1, M2 | M4, M1 | M2 | M3 | M4] {
        b.set(p);
        b.cycle();
        b.expect(SL_STATE_RUN, RUN_OUT);
    }
    // Field interrupted: MuteOut off in the same cycle (delay 0: SAFE).
    b.set(M1 | M2 | F);
    b.cycle();
    b.expect(SL_STATE_SAFE, OFF);
    b.cycle();
    b.expect(SL_STATE_SAFE, OFF);
    // Enable TRUE in SAFE changes nothing; field clear → RUN.
    b.fb.bMutingEnable = 1;
    b.cycle();
    b.expect(SL_STATE_SAFE, OFF);
    b.set(0);
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
}

#[test]
fn enable_true_an_intrusion_is_a_violation() {
    let mut b = Bench::sequential();
    b.start();
    b.set(F);
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_MUTING_SEQUENCE);
    // One OSSD channel is enough.
    let mut b = Bench::sequential();
    b.start();
    b.fb.bOSSDIn2 = 0;
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
}

#[test]
fn enable_false_during_muting_ends_it() {
    // Field interrupted: MuteOut off at once, MuteDelOut after the delay.
    let mut b = Bench::sequential();
    b.fb.tMuteDelOutDelay = 40;
    b.start();
    for &p in TABLE.iter().take(4).skip(1) {
        b.set(p);
        b.cycle();
    }
    b.expect(SL_STATE_MUTING_MUTING3, MUTING_OUT);
    b.fb.bMutingEnable = 0;
    b.cycle();
    b.expect(SL_STATE_DELAYOUT, DELAY_OUT);
    b.step(39);
    b.expect(SL_STATE_DELAYOUT, DELAY_OUT);
    b.step(1);
    b.expect(SL_STATE_SAFE, OFF);
    // Field clear: RUN, MutingActive off; Enable TRUE again with sensors mid-way: violation.
    let mut b = Bench::sequential();
    b.start();
    for &p in TABLE.iter().take(3).skip(1) {
        b.set(p);
        b.cycle();
    }
    b.expect(SL_STATE_MUTING_MUTING2, MUTING_OUT);
    b.fb.bMutingEnable = 0;
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
    b.set(M1 | M2 | F);
    b.cycle();
    b.expect(SL_STATE_SAFE, OFF);
    b.set(M1 | M2);
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
    b.fb.bMutingEnable = 1;
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_MUTING_SEQUENCE);
}

// ---------------------------------------------------------------------------------------
// Filter time (M9)

#[test]
fn filter_time_suppresses_bounces_and_delays_changes() {
    let mut b = Bench::sequential();
    b.fb.tFilterTime = 100;
    b.start();
    // M1 actuated: taken over exactly 100 ms after the first cycle that sees it.
    b.set(M1);
    b.step(10);
    b.expect(SL_STATE_RUN, RUN_OUT);
    b.step(99);
    b.expect(SL_STATE_RUN, RUN_OUT);
    b.step(1);
    b.expect(SL_STATE_MUTING_MUTING1, MUTING_OUT);
    // M1 bounces off for 60 ms: ignored (a violation without the filter).
    b.set(0);
    b.step(60);
    b.set(M1);
    b.step(10);
    b.expect(SL_STATE_MUTING_MUTING1, MUTING_OUT);
    // M2 bounces on shortly: ignored; then stays on: MUTING2 after 100 ms.
    b.set(M1 | M2);
    b.step(30);
    b.set(M1);
    b.step(30);
    b.set(M1 | M2);
    b.step(1);
    b.step(99);
    b.expect(SL_STATE_MUTING_MUTING1, MUTING_OUT);
    b.step(1);
    b.expect(SL_STATE_MUTING_MUTING2, MUTING_OUT);
    // The OSSD inputs are not filtered.
    b.set(M1 | M2 | F);
    b.step(1);
    b.expect(SL_STATE_MUTING_MUTING3, MUTING_OUT);
    assert_eq!(b.fb.nDiag, 0);
}

#[test]
fn without_filter_a_bounce_is_a_violation() {
    let mut b = Bench::sequential();
    b.start();
    b.set(M1);
    b.cycle();
    b.set(0);
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_MUTING_SEQUENCE);
}

#[test]
fn filter_keeps_the_order_of_close_changes() {
    // M1 and M2 5 ms apart with 50 ms filter: taken over 5 ms apart, in order.
    let mut b = Bench::sequential();
    b.fb.tFilterTime = 50;
    b.start();
    b.set(M1);
    b.step(1);
    b.set(M1 | M2);
    b.step(5);
    b.step(45);
    b.expect(SL_STATE_MUTING_MUTING1, MUTING_OUT);
    b.step(5);
    b.expect(SL_STATE_MUTING_MUTING2, MUTING_OUT);
}

// ---------------------------------------------------------------------------------------
// Maximum muting time (M10)

#[test]
fn maximum_muting_time() {
    let mut b = Bench::sequential();
    b.fb.tMaxMutingTime = 1000;
    b.start();
    let t0 = b.t + 10;
    b.set(M1);
    b.step(10);
    b.expect(SL_STATE_MUTING_MUTING1, MUTING_OUT);
    for &p in TABLE.iter().take(6).skip(2) {
        b.set(p);
        b.step(100);
    }
    b.expect(SL_STATE_MUTING_MUTING5, MUTING_OUT);
    let left = 999 - (b.t - t0);
    b.step(left);
    b.expect(SL_STATE_MUTING_MUTING5, MUTING_OUT);
    b.step(1);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_MUTING_MAX_TIME);

    // The error wins over completing the sequence in the same cycle.
    let mut b = Bench::sequential();
    b.fb.tMaxMutingTime = 1000;
    b.start();
    for &p in TABLE.iter().take(10).skip(1) {
        b.set(p);
        b.step(10);
    }
    b.expect(SL_STATE_MUTING_MUTING9, MUTING_OUT);
    b.set(0);
    b.step(1000);
    assert_eq!(
        (b.fb.nState, b.fb.nDiag),
        (SL_STATE_ERROR, SL_DIAG_MUTING_MAX_TIME)
    );

    // Completed in time: no error, and the next sequence has its own time.
    let mut b = Bench::sequential();
    b.fb.tMaxMutingTime = 1000;
    b.start();
    for _ in 0..3 {
        for &p in TABLE.iter().skip(1) {
            b.set(p);
            b.step(99);
        }
        b.expect(SL_STATE_RUN, RUN_OUT);
    }
}

#[test]
fn maximum_muting_time_zero_is_off() {
    let mut b = Bench::sequential();
    b.start();
    b.set(M1);
    b.cycle();
    b.step(600_000);
    b.step(3_000_000);
    b.expect(SL_STATE_MUTING_MUTING1, MUTING_OUT);
    // Muting still ends with the sequence.
    for &p in TABLE.iter().skip(2) {
        b.set(p);
        b.cycle();
    }
    b.expect(SL_STATE_RUN, RUN_OUT);
}

// ---------------------------------------------------------------------------------------
// Discrepancy monitoring (M4, M14, M16, M22)

/// OSSD discrepancy during muting: a one-channel interruption is muted but monitored.
#[test]
fn ossd_discrepancy_during_muting() {
    let mut b = Bench::sequential();
    b.fb.tDiscTimeOSSD = 50;
    b.start();
    for &p in TABLE.iter().take(3).skip(1) {
        b.set(p);
        b.cycle();
    }
    b.fb.bOSSDIn1 = 0;
    b.cycle();
    b.expect(SL_STATE_MUTING_MUTING3, MUTING_OUT);
    b.step(49);
    b.expect(SL_STATE_MUTING_MUTING3, MUTING_OUT);
    b.step(1);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_DISC2 | SL_DIAG_SAFE_IN_DISC2);
    // Acknowledgement: muting sensors released and the channels agreeing is not enough
    // while "not yet reset" (bit 9) is set; both OSSD channels FALSE together resets it.
    b.set(0);
    b.fb.bErrAck = 1;
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    b.fb.bErrAck = 0;
    b.set(F);
    b.cycle();
    assert_eq!(b.fb.nDiag, SL_DIAG_DISC2, "bit 9 cleared by the reset");
    // Field still interrupted: the area is not clear (M15).
    b.fb.bErrAck = 1;
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    b.fb.bErrAck = 0;
    b.set(0);
    b.cycle();
    b.ack();
    b.expect(SL_STATE_SAFE, OFF);
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
}

#[test]
fn ossd_discrepancy_in_safe_and_run() {
    // Enable FALSE, delay 0: one channel → SAFE at once, ERROR after the disc time.
    let mut b = Bench::sequential();
    b.fb.tDiscTimeOSSD = 30;
    b.fb.bMutingEnable = 0;
    b.start();
    b.fb.bOSSDIn2 = 0;
    b.cycle();
    b.expect(SL_STATE_SAFE, OFF);
    b.step(29);
    b.expect(SL_STATE_SAFE, OFF);
    b.step(1);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_DISC2 | SL_DIAG_SAFE_IN_DISC2);
    // Agreeing again within the time restarts the timer.
    let mut b = Bench::sequential();
    b.fb.tDiscTimeOSSD = 30;
    b.fb.bMutingEnable = 0;
    b.start();
    b.fb.bOSSDIn2 = 0;
    b.step(1);
    b.step(20);
    b.set(F);
    b.step(1);
    b.set(0);
    b.step(1);
    b.expect(SL_STATE_RUN, RUN_OUT);
    b.fb.bOSSDIn1 = 0;
    b.step(1);
    b.step(29);
    b.expect(SL_STATE_SAFE, OFF);
    b.step(1);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
}

#[test]
fn muting_pair_discrepancies_in_parallel_mode() {
    // Group A: MutingIn1 without MutingIn2 for the discrepancy time.
    let mut b = Bench::parallel();
    b.start();
    b.fb.bMutingIn1 = 1;
    b.step(1);
    b.step(49);
    b.expect(SL_STATE_RUN, RUN_OUT);
    b.step(1);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
    // Releasing both resets and clears the area in one go.
    b.set(0);
    b.cycle();
    assert_eq!(b.fb.nDiag, SL_DIAG_DISC1);
    b.ack();
    b.expect(SL_STATE_SAFE, OFF);

    // Group B during muting: MutingIn3 actuated alone; group B is not actuated yet (MUTING3
    // stays), and after the discrepancy time it is an error.
    let mut b = Bench::parallel();
    b.start();
    for p in [M1, M1 | F] {
        b.set_groups(p);
        b.cycle();
    }
    b.fb.bMutingIn3 = 1;
    b.step(1);
    b.expect(SL_STATE_MUTING_MUTING3, MUTING_OUT);
    b.step(49);
    b.expect(SL_STATE_MUTING_MUTING3, MUTING_OUT);
    b.step(1);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_DISC3 | SL_DIAG_SAFE_IN_DISC3);
    // The muting area is not clear while a muting sensor is actuated (M15).
    b.set(0);
    b.fb.bMutingIn3 = 1;
    b.cycle();
    b.fb.bErrAck = 1;
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    b.fb.bErrAck = 0;
    b.fb.bMutingIn3 = 0;
    b.cycle();
    b.ack();
    b.expect(SL_STATE_SAFE, OFF);
}

/// M16: a discrepancy error arriving in DELAYOUT waits for the end of the delay.
#[test]
fn delayout_with_a_discrepancy_error_arriving_during_it() {
    let mut b = Bench::sequential();
    b.fb.tDiscTimeOSSD = 30;
    b.fb.tMuteDelOutDelay = 100;
    b.fb.bMutingEnable = 0;
    b.start();
    let t0 = b.t + 1;
    b.fb.bOSSDIn1 = 0;
    b.cycle();
    b.expect(SL_STATE_DELAYOUT, DELAY_OUT);
    assert_eq!(b.fb.nDiag, 0);
    b.step(29);
    b.expect(SL_STATE_DELAYOUT, DELAY_OUT);
    b.step(1);
    b.expect(SL_STATE_DELAYOUT, DELAY_OUT);
    assert_eq!(
        b.fb.nDiag,
        SL_DIAG_DISC2 | SL_DIAG_SAFE_IN_DISC2,
        "the pending error is visible"
    );
    // Even if the channels agree again, the error stays pending.
    b.set(0);
    b.step(10);
    b.expect(SL_STATE_DELAYOUT, DELAY_OUT);
    b.step(99 - (b.t - t0));
    b.expect(SL_STATE_DELAYOUT, DELAY_OUT);
    b.step(1);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_DISC2 | SL_DIAG_SAFE_IN_DISC2);

    // bRun FALSE while the error is pending: ERROR, not STOP.
    let mut b = Bench::sequential();
    b.fb.tDiscTimeOSSD = 30;
    b.fb.tMuteDelOutDelay = 100;
    b.fb.bMutingEnable = 0;
    b.start();
    b.fb.bOSSDIn1 = 0;
    b.cycle();
    b.step(30);
    b.expect(SL_STATE_DELAYOUT, DELAY_OUT);
    b.fb.bRun = 0;
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);

    // bRun FALSE in DELAYOUT without an error: STOP.
    let mut b = Bench::sequential();
    b.fb.tMuteDelOutDelay = 100;
    b.fb.bMutingEnable = 0;
    b.start();
    b.set(F);
    b.cycle();
    b.expect(SL_STATE_DELAYOUT, DELAY_OUT);
    b.fb.bRun = 0;
    b.cycle();
    b.expect(SL_STATE_STOP, OFF);
}

/// M13: DELAYOUT runs to its end even if the field clears; delay 0 goes to SAFE.
#[test]
fn delayout_runs_to_its_end() {
    let mut b = Bench::sequential();
    b.fb.tMuteDelOutDelay = 30_000;
    b.fb.bMutingEnable = 0;
    b.start();
    b.set(F);
    b.cycle();
    b.expect(SL_STATE_DELAYOUT, DELAY_OUT);
    b.set(0);
    b.step(29_999);
    b.expect(SL_STATE_DELAYOUT, DELAY_OUT);
    b.step(1);
    b.expect(SL_STATE_SAFE, OFF);
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
}

// ---------------------------------------------------------------------------------------
// EDM (M12)

#[test]
fn edm_keeps_the_safe_state_without_error() {
    let mut b = Bench::sequential();
    b.fb.dwOptions |= SL_OPT_EDM1 | SL_OPT_EDM2;
    b.fb.tMuteDelOutDelay = 50;
    b.start();
    // Outputs on: the contactors pull in, EDM FALSE is fine.
    b.fb.bEDM1 = 0;
    b.fb.bEDM2 = 0;
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
    b.fb.bMutingEnable = 0;
    b.set(F);
    b.cycle();
    b.expect(SL_STATE_DELAYOUT, DELAY_OUT);
    b.fb.bEDM1 = 1;
    b.step(50);
    b.expect(SL_STATE_SAFE, OFF);
    b.set(0);
    // EDM2 still FALSE: SAFE, no error, for as long as it takes.
    for _ in 0..10 {
        b.step(1000);
        b.expect(SL_STATE_SAFE, OFF);
        assert_eq!(b.fb.nDiag, 0);
    }
    // An invalid EDM byte is not TRUE either.
    b.fb.bEDM2 = 9;
    assert_eq!(b.cycle(), SL_E_INVALID_BOOL);
    b.expect(SL_STATE_SAFE, OFF);
    b.fb.bEDM2 = 1;
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
    // EDM1 alone.
    b.set(F);
    b.cycle();
    b.fb.bEDM1 = 0;
    b.step(50);
    b.set(0);
    b.cycle();
    b.expect(SL_STATE_SAFE, OFF);
    b.fb.bEDM1 = 1;
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
}

#[test]
fn inactive_edm_is_not_read() {
    let mut b = Bench::sequential();
    b.start();
    b.fb.bEDM1 = 0;
    b.fb.bEDM2 = 5;
    b.fb.bMutingEnable = 0;
    b.set(F);
    assert_eq!(b.cycle(), SL_OK);
    b.set(0);
    assert_eq!(b.cycle(), SL_OK);
    b.expect(SL_STATE_RUN, RUN_OUT);
}

// ---------------------------------------------------------------------------------------
// EL6910 options (M2, M17, M18)

#[test]
fn ossd_check_optional_sequential() {
    let mut b = Bench::new(
        ALL_INPUTS,
        SL_OPT_MUTING_SEQUENTIAL | SL_OPT_MUTING_OSSD_CHECK_OPTIONAL,
    );
    b.start();
    // The docs' table: MUTING1, 2, 4, 5, 6, 7, 9, then RUN; the field toggles anywhere.
    let steps = [
        (M1, SL_STATE_MUTING_MUTING1),
        (M1 | F, SL_STATE_MUTING_MUTING1),
        (M1 | M2, SL_STATE_MUTING_MUTING2),
        (M1 | M2 | M3, SL_STATE_MUTING_MUTING4),
        (M1 | M2 | M3 | M4 | F, SL_STATE_MUTING_MUTING5),
        (M2 | M3 | M4, SL_STATE_MUTING_MUTING6),
        (M3 | M4 | F, SL_STATE_MUTING_MUTING7),
        (M4, SL_STATE_MUTING_MUTING9),
        (M4 | F, SL_STATE_MUTING_MUTING9),
        (M4, SL_STATE_MUTING_MUTING9),
        (0, SL_STATE_RUN),
    ];
    run_sequence(&mut b, &steps, false);
    // Outside a sequence the field is not muted (Enable TRUE: violation).
    b.set(F);
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_MUTING_SEQUENCE);
    // A sequence that ends with the field interrupted: violation in that cycle.
    let mut b = Bench::new(
        ALL_INPUTS,
        SL_OPT_MUTING_SEQUENTIAL | SL_OPT_MUTING_OSSD_CHECK_OPTIONAL,
    );
    b.start();
    for p in [
        M1,
        M1 | M2,
        M1 | M2 | M3,
        M1 | M2 | M3 | M4,
        M2 | M3 | M4,
        M3 | M4,
        M4,
    ] {
        b.set(p);
        b.cycle();
    }
    b.expect(SL_STATE_MUTING_MUTING9, MUTING_OUT);
    b.set(F);
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_MUTING_SEQUENCE);
    // Start with the field already interrupted by the object: muted from the first step.
    let mut b = Bench::new(
        ALL_INPUTS,
        SL_OPT_MUTING_SEQUENTIAL | SL_OPT_MUTING_OSSD_CHECK_OPTIONAL,
    );
    b.start();
    b.set(M1 | F);
    b.cycle();
    b.expect(SL_STATE_MUTING_MUTING1, MUTING_OUT);
}

#[test]
fn ossd_check_optional_parallel() {
    let mut b = Bench::parallel();
    b.fb.dwOptions = SL_OPT_MUTING_OSSD_CHECK_OPTIONAL;
    b.start();
    let steps = [
        (M1, SL_STATE_MUTING_MUTING2),
        (M1 | F, SL_STATE_MUTING_MUTING2),
        (M1 | M3 | F, SL_STATE_MUTING_MUTING5),
        (M3 | F, SL_STATE_MUTING_MUTING6),
        (M3, SL_STATE_MUTING_MUTING6),
        (0, SL_STATE_RUN),
    ];
    run_sequence(&mut b, &steps, true);
}

/// §4.8.4 wiring change: sequential with MutingIn3/4 inactive.
#[test]
fn sequential_with_muting3_and_4_inactive() {
    let mut b = Bench::new(0b00_1111, SL_OPT_MUTING_SEQUENTIAL);
    b.start();
    let steps = [
        (M1, SL_STATE_MUTING_MUTING1),
        (M1 | M2, SL_STATE_MUTING_MUTING2),
        (M1 | M2 | F, SL_STATE_MUTING_MUTING3),
        (M2 | F, SL_STATE_MUTING_MUTING6),
        (F, SL_STATE_MUTING_MUTING7),
        (0, SL_STATE_RUN),
    ];
    run_sequence(&mut b, &steps, false);
    // Bytes of the inactive inputs are not read.
    b.fb.bMutingIn3 = 1;
    b.fb.bMutingIn4 = 3;
    assert_eq!(b.cycle(), SL_OK);
    b.expect(SL_STATE_RUN, RUN_OUT);
    // With OSSD check optional the sequence is M1, M2, M1 released, M2 released.
    let mut b = Bench::new(
        0b00_1111,
        SL_OPT_MUTING_SEQUENTIAL | SL_OPT_MUTING_OSSD_CHECK_OPTIONAL,
    );
    b.start();
    let steps = [
        (M1, SL_STATE_MUTING_MUTING1),
        (M1 | M2 | F, SL_STATE_MUTING_MUTING2),
        (M2 | F, SL_STATE_MUTING_MUTING6),
        (M2, SL_STATE_MUTING_MUTING6),
        (0, SL_STATE_RUN),
    ];
    run_sequence(&mut b, &steps, false);
}

#[test]
fn single_channel_ossd_and_negated_inputs() {
    // OSSDIn2 only, MutingIn1 a make contact (negated).
    let mut b = Bench::new(0b11_1011, SL_OPT_MUTING_SEQUENTIAL);
    b.fb.wInputNegated = 0b00_0001;
    assert_eq!(b.fb.init(), SL_OK);
    b.set(0);
    b.fb.bMutingIn1 = 1; // not actuated (negated)
    b.fb.bOSSDIn1 = 0; // inactive
    b.fb.bRun = 1;
    b.cycle();
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
    b.fb.bMutingIn1 = 0; // actuated
    b.cycle();
    b.expect(SL_STATE_MUTING_MUTING1, MUTING_OUT);
    b.fb.bMutingIn2 = 1;
    b.cycle();
    b.fb.bOSSDIn2 = 0;
    b.cycle();
    b.expect(SL_STATE_MUTING_MUTING3, MUTING_OUT);
}

// ---------------------------------------------------------------------------------------
// Acknowledgement (C8, M15)

#[test]
fn acknowledgement_needs_a_clear_area_and_a_fresh_edge() {
    let mut b = Bench::sequential();
    b.start();
    b.set(M1);
    b.cycle();
    b.set(M1 | F);
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    // ErrAck while the object is in the field: nothing, and the edge is consumed.
    b.fb.bErrAck = 1;
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    b.set(0);
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    b.fb.bErrAck = 0;
    b.cycle();
    b.ack();
    b.expect(SL_STATE_SAFE, OFF);
    // RESET with bRun FALSE goes to STOP.
    b.set(M2);
    b.cycle();
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    b.set(0);
    b.fb.bRun = 0;
    b.cycle();
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    b.fb.bErrAck = 1;
    b.cycle();
    b.expect(SL_STATE_RESET, OFF);
    b.fb.bErrAck = 0;
    b.cycle();
    b.expect(SL_STATE_STOP, OFF);
}

// ---------------------------------------------------------------------------------------
// Configuration errors (M17)

#[test]
fn configuration_errors() {
    type Edit = fn(&mut FB_MUTING);
    let base = |edit: Edit| {
        let mut f = FB_MUTING {
            wInputActive: ALL_INPUTS,
            dwOptions: SL_OPT_MUTING_SEQUENTIAL,
            ..Default::default()
        };
        f.bRun = 1;
        edit(&mut f);
        f
    };
    let cases: [(&str, Edit); 23] = [
        ("no inputs", |f| f.wInputActive = 0),
        ("MutingIn1 inactive", |f| f.wInputActive = 0b11_1110),
        ("MutingIn2 inactive", |f| f.wInputActive = 0b11_1101),
        ("no OSSD", |f| f.wInputActive = 0b11_0011),
        ("MutingIn3 alone", |f| f.wInputActive = 0b01_1111),
        ("MutingIn4 alone", |f| f.wInputActive = 0b10_1111),
        ("unknown input bit", |f| f.wInputActive = 0x7F),
        ("unknown negation bit", |f| f.wInputNegated = 0x40),
        ("unknown option", |f| f.dwOptions |= 1 << 11),
        ("safe inputs option", |f| {
            f.dwOptions |= SL_OPT_SAFE_INPUTS_AFTER_DISC
        }),
        ("manual restart", |f| f.dwOptions |= SL_OPT_MANUAL_RESTART),
        ("function test", |f| f.dwOptions |= SL_OPT_FUNCTION_TEST),
        ("sequential with disc 12", |f| f.tDiscTime12 = 10),
        ("sequential with disc 34", |f| f.tDiscTime34 = 10),
        ("parallel without MutingIn3/4", |f| {
            f.wInputActive = 0b00_1111;
            f.dwOptions = 0;
        }),
        ("parallel without MutingIn4", |f| {
            f.wInputActive = 0b01_1111;
            f.dwOptions = 0;
        }),
        ("backwards without MutingIn3/4", |f| {
            f.wInputActive = 0b00_1111;
            f.dwOptions |= SL_OPT_MUTING_BACKWARDS;
        }),
        ("OSSD disc with one OSSD", |f| {
            f.wInputActive = 0b11_0111;
            f.tDiscTimeOSSD = 10;
        }),
        ("disc 12 above max", |f| {
            f.dwOptions = 0;
            f.tDiscTime12 = 65_536;
        }),
        ("OSSD disc above max", |f| f.tDiscTimeOSSD = 65_536),
        ("filter above 500", |f| f.tFilterTime = 501),
        ("max muting above 10 min", |f| f.tMaxMutingTime = 600_001),
        ("delay above 30 s", |f| f.tMuteDelOutDelay = 30_001),
    ];
    for (what, edit) in cases {
        let mut f = base(edit);
        assert_eq!(f.init(), SL_E_CONFIG, "{what}");
        assert_eq!((f.nState, f.bMuteOut, f.bMuteDelOut), (SL_STATE_STOP, 0, 0));
        assert_eq!(f.cycle(1), SL_E_CONFIG, "{what}: stays STOP");
        assert_eq!(f.nState, SL_STATE_STOP, "{what}");
        f.bRun = 0;
        assert_eq!(f.cycle(2), SL_E_CONFIG, "{what}: also with bRun FALSE");
    }
    // The limits themselves are valid, and so are the configurations of the docs' table.
    let ok: [Edit; 6] = [
        |f| {
            f.tFilterTime = 500;
            f.tMaxMutingTime = 600_000;
            f.tMuteDelOutDelay = 30_000;
            f.tDiscTimeOSSD = 65_535;
        },
        |f| f.wInputActive = 0b00_1111,
        |f| f.wInputActive = 0b11_0111,
        |f| {
            f.wInputActive = 0b11_1011;
            f.wInputNegated = 0b00_0100;
        },
        |f| {
            f.dwOptions = SL_OPT_EDM1
                | SL_OPT_EDM2
                | SL_OPT_MUTING_BACKWARDS
                | SL_OPT_MUTING_OSSD_CHECK_OPTIONAL;
            f.tDiscTime12 = 65_535;
            f.tDiscTime34 = 1;
        },
        |f| f.dwOptions |= SL_OPT_MUTING_BACKWARDS,
    ];
    for edit in ok {
        let mut f = base(edit);
        assert_eq!(f.init(), SL_OK, "{f:?}");
    }
    // A configuration error found at the STOP → run latch.
    let mut f = base(|f| f.bRun = 0);
    assert_eq!(f.init(), SL_OK);
    f.tFilterTime = 600;
    f.bRun = 1;
    assert_eq!(f.cycle(1), SL_E_CONFIG);
    assert_eq!(f.nState, SL_STATE_STOP);
    f.tFilterTime = 10;
    assert_eq!(f.cycle(2), SL_OK);
    assert_eq!(f.nState, SL_STATE_SAFE);
}

// ---------------------------------------------------------------------------------------
// Invalid BOOL (M20)

#[test]
fn invalid_bools_read_safe() {
    // Invalid OSSD: field interrupted (Enable FALSE: SAFE).
    let mut b = Bench::sequential();
    b.fb.bMutingEnable = 0;
    b.start();
    b.fb.bOSSDIn1 = 2;
    assert_eq!(b.cycle(), SL_E_INVALID_BOOL);
    b.expect(SL_STATE_SAFE, OFF);
    // Invalid OSSD during muting is an interruption, muted in MUTING3.
    let mut b = Bench::sequential();
    b.start();
    for &p in TABLE.iter().take(3).skip(1) {
        b.set(p);
        b.cycle();
    }
    b.fb.bOSSDIn2 = 0xFF;
    assert_eq!(b.cycle(), SL_E_INVALID_BOOL);
    b.expect(SL_STATE_MUTING_MUTING3, MUTING_OUT);
    // Invalid muting input: not actuated → in MUTING3 a released M1 is a violation.
    b.fb.bMutingIn1 = 3;
    assert_eq!(b.cycle(), SL_E_INVALID_BOOL);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    // Invalid muting input in RUN cannot start muting, even negated.
    let mut b = Bench::sequential();
    b.fb.wInputNegated = 0b1;
    assert_eq!(b.fb.init(), SL_OK);
    b.set(0);
    b.fb.bMutingIn1 = 1;
    b.fb.bRun = 1;
    b.cycle();
    b.cycle();
    b.expect(SL_STATE_RUN, RUN_OUT);
    b.fb.bMutingIn1 = 7;
    assert_eq!(b.cycle(), SL_E_INVALID_BOOL);
    b.expect(SL_STATE_RUN, RUN_OUT);
    // Invalid Enable: FALSE. During MUTING3 it ends muting (DELAYOUT/SAFE).
    let mut b = Bench::sequential();
    b.start();
    for &p in TABLE.iter().take(4).skip(1) {
        b.set(p);
        b.cycle();
    }
    b.fb.bMutingEnable = 2;
    assert_eq!(b.cycle(), SL_E_INVALID_BOOL);
    b.expect(SL_STATE_SAFE, OFF);
    // Invalid Run, ErrAck.
    let mut b = Bench::sequential();
    b.start();
    b.fb.bRun = 9;
    assert_eq!(b.cycle(), SL_E_INVALID_BOOL);
    b.expect(SL_STATE_STOP, OFF);
}

// ---------------------------------------------------------------------------------------
// Envelope errors (C3, C4, C5) and the C ABI

#[test]
fn parameter_change_while_running() {
    let mut b = Bench::sequential();
    b.start();
    b.fb.tMaxMutingTime = 5000;
    assert_eq!(b.cycle(), SL_E_PARAM_CHANGED);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_PARAM_CHANGED);
    // Adopted after a stop; reported until acknowledged (C5).
    b.fb.bRun = 0;
    assert_eq!(b.cycle(), SL_E_PARAM_CHANGED);
    b.fb.bErrAck = 1;
    b.cycle();
    b.fb.bErrAck = 0;
    b.cycle();
    b.expect(SL_STATE_STOP, OFF);
    b.fb.bRun = 1;
    assert_eq!(b.cycle(), SL_OK);
    b.expect(SL_STATE_SAFE, OFF);
    // Every parameter field counts.
    for change in 0..9 {
        let mut b = Bench::sequential();
        b.start();
        match change {
            0 => b.fb.tDiscTimeOSSD = 1,
            1 => b.fb.tFilterTime = 1,
            2 => b.fb.tMaxMutingTime = 1,
            3 => b.fb.tMuteDelOutDelay = 1,
            4 => b.fb.wInputActive = 0b00_1111,
            5 => b.fb.wInputNegated = 1,
            6 => b.fb.dwOptions |= SL_OPT_MUTING_BACKWARDS,
            7 => b.fb.tDiscTime12 = 1,
            _ => b.fb.tDiscTime34 = 1,
        }
        assert_eq!(b.cycle(), SL_E_PARAM_CHANGED, "change {change}");
    }
}

#[test]
fn clock_going_backwards() {
    let mut b = Bench::sequential();
    b.start();
    b.set(M1);
    b.cycle();
    b.expect(SL_STATE_MUTING_MUTING1, MUTING_OUT);
    let t = b.t;
    assert_eq!(b.fb.cycle(t - 1), SL_E_CLOCK);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_CLOCK);
    // Clock errors do not need a clear area (C4, M15).
    b.t = t;
    b.fb.bErrAck = 1;
    b.cycle();
    b.expect(SL_STATE_RESET, OFF);
}

#[test]
fn time_wraps_around() {
    let mut b = Bench::sequential();
    b.fb.tMaxMutingTime = 100;
    b.t = u32::MAX - 50;
    b.start();
    b.set(M1);
    b.step(10);
    b.expect(SL_STATE_MUTING_MUTING1, MUTING_OUT);
    b.step(99);
    b.expect(SL_STATE_MUTING_MUTING1, MUTING_OUT);
    b.step(1);
    assert_eq!(b.fb.nDiag, SL_DIAG_MUTING_MAX_TIME);
}

#[test]
fn corrupt_private_state() {
    // The control word.
    let mut b = Bench::sequential();
    b.start();
    b.fb.stPrivate.stHeader.nState = SL_STATE_MUTING_MUTING5;
    assert_eq!(b.cycle(), SL_E_CORRUPT);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_CORRUPT);
    // The aux word (filtered inputs, direction).
    let mut b = Bench::sequential();
    b.start();
    b.fb.stPrivate.stHeader.wAux ^= 1;
    assert_eq!(b.cycle(), SL_E_CORRUPT);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    // A latched time: found when it differs from the live parameter...
    let mut b = Bench::sequential();
    b.start();
    b.fb.stPrivate.tMaxMutingTime = 7;
    assert_eq!(b.cycle(), SL_E_CORRUPT);
    // ...and by the CRC when both were changed alike, at the start of muting.
    let mut b = Bench::sequential();
    b.start();
    b.fb.stPrivate.awTime[3] = 40;
    b.fb.tFilterTime = 40;
    b.set(M1);
    assert_eq!(b.step(1), SL_OK);
    assert_eq!(b.step(40), SL_E_CORRUPT);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
    assert_eq!(b.fb.nDiag, SL_DIAG_CORRUPT);
    // ...or when SAFE would switch the outputs on.
    let mut b = Bench::sequential();
    b.fb.bMutingEnable = 0;
    b.start();
    b.set(F);
    b.cycle();
    b.expect(SL_STATE_SAFE, OFF);
    b.fb.stPrivate.tMaxMutingTime = 9;
    b.fb.tMaxMutingTime = 9;
    b.set(0);
    assert_eq!(b.cycle(), SL_E_CORRUPT);
    b.expect(SL_STATE_ERROR, ERROR_OUT);
}

/// Defence in depth: a state value the configuration never takes, even with intact
/// complement copies, is a corrupt private state.
#[test]
fn state_values_the_block_never_takes() {
    for (bench, state) in [
        (Bench::parallel(), SL_STATE_MUTING_MUTING1),
        (Bench::parallel(), SL_STATE_MUTING_MUTING4),
        (Bench::sequential(), 6),
        (Bench::sequential(), 7),
        (Bench::sequential(), 18),
    ] {
        let mut b = bench;
        b.start();
        b.fb.stPrivate.stHeader.nState = state;
        b.fb.stPrivate.stHeader.seal();
        assert_eq!(b.cycle(), SL_E_CORRUPT, "state {state}");
        b.expect(SL_STATE_ERROR, ERROR_OUT);
        assert_eq!(b.fb.nDiag, SL_DIAG_CORRUPT);
    }
}

#[test]
fn c_abi_functions() {
    use safelogic::ffi::{sl_muting_cycle, sl_muting_init};
    null_refused!(sl_muting_init, sl_muting_cycle);
    let mut b = Bench::sequential();
    b.set(0);
    assert_eq!(unsafe { sl_muting_init(&mut b.fb) }, SL_OK);
    b.fb.bRun = 1;
    assert_eq!(unsafe { sl_muting_cycle(&mut b.fb, 1) }, SL_OK);
    assert_eq!(unsafe { sl_muting_cycle(&mut b.fb, 2) }, SL_OK);
    b.expect(SL_STATE_RUN, RUN_OUT);
    // Misaligned pointer.
    let mut raw = vec![0u64; 40];
    let p = (raw.as_mut_ptr() as *mut u8).wrapping_add(1) as *mut FB_MUTING;
    assert_eq!(unsafe { sl_muting_init(p) }, SL_E_ALIGNMENT);
}

/// The block as a group member: an error in MUTING stops the group; links reach its inputs.
#[test]
fn group_member_and_links() {
    let mut m = Bench::sequential();
    m.fb.bMutingEnable = 0;
    m.set(0);
    assert_eq!(m.fb.init(), SL_OK);
    let mut a = FB_AND {
        wInputActive: 0b11,
        ..Default::default()
    };
    a.bAndIn2 = 1;
    assert_eq!(a.init(), SL_OK);
    let mut g = common::new_group(2, 1);
    let mut links = [SL_LINK::default(); 1];
    let l = common::link(
        0,
        offset_of!(FB_MUTING, bMuteOut) as u16,
        1,
        offset_of!(FB_AND, bAndIn1) as u16,
    );
    {
        let mut ms: [&mut dyn Member; 2] = [&mut m.fb, &mut a];
        assert_eq!(group::add_link(&mut g, &mut ms[..], &mut links, l), SL_OK);
        assert!(ms[0]
            .input_mut(offset_of!(FB_MUTING, bMutingIn3) as u16)
            .is_some());
        assert!(ms[0]
            .input_mut(offset_of!(FB_MUTING, bRun) as u16)
            .is_none());
        assert_eq!(
            ms[0].output(offset_of!(FB_MUTING, bMutingActive) as u16),
            Some(0)
        );
        g.bRun = 1;
        for t in 0..3 {
            group::cycle(&mut g, &mut ms[..], &links, t);
        }
        assert_eq!(ms[0].state(), SL_STATE_RUN);
        assert_eq!(ms[1].output(offset_of!(FB_AND, bAndOut) as u16), Some(1));
    }
    // Enable TRUE and an intrusion: sequence violation, group ERROR.
    m.fb.bMutingEnable = 1;
    m.fb.bOSSDIn1 = 0;
    let mut ms: [&mut dyn Member; 2] = [&mut m.fb, &mut a];
    group::cycle(&mut g, &mut ms[..], &links, 3);
    assert_eq!(g.nState, SL_STATE_ERROR);
    assert_eq!(g.nFailedMember, 0);
    assert_eq!(ms[1].output(offset_of!(FB_AND, bAndOut) as u16), Some(0));
}

#[test]
fn member_via_the_c_abi() {
    use safelogic::ffi::{sl_group_add_member, sl_group_cycle};
    let mut m = Bench::sequential();
    m.set(0);
    assert_eq!(m.fb.init(), SL_OK);
    let mut g = SL_GROUP::default();
    let mut members = [SL_MEMBER::default(); 1];
    let mut links = [SL_LINK::default(); 1];
    common::c_group_init(&mut g, (members.as_mut_ptr(), 1), (links.as_mut_ptr(), 1));
    let mut idx = 0xFFFFu16;
    assert_eq!(
        unsafe {
            sl_group_add_member(
                &mut g,
                members.as_mut_ptr(),
                SL_TYPE_MUTING,
                (&mut m.fb as *mut FB_MUTING).cast(),
                &mut idx,
            )
        },
        SL_OK
    );
    assert_eq!(idx, 0);
    g.bRun = 1;
    for t in 0..3 {
        assert_eq!(
            unsafe { sl_group_cycle(&mut g, members.as_mut_ptr(), links.as_mut_ptr(), t) },
            SL_OK
        );
    }
    assert_eq!(m.fb.nState, SL_STATE_RUN);
    assert_eq!(g.bFbRun, 1);
}

// ---------------------------------------------------------------------------------------
// Properties

fn config() -> impl Strategy<Value = (u16, u32, u16)> {
    // (active, options, negated) valid configurations.
    prop_oneof![
        Just((0x3F, SL_OPT_MUTING_SEQUENTIAL)),
        Just((0x0F, SL_OPT_MUTING_SEQUENTIAL)),
        Just((0x3B, SL_OPT_MUTING_SEQUENTIAL | SL_OPT_MUTING_BACKWARDS)),
        Just((0x3F, 0)),
        Just((0x37, SL_OPT_MUTING_BACKWARDS)),
        Just((0x3F, SL_OPT_MUTING_OSSD_CHECK_OPTIONAL)),
        Just((
            0x3F,
            SL_OPT_MUTING_SEQUENTIAL | SL_OPT_MUTING_OSSD_CHECK_OPTIONAL
        )),
    ]
    .prop_flat_map(|(a, o)| {
        (
            Just(a),
            (0u32..4).prop_map(move |e| o | e),
            (0u16..0x40).prop_map(move |n| n & a),
        )
    })
}

fn is_muting(s: u8) -> bool {
    (SL_STATE_MUTING_MUTING1..=SL_STATE_MUTING_MUTING9).contains(&s)
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_SAFE, SL_STATE_STOP, SL_STATE_ERROR];
    /// No output TRUE in STOP, ERROR, RESET (and SAFE); bError TRUE exactly in ERROR;
    /// MuteOut TRUE only with the field clear or muting active; MutingActive exactly in the
    /// MUTING states; EDM bits never set; nState always one of the block's states.
    fn output_invariants(
        (active, options, negated) in config(),
        times in (0u32..80, 0u32..80, 0u32..40, 0u32..500, 0u32..60),
        steps in proptest::collection::vec(
            (any::<u8>(), any::<u8>(), 0u8..32, 0u8..4, 0u32..40, 0u8..40),
            1..200,
        ),
    ) {
        let mut fb = FB_MUTING {
            wInputActive: active,
            wInputNegated: negated,
            dwOptions: options,
            tDiscTimeOSSD: if active & 0b1100 == 0b1100 { times.0 } else { 0 },
            tDiscTime12: if options & SL_OPT_MUTING_SEQUENTIAL == 0 { times.1 } else { 0 },
            tDiscTime34: if options & SL_OPT_MUTING_SEQUENTIAL == 0 { times.1 / 2 } else { 0 },
            tFilterTime: times.2,
            tMaxMutingTime: times.3 * 6,
            tMuteDelOutDelay: times.4,
            ..Default::default()
        };
        prop_assert_eq!(fb.init(), SL_OK);
        let mut t = 0u32;
        // A guided walk along the step table (forwards or mirrored), with noise: a random
        // input flipped now and then, Enable dropping, Run and ErrAck toggling, so that the
        // MUTING states, violations, discrepancies and DELAYOUT all occur.
        let (mut pos, mut back) = (0usize, false);
        for (mv, noise, ctl, edm, dt, odd) in steps {
            if fb.nState == SL_STATE_ERROR && mv % 2 == 0 {
                // The operator clears the muting area.
                pos = 0;
            } else if mv % 4 == 1 {
                pos = (pos + 1) % 10;
                if pos == 0 {
                    back = noise & 1 != 0;
                }
            }
            let pat = if back { mirror(TABLE[pos]) } else { TABLE[pos] };
            // Pattern → logical inputs (wInputActive order) → raw bytes.
            let mut logical = (pat & (M1 | M2))
                | if pat & F == 0 { 0b1100 } else { 0 }
                | if pat & M3 != 0 { 0b1_0000 } else { 0 }
                | if pat & M4 != 0 { 0b10_0000 } else { 0 };
            if noise >= 240 {
                logical ^= 1 << (noise % 6);
            }
            let raw = logical ^ (negated as u8);
            let bit = |i: u8| (raw >> i) & 1;
            // Inputs mostly valid, sometimes an invalid byte.
            fb.bMutingIn1 = if odd == 39 { 2 } else { bit(0) };
            fb.bMutingIn2 = bit(1);
            fb.bOSSDIn1 = bit(2);
            fb.bOSSDIn2 = if odd == 38 { 5 } else { bit(3) };
            fb.bMutingIn3 = bit(4);
            fb.bMutingIn4 = bit(5);
            fb.bMutingEnable = u8::from(!(200..204).contains(&mv));
            fb.bRun = u8::from(ctl != 0);
            fb.bErrAck = u8::from((1..=4).contains(&ctl));
            fb.bEDM1 = edm & 1;
            fb.bEDM2 = (edm >> 1) & 1;
            t = t.wrapping_add(dt);
            let rc = fb.cycle(t);
            common::saw(fb.nState);
            prop_assert!(matches!(rc, SL_OK | SL_E_INVALID_BOOL), "rc {}", rc);
            let s = fb.nState;
            prop_assert!(matches!(s, 1..=5 | 8 | 9..=17), "state {}", s);
            if matches!(s, SL_STATE_STOP | SL_STATE_ERROR | SL_STATE_RESET | SL_STATE_SAFE) {
                prop_assert_eq!((fb.bMutingActive, fb.bMuteOut, fb.bMuteDelOut), (0, 0, 0));
            }
            prop_assert_eq!(fb.bError == 1, s == SL_STATE_ERROR);
            prop_assert_eq!(fb.bMutingActive == 1, is_muting(s));
            // The protective field as the inputs say (invalid byte = interrupted).
            let ossd = [fb.bOSSDIn1, fb.bOSSDIn2];
            let field_clear = (0..2).all(|i| {
                let bit = 1u16 << (2 + i);
                active & bit == 0
                    || (ossd[i] <= 1 && (ossd[i] == 1) != (negated & bit != 0))
            });
            if fb.bMuteOut == 1 {
                prop_assert!(field_clear || fb.bMutingActive == 1, "MuteOut with the field interrupted");
            }
            prop_assert_eq!(fb.nDiag & (SL_DIAG_EDM1 | SL_DIAG_EDM2), 0);
            if fb.nDiag != 0 {
                prop_assert!(matches!(s, SL_STATE_ERROR | SL_STATE_DELAYOUT));
            }
        }
    }
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RUN, SL_STATE_SAFE, SL_STATE_STOP];
    /// Run FALSE: STOP (or ERROR) with every output FALSE in the same call.
    fn run_false_switches_off_at_once(
        prefix in proptest::collection::vec((0u8..64, 0u32..30), 0..60),
    ) {
        let mut b = Bench::sequential();
        b.fb.tMuteDelOutDelay = 100;
        b.start();
        for (p, dt) in prefix {
            b.set(p & 0x1F);
            b.fb.bMutingEnable = (p >> 5) & 1;
            b.step(dt);
            common::saw(b.fb.nState);
        }
        b.fb.bRun = 0;
        b.cycle();
        common::saw(b.fb.nState);
        prop_assert!(matches!(b.fb.nState, SL_STATE_STOP | SL_STATE_ERROR | SL_STATE_RESET));
        prop_assert_eq!((b.fb.bMutingActive, b.fb.bMuteOut, b.fb.bMuteDelOut), (0, 0, 0));
    }
}

common::property! {
    cases: common::depth_cases(10_000), reach: [
        SL_STATE_RUN, SL_STATE_MUTING_MUTING1, SL_STATE_MUTING_MUTING2, SL_STATE_MUTING_MUTING3,
        SL_STATE_MUTING_MUTING4, SL_STATE_MUTING_MUTING5, SL_STATE_MUTING_MUTING6,
        SL_STATE_MUTING_MUTING7, SL_STATE_MUTING_MUTING8, SL_STATE_MUTING_MUTING9,
    ];
    /// Valid sequences of every kind complete without error whatever the dwell times, and
    /// bounces of the muting inputs shorter than the filter time change nothing (M1–M5, M9).
    /// Each step holds long enough for its change to be taken over before the bounce; a
    /// bounce of `len` < 40 ms is seen for at most `len` + 9 ms (cycle spacing) < 50 ms.
    fn valid_sequences_complete(
        kind in 0usize..4,
        dwell in proptest::collection::vec((140u32..300, any::<bool>(), 0u8..4, 1u32..40), 10),
        dts in proptest::collection::vec(1u32..10, 16),
    ) {
        let (mut b, back, groups) = match kind {
            0 => (Bench::new(ALL_INPUTS, SL_OPT_MUTING_SEQUENTIAL), false, false),
            1 => (Bench::new(ALL_INPUTS, SL_OPT_MUTING_SEQUENTIAL | SL_OPT_MUTING_BACKWARDS), true, false),
            2 => (Bench::parallel(), false, true),
            _ => {
                let mut b = Bench::parallel();
                b.fb.dwOptions = SL_OPT_MUTING_BACKWARDS;
                (b, true, true)
            }
        };
        b.fb.tFilterTime = 50;
        b.fb.tDiscTime12 = 0;
        b.fb.tDiscTime34 = 0;
        b.fb.tMaxMutingTime = 600_000;
        b.start();
        let patterns: Vec<u8> = if groups {
            vec![M1 | M2, M1 | M2 | F, M1 | M2 | F | M3 | M4, F | M3 | M4, M3 | M4, 0]
        } else {
            TABLE[1..].to_vec()
        };
        let mut k = 0usize;
        for (i, &p) in patterns.iter().enumerate() {
            let p = if back { mirror(p) } else { p };
            let (hold, bounce, which, len) = dwell[i];
            let bit = [M1, M2, M3, M4][usize::from(which)];
            let start = b.t;
            let mut bounced = false;
            while b.t.wrapping_sub(start) < hold {
                let in_bounce = bounce && !bounced
                    && b.t.wrapping_sub(start) >= 75
                    && b.t.wrapping_sub(start) < 75 + len;
                if bounce && !in_bounce && b.t.wrapping_sub(start) >= 75 + len {
                    bounced = true;
                }
                b.set(if in_bounce { p ^ bit } else { p });
                b.step(dts[k % dts.len()]);
                common::saw(b.fb.nState);
                k += 1;
                prop_assert_ne!(b.fb.nState, SL_STATE_ERROR, "diag {:#x}", b.fb.nDiag);
                prop_assert_eq!(b.fb.bMuteOut, 1);
                if i > 0 && i + 1 < patterns.len() {
                    prop_assert_eq!(b.fb.bMutingActive, 1);
                }
            }
        }
        prop_assert_eq!(b.fb.nState, SL_STATE_RUN);
        prop_assert_eq!(b.fb.nDiag, 0);
    }
}
