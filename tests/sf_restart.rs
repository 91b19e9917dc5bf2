//! SF_EmergencyStop, SF_ESPE and SF_PSE (PLCopen TC5 Part 1; research `plcopen_safety.md`
//! §4.1–§4.3, §5; generic rules §3 and `plcopen-safety-generic-diag.txt`): every
//! transition of the table of §4.1 with its first-match order, every DiagCode in both
//! profiles, static-reset errors, Activate FALSE from every state, start-up with and
//! without S_StartReset, the envelope's library faults, the C functions and texts, and
//! 10,000 random sequences against an independent model of the table. Every expected code
//! is the research table's (v2.01 / v1.0 column), never read back from the library.

mod common;
use common::cgroup::*;
use common::plcopen::*;
use common::*;
use safelogic::base::member::Member;
use safelogic::*;
use std::collections::BTreeSet;
use std::ffi::CStr;

// (v2.01, v1.0) codes of the states of §4.1's DiagCode table.
codes! {
    IDLE = 0x0000 / 0x0000, INIT = 0x8001 / 0x8001, ENABLED = 0x8000 / 0x8000,
    WAIT_IN_1 = 0x8802 / 0x8002, WAIT_RESET_1 = 0x8402 / 0x8003, WAIT_IN_2 = 0x8804 / 0x8004,
    WAIT_RESET_2 = 0x8404 / 0x8005, ERR_RESET_1 = 0xC001 / 0xC001, ERR_RESET_2 = 0xC011 / 0xC002,
}

/// One call's inputs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct In {
    activate: bool,
    input: bool,
    start_reset: bool,
    auto_reset: bool,
    reset: bool,
}

/// The independent model: §4.1's table with the v1.0 codes, written from the research
/// text (guards top to bottom, first match), R_TRIG on Reset in every call, Activate first.
#[derive(Default)]
struct Model {
    state: u16,
    reset_prev: bool,
}

impl Model {
    fn step(&mut self, i: In) -> u16 {
        let (rt, static_reset) = edges(&mut self.reset_prev, i.reset);
        self.state = if !i.activate {
            0x0000
        } else {
            match self.state {
                0x0000 => 0x8001,
                0x8001 if !i.start_reset => 0x8002,
                0x8001 if !i.input => 0x8004,
                0x8001 => 0x8000,
                0x8002 if i.input => 0x8003,
                0x8003 if static_reset => 0xC001,
                0x8003 if !i.input => 0x8002,
                0x8003 if rt => 0x8000,
                0xC001 if !i.reset => 0x8003,
                0x8004 if i.input && !i.auto_reset => 0x8005,
                0x8004 if i.input && i.auto_reset => 0x8000,
                0x8005 if static_reset => 0xC002,
                0x8005 if !i.input => 0x8004,
                0x8005 if rt || i.auto_reset => 0x8000,
                0xC002 if !i.reset => 0x8005,
                0x8000 if !i.input => 0x8004,
                s => s,
            }
        };
        self.state
    }
}

/// What a test needs of each block of the family.
trait Family: FunctionBlock + Member + Default + Copy {
    const NAME: &'static str;
    const HAS_V10: bool;
    fn apply(&mut self, i: In);
    fn out(&self) -> bool;
    fn outputs(&self) -> [u8; 5];
    fn code(&self) -> u16;
    fn profile(&mut self, p: u8);
    fn c_cycle(&mut self, now: u32) -> i32;
    fn c_init(&mut self) -> i32;
    fn set_activate_raw(&mut self, v: u8);
}

macro_rules! family {
    ($ty:ident, $v10:expr, $input:ident, $output:ident, $init:ident, $cycle:ident) => {
        impl Family for $ty {
            const NAME: &'static str = stringify!($ty);
            const HAS_V10: bool = $v10;
            fn apply(&mut self, i: In) {
                self.Activate = u8::from(i.activate);
                self.$input = u8::from(i.input);
                self.S_StartReset = u8::from(i.start_reset);
                self.S_AutoReset = u8::from(i.auto_reset);
                self.Reset = u8::from(i.reset);
            }
            fn out(&self) -> bool {
                self.$output == 1
            }
            fn outputs(&self) -> [u8; 5] {
                [
                    self.Ready,
                    self.$output,
                    self.SafetyDemand,
                    self.ResetRequest,
                    self.Error,
                ]
            }
            fn code(&self) -> u16 {
                self.DiagCode
            }
            fn profile(&mut self, p: u8) {
                self.nDiagProfile = p;
            }
            fn c_cycle(&mut self, now: u32) -> i32 {
                // SAFETY: a live, exclusively borrowed instance.
                unsafe { safelogic::ffi::$cycle(self, now) }
            }
            fn c_init(&mut self) -> i32 {
                // SAFETY: as above.
                unsafe { safelogic::ffi::$init(self) }
            }
            fn set_activate_raw(&mut self, v: u8) {
                self.Activate = v;
            }
        }
    };
}
family!(
    SF_EmergencyStop,
    true,
    S_EStopIn,
    S_EStopOut,
    sl_sf_emergencystop_init,
    sl_sf_emergencystop_cycle
);
family!(
    SF_ESPE,
    true,
    S_ESPE_In,
    S_ESPE_Out,
    sl_sf_espe_init,
    sl_sf_espe_cycle
);
family!(
    SF_PSE,
    false,
    S_PSE_In,
    S_PSE_Out,
    sl_sf_pse_init,
    sl_sf_pse_cycle
);

/// A driven instance: one call per `step`, 10 ms apart.
struct Rig<B: Family> {
    fb: B,
    now: u32,
    profile: u8,
}

impl<B: Family> Rig<B> {
    fn new(profile: u8) -> Self {
        let mut fb = B::default();
        fb.profile(profile);
        assert_eq!(fb.c_init(), SL_OK);
        assert_eq!(fb.code(), 0);
        Self {
            fb,
            now: 1_000,
            profile,
        }
    }
    fn step(&mut self, i: In) -> u16 {
        self.fb.apply(i);
        self.now = self.now.wrapping_add(10);
        assert_eq!(self.fb.c_cycle(self.now), SL_OK, "{}", B::NAME);
        self.fb.code()
    }
    /// The code of a state pair in this rig's profile.
    fn c(&self, s: Code) -> u16 {
        code(self.profile, s)
    }
    /// Drives to a state of §4.1 from IDLE by its documented path; the path's own codes are
    /// checked on the way.
    fn reach(&mut self, target: Code) -> In {
        let mut i = In {
            activate: true,
            ..In::default()
        };
        assert_eq!(self.step(i), self.c(INIT));
        if target == INIT {
            return i;
        }
        match target {
            WAIT_IN_1 | WAIT_RESET_1 | ERR_RESET_1 => {
                assert_eq!(self.step(i), self.c(WAIT_IN_1));
                if target == WAIT_IN_1 {
                    return i;
                }
                if target == ERR_RESET_1 {
                    // Reset pressed while waiting for the input, held into 8402.
                    i.reset = true;
                    assert_eq!(self.step(i), self.c(WAIT_IN_1));
                }
                i.input = true;
                assert_eq!(self.step(i), self.c(WAIT_RESET_1));
                if target == ERR_RESET_1 {
                    assert_eq!(self.step(i), self.c(ERR_RESET_1));
                }
                i
            }
            ENABLED => {
                i.input = true;
                i.start_reset = true;
                assert_eq!(self.step(i), self.c(ENABLED));
                i
            }
            WAIT_IN_2 | WAIT_RESET_2 | ERR_RESET_2 => {
                i.start_reset = true;
                assert_eq!(self.step(i), self.c(WAIT_IN_2));
                if target == WAIT_IN_2 {
                    return i;
                }
                if target == ERR_RESET_2 {
                    i.reset = true;
                    assert_eq!(self.step(i), self.c(WAIT_IN_2));
                }
                i.input = true;
                assert_eq!(self.step(i), self.c(WAIT_RESET_2));
                if target == ERR_RESET_2 {
                    assert_eq!(self.step(i), self.c(ERR_RESET_2));
                }
                i
            }
            other => panic!("no path to {other:X?}"),
        }
    }
}

fn profiles<B: Family>() -> Vec<u8> {
    if B::HAS_V10 {
        vec![SL_SF_PROFILE_V201, SL_SF_PROFILE_V10]
    } else {
        vec![SL_SF_PROFILE_V201]
    }
}

/// Every row of §4.1's table, in both profiles, with the guards that come earlier in the
/// row order made to match too where they can (first match wins).
fn transitions<B: Family>() {
    for p in profiles::<B>() {
        let r = |t| {
            let mut rig = Rig::<B>::new(p);
            let i = rig.reach(t);
            (rig, i)
        };
        // 0000 --Activate--> 8001, and nothing else in that call (one transition per call).
        let (mut rig, mut i) = (Rig::<B>::new(p), In::default());
        i.input = true;
        i.start_reset = true;
        assert_eq!(rig.step(i), 0);
        i.activate = true;
        assert_eq!(rig.step(i), rig.c(INIT));
        // 8001: NOT S_StartReset → 8802 even with the input TRUE (first row).
        let (mut rig, mut i) = r(INIT);
        i.input = true;
        assert_eq!(rig.step(i), rig.c(WAIT_IN_1), "{}", B::NAME);
        // 8001: S_StartReset AND NOT input → 8804; S_StartReset AND input → 8000.
        #[rustfmt::skip]
        let cases: &[Case<In>] = &[
            (INIT, &[(|i| i.start_reset = true, WAIT_IN_2, "")]),
            (INIT, &[(|i| (i.start_reset, i.input) = (true, true), ENABLED, "")]),
            // 8802: stays while the input is FALSE (a Reset edge changes nothing), input → 8402.
            (WAIT_IN_1, &[
                (|i| i.reset = true, WAIT_IN_1, ""),
                (|i| (i.reset, i.input) = (false, true), WAIT_RESET_1, ""),
            ]),
            // 8402: static Reset first (before NOT input): → C001.
            (WAIT_IN_1, &[
                (|i| i.reset = true, WAIT_IN_1, ""),
                (|i| i.input = true, WAIT_RESET_1, ""),
                (|i| i.input = false, ERR_RESET_1, "static Reset before NOT input"),
            ]),
            // 8402: NOT input before RT(Reset): → 8802.
            (WAIT_RESET_1, &[(|i| (i.input, i.reset) = (false, true), WAIT_IN_1, "")]),
            // 8402: RT(Reset) → 8000; stays without an edge.
            (WAIT_RESET_1, &[
                (|_| {}, WAIT_RESET_1, ""),
                (|i| i.auto_reset = true, WAIT_RESET_1, ""), // S_AutoReset does not reset after activation
                (|i| i.reset = true, ENABLED, ""),
            ]),
            // C001: stays while Reset is TRUE (the input falling changes nothing), NOT Reset → 8402.
            (ERR_RESET_1, &[
                (|i| i.input = false, ERR_RESET_1, ""),
                (|i| (i.input, i.reset) = (true, false), WAIT_RESET_1, ""),
                (|i| i.reset = true, ENABLED, ""),
            ]),
            // 8804: input AND NOT S_AutoReset → 8404; input AND S_AutoReset → 8000; a Reset
            // edge while the input is FALSE changes nothing.
            (WAIT_IN_2, &[
                (|i| i.reset = true, WAIT_IN_2, ""),
                (|i| (i.reset, i.input) = (false, true), WAIT_RESET_2, ""),
            ]),
            (WAIT_IN_2, &[(|i| (i.input, i.auto_reset) = (true, true), ENABLED, "")]),
            // 8404: static Reset first (before NOT input and before S_AutoReset) → C011.
            (WAIT_IN_2, &[
                (|i| i.reset = true, WAIT_IN_2, ""),
                (|i| i.input = true, WAIT_RESET_2, ""),
                (|i| (i.input, i.auto_reset) = (false, true), ERR_RESET_2, "static Reset first"),
            ]),
            // 8404: NOT input before RT(Reset) / S_AutoReset → 8804.
            (WAIT_RESET_2, &[
                (|i| (i.input, i.reset, i.auto_reset) = (false, true, true), WAIT_IN_2, ""),
            ]),
            // 8404: RT(Reset) → 8000; S_AutoReset → 8000.
            (WAIT_RESET_2, &[
                (|_| {}, WAIT_RESET_2, ""),
                (|i| i.reset = true, ENABLED, ""),
            ]),
            (WAIT_RESET_2, &[(|i| i.auto_reset = true, ENABLED, "")]),
            // C011: stays while Reset is TRUE, NOT Reset → 8404.
            (ERR_RESET_2, &[
                (|_| {}, ERR_RESET_2, ""),
                (|i| i.reset = false, WAIT_RESET_2, ""),
            ]),
        ];
        step_table(
            &format!("{} profile {p}", B::NAME),
            cases,
            r,
            |rig, i, want| (rig.step(i), rig.c(want)),
        );
        // 8000: NOT input → 8804 with the output FALSE in the same call.
        let (mut rig, mut i) = r(ENABLED);
        assert!(rig.fb.out());
        i.reset = true; // nothing else leaves 8000
        i.start_reset = false;
        assert_eq!(rig.step(i), rig.c(ENABLED));
        i.input = false;
        assert_eq!(rig.step(i), rig.c(WAIT_IN_2));
        assert!(!rig.fb.out(), "output FALSE in the same call");
    }
}

#[test]
fn every_transition_in_first_match_order() {
    transitions::<SF_EmergencyStop>();
    transitions::<SF_ESPE>();
    transitions::<SF_PSE>();
}

/// Outputs of each state (research §3.2, §9.3; the generic page's examples): Ready, the
/// safety output, SafetyDemand, ResetRequest (Reset FALSE), Error.
fn outputs_per_state<B: Family>() {
    let expect = |s: Code| -> [u8; 5] {
        match s {
            INIT => [1, 0, 0, 0, 0],
            ENABLED => [1, 1, 0, 0, 0],
            WAIT_IN_1 | WAIT_IN_2 => [1, 0, 1, 0, 0],
            WAIT_RESET_1 | WAIT_RESET_2 => [1, 0, 0, 1, 0],
            ERR_RESET_1 | ERR_RESET_2 => [1, 0, 0, 0, 1],
            _ => [0; 5],
        }
    };
    for p in profiles::<B>() {
        for s in ALL.into_iter().filter(|s| *s != IDLE) {
            let mut rig = Rig::<B>::new(p);
            let i = rig.reach(s);
            let mut want = expect(s);
            if i.reset {
                want[3] = 0; // ResetRequest is FALSE while Reset is TRUE
            }
            assert_eq!(rig.fb.outputs(), want, "{} {s:X?} profile {p}", B::NAME);
            assert_eq!(rig.fb.code(), rig.c(s));
        }
    }
}

#[test]
fn outputs_follow_the_state() {
    outputs_per_state::<SF_EmergencyStop>();
    outputs_per_state::<SF_ESPE>();
    outputs_per_state::<SF_PSE>();
}

/// ResetRequest is FALSE while Reset is TRUE (PLCN: "the reset signal must first be
/// switched to FALSE"), TRUE again when it is released.
#[test]
fn reset_request_waits_for_reset_false() {
    let mut rig = Rig::<SF_EmergencyStop>::new(0);
    let mut i = rig.reach(WAIT_IN_1);
    i.reset = true;
    assert_eq!(rig.step(i), 0x8802);
    i.input = true;
    assert_eq!(rig.step(i), 0x8402);
    assert_eq!(rig.fb.ResetRequest, 0, "Reset TRUE: no request");
    // Held into the wait state: the next call is the static-reset error.
    assert_eq!(rig.step(i), 0xC001);
    i.reset = false;
    assert_eq!(rig.step(i), 0x8402);
    assert_eq!(rig.fb.ResetRequest, 1);
}

fn activate_false_from_every_state<B: Family>() {
    for p in profiles::<B>() {
        for s in ALL.into_iter().filter(|s| *s != IDLE) {
            let mut rig = Rig::<B>::new(p);
            let mut i = rig.reach(s);
            i.activate = false;
            assert_eq!(rig.step(i), 0, "{} {s:X?}", B::NAME);
            assert_eq!(rig.fb.outputs(), [0; 5], "{} {s:X?}", B::NAME);
            // Activate again: INIT, then the start-up path (a held Reset is static).
            i.activate = true;
            assert_eq!(rig.step(i), rig.c(INIT));
        }
        // An invalid Activate byte is FALSE.
        let mut rig = Rig::<B>::new(p);
        rig.reach(ENABLED);
        rig.fb.set_activate_raw(7);
        assert_eq!(rig.fb.c_cycle(rig.now + 10), SL_E_INVALID_BOOL);
        assert_eq!(rig.fb.code(), 0);
        assert_eq!(rig.fb.outputs(), [0; 5]);
    }
}

#[test]
fn activate_false_is_idle_from_every_state() {
    activate_false_from_every_state::<SF_EmergencyStop>();
    activate_false_from_every_state::<SF_ESPE>();
    activate_false_from_every_state::<SF_PSE>();
}

/// Start-up (research §3.1): S_StartReset FALSE needs a Reset edge after activation even
/// with the input TRUE; S_StartReset TRUE enables in the second call. A Reset held through
/// the activation is a static-reset error once the input is TRUE.
#[test]
fn start_up_with_and_without_s_start_reset() {
    let on = In {
        activate: true,
        input: true,
        ..In::default()
    };
    let mut rig = Rig::<SF_EmergencyStop>::new(0);
    assert_eq!(rig.step(on), 0x8001);
    assert_eq!(rig.step(on), 0x8802);
    assert_eq!(rig.step(on), 0x8402);
    assert_eq!(rig.step(on), 0x8402);
    assert_eq!(rig.step(In { reset: true, ..on }), 0x8000);
    assert_eq!(rig.fb.S_EStopOut, 1);

    let auto = In {
        start_reset: true,
        ..on
    };
    let mut rig = Rig::<SF_EmergencyStop>::new(0);
    assert_eq!(rig.step(auto), 0x8001);
    assert_eq!(rig.fb.S_EStopOut, 0);
    assert_eq!(rig.step(auto), 0x8000);
    assert_eq!(rig.fb.S_EStopOut, 1);

    // Reset held from before the activation: the R_TRIG saw its edge while idle.
    let held = In { reset: true, ..on };
    let mut rig = Rig::<SF_EmergencyStop>::new(0);
    assert_eq!(
        rig.step(In {
            activate: false,
            ..held
        }),
        0
    );
    assert_eq!(rig.step(held), 0x8001);
    assert_eq!(rig.step(held), 0x8802);
    assert_eq!(rig.step(held), 0x8402);
    assert_eq!(rig.step(held), 0xC001);
}

/// The v1.0 profile is latched at activation; a change while activated is the library
/// fault C3FD (SL_E_PARAM_CHANGED) until Activate FALSE; an unknown profile is C3FC
/// (SL_E_CONFIG); SF_PSE has no v1.0 codes.
#[test]
fn the_profile_is_a_constant_per_activation() {
    let on = In {
        activate: true,
        input: true,
        start_reset: true,
        ..In::default()
    };
    let mut fb = SF_EmergencyStop::default();
    fb.apply(on);
    assert_eq!(fb.c_cycle(0), SL_OK);
    assert_eq!(fb.DiagCode, 0x8001);
    fb.nDiagProfile = 1;
    assert_eq!(fb.c_cycle(10), SL_E_PARAM_CHANGED);
    assert_eq!(
        (fb.DiagCode, fb.Error, fb.S_EStopOut),
        (SL_SF_DIAG_CONST_CHANGED, 1, 0)
    );
    assert_eq!(
        fb.c_cycle(20),
        SL_E_PARAM_CHANGED,
        "stays until Activate FALSE"
    );
    fb.nDiagProfile = 0;
    assert_eq!(
        fb.c_cycle(30),
        SL_E_PARAM_CHANGED,
        "restoring the value does not leave it"
    );
    fb.nDiagProfile = 1;
    fb.Activate = 0;
    assert_eq!(fb.c_cycle(40), SL_OK);
    assert_eq!(fb.DiagCode, 0);
    fb.Activate = 1;
    assert_eq!(fb.c_cycle(50), SL_OK);
    assert_eq!(fb.c_cycle(60), SL_OK);
    assert_eq!(fb.DiagCode, 0x8000, "v1.0 now, same state");

    for bad in [2u8, 0xFF] {
        let mut fb = SF_EmergencyStop {
            nDiagProfile: bad,
            ..Default::default()
        };
        assert_eq!(fb.c_init(), SL_E_CONFIG);
        fb.apply(on);
        assert_eq!(fb.c_cycle(0), SL_E_CONFIG);
        assert_eq!((fb.DiagCode, fb.Error, fb.Ready), (SL_SF_DIAG_CONFIG, 1, 1));
        assert_eq!(fb.c_cycle(10), SL_E_CONFIG);
        fb.Activate = 0;
        assert_eq!(fb.c_cycle(20), SL_OK);
        assert_eq!(fb.DiagCode, 0);
    }
    let mut pse = SF_PSE {
        nDiagProfile: SL_SF_PROFILE_V10,
        ..Default::default()
    };
    assert_eq!(pse.c_init(), SL_E_CONFIG);
    pse.apply(on);
    assert_eq!(pse.c_cycle(0), SL_E_CONFIG);
    assert_eq!(pse.DiagCode, SL_SF_DIAG_CONFIG);
}

/// Library faults: a clock that goes back (C3FE), a corrupt private state (C3FF); both
/// leave only through Activate FALSE; a wrap of the clock at 2^32 is no fault.
#[test]
fn library_faults() {
    let on = In {
        activate: true,
        input: true,
        start_reset: true,
        ..In::default()
    };
    let mut fb = SF_EmergencyStop::default();
    fb.apply(on);
    assert_eq!(fb.c_cycle(u32::MAX - 5), SL_OK);
    assert_eq!(fb.c_cycle(4), SL_OK, "wrap");
    assert_eq!(fb.DiagCode, 0x8000);
    assert_eq!(fb.c_cycle(3), SL_E_CLOCK);
    assert_eq!(
        (fb.DiagCode, fb.S_EStopOut, fb.Error),
        (SL_SF_DIAG_CLOCK, 0, 1)
    );
    assert_eq!(fb.c_cycle(10), SL_E_CLOCK);
    fb.Activate = 0;
    assert_eq!(fb.c_cycle(20), SL_OK);
    fb.Activate = 1;
    assert_eq!(fb.c_cycle(30), SL_OK);
    assert_eq!(fb.c_cycle(40), SL_OK);
    assert_eq!(fb.DiagCode, 0x8000);
    // One flipped bit of the private state.
    fb.stPrivate.stHeader.wDiag ^= 0x0002;
    assert_eq!(fb.c_cycle(50), SL_E_CORRUPT);
    assert_eq!((fb.DiagCode, fb.S_EStopOut), (SL_SF_DIAG_CORRUPT, 0));
    assert_eq!(fb.c_cycle(60), SL_E_CORRUPT);
    fb.Activate = 0;
    assert_eq!(fb.c_cycle(70), SL_OK);
    assert_eq!(fb.DiagCode, 0);
    // An invalid safety input byte reads FALSE (the demand).
    fb.Activate = 1;
    fb.c_cycle(80);
    fb.c_cycle(90);
    assert_eq!(fb.DiagCode, 0x8000);
    fb.S_EStopIn = 0x10;
    assert_eq!(fb.c_cycle(100), SL_E_INVALID_BOOL);
    assert_eq!((fb.DiagCode, fb.S_EStopOut), (0x8804, 0));
    // NULL and misaligned pointers are refused.
    // SAFETY: NULL is the documented refusal.
    assert_eq!(
        unsafe { safelogic::ffi::sl_sf_emergencystop_cycle(std::ptr::null_mut(), 0) },
        SL_E_NULL
    );
}

/// The owning group halts an SF_ block through the member interface: DiagCode 0000 while
/// halted, the normal start-up after (semantics PO8).
#[test]
fn a_group_halt_is_idle() {
    let on = In {
        activate: true,
        input: true,
        start_reset: true,
        ..In::default()
    };
    let mut fb = SF_ESPE::default();
    fb.apply(on);
    fb.drive(1, 0);
    assert_eq!(fb.execute(0), Status::Ok);
    assert_eq!(fb.execute(10), Status::Ok);
    assert_eq!(
        (fb.DiagCode, fb.S_ESPE_Out, fb.state()),
        (0x8000, 1, SL_STATE_RUN)
    );
    fb.drive(0, 0);
    assert_eq!(fb.execute(20), Status::Ok);
    assert_eq!(
        (fb.DiagCode, fb.S_ESPE_Out, fb.state()),
        (0, 0, SL_STATE_STOP)
    );
    fb.drive(1, 1);
    fb.execute(30);
    fb.execute(40);
    assert_eq!(fb.DiagCode, 0x8000);
    assert_eq!(fb.state_name(), "ACTIVE");
}

/// sl_diag_text names every DiagCode of both profiles and every library code; sl_state_str
/// the group-level states.
#[test]
fn texts_for_every_diag_code() {
    let text = |tag: u16, code: u16| diag_text(tag, code);
    for tag in [SL_TYPE_SF_EMERGENCYSTOP, SL_TYPE_SF_ESPE, SL_TYPE_SF_PSE] {
        let mut seen = BTreeSet::new();
        for (v2, v1) in ALL {
            for c in [v2, v1] {
                let t = text(tag, c);
                assert!(
                    !t.is_empty() && t != "unknown DiagCode",
                    "{tag} {c:04X}: {t}"
                );
                seen.insert(t);
            }
        }
        assert_eq!(
            seen.len(),
            ALL.len(),
            "one text per state, the same in both profiles"
        );
        assert_eq!(text(tag, 0x8000), "safety input TRUE, safety output TRUE");
        for c in [
            SL_SF_DIAG_CORRUPT,
            SL_SF_DIAG_CLOCK,
            SL_SF_DIAG_CONST_CHANGED,
            SL_SF_DIAG_CONFIG,
        ] {
            assert!(text(tag, c).starts_with("library: "), "{c:04X}");
        }
        assert_eq!(text(tag, 0x8123), "unknown DiagCode");
        for (v, name) in [
            (SL_STATE_STOP, "IDLE"),
            (SL_STATE_RUN, "ACTIVE"),
            (SL_STATE_ERROR, "FAULT"),
        ] {
            // SAFETY: static NUL-terminated text.
            let s = unsafe { CStr::from_ptr(safelogic::ffi::sl_state_str(tag, v)) };
            assert_eq!(s.to_str().unwrap(), name);
        }
    }
}

/// 10,000 random sequences of 40 calls per block and profile against the model: the same
/// DiagCode after every call, the outputs from it, and every state reached.
fn against_the_model<B: Family>(seed: u64) {
    let walk = Walk {
        profiles: profiles::<B>(),
        ..Walk::new(B::NAME, seed, ALL.iter().map(|s| s.1))
    };
    walk.run(
        |p, _, rng| {
            let rig = Rig::<B>::new(p);
            // Per sequence, how often each input changes (some sequences hold Reset long).
            let rates: [u64; 5] = core::array::from_fn(|_| 2 + rng.next() % 12);
            (rig, Model::default(), rates, In::default())
        },
        |(rig, model, rates, i), p, rng| {
            let mut flips = [false; 5];
            for (k, f) in flips.iter_mut().enumerate() {
                *f = rng.next() % rates[k] == 0;
            }
            // Activate mostly TRUE: an idle block reaches nothing.
            i.activate = if i.activate {
                !flips[0]
            } else {
                flips[0] || rng.next() % 3 == 0
            };
            i.input ^= flips[1];
            i.start_reset ^= flips[2];
            i.auto_reset ^= flips[3];
            i.reset ^= flips[4];
            let got = rig.step(*i);
            let v1 = model.step(*i);
            let want = ALL.iter().find(|s| s.1 == v1).map(|s| rig.c(*s)).unwrap();
            assert_eq!(got, want, "{} profile {p}: {i:?}", B::NAME);
            let o = rig.fb.outputs();
            assert_eq!(o[0] == 1, got != 0);
            assert_eq!(o[1] == 1, got == 0x8000);
            assert_eq!(o[4] == 1, got >= 0xC000);
            assert!(i.input || o[1] == 0, "input FALSE, output TRUE");
            v1
        },
    );
}

#[test]
fn random_sequences_agree_with_the_model() {
    against_the_model::<SF_EmergencyStop>(0x5F01);
    against_the_model::<SF_ESPE>(0x5F02);
    against_the_model::<SF_PSE>(0x5F03);
}

/// An SF_ block as a group member (semantics PO8): refused never-initialised, accepted
/// after init; its safety output linked to an FB_AND; a PLCopen error (static reset) does
/// not stop the group; the group's FbRun FALSE (group STOP) halts it: DiagCode 0000.
#[test]
fn in_a_group_with_a_link() {
    let mut w = WithAnd::of(SF_EmergencyStop::default(), "S_EStopOut");
    w.fb.Activate = 1;
    w.fb.S_EStopIn = 1;
    w.fb.S_StartReset = 1;
    w.run(3);
    w.expect_group(0x8000, 1, SL_STATE_RUN);
    // A safety demand and a Reset held into the wait state: C011, the group runs on.
    w.fb.S_StartReset = 0;
    w.fb.S_EStopIn = 0;
    w.fb.Reset = 1;
    w.grp.cycle(10);
    w.expect(0x8804, 0);
    w.fb.S_EStopIn = 1;
    w.grp.cycle(10);
    w.grp.cycle(10);
    assert_eq!(
        (w.fb.DiagCode, w.fb.Error, w.grp.g.nState),
        (0xC011, 1, SL_STATE_RUN)
    );
    w.fb.Reset = 0;
    w.grp.cycle(10);
    w.fb.Reset = 1;
    w.grp.cycle(10);
    w.expect(0x8000, 1);
    // Group STOP: the SF_ block is halted (idle), its link carries FALSE.
    w.stop_group();
    assert_eq!(w.fb.S_EStopOut, 0);
    assert_eq!(w.grp.g.nState, SL_STATE_STOP);
}

/// An SF_EmergencyStop activated at 100 with automatic reset, its output enabled at 110.
fn enabled_at_110() -> SF_EmergencyStop {
    let on = In {
        activate: true,
        input: true,
        start_reset: true,
        ..In::default()
    };
    let mut fb = SF_EmergencyStop::default();
    fb.apply(on);
    assert_eq!(fb.c_cycle(100), SL_OK);
    assert_eq!(fb.c_cycle(110), SL_OK);
    assert_eq!((fb.DiagCode, fb.S_EStopOut), (0x8000, 1));
    fb
}

/// The clock check holds across a return to IDLE (idle keeps the clock memory, semantics
/// PO6): a clock that went back between the call that left for IDLE and the activating call
/// is C3FE (a mutation-testing finding).
#[test]
fn the_clock_check_holds_across_idle() {
    let mut fb = enabled_at_110();
    fb.Activate = 0;
    assert_eq!(fb.c_cycle(120), SL_OK);
    assert_eq!(fb.DiagCode, 0);
    fb.Activate = 1;
    assert_eq!(fb.c_cycle(50), SL_E_CLOCK);
    assert_eq!((fb.DiagCode, fb.S_EStopOut), (SL_SF_DIAG_CLOCK, 0));
}

/// The panic boundary's recovery of an `SF_` block (`Cyclic::force_safe`, base::sf
/// `force_fault`): the library fault C3FF with the safety output FALSE, sealed on the
/// instance's own consistent state (its clock memory kept: a clock that then goes back is
/// C3FE); only Activate FALSE leaves it. Mutation-testing findings.
#[test]
fn forced_fault_is_c3ff_sealed_on_the_instance() {
    use safelogic::base::block::Cyclic;
    let mut fb = enabled_at_110();
    fb.force_safe();
    assert_eq!(
        (fb.DiagCode, fb.S_EStopOut, fb.Error, fb.Ready),
        (SL_SF_DIAG_CORRUPT, 0, 1, 1)
    );
    assert_eq!(fb.c_cycle(50), SL_E_CLOCK, "the clock memory was kept");
    assert_eq!((fb.DiagCode, fb.S_EStopOut), (SL_SF_DIAG_CLOCK, 0));
    fb.Activate = 0;
    assert_eq!(fb.c_cycle(60), SL_OK);
    assert_eq!(fb.DiagCode, 0);
}
