//! FB ENVELOPE (manual §4.32, fb-envelope-states.txt, ABI-2 §11.11, §12; docs/semantics.md
//! EV1–EV7) in all four integer variants: one test per statement of the manual section, then
//! random sequences against a small model of the block (≥ 10,000 per variant) that assert
//! what they reached.

mod common;

use common::{Rng, CORE_STATES};
use safelogic::blocks::analog::Analog;
use safelogic::*;

const MONITOR: u8 = SL_STATE_ENVELOPE_MONITOR;
const DELAYOUT: u8 = SL_STATE_DELAYOUT;

common::analog_outputs!(error: u8, out: u8);

/// The parameters of a test instance.
#[derive(Clone, Copy, Debug)]
struct Params {
    in_target: u32,
    max_time: u32,
    target: u32,
    offset: u32,
}

macro_rules! variant {
    ($name:ident, $ty:ty, $t:ty) => {
        crate::common::analog_wrapper!($name, $ty, $t);
        impl $name {
            fn new(p: Params) -> Self {
                let mut fb = <$ty>::default();
                fb.wInputActive = SL_ENVELOPE_ACTIVE;
                fb.tTimeAfterInTarget = p.in_target;
                fb.tMaxTime = p.max_time;
                fb.nTargetValue = p.target;
                fb.nOffset = p.offset;
                Self(fb)
            }
            fn set_inputs(&mut self, sf: u8, v: i128) {
                self.0.bSafeFunction = sf;
                self.0.nInValue = Self::t(v);
            }
            fn outputs(&self) -> Outputs {
                let f = &self.0;
                crate::common::read_outputs!(f {
                    error: f.bError,
                    out: f.bSafeFunctionOut,
                })
            }
        }
    };
}

variant!(EnvInt, FB_ENVELOPE_INT, i16);
variant!(EnvUint, FB_ENVELOPE_UINT, u16);
variant!(EnvDint, FB_ENVELOPE_DINT, i32);
variant!(EnvUdint, FB_ENVELOPE_UDINT, u32);

/// The envelope of the model: the straight line from `start` (t = 0) to `target` (t = max),
/// its exact value rounded down, not below `target` (EV3).
fn model_envelope(start: i128, target: i128, t: i128, max: i128) -> i128 {
    let exact_num = start * max - (start - target) * t;
    (exact_num.div_euclid(max)).max(target)
}

/// The outputs of a state without an error message.
fn plain(state: u8) -> Outputs {
    Outputs {
        error: u8::from(state == SL_STATE_ERROR),
        out: u8::from(matches!(state, SL_STATE_RUN | DELAYOUT | MONITOR)),
        state,
        diag: 0,
        text: 0,
        par: (0, 0),
    }
}

/// A model of the block written from the manual's state table and ABI-2 §11.11.
struct Model {
    p: Params,
    state: u8,
    ack: bool,
    latch: i128,
    t_edge: u32,
    t_in: u32,
    diag: u16,
    par: (i128, i128),
}

impl Model {
    fn new(p: Params) -> Self {
        Self {
            p,
            state: SL_STATE_STOP,
            ack: false,
            latch: 0,
            t_edge: 0,
            t_in: 0,
            diag: 0,
            par: (0, 0),
        }
    }
    fn cycle(&mut self, run: bool, ack: bool, sf: u8, v: i128, now: u32) {
        let rising = ack && !self.ack;
        let falling = !ack && self.ack;
        self.ack = ack;
        match self.state {
            SL_STATE_STOP => {
                if run {
                    self.start(sf, v, now);
                }
            }
            SL_STATE_ERROR => {
                if rising {
                    self.state = SL_STATE_RESET;
                    self.diag = 0;
                }
            }
            SL_STATE_RESET => {
                if falling {
                    if run {
                        self.start(sf, v, now);
                    } else {
                        self.state = SL_STATE_STOP;
                    }
                }
            }
            _ if !run => self.state = SL_STATE_STOP,
            _ => self.step(sf, v, now),
        }
    }
    fn start(&mut self, sf: u8, v: i128, now: u32) {
        self.state = SL_STATE_SAFE;
        self.step(sf, v, now);
    }
    fn step(&mut self, sf: u8, v: i128, now: u32) {
        if sf == 1 {
            self.state = SL_STATE_RUN;
            return;
        }
        match self.state {
            SL_STATE_RUN => {
                self.latch = v.abs();
                self.t_edge = now;
                self.monitor(v, now);
            }
            DELAYOUT | MONITOR => self.monitor(v, now),
            _ => self.state = SL_STATE_SAFE,
        }
    }
    fn monitor(&mut self, v: i128, now: u32) {
        let t = now.wrapping_sub(self.t_edge);
        if t >= self.p.max_time {
            self.state = SL_STATE_SAFE;
            return;
        }
        let target = i128::from(self.p.target);
        if v.abs() <= target {
            if self.state != DELAYOUT {
                self.t_in = now;
            }
            self.state = if now.wrapping_sub(self.t_in) >= self.p.in_target {
                SL_STATE_SAFE
            } else {
                DELAYOUT
            };
            return;
        }
        let e = model_envelope(
            self.latch + i128::from(self.p.offset),
            target,
            i128::from(t),
            i128::from(self.p.max_time),
        );
        if v.abs() > e {
            self.state = SL_STATE_ERROR;
            (self.diag, self.par) = if v < 0 { (1, (v, -e)) } else { (2, (v, e)) };
        } else {
            self.state = MONITOR;
        }
    }
    fn outputs(&self) -> Outputs {
        let mut o = plain(self.state);
        if self.state == SL_STATE_ERROR {
            o.diag = self.diag;
            o.text = if self.diag == 1 { 0x40C8 } else { 0x40C9 };
            o.par = (self.par.0 as i64 as u32, self.par.1 as i64 as u32);
        }
        if self.state == SL_STATE_RESET {
            o.diag = 0;
        }
        o
    }
}

macro_rules! envelope_tests {
    ($modname:ident, $v:ident, $t:ty) => {
        mod $modname {
            use super::*;

            type T = $t;
            const LO: i128 = T::MIN as i128;
            const HI: i128 = T::MAX as i128;
            const SIGNED: bool = LO < 0;

            fn pattern(v: i128) -> u32 {
                v as i64 as u32
            }

            const P: Params = Params {
                in_target: 100,
                max_time: 1000,
                target: 10,
                offset: 50,
            };

            /// A running instance in RUN at t = 0 with InValue `v`.
            fn in_run(p: Params, v: i128) -> $v {
                let mut fb = $v::new(p);
                assert_eq!(fb.init(), SL_OK);
                fb.control(1, 0);
                fb.set_inputs(1, v);
                assert_eq!(fb.cycle(0), SL_OK);
                assert_eq!(fb.outputs(), plain(SL_STATE_RUN));
                fb
            }

            /// One call at `now` with SafeFunction `sf` and InValue `v`; returns the state.
            fn at(fb: &mut $v, now: u32, sf: u8, v: i128) -> u8 {
                fb.set_inputs(sf, v);
                assert_eq!(fb.cycle(now), SL_OK);
                fb.outputs().state
            }

            /// §4.32.2 RUN: "If the input SafeFunction=TRUE … Error=0 SafeFunctionOut=1".
            #[test]
            fn run_while_safefunction_is_true() {
                let mut fb = in_run(P, 0);
                for (t, v) in [(1, LO), (2, HI), (3, 0)] {
                    assert_eq!(at(&mut fb, t, 1, v), SL_STATE_RUN);
                    assert_eq!(fb.outputs(), plain(SL_STATE_RUN));
                }
                assert_eq!(fb.state_name(), "RUN");
            }

            /// §4.32.2 STOP: "If the input FbRun=FALSE … Error=0 SafeFunctionOut=0".
            #[test]
            fn stop_with_run_false() {
                for sf in [0, 1] {
                    let mut fb = in_run(P, 0);
                    let expected = if sf == 1 { SL_STATE_RUN } else { MONITOR };
                    assert_eq!(at(&mut fb, 1, sf, 100), expected);
                    fb.control(0, 0);
                    assert_eq!(fb.cycle(2), SL_OK);
                    assert_eq!(fb.outputs(), plain(SL_STATE_STOP));
                }
            }

            /// A start with SafeFunction FALSE has no edge to monitor: SAFE (EV1); SAFE
            /// stays while SafeFunction is FALSE, SafeFunction TRUE → RUN.
            #[test]
            fn start_with_safefunction_false_is_safe() {
                let mut fb = $v::new(P);
                assert_eq!(fb.init(), SL_OK);
                fb.control(1, 0);
                assert_eq!(at(&mut fb, 0, 0, 0), SL_STATE_SAFE);
                assert_eq!(fb.outputs(), plain(SL_STATE_SAFE));
                assert_eq!(at(&mut fb, 5000, 0, 0), SL_STATE_SAFE);
                assert_eq!(at(&mut fb, 5001, 1, 0), SL_STATE_RUN);
            }

            /// §4.32.1 "Time after in Target starts running when InValue reaches the range
            /// between −TargetValue and +TargetValue … If InValue remains within the range,
            /// the output SafeFunctionOut is set to FALSE when Time after inTarget has
            /// elapsed"; DELAYOUT (8) "SafeFunctionOut=1" (EV2, EV4): the edge inside the
            /// window, SAFE exactly at the time, not 1 ms before.
            #[test]
            fn delayout_inside_the_target_window() {
                let values = if SIGNED {
                    vec![10, -10, 0]
                } else {
                    vec![10, 0]
                };
                for v in values {
                    let mut fb = in_run(P, v);
                    assert_eq!(at(&mut fb, 1000, 0, v), DELAYOUT, "{v}");
                    assert_eq!(fb.outputs(), plain(DELAYOUT));
                    assert_eq!(fb.state_name(), "DELAYOUT");
                    assert_eq!(at(&mut fb, 1099, 0, v), DELAYOUT);
                    assert_eq!(at(&mut fb, 1100, 0, v), SL_STATE_SAFE);
                    assert_eq!(fb.outputs(), plain(SL_STATE_SAFE));
                }
            }

            /// §4.32.1 "The time is reset when InValue exits this range and restarts if
            /// InValue enters the range again" (EV4): leaving the window goes to MONITOR,
            /// re-entering restarts the full time.
            #[test]
            fn leaving_the_window_resets_the_time() {
                let mut fb = in_run(P, 5);
                assert_eq!(at(&mut fb, 0, 0, 5), DELAYOUT);
                assert_eq!(at(&mut fb, 99, 0, 5), DELAYOUT);
                assert_eq!(at(&mut fb, 100, 0, 11), MONITOR);
                assert_eq!(at(&mut fb, 101, 0, 10), DELAYOUT);
                assert_eq!(at(&mut fb, 200, 0, 10), DELAYOUT);
                assert_eq!(at(&mut fb, 201, 0, 10), SL_STATE_SAFE);
            }

            /// "Time after in Target" 0: SAFE in the call that enters the window (EV4).
            #[test]
            fn a_zero_time_after_in_target_ends_at_once() {
                let mut fb = in_run(Params { in_target: 0, ..P }, 3);
                assert_eq!(at(&mut fb, 1, 0, 3), SL_STATE_SAFE);
            }

            /// §4.32.2 MONITOR (9): "If the input SafeFunction=FALSE, InValueInTarget=FALSE
            /// and MaxTimeExpired=FALSE … SafeFunctionOut=1"; the envelope starts at
            /// |InValue| + Offset (§4.32.1 "from the amount of InValue plus the defined
            /// Offset") and is checked in the edge's call already (EV2, EV3).
            #[test]
            fn monitor_outside_the_window() {
                let mut fb = in_run(P, 200);
                assert_eq!(at(&mut fb, 0, 0, 250), MONITOR);
                assert_eq!(fb.outputs(), plain(MONITOR));
                assert_eq!(fb.state_name(), "MONITOR");
                // The latch is the InValue of the edge's call: the envelope starts 50 above it.
                let mut fb = in_run(P, 200);
                assert_eq!(at(&mut fb, 0, 0, 300), MONITOR);
                assert_eq!(at(&mut fb, 0, 0, 350), MONITOR);
                assert_eq!(at(&mut fb, 0, 0, 351), SL_STATE_ERROR);
            }

            /// The envelope E(t) = ⌊(Start·(MaxTime − t) + Target·t) / MaxTime⌋ (EV3): at
            /// every t of a non-integer slope, InValue = E(t) stays in MONITOR and E(t) + 1
            /// is the overflow (diag 2, 0x40C9, Par2 InValue, Par3 +E(t)).
            #[test]
            fn the_envelope_at_its_boundary() {
                let p = Params {
                    in_target: 100,
                    max_time: 7,
                    target: 3,
                    offset: 0,
                };
                let start = 100;
                for t in 0..7u32 {
                    let e = model_envelope(start, 3, i128::from(t), 7);
                    let mut fb = in_run(p, start);
                    assert_eq!(at(&mut fb, 0, 0, start), MONITOR);
                    if t > 0 {
                        assert_eq!(at(&mut fb, t, 0, e), MONITOR, "t {t} e {e}");
                    }
                    let mut over = fb;
                    assert_eq!(at(&mut over, t, 0, e + 1), SL_STATE_ERROR, "t {t}");
                    let o = over.outputs();
                    assert_eq!((o.error, o.out), (1, 0));
                    assert_eq!(o.diag, SL_DIAG_ENVELOPE_OVERFLOW);
                    assert_eq!(o.text, SL_TEXT_ENVELOPE_OVERFLOW);
                    assert_eq!(o.par, (pattern(e + 1), pattern(e)));
                }
                // The values: 100, 86 (100 − 97/7 = 86.14…), 72, 58, 44, 30, 16.
                let es: Vec<i128> = (0..7).map(|t| model_envelope(100, 3, t, 7)).collect();
                assert_eq!(es, [100, 86, 72, 58, 44, 30, 16]);
            }

            /// Underflow: InValue below −E(t) → ERROR, diag 1, 0x40C8, Par2 InValue, Par3
            /// −E(t) ("MinAllowedValue"). Only the signed variants have negative values.
            #[test]
            fn underflow_below_the_envelope() {
                if !SIGNED {
                    return;
                }
                let mut fb = in_run(P, -200);
                assert_eq!(at(&mut fb, 0, 0, -200), MONITOR);
                let e = model_envelope(250, 10, 500, 1000);
                assert_eq!(e, 130);
                assert_eq!(at(&mut fb, 500, 0, -e), MONITOR);
                assert_eq!(at(&mut fb, 500, 0, -e - 1), SL_STATE_ERROR);
                let o = fb.outputs();
                assert_eq!((o.error, o.out, o.diag, o.text), (1, 0, 1, 0x40C8));
                assert_eq!(o.par, (pattern(-e - 1), pattern(-e)));
                assert_eq!(fb.state_name(), "ERROR");
            }

            /// §4.32.1 "The output SafeFunctionOut is set to FALSE once MaxTime has elapsed at
            /// the latest"; SAFE "MaxTimeExpired=TRUE": SAFE without an error, diag 0, in
            /// MONITOR and in DELAYOUT, exactly at MaxTime (EV5, EV6).
            #[test]
            fn max_time_ends_in_safe_without_error() {
                let mut fb = in_run(P, 200);
                assert_eq!(at(&mut fb, 10, 0, 200), MONITOR);
                assert_eq!(at(&mut fb, 510, 0, 100), MONITOR);
                // Far outside the envelope, but MaxTime has elapsed: SAFE, no error.
                assert_eq!(at(&mut fb, 1010, 0, 200), SL_STATE_SAFE);
                assert_eq!(fb.outputs(), plain(SL_STATE_SAFE));
                let mut fb = in_run(
                    Params {
                        in_target: 5000,
                        ..P
                    },
                    0,
                );
                assert_eq!(at(&mut fb, 10, 0, 0), DELAYOUT);
                assert_eq!(at(&mut fb, 1009, 0, 0), DELAYOUT);
                assert_eq!(at(&mut fb, 1010, 0, 0), SL_STATE_SAFE);
                assert_eq!(fb.outputs(), plain(SL_STATE_SAFE));
            }

            /// SafeFunction TRUE ends the monitored stop: DELAYOUT, MONITOR and SAFE → RUN.
            #[test]
            fn safefunction_true_returns_to_run() {
                for v in [0, 200] {
                    let mut fb = in_run(P, v);
                    assert_ne!(at(&mut fb, 1, 0, v), SL_STATE_RUN);
                    assert_eq!(at(&mut fb, 2, 1, v), SL_STATE_RUN);
                    // A new edge latches anew.
                    assert_eq!(at(&mut fb, 3, 0, 20), MONITOR);
                    assert_eq!(at(&mut fb, 3, 0, 71), SL_STATE_ERROR);
                }
            }

            /// §4.32.2 ERROR/RESET: the violation is an event (ABI-2 §12.5): an ErrAck edge
            /// → RESET (diag and message cleared), its falling edge → SAFE or RUN.
            #[test]
            fn error_acknowledged_through_reset() {
                for (sf, after) in [(0, SL_STATE_SAFE), (1, SL_STATE_RUN)] {
                    let mut fb = in_run(P, 200);
                    assert_eq!(at(&mut fb, 1, 0, 200), MONITOR);
                    assert_eq!(at(&mut fb, 2, 0, 300), SL_STATE_ERROR);
                    fb.control(1, 1);
                    assert_eq!(at(&mut fb, 3, 0, 300), SL_STATE_RESET);
                    assert_eq!(fb.outputs(), plain(SL_STATE_RESET));
                    assert_eq!(fb.state_name(), "RESET");
                    fb.control(1, 0);
                    assert_eq!(at(&mut fb, 4, sf, 300), after);
                }
            }

            /// An invalid SafeFunction byte reads FALSE (the stop request, ABI-2 §12.7) and
            /// the call returns SL_E_INVALID_BOOL.
            #[test]
            fn an_invalid_safefunction_byte_reads_false() {
                let mut fb = in_run(P, 0);
                fb.set_inputs(2, 0);
                assert_eq!(fb.cycle(1), SL_E_INVALID_BOOL);
                assert_eq!(fb.outputs().state, DELAYOUT);
            }

            /// The extremes of each type: |InValue| + Offset beyond 32 bits, |MIN| of the
            /// signed types, Target at its maximum: no overflow, exact results.
            #[test]
            fn extremes_of_the_type() {
                let p = Params {
                    in_target: 10,
                    max_time: 65_535,
                    target: 0,
                    offset: u32::MAX,
                };
                let mut fb = in_run(p, HI);
                assert_eq!(at(&mut fb, 1, 0, HI), MONITOR);
                let e = model_envelope(HI + i128::from(u32::MAX), 0, 65_533, 65_535);
                if HI <= e {
                    assert_eq!(at(&mut fb, 65_534, 0, HI), MONITOR);
                } else {
                    assert_eq!(at(&mut fb, 65_534, 0, HI), SL_STATE_ERROR);
                    assert_eq!(fb.outputs().par, (pattern(HI), pattern(e)));
                }
                if SIGNED {
                    let mut fb = in_run(Params { offset: 0, ..p }, LO);
                    assert_eq!(at(&mut fb, 0, 0, LO), MONITOR);
                    assert_eq!(at(&mut fb, 1, 0, LO), SL_STATE_ERROR);
                    let e = model_envelope(-LO, 0, 1, 65_535);
                    assert_eq!(fb.outputs().par, (pattern(LO), pattern(-e)));
                }
                let mut fb = in_run(
                    Params {
                        target: u32::MAX,
                        ..p
                    },
                    HI,
                );
                assert_eq!(at(&mut fb, 1, 0, LO), DELAYOUT);
            }

            /// Parameter limits (ABI-2 §11.11, §12.9): MaxTime 1…65 535 ms, Time after in
            /// Target 0…65 535 ms, wInputActive exactly bits 0 and 8.
            #[test]
            fn parameter_limits() {
                for (p, rc) in [
                    (Params { max_time: 0, ..P }, SL_E_CONFIG),
                    (Params { max_time: 1, ..P }, SL_OK),
                    (
                        Params {
                            max_time: 65_535,
                            ..P
                        },
                        SL_OK,
                    ),
                    (
                        Params {
                            max_time: 65_536,
                            ..P
                        },
                        SL_E_CONFIG,
                    ),
                    (Params { in_target: 0, ..P }, SL_OK),
                    (
                        Params {
                            in_target: 65_535,
                            ..P
                        },
                        SL_OK,
                    ),
                    (
                        Params {
                            in_target: 65_536,
                            ..P
                        },
                        SL_E_CONFIG,
                    ),
                    (
                        Params {
                            target: u32::MAX,
                            offset: u32::MAX,
                            ..P
                        },
                        SL_OK,
                    ),
                ] {
                    assert_eq!($v::new(p).init(), rc, "{p:?}");
                }
                for (active, rc) in [
                    (0x0101, SL_OK),
                    (0x0100, SL_E_CONFIG),
                    (0x0001, SL_E_CONFIG),
                    (0x0103, SL_E_CONFIG),
                    (0x0301, SL_E_CONFIG),
                ] {
                    let mut fb = $v::new(P);
                    fb.wInputActive = active;
                    assert_eq!(fb.init(), rc, "{active:#x}");
                }
            }

            /// MaxTime 1: the envelope reaches TargetValue after 1 ms, MaxTime ends it then.
            #[test]
            fn max_time_of_one_ms() {
                let mut fb = in_run(Params { max_time: 1, ..P }, 200);
                assert_eq!(at(&mut fb, 0, 0, 200), MONITOR);
                assert_eq!(at(&mut fb, 1, 0, HI), SL_STATE_SAFE);
            }

            /// ≥ 10,000 random sequences against the model: random parameters (small and
            /// extreme), SafeFunction pulses (invalid bytes included), InValue near the
            /// envelope, time steps around the parameters, bRun and ErrAck. Asserts every
            /// state reached and that diag values 3 and 4 never appear (EV6).
            #[test]
            fn random_sequences_against_the_model() {
                let mut rng = Rng(0xE7E1_0900 ^ (HI as u64));
                let mut reached = 0u64;
                let mut diags = [0u32; 5];
                const SEQUENCES: u32 = 10_000;
                let pick = |rng: &mut Rng, small: u32| -> u32 {
                    match rng.next() % 4 {
                        0 => (rng.next() % u64::from(small)) as u32,
                        1 => [0, 1, u32::MAX, 65_535][(rng.next() % 4) as usize],
                        _ => (rng.next() % u64::from(small * 10)) as u32,
                    }
                };
                for _ in 0..SEQUENCES {
                    let p = Params {
                        in_target: pick(&mut rng, 50).min(65_535),
                        max_time: pick(&mut rng, 200).clamp(1, 65_535),
                        target: pick(&mut rng, 50),
                        offset: pick(&mut rng, 50),
                    };
                    let mut fb = $v::new(p);
                    assert_eq!(fb.init(), SL_OK);
                    let mut m = Model::new(p);
                    let mut now = rng.next() as u32;
                    let mut v: i128 = 0;
                    for step in 0..24 {
                        let r = rng.next();
                        let run = r % 16 != 0;
                        let ack = r >> 4 & 7 == 0;
                        let sf = match r >> 8 & 7 {
                            0..=2 => 1,
                            3 if r >> 11 & 7 == 0 => 2,
                            _ => 0,
                        };
                        // InValue: a step around the last value, near ±Target, or anywhere.
                        v = match r >> 14 & 7 {
                            0 => LO + (rng.next() as i128).rem_euclid(HI - LO + 1),
                            1 | 2 => {
                                let t = i128::from(p.target) + (rng.next() % 5) as i128 - 2;
                                if rng.next() % 2 == 0 {
                                    t
                                } else {
                                    -t
                                }
                            }
                            _ => {
                                v + (rng.next() % 41) as i128
                                    - 20
                                    - v.signum() * (rng.next() % 8) as i128
                            }
                        }
                        .clamp(LO, HI);
                        now = now.wrapping_add(match r >> 17 & 3 {
                            0 => 0,
                            1 => (rng.next() % 3) as u32,
                            _ => (rng.next() % u64::from(p.max_time.min(400) / 4 + 2)) as u32,
                        });
                        fb.control(u8::from(run), u8::from(ack));
                        fb.set_inputs(sf, v);
                        let rc = fb.cycle(now);
                        assert_eq!(rc, if sf == 2 { SL_E_INVALID_BOOL } else { SL_OK });
                        m.cycle(run, ack, sf, v, now);
                        assert_eq!(
                            fb.outputs(),
                            m.outputs(),
                            "step {step}: sf {sf} v {v} now {now} {p:?}"
                        );
                        reached |= 1 << m.state;
                        diags[usize::from(fb.outputs().diag).min(4)] += 1;
                    }
                }
                crate::common::assert_reached(
                    reached,
                    CORE_STATES.into_iter().chain([DELAYOUT, MONITOR]),
                );
                assert!(diags[2] > 100, "overflows {diags:?}");
                assert!(!SIGNED || diags[1] > 100, "underflows {diags:?}");
                assert_eq!(diags[3] + diags[4], 0, "diag 3/4 {diags:?}");
            }
        }
    };
}

envelope_tests!(int, EnvInt, i16);
envelope_tests!(uint, EnvUint, u16);
envelope_tests!(dint, EnvDint, i32);
envelope_tests!(udint, EnvUdint, u32);
