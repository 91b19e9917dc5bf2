//! SF_OutControl (PLCopen TC5 Part 1; research `plcopen_safety.md` §4.13, §5): every
//! transition of §4.13's v2.01 state machine in first-match order, every DiagCode in both
//! profiles, the R_TRIG of ProcessControl (every call, whatever the state), StaticControl
//! (a latched constant), the static-reset and simultaneous-edge errors, Activate FALSE from
//! every state, start-up with and without S_StartReset, the texts, a group with links, and
//! 10,000 random sequences per profile against an independent model with every state
//! reached. Expected codes are the research's, never read back.

mod common;
use common::cgroup::*;
use common::plcopen::*;
use common::*;
use safelogic::*;
use std::collections::BTreeSet;

// (v2.01, v1.0) codes of §4.13 (v1.0: the research's recollection, semantics QO6).
codes! {
    IDLE = 0x0000 / 0x0000, INIT = 0x8401 / 0x8001, SAFE = 0x8802 / 0x8002,
    LOCK = 0x8404 / 0x8003, DISABLE = 0x8006 / 0x8010, ENABLE = 0x8000 / 0x8000,
    ERR_RESET_1 = 0xC001 / 0xC001, ERR_RESET_2 = 0xC011 / 0xC002, ERR_CONTROL = 0xC010 / 0xC010,
    ERR_INIT = 0xC020 / 0xC011, ERR_LOCK = 0xC030 / 0xC111,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct In {
    activate: bool,
    safe: bool,
    pc: bool,
    start_reset: bool,
    auto_reset: bool,
    reset: bool,
}

const ON: In = In {
    activate: true,
    safe: false,
    pc: false,
    start_reset: false,
    auto_reset: false,
    reset: false,
};

/// The independent model: research §4.13's "State machine v2 [I]" text with the v2.01 codes,
/// R_TRIG on Reset and ProcessControl in every call, Activate first; the exits of C020 /
/// C030 are ours (semantics QO2).
#[derive(Default)]
struct Model {
    state: u16,
    reset_prev: bool,
    pc_prev: bool,
}

impl Model {
    fn step(&mut self, i: In, static_control: bool) -> u16 {
        let (rt, stat) = edges(&mut self.reset_prev, i.reset);
        let (rpc, _) = edges(&mut self.pc_prev, i.pc);
        self.state = if !i.activate {
            0
        } else {
            match self.state {
                0x0000 => 0x8401,
                0x8401 if i.start_reset => 0x8006,
                0x8401 if stat => 0xC001,
                0x8401 if rt && rpc => 0xC020,
                0x8401 if rt => 0x8006,
                0xC001 if !i.reset => 0x8401,
                0x8006 if !i.safe => 0x8802,
                0x8006 if rpc || (static_control && i.pc) => 0x8000,
                0x8006 if !static_control && i.pc => 0xC010,
                0x8000 if !i.safe => 0x8802,
                0x8000 if !i.pc => 0x8006,
                0x8802 if i.safe && i.auto_reset => 0x8006,
                0x8802 if i.safe => 0x8404,
                0x8404 if !i.safe => 0x8802,
                0x8404 if stat => 0xC011,
                0x8404 if rt && rpc => 0xC030,
                0x8404 if rt => 0x8006,
                0xC011 if !i.reset => 0x8404,
                0xC010 if !i.pc => 0x8006,
                0xC020 if !i.reset && !i.pc => 0x8401,
                0xC030 if !i.reset && !i.pc => 0x8404,
                s => s,
            }
        };
        self.state
    }
}

struct Rig {
    fb: SF_OutControl,
    now: u32,
    profile: u8,
}

impl Rig {
    fn new(profile: u8, static_control: bool) -> Self {
        let mut fb = SF_OutControl {
            nDiagProfile: profile,
            StaticControl: static_control.into(),
            ..Default::default()
        };
        // SAFETY: a live, exclusively borrowed instance.
        assert_eq!(
            unsafe { safelogic::ffi::sl_sf_outcontrol_init(&mut fb) },
            SL_OK
        );
        Self {
            fb,
            now: 500,
            profile,
        }
    }
    fn step(&mut self, i: In) -> u16 {
        let f = &mut self.fb;
        f.Activate = i.activate.into();
        f.S_SafeControl = i.safe.into();
        f.ProcessControl = i.pc.into();
        f.S_StartReset = i.start_reset.into();
        f.S_AutoReset = i.auto_reset.into();
        f.Reset = i.reset.into();
        self.now = self.now.wrapping_add(10);
        // SAFETY: as above.
        let rc = unsafe { safelogic::ffi::sl_sf_outcontrol_cycle(&mut self.fb, self.now) };
        assert_eq!(rc, SL_OK);
        self.fb.DiagCode
    }
    fn c(&self, s: Code) -> u16 {
        code(self.profile, s)
    }
    fn outputs(&self) -> [u8; 5] {
        let f = &self.fb;
        [
            f.Ready,
            f.S_OutControl,
            f.SafetyDemand,
            f.ResetRequest,
            f.Error,
        ]
    }
    /// IDLE → `target` by the machine's paths (StaticControl FALSE); returns the last inputs.
    fn reach(&mut self, target: Code) -> In {
        let mut i = ON;
        if target == ERR_RESET_1 {
            i.reset = true;
            assert_eq!(self.step(i), self.c(INIT));
            assert_eq!(self.step(i), self.c(ERR_RESET_1));
            return i;
        }
        assert_eq!(self.step(i), self.c(INIT));
        if target == INIT {
            return i;
        }
        if target == ERR_INIT {
            i.reset = true;
            i.pc = true;
            assert_eq!(self.step(i), self.c(ERR_INIT));
            return i;
        }
        i.reset = true;
        i.safe = true;
        assert_eq!(self.step(i), self.c(DISABLE));
        i.reset = false;
        match target {
            DISABLE => return i,
            ERR_CONTROL => {
                i.pc = true;
                assert_eq!(self.step(i), self.c(ENABLE));
                // Through SAFE with S_AutoReset back to DISABLE with ProcessControl held.
                i.safe = false;
                assert_eq!(self.step(i), self.c(SAFE));
                i.safe = true;
                i.auto_reset = true;
                assert_eq!(self.step(i), self.c(DISABLE));
                assert_eq!(self.step(i), self.c(ERR_CONTROL));
                return i;
            }
            _ => {}
        }
        i.pc = true;
        assert_eq!(self.step(i), self.c(ENABLE));
        if target == ENABLE {
            return i;
        }
        i.safe = false;
        assert_eq!(self.step(i), self.c(SAFE));
        if target == SAFE {
            return i;
        }
        i.pc = false;
        if target == ERR_RESET_2 {
            i.reset = true;
            assert_eq!(self.step(i), self.c(SAFE));
        }
        i.safe = true;
        assert_eq!(self.step(i), self.c(LOCK));
        match target {
            LOCK => i,
            ERR_RESET_2 => {
                assert_eq!(self.step(i), self.c(ERR_RESET_2));
                i
            }
            ERR_LOCK => {
                i.reset = true;
                i.pc = true;
                assert_eq!(self.step(i), self.c(ERR_LOCK));
                i
            }
            other => panic!("no path to {other:X?}"),
        }
    }
}

#[test]
fn every_transition_in_first_match_order() {
    for p in profiles() {
        let r = |t| {
            let mut rig = Rig::new(p, false);
            let i = rig.reach(t);
            (rig, i)
        };
        // INIT: S_StartReset first (even with a held Reset), then static Reset, then both
        // edges (C020), then RT(Reset).
        let mut rig = Rig::new(p, false);
        let held = In { reset: true, ..ON };
        assert_eq!(rig.step(held), rig.c(INIT));
        assert_eq!(
            rig.step(In {
                start_reset: true,
                ..held
            }),
            rig.c(DISABLE)
        );
        #[rustfmt::skip]
        let cases: &[Case<In>] = &[
            (INIT, &[
                (|i| (i.safe, i.pc) = (true, true), INIT, "no Reset edge: stays"),
                (|i| i.pc = false, INIT, ""),
                (|i| (i.pc, i.reset) = (true, true), ERR_INIT, "both edges"),
            ]),
            (INIT, &[
                (|i| i.pc = true, INIT, ""),
                (|i| i.reset = true, DISABLE, "Reset edge, ProcessControl held"),
            ]),
            // C001: left with Reset FALSE, to INIT.
            (ERR_RESET_1, &[
                (|i| i.safe = true, ERR_RESET_1, ""),
                (|i| i.reset = false, INIT, ""),
            ]),
            // C020: left with Reset and ProcessControl FALSE, to INIT.
            (ERR_INIT, &[
                (|i| i.reset = false, ERR_INIT, ""),
                (|i| (i.reset, i.pc) = (true, false), ERR_INIT, ""),
                (|i| i.reset = false, INIT, ""),
            ]),
            // DISABLE: NOT S_SafeControl first (even with a ProcessControl edge), then the
            // edge; S_OutControl TRUE in ENABLE.
            (DISABLE, &[(|i| (i.safe, i.pc) = (false, true), SAFE, "")]),
            (DISABLE, &[(|i| i.pc = true, ENABLE, "")]),
            // DISABLE with ProcessControl TRUE at the entry: static → C010, left with it FALSE.
            (ERR_CONTROL, &[
                (|i| i.auto_reset = false, ERR_CONTROL, ""),
                (|i| i.pc = false, DISABLE, ""),
                (|i| i.pc = true, ENABLE, ""),
            ]),
            // ENABLE: NOT S_SafeControl before NOT ProcessControl.
            (ENABLE, &[
                (|i| i.reset = true, ENABLE, ""),
                (|i| (i.safe, i.pc) = (false, false), SAFE, "S_OutControl FALSE in the same call"),
            ]),
            (ENABLE, &[(|i| i.pc = false, DISABLE, "")]),
            // SAFE: S_AutoReset → DISABLE, else LOCK; stays while S_SafeControl is FALSE.
            (SAFE, &[
                (|i| (i.reset, i.auto_reset) = (true, true), SAFE, ""),
                (|i| i.safe = true, DISABLE, ""),
            ]),
            // LOCK: NOT S_SafeControl first, static Reset, both edges (C030), RT(Reset).
            (LOCK, &[(|i| (i.safe, i.reset) = (false, true), SAFE, "")]),
            (LOCK, &[
                (|i| i.auto_reset = true, LOCK, "S_AutoReset does not leave LOCK"),
                (|i| i.reset = true, DISABLE, ""),
            ]),
            (ERR_RESET_2, &[
                (|i| i.safe = false, ERR_RESET_2, "stays while Reset is TRUE"),
                (|i| i.reset = false, LOCK, ""),
                (|_| {}, SAFE, ""),
            ]),
            // C030: left with Reset and ProcessControl FALSE, to LOCK.
            (ERR_LOCK, &[
                (|i| i.reset = false, ERR_LOCK, ""),
                (|i| i.pc = false, LOCK, ""),
            ]),
        ];
        // Every step: the DiagCode of the state, S_OutControl TRUE exactly in ENABLE.
        step_table(&format!("profile {p}"), cases, r, |rig, i, want| {
            let got = rig.step(i);
            (
                (got, rig.fb.S_OutControl),
                (rig.c(want), u8::from(want == ENABLE)),
            )
        });
    }
}

/// StaticControl TRUE: ProcessControl's level suffices in DISABLE (no C010); it is a
/// constant (a change while activated is C3FD; an invalid byte is C3FC).
#[test]
fn static_control() {
    for p in profiles() {
        let mut rig = Rig::new(p, true);
        let mut i = In {
            start_reset: true,
            safe: true,
            pc: true,
            ..ON
        };
        assert_eq!(rig.step(i), rig.c(INIT));
        assert_eq!(rig.step(i), rig.c(DISABLE));
        assert_eq!(rig.step(i), rig.c(ENABLE), "level, no edge");
        i.safe = false;
        assert_eq!(rig.step(i), rig.c(SAFE));
        i.safe = true;
        i.auto_reset = true;
        assert_eq!(rig.step(i), rig.c(DISABLE));
        assert_eq!(rig.step(i), rig.c(ENABLE));
    }
    // The same sequence with StaticControl FALSE needs the edge: C010.
    let mut rig = Rig::new(0, false);
    let i = In {
        start_reset: true,
        safe: true,
        pc: true,
        ..ON
    };
    assert_eq!(rig.step(i), 0x8401);
    assert_eq!(rig.step(i), 0x8006);
    assert_eq!(rig.step(i), 0xC010);

    let mut fb = SF_OutControl {
        Activate: 1,
        ..Default::default()
    };
    assert_eq!(fb.cycle(0), SL_OK);
    fb.StaticControl = 1;
    assert_eq!(fb.cycle(1), SL_E_PARAM_CHANGED);
    assert_eq!((fb.DiagCode, fb.Error), (SL_SF_DIAG_CONST_CHANGED, 1));
    fb.Activate = 0;
    assert_eq!(fb.cycle(2), SL_OK);
    fb.StaticControl = 2;
    assert_eq!(fb.init(), SL_E_CONFIG);
    fb.Activate = 1;
    assert_eq!(fb.cycle(3), SL_E_CONFIG);
    assert_eq!((fb.DiagCode, fb.S_OutControl), (SL_SF_DIAG_CONFIG, 0));
}

/// The R_TRIG of ProcessControl runs in every call: a ProcessControl raised while the block
/// is in SAFE or LOCK is no edge in DISABLE later.
#[test]
fn the_process_control_edge_is_evaluated_every_call() {
    let mut rig = Rig::new(0, false);
    let mut i = rig.reach(LOCK);
    i.pc = true;
    assert_eq!(rig.step(i), 0x8404);
    i.reset = true;
    assert_eq!(rig.step(i), 0x8006);
    assert_eq!(rig.step(i), 0xC010, "held since LOCK: static");
    // Activate FALSE with ProcessControl TRUE, then activation and a Reset edge: the edge
    // of ProcessControl is long gone.
    let mut rig = Rig::new(0, false);
    let mut i = In {
        activate: false,
        safe: true,
        pc: true,
        ..ON
    };
    assert_eq!(rig.step(i), 0);
    i.activate = true;
    assert_eq!(rig.step(i), 0x8401);
    i.reset = true;
    assert_eq!(rig.step(i), 0x8006);
    assert_eq!(rig.step(i), 0xC010);
    // An invalid ProcessControl byte reads FALSE: the output drops.
    let mut rig = Rig::new(0, false);
    rig.reach(ENABLE);
    rig.fb.ProcessControl = 0x11;
    rig.now += 10;
    assert_eq!(rig.fb.cycle(rig.now), SL_E_INVALID_BOOL);
    assert_eq!((rig.fb.DiagCode, rig.fb.S_OutControl), (0x8006, 0));
}

#[test]
fn outputs_per_state_and_activate_false_from_every_state() {
    let expect = |s: Code| -> [u8; 5] {
        match s {
            INIT | LOCK => [1, 0, 0, 1, 0],
            SAFE => [1, 0, 1, 0, 0],
            DISABLE => [1, 0, 0, 0, 0],
            ENABLE => [1, 1, 0, 0, 0],
            ERR_RESET_1 | ERR_RESET_2 | ERR_CONTROL | ERR_INIT | ERR_LOCK => [1, 0, 0, 0, 1],
            _ => [0; 5],
        }
    };
    for p in profiles() {
        for s in ALL.into_iter().filter(|s| *s != IDLE) {
            let mut rig = Rig::new(p, false);
            let mut i = rig.reach(s);
            let mut want = expect(s);
            if i.reset {
                want[3] = 0;
            }
            assert_eq!(rig.outputs(), want, "{s:X?} profile {p}");
            assert_eq!(rig.fb.DiagCode, rig.c(s));
            i.activate = false;
            assert_eq!(rig.step(i), 0);
            assert_eq!(rig.outputs(), [0; 5], "{s:X?}");
            i.activate = true;
            assert_eq!(rig.step(i), rig.c(INIT));
        }
    }
}

/// Start-up: without S_StartReset the start-up inhibit (8401, ResetRequest) until a Reset
/// edge, then a ProcessControl edge; with it DISABLE in the second call.
#[test]
fn start_up_with_and_without_s_start_reset() {
    let mut rig = Rig::new(0, false);
    let mut i = In { safe: true, ..ON };
    assert_eq!(rig.step(i), 0x8401);
    assert_eq!(rig.step(i), 0x8401);
    assert_eq!(rig.fb.ResetRequest, 1);
    i.reset = true;
    assert_eq!(rig.step(i), 0x8006);
    assert_eq!(rig.fb.ResetRequest, 0);
    i.pc = true;
    assert_eq!(rig.step(i), 0x8000);
    assert_eq!(rig.fb.S_OutControl, 1);

    let mut rig = Rig::new(1, false);
    let i = In {
        safe: true,
        start_reset: true,
        ..ON
    };
    assert_eq!(rig.step(i), 0x8001);
    assert_eq!(rig.step(i), 0x8010);
    assert_eq!(
        rig.step(In { pc: true, ..i }),
        0x8000,
        "v1.0 profile, same machine"
    );
}

/// sl_diag_text: every code of both profiles; 8002 (v1.0 SAFE) has no v2.01 meaning here,
/// C010 is ERR_CONTROL in both, C011 is ERR_RESET_2 in v2.01 and ERR_INIT in v1.0 (the v2.01
/// text is given: semantics QO6).
#[test]
fn texts_for_every_diag_code() {
    let text = |code: u16| diag_text(SL_TYPE_SF_OUTCONTROL, code);
    let mut seen = BTreeSet::new();
    for (v2, v1) in ALL {
        let t = text(v2);
        assert!(!t.is_empty() && t != "unknown DiagCode", "{v2:04X}");
        seen.insert(t.clone());
        if !ALL.iter().any(|s| s.0 == v1) {
            assert_eq!(text(v1), t, "v1.0 {v1:04X}");
        }
    }
    assert_eq!(seen.len(), ALL.len());
    assert_eq!(text(0xC011), text(ERR_RESET_2.0));
    assert_eq!(text(0x8123), "unknown DiagCode");
}

#[test]
fn random_sequences_agree_with_the_model() {
    let walk = Walk::new("SF_OutControl", 0x5F19, ALL.iter().map(|s| s.0));
    walk.run(
        |p, seq, rng| {
            let static_control = seq % 3 == 0;
            let rig = Rig::new(p, static_control);
            (
                static_control,
                rig,
                Model::default(),
                rates::<6>(rng),
                In::default(),
            )
        },
        |(static_control, rig, model, rates, i), p, rng| {
            let f = flips(rng, rates, &mut i.activate);
            i.safe ^= f[1];
            i.pc ^= f[2];
            i.start_reset ^= f[3] && rng.next() % 3 == 0;
            i.auto_reset ^= f[4];
            i.reset ^= f[5];
            let got = rig.step(*i);
            let v2 = model.step(*i, *static_control);
            let want = ALL.iter().find(|s| s.0 == v2).map(|s| rig.c(*s)).unwrap();
            assert_eq!(got, want, "profile {p} static {static_control}: {i:?}");
            let o = rig.outputs();
            assert_eq!(o[0] == 1, got != 0);
            assert_eq!(o[1] == 1, got == 0x8000);
            assert_eq!(o[4] == 1, got >= 0xC000);
            assert!(o[1] == 0 || (i.safe && i.pc), "output TRUE without both");
            v2
        },
    );
}

/// SF_OutControl in a group: S_SafeControl linked from an SF_EmergencyStop's output, its
/// S_OutControl to an FB_AND; the E-stop pressed drops the chain in the same group cycle.
#[test]
fn in_a_group_with_links() {
    let mut es = RawBox::new(SF_EmergencyStop::default());
    let mut oc = RawBox::new(SF_OutControl::default());
    let and = and_following_in1();
    let mut grp = CGroup::new(3, 2);
    grp.add_estop(&es);
    grp.add_init(
        SL_TYPE_SF_OUTCONTROL,
        &oc,
        safelogic::ffi::sl_sf_outcontrol_init,
    );
    grp.add_init(SL_TYPE_AND, &and, safelogic::ffi::sl_and_init);
    grp.link(
        0,
        core::mem::offset_of!(SF_EmergencyStop, S_EStopOut) as u16,
        1,
        core::mem::offset_of!(SF_OutControl, S_SafeControl) as u16,
    );
    grp.link(
        1,
        core::mem::offset_of!(SF_OutControl, S_OutControl) as u16,
        2,
        field(SL_TYPE_AND, "bAndIn1"),
    );

    es.Activate = 1;
    es.S_EStopIn = 1;
    es.S_StartReset = 1;
    oc.Activate = 1;
    oc.S_StartReset = 1;
    oc.S_AutoReset = 1;
    grp.g.bRun = 1;
    for k in 0..3 {
        assert_eq!(grp.cycle(10), SL_OK, "group call {k}");
    }
    assert_eq!(oc.DiagCode, 0x8006);
    oc.ProcessControl = 1;
    grp.cycle(10);
    assert_eq!((oc.DiagCode, and.bAndOut), (0x8000, 1));
    es.S_EStopIn = 0;
    grp.cycle(10);
    assert_eq!((es.DiagCode, oc.DiagCode, and.bAndOut), (0x8804, 0x8802, 0));
    grp.g.bRun = 0;
    assert_eq!(grp.cycle(10), SL_OK);
    assert_eq!((oc.DiagCode, oc.Ready), (0, 0));
}
