//! SF_ModeSelector (PLCopen TC5 Part 1; research `plcopen_safety.md` §4.8, §5): every
//! transition of §4.8's table in first-match order with the v2.01 "fault gone" states
//! (semantics QM1–QM6) in both profiles, the selection outputs (held while locked), the
//! R_TRIG of S_SetMode, AutoSetMode, ModeMonitorTime at its limit (T ms allowed, T + 1 ms
//! an error, only after a falling S_ModeX), the static-reset errors, Activate FALSE from
//! every state, start-up, the constants, texts, a group with a link, and 10,000 random
//! sequences per profile against an independent model with every state reached. Expected
//! codes are the research table's (v2.01 / v1.0 columns).

mod common;
use common::cgroup::*;
use common::plcopen::*;
use common::*;
use safelogic::*;
use std::collections::BTreeSet;

codes! {
    IDLE = 0x0000 / 0x0000, CHANGED = 0x8802 / 0x8005, SELECTED = 0x8000 / 0x8000,
    LOCKED = 0x8010 / 0x8004, SHORT = 0xC010 / 0xC001, SHORT_RR = 0xC410 / 0xC001,
    OPEN = 0xC020 / 0xC002, OPEN_RR = 0xC420 / 0xC002, RESET_1 = 0xC011 / 0xC003,
    RESET_2 = 0xC021 / 0xC004,
}

/// The rig's ModeMonitorTime (ms).
const T: u32 = 100;

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct In {
    activate: bool,
    modes: u8,
    unlock: bool,
    set: bool,
    reset: bool,
}

fn on(modes: u8) -> In {
    In {
        activate: true,
        modes,
        unlock: true,
        ..In::default()
    }
}

impl In {
    fn set(self) -> Self {
        In { set: true, ..self }
    }
    fn reset(self) -> Self {
        In {
            reset: true,
            ..self
        }
    }
    fn locked(self) -> Self {
        In {
            unlock: false,
            ..self
        }
    }
}

struct Rig {
    fb: SF_ModeSelector,
    now: u32,
    profile: u8,
}

impl Rig {
    fn with(profile: u8, auto: bool, monitor: u32) -> Self {
        let fb = common::ready(SF_ModeSelector {
            nDiagProfile: profile,
            AutoSetMode: auto.into(),
            ModeMonitorTime: monitor,
            ..Default::default()
        });
        Self {
            fb,
            now: 3_000,
            profile,
        }
    }
    fn new(profile: u8) -> Self {
        Self::with(profile, false, T)
    }
    fn at(&mut self, dt: u32, i: In) -> u16 {
        let fb = &mut self.fb;
        fb.Activate = i.activate.into();
        let m: [u8; 8] = core::array::from_fn(|k| i.modes >> k & 1);
        [
            fb.S_Mode0, fb.S_Mode1, fb.S_Mode2, fb.S_Mode3, fb.S_Mode4, fb.S_Mode5, fb.S_Mode6,
            fb.S_Mode7,
        ] = m;
        fb.S_Unlock = i.unlock.into();
        fb.S_SetMode = i.set.into();
        fb.Reset = i.reset.into();
        self.now = self.now.wrapping_add(dt);
        // SAFETY: a live, exclusively borrowed instance.
        let rc = unsafe { safelogic::ffi::sl_sf_modeselector_cycle(fb, self.now) };
        assert_eq!(rc, SL_OK);
        fb.DiagCode
    }
    fn step(&mut self, i: In) -> u16 {
        self.at(10, i)
    }
    fn c(&self, s: Code) -> u16 {
        code(self.profile, s)
    }
    fn go(&mut self, dt: u32, i: In, s: (u16, u16)) -> In {
        assert_eq!(self.at(dt, i), self.c(s), "towards {s:X?}: {i:?}");
        i
    }
    /// The selection outputs as a mask, and S_AnyModeSel.
    fn sel(&self) -> (u8, u8) {
        let f = &self.fb;
        let v = [
            f.S_Mode0Sel,
            f.S_Mode1Sel,
            f.S_Mode2Sel,
            f.S_Mode3Sel,
            f.S_Mode4Sel,
            f.S_Mode5Sel,
            f.S_Mode6Sel,
            f.S_Mode7Sel,
        ];
        let mask = v.iter().enumerate().fold(0u8, |m, (k, b)| {
            assert!(*b <= 1);
            m | b << k
        });
        (mask, f.S_AnyModeSel)
    }
    /// IDLE → `target` (ModeMonitorTime T, no AutoSetMode) with mode 2 (bit 4) as the
    /// selection; returns the last inputs.
    fn reach(&mut self, target: (u16, u16)) -> In {
        let m = 0b100;
        let mut last = self.go(10, on(0), CHANGED);
        match target {
            CHANGED => {}
            SELECTED | LOCKED => {
                self.go(10, on(m), CHANGED);
                last = self.go(10, on(m).set(), SELECTED);
                if target == LOCKED {
                    last = self.go(10, on(m).locked(), LOCKED);
                }
            }
            SHORT => last = self.go(10, on(0b101), SHORT),
            SHORT_RR => {
                self.go(10, on(0b101), SHORT);
                last = self.go(10, on(m), SHORT_RR);
            }
            RESET_1 => {
                self.go(10, on(0b101), SHORT);
                self.go(10, on(0b101).reset(), SHORT);
                self.go(10, on(m).reset(), SHORT_RR);
                last = self.go(10, on(m).reset(), RESET_1);
            }
            OPEN | OPEN_RR | RESET_2 => {
                self.go(10, on(m), CHANGED);
                self.go(10, on(0), CHANGED);
                last = self.go(T + 1, on(0), OPEN);
                if target == OPEN_RR {
                    last = self.go(10, on(m), OPEN_RR);
                } else if target == RESET_2 {
                    self.go(10, on(0).reset(), OPEN);
                    self.go(10, on(m).reset(), OPEN_RR);
                    last = self.go(10, on(m).reset(), RESET_2);
                }
            }
            other => panic!("{other:X?}"),
        }
        last
    }
}

fn t(p: u8, from: (u16, u16), i: In, to: (u16, u16), what: &str) -> Rig {
    let mut rig = Rig::new(p);
    rig.reach(from);
    assert_eq!(
        rig.step(i),
        rig.c(to),
        "{from:X?} --{what}--> {to:X?} (profile {p})"
    );
    rig
}

#[test]
fn every_transition_in_first_match_order() {
    for p in profiles() {
        // MODE_CHANGED: two modes → C010 (even with an S_SetMode edge); one mode, S_Unlock
        // and a rising S_SetMode → 8000; no edge, S_Unlock FALSE or no single mode: stays.
        t(p, CHANGED, on(0b11).set(), SHORT, "short circuit");
        t(p, CHANGED, on(0xFF), SHORT, "all modes");
        let rig = t(p, CHANGED, on(0b1000).set(), SELECTED, "RT(S_SetMode)");
        assert_eq!(rig.sel(), (0b1000, 1));
        t(p, CHANGED, on(0b1000), CHANGED, "no S_SetMode");
        t(p, CHANGED, on(0).set(), CHANGED, "no mode");
        let mut rig = t(p, CHANGED, on(0b1000).set().locked(), CHANGED, "locked");
        assert_eq!(
            rig.step(on(0b1000).set()),
            rig.c(CHANGED),
            "a held S_SetMode is no edge"
        );
        assert_eq!(rig.step(on(0b1000)), rig.c(CHANGED));
        assert_eq!(rig.step(on(0b1000).set()), rig.c(SELECTED));
        // MODE_SELECTED: short circuit first; then any S_ModeX other than the selection
        // (another mode, none) → 8802; then S_Unlock FALSE → 8010.
        t(
            p,
            SELECTED,
            on(0b110).locked(),
            SHORT,
            "short before change / lock",
        );
        t(
            p,
            SELECTED,
            on(0b010).locked(),
            CHANGED,
            "change before lock",
        );
        t(p, SELECTED, on(0), CHANGED, "mode falls");
        let rig = t(p, SELECTED, on(0b100).locked(), LOCKED, "S_Unlock FALSE");
        assert_eq!(rig.sel(), (0b100, 1), "the selection held");
        let rig = t(p, SELECTED, on(0b100).set(), SELECTED, "stays");
        assert_eq!(rig.sel(), (0b100, 1));
        // MODE_LOCKED: changes ignored (a short circuit too), the selection held; S_Unlock
        // with the same mode → 8000, with another (or several) → 8802 (QM3).
        let mut rig = Rig::new(p);
        rig.reach(LOCKED);
        for m in [0, 0b1, 0b11, 0xFF] {
            assert_eq!(rig.step(on(m).set().locked()), rig.c(LOCKED), "{m:b}");
            assert_eq!(rig.sel(), (0b100, 1), "held while locked");
        }
        assert_eq!(rig.step(on(0b100).locked()), rig.c(LOCKED));
        assert_eq!(rig.step(on(0b100)), rig.c(SELECTED));
        assert_eq!(rig.sel(), (0b100, 1));
        for m in [0, 0b1, 0b101] {
            let rig = t(p, LOCKED, on(m), CHANGED, "unlocked, another mode");
            assert_eq!(rig.sel(), (0, 0));
        }
        // C010 → C410 once at most one mode is TRUE; Reset does nothing in C010.
        t(p, SHORT, on(0b11).reset(), SHORT, "fault present");
        t(p, SHORT, on(0), SHORT_RR, "none");
        t(p, SHORT, on(1), SHORT_RR, "one");
        // C410: the fault again first; static Reset → C011; RT(Reset) → 8802.
        t(
            p,
            SHORT_RR,
            on(0b11).reset(),
            SHORT,
            "fault again before reset",
        );
        t(p, SHORT_RR, on(0b100).reset(), CHANGED, "RT(Reset)");
        t(p, SHORT_RR, on(0b100), SHORT_RR, "waits");
        t(p, RESET_1, on(0b100).reset(), RESET_1, "Reset held");
        t(
            p,
            RESET_1,
            on(0b11),
            SHORT_RR,
            "NOT Reset (fault again: next call)",
        );
        // C020 → C420 with exactly one mode; C420: open again first, static Reset → C021,
        // RT(Reset) → 8802.
        t(p, OPEN, on(0), OPEN, "no mode");
        t(p, OPEN, on(0b11).reset(), OPEN, "two modes");
        t(p, OPEN, on(0b1000), OPEN_RR, "one mode");
        t(p, OPEN_RR, on(0b100).reset(), CHANGED, "RT(Reset)");
        t(p, OPEN_RR, on(0b11), OPEN_RR, "waits");
        let mut rig = Rig::new(p);
        rig.reach(OPEN_RR);
        assert_eq!(rig.step(on(0)), rig.c(OPEN_RR), "falls: time runs");
        assert_eq!(rig.at(T, on(0)), rig.c(OPEN_RR), "T ms");
        assert_eq!(
            rig.at(1, on(0).reset()),
            rig.c(OPEN),
            "open again before reset"
        );
        t(p, RESET_2, on(0b100).reset(), RESET_2, "Reset held");
        t(p, RESET_2, on(0b100), OPEN_RR, "NOT Reset");
    }
}

/// ModeMonitorTime: from the call in which all S_ModeX became FALSE after one was TRUE; T ms
/// allowed, more an error (semantics QM4); never without a falling S_ModeX; re-armed.
#[test]
fn the_mode_monitor_time() {
    for p in profiles() {
        let mut rig = Rig::new(p);
        rig.reach(SELECTED);
        assert_eq!(rig.step(on(0)), rig.c(CHANGED), "the mode falls");
        assert_eq!(rig.at(T, on(0)), rig.c(CHANGED), "T ms");
        assert_eq!(rig.at(1, on(0)), rig.c(OPEN), "T + 1 ms");
        // A new mode within T: no error, the time re-armed by the next fall.
        let mut rig = Rig::new(p);
        rig.reach(SELECTED);
        rig.go(10, on(0), CHANGED);
        rig.go(T, on(0b10), CHANGED);
        rig.go(10, on(0), CHANGED);
        assert_eq!(rig.at(T, on(0)), rig.c(CHANGED), "re-armed");
        // No fall since the activation: no open-circuit error, whatever the time.
        let mut rig = Rig::new(p);
        rig.go(10, on(0), CHANGED);
        assert_eq!(rig.at(1_000_000, on(0)), rig.c(CHANGED));
        // T#0: a switch-over within the same ms passes, the next ms is an error.
        let mut rig = Rig::with(p, false, 0);
        rig.reach(SELECTED);
        rig.go(10, on(0), CHANGED);
        assert_eq!(rig.at(0, on(0b10).set()), rig.c(SELECTED));
        rig.go(10, on(0), CHANGED);
        assert_eq!(rig.at(1, on(0)), rig.c(OPEN));
    }
}

/// AutoSetMode (constant): a single mode with S_Unlock selects without S_SetMode; not while
/// locked; a change after 8000 passes through 8802 (outputs FALSE for one call).
#[test]
fn auto_set_mode() {
    for p in profiles() {
        let mut rig = Rig::with(p, true, T);
        assert_eq!(rig.step(on(0b1)), rig.c(CHANGED), "activation");
        assert_eq!(rig.step(on(0b1)), rig.c(SELECTED));
        assert_eq!(rig.sel(), (0b1, 1));
        assert_eq!(rig.step(on(0b10)), rig.c(CHANGED));
        assert_eq!(rig.sel(), (0, 0));
        assert_eq!(rig.step(on(0b10)), rig.c(SELECTED));
        assert_eq!(rig.sel(), (0b10, 1));
        assert_eq!(rig.step(on(0)), rig.c(CHANGED));
        assert_eq!(rig.step(on(0b10).locked()), rig.c(CHANGED), "not unlocked");
    }
}

#[test]
fn outputs_per_state_and_activate_false_from_every_state() {
    for p in profiles() {
        for s in ALL.into_iter().filter(|s| *s != IDLE) {
            let mut rig = Rig::new(p);
            let last = rig.reach(s);
            let held = matches!(s, SELECTED | LOCKED);
            assert_eq!(rig.sel(), if held { (0b100, 1) } else { (0, 0) }, "{s:X?}");
            let f = &rig.fb;
            assert_eq!(f.SafetyDemand, u8::from(s.0 & 0x0800 != 0), "{s:X?}");
            let rr = s.0 & 0x0400 != 0 && !last.reset;
            assert_eq!(f.ResetRequest, u8::from(rr), "{s:X?}");
            assert_eq!((f.Ready, f.Error), (1, u8::from(s.0 >= 0xC000)));
            assert_eq!(
                rig.step(In {
                    activate: false,
                    ..last
                }),
                0
            );
            assert_eq!(rig.sel(), (0, 0));
            let f = &rig.fb;
            assert_eq!([f.Ready, f.SafetyDemand, f.ResetRequest, f.Error], [0; 4]);
        }
    }
    // ResetRequest in C410 / C420 follows NOT Reset.
    let mut rig = Rig::new(0);
    rig.reach(SHORT_RR);
    assert_eq!(rig.fb.ResetRequest, 1);
}

/// Start-up: 0000 → 8802 whatever the inputs (an S_SetMode edge in the activating call is
/// used up there); the selection needs the next edge.
#[test]
fn start_up() {
    let mut rig = Rig::new(0);
    assert_eq!(rig.step(on(0b1).set()), 0x8802);
    assert_eq!(rig.step(on(0b1).set()), 0x8802, "no new edge");
    assert_eq!(rig.step(on(0b1)), 0x8802);
    assert_eq!(rig.step(on(0b1).set()), 0x8000);
    // Reset held through the activation: no effect on the selection.
    let mut rig = Rig::new(0);
    assert_eq!(rig.step(on(0b1).reset()), 0x8802);
    assert_eq!(rig.step(on(0b1).reset().set()), 0x8000);
}

/// The constants: AutoSetMode and ModeMonitorTime latched at activation (a change is C3FD),
/// an invalid AutoSetMode byte is refused (C3FC, SL_E_CONFIG); an invalid mode byte reads
/// FALSE with SL_E_INVALID_BOOL.
#[test]
fn constants_and_invalid_bytes() {
    let mut rig = Rig::new(0);
    rig.reach(SELECTED);
    rig.fb.AutoSetMode = 1;
    assert_eq!(rig.fb.cycle(rig.now + 10), SL_E_PARAM_CHANGED);
    assert_eq!(
        (rig.fb.DiagCode, rig.sel()),
        (SL_SF_DIAG_CONST_CHANGED, (0, 0))
    );
    let mut rig = Rig::new(0);
    rig.reach(CHANGED);
    rig.fb.ModeMonitorTime = T + 1;
    assert_eq!(rig.fb.cycle(rig.now + 10), SL_E_PARAM_CHANGED);
    let mut bad = common::refused(
        SF_ModeSelector {
            AutoSetMode: 2,
            ..Default::default()
        },
        &[],
    );
    bad.Activate = 1;
    assert_eq!(bad.cycle(0), SL_E_CONFIG);
    assert_eq!(bad.DiagCode, SL_SF_DIAG_CONFIG);
    let mut rig = Rig::new(0);
    rig.reach(SELECTED);
    rig.fb.S_Mode2 = 0x11;
    assert_eq!(rig.fb.cycle(rig.now + 10), SL_E_INVALID_BOOL);
    assert_eq!((rig.fb.DiagCode, rig.sel()), (0x8802, (0, 0)));
}

#[test]
fn texts_for_every_diag_code() {
    let text = |code: u16| diag_text(SL_TYPE_SF_MODESELECTOR, code);
    let mut seen = BTreeSet::new();
    for (v2, v1) in ALL {
        for c in [v2, v1] {
            let t = text(c);
            assert!(!t.is_empty() && t != "unknown DiagCode", "{c:04X}");
            seen.insert(t);
        }
    }
    assert_eq!(seen.len(), ALL.len(), "one text per v2.01 state");
    // v1.0 has one code per fault (QM1): C001 reads as the short circuit.
    assert_eq!(text(0xC001), text(0xC010));
    assert_eq!(text(0xC002), text(0xC020));
}

#[test]
fn in_a_group_with_a_link() {
    let mut w = WithAnd::of(SF_ModeSelector::default(), "S_Mode1Sel");
    w.fb.Activate = 1;
    w.fb.S_Unlock = 1;
    w.fb.S_Mode1 = 1;
    w.run(3);
    w.fb.S_SetMode = 1;
    w.grp.cycle(10);
    w.expect(0x8000, 1);
    // Locked: the link keeps carrying the selection.
    w.fb.S_Unlock = 0;
    w.grp.cycle(10);
    w.fb.S_Mode1 = 0;
    w.grp.cycle(10);
    w.expect(0x8010, 1);
    // Unlocked with a short circuit: 8802, then C010; the group runs on.
    (w.fb.S_Unlock, w.fb.S_Mode2, w.fb.S_Mode3) = (1, 1, 1);
    w.grp.cycle(10);
    w.grp.cycle(10);
    w.expect_group(0xC010, 0, SL_STATE_RUN);
    w.stop_group();
}

/// The model, written from research §4.8 and semantics QM1–QM6 (v2.01 codes): R_TRIG of
/// S_SetMode and of Reset every call, the selection latched on entering 8000, the
/// open-circuit TON from a falling S_ModeX that leaves none TRUE.
#[derive(Default)]
struct Model {
    state: u16,
    sel: u8,
    set_prev: bool,
    reset_prev: bool,
    prev_modes: u8,
    off_since: Option<u32>,
}

impl Model {
    fn step(&mut self, i: In, now: u32, auto: bool, t: u32) -> u16 {
        let (set_rt, _) = edges(&mut self.set_prev, i.set);
        let (rt, st) = edges(&mut self.reset_prev, i.reset);
        if i.modes != 0 {
            self.off_since = None;
        } else if self.prev_modes != 0 && self.state != 0 {
            self.off_since = Some(now);
        }
        self.prev_modes = if i.activate { i.modes } else { 0 };
        let n = i.modes.count_ones();
        let e1 = n >= 2;
        let e2 = self.off_since.is_some_and(|s| now.wrapping_sub(s) > t);
        let next = if !i.activate {
            self.off_since = None;
            0
        } else {
            match self.state {
                0 => 0x8802,
                0x8802 if e1 => 0xC010,
                0x8802 if e2 => 0xC020,
                0x8802 if (auto || set_rt) && i.unlock && n == 1 => 0x8000,
                0x8000 if e1 => 0xC010,
                0x8000 if i.modes != self.sel => 0x8802,
                0x8000 if !i.unlock => 0x8010,
                0x8010 if i.unlock && i.modes == self.sel => 0x8000,
                0x8010 if i.unlock => 0x8802,
                0xC010 if !e1 => 0xC410,
                0xC410 if e1 => 0xC010,
                0xC410 if st => 0xC011,
                0xC410 if rt => 0x8802,
                0xC011 if !i.reset => 0xC410,
                0xC020 if n == 1 => 0xC420,
                0xC420 if e2 => 0xC020,
                0xC420 if st => 0xC021,
                0xC420 if rt => 0x8802,
                0xC021 if !i.reset => 0xC420,
                s => s,
            }
        };
        if next == 0x8000 && self.state != 0x8000 && self.state != 0x8010 {
            self.sel = i.modes;
        }
        self.state = next;
        next
    }
}

#[test]
fn random_sequences_agree_with_the_model() {
    let walk = Walk::new("SF_ModeSelector", 0x5F26, ALL.iter().map(|s| s.0));
    walk.run(
        |p, _, rng| {
            let auto = rng.next() % 4 == 0;
            let t = [0, 5, 20, 60][(rng.next() % 4) as usize];
            let rig = Rig::with(p, auto, t);
            let i = In {
                activate: true,
                ..In::default()
            };
            let rates: [u64; 4] = core::array::from_fn(|_| 2 + rng.next() % 8);
            (auto, t, rig, Model::default(), i, rates)
        },
        |(auto, t, rig, model, i, rates), p, rng| {
            let r = rng.next();
            if r % 31 == 0 {
                i.activate = !i.activate;
            }
            // Mostly a rotary switch: one mode, none, sometimes two.
            if (r >> 8) % rates[0] == 0 {
                let k = (r >> 16) % 8;
                i.modes = match (r >> 20) % 6 {
                    0 => 0,
                    1 => i.modes | 1 << k,
                    _ => 1 << k,
                };
            }
            i.unlock ^= (r >> 24) % (rates[1] * 2) == 0;
            i.set ^= (r >> 32) % rates[2] == 0;
            i.reset ^= (r >> 40) % rates[3] == 0;
            let dt = ((r >> 48) % 40) as u32;
            let got = rig.at(dt, *i);
            let v2 = model.step(*i, rig.now, *auto, *t);
            let want = ALL.iter().find(|s| s.0 == v2).map(|s| rig.c(*s)).unwrap();
            assert_eq!(got, want, "profile {p} auto {auto} t {t}: {i:?}");
            let (mask, any) = rig.sel();
            let selected = v2 == 0x8000 || v2 == 0x8010;
            assert_eq!(mask, if selected { model.sel } else { 0 });
            assert_eq!(any == 1, selected);
            assert!(mask.count_ones() <= 1);
            assert!(v2 != 0x8000 || (i.unlock && i.modes == mask));
            v2
        },
    );
}
