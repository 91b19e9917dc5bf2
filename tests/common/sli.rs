//! What tests/sli.rs and tests/sli2.rs share: every statement of manual §4.27 (FB SLI
//! inherits them all, §4.28.1) checked on each variant of a block, and the random test
//! against a small independent model. Fields are reached by name through the field table
//! (`FunctionBlock::get` / `set`), so one body serves both structs.

use crate::common::Rng;
use safelogic::*;

/// Everything the block shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Outs {
    pub state: u8,
    pub error: u32,
    pub active: u32,
    pub below: u32,
    pub above: u32,
    /// PositionDiff, sign-extended.
    pub diff: i64,
    pub diag: u32,
    pub text: u32,
    pub par: (u32, u32),
}

pub fn outs<B: FunctionBlock>(fb: &B) -> Outs {
    let g = |n: &str| fb.get(n).unwrap_or(0);
    Outs {
        state: g("nState") as u8,
        error: g("bError"),
        active: g("bSLIActive"),
        below: g("bBelowMin"),
        above: g("bAboveMax"),
        diff: i64::from(g("nPositionDiff") as i32),
        diag: g("nDiag"),
        text: g("nDiagTextId"),
        par: (g("dwDiagPar2"), g("dwDiagPar3")),
    }
}

/// A configured instance after `init` (status returned).
pub fn make<B: FunctionBlock + Default>(pos: u32, neg: u32, options: u32) -> (B, i32) {
    let mut fb = B::default();
    fb.set("wInputActive", i64::from(SL_SLI_ACTIVE)).unwrap();
    fb.set("nLimitPos", i64::from(pos)).unwrap();
    fb.set("nLimitNeg", i64::from(neg)).unwrap();
    if options != 0 {
        fb.set("dwOptions", i64::from(options)).unwrap();
    }
    let rc = fb.init();
    (fb, rc)
}

/// One call: SLI byte, Position, bRun, ErrAck.
pub fn call<B: FunctionBlock>(fb: &mut B, t: u32, sli: u8, pos: i128, run: u8, ack: u8) -> i32 {
    fb.set("nPosition", pos as i64).unwrap();
    // An invalid BOOL byte cannot go through `set`; write it as the raw input bits.
    fb.set("bSLI", i64::from(sli.min(1))).unwrap();
    if sli > 1 {
        let off = fb.field("bSLI").unwrap().offset;
        assert_eq!(off, 0);
        // SAFETY: bSLI is the first byte of every SLI/SLI2 struct (ABI-2 §11.9, §11.10).
        unsafe { *(fb as *mut B).cast::<u8>() = sli };
    }
    fb.set("bRun", i64::from(run)).unwrap();
    fb.set("bErrAck", i64::from(ack)).unwrap();
    fb.cycle(t)
}

/// The model: an independent reading of §4.27 / §4.28 and docs/semantics.md SI1–SI8.
#[derive(Clone, Copy, Debug)]
pub struct Model {
    pub state: u8,
    prev_sli: bool,
    prev_ack: bool,
    held: bool,
    latch: i128,
    diff: i128,
    dir: (u32, u32),
    diag: u32,
    par: (i128, i128),
    pub lo: i128,
    pub hi: i128,
    /// PositionDiff's range (INT16 / INT32).
    pub ts: (i128, i128),
    pub limits: (i128, i128),
    pub modular: bool,
    pub exceeded: bool,
}

impl Model {
    pub fn new(lo: i128, hi: i128, ts: (i128, i128), limits: (u32, u32), options: u32) -> Self {
        Model {
            state: SL_STATE_STOP,
            prev_sli: false,
            prev_ack: false,
            held: false,
            latch: 0,
            diff: 0,
            dir: (0, 0),
            diag: 0,
            par: (0, 0),
            lo,
            hi,
            ts,
            limits: (i128::from(limits.0), i128::from(limits.1)),
            modular: options & SL_OPT_SLI2_OVERFLOW_ALLOWED != 0,
            exceeded: options & SL_OPT_SLI2_EXCEEDED_SUPPORT != 0,
        }
    }

    fn diff_of(&self, pos: i128) -> i128 {
        let d = pos - self.latch;
        if !self.modular {
            d
        } else if self.hi - self.lo == 0xFFFF {
            i128::from(d as i16)
        } else {
            i128::from(d as i32)
        }
    }

    fn run_step(&mut self, sli: bool, rising: bool, pos: i128) {
        match self.state {
            SL_STATE_SAFE => {
                if rising {
                    self.latch = pos;
                    self.diff = 0;
                    self.state = SL_STATE_RUN;
                }
            }
            _ if !sli => self.state = SL_STATE_SAFE,
            SL_STATE_RUN | SL_STATE_SLI2_EXCEEDED => {
                let d = self.diff_of(pos);
                let below = d < -self.limits.1;
                let above = d > self.limits.0;
                if self.state == SL_STATE_RUN && !below && !above {
                    self.diff = d;
                } else if self.state == SL_STATE_SLI2_EXCEEDED || self.exceeded {
                    self.state = SL_STATE_SLI2_EXCEEDED;
                    self.diff = d.clamp(self.ts.0, self.ts.1);
                    self.dir = (u32::from(below), u32::from(above));
                } else {
                    self.state = SL_STATE_ERROR;
                    self.diag = if below { 1 } else { 2 };
                    self.par = (pos, self.latch);
                }
            }
            _ => unreachable!(),
        }
    }

    /// One call (valid control bytes; `sli` may be invalid).
    pub fn cycle(&mut self, sli_byte: u8, pos: i128, run: bool, ack: bool) {
        let sli = sli_byte == 1;
        let rising = sli && !self.prev_sli;
        self.prev_sli = sli;
        let (ack_rise, ack_fall) = (ack && !self.prev_ack, !ack && self.prev_ack);
        self.prev_ack = ack;
        match self.state {
            SL_STATE_STOP => {
                if run {
                    self.state = SL_STATE_SAFE;
                    self.run_step(sli, rising, pos);
                }
            }
            SL_STATE_ERROR => {
                if ack_rise {
                    self.state = SL_STATE_RESET;
                    self.diag = 0;
                    self.held = false;
                }
            }
            SL_STATE_RESET => {
                if ack_fall || (self.held && !ack) {
                    if !run {
                        self.held = false;
                        self.state = SL_STATE_STOP;
                    } else if sli {
                        self.held = true;
                    } else {
                        self.held = false;
                        self.state = SL_STATE_SAFE;
                    }
                }
            }
            _ if !run => self.state = SL_STATE_STOP,
            _ => self.run_step(sli, rising, pos),
        }
        if self.state != SL_STATE_SLI2_EXCEEDED {
            self.dir = (0, 0);
        }
    }

    pub fn outs(&self, sli2: bool, pattern: impl Fn(i128) -> u32) -> Outs {
        let s = self.state;
        let diff = match s {
            SL_STATE_RUN | SL_STATE_SLI2_EXCEEDED => self.diff as i64,
            _ => 0,
        };
        let err = s == SL_STATE_ERROR;
        Outs {
            state: s,
            error: u32::from(err),
            active: u32::from(s == SL_STATE_RUN),
            below: if sli2 { self.dir.0 } else { 0 },
            above: if sli2 { self.dir.1 } else { 0 },
            diff,
            diag: if err { self.diag } else { 0 },
            text: if err { 0x40BF + self.diag } else { 0 },
            par: if err {
                (pattern(self.par.0), pattern(self.par.1))
            } else {
                (0, 0)
            },
        }
    }
}

/// A random value of the variant's range, often near an anchor.
pub fn value(rng: &mut Rng, lo: i128, hi: i128, anchors: &[i128], spread: i128) -> i128 {
    if rng.next() % 4 != 0 {
        let a = anchors[(rng.next() % anchors.len() as u64) as usize];
        (a + (rng.next() as i128).rem_euclid(2 * spread + 1) - spread).clamp(lo, hi)
    } else {
        lo + (rng.next() as i128).rem_euclid(hi - lo + 1)
    }
}

/// The statements of §4.27 on one variant: `$ty` the struct, `$t` Position's type, `$ts`
/// PositionDiff's type, `$sli2` whether the block is SLI2.
macro_rules! sli_tests {
    ($modname:ident, $ty:ty, $t:ty, $ts:ty, $sli2:expr) => {
        mod $modname {
            use super::sli::*;
            use super::common::Rng;
            use safelogic::*;

            const LO: i128 = <$t>::MIN as i128;
            const HI: i128 = <$t>::MAX as i128;
            const TS_MAX: u32 = <$ts>::MAX as u32;
            /// A position with room on both sides.
            const MID: i128 = (LO + HI) / 2;

            fn pattern(v: i128) -> u32 {
                v as $t as i64 as u32
            }

            /// Running with SLI risen at `latch`.
            fn latched(pos: u32, neg: u32, options: u32, latch: i128) -> $ty {
                let (mut fb, rc) = make::<$ty>(pos, neg, options);
                assert_eq!(rc, SL_OK);
                assert_eq!(call(&mut fb, 0, 0, latch, 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_SAFE);
                assert_eq!(call(&mut fb, 1, 1, latch, 1, 0), SL_OK);
                fb
            }

            /// §4.27.1 "save the Position input when a rising edge is encountered at input
            /// SLI"; RUN "SLIActive = 1 PositionDiff = Position - LatchPosition".
            #[test]
            fn rising_edge_latches_and_run_shows_the_difference() {
                let mut fb = latched(100, 50, 0, MID);
                let o = outs(&fb);
                assert_eq!((o.state, o.error, o.active, o.diff), (SL_STATE_RUN, 0, 1, 0));
                assert_eq!(fb.state_name(), "RUN");
                for (t, d) in [(2, 7i128), (3, 100), (4, -50), (5, -1), (6, 0)] {
                    assert_eq!(call(&mut fb, t, 1, MID + d, 1, 0), SL_OK);
                    let o = outs(&fb);
                    assert_eq!((o.state, o.active, o.diff), (SL_STATE_RUN, 1, d as i64), "{d}");
                    assert_eq!((o.diag, o.text, o.par), (0, 0, (0, 0)));
                }
            }

            /// RUN "checks whether −NegLimit ≤ PositionDiff ≤ PosLimit": both bounds
            /// inclusive; one beyond Limit pos → ERROR, diag 2 "Overflow", 0x40C1 with
            /// Position and LatchPosition; ERROR "Error = 1 SLIActive = 0 PositionDiff = 0".
            #[test]
            fn overflow_just_beyond_limit_pos() {
                let mut fb = latched(100, 50, 0, MID);
                assert_eq!(call(&mut fb, 2, 1, MID + 100, 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_RUN);
                assert_eq!(call(&mut fb, 3, 1, MID + 101, 1, 0), SL_OK);
                let o = outs(&fb);
                assert_eq!((o.state, o.error, o.active, o.diff, o.below, o.above), (4, 1, 0, 0, 0, 0));
                assert_eq!((o.diag, o.text), (2, SL_TEXT_SLI_OVERFLOW as u32));
                assert_eq!(o.par, (pattern(MID + 101), pattern(MID)));
                assert_eq!(fb.state_name(), "ERROR");
            }

            /// One beyond −Limit neg → ERROR, diag 1 "Underflow", 0x40C0.
            #[test]
            fn underflow_just_beyond_limit_neg() {
                let mut fb = latched(100, 50, 0, MID);
                assert_eq!(call(&mut fb, 2, 1, MID - 50, 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_RUN);
                assert_eq!(call(&mut fb, 3, 1, MID - 51, 1, 0), SL_OK);
                let o = outs(&fb);
                assert_eq!((o.state, o.error, o.active, o.diff), (4, 1, 0, 0));
                assert_eq!((o.diag, o.text), (1, SL_TEXT_SLI_UNDERFLOW as u32));
                assert_eq!(o.par, (pattern(MID - 51), pattern(MID)));
            }

            /// Limits 0: a one-position window (the latch itself).
            #[test]
            fn zero_limits_allow_only_the_latched_position() {
                let mut fb = latched(0, 0, 0, MID);
                assert_eq!(outs(&fb).state, SL_STATE_RUN);
                assert_eq!(call(&mut fb, 2, 1, MID + 1, 1, 0), SL_OK);
                assert_eq!(outs(&fb).diag, 2);
                let mut fb = latched(0, 0, 0, MID);
                assert_eq!(call(&mut fb, 2, 1, MID - 1, 1, 0), SL_OK);
                assert_eq!(outs(&fb).diag, 1);
            }

            /// Par2/Par3 as 32-bit patterns: INT sign-extended, UINT zero-extended (§10.4).
            #[test]
            fn message_parameters_at_the_ends_of_the_type() {
                let mut fb = latched(10, 10, 0, LO);
                assert_eq!(call(&mut fb, 2, 1, HI, 1, 0), SL_OK);
                let o = outs(&fb);
                assert_eq!((o.diag, o.par), (2, (pattern(HI), pattern(LO))));
                assert_eq!(o.par.1, LO as i64 as u32);
                let mut fb = latched(10, 10, 0, HI);
                assert_eq!(call(&mut fb, 2, 1, LO, 1, 0), SL_OK);
                let o = outs(&fb);
                assert_eq!((o.diag, o.par), (1, (pattern(LO), pattern(HI))));
            }

            /// SAFE "If the input SLI=FALSE … SLIActive = 0 PositionDiff = 0"; a new rising
            /// edge latches the new position.
            #[test]
            fn sli_false_is_safe_and_the_next_edge_latches_anew() {
                let mut fb = latched(100, 100, 0, MID);
                assert_eq!(call(&mut fb, 2, 1, MID + 5, 1, 0), SL_OK);
                assert_eq!(call(&mut fb, 3, 0, MID + 5, 1, 0), SL_OK);
                let o = outs(&fb);
                assert_eq!((o.state, o.error, o.active, o.diff), (SL_STATE_SAFE, 0, 0, 0));
                assert_eq!(fb.state_name(), "SAFE");
                // Far away while SLI is FALSE: no check.
                assert_eq!(call(&mut fb, 4, 0, HI, 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_SAFE);
                assert_eq!(call(&mut fb, 5, 1, MID + 500, 1, 0), SL_OK);
                assert_eq!((outs(&fb).state, outs(&fb).diff), (SL_STATE_RUN, 0));
                assert_eq!(call(&mut fb, 6, 1, MID + 600, 1, 0), SL_OK);
                assert_eq!((outs(&fb).state, outs(&fb).diff), (SL_STATE_RUN, 100));
            }

            /// SLI TRUE without an edge stays SAFE (held TRUE through STOP → run, SI3).
            #[test]
            fn sli_held_through_stop_to_run_is_no_edge() {
                let (mut fb, _) = make::<$ty>(10, 10, 0);
                assert_eq!(call(&mut fb, 0, 1, MID, 0, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_STOP);
                assert_eq!(fb.state_name(), "STOP");
                assert_eq!(call(&mut fb, 1, 1, MID, 1, 0), SL_OK);
                assert_eq!((outs(&fb).state, outs(&fb).active), (SL_STATE_SAFE, 0));
                assert_eq!(call(&mut fb, 2, 1, MID + 1000.min(HI - MID), 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_SAFE);
                assert_eq!(call(&mut fb, 3, 0, MID, 1, 0), SL_OK);
                assert_eq!(call(&mut fb, 4, 1, MID, 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_RUN);
            }

            /// SLI rising in the very call that starts the group is an edge (SI3).
            #[test]
            fn sli_rising_with_the_start_latches() {
                let (mut fb, _) = make::<$ty>(10, 10, 0);
                assert_eq!(call(&mut fb, 0, 0, MID, 0, 0), SL_OK);
                assert_eq!(call(&mut fb, 1, 1, MID, 1, 0), SL_OK);
                assert_eq!((outs(&fb).state, outs(&fb).active), (SL_STATE_RUN, 1));
            }

            /// STOP "If the input FbRun=FALSE … SLIActive = 0 PositionDiff = 0"; the next
            /// start needs a new edge.
            #[test]
            fn run_false_is_stop_and_outputs_are_zero() {
                let mut fb = latched(10, 10, 0, MID);
                assert_eq!(call(&mut fb, 2, 1, MID + 3, 0, 0), SL_OK);
                let o = outs(&fb);
                assert_eq!((o.state, o.error, o.active, o.diff), (SL_STATE_STOP, 0, 0, 0));
                assert_eq!(call(&mut fb, 3, 1, MID + 3, 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_SAFE);
            }

            /// ERROR is an event (SI4): the next ErrAck edge acknowledges even with the
            /// position still outside; RESET "should only exit the RESET state if
            /// ErrAck=FALSE and SLI=FALSE"; outputs 0 and the message cleared in RESET.
            #[test]
            fn reset_is_left_only_with_errack_and_sli_false() {
                let mut fb = latched(10, 10, 0, MID);
                assert_eq!(call(&mut fb, 2, 1, MID + 11, 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_ERROR);
                // ErrAck in the call that detects the error cannot acknowledge it; still
                // outside, the rising edge does.
                assert_eq!(call(&mut fb, 3, 1, MID + 11, 1, 1), SL_OK);
                let o = outs(&fb);
                assert_eq!((o.state, o.error, o.active, o.diff), (SL_STATE_RESET, 0, 0, 0));
                assert_eq!((o.diag, o.text, o.par), (0, 0, (0, 0)));
                assert_eq!(fb.state_name(), "RESET");
                // ErrAck falls with SLI TRUE: RESET holds.
                assert_eq!(call(&mut fb, 4, 1, MID, 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_RESET);
                assert_eq!(call(&mut fb, 5, 1, MID, 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_RESET);
                // ErrAck TRUE again while SLI falls: still RESET (ErrAck must be FALSE).
                assert_eq!(call(&mut fb, 6, 0, MID, 1, 1), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_RESET);
                assert_eq!(call(&mut fb, 7, 0, MID, 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_SAFE);
                assert_eq!(call(&mut fb, 8, 1, MID, 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_RUN);
            }

            /// RESET left in the call ErrAck falls when SLI is already FALSE; a held RESET
            /// goes to STOP when bRun falls.
            #[test]
            fn reset_exits_at_once_with_sli_false_and_to_stop_without_run() {
                let mut fb = latched(10, 10, 0, MID);
                assert_eq!(call(&mut fb, 2, 1, MID - 11, 1, 0), SL_OK);
                assert_eq!(call(&mut fb, 3, 0, MID, 1, 1), SL_OK);
                assert_eq!(call(&mut fb, 4, 0, MID, 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_SAFE);
                let mut fb = latched(10, 10, 0, MID);
                assert_eq!(call(&mut fb, 2, 1, MID - 11, 1, 0), SL_OK);
                assert_eq!(call(&mut fb, 3, 1, MID, 1, 1), SL_OK);
                assert_eq!(call(&mut fb, 4, 1, MID, 1, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_RESET);
                assert_eq!(call(&mut fb, 5, 1, MID, 0, 0), SL_OK);
                assert_eq!(outs(&fb).state, SL_STATE_STOP);
            }

            /// Limit pos/neg "UINT32 values … always specified positive", bounded by the
            /// maximum of PositionDiff's type (SI5): at the bound valid, one above
            /// SL_E_CONFIG with the block held in STOP.
            #[test]
            fn limits_at_the_maximum_of_positiondiff() {
                assert_eq!(make::<$ty>(TS_MAX, TS_MAX, 0).1, SL_OK);
                for (pos, neg) in [(TS_MAX + 1, 0), (0, TS_MAX + 1), (u32::MAX, u32::MAX)] {
                    let (mut fb, rc) = make::<$ty>(pos, neg, 0);
                    assert_eq!(rc, SL_E_CONFIG, "{pos} {neg}");
                    assert_eq!(call(&mut fb, 0, 1, MID, 1, 0), SL_E_CONFIG);
                    assert_eq!(outs(&fb).state, SL_STATE_STOP);
                }
                // The full window: any in-range difference shows in PositionDiff.
                let mut fb = latched(TS_MAX, TS_MAX, 0, 0.max(LO));
                let far = (0.max(LO) + TS_MAX as i128).min(HI);
                assert_eq!(call(&mut fb, 2, 1, far, 1, 0), SL_OK);
                assert_eq!(outs(&fb).diff, (far - 0.max(LO)) as i64);
            }

            /// ABI-2 §11.9 "bits 0, 8 must be set": anything else is SL_E_CONFIG.
            #[test]
            fn input_active_must_be_sli_and_position() {
                for active in [0u16, 0x0001, 0x0100, 0x0103, 0x0301, 0xFFFF] {
                    let mut fb = <$ty>::default();
                    fb.set("wInputActive", i64::from(active)).unwrap();
                    assert_eq!(fb.init(), SL_E_CONFIG, "{active:#x}");
                }
            }

            /// An invalid SLI byte reads FALSE (SAFE) and makes no edge (ABI-2 §12.7).
            #[test]
            fn invalid_sli_byte_reads_false() {
                let mut fb = latched(10, 10, 0, MID);
                assert_eq!(call(&mut fb, 2, 7, MID, 1, 0), SL_E_INVALID_BOOL);
                assert_eq!((outs(&fb).state, outs(&fb).active), (SL_STATE_SAFE, 0));
                assert_eq!(call(&mut fb, 3, 7, MID, 1, 0), SL_E_INVALID_BOOL);
                assert_eq!(outs(&fb).state, SL_STATE_SAFE);
                assert_eq!(call(&mut fb, 4, 1, MID + 1, 1, 0), SL_OK);
                assert_eq!((outs(&fb).state, outs(&fb).diff), (SL_STATE_RUN, 0));
            }

            /// Exact differences (no wrap) without OverflowAllowed: a jump from one end of
            /// the type to the other is a range error, never a small wrapped difference.
            #[test]
            fn no_wrap_without_overflow_allowed() {
                let mut fb = latched(TS_MAX, TS_MAX, 0, HI);
                assert_eq!(call(&mut fb, 2, 1, LO, 1, 0), SL_OK);
                assert_eq!((outs(&fb).state, outs(&fb).diag), (SL_STATE_ERROR, 1));
                let mut fb = latched(TS_MAX, TS_MAX, 0, LO);
                assert_eq!(call(&mut fb, 2, 1, HI, 1, 0), SL_OK);
                assert_eq!((outs(&fb).state, outs(&fb).diag), (SL_STATE_ERROR, 2));
            }

            /// ≥ 10,000 random sequences against the model; asserts the states reached.
            #[test]
            fn random_sequences_against_the_model() {
                let sli2: bool = $sli2;
                let mut rng = Rng(0x5111_0000 ^ (HI as u64) ^ (u64::from(sli2) << 40));
                let ts = (<$ts>::MIN as i128, <$ts>::MAX as i128);
                let mut reached = 0u32;
                let (mut below, mut above) = (0u32, 0u32);
                const SEQUENCES: u32 = 12_000;
                for _ in 0..SEQUENCES {
                    let lim = |rng: &mut Rng| -> u32 {
                        match rng.next() % 4 {
                            0 => (rng.next() % 4) as u32,
                            1 => (rng.next() % 200) as u32,
                            2 => TS_MAX,
                            _ => (rng.next() % (u64::from(TS_MAX) + 1)) as u32,
                        }
                    };
                    let (pos, neg) = (lim(&mut rng), lim(&mut rng));
                    let options = if sli2 { (rng.next() % 4) as u32 * 0x100 } else { 0 };
                    let (mut fb, rc) = make::<$ty>(pos, neg, options);
                    assert_eq!(rc, SL_OK);
                    let mut m = Model::new(LO, HI, ts, (pos, neg), options);
                    let mut p = value(&mut rng, LO, HI, &[MID, LO, HI, 0.max(LO)], 300);
                    for t in 0..16u32 {
                        let r = rng.next();
                        let run = r % 10 != 0;
                        let ack = r >> 4 & 3 == 0;
                        let sli = if r >> 8 & 127 == 0 { 2 } else { u8::from(r >> 16 & 3 != 0) };
                        let span = i128::from(pos.max(neg)) + 2;
                        p = value(&mut rng, LO, HI, &[p, m_latch(&m, p)], span);
                        let rc = call(&mut fb, t, sli, p, u8::from(run), u8::from(ack));
                        assert_eq!(rc, if sli > 1 { SL_E_INVALID_BOOL } else { SL_OK });
                        m.cycle(sli, p, run, ack);
                        assert_eq!(
                            outs(&fb),
                            m.outs(sli2, pattern),
                            "t {t}: sli {sli} p {p} run {run} ack {ack} limits {pos}/{neg} options {options:#x}"
                        );
                        reached |= 1 << m.state;
                        below += outs(&fb).below;
                        above += outs(&fb).above;
                    }
                }
                let mut want = vec![
                    SL_STATE_RUN,
                    SL_STATE_STOP,
                    SL_STATE_SAFE,
                    SL_STATE_ERROR,
                    SL_STATE_RESET,
                ];
                if sli2 {
                    want.push(SL_STATE_SLI2_EXCEEDED);
                    assert!(below > 500 && above > 500, "BelowMin {below}, AboveMax {above}");
                } else {
                    assert_eq!(reached & 1 << SL_STATE_SLI2_EXCEEDED, 0);
                }
                for s in want {
                    assert!(reached & 1 << s != 0, "state {s} never reached ({reached:#b})");
                }
            }

            /// The model's latch while running, else the current position (to aim the next
            /// position at the window's edges).
            fn m_latch(m: &Model, p: i128) -> i128 {
                m.latch_or(p)
            }
        }
    };
}

impl Model {
    /// LatchPosition while a window is open, else `p`.
    pub fn latch_or(&self, p: i128) -> i128 {
        match self.state {
            SL_STATE_RUN | SL_STATE_SLI2_EXCEEDED => self.latch,
            _ => p,
        }
    }
}

/// [`sli_tests!`] for the four integer variants INT, UINT, DINT, UDINT of one block (the
/// four structs in that order), `$sli2` as there.
macro_rules! sli_tests_all {
    ($int:ty, $uint:ty, $dint:ty, $udint:ty, $sli2:expr) => {
        sli_tests!(int, $int, i16, i16, $sli2);
        sli_tests!(uint, $uint, u16, i16, $sli2);
        sli_tests!(dint, $dint, i32, i32, $sli2);
        sli_tests!(udint, $udint, u32, i32, $sli2);
    };
}
