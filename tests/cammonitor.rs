//! FB CAMMONITOR (manual §4.26, ABI-2 §11.13, §12; docs/semantics.md CM1–CM20): one test
//! per diag message (every Text ID reached by a scenario), every state reached, the
//! parameter checks at their boundaries, then random crank trajectories (≥ 10,000 per
//! variant and property, × SL_PROP_DEPTH) that assert what they reached. Every test runs
//! for both variants (UINT, UDINT).

mod common;

use common::Rng;
use safelogic::*;

const A_AUTO: u16 = SL_CAMMONITOR_ACTIVE_AUTOMATIC;
const A_BACK: u16 = SL_CAMMONITOR_ACTIVE_BACKWARDSMOVE;
const A_RESET: u16 = SL_CAMMONITOR_ACTIVE_RESET;
const A_PS: u16 = SL_CAMMONITOR_ACTIVE_PRESSSTARTED;
const A_OCAM: u16 = SL_CAMMONITOR_ACTIVE_OVERRUNCAM;
const A_UCAM: u16 = SL_CAMMONITOR_ACTIVE_UPWARDCAM;
const A_SET: u16 = SL_CAMMONITOR_ACTIVE_SETTINGMODE;
const A_POS: u16 = SL_CAMMONITOR_ACTIVE_POSITION;
const BASE: u16 = A_RESET | A_POS | A_AUTO | A_SET;

const M: u64 = 8192;
const C: u64 = M + 1;
const J: u64 = 4;
/// Excentric limits (TDC1 LL, TDC1 UL, TDC2 LL, TDC2 UL, BDC LL, BDC UL, OverrunMax):
/// the manual's example, TDC 8092…100 (§4.26.3.5).
const EXC: [u64; 7] = [8092, 100, 0, 0, 3896, 4296, 800];
/// Pendulum limits: TDC2 400…3696, TDC1 4496…7796 (§4.26.4.5).
const PEN: [u64; 7] = [4496, 7796, 3696, 400, 3996, 4196, 0];

const RUN: u8 = SL_STATE_RUN;
const STOP: u8 = SL_STATE_STOP;
const SAFE: u8 = SL_STATE_SAFE;
const ERROR: u8 = SL_STATE_ERROR;
const RESET: u8 = SL_STATE_RESET;
const START: u8 = SL_STATE_START;
const WAIT: u8 = SL_STATE_CAMMONITOR_WAIT_FOR_RESET;
const MSTOP: u8 = SL_STATE_CAMMONITOR_MOVE_STOP;
const MSTART: u8 = SL_STATE_CAMMONITOR_MOVE_START;
const MDOWN: u8 = SL_STATE_CAMMONITOR_MOVE_DOWN;
const MUP: u8 = SL_STATE_CAMMONITOR_MOVE_UP;
const MTDC: u8 = SL_STATE_CAMMONITOR_MOVE_TDC;

/// Every Text ID of §4.26.7 and §4.26.8.
const ALL_TEXTS: [u16; 37] = [
    0x4001, 0x4002, 0x4003, 0x4004, 0x4005, 0x4006, 0x4007, 0x4008, 0x4009, 0x400A, 0x400B, 0x400C,
    0x400D, 0x400E, 0x400F, 0x4010, 0x4011, 0x4012, 0x4013, 0x4014, 0x4015, 0x4016, 0x4017, 0x4018,
    0x4019, 0x401A, 0x401B, 0x401C, 0x401D, 0x401E, 0x401F, 0x4020, 0x4021, 0x4022, 0x4023, 0x4024,
    0x4025,
];

thread_local! {
    /// The states and Text IDs the calls of this thread showed.
    static SEEN: std::cell::RefCell<(std::collections::BTreeSet<u8>, std::collections::BTreeSet<u16>)> =
        Default::default();
}

fn note(state: u8, text: u16) {
    SEEN.with(|s| {
        let mut s = s.borrow_mut();
        s.0.insert(state);
        if text != 0 {
            s.1.insert(text);
        }
    });
}

macro_rules! suite {
    ($m:ident, $fb:ty, $t:ty) => {
        mod $m {
            use super::*;
            type Fb = $fb;

            fn make(pendulum: bool, active: u16, l: [u64; 7]) -> Fb {
                let mut fb = Fb::default();
                fb.wInputActive = active;
                fb.dwOptions = if pendulum {
                    SL_OPT_CAMMONITOR_PENDULUM
                } else {
                    0
                };
                fb.tStopDetectionTime = 50;
                fb.tPressStartDelayTime = 200;
                fb.tMoveDetectionTime = 100;
                fb.nAllowedPositionJitter = J as $t;
                fb.nMinPositionChange = 10;
                fb.nMaxPosition = M as $t;
                set_fix(&mut fb, l);
                fb
            }

            fn set_fix(fb: &mut Fb, l: [u64; 7]) {
                fb.nTDC1LowerLimitFix = l[0] as $t;
                fb.nTDC1UpperLimitFix = l[1] as $t;
                fb.nTDC2LowerLimitFix = l[2] as $t;
                fb.nTDC2UpperLimitFix = l[3] as $t;
                fb.nBDCLowerLimitFix = l[4] as $t;
                fb.nBDCUpperLimitFix = l[5] as $t;
                fb.nOverrunMaxFix = l[6] as $t;
            }

            fn set_inputs(fb: &mut Fb, l: [u64; 7]) {
                fb.nTDC1LowerLimit = l[0] as $t;
                fb.nTDC1UpperLimit = l[1] as $t;
                fb.nTDC2LowerLimit = l[2] as $t;
                fb.nTDC2UpperLimit = l[3] as $t;
                fb.nBDCLowerLimit = l[4] as $t;
                fb.nBDCUpperLimit = l[5] as $t;
                fb.nOverrunMax = l[6] as $t;
            }

            /// A running instance driven in 10 ms calls.
            struct Sim {
                fb: Fb,
                now: u32,
                pos: u64,
                rc: i32,
                seen: Vec<u8>,
            }

            impl Sim {
                fn new(fb: Fb, pos: u64) -> Sim {
                    let mut s = Sim {
                        fb,
                        now: common::T0,
                        pos,
                        rc: 0,
                        seen: Vec::new(),
                    };
                    assert_eq!(s.fb.init(), SL_OK);
                    note(s.fb.nState, 0);
                    s.fb.bRun = 1;
                    s.at(pos);
                    s
                }
                fn exc(active: u16, pos: u64) -> Sim {
                    Sim::new(make(false, active, EXC), pos)
                }
                fn pen(active: u16, pos: u64) -> Sim {
                    Sim::new(make(true, active, PEN), pos)
                }
                fn at(&mut self, pos: u64) -> i32 {
                    self.pos = pos;
                    self.fb.nPosition = pos as $t;
                    self.now = self.now.wrapping_add(10);
                    self.rc = self.fb.cycle(self.now);
                    self.seen.push(self.fb.nState);
                    note(self.fb.nState, self.fb.nDiagTextId);
                    self.rc
                }
                fn state(&self) -> u8 {
                    self.fb.nState
                }
                /// `ms` of standstill.
                fn hold(&mut self, ms: u32) {
                    for _ in 0..ms / 10 {
                        self.at(self.pos);
                    }
                }
                /// Reset TRUE for one call, then FALSE for one.
                fn reset_pulse(&mut self) {
                    self.fb.bReset = 1;
                    self.at(self.pos);
                    self.fb.bReset = 0;
                    self.at(self.pos);
                }
                /// Clockwise by `dist` in steps of `step` (wrapping at 360°); stops early
                /// when the block leaves its running states.
                fn cw(&mut self, dist: u64, step: u64) {
                    let mut done = 0;
                    while done < dist && self.state() != ERROR {
                        let s = step.min(dist - done);
                        done += s;
                        self.at((self.pos + s) % C);
                    }
                }
                /// Counter-clockwise (pendulum: along the line).
                fn ccw(&mut self, dist: u64, step: u64) {
                    let mut done = 0;
                    while done < dist && self.state() != ERROR {
                        let s = step.min(dist - done);
                        done += s;
                        self.at((self.pos + C - s) % C);
                    }
                }
                /// Clockwise to `target`.
                fn cw_to(&mut self, target: u64, step: u64) {
                    let d = (target + C - self.pos) % C;
                    self.cw(d, step);
                }
                fn ccw_to(&mut self, target: u64, step: u64) {
                    let d = (self.pos + C - target) % C;
                    self.ccw(d, step);
                }
                fn message(&self) -> (u16, u16, u32, u32) {
                    (
                        self.fb.nDiag,
                        self.fb.nDiagTextId,
                        self.fb.dwDiagPar2,
                        self.fb.dwDiagPar3,
                    )
                }
                /// (Error, CamMonOK, UpwardsMove, TDC, BDC).
                fn outs(&self) -> (u8, u8, u8, u8, u8) {
                    let f = &self.fb;
                    (f.bError, f.bCamMonOK, f.bUpwardsMove, f.bTDC, f.bBDC)
                }
                fn expect_error(&self, text: u16) {
                    assert_eq!(
                        self.state(),
                        ERROR,
                        "expected {text:#x}, seen {:?}",
                        self.seen
                    );
                    assert_eq!(self.fb.nDiagTextId, text);
                    assert_eq!(self.fb.nDiag, text - 0x4000);
                    assert_eq!(self.outs(), (1, 0, 0, 0, 0));
                    assert_eq!((self.fb.nOverrunTDC, self.fb.nOverrunStop), (0, 0));
                }
                /// From WAIT-FOR-RESET: Reset pulse → RUN.
                fn release(&mut self) {
                    assert_eq!(self.state(), WAIT);
                    self.fb.bReset = 1;
                    self.at(self.pos);
                    assert_eq!(self.state(), START);
                    self.fb.bReset = 0;
                    self.at(self.pos);
                    assert_eq!(self.state(), RUN);
                }
            }

            /// An excentric press released in RUN at 50 (just past TDC).
            fn exc_run(active: u16) -> Sim {
                let mut s = Sim::exc(active, 50);
                s.release();
                s
            }

            /// One full excentric stroke from RUN/MOVE-DOWN at TDC back to MOVE-STOP at 300.
            fn stroke(s: &mut Sim) {
                s.cw_to(4000, 40);
                s.cw_to(8000, 40);
                s.cw_to(300, 40);
                s.hold(60);
            }

            /// §4.26.9: STOP → WAIT-FOR-RESET (Reset FALSE) → START → RUN, outputs by
            /// position; START directly when the STOP state is left with Reset TRUE.
            #[test]
            fn start_sequence_and_outputs() {
                let mut fb = make(false, BASE, EXC);
                assert_eq!(fb.init(), SL_OK);
                assert_eq!(fb.nState, STOP);
                let mut s = Sim::exc(BASE, 50);
                assert_eq!(s.state(), WAIT);
                assert_eq!(s.outs(), (0, 0, 0, 0, 0));
                s.release();
                assert_eq!(s.outs(), (0, 1, 0, 1, 0));
                assert_eq!(s.fb.nOverrunTDC, (50 + C - 8092) as $t);
                let mut fb = make(false, BASE, EXC);
                fb.bReset = 1;
                let s2 = Sim::new(fb, 50);
                assert_eq!(s2.state(), START);
                assert_eq!(s2.outs(), (0, 0, 0, 0, 0));
                // bRun FALSE → STOP, all outputs 0.
                s.fb.bRun = 0;
                s.at(50);
                assert_eq!(s.state(), STOP);
                assert_eq!(s.outs(), (0, 0, 0, 0, 0));
            }

            /// §4.26.3, §4.26.9: a stroke through MOVE-DOWN, MOVE-UP, MOVE-TDC, MOVE-STOP,
            /// the next released by MOVE-START; UpwardsMove from BDC_UpperLimit to 0°, TDC
            /// and BDC by position, OverrunTDC from TDC1_LowerLimit.
            #[test]
            fn excentric_strokes_pass_every_move_state() {
                let mut s = exc_run(BASE);
                s.cw(40, 40);
                assert_eq!(s.state(), MDOWN);
                assert_eq!(s.outs(), (0, 1, 0, 1, 0));
                s.cw_to(3900, 40);
                assert_eq!(s.outs(), (0, 1, 0, 0, 1));
                s.cw_to(4300, 40);
                assert_eq!(s.state(), MUP);
                assert_eq!(s.outs(), (0, 1, 1, 0, 0));
                s.cw_to(8080, 40);
                assert_eq!(s.state(), MUP);
                s.cw_to(8100, 20);
                assert_eq!(s.state(), MTDC);
                assert_eq!(s.outs(), (0, 1, 1, 1, 0));
                assert_eq!(s.fb.nOverrunTDC, 8 as $t);
                s.cw_to(20, 40);
                assert_eq!(s.state(), MTDC);
                assert_eq!(s.outs(), (0, 1, 0, 1, 0), "UpwardsMove resets at 0°");
                s.cw_to(300, 40);
                assert_eq!(s.fb.nOverrunTDC, (300 + C - 8092) as $t);
                assert_eq!(s.outs(), (0, 1, 0, 0, 0));
                s.hold(40);
                assert_eq!(s.state(), MTDC);
                s.hold(20);
                assert_eq!(s.state(), MSTOP);
                assert_eq!(s.fb.bCamMonOK, 1);
                s.fb.bReset = 1;
                s.at(300);
                assert_eq!(s.state(), MSTART);
                s.fb.bReset = 0;
                s.at(300);
                assert_eq!(s.state(), MDOWN);
                stroke(&mut s);
                assert_eq!(s.state(), MSTOP);
                assert_eq!(s.rc, SL_OK);
            }

            /// §4.26.3: "CamMonOK is immediately set to FALSE if the press comes to a
            /// standstill without having reached or exceeded TDC" → SAFE; a Reset pulse
            /// releases it again (START → RUN).
            #[test]
            fn standstill_mid_stroke_is_safe() {
                let mut s = exc_run(BASE);
                s.cw_to(2000, 40);
                assert_eq!(s.state(), MDOWN);
                s.hold(60);
                assert_eq!(s.state(), SAFE);
                assert_eq!(s.outs(), (0, 0, 0, 0, 0));
                s.fb.bReset = 1;
                s.at(2000);
                assert_eq!(s.state(), START);
                s.fb.bReset = 0;
                s.at(2000);
                assert_eq!(s.state(), RUN);
                // In the upstroke likewise.
                s.cw_to(5000, 40);
                assert_eq!(s.state(), MUP);
                s.hold(60);
                assert_eq!(s.state(), SAFE);
            }

            /// RUN in the left half: the first movement is MOVE-UP.
            #[test]
            fn release_in_the_left_half_moves_up() {
                let mut s = Sim::exc(BASE, 5000);
                s.release();
                s.cw(40, 40);
                assert_eq!(s.state(), MUP);
            }

            /// 0x400D: the press passes OverrunMax in MOVE-TDC; ERROR, Error 1, acknowledged
            /// by ErrAck (RESET → WAIT-FOR-RESET / START).
            #[test]
            fn overrun_past_overrunmax_is_0x400d_then_reset() {
                let mut s = exc_run(BASE);
                s.cw_to(8100, 40);
                assert_eq!(s.state(), MTDC);
                s.cw_to(780, 40);
                assert_eq!(s.state(), MTDC);
                s.cw(40, 40);
                s.expect_error(0x400D);
                assert_eq!(s.message(), (0x0D, 0x400D, 820, 0));
                s.fb.bErrAck = 1;
                s.at(820);
                assert_eq!(s.state(), RESET);
                assert_eq!(s.message(), (0, 0, 0, 0));
                s.fb.bErrAck = 0;
                s.at(820);
                assert_eq!(s.state(), WAIT);
                s.fb.bReset = 1;
                s.at(820);
                assert_eq!(s.state(), START);
            }

            /// 0x400A / 0x400B: movement in MOVE-STOP, in MOVE-START.
            #[test]
            fn moving_in_move_stop_and_move_start() {
                let mut s = exc_run(BASE);
                stroke(&mut s);
                assert_eq!(s.state(), MSTOP);
                s.cw(10, 10);
                s.expect_error(0x400A);
                let mut s = exc_run(BASE);
                stroke(&mut s);
                s.fb.bReset = 1;
                s.at(300);
                assert_eq!(s.state(), MSTART);
                s.cw(10, 10);
                s.expect_error(0x400B);
                // In START (excentric) the same message.
                let mut s = Sim::exc(BASE, 50);
                s.fb.bReset = 1;
                s.at(50);
                assert_eq!(s.state(), START);
                s.cw(10, 10);
                s.expect_error(0x400B);
            }

            /// 0x4024: movement in WAIT-FOR-RESET (excentric: no parameters; pendulum:
            /// Position).
            #[test]
            fn moving_in_wait_for_reset() {
                let mut s = Sim::exc(BASE, 50);
                s.cw(10, 10);
                s.expect_error(0x4024);
                assert_eq!(s.message(), (0x24, 0x4024, 0, 0));
                let mut s = Sim::pen(BASE, 1300);
                s.cw(10, 10);
                s.expect_error(0x4024);
                assert_eq!(s.message(), (0x24, 0x4024, 1310, 0));
            }

            /// 0x400C: a position between OverrunMax and BDC in MOVE-UP (reached with
            /// Automatic TRUE, which switches off the direction check but not this one).
            #[test]
            fn move_up_outside_its_areas_is_0x400c() {
                let mut s = exc_run(BASE);
                s.cw_to(4400, 40);
                assert_eq!(s.state(), MUP);
                s.fb.bAutomatic = 1;
                s.ccw_to(4000, 40);
                s.expect_error(0x400C);
                assert_eq!(s.fb.dwDiagPar2, 4280);
            }

            /// 0x400E: a backward step beyond the jitter without BackwardsMove; a step back
            /// within the jitter is none.
            #[test]
            fn backwards_beyond_the_jitter_is_0x400e() {
                let mut s = exc_run(BASE);
                s.cw_to(1000, 40);
                s.at(1000 - J);
                assert_eq!(s.state(), MDOWN);
                s.at(1000 - J - 1);
                s.expect_error(0x400E);
                assert_eq!(s.message(), (0x0E, 0x400E, 0, 0));
            }

            /// BackwardsMove: counter-clockwise permitted between TDC1_UpperLimit and
            /// BDC_LowerLimit (0 errors); 0x4013 clockwise with BackwardsMove; 0x4012
            /// BackwardsMove in the left half.
            #[test]
            fn backwards_move() {
                let mut s = exc_run(BASE | A_BACK);
                s.cw_to(2000, 40);
                s.hold(60);
                assert_eq!(s.state(), SAFE);
                s.reset_pulse();
                assert_eq!(s.state(), RUN);
                s.fb.bBackwardsMove = 1;
                s.ccw_to(150, 40);
                assert_eq!(s.state(), RUN);
                assert_eq!(s.rc, SL_OK);
                s.cw(10, 10);
                s.expect_error(0x4013);
                let mut s = Sim::exc(BASE | A_BACK, 5000);
                s.fb.bBackwardsMove = 1;
                s.at(5000);
                s.expect_error(0x4012);
                assert_eq!(s.fb.dwDiagPar2, 5000);
            }

            /// Hardware cams (§4.26.5) following the areas: no error over two strokes.
            fn cam_stroke(s: &mut Sim, cams: bool) {
                // OverrunCam: on from 6000 (left half) to 1500; UpwardCam: 4000 to 0°.
                let mut pos = s.pos;
                let mut steps = 0;
                loop {
                    let next = (pos + 40) % C;
                    pos = next;
                    if cams {
                        s.fb.bOverrunCam = u8::from(!(1500..6000).contains(&pos));
                        s.fb.bUpwardCam = u8::from((4000..C).contains(&pos));
                    }
                    s.at(pos);
                    steps += 1;
                    if s.state() == MTDC && (200..300).contains(&pos)
                        || s.state() == ERROR
                        || steps > 1000
                    {
                        break;
                    }
                }
                s.hold(60);
            }

            fn cam_sim() -> Sim {
                let mut fb = make(false, BASE | A_OCAM | A_UCAM, EXC);
                fb.bOverrunCam = 1;
                let mut s = Sim::new(fb, 50);
                s.release();
                s
            }

            #[test]
            fn cams_following_the_areas_make_no_error() {
                let mut s = cam_sim();
                for _ in 0..2 {
                    cam_stroke(&mut s, true);
                    assert_eq!(s.state(), MSTOP, "{:?}", s.message());
                    s.reset_pulse();
                    assert_eq!(s.state(), MDOWN);
                }
            }

            /// 0x4003: OverrunCAM FALSE in the TDC area.
            #[test]
            fn overrun_cam_false_in_tdc() {
                let s = Sim::exc(BASE | A_OCAM, 50);
                s.expect_error(0x4003);
                assert_eq!(s.fb.dwDiagPar2, 50);
            }

            /// 0x4004: OverrunCAM rises outside BDC_UpperLimit … TDC1_LowerLimit.
            #[test]
            fn overrun_cam_rising_outside_the_left_area() {
                let mut s = cam_sim();
                s.cw_to(2000, 40);
                s.fb.bOverrunCam = 0;
                s.at(2040);
                s.fb.bOverrunCam = 1;
                s.at(2080);
                s.expect_error(0x4004);
            }

            /// 0x4005: OverrunCAM still TRUE beyond BDC_LowerLimit.
            #[test]
            fn overrun_cam_true_in_bdc() {
                let mut s = cam_sim();
                s.cw_to(3880, 40);
                assert_eq!(s.state(), MDOWN);
                s.cw(40, 40);
                s.expect_error(0x4005);
            }

            /// 0x4006: OverrunCAM falls before OverrunMax.
            #[test]
            fn overrun_cam_falling_before_overrunmax() {
                let mut s = cam_sim();
                s.cw_to(500, 40);
                s.fb.bOverrunCam = 0;
                s.at(540);
                s.expect_error(0x4006);
                assert_eq!(s.fb.dwDiagPar2, 540);
            }

            /// 0x400F: UpwardsCAM TRUE between OverrunMax and BDC_LowerLimit.
            #[test]
            fn upward_cam_true_before_bdc() {
                let mut fb = make(false, BASE | A_UCAM, EXC);
                fb.bUpwardCam = 1;
                let mut s = Sim::new(fb, 50);
                s.release();
                s.cw_to(800, 40);
                assert_eq!(s.state(), MDOWN);
                s.cw(40, 40);
                s.expect_error(0x400F);
            }

            /// 0x4007: UpwardsCAM FALSE in the left half.
            #[test]
            fn upward_cam_false_in_the_left_half() {
                let s = Sim::exc(BASE | A_UCAM, 5000);
                s.expect_error(0x4007);
            }

            /// 0x4008: UpwardsCAM rises before BDC_LowerLimit.
            #[test]
            fn upward_cam_rising_before_bdc() {
                let mut s = exc_run(BASE | A_UCAM);
                s.cw_to(300, 40);
                s.fb.bUpwardCam = 1;
                s.at(340);
                s.expect_error(0x4008);
            }

            /// 0x4009: UpwardsCAM falls outside TDC1_LowerLimit … OverrunMax.
            #[test]
            fn upward_cam_falling_in_bdc() {
                let mut s = exc_run(BASE | A_UCAM);
                s.cw_to(3900, 40);
                s.fb.bUpwardCam = 1;
                s.at(3940);
                assert_eq!(s.state(), MDOWN);
                s.fb.bUpwardCam = 0;
                s.at(3980);
                s.expect_error(0x4009);
            }

            /// Automatic TRUE: no direction or cam checks ("Automatic = FALSE AND …").
            #[test]
            fn automatic_switches_off_movement_and_cam_checks() {
                let mut fb = make(false, BASE | A_OCAM, EXC);
                fb.bAutomatic = 1;
                let mut s = Sim::new(fb, 50);
                assert_eq!(s.state(), WAIT, "OverrunCam FALSE in TDC is no error");
                s.release();
                s.cw_to(1000, 40);
                s.at(900);
                assert_eq!(s.state(), MDOWN, "backwards is no error");
                s.fb.bAutomatic = 0;
                s.at(850);
                s.expect_error(0x400E);
            }

            /// 0x4002: Position > MaxPosition + AllowedPositionJitter (Par2 Position, Par3
            /// the limit); at the limit no error; the error remains while the position is
            /// out of range.
            #[test]
            fn position_beyond_maxposition_plus_jitter() {
                let mut s = Sim::exc(BASE, M + J);
                assert_eq!(s.state(), WAIT);
                s.at(M + J + 1);
                s.expect_error(0x4002);
                assert_eq!(
                    s.message(),
                    (0x02, 0x4002, (M + J + 1) as u32, (M + J) as u32)
                );
                s.fb.bErrAck = 1;
                s.at(M + J + 1);
                assert_eq!(s.state(), ERROR);
                s.fb.bErrAck = 0;
                s.at(M + J);
                s.fb.bErrAck = 1;
                s.at(M + J);
                assert_eq!(s.state(), RESET);
            }

            /// Press_Started: 0x401F no movement within PressStartDelayTime.
            #[test]
            fn press_started_without_movement() {
                let mut s = exc_run(BASE | A_PS);
                s.fb.bPressStarted = 1;
                s.hold(200);
                assert_eq!(s.state(), RUN);
                s.hold(10);
                s.expect_error(0x401F);
            }

            /// 0x4020: stopped while Press_Started is TRUE after moving; OverrunStop after
            /// its falling edge.
            #[test]
            fn press_started_stop_and_overrun_stop() {
                let mut s = exc_run(BASE | A_PS);
                s.fb.bPressStarted = 1;
                s.cw_to(8000, 40);
                s.fb.bPressStarted = 0;
                s.at(8000);
                s.cw_to(8100, 40);
                assert_eq!(s.fb.nOverrunStop, 100 as $t);
                s.cw_to(200, 40);
                s.hold(60);
                assert_eq!(s.state(), MSTOP);
                assert_eq!(s.fb.nOverrunStop, (200 + C - 8000) as $t);
                s.reset_pulse();
                s.fb.bPressStarted = 1;
                s.cw_to(400, 40);
                assert_eq!(s.fb.nOverrunStop, 0);
                s.hold(60);
                s.expect_error(0x4020);
            }

            /// 0x4021: less than MinPositionChange within MoveDetectionTime (Par2 Position,
            /// Par3 comparison position); exactly MinPositionChange is enough.
            #[test]
            fn press_started_too_slow() {
                let mut fb = make(false, BASE | A_PS, EXC);
                fb.nMinPositionChange = 50;
                let mut s = Sim::new(fb, 50);
                s.release();
                s.fb.bPressStarted = 1;
                s.cw(5, 5); // first movement: comparison position 55
                s.cw(50, 5); // exactly 50 in 100 ms
                assert_eq!(s.state(), MDOWN);
                s.cw(45, 5);
                assert_eq!(s.state(), MDOWN);
                s.at(150);
                s.expect_error(0x4021);
                assert_eq!(s.message(), (0x21, 0x4021, 150, 105));
            }

            /// Pendulum (§4.26.4): RUN → MOVE-DOWN-CLOCKWISE → MOVE-UP-CLOCKWISE →
            /// MOVE-UP-TDC1 → MOVE-STOP-TDC1 → MOVE-START-TDC1 → RUN → MOVE-DOWN-CONTRA-
            /// CLOCKWISE → MOVE-UP-CONTRA-CLOCKWISE → MOVE-UP-TDC2 → MOVE-STOP-TDC2 →
            /// MOVE-START-TDC2 → RUN; UpwardsMove in the MOVE-UP states.
            #[test]
            fn pendulum_swings_through_every_state() {
                let mut s = Sim::pen(BASE, 1300);
                s.release();
                assert_eq!(s.outs(), (0, 1, 0, 1, 0));
                s.cw(40, 40);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_DOWN_CW);
                s.ccw(40, 40);
                assert_eq!(
                    s.state(),
                    SL_STATE_CAMMONITOR_MOVE_DOWN_CCW,
                    "pulsating before BDC"
                );
                s.cw_to(4000, 40);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_DOWN_CW);
                assert_eq!(s.outs(), (0, 1, 0, 0, 1));
                s.cw_to(4200, 40);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_UP_CW);
                assert_eq!(s.outs(), (0, 1, 1, 0, 0));
                s.cw_to(4520, 40);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_UP_TDC1);
                assert_eq!(s.outs(), (0, 1, 1, 1, 0));
                s.cw_to(6520, 40);
                s.hold(60);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_STOP_TDC1);
                assert_eq!(s.outs(), (0, 1, 0, 1, 0));
                assert_eq!(s.fb.nOverrunTDC, 0, "not used in pendulum mode");
                s.fb.bReset = 1;
                s.at(s.pos);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_START_TDC1);
                s.fb.bReset = 0;
                s.at(s.pos);
                assert_eq!(s.state(), RUN);
                s.ccw(40, 40);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_DOWN_CCW);
                s.ccw_to(3960, 40);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_UP_CCW);
                s.ccw_to(3680, 40);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_UP_TDC2);
                s.ccw_to(1300, 40);
                s.hold(60);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_STOP_TDC2);
                s.fb.bReset = 1;
                s.at(s.pos);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_START_TDC2);
                s.fb.bReset = 0;
                s.at(s.pos);
                assert_eq!(s.state(), RUN);
                assert_eq!(s.rc, SL_OK);
            }

            /// Pendulum: exceeding an upper reversal limit is SAFE (CamMonOK FALSE); a
            /// standstill after BDC before TDC likewise.
            #[test]
            fn pendulum_exceeding_tdc1_is_safe() {
                let mut s = Sim::pen(BASE, 1300);
                s.release();
                s.cw_to(7780, 40);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_UP_TDC1);
                s.cw(40, 40);
                assert_eq!(s.state(), SAFE);
                assert_eq!(s.outs(), (0, 0, 0, 0, 0));
                let mut s = Sim::pen(BASE, 1300);
                s.release();
                s.cw_to(4300, 40);
                s.hold(60);
                assert_eq!(s.state(), SAFE);
            }

            /// 0x4022 / 0x4023: reversal after BDC.
            #[test]
            fn pendulum_reversal_after_bdc() {
                let mut s = Sim::pen(BASE, 1300);
                s.release();
                s.cw_to(4300, 40);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_UP_CW);
                s.ccw(40, 40);
                s.expect_error(0x4022);
                assert_eq!(s.message(), (0x22, 0x4022, 4260, 4300));
                let mut s = Sim::pen(BASE, 6500);
                s.release();
                s.ccw_to(3900, 40);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_UP_CCW);
                s.cw(40, 40);
                s.expect_error(0x4023);
            }

            /// 0x4011 / 0x4014: movement in MOVE-STOP-TDC and MOVE-START-TDC; 0x4014 in
            /// START too.
            #[test]
            fn pendulum_moving_while_waiting_for_reset() {
                let mut s = Sim::pen(BASE, 1300);
                s.release();
                s.cw_to(6500, 40);
                s.hold(60);
                assert_eq!(s.state(), SL_STATE_CAMMONITOR_MOVE_STOP_TDC1);
                s.ccw(10, 10);
                s.expect_error(0x4011);
                let mut s = Sim::pen(BASE, 1300);
                s.release();
                s.cw_to(6500, 40);
                s.hold(60);
                s.fb.bReset = 1;
                s.at(6500);
                s.ccw(10, 10);
                s.expect_error(0x4014);
                let mut fb = make(true, BASE, PEN);
                fb.bReset = 1;
                let mut s = Sim::new(fb, 1300);
                assert_eq!(s.state(), START);
                s.cw(10, 10);
                s.expect_error(0x4014);
            }

            /// 0x4010: the position wraps across 0°/360° in pendulum mode.
            #[test]
            fn pendulum_circle_overflow() {
                let mut fb = make(true, BASE, PEN);
                fb.bAutomatic = 1;
                let mut s = Sim::new(fb, 500);
                s.at(8100);
                s.expect_error(0x4010);
                assert_eq!(s.message(), (0x10, 0x4010, 8100, 500));
            }

            /// The excentric parameter checks at their boundaries: value at the limit
            /// accepted, one beyond refused with SL_E_CONFIG, the Text ID and its
            /// parameters shown in STOP.
            #[test]
            fn excentric_ordering_boundaries() {
                // (limit index, accepted, refused, Text ID, Par2, Par3 when refused)
                let cases: [(usize, u64, u64, u16, u64, u64); 7] = [
                    (1, J + 1, J, 0x4025, J, J),
                    (
                        6,
                        100 + 2 * J + 1,
                        100 + 2 * J,
                        0x401A,
                        100 + 2 * J,
                        100 + 2 * J,
                    ),
                    (
                        4,
                        800 + 2 * J + 1,
                        800 + 2 * J,
                        0x4019,
                        800 + 2 * J,
                        800 + 2 * J,
                    ),
                    (4, M / 2 - J - 1, M / 2 - J, 0x4018, M / 2, M / 2),
                    (5, M / 2 + J + 1, M / 2 + J, 0x4017, M / 2 + J, M / 2 + J),
                    (
                        0,
                        4296 + 2 * J + 1,
                        4296 + 2 * J,
                        0x4016,
                        4296 + 2 * J,
                        4296 + 2 * J,
                    ),
                    (0, M - J, M - J + 1, 0x4015, M + 1, M),
                ];
                for (i, ok, bad, text, p2, p3) in cases {
                    let mut l = EXC;
                    l[i] = ok;
                    let mut fb = make(false, BASE, l);
                    assert_eq!(fb.init(), SL_OK, "{text:#x} at the limit");
                    assert_eq!(fb.nDiagTextId, 0);
                    l[i] = bad;
                    let mut fb = make(false, BASE, l);
                    assert_eq!(fb.init(), SL_E_CONFIG, "{text:#x}");
                    note(fb.nState, fb.nDiagTextId);
                    assert_eq!(
                        (fb.nDiagTextId, fb.dwDiagPar2, fb.dwDiagPar3),
                        (text, p2 as u32, p3 as u32)
                    );
                    fb.bRun = 1;
                    assert_eq!(fb.cycle(0), SL_E_CONFIG);
                    assert_eq!(fb.nState, STOP);
                    assert_eq!(fb.nDiagTextId, text);
                }
            }

            #[test]
            fn pendulum_ordering_boundaries() {
                let cases: [(usize, u64, u64, u16, u64, u64); 8] = [
                    (3, J + 1, J, 0x4001, J, J),
                    (
                        2,
                        400 + 2 * J + 1,
                        400 + 2 * J,
                        0x401E,
                        400 + 2 * J,
                        400 + 2 * J,
                    ),
                    (
                        4,
                        3696 + 2 * J + 1,
                        3696 + 2 * J,
                        0x401D,
                        3696 + 2 * J,
                        3696 + 2 * J,
                    ),
                    (4, M / 2 - J - 1, M / 2 - J, 0x4018, M / 2, M / 2),
                    (5, M / 2 + J + 1, M / 2 + J, 0x4017, M / 2 + J, M / 2 + J),
                    (
                        0,
                        4196 + 2 * J + 1,
                        4196 + 2 * J,
                        0x4016,
                        4196 + 2 * J,
                        4196 + 2 * J,
                    ),
                    (
                        1,
                        4496 + 2 * J + 1,
                        4496 + 2 * J,
                        0x401C,
                        4496 + 2 * J,
                        4496 + 2 * J,
                    ),
                    (1, M - J - 1, M - J, 0x401B, M, M),
                ];
                for (i, ok, bad, text, p2, p3) in cases {
                    let mut l = PEN;
                    l[i] = ok;
                    let mut fb = make(true, BASE, l);
                    assert_eq!(fb.init(), SL_OK, "{text:#x} at the limit");
                    l[i] = bad;
                    let mut fb = make(true, BASE, l);
                    assert_eq!(fb.init(), SL_E_CONFIG, "{text:#x}");
                    note(fb.nState, fb.nDiagTextId);
                    assert_eq!(
                        (fb.nDiagTextId, fb.dwDiagPar2, fb.dwDiagPar3),
                        (text, p2 as u32, p3 as u32)
                    );
                }
            }

            /// The configuration rules of ABI-2 §11.13: required and unknown bits, the
            /// mode's unused inputs, the times.
            #[test]
            fn configuration_rules() {
                let ok = |f: &mut dyn FnMut(&mut Fb), pendulum: bool| {
                    let mut fb = make(pendulum, BASE, if pendulum { PEN } else { EXC });
                    f(&mut fb);
                    fb.init()
                };
                assert_eq!(ok(&mut |_| {}, false), SL_OK);
                assert_eq!(ok(&mut |_| {}, true), SL_OK);
                assert_eq!(ok(&mut |f| f.wInputActive &= !A_RESET, false), SL_E_CONFIG);
                assert_eq!(ok(&mut |f| f.wInputActive &= !A_POS, false), SL_E_CONFIG);
                assert_eq!(ok(&mut |f| f.wInputActive |= 0x80, false), SL_E_CONFIG);
                assert_eq!(ok(&mut |f| f.dwOptions |= 1, false), SL_E_CONFIG);
                assert_eq!(ok(&mut |f| f.wInputActive |= 1 << 11, false), SL_E_CONFIG);
                assert_eq!(ok(&mut |f| f.nTDC2UpperLimitFix = 1, false), SL_E_CONFIG);
                for bit in [A_BACK, A_OCAM, A_UCAM, 1 << 15] {
                    assert_eq!(
                        ok(&mut |f| f.wInputActive |= bit, true),
                        SL_E_CONFIG,
                        "{bit:#x}"
                    );
                    assert_eq!(ok(&mut |f| f.wInputActive |= bit, false), SL_OK, "{bit:#x}");
                }
                assert_eq!(ok(&mut |f| f.nOverrunMaxFix = 1, true), SL_E_CONFIG);
                assert_eq!(ok(&mut |f| f.tStopDetectionTime = 0, false), SL_E_CONFIG);
                assert_eq!(ok(&mut |f| f.tStopDetectionTime = 1, false), SL_OK);
                for t in 0..3 {
                    let set = |f: &mut Fb, v: u32| match t {
                        0 => f.tStopDetectionTime = v,
                        1 => f.tPressStartDelayTime = v,
                        _ => f.tMoveDetectionTime = v,
                    };
                    assert_eq!(ok(&mut |f| set(f, 65_535), false), SL_OK);
                    assert_eq!(ok(&mut |f| set(f, 65_536), false), SL_E_CONFIG);
                }
                let ps = |f: &mut Fb| f.wInputActive |= A_PS;
                assert_eq!(
                    ok(
                        &mut |f| {
                            ps(f);
                            f.tPressStartDelayTime = 0
                        },
                        false
                    ),
                    SL_E_CONFIG
                );
                assert_eq!(
                    ok(
                        &mut |f| {
                            ps(f);
                            f.tMoveDetectionTime = 0
                        },
                        false
                    ),
                    SL_E_CONFIG
                );
                assert_eq!(
                    ok(
                        &mut |f| {
                            ps(f);
                            f.nMinPositionChange = 0
                        },
                        false
                    ),
                    SL_E_CONFIG
                );
                assert_eq!(ok(&mut |f| f.nMinPositionChange = 0, false), SL_OK);
            }

            /// Limits from inputs are verified every cycle (ERROR with the Text ID, which
            /// remains while the check fails); Automatic TRUE skips the verification.
            #[test]
            fn limits_from_inputs_are_verified_unless_automatic() {
                let active = BASE | SL_CAMMONITOR_ACTIVE_BDCUPPERLIMIT;
                let mut fb = make(false, active, EXC);
                set_inputs(&mut fb, EXC);
                fb.nBDCUpperLimit = (M / 2 + J) as $t;
                let mut s = Sim::new(fb, 50);
                s.expect_error(0x4017);
                assert_eq!(
                    s.message(),
                    (0x17, 0x4017, (M / 2 + J) as u32, (M / 2 + J) as u32)
                );
                s.fb.bErrAck = 1;
                s.at(50);
                assert_eq!(s.state(), ERROR, "remains while the check fails");
                s.fb.bErrAck = 0;
                s.fb.nBDCUpperLimit = 4296;
                s.at(50);
                s.fb.bErrAck = 1;
                s.at(50);
                assert_eq!(s.state(), RESET);
                let mut fb = make(false, active, EXC);
                set_inputs(&mut fb, EXC);
                fb.nBDCUpperLimit = (M / 2 + J) as $t;
                fb.bAutomatic = 1;
                let s = Sim::new(fb, 50);
                assert_eq!(s.state(), WAIT);
            }

            /// SettingMode: fixed limits changed while it is TRUE are re-latched (no
            /// SL_E_PARAM_CHANGED) and verified; without it a change is SL_E_PARAM_CHANGED.
            #[test]
            fn setting_mode_relatches_the_fixed_values() {
                let mut s = exc_run(BASE);
                s.fb.nBDCUpperLimitFix = 4500;
                assert_eq!(s.at(50), SL_E_PARAM_CHANGED);
                let mut s = exc_run(BASE);
                s.fb.bSettingMode = 1;
                s.fb.nBDCUpperLimitFix = 4500;
                assert_eq!(s.at(50), SL_OK);
                s.fb.bSettingMode = 0;
                assert_eq!(s.at(50), SL_OK);
                s.cw_to(4400, 40);
                assert_eq!(s.state(), MDOWN, "BDC_UpperLimit is now 4500");
                assert_eq!(s.fb.bBDC, 1);
                s.cw_to(4520, 40);
                assert_eq!(s.state(), MUP);
                // Not every parameter: the jitter is no fixed limit.
                s.fb.bSettingMode = 1;
                s.fb.nAllowedPositionJitter = 5;
                assert_eq!(s.at(4520), SL_E_PARAM_CHANGED);
                // A re-latched value that breaks an ordering check is an ERROR.
                let mut s = exc_run(BASE);
                s.fb.bSettingMode = 1;
                s.fb.nBDCUpperLimitFix = 4100;
                assert_eq!(s.at(50), SL_OK);
                s.expect_error(0x4017);
            }

            /// An invalid Press_Started byte reads TRUE (motion expected); invalid others
            /// read FALSE; the call reports SL_E_INVALID_BOOL.
            #[test]
            fn invalid_bool_bytes() {
                let mut s = exc_run(BASE | A_PS);
                s.fb.bPressStarted = 7;
                assert_eq!(s.at(50), SL_E_INVALID_BOOL);
                s.hold(200);
                s.expect_error(0x401F);
            }

            /// Every state of §4.26.9 and every Text ID of §4.26.7/§4.26.8 is reached by
            /// the scenarios of this file (run again here on one thread, which collects the
            /// states and Text IDs every call showed).
            #[test]
            fn every_state_and_every_text_is_reached() {
                start_sequence_and_outputs();
                excentric_strokes_pass_every_move_state();
                standstill_mid_stroke_is_safe();
                overrun_past_overrunmax_is_0x400d_then_reset();
                moving_in_move_stop_and_move_start();
                moving_in_wait_for_reset();
                move_up_outside_its_areas_is_0x400c();
                backwards_beyond_the_jitter_is_0x400e();
                backwards_move();
                cams_following_the_areas_make_no_error();
                overrun_cam_false_in_tdc();
                overrun_cam_rising_outside_the_left_area();
                overrun_cam_true_in_bdc();
                overrun_cam_falling_before_overrunmax();
                upward_cam_true_before_bdc();
                upward_cam_false_in_the_left_half();
                upward_cam_rising_before_bdc();
                upward_cam_falling_in_bdc();
                position_beyond_maxposition_plus_jitter();
                press_started_without_movement();
                press_started_stop_and_overrun_stop();
                press_started_too_slow();
                pendulum_swings_through_every_state();
                pendulum_exceeding_tdc1_is_safe();
                pendulum_reversal_after_bdc();
                pendulum_moving_while_waiting_for_reset();
                pendulum_circle_overflow();
                excentric_ordering_boundaries();
                pendulum_ordering_boundaries();
                limits_from_inputs_are_verified_unless_automatic();
                setting_mode_relatches_the_fixed_values();
                let (states, texts) = SEEN.with(|s| s.borrow().clone());
                let table = <Fb as safelogic::base::block::Registered>::INFO.states;
                assert_eq!(table.len(), 22);
                for (v, name) in table {
                    assert!(states.contains(v), "state {v} {name} never reached");
                }
                for text in ALL_TEXTS {
                    assert!(texts.contains(&text), "Text ID {text:#x} never shown");
                    let v = text - 0x4000;
                    assert!(
                        <Fb as safelogic::base::block::Registered>::INFO
                            .diag_values
                            .iter()
                            .any(|(d, _)| *d == v),
                        "{text:#x} has a message text"
                    );
                }
            }

            /// A random excentric press: M, J and limits scaled from M.
            fn random_limits(rng: &mut Rng) -> (u64, u64, [u64; 7]) {
                let max_m: u64 = if core::mem::size_of::<$t>() == 2 {
                    65_000
                } else {
                    2_000_000_000
                };
                let m = 2000 + rng.next() % (max_m - 2000);
                let j = rng.next() % (m / 200 + 1);
                let tdc1_ul = j + 1 + m / 100;
                let ovr = tdc1_ul + 2 * j + 1 + m / 20;
                let bdc_ll = m / 2 - j - 1 - m / 50;
                let bdc_ul = m / 2 + j + 1 + m / 50;
                let tdc1_ll = m - j - m / 100;
                (m, j, [tdc1_ll, tdc1_ul, 0, 0, bdc_ll, bdc_ul, ovr])
            }

            /// Drives `strokes` excentric strokes along a forward crank trajectory (true
            /// position never decreasing, each measurement = true + jitter in 0…J, steps
            /// beyond 2J while moving), cams from the true position, Press_Started around
            /// the motion. With `back_at = Some((stroke, call))` the measurement of that
            /// motion call instead steps back by more than J. Returns the states seen, the
            /// strokes completed (MOVE-STOP reached) and the call's (state, Text ID) at the
            /// backward step.
            fn trajectory(
                rng: &mut Rng,
                strokes: usize,
                back_at: Option<(usize, usize)>,
            ) -> (Vec<u8>, usize, Option<(u8, u16)>) {
                let (m, j, l) = random_limits(rng);
                let c = m + 1;
                let [tdc1_ll, _tdc1_ul, _, _, bdc_ll, bdc_ul, ovr] = l;
                let cams = rng.next() % 2 == 0;
                let ps = rng.next() % 2 == 0;
                let mut active = A_RESET | A_POS;
                if cams {
                    active |= A_OCAM | A_UCAM;
                }
                if ps {
                    active |= A_PS;
                }
                let mut fb = make(false, active, l);
                fb.nMaxPosition = m as $t;
                fb.nAllowedPositionJitter = j as $t;
                fb.nMinPositionChange = 1;
                fb.tStopDetectionTime = 30 + (rng.next() % 5) as u32 * 10;
                let o_on = (bdc_ul + tdc1_ll - j) / 2;
                let o_off = ovr + (bdc_ll - j - ovr) / 4;
                let u_on = bdc_ll + (bdc_ul - j - bdc_ll) / 2;
                let max_step = (m / 25).max(2 * j + 1);
                // Stop targets: TDC1_LowerLimit … 360° … OverrunMax − J (unwrapped from 0).
                let target = |rng: &mut Rng| tdc1_ll + rng.next() % (c - tdc1_ll + ovr - j);
                let mut truth = target(rng) % c; // unwrapped position, monotone
                let mut states = Vec::new();
                let mut done = 0;
                let mut back_result = None;
                assert_eq!(fb.init(), SL_OK);
                fb.bRun = 1;
                let mut now = 1000u32;
                let mut last_meas = 0u64;
                let call = |fb: &mut Fb,
                            now: &mut u32,
                            truth: u64,
                            noise: u64,
                            states: &mut Vec<u8>|
                 -> u64 {
                    let t = truth % c;
                    if cams {
                        fb.bOverrunCam = u8::from(!(o_off..o_on).contains(&t));
                        fb.bUpwardCam = u8::from(t >= u_on);
                    }
                    let meas = (t + noise) % c;
                    fb.nPosition = meas as $t;
                    *now = now.wrapping_add(10);
                    let rc = fb.cycle(*now);
                    states.push(fb.nState);
                    if std::env::var("CAM_DEBUG").is_ok() {
                        eprintln!(
                            "t={t} meas={meas} state={} reset={} text={:#x} j={j}",
                            fb.nState, fb.bReset, fb.nDiagTextId
                        );
                    }
                    assert_eq!(rc, SL_OK, "{states:?} {:#x}", fb.nDiagTextId);
                    meas
                };
                // A late detection of the last small step restarts the window once.
                let stop_calls = 2 * (fb.tStopDetectionTime / 10) + 3;
                // Release: WAIT-FOR-RESET → START → RUN.
                call(&mut fb, &mut now, truth, rng.next() % (j + 1), &mut states);
                for r in [1, 0] {
                    fb.bReset = r;
                    last_meas = call(&mut fb, &mut now, truth, rng.next() % (j + 1), &mut states);
                }
                'strokes: for k in 0..strokes {
                    if k > 0 {
                        for r in [1, 0] {
                            fb.bReset = r;
                            last_meas =
                                call(&mut fb, &mut now, truth, rng.next() % (j + 1), &mut states);
                        }
                    }
                    for _ in 0..rng.next() % 3 {
                        last_meas =
                            call(&mut fb, &mut now, truth, rng.next() % (j + 1), &mut states);
                    }
                    // Next stop: one turn on, at a stop target.
                    let mut d = (target(rng) % c + c - truth % c) % c;
                    if d < c / 2 {
                        d += c;
                    }
                    let goal = truth + d;
                    let mut n = 0;
                    if ps {
                        fb.bPressStarted = 1;
                    }
                    while truth < goal {
                        let step = (2 * j + 1 + rng.next() % (max_step - 2 * j)).min(goal - truth);
                        truth += step;
                        if truth == goal && ps {
                            fb.bPressStarted = 0;
                        }
                        n += 1;
                        if back_at == Some((k, n)) && fb.nState != ERROR {
                            let b = j + 1 + rng.next() % (m / 4 - j);
                            let meas = (last_meas + c - b) % c;
                            now = now.wrapping_add(10);
                            fb.nPosition = meas as $t;
                            let rc = fb.cycle(now);
                            assert!(rc == SL_OK);
                            states.push(fb.nState);
                            back_result = Some((fb.nState, fb.nDiagTextId));
                            break 'strokes;
                        }
                        last_meas =
                            call(&mut fb, &mut now, truth, rng.next() % (j + 1), &mut states);
                    }
                    for _ in 0..stop_calls {
                        last_meas =
                            call(&mut fb, &mut now, truth, rng.next() % (j + 1), &mut states);
                    }
                    if fb.nState == MSTOP {
                        done += 1;
                    }
                    if fb.nState == ERROR {
                        back_result = Some((fb.nState, fb.nDiagTextId));
                        break;
                    }
                }
                (states, done, back_result)
            }

            /// A random pendulum press swinging between its two TDC areas: `swings` swings,
            /// each released by a Reset pulse, moving (true position monotone per swing,
            /// measurement = true + 0…J, steps beyond 2J) from a stop in one TDC area to a
            /// stop in the other, at least J inside it. Returns the states seen.
            fn pendulum_swings(rng: &mut Rng, swings: usize) -> Vec<u8> {
                let max_m: u64 = if core::mem::size_of::<$t>() == 2 {
                    65_000
                } else {
                    2_000_000_000
                };
                let m = 2000 + rng.next() % (max_m - 2000);
                let c = m + 1;
                let j = rng.next() % (m / 200 + 1);
                let tdc2_ul = j + 1 + m / 100;
                let tdc2_ll = 3 * j + 2 + m / 10;
                let (bdc_ll, bdc_ul) = (m / 2 - j - 1 - m / 50, m / 2 + j + 1 + m / 50);
                let tdc1_ll = m - 3 * j - 2 - m / 10;
                let tdc1_ul = m - j - 1 - m / 100;
                let mut fb = make(
                    true,
                    A_RESET | A_POS,
                    [tdc1_ll, tdc1_ul, tdc2_ll, tdc2_ul, bdc_ll, bdc_ul, 0],
                );
                fb.nMaxPosition = m as $t;
                fb.nAllowedPositionJitter = j as $t;
                assert_eq!(fb.init(), SL_OK);
                fb.bRun = 1;
                let max_step = (m / 25).max(2 * j + 1);
                let mut now = 1000u32;
                let mut states = Vec::new();
                let mut call = |fb: &mut Fb, truth: u64, rng: &mut Rng| {
                    let meas = (truth + rng.next() % (j + 1)) % c;
                    fb.nPosition = meas as $t;
                    now = now.wrapping_add(10);
                    assert_eq!(fb.cycle(now), SL_OK);
                    states.push(fb.nState);
                };
                let in_tdc2 = |rng: &mut Rng| tdc2_ul + rng.next() % (tdc2_ll - j - tdc2_ul);
                let in_tdc1 = |rng: &mut Rng| tdc1_ll + rng.next() % (tdc1_ul - j - tdc1_ll);
                let mut truth = in_tdc2(rng);
                call(&mut fb, truth, rng);
                for k in 0..swings {
                    for r in [1, 0] {
                        fb.bReset = r;
                        call(&mut fb, truth, rng);
                    }
                    let goal = if k % 2 == 0 {
                        in_tdc1(rng)
                    } else {
                        in_tdc2(rng)
                    };
                    while truth != goal {
                        let step =
                            (2 * j + 1 + rng.next() % (max_step - 2 * j)).min(truth.abs_diff(goal));
                        truth = if goal > truth {
                            truth + step
                        } else {
                            truth - step
                        };
                        call(&mut fb, truth, rng);
                    }
                    for _ in 0..2 * (fb.tStopDetectionTime / 10) + 3 {
                        call(&mut fb, truth, rng);
                    }
                }
                states
            }

            /// Property: a pendulum press swinging from one TDC area to the other, each swing
            /// released by a Reset pulse, makes no error and is never SAFE; every pendulum
            /// state is reached (≥ 10,000 sequences).
            #[test]
            fn pendulum_swings_make_no_error() {
                let mut rng = Rng(0x9E4D_0000 ^ core::mem::size_of::<$t>() as u64);
                let mut reached = std::collections::BTreeSet::new();
                for seq in 0..10_000 * depth() {
                    let swings = 2 + (rng.next() % 3) as usize;
                    let states = pendulum_swings(&mut rng, swings);
                    assert!(
                        !states.contains(&ERROR) && !states.contains(&SAFE),
                        "sequence {seq}: {states:?}"
                    );
                    reached.extend(states);
                }
                for st in [RUN, START, WAIT, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41] {
                    assert!(reached.contains(&st), "state {st} not reached: {reached:?}");
                }
            }

            fn depth() -> usize {
                std::env::var("SL_PROP_DEPTH")
                    .ok()
                    .and_then(|v| v.parse().ok())
                    .unwrap_or(1)
            }

            /// Property: any crank trajectory that moves only forwards within the jitter and
            /// obeys the cams (and Press_Started) makes no error; RUN and every excentric
            /// MOVE state are reached and every stroke completes (≥ 10,000 sequences).
            #[test]
            fn forward_trajectories_make_no_error() {
                let mut rng = Rng(0xCA11_0000 ^ core::mem::size_of::<$t>() as u64);
                let mut reached = std::collections::BTreeSet::new();
                let mut total = 0;
                let n = 10_000 * depth();
                for seq in 0..n {
                    let strokes = 2 + (rng.next() % 3) as usize;
                    let (states, done, back) = trajectory(&mut rng, strokes, None);
                    assert!(
                        !states.contains(&ERROR),
                        "sequence {seq}: {states:?} {back:?}"
                    );
                    assert_eq!(
                        done, strokes,
                        "sequence {seq}: strokes completed, {states:?}"
                    );
                    reached.extend(states);
                    total += done;
                }
                for st in [WAIT, START, RUN, MDOWN, MUP, MTDC, MSTOP, MSTART] {
                    assert!(reached.contains(&st), "state {st} not reached: {reached:?}");
                }
                assert!(total >= 2 * n);
            }

            /// Property: a backward step beyond the jitter without BackwardsMove during a
            /// stroke is an ERROR (0x400E) in that very call (≥ 10,000 sequences).
            #[test]
            fn a_backward_step_beyond_the_jitter_is_an_error_in_that_call() {
                let mut rng = Rng(0xBAC0_0000 ^ core::mem::size_of::<$t>() as u64);
                let n = 10_000 * depth();
                let mut moving_states = std::collections::BTreeSet::new();
                for seq in 0..n {
                    let at = ((rng.next() % 2) as usize, 1 + (rng.next() % 20) as usize);
                    let (states, _, back) = trajectory(&mut rng, 2, Some(at));
                    let before = states[states.len() - 2];
                    moving_states.insert(before);
                    assert_eq!(back, Some((ERROR, 0x400E)), "sequence {seq}: {states:?}");
                }
                for st in [RUN, MDOWN, MUP] {
                    assert!(
                        moving_states.contains(&st),
                        "backward step in {st} never tried: {moving_states:?}"
                    );
                }
            }
        }
    };
}

suite!(uint, FB_CAMMONITOR_UINT, u16);
suite!(udint, FB_CAMMONITOR_UDINT, u32);
