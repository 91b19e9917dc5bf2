//! SF_EnableSwitch (PLCopen TC5 Part 1; research `plcopen_safety.md` §4.9, §5): every
//! transition of §4.9's table in first-match order (NOT S_SafetyActive first, from every
//! state), every DiagCode in both profiles, the static-reset errors, S_AutoReset, Activate
//! FALSE from every state, start-up with the switch in each position, the positions from
//! the two channels (an invalid byte reads position 3), texts, a group with a link, and
//! 10,000 random sequences per profile against an independent model with every state
//! reached. Expected codes are the research table's (v2.01 / v1.0 columns).

mod common;
use common::cgroup::*;
use common::plcopen::*;
use common::*;
use safelogic::*;
use std::collections::BTreeSet;

codes! {
    IDLE = 0x0000 / 0x0000, BASIC = 0x8002 / 0x8004, SAFE = 0x8004 / 0x8005,
    POS1 = 0x8802 / 0x8006, POS3 = 0x8804 / 0x8007, POS2 = 0x8000 / 0x8000,
    ERR1 = 0xC010 / 0xC010, ERR2 = 0xC020 / 0xC020, ERR3 = 0xC030 / 0xC030,
    ERR4 = 0xC040 / 0xC040, ERR_RESET_1 = 0xC001 / 0xC001, ERR_RESET_2 = 0xC011 / 0xC002,
}

/// (Ch1, Ch2) of the switch positions (research §4.9 [I]) and the invalid combination.
const P1: (bool, bool) = (false, true);
const P2: (bool, bool) = (true, true);
const P3: (bool, bool) = (false, false);
const BAD: (bool, bool) = (true, false);

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct In {
    activate: bool,
    safety: bool,
    ch: (bool, bool),
    auto: bool,
    reset: bool,
}

impl In {
    fn on(ch: (bool, bool)) -> Self {
        In {
            activate: true,
            safety: true,
            ch,
            ..In::default()
        }
    }
    fn reset(self, reset: bool) -> Self {
        In { reset, ..self }
    }
    fn auto(self) -> Self {
        In { auto: true, ..self }
    }
}

struct Rig {
    fb: SF_EnableSwitch,
    now: u32,
    profile: u8,
}

impl Rig {
    fn new(profile: u8) -> Self {
        let fb = common::ready(SF_EnableSwitch {
            nDiagProfile: profile,
            ..Default::default()
        });
        Self {
            fb,
            now: 1000,
            profile,
        }
    }
    fn step(&mut self, i: In) -> u16 {
        let fb = &mut self.fb;
        fb.Activate = i.activate.into();
        fb.S_SafetyActive = i.safety.into();
        (fb.S_EnableSwitchCh1, fb.S_EnableSwitchCh2) = (i.ch.0.into(), i.ch.1.into());
        fb.S_AutoReset = i.auto.into();
        fb.Reset = i.reset.into();
        self.now += 10;
        // SAFETY: a live, exclusively borrowed instance.
        let rc = unsafe { safelogic::ffi::sl_sf_enableswitch_cycle(fb, self.now) };
        assert_eq!(rc, SL_OK);
        fb.DiagCode
    }
    fn c(&self, s: Code) -> u16 {
        code(self.profile, s)
    }
    /// IDLE → `target` by the table's paths; returns the last inputs.
    fn reach(&mut self, target: Code) -> In {
        let go = |rig: &mut Self, i: In, s: Code| {
            assert_eq!(rig.step(i), rig.c(s), "on the way to {target:X?}");
            i
        };
        let basic = In {
            safety: false,
            ..In::on(P1)
        };
        let mut last = go(self, basic, BASIC);
        if target == BASIC {
            return last;
        }
        let first = if matches!(target, ERR1 | ERR2 | ERR_RESET_1) {
            P3
        } else {
            P1
        };
        last = go(self, In::on(first), SAFE);
        match target {
            SAFE => {}
            POS1 => last = go(self, In::on(P1), POS1),
            POS2 => {
                go(self, In::on(P1), POS1);
                last = go(self, In::on(P2), POS2);
            }
            POS3 => {
                go(self, In::on(P1), POS1);
                last = go(self, In::on(P3), POS3);
            }
            ERR1 => last = go(self, In::on(P3), ERR1),
            ERR2 => {
                go(self, In::on(P3), ERR1);
                last = go(self, In::on(P1), ERR2);
            }
            ERR_RESET_1 => {
                go(self, In::on(P3), ERR1);
                go(self, In::on(P3).reset(true), ERR1);
                go(self, In::on(P1).reset(true), ERR2);
                last = go(self, In::on(P1).reset(true), ERR_RESET_1);
            }
            ERR3 | ERR4 | ERR_RESET_2 => {
                go(self, In::on(P1), POS1);
                go(self, In::on(P3), POS3);
                last = go(self, In::on(P2), ERR3);
                if target == ERR4 {
                    last = go(self, In::on(P1), ERR4);
                } else if target == ERR_RESET_2 {
                    go(self, In::on(P2).reset(true), ERR3);
                    go(self, In::on(P1).reset(true), ERR4);
                    last = go(self, In::on(P1).reset(true), ERR_RESET_2);
                }
            }
            other => panic!("{other:X?}"),
        }
        last
    }
}

/// One transition: from `from` (reached by the table's paths), inputs `i` give `to`.
fn t(p: u8, from: Code, i: In, to: Code, what: &str) {
    let mut rig = Rig::new(p);
    rig.reach(from);
    assert_eq!(
        rig.step(i),
        rig.c(to),
        "{from:X?} --{what}--> {to:X?} (profile {p})"
    );
}

#[test]
fn every_transition_in_first_match_order() {
    for p in profiles() {
        // NOT S_SafetyActive first, from every state (the errors too), whatever else.
        for s in ALL.into_iter().filter(|s| *s != IDLE) {
            for ch in [P1, P2, P3, BAD] {
                for reset in [false, true] {
                    let i = In {
                        safety: false,
                        ..In::on(ch).reset(reset)
                    };
                    t(p, s, i, BASIC, "NOT S_SafetyActive");
                }
            }
        }
        // BASIC_OPMODE: S_SafetyActive → SAFE_OPMODE whatever the position.
        for ch in [P1, P2, P3, BAD] {
            t(p, BASIC, In::on(ch), SAFE, "S_SafetyActive");
        }
        // SAFE_OPMODE: NOT position 1 → C010; position 1 → POSITION_1.
        for ch in [P2, P3, BAD] {
            t(p, SAFE, In::on(ch), ERR1, "not position 1");
        }
        t(p, SAFE, In::on(P1), POS1, "position 1");
        // POSITION_1: 2 → 8000; 3 or invalid → POSITION_3; 1 stays.
        t(p, POS1, In::on(P2), POS2, "1 → 2");
        t(p, POS1, In::on(P3), POS3, "position 3");
        t(p, POS1, In::on(BAD), POS3, "invalid = 3");
        t(p, POS1, In::on(P1), POS1, "stays");
        // POSITION_2 (enabled): 3 or invalid → POSITION_3; 1 → POSITION_1; 2 stays.
        t(p, POS2, In::on(P3), POS3, "panic");
        t(p, POS2, In::on(BAD), POS3, "invalid");
        t(p, POS2, In::on(P1), POS1, "released");
        t(p, POS2, In::on(P2).reset(true), POS2, "stays");
        // POSITION_3: 2 → C030 (3 → 2 never enables); 1 → POSITION_1; 3 / invalid stay.
        t(p, POS3, In::on(P2), ERR3, "3 → 2");
        t(p, POS3, In::on(P1), POS1, "released");
        t(p, POS3, In::on(BAD), POS3, "stays");
        // C010: position 1 → C020; anything else stays, Reset does nothing.
        t(p, ERR1, In::on(P1), ERR2, "position 1");
        for ch in [P2, P3, BAD] {
            t(p, ERR1, In::on(ch).reset(true), ERR1, "stays");
        }
        // C020: NOT position 1 first (even with a Reset edge or S_AutoReset); then static
        // Reset without S_AutoReset → C001; then RT(Reset) or S_AutoReset → POSITION_1.
        t(
            p,
            ERR2,
            In::on(P2).reset(true).auto(),
            ERR1,
            "not 1 before reset",
        );
        t(
            p,
            ERR2,
            In::on(BAD).reset(true),
            ERR1,
            "invalid before reset",
        );
        t(p, ERR2, In::on(P1).reset(true), POS1, "RT(Reset)");
        t(p, ERR2, In::on(P1).auto(), POS1, "S_AutoReset");
        t(p, ERR2, In::on(P1), ERR2, "waits");
        let mut rig = Rig::new(p);
        rig.reach(ERR_RESET_1);
        // ERR_RESET_1 path: static Reset; with S_AutoReset a held Reset passes.
        let mut rig2 = Rig::new(p);
        rig2.reach(ERR1);
        rig2.step(In::on(P3).reset(true));
        assert_eq!(rig2.step(In::on(P1).reset(true)), rig2.c(ERR2));
        assert_eq!(
            rig2.step(In::on(P1).reset(true).auto()),
            rig2.c(POS1),
            "held Reset with S_AutoReset"
        );
        // C001: only NOT Reset → C020 (the position does not matter).
        assert_eq!(rig.step(In::on(P3).reset(true)), rig.c(ERR_RESET_1));
        assert_eq!(rig.step(In::on(P3)), rig.c(ERR2));
        assert_eq!(rig.step(In::on(P3)), rig.c(ERR1));
        t(p, ERR_RESET_1, In::on(P1), ERR2, "NOT Reset");
        // C030: NOT position 2 → C040; 2 stays.
        t(p, ERR3, In::on(P2).reset(true), ERR3, "stays");
        for ch in [P1, P3, BAD] {
            t(p, ERR3, In::on(ch), ERR4, "not 2");
        }
        // C040: position 2 first; static Reset w/o S_AutoReset → C011; RT or auto → 3.
        t(
            p,
            ERR4,
            In::on(P2).reset(true).auto(),
            ERR3,
            "2 before reset",
        );
        t(p, ERR4, In::on(P1).reset(true), POS3, "RT(Reset)");
        t(p, ERR4, In::on(P3).auto(), POS3, "S_AutoReset");
        t(p, ERR4, In::on(P3), ERR4, "waits");
        let mut rig = Rig::new(p);
        rig.reach(ERR_RESET_2);
        assert_eq!(rig.step(In::on(P2).reset(true)), rig.c(ERR_RESET_2));
        assert_eq!(rig.step(In::on(P1)), rig.c(ERR4), "NOT Reset");
        let mut rig = Rig::new(p);
        rig.reach(ERR3);
        rig.step(In::on(P2).reset(true));
        rig.step(In::on(P3).reset(true));
        assert_eq!(
            rig.step(In::on(P3).reset(true).auto()),
            rig.c(POS3),
            "held Reset with S_AutoReset"
        );
        // After the reset from C040 the switch is in position 3: it must pass 1 to enable.
        assert_eq!(rig.step(In::on(P2)), rig.c(ERR3));
    }
}

#[test]
fn outputs_per_state_and_activate_false_from_every_state() {
    for p in profiles() {
        for s in ALL.into_iter().filter(|s| *s != IDLE) {
            let mut rig = Rig::new(p);
            let last = rig.reach(s);
            let fb = &rig.fb;
            assert_eq!(fb.S_EnableSwitchOut, u8::from(s == POS2), "{s:X?}");
            assert_eq!(fb.SafetyDemand, u8::from(s.0 & 0x0800 != 0), "{s:X?}");
            assert_eq!(fb.ResetRequest, 0, "no state has bit 0x0400");
            assert_eq!((fb.Ready, fb.Error), (1, u8::from(s.0 >= 0xC000)));
            assert_eq!(
                rig.step(In {
                    activate: false,
                    ..last
                }),
                0
            );
            let fb = &rig.fb;
            assert_eq!(
                [
                    fb.Ready,
                    fb.S_EnableSwitchOut,
                    fb.SafetyDemand,
                    fb.ResetRequest,
                    fb.Error
                ],
                [0; 5]
            );
        }
    }
}

/// Start-up: activation enters BASIC_OPMODE (8002) whatever the inputs; the switch must be in
/// position 1 when the safe mode starts, else C010 (research §4.9 ERR_OPERATION_1).
#[test]
fn start_up_with_the_switch_in_each_position() {
    for (ch, second) in [(P1, POS1), (P2, ERR1), (P3, ERR1), (BAD, ERR1)] {
        let mut rig = Rig::new(0);
        assert_eq!(rig.step(In::on(ch)), 0x8002, "activation");
        assert_eq!(rig.step(In::on(ch)), 0x8004);
        assert_eq!(rig.step(In::on(ch)), second.0);
        assert_eq!(rig.fb.S_EnableSwitchOut, 0);
    }
    // Position 2 held through the activation never enables: 8004 → C010 → 1 → reset.
    let mut rig = Rig::new(0);
    rig.step(In::on(P2));
    rig.step(In::on(P2));
    assert_eq!(rig.step(In::on(P2)), 0xC010);
    assert_eq!(rig.step(In::on(P1)), 0xC020);
    assert_eq!(rig.step(In::on(P1).reset(true)), 0x8802);
    assert_eq!(rig.step(In::on(P2)), 0x8000);
    assert_eq!(rig.fb.S_EnableSwitchOut, 1);
}

/// An invalid byte on either channel reads position 3 (semantics QN2) with
/// SL_E_INVALID_BOOL; invalid S_SafetyActive reads FALSE.
#[test]
fn an_invalid_channel_byte_is_position_3() {
    let mut rig = Rig::new(0);
    rig.reach(POS2);
    rig.fb.S_EnableSwitchCh1 = 2;
    assert_eq!(rig.fb.cycle(5000), SL_E_INVALID_BOOL);
    assert_eq!((rig.fb.DiagCode, rig.fb.S_EnableSwitchOut), (0x8804, 0));
    (rig.fb.S_EnableSwitchCh1, rig.fb.S_EnableSwitchCh2) = (1, 0x80);
    assert_eq!(rig.fb.cycle(5010), SL_E_INVALID_BOOL);
    assert_eq!(rig.fb.DiagCode, 0x8804, "still position 3");
    rig.fb.S_EnableSwitchCh2 = 1;
    assert_eq!(rig.fb.cycle(5020), SL_OK);
    assert_eq!(rig.fb.DiagCode, 0xC030, "3 → 2");
    rig.fb.S_SafetyActive = 7;
    assert_eq!(rig.fb.cycle(5030), SL_E_INVALID_BOOL);
    assert_eq!(rig.fb.DiagCode, 0x8002);
}

/// The profile is a constant (C3FD when changed while activated); the clock fault.
#[test]
fn profile_constant_and_library_faults() {
    let mut rig = Rig::new(0);
    rig.reach(POS2);
    rig.fb.nDiagProfile = 1;
    assert_eq!(rig.fb.cycle(5000), SL_E_PARAM_CHANGED);
    assert_eq!(
        (rig.fb.DiagCode, rig.fb.S_EnableSwitchOut),
        (SL_SF_DIAG_CONST_CHANGED, 0)
    );
    rig.fb.Activate = 0;
    assert_eq!(rig.fb.cycle(5010), SL_OK);
    rig.fb.Activate = 1;
    assert_eq!(rig.fb.cycle(5020), SL_OK);
    assert_eq!(rig.fb.DiagCode, 0x8004, "v1.0 BASIC_OPMODE");
    assert_eq!(rig.fb.cycle(5010), SL_E_CLOCK);
    assert_eq!(rig.fb.DiagCode, SL_SF_DIAG_CLOCK);
    common::refused(
        SF_EnableSwitch {
            nDiagProfile: 2,
            ..Default::default()
        },
        &[],
    );
}

#[test]
fn texts_for_every_diag_code() {
    let text = |code: u16| diag_text(SL_TYPE_SF_ENABLESWITCH, code);
    let mut seen = BTreeSet::new();
    for (v2, v1) in ALL {
        for c in [v2, v1] {
            let t = text(c);
            assert!(!t.is_empty() && t != "unknown DiagCode", "{c:04X}");
            seen.insert(t);
        }
    }
    assert_eq!(seen.len(), ALL.len());
    // 8004 is SAFE_OPMODE in v2.01 and BASIC_OPMODE in v1.0: the text says both (QN4).
    assert!(text(0x8004).contains("v1.0 8004 is BASIC_OPMODE"));
    assert_eq!(text(0x8005), text(0x8004));
    assert_eq!(text(0x8123), "unknown DiagCode");
}

/// As a group member: its output linked to an FB_AND input; a PLCopen error does not stop
/// the group; the group's STOP halts it.
#[test]
fn in_a_group_with_a_link() {
    let mut w = WithAnd::of(SF_EnableSwitch::default(), "S_EnableSwitchOut");
    w.fb.Activate = 1;
    w.fb.S_SafetyActive = 1;
    w.fb.S_EnableSwitchCh2 = 1;
    w.run(4);
    assert_eq!(w.fb.DiagCode, 0x8802);
    w.fb.S_EnableSwitchCh1 = 1;
    w.grp.cycle(10);
    w.expect(0x8000, 1);
    // Panic position, then 3 → 2: C030, the group runs on, the link carries FALSE.
    (w.fb.S_EnableSwitchCh1, w.fb.S_EnableSwitchCh2) = (0, 0);
    w.grp.cycle(10);
    (w.fb.S_EnableSwitchCh1, w.fb.S_EnableSwitchCh2) = (1, 1);
    w.grp.cycle(10);
    w.expect_group(0xC030, 0, SL_STATE_RUN);
    w.stop_group();
}

/// The model: research §4.9's table with the v1.0 codes, written from the text (position 1 =
/// Ch1 FALSE and Ch2 TRUE, position 2 = both TRUE, anything else position 3).
#[derive(Default)]
struct Model {
    state: u16,
    reset_prev: bool,
}

impl Model {
    fn step(&mut self, i: In) -> u16 {
        let (rt, st) = edges(&mut self.reset_prev, i.reset);
        let pos1 = !i.ch.0 && i.ch.1;
        let pos2 = i.ch.0 && i.ch.1;
        let pos3 = !pos1 && !pos2;
        self.state = if !i.activate {
            0
        } else if self.state == 0 || !i.safety {
            // IDLE → 8004 (activation); NOT S_SafetyActive first in every other state.
            0x8004
        } else {
            match self.state {
                0x8004 => 0x8005,
                0x8005 if !pos1 => 0xC010,
                0x8005 => 0x8006,
                0x8006 if pos2 => 0x8000,
                0x8006 if pos3 => 0x8007,
                0x8000 if pos3 => 0x8007,
                0x8000 if pos1 => 0x8006,
                0x8007 if pos2 => 0xC030,
                0x8007 if pos1 => 0x8006,
                0xC010 if pos1 => 0xC020,
                0xC020 if !pos1 => 0xC010,
                0xC020 if st && !i.auto => 0xC001,
                0xC020 if rt || i.auto => 0x8006,
                0xC001 if !i.reset => 0xC020,
                0xC030 if !pos2 => 0xC040,
                0xC040 if pos2 => 0xC030,
                0xC040 if st && !i.auto => 0xC002,
                0xC040 if rt || i.auto => 0x8007,
                0xC002 if !i.reset => 0xC040,
                s => s,
            }
        };
        self.state
    }
}

#[test]
fn random_sequences_agree_with_the_model() {
    let walk = Walk::new("SF_EnableSwitch", 0x5F23, ALL.iter().map(|s| s.1));
    walk.run(
        |p, _, rng| {
            (
                Rig::new(p),
                Model::default(),
                rates::<6>(rng),
                In::default(),
            )
        },
        |(rig, model, rates, i), p, rng| {
            let f: [bool; 6] = core::array::from_fn(|k| rng.next() % rates[k] == 0);
            i.activate = if i.activate {
                !f[0] || rng.next() % 4 != 0
            } else {
                true
            };
            i.safety ^= f[1];
            i.ch.0 ^= f[2];
            i.ch.1 ^= f[3];
            i.auto ^= f[4] && rng.next() % 3 == 0;
            i.reset ^= f[5];
            let got = rig.step(*i);
            let v1 = model.step(*i);
            let want = ALL.iter().find(|s| s.1 == v1).map(|s| rig.c(*s)).unwrap();
            assert_eq!(got, want, "profile {p}: {i:?}");
            let fb = &rig.fb;
            assert_eq!(fb.S_EnableSwitchOut == 1, got == 0x8000);
            assert!(fb.S_EnableSwitchOut == 0 || (i.safety && i.ch == P2));
            assert_eq!(fb.Ready == 1, got != 0);
            assert_eq!(fb.Error == 1, got >= 0xC000);
            v1
        },
    );
}
