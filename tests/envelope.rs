//! The cycle envelope common to FB_ESTOP and FB_MON: clock, parameter latching and change,
//! invalid BOOLs, never-initialised and corrupt private state, configuration errors, Run,
//! ERROR / RESET and acknowledgement.
//!
//! References: "ABI §n" = shared/design/ABI.md; "Cn"/"Gn" = docs/semantics.md rows;
//! "§4.4.x"/"§4.5.x" = twinsafe-logic-fb-manual.txt. Most tests run for both blocks
//! (`<test>::estop`, `<test>::mon`; MON with manual restart so both need the Restart
//! sequence).

mod common;
use common::*;
use safelogic::*;

const MANUAL: u32 = SL_OPT_MANUAL_RESTART;

/// Parameter access the generic tests need.
trait Params: Guard {
    fn set_delay(&mut self, t: u32);
    fn set_disc12(&mut self, t: u32);
    fn options(&mut self) -> &mut u32;
    fn negated(&mut self) -> &mut u16;
    fn set_edm2_reset(&mut self, t: u32);
    fn private_bytes(&mut self) -> &mut [u8];
}

impl Params for FB_ESTOP {
    fn set_delay(&mut self, t: u32) {
        self.tEStopDelOutDelay = t;
    }
    fn set_disc12(&mut self, t: u32) {
        self.tDiscTime12 = t;
    }
    fn options(&mut self) -> &mut u32 {
        &mut self.dwOptions
    }
    fn negated(&mut self) -> &mut u16 {
        &mut self.wInputNegated
    }
    fn set_edm2_reset(&mut self, t: u32) {
        self.tEDM2ResetTime = t;
    }
    fn private_bytes(&mut self) -> &mut [u8] {
        private_bytes(&mut self.stPrivate)
    }
}

impl Params for FB_MON {
    fn set_delay(&mut self, t: u32) {
        self.tMonDelOutDelay = t;
    }
    fn set_disc12(&mut self, t: u32) {
        self.tDiscTime12 = t;
    }
    fn options(&mut self) -> &mut u32 {
        &mut self.dwOptions
    }
    fn negated(&mut self) -> &mut u16 {
        &mut self.wInputNegated
    }
    fn set_edm2_reset(&mut self, t: u32) {
        self.tEDM2ResetTime = t;
    }
    fn private_bytes(&mut self) -> &mut [u8] {
        private_bytes(&mut self.stPrivate)
    }
}

fn private_bytes(p: &mut SL_GUARD_PRIVATE) -> &mut [u8] {
    // SAFETY: SL_GUARD_PRIVATE is a repr(C) struct of plain integers (ABI §3.6: no
    // pointers); every byte pattern is a valid value of it.
    unsafe {
        std::slice::from_raw_parts_mut(
            (p as *mut SL_GUARD_PRIVATE).cast::<u8>(),
            std::mem::size_of::<SL_GUARD_PRIVATE>(),
        )
    }
}

/// Pair 1 (inputs 1, 2) with a 100 ms discrepancy time, break contacts, all TRUE.
fn estop_pair() -> FB_ESTOP {
    let mut fb = estop(0b11);
    fb.tDiscTime12 = 100;
    fb
}

/// MonIn1/MonIn2 pair with 100 ms, manual restart.
fn mon_pair() -> FB_MON {
    let mut fb = mon(0b11, MANUAL);
    fb.tDiscTime12 = 100;
    fb
}

/// init, STOP → SAFE, Restart sequence → RUN (G12).
fn running<B: Guard>(fb: B) -> Sim<B> {
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.restart();
    s
}

/// Discrepancy error on pair 1 (input 1 FALSE for 100 ms), ending in ERROR with bit 0.
#[track_caller]
fn disc_error<B: Guard>(s: &mut Sim<B>) {
    s.fb.set_in(0, 0);
    s.adv(1);
    s.adv(100);
    expect_error(&s.fb, SL_DIAG_DISC1);
}

macro_rules! both {
    ($name:ident) => {
        mod $name {
            use super::*;
            #[test]
            fn estop() {
                super::$name(estop_pair());
            }
            #[test]
            fn mon() {
                super::$name(mon_pair());
            }
        }
    };
}

// ---------------------------------------------------------------------------------------
// Clock (ABI §4 wrapping clock, ABI §5 SL_E_CLOCK, C4)
// ---------------------------------------------------------------------------------------

/// ABI §5 SL_E_CLOCK "tNow went backwards ... ERROR (4), bError TRUE"; C4: diag bit 14;
/// "one ErrAck edge clears it" (the condition does not remain).
fn clock_backwards_is_an_acknowledgeable_error<B: Guard>(fb: B) {
    let mut s = running(fb);
    let t = s.t;
    assert_eq!(s.at(t - 1), SL_E_CLOCK);
    expect_error(&s.fb, SL_DIAG_CLOCK);
    // later calls go forward from the resynchronised clock: no new clock error
    assert_eq!(s.at(t), SL_OK);
    expect_error(&s.fb, SL_DIAG_CLOCK);
    s.acknowledge(SL_STATE_SAFE);
    s.restart();
}
both!(clock_backwards_is_an_acknowledgeable_error);

/// C4 "Applies in every state, STOP included"; C9: ERROR persists with bRun FALSE and
/// RESET is left to STOP.
fn clock_backwards_in_stop_is_an_error<B: Guard>(mut fb: B) {
    fb.set_run(0);
    let mut s = Sim::new(fb, T0);
    s.step(10, SL_STATE_STOP);
    s.step(10, SL_STATE_STOP);
    assert_eq!(s.at(T0), SL_E_CLOCK);
    expect_error(&s.fb, SL_DIAG_CLOCK);
    s.step(10, SL_STATE_ERROR);
    s.acknowledge(SL_STATE_STOP);
}
both!(clock_backwards_in_stop_is_an_error);

/// ABI §5 "wrapping difference to the last call ≥ 2^31": 2^31 - 1 forward is time passing,
/// 2^31 forward is a clock error.
fn clock_difference_limit_is_2_pow_31<B: Guard>(fb: B) {
    let mut s = running(fb);
    s.step(0x7FFF_FFFF, SL_STATE_RUN);
    assert_eq!(s.adv(0x8000_0000), SL_E_CLOCK);
    expect_error(&s.fb, SL_DIAG_CLOCK);
}
both!(clock_difference_limit_is_2_pow_31);

/// C4 "The first call after init has no previous time and is never a clock error"; a time
/// step of 0 is no error.
fn first_call_after_init_and_zero_steps_are_no_clock_error<B: Guard>(fb: B) {
    let mut s = running(fb);
    s.step(0, SL_STATE_RUN);
    s.step(0, SL_STATE_RUN);
    // re-init, then a call "before" every earlier call
    assert_eq!(s.fb.init(), SL_OK);
    expect(&s.fb, SL_STATE_STOP);
    assert_eq!(s.at(T0 - 5000), SL_OK);
    expect(&s.fb, SL_STATE_SAFE);
}
both!(first_call_after_init_and_zero_steps_are_no_clock_error);

/// C8 "An error entered in a call cannot be acknowledged in the same call, even if ErrAck
/// rises in it".
fn errack_rising_in_the_call_of_the_error_does_not_acknowledge<B: Guard>(fb: B) {
    let mut s = running(fb);
    let t = s.t;
    s.fb.set_errack(1);
    assert_eq!(s.at(t - 10), SL_E_CLOCK);
    expect_error(&s.fb, SL_DIAG_CLOCK);
    for _ in 0..5 {
        s.adv(10);
        expect_error(&s.fb, SL_DIAG_CLOCK);
    }
    s.fb.set_errack(0);
    s.adv(10);
    expect_error(&s.fb, SL_DIAG_CLOCK);
    s.acknowledge(SL_STATE_SAFE);
}
both!(errack_rising_in_the_call_of_the_error_does_not_acknowledge);

// ---------------------------------------------------------------------------------------
// Parameters (ABI §7 Parameters, ABI §5 SL_E_PARAM_CHANGED, C5)
// ---------------------------------------------------------------------------------------

/// ABI §5 SL_E_PARAM_CHANGED "a parameter changed while the block was not in STOP: ERROR
/// (4), bError TRUE"; C5: diag bit 13, every such call returns SL_E_PARAM_CHANGED, the
/// mismatch blocks acknowledgement while bRun is TRUE; restoring the old value clears it.
fn parameter_changed_while_running<B: Params>(fb: B) {
    let mut s = running(fb);
    s.fb.set_delay(500);
    assert_eq!(s.adv(1), SL_E_PARAM_CHANGED);
    expect_error(&s.fb, SL_DIAG_PARAM_CHANGED);
    assert_eq!(s.adv(1), SL_E_PARAM_CHANGED);
    s.fb.set_errack(1);
    assert_eq!(s.adv(1), SL_E_PARAM_CHANGED);
    expect_error(&s.fb, SL_DIAG_PARAM_CHANGED);
    s.fb.set_errack(0);
    assert_eq!(s.adv(1), SL_E_PARAM_CHANGED);
    // restore the latched value: the condition is gone
    s.fb.set_delay(0);
    assert_eq!(s.adv(1), SL_OK);
    expect_error(&s.fb, SL_DIAG_PARAM_CHANGED);
    s.acknowledge(SL_STATE_SAFE);
    s.restart();
}
both!(parameter_changed_while_running);

/// ABI §5 "while the block was not in STOP": SAFE and START count too.
fn parameter_changed_in_safe_or_start<B: Params>(fb: B) {
    let mut s = Sim::new(fb.clone(), T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.set_disc12(99);
    assert_eq!(s.adv(1), SL_E_PARAM_CHANGED);
    expect_error(&s.fb, SL_DIAG_PARAM_CHANGED);

    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.set_restart(1);
    s.step(1, SL_STATE_START);
    *s.fb.options() |= SL_OPT_SAFE_INPUTS_AFTER_DISC;
    assert_eq!(s.adv(1), SL_E_PARAM_CHANGED);
    expect_error(&s.fb, SL_DIAG_PARAM_CHANGED);
}
both!(parameter_changed_in_safe_or_start);

/// ABI §7 "Parameters are latched ... at every STOP→run transition"; C5: a change while
/// stopped is no error and takes effect at the next STOP→run.
fn parameter_changed_while_stopped_is_latched_at_start<B: Params>(fb: B) {
    let mut s = running(fb);
    s.fb.set_run(0);
    s.step(1, SL_STATE_STOP);
    s.fb.set_delay(100);
    s.step(10, SL_STATE_STOP);
    s.step(10, SL_STATE_STOP);
    s.start_up(SL_STATE_SAFE);
    s.restart();
    // the new delay is in force
    s.fb.set_in(0, 0);
    s.fb.set_in(1, 0);
    s.step(1, SL_STATE_DELAYOUT);
    s.step(99, SL_STATE_DELAYOUT);
    s.step(1, SL_STATE_SAFE);
}
both!(parameter_changed_while_stopped_is_latched_at_start);

/// C5 "With bRun FALSE it is tolerated: a block on its way to STOP ... latches the new
/// values at the next STOP→run".
fn parameter_changed_in_the_call_that_stops_is_tolerated<B: Params>(fb: B) {
    let mut s = running(fb);
    s.fb.set_run(0);
    s.fb.set_delay(50);
    s.step(1, SL_STATE_STOP);
    s.start_up(SL_STATE_SAFE);
    s.restart();
    s.fb.set_in(1, 0);
    s.fb.set_in(0, 0);
    s.step(1, SL_STATE_DELAYOUT);
    s.step(50, SL_STATE_SAFE);
}
both!(parameter_changed_in_the_call_that_stops_is_tolerated);

/// C5 "(or acknowledged with bRun FALSE) latches the new values at the next STOP→run";
/// "Without the bRun exception a changed parameter could never be adopted after the error";
/// every call before STOP returns SL_E_PARAM_CHANGED (issue 16 item 5).
fn parameter_change_error_acknowledged_with_run_false_adopts_the_new_value<B: Params>(fb: B) {
    let mut s = running(fb);
    s.fb.set_delay(70);
    assert_eq!(s.adv(1), SL_E_PARAM_CHANGED);
    expect_error(&s.fb, SL_DIAG_PARAM_CHANGED);
    s.fb.set_run(0);
    // Still reported with bRun FALSE (not in STOP: ABI §5, §7), no longer blocking.
    assert_eq!(s.adv(1), SL_E_PARAM_CHANGED);
    expect_error(&s.fb, SL_DIAG_PARAM_CHANGED); // C9: ERROR persists with bRun FALSE
    s.acknowledge(SL_STATE_STOP);
    s.start_up(SL_STATE_SAFE);
    s.restart();
    s.fb.set_in(0, 0);
    s.fb.set_in(1, 0);
    s.step(1, SL_STATE_DELAYOUT);
    s.step(69, SL_STATE_DELAYOUT);
    s.step(1, SL_STATE_SAFE);
}
both!(parameter_change_error_acknowledged_with_run_false_adopts_the_new_value);

/// C5 for every parameter field of FB_ESTOP (ABI §8): any change in RUN is detected.
#[test]
fn every_estop_parameter_change_is_detected() {
    type Change = fn(&mut FB_ESTOP);
    let changes: [(&str, Change); 10] = [
        ("tDiscTime12", |f| f.tDiscTime12 = 101),
        ("tDiscTime34", |f| f.tDiscTime34 = 1),
        ("tDiscTime56", |f| f.tDiscTime56 = 1),
        ("tDiscTime78", |f| f.tDiscTime78 = 1),
        ("tEDM1ResetTime", |f| f.tEDM1ResetTime = 1),
        ("tEDM2ResetTime", |f| f.tEDM2ResetTime = 1),
        ("tEStopDelOutDelay", |f| f.tEStopDelOutDelay = 1),
        ("wInputActive", |f| f.wInputActive = 0b111),
        ("wInputNegated", |f| f.wInputNegated = 0b1000_0000),
        ("dwOptions", |f| f.dwOptions = SL_OPT_EDM1),
    ];
    for (name, change) in changes {
        let mut s = running(estop_pair());
        change(&mut s.fb);
        assert_eq!(s.adv(1), SL_E_PARAM_CHANGED, "{name}");
        expect_error(&s.fb, SL_DIAG_PARAM_CHANGED);
    }
}

/// C5 for every parameter field of FB_MON (ABI §8).
#[test]
fn every_mon_parameter_change_is_detected() {
    type Change = fn(&mut FB_MON);
    let changes: [(&str, Change); 9] = [
        ("tDiscTime12", |f| f.tDiscTime12 = 101),
        ("tDiscTime34", |f| f.tDiscTime34 = 1),
        ("tDiscTimeSecure12", |f| f.tDiscTimeSecure12 = 1),
        ("tEDM1ResetTime", |f| f.tEDM1ResetTime = 1),
        ("tEDM2ResetTime", |f| f.tEDM2ResetTime = 1),
        ("tMonDelOutDelay", |f| f.tMonDelOutDelay = 1),
        ("wInputActive", |f| f.wInputActive = 0b111),
        ("wInputNegated", |f| f.wInputNegated = 0b1000),
        ("dwOptions", |f| f.dwOptions = 0),
    ];
    for (name, change) in changes {
        let mut s = running(mon_pair());
        change(&mut s.fb);
        assert_eq!(s.adv(1), SL_E_PARAM_CHANGED, "{name}");
        expect_error(&s.fb, SL_DIAG_PARAM_CHANGED);
    }
}

// ---------------------------------------------------------------------------------------
// Invalid BOOL bytes (ABI §2, ABI §5 SL_E_INVALID_BOOL, C7)
// ---------------------------------------------------------------------------------------

/// ABI §2 "a safety input then requests the safe state ... finishes the cycle, and the call
/// returns SL_E_INVALID_BOOL"; C7 "An invalid safety input is logical FALSE whatever its
/// negation bit".
fn invalid_safety_input_requests_the_safe_state<B: Params>(fb: B) {
    for negated in [false, true] {
        for bad in [2u8, 0x80, 0xFF] {
            let mut f = fb.clone();
            if negated {
                // input 2 as make contact (wInputNegated bit 1, ABI §8): raw 0 is TRUE
                *f.negated() |= 0b10;
                f.set_in(1, 0);
            }
            let mut s = running(f);
            s.fb.set_in(1, bad);
            assert_eq!(s.adv(1), SL_E_INVALID_BOOL, "byte {bad}");
            expect(&s.fb, SL_STATE_SAFE);
            s.fb.set_in(1, u8::from(!negated));
            assert_eq!(s.adv(1), SL_OK);
            expect(&s.fb, SL_STATE_SAFE);
        }
    }
}
both!(invalid_safety_input_requests_the_safe_state);

/// An invalid byte in a two-channel pair is a logical FALSE for discrepancy monitoring too
/// (ABI §2, ABI §7 Pairs): FALSE/invalid agree, TRUE/invalid differ.
fn invalid_byte_in_a_pair_counts_as_logical_false<B: Params>(fb: B) {
    let mut s = running(fb);
    s.fb.set_in(0, 0);
    s.fb.set_in(1, 7);
    assert_eq!(s.adv(1), SL_E_INVALID_BOOL);
    expect(&s.fb, SL_STATE_SAFE);
    assert_eq!(s.adv(1000), SL_E_INVALID_BOOL);
    expect(&s.fb, SL_STATE_SAFE);
    s.fb.set_in(0, 1);
    assert_eq!(s.adv(1), SL_E_INVALID_BOOL);
    expect(&s.fb, SL_STATE_SAFE);
    assert_eq!(s.adv(100), SL_E_INVALID_BOOL);
    expect_error(&s.fb, SL_DIAG_DISC1);
}
both!(invalid_byte_in_a_pair_counts_as_logical_false);

/// C7 "Only bytes the block reads count: inactive inputs, inactive EDMs ... are ignored,
/// also for SL_E_INVALID_BOOL".
fn invalid_bytes_of_inactive_inputs_and_edms_are_ignored<B: Params>(fb: B) {
    let mut s = running(fb);
    for i in 2..6 {
        s.fb.set_in(i, 0xAA);
    }
    s.fb.set_edm(1, 3);
    s.fb.set_edm(2, 0xFE);
    s.step(1, SL_STATE_RUN);
    s.step(1000, SL_STATE_RUN);
}
both!(invalid_bytes_of_inactive_inputs_and_edms_are_ignored);

/// C7 "a Restart going 1 → 2 does not count as a falling edge, so it cannot enable outputs;
/// it aborts the restart sequence instead (START → SAFE)"; G1.
fn invalid_restart_byte_gives_no_falling_edge<B: Guard>(fb: B) {
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.set_restart(1);
    s.step(1, SL_STATE_START);
    s.fb.set_restart(2);
    assert_eq!(s.adv(1), SL_E_INVALID_BOOL);
    expect(&s.fb, SL_STATE_SAFE);
    s.fb.set_restart(0);
    assert_eq!(s.adv(1), SL_OK);
    expect(&s.fb, SL_STATE_SAFE);
    // an invalid Restart reads FALSE: no START either
    s.fb.set_restart(0xFF);
    assert_eq!(s.adv(1), SL_E_INVALID_BOOL);
    expect(&s.fb, SL_STATE_SAFE);
    s.fb.set_restart(0);
    s.step(1, SL_STATE_SAFE);
    s.restart();
}
both!(invalid_restart_byte_gives_no_falling_edge);

/// ABI §2 "Run ... read FALSE": an invalid Run byte puts the block in STOP.
fn invalid_run_byte_reads_false<B: Guard>(fb: B) {
    let mut s = running(fb);
    s.fb.set_run(0x42);
    assert_eq!(s.adv(1), SL_E_INVALID_BOOL);
    expect(&s.fb, SL_STATE_STOP);
    assert_eq!(s.adv(1), SL_E_INVALID_BOOL);
    expect(&s.fb, SL_STATE_STOP);
}
both!(invalid_run_byte_reads_false);

/// ABI §2 "ErrAck ... read FALSE"; C7 "produces no edge": 0 → 2 does not acknowledge, and in
/// RESET 1 → 2 → 0 is no falling edge.
fn invalid_errack_byte_gives_no_edge<B: Guard>(fb: B) {
    let mut s = running(fb);
    assert_eq!(s.at(s.t - 1), SL_E_CLOCK);
    s.fb.set_errack(2);
    assert_eq!(s.adv(1), SL_E_INVALID_BOOL);
    expect_error(&s.fb, SL_DIAG_CLOCK);
    s.fb.set_errack(0);
    s.adv(1);
    expect_error(&s.fb, SL_DIAG_CLOCK);
    s.fb.set_errack(1);
    s.step(1, SL_STATE_RESET);
    s.fb.set_errack(2);
    assert_eq!(s.adv(1), SL_E_INVALID_BOOL);
    expect(&s.fb, SL_STATE_RESET);
    s.fb.set_errack(0);
    s.step(1, SL_STATE_RESET);
    s.fb.set_errack(1);
    s.step(1, SL_STATE_RESET);
    s.fb.set_errack(0);
    s.step(1, SL_STATE_SAFE);
}
both!(invalid_errack_byte_gives_no_edge);

/// ABI §2 "finishes the cycle ... outputs as computed": an invalid ErrAck while running does
/// not disturb RUN.
fn invalid_errack_while_running_keeps_running<B: Guard>(fb: B) {
    let mut s = running(fb);
    s.fb.set_errack(9);
    assert_eq!(s.adv(1), SL_E_INVALID_BOOL);
    expect(&s.fb, SL_STATE_RUN);
}
both!(invalid_errack_while_running_keeps_running);

/// C7 "An invalid EDM byte is neither TRUE (blocks restart, keeps an EDM error) nor FALSE
/// (does not satisfy the EDM reset time)" — restart check (ABI §7).
fn invalid_edm_byte_fails_the_restart_check<B: Params>(fb: B) {
    let mut f = fb;
    *f.options() |= SL_OPT_EDM1;
    let mut s = Sim::new(f, T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.set_edm(1, 2);
    s.fb.set_restart(1);
    assert_eq!(s.adv(1), SL_E_INVALID_BOOL);
    expect_error(&s.fb, SL_DIAG_EDM1);
    // ... and keeps the EDM error
    s.fb.set_restart(0);
    s.fb.set_errack(1);
    assert_eq!(s.adv(1), SL_E_INVALID_BOOL);
    expect_error(&s.fb, SL_DIAG_EDM1);
    s.fb.set_errack(0);
    s.fb.set_edm(1, 1);
    assert_eq!(s.adv(1), SL_OK);
    s.acknowledge(SL_STATE_SAFE);
}
both!(invalid_edm_byte_fails_the_restart_check);

/// C7: an invalid EDM byte does not satisfy the EDM reset time (§4.4.5 / §4.5.5).
fn invalid_edm_byte_does_not_satisfy_the_reset_time<B: Params>(fb: B) {
    let mut f = fb;
    *f.options() |= SL_OPT_EDM2;
    f.set_edm2_reset(30);
    let mut s = running(f);
    let tr = s.t;
    s.fb.set_edm(2, 0x10);
    assert_eq!(s.at(tr + 10), SL_E_INVALID_BOOL);
    expect(&s.fb, SL_STATE_RUN);
    assert_eq!(s.at(tr + 30), SL_E_INVALID_BOOL);
    expect_error(&s.fb, SL_DIAG_EDM2);
}
both!(invalid_edm_byte_does_not_satisfy_the_reset_time);

/// C7 with G3: an automatic MON does not leave SAFE while an active EDM byte is invalid
/// (not TRUE), and reports no EDM error.
#[test]
fn invalid_edm_byte_keeps_automatic_mon_in_safe() {
    let mut s = Sim::new(mon(0b1, SL_OPT_EDM1), T0);
    s.fb.bEDM1 = 0xC3;
    s.fb.set_run(1);
    assert_eq!(s.adv(1), SL_E_INVALID_BOOL);
    expect(&s.fb, SL_STATE_SAFE);
    for _ in 0..5 {
        assert_eq!(s.adv(10), SL_E_INVALID_BOOL);
        expect(&s.fb, SL_STATE_SAFE);
    }
    s.fb.bEDM1 = 1;
    s.step(1, SL_STATE_RUN);
}

// ---------------------------------------------------------------------------------------
// Private state (ABI §3.6, ABI §4, C2, C3)
// ---------------------------------------------------------------------------------------

/// ABI §3.6 "A private area of all zero bytes is a valid never-initialised instance"; ABI
/// §4 "cycle on a never-initialised instance initialises it first"; C2: "the cycle then runs
/// normally in the same call" (STOP → run = SAFE).
fn zeroed_private_state_is_a_never_initialised_instance<B: Params>(fb: B) {
    // never init'ed, bRun TRUE
    let mut f = fb.clone();
    assert_eq!(f.cycle(T0), SL_OK);
    expect(&f, SL_STATE_SAFE);
    assert_eq!(f.diag(), 0);
    // never init'ed, bRun FALSE
    let mut f = fb.clone();
    f.set_run(0);
    assert_eq!(f.cycle(T0), SL_OK);
    expect(&f, SL_STATE_STOP);
    // a running instance whose private area is zeroed starts over (outputs off)
    let mut s = running(fb);
    s.fb.private_bytes().fill(0);
    assert_eq!(s.adv(1), SL_OK);
    expect(&s.fb, SL_STATE_SAFE);
    s.restart();
    // zeroed, then an "earlier" time: no previous time, no clock error (C4)
    s.fb.private_bytes().fill(0);
    assert_eq!(s.at(1), SL_OK);
    expect(&s.fb, SL_STATE_SAFE);
}
both!(zeroed_private_state_is_a_never_initialised_instance);

/// ABI §3.6: only a private area of *all* zero bytes is a never-initialised instance. One
/// non-zero byte anywhere in the common header of an otherwise zeroed area makes it a
/// corrupted one (SL_E_CORRUPT, ERROR, diag bit 15), not a fresh start — whichever byte it is.
fn one_non_zero_header_byte_is_corrupt_not_never_initialised<B: Params>(fb: B) {
    let header = std::mem::size_of::<safelogic::base::header::SL_PRIVATE_HEADER>();
    for at in 0..header {
        for value in [0x01u8, 0x80] {
            let mut s = running(fb.clone());
            s.fb.private_bytes().fill(0);
            s.fb.private_bytes()[at] = value;
            assert_eq!(s.adv(1), SL_E_CORRUPT, "header byte {at} = {value:#04x}");
            expect(&s.fb, SL_STATE_ERROR);
            assert_ne!(s.fb.diag() & SL_DIAG_CORRUPT, 0);
        }
    }
}
both!(one_non_zero_header_byte_is_corrupt_not_never_initialised);

/// ABI §5 SL_E_CORRUPT "the private state failed its integrity check: ERROR (4), bError
/// TRUE"; C3 "put into ERROR with diag bit 15"; outputs FALSE. Several garbage patterns,
/// from a running and from a fresh instance.
fn garbage_private_state_is_corrupt<B: Params>(fb: B) {
    let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
    // As long as the private state (ESTOP and MON: 80 bytes since their latched times are
    // full width).
    let len = running(fb.clone()).fb.private_bytes().len();
    let mut patterns: Vec<Vec<u8>> = [0xFFu8, 0xA5, 0x01, 0x5A]
        .iter()
        .map(|&b| vec![b; len])
        .collect();
    for _ in 0..8 {
        patterns.push(
            (0..len)
                .map(|_| {
                    x ^= x << 13;
                    x ^= x >> 7;
                    x ^= x << 17;
                    (x >> 24) as u8
                })
                .collect(),
        );
    }
    for p in &patterns {
        for from_running in [false, true] {
            let mut s = if from_running {
                running(fb.clone())
            } else {
                Sim::new(fb.clone(), T0)
            };
            let n = s.fb.private_bytes().len();
            s.fb.private_bytes().copy_from_slice(&p[..n]);
            assert_eq!(s.adv(1), SL_E_CORRUPT, "pattern {:02x?}", &p[..8]);
            expect_error(&s.fb, SL_DIAG_CORRUPT);
        }
    }
}
both!(garbage_private_state_is_corrupt);

/// G4 "Clock and corruption errors do not remain": one acknowledgement clears a corrupt
/// error; the block starts over.
fn corrupt_error_is_acknowledgeable<B: Params>(fb: B) {
    let mut s = running(fb);
    s.fb.private_bytes().fill(0xEE);
    assert_eq!(s.adv(1), SL_E_CORRUPT);
    expect_error(&s.fb, SL_DIAG_CORRUPT);
    s.step(1, SL_STATE_ERROR);
    s.acknowledge(SL_STATE_SAFE);
    s.restart();
}
both!(corrupt_error_is_acknowledgeable);

/// C3 "the block's magic word": an FB_MON's private state copied into an FB_ESTOP (and the
/// other way round) is SL_E_CORRUPT.
#[test]
fn private_state_of_the_other_block_type_is_corrupt() {
    let mon_s = running(mon_pair());
    let mut s = running(estop_pair());
    s.fb.stPrivate = mon_s.fb.stPrivate;
    assert_eq!(s.adv(1), SL_E_CORRUPT);
    expect_error(&s.fb, SL_DIAG_CORRUPT);

    let estop_s = running(estop_pair());
    let mut s = running(mon_pair());
    s.fb.stPrivate = estop_s.fb.stPrivate;
    assert_eq!(s.adv(1), SL_E_CORRUPT);
    expect_error(&s.fb, SL_DIAG_CORRUPT);
}

// ---------------------------------------------------------------------------------------
// Configuration errors (ABI §5 SL_E_CONFIG, C6, C10, G11, G13)
// ---------------------------------------------------------------------------------------

/// ABI §5 SL_E_CONFIG "safe (all FALSE), nState = STOP (2)"; C6: init returns it and
/// every call returns it while the latched parameters are invalid, with bRun TRUE or FALSE;
/// the restart sequence does nothing.
#[track_caller]
fn assert_config_error<B: Guard>(fb: B, what: &str) {
    let mut f = fb.clone();
    assert_eq!(f.init(), SL_E_CONFIG, "init: {what}");
    expect(&f, SL_STATE_STOP);
    let mut t = T0;
    for (run, restart) in [(1, 0), (1, 1), (1, 0), (0, 0), (1, 0)] {
        t += 10;
        f.set_run(run);
        f.set_restart(restart);
        assert_eq!(f.cycle(t), SL_E_CONFIG, "cycle: {what}");
        expect(&f, SL_STATE_STOP);
        assert_eq!(f.diag(), 0);
    }
    // never initialised: the first cycle latches and reports the same
    let mut f = fb;
    assert_eq!(f.cycle(T0), SL_E_CONFIG, "first cycle: {what}");
    expect(&f, SL_STATE_STOP);
}

/// ABI §5 "no active input"; §4.4.3/§4.5.3 "In the default state all inputs are disabled";
/// G13.
#[test]
fn no_active_input_is_a_config_error() {
    assert_config_error(estop(0), "ESTOP without inputs");
    assert_config_error(FB_ESTOP::default(), "default ESTOP");
    assert_config_error(mon(0, 0), "MON without inputs");
    assert_config_error(FB_MON::default(), "default MON");
    assert_config_error(mon(0, MANUAL), "MON without inputs, manual");
}

/// G13 "MON needs at least one active MonIn (Secure inputs alone are SL_E_CONFIG)".
#[test]
fn mon_with_only_secure_inputs_is_a_config_error() {
    assert_config_error(mon(0b01_0000, 0), "Secure1 only");
    assert_config_error(mon(0b11_0000, 0), "Secure1+2 only");
}

/// ABI §5 "a time above the manual's maximum"; C10: every ESTOP/MON time ≤ 65 535 ms.
#[test]
fn time_above_65535_is_a_config_error_and_65535_is_accepted() {
    type E = fn(&mut FB_ESTOP, u32);
    let estop_times: [(&str, E); 7] = [
        ("tDiscTime12", |f, t| f.tDiscTime12 = t),
        ("tDiscTime34", |f, t| f.tDiscTime34 = t),
        ("tDiscTime56", |f, t| f.tDiscTime56 = t),
        ("tDiscTime78", |f, t| f.tDiscTime78 = t),
        ("tEDM1ResetTime", |f, t| f.tEDM1ResetTime = t),
        ("tEDM2ResetTime", |f, t| f.tEDM2ResetTime = t),
        ("tEStopDelOutDelay", |f, t| f.tEStopDelOutDelay = t),
    ];
    for (name, set) in estop_times {
        let mut fb = estop(0xFF);
        fb.dwOptions = SL_OPT_EDM1 | SL_OPT_EDM2;
        set(&mut fb, SL_TIME_PARAM_MAX);
        assert_eq!(fb.clone().init(), SL_OK, "{name} = 65535");
        for bad in [65_536, 100_000, u32::MAX] {
            set(&mut fb, bad);
            assert_config_error(fb, &format!("{name} = {bad}"));
        }
    }
    type M = fn(&mut FB_MON, u32);
    let mon_times: [(&str, M); 6] = [
        ("tDiscTime12", |f, t| f.tDiscTime12 = t),
        ("tDiscTime34", |f, t| f.tDiscTime34 = t),
        ("tDiscTimeSecure12", |f, t| f.tDiscTimeSecure12 = t),
        ("tEDM1ResetTime", |f, t| f.tEDM1ResetTime = t),
        ("tEDM2ResetTime", |f, t| f.tEDM2ResetTime = t),
        ("tMonDelOutDelay", |f, t| f.tMonDelOutDelay = t),
    ];
    for (name, set) in mon_times {
        let mut fb = mon(0b11_1111, SL_OPT_EDM1 | SL_OPT_EDM2);
        set(&mut fb, SL_TIME_PARAM_MAX);
        assert_eq!(fb.clone().init(), SL_OK, "{name} = 65535");
        for bad in [65_536, 1 << 20, u32::MAX] {
            set(&mut fb, bad);
            assert_config_error(fb, &format!("{name} = {bad}"));
        }
    }
}

/// ABI §5 "a pair with one input inactive"; C6 "a discrepancy time for a pair that does not
/// have both inputs active".
#[test]
fn pair_time_with_one_input_inactive_is_a_config_error() {
    for k in 0..4usize {
        for missing in 0..2 {
            let active = 0xFF & !(1u16 << (2 * k + missing));
            let mut fb = estop(active);
            match k {
                0 => fb.tDiscTime12 = 100,
                1 => fb.tDiscTime34 = 100,
                2 => fb.tDiscTime56 = 100,
                _ => fb.tDiscTime78 = 100,
            }
            assert_config_error(fb, &format!("ESTOP pair {k} without input {missing}"));
        }
    }
    for k in 0..3usize {
        for missing in 0..2 {
            let active = 0b11_1111 & !(1u16 << (2 * k + missing));
            let mut fb = mon(active, 0);
            match k {
                0 => fb.tDiscTime12 = 100,
                1 => fb.tDiscTime34 = 100,
                _ => fb.tDiscTimeSecure12 = 100,
            }
            assert_config_error(fb, &format!("MON pair {k} without input {missing}"));
        }
    }
}

/// C6 "unknown option bits"; ABI §6 option table (ESTOP: EDM1, EDM2,
/// SAFE_INPUTS_AFTER_DISC, MANUAL_RESTART per G11; MON: bits 0-4).
#[test]
fn unknown_option_bits_are_a_config_error() {
    for bit in 5..32 {
        let mut fb = estop(0b1);
        fb.dwOptions = 1 << bit;
        assert_config_error(fb, &format!("ESTOP option bit {bit}"));
        let fb = mon(0b1, 1 << bit);
        assert_config_error(fb, &format!("MON option bit {bit}"));
    }
    // every documented bit is accepted
    let mut fb = estop(0b1);
    fb.dwOptions =
        SL_OPT_EDM1 | SL_OPT_EDM2 | SL_OPT_SAFE_INPUTS_AFTER_DISC | SL_OPT_MANUAL_RESTART;
    assert_eq!(fb.init(), SL_OK);
    let mut fb = mon(
        0b1,
        SL_OPT_EDM1 | SL_OPT_EDM2 | SL_OPT_SAFE_INPUTS_AFTER_DISC | MANUAL | SL_OPT_FUNCTION_TEST,
    );
    assert_eq!(fb.init(), SL_OK);
}

/// G11 "SL_OPT_FUNCTION_TEST is SL_E_CONFIG for ESTOP" (ABI §6: FUNCTION_TEST is MON's).
#[test]
fn function_test_option_on_estop_is_a_config_error() {
    let mut fb = estop(0b11);
    fb.dwOptions = SL_OPT_FUNCTION_TEST;
    assert_config_error(fb, "ESTOP FUNCTION_TEST");
    fb.dwOptions = SL_OPT_FUNCTION_TEST | SL_OPT_EDM1;
    assert_config_error(fb, "ESTOP FUNCTION_TEST | EDM1");
}

/// C6 "an EDM reset time for an inactive EDM input".
#[test]
fn edm_reset_time_without_edm_active_is_a_config_error() {
    for (opts, x) in [(0, 1), (0, 2), (SL_OPT_EDM2, 1), (SL_OPT_EDM1, 2)] {
        let mut fb = estop(0b1);
        fb.dwOptions = opts;
        if x == 1 {
            fb.tEDM1ResetTime = 10;
        } else {
            fb.tEDM2ResetTime = 10;
        }
        assert_config_error(fb, &format!("ESTOP EDM{x} reset time, options {opts}"));
        let mut fb = mon(0b1, opts);
        if x == 1 {
            fb.tEDM1ResetTime = 10;
        } else {
            fb.tEDM2ResetTime = 10;
        }
        assert_config_error(fb, &format!("MON EDM{x} reset time, options {opts}"));
    }
}

/// C6 "Bits in wInputActive/wInputNegated for inputs the block does not have".
#[test]
fn input_bits_for_missing_inputs_are_a_config_error() {
    for bit in 8..16 {
        let mut fb = estop(0b1);
        fb.wInputActive |= 1 << bit;
        assert_config_error(fb, &format!("ESTOP active bit {bit}"));
        let mut fb = estop(0b1);
        fb.wInputNegated = 1 << bit;
        assert_config_error(fb, &format!("ESTOP negated bit {bit}"));
    }
    for bit in 6..16 {
        let mut fb = mon(0b1, 0);
        fb.wInputActive |= 1 << bit;
        assert_config_error(fb, &format!("MON active bit {bit}"));
        let mut fb = mon(0b1, 0);
        fb.wInputNegated = 1 << bit;
        assert_config_error(fb, &format!("MON negated bit {bit}"));
    }
}

/// C6 "Negation bits of inactive inputs are ignored".
#[test]
fn negation_bits_of_inactive_inputs_are_ignored() {
    let mut fb = estop(0b1);
    fb.wInputNegated = 0xFE;
    let mut s = running(fb);
    s.step(1, SL_STATE_RUN);
    let mut fb = mon(0b1, 0);
    fb.wInputNegated = 0b11_1110;
    let mut s = mon_running(fb);
    s.step(1, SL_STATE_RUN);
}

/// C6 "Checked by init and at every STOP→run latch": invalid parameters written while
/// stopped give SL_E_CONFIG at the next STOP→run and keep STOP; C6 "every call returns
/// SL_E_CONFIG while the latched parameters are invalid, also with bRun FALSE"; valid ones
/// latched at the next STOP→run end it.
#[test]
fn invalid_parameters_at_the_stop_to_run_latch() {
    let mut s = running(estop_pair());
    s.fb.bRun = 0;
    s.step(1, SL_STATE_STOP);
    s.fb.wInputActive = 0b01; // pair time with one input inactive
    s.step(1, SL_STATE_STOP); // not latched yet: no error while stopped
    s.fb.bRun = 1;
    assert_eq!(s.adv(1), SL_E_CONFIG);
    expect(&s.fb, SL_STATE_STOP);
    s.fb.bRestart = 1;
    assert_eq!(s.adv(1), SL_E_CONFIG);
    expect(&s.fb, SL_STATE_STOP);
    s.fb.bRestart = 0;
    assert_eq!(s.adv(1), SL_E_CONFIG);
    expect(&s.fb, SL_STATE_STOP);
    // fixed while bRun is FALSE: still the invalid latched set
    s.fb.bRun = 0;
    s.fb.wInputActive = 0b11;
    assert_eq!(s.adv(1), SL_E_CONFIG);
    expect(&s.fb, SL_STATE_STOP);
    s.fb.bRun = 1;
    s.step(1, SL_STATE_SAFE);
    s.restart();
}

// ---------------------------------------------------------------------------------------
// Run, ERROR, RESET and acknowledgement (ABI §7, C8, C9, G4, G15)
// ---------------------------------------------------------------------------------------

/// ABI §7 "a bErrAck already TRUE when the error occurred does not acknowledge it".
fn errack_already_true_when_the_error_occurs_does_not_acknowledge<B: Guard>(fb: B) {
    let mut s = running(fb);
    s.fb.set_errack(1);
    s.step(1, SL_STATE_RUN);
    disc_error(&mut s);
    s.fb.set_in(0, 1); // condition gone
    for _ in 0..5 {
        s.adv(10);
        expect_error(&s.fb, SL_DIAG_DISC1);
    }
    s.fb.set_errack(0);
    s.adv(10);
    expect_error(&s.fb, SL_DIAG_DISC1);
    s.acknowledge(SL_STATE_SAFE);
    s.restart();
}
both!(errack_already_true_when_the_error_occurs_does_not_acknowledge);

/// ABI §7 "ERROR is left only through RESET (5): on a rising edge of bErrAck while no error
/// condition remains"; C8 "A rising edge while an error condition remains is consumed: the
/// operator must release and press again"; G4 discrepancy: "the two channels must agree
/// now".
fn ack_while_the_error_condition_remains_does_nothing<B: Guard>(fb: B) {
    let mut s = running(fb);
    disc_error(&mut s);
    s.fb.set_errack(1);
    s.adv(10);
    expect_error(&s.fb, SL_DIAG_DISC1);
    s.fb.set_in(0, 1); // channels agree, ErrAck still held
    s.adv(10);
    expect_error(&s.fb, SL_DIAG_DISC1);
    s.adv(10);
    expect_error(&s.fb, SL_DIAG_DISC1);
    s.fb.set_errack(0);
    s.adv(10);
    expect_error(&s.fb, SL_DIAG_DISC1);
    s.acknowledge(SL_STATE_SAFE);
}
both!(ack_while_the_error_condition_remains_does_nothing);

/// G4: both channels agreeing on FALSE also ends the discrepancy condition (no option).
fn ack_with_both_channels_false_is_accepted<B: Guard>(fb: B) {
    let mut s = running(fb);
    disc_error(&mut s);
    s.fb.set_in(1, 0);
    s.adv(10);
    s.acknowledge(SL_STATE_SAFE);
    s.step(10, SL_STATE_SAFE);
}
both!(ack_with_both_channels_false_is_accepted);

/// §4.4.1/§4.5.1 "If the checkbox [Safe Inputs after Disc Error] is checked, both inputs of
/// the input group that has caused the discrepancy error have to switch to safe state
/// simultaneously before the error can be reset"; G4 "both channels must have requested the
/// safe state in the same cycle at some time since the error".
fn safe_inputs_after_disc_error_latch<B: Params>(fb: B) {
    let mut f = fb;
    *f.options() |= SL_OPT_SAFE_INPUTS_AFTER_DISC;
    let mut s = running(f);
    s.fb.set_in(0, 0);
    s.adv(1);
    s.adv(100);
    expect_error(&s.fb, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
    // channels agree on TRUE, but never were FALSE together: ack refused
    s.fb.set_in(0, 1);
    s.adv(10);
    s.fb.set_errack(1);
    s.adv(10);
    expect_error(&s.fb, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
    s.fb.set_errack(0);
    s.adv(10);
    // alternating channels: never both FALSE in the same cycle
    s.fb.set_in(0, 0);
    s.adv(10);
    s.fb.set_in(0, 1);
    s.fb.set_in(1, 0);
    s.adv(10);
    s.fb.set_in(1, 1);
    s.adv(10);
    s.fb.set_errack(1);
    s.adv(10);
    expect_error(&s.fb, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
    s.fb.set_errack(0);
    s.adv(10);
    // both FALSE in one cycle, then both TRUE again: the latch holds, ack accepted
    s.fb.set_in(0, 0);
    s.fb.set_in(1, 0);
    s.adv(10);
    expect_error(&s.fb, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
    s.fb.set_in(0, 1);
    s.fb.set_in(1, 1);
    s.adv(10);
    expect_error(&s.fb, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
    s.acknowledge(SL_STATE_SAFE);
    s.restart();
}
both!(safe_inputs_after_disc_error_latch);

/// G4 without the option: agreeing channels (on TRUE) are enough.
fn without_safe_inputs_option_agreeing_channels_suffice<B: Guard>(fb: B) {
    let mut s = running(fb);
    disc_error(&mut s);
    s.fb.set_in(0, 1);
    s.adv(10);
    s.acknowledge(SL_STATE_SAFE);
}
both!(without_safe_inputs_option_agreeing_channels_suffice);

/// ABI §7 Run "bRun FALSE puts the block in STOP ... except that a block in ERROR stays in
/// ERROR until acknowledged"; ABI §7 RESET "the falling edge of bErrAck leaves RESET (to
/// STOP when bRun is FALSE ...)"; C9 "With bRun FALSE, ERROR and RESET persist".
fn error_stays_with_run_false_and_reset_exits_to_stop<B: Guard>(fb: B) {
    let mut s = running(fb);
    disc_error(&mut s);
    s.fb.set_in(0, 1);
    s.fb.set_run(0);
    for _ in 0..5 {
        s.adv(100);
        expect_error(&s.fb, SL_DIAG_DISC1);
    }
    s.fb.set_errack(1);
    s.step(1, SL_STATE_RESET);
    assert_eq!(s.fb.diag(), 0);
    s.step(100, SL_STATE_RESET); // RESET persists while ErrAck is held
    s.fb.set_errack(0);
    s.step(1, SL_STATE_STOP);
    s.step(100, SL_STATE_STOP);
    s.start_up(SL_STATE_SAFE);
    s.restart();
}
both!(error_stays_with_run_false_and_reset_exits_to_stop);

/// C9: bRun going FALSE while in RESET: the falling ErrAck edge leads to STOP.
fn run_false_during_reset_exits_to_stop<B: Guard>(fb: B) {
    let mut s = running(fb);
    disc_error(&mut s);
    s.fb.set_in(0, 1);
    s.fb.set_errack(1);
    s.step(1, SL_STATE_RESET);
    s.fb.set_run(0);
    s.step(1, SL_STATE_RESET);
    s.fb.set_errack(0);
    s.step(1, SL_STATE_STOP);
}
both!(run_false_during_reset_exits_to_stop);

/// ABI §7 RESET: "In RESET all outputs are FALSE; the falling edge of bErrAck leaves RESET
/// (... else to the block's start state)"; §4.4.2/§4.5.2 RESET row; C9/G15 nDiag cleared.
fn reset_waits_for_the_falling_edge_then_start_state<B: Guard>(fb: B) {
    let mut s = running(fb);
    disc_error(&mut s);
    s.fb.set_in(0, 1);
    s.fb.set_errack(1);
    s.step(1, SL_STATE_RESET);
    assert_eq!(s.fb.diag(), 0);
    for _ in 0..5 {
        s.step(100, SL_STATE_RESET);
    }
    s.fb.set_errack(0);
    s.step(1, SL_STATE_SAFE);
    assert_eq!(s.fb.diag(), 0);
}
both!(reset_waits_for_the_falling_edge_then_start_state);

/// ABI §7 Run "bRun FALSE puts the block in STOP (2) with all outputs FALSE" — from RUN,
/// DELAYOUT (the delayed output too), SAFE and START.
fn run_false_stops_every_running_state<B: Params>(fb: B) {
    // RUN
    let mut s = running(fb.clone());
    s.fb.set_run(0);
    s.step(1, SL_STATE_STOP);
    // DELAYOUT
    let mut f = fb.clone();
    f.set_delay(1000);
    let mut s = running(f);
    s.fb.set_in(0, 0);
    s.fb.set_in(1, 0);
    s.step(1, SL_STATE_DELAYOUT);
    s.fb.set_run(0);
    s.step(1, SL_STATE_STOP);
    // SAFE
    let mut s = Sim::new(fb.clone(), T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.set_run(0);
    s.step(1, SL_STATE_STOP);
    // START
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.set_restart(1);
    s.step(1, SL_STATE_START);
    s.fb.set_run(0);
    s.step(1, SL_STATE_STOP);
    // a restart afterwards needs the whole sequence again (G12)
    s.fb.set_restart(0);
    s.start_up(SL_STATE_SAFE);
    s.step(1, SL_STATE_SAFE);
    s.restart();
}
both!(run_false_stops_every_running_state);

/// ABI §7 Run for MON's FUNCTEST (G9).
#[test]
fn run_false_stops_functest() {
    let mut s = Sim::new(mon(0b1, SL_OPT_FUNCTION_TEST), T0);
    s.start_up(SL_STATE_FUNCTEST);
    s.fb.bRun = 0;
    s.step(1, SL_STATE_STOP);
}

/// C4 "Applies in every state": a clock error in ERROR adds diag bit 14; G15 "Shows the
/// latched error bits in ERROR" (the discrepancy bit stays).
fn a_second_error_adds_its_diag_bit<B: Guard>(fb: B) {
    let mut s = running(fb);
    disc_error(&mut s);
    let t = s.t;
    assert_eq!(s.at(t - 1), SL_E_CLOCK);
    expect_error(&s.fb, SL_DIAG_DISC1 | SL_DIAG_CLOCK);
}
both!(a_second_error_adds_its_diag_bit);

// ---------------------------------------------------------------------------------------
// The latched parameter copy (C3). These two tests reach into SL_GUARD_PRIVATE's public
// fields (`adwTime`, src/blocks/boolean/guard.rs): C3 describes the mechanism, the layout is the
// implementation's.
// ---------------------------------------------------------------------------------------

/// A running ESTOP whose latched copy has time words altered by `alter` (given the copy
/// and the index of the output delay) must report SL_E_CORRUPT (ERROR, diag bit 15), not a
/// parameter change.
fn altered_latched_time_is_corrupt(alter: fn(&mut [u32; 8], usize)) {
    let mut fb = estop_pair();
    fb.tEStopDelOutDelay = 100;
    let mut s = running(fb);
    let d =
        s.fb.stPrivate
            .adwTime
            .iter()
            .position(|&t| t == 100)
            .unwrap();
    alter(&mut s.fb.stPrivate.adwTime, d);
    assert_eq!(s.adv(1), SL_E_CORRUPT);
    expect(&s.fb, SL_STATE_ERROR);
    assert_ne!(s.fb.nDiag & SL_DIAG_CORRUPT, 0);
}

/// C3 "verified ... whenever a live parameter differs from the copy (a bad CRC then means
/// SL_E_CORRUPT, a good one SL_E_PARAM_CHANGED)": a corrupted latched copy is not mistaken
/// for a parameter change.
#[test]
fn corrupted_latched_parameter_copy_is_corrupt_not_param_changed() {
    altered_latched_time_is_corrupt(|t, d| t[d] = 7);
}

/// The same for the high half of a latched time (the copy keeps the times full width; the
/// CRC covers the OR of the high halves, 0 in every valid set), also when every high half
/// gains the same bit (an even number of equal changes, which a XOR of them would cancel).
#[test]
fn corrupted_high_half_of_a_latched_time_is_corrupt_not_param_changed() {
    altered_latched_time_is_corrupt(|t, d| t[d] |= 1 << 20);
    altered_latched_time_is_corrupt(|t, _| t.iter_mut().for_each(|w| *w |= 1 << 20));
    // Two high halves with the same bit, and both masks' high bytes in the copy's last word
    // (wInputActive | wInputNegated << 16) with the same bit: even numbers of equal changes.
    altered_latched_time_is_corrupt(|t, _| t[..2].iter_mut().for_each(|w| *w |= 1 << 20));
    altered_latched_time_is_corrupt(|t, _| t[7] |= 1 << 8 | 1 << 24);
}

/// Every bit of the latched copy, the input masks in its last word (wInputActive |
/// wInputNegated << 16) included, of a running ESTOP and MON: a flipped bit is SL_E_CORRUPT,
/// not a parameter change (the copy no longer equals the live fields, and its CRC covers
/// every bit of it).
#[test]
fn every_bit_of_the_latched_copy_is_corrupt_not_param_changed() {
    for (word, bit) in (0..8).flat_map(|w| (0..32).map(move |b| (w, b))) {
        let mut e = running(estop_pair());
        e.fb.stPrivate.adwTime[word] ^= 1 << bit;
        assert_eq!(e.adv(1), SL_E_CORRUPT, "ESTOP word {word}, bit {bit}");
        expect(&e.fb, SL_STATE_ERROR);
        let mut m = running(mon_pair());
        m.fb.stPrivate.adwTime[word] ^= 1 << bit;
        assert_eq!(m.adv(1), SL_E_CORRUPT, "MON word {word}, bit {bit}");
        expect(&m.fb, SL_STATE_ERROR);
    }
}

/// C3 "The latched copy carries a CRC-16 ... verified before the outputs are enabled": a
/// corruption of the copy that no live parameter reveals stops the restart.
#[test]
fn latched_copy_is_verified_before_the_outputs_are_enabled() {
    let mut fb = estop_pair();
    fb.tEStopDelOutDelay = 250;
    let mut s = Sim::new(fb, T0);
    s.start_up(SL_STATE_SAFE);
    s.fb.bRestart = 1;
    s.step(1, SL_STATE_START);
    // Every latched word is compared with its live field, so only a corruption that the
    // live field repeats goes unseen by the compare: the latched output delay and the live
    // one changed alike.
    let d = (s.fb.stPrivate.adwTime.iter())
        .position(|&t| t == 250)
        .unwrap();
    s.fb.stPrivate.adwTime[d] = 7;
    s.fb.tEStopDelOutDelay = 7;
    s.fb.bRestart = 0;
    assert_eq!(s.adv(1), SL_E_CORRUPT);
    expect(&s.fb, SL_STATE_ERROR);
    assert_ne!(s.fb.nDiag & SL_DIAG_CORRUPT, 0);
}

// ---------------------------------------------------------------------------------------
// The panic boundary's recovery (src/ffi/mod.rs `block_call`: a caught panic forces ERROR)
// ---------------------------------------------------------------------------------------

/// ABI §5 SL_E_INTERNAL "the instance is in ERROR with its outputs FALSE": after an internal
/// fault a running block is in ERROR (diag bit 15 added to what it had), bError TRUE, the
/// outputs FALSE; its private state is sealed (the next call sees no corruption and keeps
/// the error) and one ErrAck edge acknowledges it (C4: nothing remains).
fn forced_error_is_an_acknowledgeable_error<B: Guard + safelogic::base::envelope::Block>(fb: B) {
    let mut s = running(fb);
    expect(&s.fb, SL_STATE_RUN);
    safelogic::base::envelope::force_error(&mut s.fb);
    expect_error(&s.fb, SL_DIAG_CORRUPT);
    assert_eq!(
        s.adv(1),
        SL_OK,
        "sealed: no corruption seen in the next call"
    );
    expect_error(&s.fb, SL_DIAG_CORRUPT);
    s.fb.set_errack(1);
    s.step(1, SL_STATE_RESET);
    s.fb.set_errack(0);
    s.step(1, SL_STATE_SAFE);
    s.restart();
    expect(&s.fb, SL_STATE_RUN);
}
both!(forced_error_is_an_acknowledgeable_error);

/// A block already in ERROR keeps its diag bits and gains bit 15 (ABI §7: a block in ERROR
/// only gains new bits); its error condition still blocks the acknowledgement.
fn forced_error_in_error_keeps_the_diag<B: Guard + safelogic::base::envelope::Block>(fb: B) {
    let mut s = running(fb);
    disc_error(&mut s);
    safelogic::base::envelope::force_error(&mut s.fb);
    expect_error(&s.fb, SL_DIAG_DISC1 | SL_DIAG_CORRUPT);
    s.fb.set_errack(1);
    s.step(1, SL_STATE_ERROR);
    expect_error(&s.fb, SL_DIAG_DISC1 | SL_DIAG_CORRUPT);
}
both!(forced_error_in_error_keeps_the_diag);

/// An internal fault on a corrupted private state: a fresh private state in ERROR (diag
/// bit 15 only), sealed, so the next call reports no further corruption and ErrAck leads
/// through RESET to the start state with the parameters still latched.
fn forced_error_on_a_corrupt_instance_is_recoverable<
    B: Params + safelogic::base::envelope::Block,
>(
    fb: B,
) {
    let mut s = running(fb);
    disc_error(&mut s);
    s.fb.private_bytes()[0] ^= 0x5A; // the magic word
    safelogic::base::envelope::force_error(&mut s.fb);
    expect_error(&s.fb, SL_DIAG_CORRUPT);
    s.fb.set_in(0, 1);
    assert_eq!(s.adv(1), SL_OK, "a fresh, sealed private state");
    expect_error(&s.fb, SL_DIAG_CORRUPT);
    s.fb.set_errack(1);
    s.step(1, SL_STATE_RESET);
    s.fb.set_errack(0);
    s.step(1, SL_STATE_SAFE);
}
both!(forced_error_on_a_corrupt_instance_is_recoverable);

/// C5: a block in ERROR with bRun FALSE reports a changed parameter (SL_E_PARAM_CHANGED,
/// diag bit 13) in addition to the error it is in: the diag bits of that error stay.
fn parameter_changed_in_error_with_run_false_adds_bit_13<B: Params>(fb: B) {
    let mut s = running(fb);
    disc_error(&mut s);
    s.fb.set_run(0);
    assert_eq!(s.adv(1), SL_OK);
    expect_error(&s.fb, SL_DIAG_DISC1);
    s.fb.set_delay(70);
    assert_eq!(s.adv(1), SL_E_PARAM_CHANGED);
    expect_error(&s.fb, SL_DIAG_DISC1 | SL_DIAG_PARAM_CHANGED);
    assert_eq!(s.adv(1), SL_E_PARAM_CHANGED);
    expect_error(&s.fb, SL_DIAG_DISC1 | SL_DIAG_PARAM_CHANGED);
}
both!(parameter_changed_in_error_with_run_false_adds_bit_13);

/// ABI §3.6 / C3: the private diagnosis word is under the integrity check like the state:
/// one flipped bit of it (low or high byte) is SL_E_CORRUPT, in RUN and in ERROR.
fn corrupted_private_diag_word_is_corrupt<B: Params>(fb: B) {
    // SL_PRIVATE_HEADER: wMagic 0..2, wParamCrc 2..4, nState 4, nFlags 5, wDiag 6..8.
    for (byte, bit) in [(6usize, 0x01u8), (7, 0x01), (7, 0x80)] {
        let mut s = running(fb.clone());
        s.fb.private_bytes()[byte] ^= bit;
        assert_eq!(s.adv(1), SL_E_CORRUPT, "RUN, byte {byte} bit {bit:#x}");
        expect_error(&s.fb, SL_DIAG_CORRUPT);
        let mut s = running(fb.clone());
        disc_error(&mut s);
        s.fb.private_bytes()[byte] ^= bit;
        assert_eq!(s.adv(1), SL_E_CORRUPT, "ERROR, byte {byte} bit {bit:#x}");
        expect_error(&s.fb, SL_DIAG_CORRUPT);
    }
}
both!(corrupted_private_diag_word_is_corrupt);

/// "Safe Inputs after Disc Error" (ABI §7 Pairs, §4.4.1): once both channels have requested
/// the safe state together, the condition is met; an error that joins later (here the clock,
/// C4) only adds its diag bit (ABI §7: a block in ERROR gains new bits) and does not undo
/// it: one ErrAck edge acknowledges both.
fn safe_inputs_condition_met_survives_a_further_error<B: Params>(mut fb: B) {
    *fb.options() |= SL_OPT_SAFE_INPUTS_AFTER_DISC;
    let mut s = running(fb);
    s.fb.set_in(0, 0);
    s.adv(1);
    s.adv(100);
    expect_error(&s.fb, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
    s.fb.set_in(1, 0);
    assert_eq!(s.adv(1), SL_OK);
    s.fb.set_in(0, 1);
    s.fb.set_in(1, 1);
    assert_eq!(s.adv(1), SL_OK);
    s.t -= 10;
    assert_eq!(s.cyc(), SL_E_CLOCK);
    expect_error(&s.fb, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1 | SL_DIAG_CLOCK);
    s.fb.set_errack(1);
    s.step(1, SL_STATE_RESET);
}
both!(safe_inputs_condition_met_survives_a_further_error);
