//! FB SPEED (manual §4.24, ABI-2 §11.7, §12; docs/semantics.md SP1–SP4) in all four integer
//! variants: one test per statement of the manual section, then random sequences against a
//! small model of the block (≥ 10,000 per variant) that assert what they reached.

mod common;

use common::Rng;
use safelogic::base::block::FieldType;
use safelogic::blocks::analog::Analog;
use safelogic::*;

const POS: u16 = SL_SPEED_ACTIVE_POSITION;
const WRAP: u32 = SL_OPT_SPEED_OVERFLOW_CHECK;

common::analog_outputs!(error: u8, speed: i128);

macro_rules! speed_tests {
    ($modname:ident, $ty:ty, $t:ty) => {
        mod $modname {
            use super::*;

            type Fb = $ty;
            crate::common::analog_bounds!($t);
            const SIGNED: bool = LO < 0;
            /// 2^W.
            const MODULUS: i128 = HI - LO + 1;

            fn pattern(v: i128) -> u32 {
                t(v).to_bits()
            }

            fn new(interval: u32, options: u32) -> Fb {
                let mut fb = Fb::default();
                fb.wInputActive = POS;
                fb.tTimeInterval = interval;
                fb.dwOptions = options;
                assert_eq!(fb.init(), SL_OK);
                fb
            }

            fn outputs(f: &Fb) -> Outputs {
                crate::common::read_outputs!(f {
                    error: f.bError,
                    speed: f.nSpeed.wide(),
                })
            }

            fn step(fb: &mut Fb, now: u32, pos: i128) -> i32 {
                fb.nPosition = t(pos);
                fb.cycle(now)
            }

            /// Runs a step table of (time, position, expected Speed, note) rows: a failure
            /// names the row, its time and position, and its note.
            #[track_caller]
            fn speeds(fb: &mut Fb, rows: &[(u32, i128, i128, &str)]) {
                for (k, &(now, pos, want, note)) in rows.iter().enumerate() {
                    step(fb, now, pos);
                    assert_eq!(
                        fb.nSpeed.wide(),
                        want,
                        "row {k} (t {now}, position {pos}): Speed; {note}"
                    );
                }
            }

            /// A block started at `now` at position `pos`.
            fn running_at(interval: u32, options: u32, now: u32, pos: i128) -> Fb {
                let mut fb = new(interval, options);
                fb.bRun = 1;
                assert_eq!(step(&mut fb, now, pos), SL_OK);
                let o = outputs(&fb);
                assert_eq!(
                    (o.state, o.error, o.speed),
                    (SL_STATE_RUN, 0, 0),
                    "start: Speed 0"
                );
                fb
            }

            /// One interval from `from` to `to`: the speed or the diag value.
            fn one_interval(options: u32, from: i128, to: i128) -> Result<i128, u16> {
                let mut fb = running_at(10, options, 0, from);
                assert_eq!(step(&mut fb, 10, to), SL_OK);
                let o = outputs(&fb);
                if o.state == SL_STATE_RUN {
                    assert_eq!((o.error, o.diag, o.text, o.par), (0, 0, 0, (0, 0)));
                    Ok(o.speed)
                } else {
                    assert_eq!((o.state, o.error, o.speed), (SL_STATE_ERROR, 1, 0));
                    assert_eq!(o.text, 0x4087 + o.diag, "Text ID of diag value {}", o.diag);
                    assert_eq!(
                        o.par,
                        (pattern(to), pattern(from)),
                        "Par2 current, Par3 latched"
                    );
                    Err(o.diag)
                }
            }

            /// §4.24.1 "store the AnalogIn input and calculate a speed from it, based on the
            /// specified time interval … The speed output is given in increments per time
            /// interval": Speed 0 after the start, the difference at the first call with
            /// the interval elapsed (just below: unchanged), held until the next.
            #[test]
            fn speed_per_interval_edges() {
                let mut fb = running_at(100, 0, 1000, 10);
                speeds(&mut fb, &[(1050, 30, 0, "50 ms"), (1099, 40, 0, "99 ms")]);
                step(&mut fb, 1100, 45);
                assert_eq!(
                    (fb.nState, fb.nSpeed.wide()),
                    (SL_STATE_RUN, 35),
                    "100 ms: 45 − 10"
                );
                speeds(
                    &mut fb,
                    &[
                        (1150, 100, 35, "held between updates"),
                        (1199, 100, 35, ""),
                        (1200, 105, 60, "105 − 45"),
                        (1300, 105, 0, "standing still"),
                    ],
                );
            }

            /// ABI-2 §11.7: a late call is one update with the whole difference, not
            /// rescaled, and the next interval starts at that call.
            #[test]
            fn late_update_restarts_the_interval_at_the_call() {
                let mut fb = running_at(100, 0, 0, 0);
                speeds(
                    &mut fb,
                    &[
                        (250, 50, 50, ""),
                        (349, 70, 50, "99 ms after the late update"),
                        (350, 70, 20, ""),
                    ],
                );
            }

            /// "Time Interval … in ms": 1 ms updates at every call one ms apart; a call at
            /// the same tNow is no interval.
            #[test]
            fn interval_of_one_ms() {
                let mut fb = running_at(1, 0, 7, 0);
                speeds(&mut fb, &[(7, 5, 0, "0 ms"), (8, 5, 5, ""), (9, 8, 3, "")]);
            }

            /// ABI §4: the interval across the 2^32 ms wrap of tNow (base::time), at the
            /// largest interval too.
            #[test]
            fn interval_across_the_clock_wrap() {
                let t0 = u32::MAX - 40;
                let mut fb = running_at(100, 0, t0, 1);
                step(&mut fb, t0.wrapping_add(99), 3);
                assert_eq!(fb.nSpeed.wide(), 0, "99 ms across the wrap");
                step(&mut fb, t0.wrapping_add(100), 4);
                assert_eq!((fb.nState, fb.nSpeed.wide()), (SL_STATE_RUN, 3));
                let t1 = u32::MAX - 1000;
                let mut fb = running_at(SL_TIME_PARAM_MAX, 0, t1, 0);
                speeds(
                    &mut fb,
                    &[
                        (t1.wrapping_add(SL_TIME_PARAM_MAX - 1), 9, 0, ""),
                        (t1.wrapping_add(SL_TIME_PARAM_MAX), 9, 9, ""),
                    ],
                );
            }

            /// §4.24.2 diag 1 / 0x4088 and 2 / 0x4089 without the Overflow Check: the exact
            /// difference outside the type; UINT/UDINT: every backward movement is an
            /// underflow. ERROR: "Error = 1 Speed = 0"; Par2 current, Par3 latched position.
            #[test]
            fn range_errors_without_overflow_check() {
                if SIGNED {
                    assert_eq!(one_interval(0, -5, 7), Ok(12));
                    assert_eq!(one_interval(0, 7, -5), Ok(-12));
                    assert_eq!(one_interval(0, 0, HI), Ok(HI), "at the maximum");
                    assert_eq!(one_interval(0, -1, HI), Err(SL_DIAG_VALUE_OVERFLOW));
                    assert_eq!(one_interval(0, 0, LO), Ok(LO), "at the minimum");
                    assert_eq!(one_interval(0, 1, LO), Err(SL_DIAG_VALUE_UNDERFLOW));
                    assert_eq!(one_interval(0, LO, HI), Err(SL_DIAG_VALUE_OVERFLOW));
                } else {
                    assert_eq!(one_interval(0, 0, HI), Ok(HI), "no overflow possible");
                    assert_eq!(one_interval(0, 5, 5), Ok(0));
                    assert_eq!(
                        one_interval(0, 5, 4),
                        Err(SL_DIAG_VALUE_UNDERFLOW),
                        "backwards"
                    );
                    assert_eq!(one_interval(0, HI, 0), Err(SL_DIAG_VALUE_UNDERFLOW));
                }
            }

            /// §4.24.3 "Overflow Check … speed calculation method in the event of an input
            /// signal overflow" (semantics SP2): the difference modulo 2^W, the short way
            /// round, then the range check.
            #[test]
            fn overflow_check_is_the_modular_difference() {
                // A counter wrapping forwards at the end of the type.
                assert_eq!(one_interval(WRAP, HI - 2, LO + 3), Ok(6));
                assert_eq!(one_interval(WRAP, 5, 9), Ok(4));
                if SIGNED {
                    // Backwards across the wrap, and every jump inside the type.
                    assert_eq!(one_interval(WRAP, LO + 3, HI - 2), Ok(-6));
                    assert_eq!(one_interval(WRAP, -1, HI), Ok(LO), "−1 → MAX: −2^(W−1)");
                    assert_eq!(
                        one_interval(WRAP, 0, HI),
                        Ok(HI),
                        "half the circle forwards"
                    );
                    assert_eq!(one_interval(WRAP, 0, LO), Ok(LO));
                    assert_eq!(one_interval(WRAP, LO, HI), Ok(-1));
                } else {
                    // Forwards by up to half the circle; anything else reads as backwards.
                    assert_eq!(one_interval(WRAP, 0, MODULUS / 2 - 1), Ok(MODULUS / 2 - 1));
                    assert_eq!(
                        one_interval(WRAP, 0, MODULUS / 2),
                        Err(SL_DIAG_VALUE_UNDERFLOW)
                    );
                    assert_eq!(one_interval(WRAP, 9, 5), Err(SL_DIAG_VALUE_UNDERFLOW));
                    assert_eq!(one_interval(WRAP, 3, HI), Err(SL_DIAG_VALUE_UNDERFLOW));
                }
            }

            /// §4.24.2 RESET "If there is no longer an error after an error has occurred and
            /// the ErrAck input … is set to TRUE": the range error is an event (ABI-2 §12.5),
            /// the next ErrAck edge acknowledges; RESET "Error = 0 Speed = 0", message
            /// cleared; ErrAck FALSE → RUN with a new latch and Speed 0.
            #[test]
            fn error_is_an_event() {
                let mut fb = running_at(10, 0, 0, 5);
                assert_eq!(step(&mut fb, 10, if SIGNED { LO } else { 0 }), SL_OK);
                assert_eq!(fb.nState, SL_STATE_ERROR);
                assert_eq!(fb.nDiag, SL_DIAG_VALUE_UNDERFLOW);
                assert_eq!(fb.nDiagTextId, SL_TEXT_SPEED_UNDERFLOW);
                fb.bErrAck = 1;
                assert_eq!(step(&mut fb, 11, 5), SL_OK);
                let r = outputs(&fb);
                assert_eq!(
                    (r.state, r.error, r.speed, r.diag, r.text, r.par),
                    (SL_STATE_RESET, 0, 0, 0, 0, (0, 0))
                );
                fb.bErrAck = 0;
                assert_eq!(step(&mut fb, 30, 20), SL_OK);
                assert_eq!(
                    (fb.nState, fb.nSpeed.wide()),
                    (SL_STATE_RUN, 0),
                    "latched anew"
                );
                speeds(
                    &mut fb,
                    &[
                        (39, 25, 0, ""),
                        (40, 26, 6, "26 − 20 from the RESET → RUN latch"),
                    ],
                );
            }

            /// §4.24.2 STOP: "Error = 0 Speed = 0"; STOP → run latches anew (SP1).
            #[test]
            fn stop_outputs_zero_and_restart_latches() {
                let mut fb = running_at(10, 0, 0, 0);
                step(&mut fb, 10, 8);
                assert_eq!(fb.nSpeed.wide(), 8);
                fb.bRun = 0;
                assert_eq!(step(&mut fb, 11, 9), SL_OK);
                let o = outputs(&fb);
                assert_eq!(
                    (o.state, o.error, o.speed, o.diag),
                    (SL_STATE_STOP, 0, 0, 0)
                );
                fb.bRun = 1;
                assert_eq!(step(&mut fb, 500, 100), SL_OK);
                assert_eq!((fb.nState, fb.nSpeed.wide()), (SL_STATE_RUN, 0));
                step(&mut fb, 510, 103);
                assert_eq!(
                    fb.nSpeed.wide(),
                    3,
                    "from the restart's latch, not the old one"
                );
            }

            /// ABI-2 §11.7, §12.9, §10.5: Time Interval 1 … 65,535 ms, Position required,
            /// the one option; refused configurations stay in STOP with Speed 0.
            #[test]
            fn configuration_limits() {
                let init = |interval: u32, options: u32, active: u16| {
                    let mut fb = Fb::default();
                    fb.tTimeInterval = interval;
                    fb.dwOptions = options;
                    fb.wInputActive = active;
                    fb.init()
                };
                assert_eq!(init(1, 0, POS), SL_OK);
                assert_eq!(init(0, 0, POS), SL_E_CONFIG, "interval 0");
                assert_eq!(init(SL_TIME_PARAM_MAX, WRAP, POS), SL_OK);
                assert_eq!(init(SL_TIME_PARAM_MAX + 1, 0, POS), SL_E_CONFIG);
                for bad in [0, 1, POS | 1 << 9, POS | 1] {
                    assert_eq!(init(10, 0, bad), SL_E_CONFIG, "active {bad:#x}");
                }
                for bad in [1, 1 << 9, WRAP | 1 << 31] {
                    assert_eq!(init(10, bad, POS), SL_E_CONFIG, "options {bad:#x}");
                }
                let mut fb = Fb::default();
                assert_eq!(fb.init(), SL_E_CONFIG, "a zeroed instance has interval 0");
                fb.bRun = 1;
                assert_eq!(step(&mut fb, 0, 5), SL_E_CONFIG);
                assert_eq!(
                    (fb.nState, fb.nSpeed.wide(), fb.bError),
                    (SL_STATE_STOP, 0, 0)
                );
            }

            /// §4.24.2 Diagnostic information and status values.
            #[test]
            fn diag_value_table() {
                let info =
                    safelogic::registry::info(<Fb as safelogic::base::block::Registered>::INFO.tag)
                        .unwrap();
                let values: Vec<u16> = info.diag_values.iter().map(|(v, _)| *v).collect();
                assert_eq!(values, [0, 1, 2]);
                assert!(info.diag_values[1].1.contains("Speed has an underflow"));
                let states: Vec<u8> = info.states.iter().map(|(s, _)| *s).collect();
                assert_eq!(states, [1, 2, 4, 5], "RUN STOP ERROR RESET, no SAFE");
            }

            /// The model of one cycle (ABI-2 §11.7 + the envelope's ABI §7 rules).
            struct Model {
                interval: u32,
                wrap: bool,
                state: u8,
                speed: i128,
                latch: i128,
                since: u32,
                diag: u16,
                par: (u32, u32),
                ack: bool,
            }

            impl Model {
                fn cycle(&mut self, run: bool, ack: bool, pos: i128, now: u32) {
                    let (rising, falling) = (ack && !self.ack, !ack && self.ack);
                    self.ack = ack;
                    let start = |m: &mut Model| {
                        m.latch = pos;
                        m.since = now;
                        m.speed = 0;
                        m.state = SL_STATE_RUN;
                    };
                    match self.state {
                        SL_STATE_STOP if run => start(self),
                        SL_STATE_STOP => {}
                        SL_STATE_ERROR => {
                            if rising {
                                self.state = SL_STATE_RESET;
                            }
                        }
                        SL_STATE_RESET => {
                            if falling {
                                if run {
                                    start(self)
                                } else {
                                    self.state = SL_STATE_STOP
                                }
                            }
                        }
                        _ if !run => self.state = SL_STATE_STOP,
                        _ if now.wrapping_sub(self.since) < self.interval => {}
                        _ => {
                            let mut d = pos - self.latch;
                            if self.wrap {
                                // The representative of d modulo 2^W nearest to 0 (ties: −).
                                while d >= MODULUS / 2 {
                                    d -= MODULUS;
                                }
                                while d < -(MODULUS / 2) {
                                    d += MODULUS;
                                }
                            }
                            if (LO..=HI).contains(&d) {
                                self.speed = d;
                                self.latch = pos;
                                self.since = now;
                            } else {
                                self.diag = if d < LO { 1 } else { 2 };
                                self.par = (pattern(pos), pattern(self.latch));
                                self.state = SL_STATE_ERROR;
                            }
                        }
                    }
                }
                fn outputs(&self) -> Outputs {
                    let run = self.state == SL_STATE_RUN;
                    let error = self.state == SL_STATE_ERROR;
                    Outputs {
                        error: u8::from(error),
                        speed: if run { self.speed } else { 0 },
                        state: self.state,
                        diag: if error { self.diag } else { 0 },
                        text: if error { 0x4087 + self.diag } else { 0 },
                        par: if error { self.par } else { (0, 0) },
                    }
                }
            }

            /// ≥ 10,000 random sequences of valid configurations against the model, cycle by
            /// cycle (positions moving by small steps and now and then jumping to the ends of
            /// the range, intervals short enough to elapse, the clock starting anywhere so
            /// that it wraps); a labelled share of invalid configurations.
            #[test]
            fn random_sequences_against_the_model() {
                let mut rng = Rng(0x5BEE_D001 ^ (HI as u64));
                let (mut reached, mut diags, mut moving, mut invalid) = (0u32, 0u8, 0u32, 0u32);
                let sequences = common::depth_cases(12_000);
                for _ in 0..sequences {
                    let r = rng.next();
                    if r % 16 == 0 {
                        invalid += 1;
                        let mut fb = Fb::default();
                        fb.wInputActive = POS;
                        match r >> 4 & 1 {
                            0 => {
                                fb.tTimeInterval = [0, SL_TIME_PARAM_MAX + 1][(r >> 8 & 1) as usize]
                            }
                            _ => (fb.tTimeInterval, fb.dwOptions) = (10, 1 << (r >> 8 & 7)),
                        }
                        assert_eq!(fb.init(), SL_E_CONFIG);
                        fb.bRun = 1;
                        assert_eq!(step(&mut fb, 0, 1), SL_E_CONFIG);
                        assert_eq!(outputs(&fb).state, SL_STATE_STOP);
                        continue;
                    }
                    let interval = [1, 2, 5, 10, 30][(r >> 8) as usize % 5];
                    let wrap = r >> 12 & 1 == 1;
                    let mut fb = new(interval, if wrap { WRAP } else { 0 });
                    let mut m = Model {
                        interval,
                        wrap,
                        state: SL_STATE_STOP,
                        speed: 0,
                        latch: 0,
                        since: 0,
                        diag: 0,
                        par: (0, 0),
                        ack: false,
                    };
                    let mut now = rng.next() as u32;
                    let mut pos = [0, LO, HI, 100][(r >> 16) as usize % 4];
                    for _ in 0..24 {
                        let r = rng.next();
                        let run = r % 12 != 0;
                        let ack = r >> 4 & 3 == 0;
                        pos = match r >> 8 & 15 {
                            0 => [LO, HI, 0][(r >> 12) as usize % 3],
                            // A step of the counter, wrapping at the ends of the type.
                            _ => LO + (pos - LO + (r >> 16 & 63) as i128 - 24).rem_euclid(MODULUS),
                        };
                        now = now.wrapping_add((r >> 24) as u32 % 12);
                        fb.bRun = u8::from(run);
                        fb.bErrAck = u8::from(ack);
                        assert_eq!(step(&mut fb, now, pos), SL_OK);
                        m.cycle(run, ack, pos, now);
                        let o = outputs(&fb);
                        assert_eq!(
                            o,
                            m.outputs(),
                            "interval {interval} wrap {wrap} pos {pos} now {now}"
                        );
                        reached |= 1 << o.state;
                        moving += u32::from(o.speed != 0);
                        if o.state == SL_STATE_ERROR {
                            diags |= 1 << o.diag;
                        }
                    }
                }
                crate::common::assert_reached(
                    reached.into(),
                    [SL_STATE_RUN, SL_STATE_STOP, SL_STATE_ERROR, SL_STATE_RESET],
                );
                // Unsigned: a speed never exceeds the type, only backwards underflows.
                assert_eq!(
                    diags,
                    if SIGNED { 0b110 } else { 0b010 },
                    "diag values {diags:#b}"
                );
                assert!(moving > 10_000, "non-zero speeds {moving}");
                crate::common::assert_invalid_share(invalid, 300, sequences / 8);
            }
        }
    };
}

speed_tests!(int, FB_SPEED_INT, i16);
speed_tests!(uint, FB_SPEED_UINT, u16);
speed_tests!(dint, FB_SPEED_DINT, i32);
speed_tests!(udint, FB_SPEED_UDINT, u32);
