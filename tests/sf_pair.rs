//! SF_Equivalent and SF_Antivalent (PLCopen TC5 Part 1; research `plcopen_safety.md`
//! §4.11, §4.12, §5): every transition of §4.11's table in first-match order, the
//! discrepancy time at its limit (T − 1 ms no error, T ms error; T#0 at the first
//! evaluation), errors left only with both channels inactive, Activate FALSE from every
//! state, the antivalent NO channel inverted (an invalid byte reads inactive), the constants,
//! and 10,000 random sequences per block and profile against an independent model with
//! every state reached. Expected codes are the research table's.

mod common;
use common::plcopen::*;
use safelogic::*;

codes! {
    IDLE = 0x0000 / 0x0000, INIT = 0x8801 / 0x8001, ENABLED = 0x8000 / 0x8000,
    WAIT_B = 0x8802 / 0x8004, WAIT_A = 0x8804 / 0x8014, FROM_ACTIVE = 0x8806 / 0x8005,
    ERR1 = 0xC010 / 0xC001, ERR2 = 0xC020 / 0xC002, ERR3 = 0xC030 / 0xC003,
}

/// The channels in the active sense: Equivalent (A, B); Antivalent (NC, NOT NO).
trait Pair: FunctionBlock + Default + Copy {
    const NAME: &'static str;
    /// Writes Activate and the channels given in the active sense.
    fn apply(&mut self, activate: bool, a: bool, b: bool);
    fn out(&self) -> u8;
    fn code(&self) -> u16;
    fn set_time(&mut self, t: u32);
    fn set_profile(&mut self, p: u8);
}

impl Pair for SF_Equivalent {
    const NAME: &'static str = "SF_Equivalent";
    fn apply(&mut self, activate: bool, a: bool, b: bool) {
        (self.Activate, self.S_ChannelA, self.S_ChannelB) = (activate.into(), a.into(), b.into());
    }
    fn out(&self) -> u8 {
        self.S_EquivalentOut
    }
    fn code(&self) -> u16 {
        self.DiagCode
    }
    fn set_time(&mut self, t: u32) {
        self.DiscrepancyTime = t;
    }
    fn set_profile(&mut self, p: u8) {
        self.nDiagProfile = p;
    }
}

impl Pair for SF_Antivalent {
    const NAME: &'static str = "SF_Antivalent";
    fn apply(&mut self, activate: bool, a: bool, b: bool) {
        // NC active = TRUE; NO active = FALSE.
        (self.Activate, self.S_ChannelNC, self.S_ChannelNO) =
            (activate.into(), a.into(), (!b).into());
    }
    fn out(&self) -> u8 {
        self.S_AntivalentOut
    }
    fn code(&self) -> u16 {
        self.DiagCode
    }
    fn set_time(&mut self, t: u32) {
        self.DiscrepancyTime = t;
    }
    fn set_profile(&mut self, p: u8) {
        self.nDiagProfile = p;
    }
}

struct Rig<B: Pair> {
    fb: B,
    now: u32,
    profile: u8,
}

impl<B: Pair> Rig<B> {
    fn new(profile: u8, t: u32) -> Self {
        let mut fb = B::default();
        fb.set_profile(profile);
        fb.set_time(t);
        assert_eq!(fb.init(), SL_OK);
        Self {
            fb,
            now: 50_000,
            profile,
        }
    }
    /// One call `dt` ms after the previous one.
    fn at(&mut self, dt: u32, a: bool, b: bool) -> u16 {
        self.fb.apply(true, a, b);
        self.now = self.now.wrapping_add(dt);
        assert_eq!(self.fb.cycle(self.now), SL_OK, "{}", B::NAME);
        self.fb.code()
    }
    fn step(&mut self, a: bool, b: bool) -> u16 {
        self.at(1, a, b)
    }
    fn c(&self, s: Code) -> u16 {
        code(self.profile, s)
    }
    /// IDLE → INIT → `target` by the table's paths (t = the rig's DiscrepancyTime ≥ 10).
    fn reach(&mut self, target: Code) {
        assert_eq!(self.step(false, false), self.c(INIT));
        match target {
            INIT => {}
            WAIT_B => assert_eq!(self.step(true, false), self.c(WAIT_B)),
            WAIT_A => assert_eq!(self.step(false, true), self.c(WAIT_A)),
            ENABLED => assert_eq!(self.step(true, true), self.c(ENABLED)),
            FROM_ACTIVE => {
                assert_eq!(self.step(true, true), self.c(ENABLED));
                assert_eq!(self.step(true, false), self.c(FROM_ACTIVE));
            }
            ERR1 => {
                assert_eq!(self.step(true, false), self.c(WAIT_B));
                assert_eq!(self.at(1_000_000, true, false), self.c(ERR1));
            }
            ERR2 => {
                assert_eq!(self.step(false, true), self.c(WAIT_A));
                assert_eq!(self.at(1_000_000, false, true), self.c(ERR2));
            }
            ERR3 => {
                assert_eq!(self.step(true, true), self.c(ENABLED));
                assert_eq!(self.step(false, true), self.c(FROM_ACTIVE));
                assert_eq!(self.at(1_000_000, false, true), self.c(ERR3));
            }
            other => panic!("{other:X?}"),
        }
    }
}

fn transitions<B: Pair>() {
    for p in profiles() {
        let r = |s| {
            let mut rig = Rig::<B>::new(p, 100);
            rig.reach(s);
            rig
        };
        // INIT: A AND NOT B → WAIT_B; B AND NOT A → WAIT_A; both → ENABLED; none stays.
        let mut rig = r(INIT);
        assert_eq!(rig.step(false, false), rig.c(INIT));
        assert_eq!(rig.step(true, false), rig.c(WAIT_B));
        let mut rig = r(INIT);
        assert_eq!(rig.step(false, true), rig.c(WAIT_A));
        let mut rig = r(INIT);
        assert_eq!(rig.step(true, true), rig.c(ENABLED));
        assert_eq!(rig.fb.out(), 1);
        // WAIT_B: the timer first (even with B now TRUE or A FALSE), then NOT A, then B.
        for (a, b) in [(true, false), (false, false), (true, true)] {
            let mut rig = r(WAIT_B);
            assert_eq!(rig.at(100, a, b), rig.c(ERR1), "timer first ({a}, {b})");
        }
        let mut rig = r(WAIT_B);
        assert_eq!(rig.at(99, true, false), rig.c(WAIT_B), "99 ms < 100 ms");
        assert_eq!(
            rig.at(1, true, false),
            rig.c(ERR1),
            "100 ms since the entry"
        );
        let mut rig = r(WAIT_B);
        assert_eq!(rig.at(50, false, true), rig.c(INIT), "NOT A before B");
        let mut rig = r(WAIT_B);
        assert_eq!(rig.at(99, true, true), rig.c(ENABLED));
        // WAIT_A symmetric.
        for (a, b) in [(false, true), (false, false), (true, true)] {
            let mut rig = r(WAIT_A);
            assert_eq!(rig.at(100, a, b), rig.c(ERR2));
        }
        let mut rig = r(WAIT_A);
        assert_eq!(rig.at(99, false, true), rig.c(WAIT_A));
        assert_eq!(rig.at(1, false, true), rig.c(ERR2));
        let mut rig = r(WAIT_A);
        assert_eq!(rig.at(50, true, false), rig.c(INIT), "NOT B before A");
        let mut rig = r(WAIT_A);
        assert_eq!(rig.at(99, true, true), rig.c(ENABLED));
        // ENABLED: one channel inactive → FROM_ACTIVE_WAIT (output FALSE in the same call);
        // both inactive → INIT; both active stays.
        for (a, b) in [(true, false), (false, true)] {
            let mut rig = r(ENABLED);
            assert_eq!(
                rig.at(1_000, true, true),
                rig.c(ENABLED),
                "no time limit while enabled"
            );
            assert_eq!(rig.step(a, b), rig.c(FROM_ACTIVE));
            assert_eq!(rig.fb.out(), 0);
        }
        let mut rig = r(ENABLED);
        assert_eq!(rig.step(false, false), rig.c(INIT));
        // FROM_ACTIVE_WAIT: the timer first, then both inactive; both active again stays.
        let mut rig = r(FROM_ACTIVE);
        assert_eq!(
            rig.at(50, true, true),
            rig.c(FROM_ACTIVE),
            "no way back to ENABLED"
        );
        assert_eq!(rig.at(49, true, false), rig.c(FROM_ACTIVE));
        assert_eq!(
            rig.at(1, false, false),
            rig.c(ERR3),
            "timer before both inactive"
        );
        let mut rig = r(FROM_ACTIVE);
        assert_eq!(rig.at(99, false, false), rig.c(INIT));
        // Errors: left only with both channels inactive; no time limit there.
        for e in [ERR1, ERR2, ERR3] {
            let mut rig = r(e);
            for (a, b) in [(true, false), (false, true), (true, true)] {
                assert_eq!(rig.at(1_000, a, b), rig.c(e));
                assert_eq!(rig.fb.out(), 0);
            }
            assert_eq!(rig.step(false, false), rig.c(INIT));
            assert_eq!(rig.step(true, true), rig.c(ENABLED));
        }
    }
}

#[test]
fn every_transition_in_first_match_order_and_the_discrepancy_time() {
    transitions::<SF_Equivalent>();
    transitions::<SF_Antivalent>();
}

/// T#0: the error at the first evaluation of a waiting state (research §8.13, semantics
/// PP3); a channel pair switching in one call never waits.
fn zero_time<B: Pair>() {
    let mut rig = Rig::<B>::new(0, 0);
    rig.reach(INIT);
    assert_eq!(rig.step(true, false), 0x8802);
    assert_eq!(rig.at(0, true, true), 0xC010, "same ms, first evaluation");
    let mut rig = Rig::<B>::new(0, 0);
    rig.reach(INIT);
    assert_eq!(rig.step(true, true), 0x8000);
    assert_eq!(rig.step(false, false), 0x8801);
}

#[test]
fn a_zero_discrepancy_time_allows_no_discrepancy() {
    zero_time::<SF_Equivalent>();
    zero_time::<SF_Antivalent>();
}

fn outputs_and_idle<B: Pair>() {
    for p in profiles() {
        for s in ALL.into_iter().filter(|s| *s != IDLE) {
            let mut rig = Rig::<B>::new(p, 100);
            rig.reach(s);
            assert_eq!(rig.fb.out(), u8::from(s == ENABLED), "{} {s:X?}", B::NAME);
            let demand = s.0 & 0x0800 != 0;
            assert_eq!(rig.fb.get_bool("SafetyDemand"), Some(demand), "{s:X?}");
            assert_eq!(rig.fb.get_bool("Error"), Some(s.0 >= 0xC000));
            assert_eq!(rig.fb.get_bool("Ready"), Some(true));
            // Activate FALSE from every state: IDLE, every output FALSE.
            rig.fb.apply(false, true, true);
            rig.now += 1;
            assert_eq!(rig.fb.cycle(rig.now), SL_OK);
            assert_eq!(rig.fb.code(), 0);
            assert_eq!(rig.fb.out(), 0);
            for n in ["Ready", "SafetyDemand", "Error"] {
                assert_eq!(rig.fb.get_bool(n), Some(false), "{n}");
            }
        }
    }
}

#[test]
fn outputs_per_state_and_activate_false_from_every_state() {
    outputs_and_idle::<SF_Equivalent>();
    outputs_and_idle::<SF_Antivalent>();
}

/// The antivalent NO channel: TRUE is inactive; an invalid byte reads inactive (the demand).
#[test]
fn antivalent_no_channel_is_inverted_and_an_invalid_byte_is_inactive() {
    let mut fb = SF_Antivalent {
        DiscrepancyTime: 100,
        Activate: 1,
        S_ChannelNC: 1,
        S_ChannelNO: 0,
        ..Default::default()
    };
    assert_eq!(fb.cycle(0), SL_OK);
    assert_eq!(fb.cycle(1), SL_OK);
    assert_eq!((fb.DiagCode, fb.S_AntivalentOut), (0x8000, 1));
    fb.S_ChannelNO = 3;
    assert_eq!(fb.cycle(2), SL_E_INVALID_BOOL);
    assert_eq!((fb.DiagCode, fb.S_AntivalentOut), (0x8806, 0));
    // Both contacts at rest (NC FALSE, NO TRUE): INIT; NC TRUE with NO TRUE waits for NO.
    fb.S_ChannelNO = 1;
    fb.S_ChannelNC = 0;
    assert_eq!(fb.cycle(3), SL_OK);
    assert_eq!(fb.DiagCode, 0x8801);
    fb.S_ChannelNC = 1;
    assert_eq!(fb.cycle(4), SL_OK);
    assert_eq!(fb.DiagCode, 0x8802, "WAIT_FOR_NO");
    fb.S_ChannelNO = 0;
    assert_eq!(fb.cycle(5), SL_OK);
    assert_eq!(fb.DiagCode, 0x8000);
}

/// DiscrepancyTime is a constant: latched at activation, a change while activated is C3FD;
/// above SL_SF_TIME_MAX it is refused (C3FC, SL_E_CONFIG).
#[test]
fn the_discrepancy_time_is_a_constant() {
    let mut fb = SF_Equivalent {
        DiscrepancyTime: 100,
        Activate: 1,
        ..Default::default()
    };
    assert_eq!(fb.cycle(0), SL_OK);
    fb.DiscrepancyTime = 200;
    assert_eq!(fb.cycle(1), SL_E_PARAM_CHANGED);
    assert_eq!((fb.DiagCode, fb.Error), (SL_SF_DIAG_CONST_CHANGED, 1));
    fb.Activate = 0;
    assert_eq!(fb.cycle(2), SL_OK);
    fb.Activate = 1;
    assert_eq!(fb.cycle(3), SL_OK);
    assert_eq!(fb.DiagCode, 0x8801, "the new time latched");
    (fb.S_ChannelA, fb.S_ChannelB) = (1, 0);
    fb.cycle(4);
    assert_eq!(fb.cycle(203), SL_OK);
    assert_eq!(fb.DiagCode, 0x8802);
    assert_eq!(fb.cycle(204), SL_OK);
    assert_eq!(fb.DiagCode, 0xC010, "200 ms");
    let mut bad = common::refused(
        SF_Equivalent {
            DiscrepancyTime: SL_SF_TIME_MAX + 1,
            Activate: 1,
            ..Default::default()
        },
        &[0],
    );
    assert_eq!(bad.DiagCode, SL_SF_DIAG_CONFIG);
    bad.DiscrepancyTime = SL_SF_TIME_MAX;
    bad.Activate = 0;
    assert_eq!(bad.cycle(1), SL_OK);
    bad.Activate = 1;
    assert_eq!(bad.cycle(2), SL_OK);
    assert_eq!(bad.DiagCode, 0x8801);
}

/// The discrepancy time across the wrap of the ms clock.
#[test]
fn the_timer_runs_across_the_clock_wrap() {
    let mut fb = SF_Equivalent {
        DiscrepancyTime: 100,
        Activate: 1,
        ..Default::default()
    };
    fb.cycle(u32::MAX - 60);
    (fb.S_ChannelA, fb.S_ChannelB) = (1, 0);
    fb.cycle(u32::MAX - 50);
    assert_eq!(fb.DiagCode, 0x8802);
    assert_eq!(fb.cycle(48), SL_OK);
    assert_eq!(fb.DiagCode, 0x8802, "99 ms");
    assert_eq!(fb.cycle(49), SL_OK);
    assert_eq!(fb.DiagCode, 0xC010, "100 ms");
}

/// The model: research §4.11's table with the v1.0 codes, written from the text; the timer
/// (TON) starts on the entry into 8004/8014/8005 and is stopped in every other state.
#[derive(Default)]
struct Model {
    state: u16,
    since: u32,
}

impl Model {
    fn step(&mut self, activate: bool, a: bool, b: bool, now: u32, t: u32) -> u16 {
        let q = now.wrapping_sub(self.since) >= t;
        let next = if !activate {
            0
        } else {
            match self.state {
                0x0000 => 0x8001,
                0x8001 if a && !b => 0x8004,
                0x8001 if b && !a => 0x8014,
                0x8001 if a && b => 0x8000,
                0x8004 if q => 0xC001,
                0x8004 if !a => 0x8001,
                0x8004 if b => 0x8000,
                0x8014 if q => 0xC002,
                0x8014 if !b => 0x8001,
                0x8014 if a => 0x8000,
                0x8000 if a != b => 0x8005,
                0x8000 if !a && !b => 0x8001,
                0x8005 if q => 0xC003,
                0x8005 if !a && !b => 0x8001,
                0xC001..=0xC003 if !a && !b => 0x8001,
                s => s,
            }
        };
        common::plcopen::enter(&mut self.state, &mut self.since, next, now)
    }
}

fn against_the_model<B: Pair>(seed: u64) {
    let walk = Walk::new(B::NAME, seed, ALL.iter().map(|s| s.1));
    walk.run(
        |p, _, rng| {
            let t = [0, 5, 20, 50][(rng.next() % 4) as usize];
            (t, Rig::<B>::new(p, t), Model::default(), true, false, false)
        },
        |(t, rig, model, act, a, b), p, rng| {
            let r = rng.next();
            if r % 23 == 0 {
                *act = !*act;
            }
            *a ^= (r >> 8) % 4 == 0;
            *b ^= (r >> 16) % 4 == 0;
            let dt = ((r >> 24) % 12) as u32;
            rig.fb.apply(*act, *a, *b);
            rig.now = rig.now.wrapping_add(dt);
            assert_eq!(rig.fb.cycle(rig.now), SL_OK);
            let v1 = model.step(*act, *a, *b, rig.now, *t);
            let want = ALL.iter().find(|s| s.1 == v1).map(|s| rig.c(*s)).unwrap();
            assert_eq!(rig.fb.code(), want, "{} profile {p} t {t}", B::NAME);
            assert_eq!(rig.fb.out() == 1, want == 0x8000);
            assert!(
                rig.fb.out() == 0 || (*a && *b),
                "output TRUE with a channel inactive"
            );
            v1
        },
    );
}

#[test]
fn random_sequences_agree_with_the_model() {
    against_the_model::<SF_Equivalent>(0x5F11);
    against_the_model::<SF_Antivalent>(0x5F12);
}

fn equivalent_cycle(fb: &mut SF_Equivalent, now: u32) -> i32 {
    // SAFETY: a live, exclusively borrowed instance.
    unsafe { safelogic::ffi::sl_sf_equivalent_cycle(fb, now) }
}

/// The latched constants are under their CRC (semantics PO7; mutation-testing findings):
/// a bit of a latched time word that changes while the block is activated is a corrupt
/// private state (C3FF, SL_E_CORRUPT), not a changed constant (C3FD), for low and high bits
/// of both words; and a latched copy changed together with the live input, so that the two
/// agree, is found where the safety output would switch on.
#[test]
fn latched_constants_are_under_their_crc() {
    let on = |fb: &mut SF_Equivalent| fb.apply(true, true, true);
    for word in 0..2 {
        for bit in [0, 15, 16, 31] {
            let mut fb = SF_Equivalent {
                DiscrepancyTime: 100,
                ..Default::default()
            };
            fb.apply(true, false, false);
            assert_eq!(equivalent_cycle(&mut fb, 0), SL_OK);
            on(&mut fb);
            assert_eq!(equivalent_cycle(&mut fb, 5), SL_OK);
            assert_eq!(fb.DiagCode, 0x8000);
            fb.stPrivate.adwTime[word] ^= 1 << bit;
            assert_eq!(
                equivalent_cycle(&mut fb, 10),
                SL_E_CORRUPT,
                "word {word} bit {bit}"
            );
            assert_eq!((fb.DiagCode, fb.S_EquivalentOut), (SL_SF_DIAG_CORRUPT, 0));
        }
    }
    // Live and latched changed alike (100 → 100 + 2^20) while waiting: no changed constant
    // to see, but the output does not switch on.
    let mut fb = SF_Equivalent {
        DiscrepancyTime: 100,
        ..Default::default()
    };
    fb.apply(true, false, false);
    assert_eq!(equivalent_cycle(&mut fb, 0), SL_OK);
    assert_ne!(fb.DiagCode, 0x8000);
    fb.DiscrepancyTime ^= 1 << 20;
    fb.stPrivate.adwTime[0] ^= 1 << 20;
    on(&mut fb);
    assert_eq!(equivalent_cycle(&mut fb, 10), SL_E_CORRUPT);
    assert_eq!((fb.DiagCode, fb.S_EquivalentOut), (SL_SF_DIAG_CORRUPT, 0));
}
