//! FB SLP (manual §4.29, ABI-2 §11.14, §12; docs/semantics.md PL1–PL6): one test per
//! statement of the manual section, then random sequences (≥ 10,000) against a small model
//! of the block that assert what they reached.

mod common;

use common::{run_steps, state_names, Rng, CORE_STATES, CORE_STATE_NAMES};
use safelogic::*;

const VALID: u16 = SL_SLP_ACTIVE_SAFEPOSVALID;
const ST: u16 = SL_SLP_ACTIVE_SINGLETURNPOS;
const MT: u16 = SL_SLP_ACTIVE_MULTITURNPOS;
const UL_IN: u16 = SL_SLP_ACTIVE_SINGLETURNPOSUL | SL_SLP_ACTIVE_MULTITURNPOSUL;
const LL_IN: u16 = SL_SLP_ACTIVE_SINGLETURNPOSLL | SL_SLP_ACTIVE_MULTITURNPOSLL;
const BASE: u16 = VALID | ST | MT;

/// A limit or position as (multi-turn, single-turn).
type Pos = (i32, u32);

fn make(active: u16, options: u32, ll: Pos, ul: Pos) -> FB_SLP {
    let mut fb = FB_SLP {
        wInputActive: active,
        dwOptions: options,
        ..Default::default()
    };
    (fb.nMultiturnPosLLFix, fb.nSingleturnPosLLFix) = ll;
    (fb.nMultiturnPosULFix, fb.nSingleturnPosULFix) = ul;
    fb
}

fn set_pos(fb: &mut FB_SLP, valid: u8, p: Pos) {
    fb.bSafePosValid = valid;
    (fb.nMultiturnPos, fb.nSingleturnPos) = p;
}

fn set_limit_inputs(fb: &mut FB_SLP, ll: Pos, ul: Pos) {
    (fb.nMultiturnPosLL, fb.nSingleturnPosLL) = ll;
    (fb.nMultiturnPosUL, fb.nSingleturnPosUL) = ul;
}

/// (Error, PositionInLimit, BelowMin, AboveMax).
fn outs(fb: &FB_SLP) -> (u8, u8, u8, u8) {
    (fb.bError, fb.bPositionInLimit, fb.bBelowMin, fb.bAboveMax)
}

fn message(fb: &FB_SLP) -> (u16, u16, u32, u32) {
    (fb.nDiag, fb.nDiagTextId, fb.dwDiagPar2, fb.dwDiagPar3)
}

/// A block with fixed limits, started at position `p`.
fn running(options: u32, ll: Pos, ul: Pos, p: Pos) -> FB_SLP {
    let mut fb = make(BASE, options, ll, ul);
    assert_eq!(fb.init(), SL_OK);
    set_pos(&mut fb, 1, p);
    fb.bRun = 1;
    assert_eq!(fb.cycle(0), SL_OK);
    fb
}

/// §4.29.1.1 "SafePositionLowerLimit ≤ SafePosition ≤ SafePositionHigherLimit":
/// PositionInLimit 1 BelowMin 0 AboveMax 0 (RUN), both bounds inclusive.
#[test]
fn multiturn_within_the_limits_is_run_bounds_inclusive() {
    let (ll, ul) = ((-1, 100), (2, 5));
    for p in [ll, (-1, 101), (0, 0), (1, u32::MAX), (2, 4), ul] {
        let fb = running(0, ll, ul, p);
        assert_eq!(fb.nState, SL_STATE_RUN, "{p:?}");
        assert_eq!(outs(&fb), (0, 1, 0, 0), "{p:?}");
        assert_eq!(message(&fb), (0, 0, 0, 0));
    }
}

/// §4.29.1.1 "SafePosition < SafePositionLowerLimit": PositionInLimit 0 BelowMin 1 (SAFE);
/// the 64-bit comparison borrows across the turn boundary.
#[test]
fn multiturn_below_the_lower_limit_is_safe_below_min() {
    for (ll, p) in [
        ((0, 0), (-1, u32::MAX)),
        ((3, 7), (3, 6)),
        ((i32::MIN, 1), (i32::MIN, 0)),
    ] {
        let fb = running(0, ll, (i32::MAX, u32::MAX), p);
        assert_eq!(fb.nState, SL_STATE_SAFE, "{p:?}");
        assert_eq!(outs(&fb), (0, 0, 1, 0), "{p:?}");
    }
}

/// §4.29.1.1 "SafePosition > SafePositionHigherLimit": AboveMax 1 (SAFE); the carry from
/// the single-turn part counts.
#[test]
fn multiturn_above_the_upper_limit_is_safe_above_max() {
    for (ul, p) in [
        ((1, u32::MAX), (2, 0)),
        ((-2, 5), (-2, 6)),
        ((0, 0), (i32::MAX, 0)),
    ] {
        let fb = running(0, (i32::MIN, 0), ul, p);
        assert_eq!(fb.nState, SL_STATE_SAFE, "{p:?}");
        assert_eq!(outs(&fb), (0, 0, 0, 1), "{p:?}");
    }
}

/// Both directions are automatic: SAFE → RUN → SAFE with the position alone.
#[test]
fn multiturn_leaves_safe_automatically() {
    let mut fb = running(0, (0, 10), (0, 20), (0, 9));
    assert_eq!(outs(&fb), (0, 0, 1, 0));
    for (t, p, state, o) in [
        (1, (0, 10), SL_STATE_RUN, (0, 1, 0, 0)),
        (2, (0, 21), SL_STATE_SAFE, (0, 0, 0, 1)),
        (3, (0, 20), SL_STATE_RUN, (0, 1, 0, 0)),
    ] {
        set_pos(&mut fb, 1, p);
        assert_eq!(fb.cycle(t), SL_OK);
        assert_eq!((fb.nState, outs(&fb)), (state, o));
    }
}

/// START "If the input SafePosValid=FALSE, the FB SLP module switches to the START state",
/// outputs 0; an invalid byte reads FALSE (SL_E_INVALID_BOOL).
#[test]
fn an_invalid_position_is_start() {
    let mut fb = running(0, (0, 0), (0, 10), (0, 5));
    assert_eq!(fb.nState, SL_STATE_RUN);
    let start = Some((SL_STATE_START, (0, 0, 0, 0)));
    let all = |f: &FB_SLP| (f.nState, outs(f));
    #[rustfmt::skip]
    run_steps("invalid", &mut fb, all, &[
        (1, |f| set_pos(f, 0, (0, 5)), SL_OK, start, ""),
        (2, |f| set_pos(f, 1, (0, 5)), SL_OK, None, "RUN, below"),
    ]);
    assert_eq!(fb.nState, SL_STATE_RUN);
    #[rustfmt::skip]
    run_steps("invalid byte", &mut fb, all, &[
        (3, |f| set_pos(f, 2, (0, 5)), SL_E_INVALID_BOOL, start, ""),
        // Outside the limits too: START, not SAFE.
        (4, |f| set_pos(f, 0, (5, 5)), SL_OK, start, ""),
    ]);
}

/// STOP "If the input FbRun=FALSE": every output 0; a zeroed instance waits in STOP.
#[test]
fn run_false_is_stop() {
    let mut fb = running(0, (0, 0), (0, 10), (0, 11));
    assert_eq!(fb.nState, SL_STATE_SAFE);
    fb.bRun = 0;
    assert_eq!(fb.cycle(1), SL_OK);
    assert_eq!((fb.nState, outs(&fb)), (SL_STATE_STOP, (0, 0, 0, 0)));
    assert_eq!(FB_SLP::default().cycle(0), SL_E_CONFIG);
}

/// ERROR 0x40D0: multi-turn, UL_Active, MultiturnPos_LL > MultiturnPos_UL: Error 1, diag
/// bit 0, Par2 = MultiturnPos_LL, Par3 = MultiturnPos_UL; it remains while the limits
/// cross; RESET (outputs 0, message cleared) on ErrAck, then running again.
#[test]
fn live_multiturn_crossing_is_error_40d0_until_acknowledged() {
    let mut fb = make(BASE | UL_IN, 0, (-3, 0), (0, 0));
    assert_eq!(fb.init(), SL_OK);
    set_pos(&mut fb, 1, (-3, 5));
    set_limit_inputs(&mut fb, (0, 0), (-4, u32::MAX));
    fb.bRun = 1;
    assert_eq!(fb.cycle(0), SL_OK);
    assert_eq!((fb.nState, outs(&fb)), (SL_STATE_ERROR, (1, 0, 0, 0)));
    assert_eq!(message(&fb), (1, 0x40D0, (-3i32) as u32, (-4i32) as u32));
    #[rustfmt::skip]
    run_steps("crossing", &mut fb, |f| f.nState, &[
        // Still crossing: the acknowledgement is ignored.
        (1, |f| f.bErrAck = 1, SL_OK, Some(SL_STATE_ERROR), ""),
        (2, |f| f.bErrAck = 0, SL_OK, None, ""),
        (3, |f| set_limit_inputs(f, (0, 0), (-3, 5)), SL_OK, Some(SL_STATE_ERROR), "an error is left only through RESET"),
    ]);
    #[rustfmt::skip]
    run_steps("acknowledged", &mut fb, |f| (f.nState, outs(f), message(f)), &[
        (4, |f| f.bErrAck = 1, SL_OK, Some((SL_STATE_RESET, (0, 0, 0, 0), (0, 0, 0, 0))), "message cleared"),
    ]);
    #[rustfmt::skip]
    run_steps("running again", &mut fb, |f| (f.nState, outs(f)), &[
        (5, |f| f.bErrAck = 0, SL_OK, Some((SL_STATE_RUN, (0, 1, 0, 0))), ""),
    ]);
}

/// ERROR 0x40D1: multi-turn, LL_Active, equal multi-turn parts and SingleturnPos_LL >
/// SingleturnPos_UL: diag bit 1, Par2 = SingleturnPos_LL, Par3 = SingleturnPos_UL. Equal
/// limits are a valid one-point window.
#[test]
fn live_singleturn_crossing_is_error_40d1() {
    let mut fb = make(BASE | LL_IN, 0, (0, 0), (7, 100));
    assert_eq!(fb.init(), SL_OK);
    set_pos(&mut fb, 1, (7, 100));
    set_limit_inputs(&mut fb, (7, 100), (0, 0));
    fb.bRun = 1;
    assert_eq!(fb.cycle(0), SL_OK);
    assert_eq!((fb.nState, outs(&fb)), (SL_STATE_RUN, (0, 1, 0, 0)));
    set_limit_inputs(&mut fb, (7, 101), (0, 0));
    assert_eq!(fb.cycle(1), SL_OK);
    assert_eq!((fb.nState, outs(&fb)), (SL_STATE_ERROR, (1, 0, 0, 0)));
    assert_eq!(message(&fb), (2, 0x40D1, 101, 100));
    // The limit error is checked whatever SafePosValid says.
    let mut fb = make(BASE | LL_IN | UL_IN, 0, (0, 0), (0, 0));
    assert_eq!(fb.init(), SL_OK);
    set_pos(&mut fb, 0, (0, 0));
    set_limit_inputs(&mut fb, (i32::MIN, u32::MAX), (i32::MIN, 0));
    fb.bRun = 1;
    assert_eq!(fb.cycle(0), SL_OK);
    assert_eq!(message(&fb), (2, 0x40D1, u32::MAX, 0));
}

/// ABI-2 §12.8: crossing `…Fix` limits (multi-turn, neither limit from an input) are
/// SL_E_CONFIG at init and STOP → run, with the Text ID, its parameters and the diag bit
/// the same message has in ERROR shown in STOP (semantics C15).
#[test]
fn fixed_limits_crossing_are_config_with_the_text_id() {
    let mut fb = make(BASE, 0, (5, 0), (4, 9));
    assert_eq!(fb.init(), SL_E_CONFIG);
    assert_eq!(fb.nState, SL_STATE_STOP);
    assert_eq!(message(&fb), (1, 0x40D0, 5, 4));
    fb.bRun = 1;
    set_pos(&mut fb, 1, (4, 0));
    assert_eq!(fb.cycle(0), SL_E_CONFIG);
    assert_eq!((fb.nState, outs(&fb)), (SL_STATE_STOP, (0, 0, 0, 0)));
    let mut fb = make(BASE, 0, (-1, 10), (-1, 9));
    assert_eq!(fb.init(), SL_E_CONFIG);
    assert_eq!(message(&fb), (2, 0x40D1, 10, 9));
    // Equal is valid; single-turn mode wraps instead (PL4).
    assert_eq!(make(BASE, 0, (-1, 9), (-1, 9)).init(), SL_OK);
    assert_eq!(
        make(BASE, SL_OPT_SLP_SINGLETURN, (5, 10), (4, 9)).init(),
        SL_OK
    );
}

/// §4.29.1.2 single-turn, LowerLimit ≤ HigherLimit: InLimit → PositionInLimit 1; otherwise
/// 0 with BelowMin = AboveMax = 0 (SAFE). Only the lower 32 bits count.
#[test]
fn singleturn_window() {
    let opt = SL_OPT_SLP_SINGLETURN;
    for (s, run) in [(9, false), (10, true), (15, true), (20, true), (21, false)] {
        let fb = running(opt, (-100, 10), (-200, 20), (i32::MAX, s));
        let state = if run { SL_STATE_RUN } else { SL_STATE_SAFE };
        assert_eq!(
            (fb.nState, outs(&fb)),
            (state, (0, u8::from(run), 0, 0)),
            "{s}"
        );
    }
}

/// §4.29.1.2 LowerLimit > HigherLimit: the window wraps through 0 (InLimit ⇔ S ≥ LL ∨
/// S ≤ UL), and PositionInLimit = InLimit (the table's "If InLimit = FALSE:
/// PositionInLimit 1" read as a typo, PL4). Live limits crossing there are no error.
#[test]
fn singleturn_wrap_around_window() {
    let opt = SL_OPT_SLP_SINGLETURN;
    for (s, run) in [
        (0, true),
        (50, true),
        (51, false),
        (u32::MAX - 50, false),
        (u32::MAX - 49, true),
        (u32::MAX, true),
    ] {
        let fb = running(opt, (0, u32::MAX - 49), (0, 50), (0, s));
        let state = if run { SL_STATE_RUN } else { SL_STATE_SAFE };
        assert_eq!(
            (fb.nState, outs(&fb)),
            (state, (0, u8::from(run), 0, 0)),
            "{s}"
        );
    }
    let mut fb = make(VALID | ST | LL_IN | UL_IN, opt, (0, 0), (0, 0));
    assert_eq!(fb.init(), SL_OK);
    set_pos(&mut fb, 1, (0, 3));
    set_limit_inputs(&mut fb, (9, 100), (-9, 2));
    fb.bRun = 1;
    assert_eq!(fb.cycle(0), SL_OK);
    assert_eq!((fb.nState, outs(&fb)), (SL_STATE_SAFE, (0, 0, 0, 0)));
    set_pos(&mut fb, 1, (0, 2));
    assert_eq!(fb.cycle(1), SL_OK);
    assert_eq!(fb.nState, SL_STATE_RUN);
}

/// ABI-2 §11.14 active bits: 0 and 8 required, 9 required in multi-turn only, the two bits
/// of a limit equal, nothing else; options: only SL_OPT_SLP_SINGLETURN.
#[test]
fn active_bits_and_options_at_their_limits() {
    let ok = |a: u16, o: u32| make(a, o, (0, 0), (0, 0)).init();
    assert_eq!(ok(BASE, 0), SL_OK);
    assert_eq!(ok(BASE | UL_IN | LL_IN, 0), SL_OK);
    assert_eq!(ok(BASE & !VALID, 0), SL_E_CONFIG);
    assert_eq!(ok(BASE & !ST, 0), SL_E_CONFIG);
    assert_eq!(ok(BASE & !MT, 0), SL_E_CONFIG);
    assert_eq!(ok(VALID | ST, SL_OPT_SLP_SINGLETURN), SL_OK);
    assert_eq!(ok(BASE, SL_OPT_SLP_SINGLETURN), SL_OK);
    assert_eq!(ok(BASE | SL_SLP_ACTIVE_SINGLETURNPOSUL, 0), SL_E_CONFIG);
    assert_eq!(ok(BASE | SL_SLP_ACTIVE_MULTITURNPOSLL, 0), SL_E_CONFIG);
    for bit in [1, 2, 7, 14, 15] {
        assert_eq!(ok(BASE | 1 << bit, 0), SL_E_CONFIG, "bit {bit}");
    }
    for bit in (0..32).filter(|b| *b != 8) {
        assert_eq!(ok(BASE, 1 << bit), SL_E_CONFIG, "option bit {bit}");
    }
}

/// A parameter changed while running is SL_E_PARAM_CHANGED (ERROR, bit 13).
#[test]
fn a_changed_limit_while_running_is_param_changed() {
    let mut fb = running(0, (0, 0), (0, 10), (0, 5));
    fb.nSingleturnPosULFix = 11;
    assert_eq!(fb.cycle(1), SL_E_PARAM_CHANGED);
    assert_eq!(fb.nState, SL_STATE_ERROR);
    assert_eq!(fb.nDiag, SL_DIAG_PARAM_CHANGED);
    assert_eq!(fb.nDiagTextId, 0);
}

/// State names and diag texts of the registry.
#[test]
fn names_and_texts() {
    let t = registry::block_type(SL_TYPE_SLP).unwrap();
    let names = state_names(&t.info);
    assert_eq!(names[..5], CORE_STATE_NAMES);
    assert_eq!(names[5..], [(6, "START")]);
    let mut out = [0u8; 128];
    let n = base::diag::diag_text(&t.info, 2, &mut out);
    assert_eq!(
        std::str::from_utf8(&out[..n]).unwrap(),
        "MultiturnPos_LL=MultiturnPos_UL AND SingleturnPosLL>SingleturnPos_UL"
    );
}

/// The model: what the block shows after one call.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Shown {
    state: u8,
    outs: (u8, u8, u8, u8),
    message: (u16, u16, u32, u32),
}

struct Model {
    single: bool,
    ll_in: bool,
    ul_in: bool,
    state: u8,
    ack: bool,
    message: (u16, u16, u32, u32),
    aux: (u8, u8),
}

impl Model {
    fn crossing(&self, ll: Pos, ul: Pos) -> Option<(u16, u16, u32, u32)> {
        if self.single || !(self.ll_in || self.ul_in) {
            return None;
        }
        if ll.0 > ul.0 {
            Some((1, 0x40D0, ll.0 as u32, ul.0 as u32))
        } else if ll.0 == ul.0 && ll.1 > ul.1 {
            Some((2, 0x40D1, ll.1, ul.1))
        } else {
            None
        }
    }

    fn evaluate(&mut self, valid: bool, p: Pos, ll: Pos, ul: Pos) {
        if let Some(m) = self.crossing(ll, ul) {
            self.state = SL_STATE_ERROR;
            self.message = m;
            return;
        }
        let full = |x: Pos| (i128::from(x.0) << 32) + i128::from(x.1);
        (self.state, self.aux) = if !valid {
            (SL_STATE_START, (0, 0))
        } else if self.single {
            let inside = if ll.1 <= ul.1 {
                ll.1 <= p.1 && p.1 <= ul.1
            } else {
                p.1 >= ll.1 || p.1 <= ul.1
            };
            (if inside { SL_STATE_RUN } else { SL_STATE_SAFE }, (0, 0))
        } else if full(p) < full(ll) {
            (SL_STATE_SAFE, (1, 0))
        } else if full(p) > full(ul) {
            (SL_STATE_SAFE, (0, 1))
        } else {
            (SL_STATE_RUN, (0, 0))
        };
    }

    fn call(&mut self, run: bool, ack: bool, valid: bool, p: Pos, ll: Pos, ul: Pos) -> Shown {
        let (rise, fall) = (ack && !self.ack, !ack && self.ack);
        self.ack = ack;
        match self.state {
            SL_STATE_STOP => {
                if run {
                    self.evaluate(valid, p, ll, ul);
                }
            }
            SL_STATE_ERROR => {
                if rise && self.crossing(ll, ul).is_none() {
                    self.state = SL_STATE_RESET;
                    self.message = (0, 0, 0, 0);
                }
            }
            SL_STATE_RESET => {
                if fall {
                    if run {
                        self.evaluate(valid, p, ll, ul);
                    } else {
                        self.state = SL_STATE_STOP;
                    }
                }
            }
            _ => {
                if run {
                    self.evaluate(valid, p, ll, ul);
                } else {
                    self.state = SL_STATE_STOP;
                }
            }
        }
        let safe = self.state == SL_STATE_SAFE;
        Shown {
            state: self.state,
            outs: (
                u8::from(self.state == SL_STATE_ERROR),
                u8::from(self.state == SL_STATE_RUN),
                if safe { self.aux.0 } else { 0 },
                if safe { self.aux.1 } else { 0 },
            ),
            message: if self.state == SL_STATE_ERROR {
                self.message
            } else {
                (0, 0, 0, 0)
            },
        }
    }
}

/// A value near a few anchors so that equality and the turn boundaries are hit often.
fn pos(rng: &mut Rng) -> Pos {
    const M: [i32; 5] = [i32::MIN, -1, 0, 1, i32::MAX];
    const S: [u32; 5] = [0, 1, 0x8000_0000, u32::MAX - 1, u32::MAX];
    let r = rng.next();
    let m = M[(r % 5) as usize].wrapping_add((r >> 8) as i32 % 2);
    let s = S[((r >> 16) % 5) as usize].wrapping_add(((r >> 24) % 3) as u32);
    (m, s)
}

/// ≥ 10,000 random sequences against the model; every state is reached.
#[test]
fn random_sequences_match_the_model() {
    let mut rng = Rng(0x051F_C0DE);
    let (mut reached, mut texts) = (
        std::collections::BTreeSet::new(),
        std::collections::BTreeSet::new(),
    );
    let mut invalid_calls = 0u32;
    for seq in 0..12_000 {
        let single = seq % 3 == 0;
        let (ll_in, ul_in) = (rng.next() % 2 == 0, rng.next() % 2 == 0);
        let (mut fll, mut ful) = (pos(&mut rng), pos(&mut rng));
        if !single && !ll_in && !ul_in && (fll.0, fll.1) > (ful.0, ful.1) {
            std::mem::swap(&mut fll, &mut ful);
        }
        let active = VALID
            | ST
            | if single { 0 } else { MT }
            | if ll_in { LL_IN } else { 0 }
            | if ul_in { UL_IN } else { 0 };
        let options = if single { SL_OPT_SLP_SINGLETURN } else { 0 };
        let mut fb = make(active, options, fll, ful);
        assert_eq!(fb.init(), SL_OK);
        let mut model = Model {
            single,
            ll_in,
            ul_in,
            state: SL_STATE_STOP,
            ack: false,
            message: (0, 0, 0, 0),
            aux: (0, 0),
        };
        let (mut ill, mut iul) = (pos(&mut rng), pos(&mut rng));
        for step in 0..20u32 {
            let r = rng.next();
            let run = r % 16 != 0;
            let ack = (r >> 4) % 3 == 0;
            let valid = (r >> 8) % 6 != 0;
            let p = if (r >> 12) % 2 == 0 {
                pos(&mut rng)
            } else {
                [fll, ful, ill, iul][((r >> 13) % 4) as usize]
            };
            if (r >> 16) % 4 == 0 {
                ill = pos(&mut rng);
            }
            if (r >> 18) % 4 == 0 {
                iul = pos(&mut rng);
            }
            // One call in 25 has an invalid SafePosValid byte: it reads FALSE.
            let invalid = (r >> 40) % 25 == 0;
            let valid = valid && !invalid;
            set_pos(
                &mut fb,
                if invalid {
                    2 + (r >> 48) as u8 % 254
                } else {
                    u8::from(valid)
                },
                p,
            );
            set_limit_inputs(&mut fb, ill, iul);
            fb.bRun = u8::from(run);
            fb.bErrAck = u8::from(ack);
            let rc = if invalid { SL_E_INVALID_BOOL } else { SL_OK };
            assert_eq!(fb.cycle(step * 10), rc);
            invalid_calls += u32::from(invalid);
            let ll = if ll_in { ill } else { fll };
            let ul = if ul_in { iul } else { ful };
            let want = model.call(run, ack, valid, p, ll, ul);
            let got = Shown {
                state: fb.nState,
                outs: outs(&fb),
                message: message(&fb),
            };
            assert_eq!(got, want, "sequence {seq} step {step}");
            reached.insert(fb.nState);
            texts.insert(fb.nDiagTextId);
        }
    }
    for s in CORE_STATES.into_iter().chain([SL_STATE_START]) {
        assert!(reached.contains(&s), "never reached {s}: {reached:?}");
    }
    assert!(
        texts.contains(&0x40D0) && texts.contains(&0x40D1),
        "{texts:?}"
    );
    assert!(
        invalid_calls > 5_000,
        "{invalid_calls} calls with an invalid byte"
    );
}
