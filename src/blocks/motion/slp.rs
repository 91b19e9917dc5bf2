//! FB SLP (safely limited position) — manual §4.29; layout ABI-2 §11.14, rules ABI-2 §12.
//!
//! With SafePosValid TRUE the block compares the position with a lower and an upper limit,
//! each taken from its inputs (UL_Active / LL_Active, `wInputActive` bits 10/11 and
//! 12/13) or from the `…Fix` parameters. Multi-turn (default): the 64-bit values
//! MultiturnPos · 2³² + SingleturnPos; LL ≤ P ≤ UL → RUN (PositionInLimit), below → SAFE
//! with BelowMin, above → SAFE with AboveMax. `SL_OPT_SLP_SINGLETURN`: only the 32-bit
//! single-turn values; LL > UL is a window wrapping through 0; SAFE shows neither BelowMin
//! nor AboveMax. SafePosValid FALSE → START. Multi-turn LL > UL with a limit from an input
//! is the manual's ERROR (diag bit 0 + 0x40D0 or bit 1 + 0x40D1, remains while LL > UL);
//! from the parameters alone it is `SL_E_CONFIG` at latch time with the Text ID shown
//! (ABI-2 §12.8). Readings: docs/semantics.md PL1–PL6.

#![allow(non_camel_case_types)] // the ABI's names

use crate::base::block::BlockInfo;
use crate::base::block::Private;
use crate::base::bools;
use crate::base::envelope::Block;
use crate::base::header::{crc_words, param_crc, F_CFG_INVALID};
use crate::base::reason::rule;
use crate::base::reason::{when, Rule, RuleDef, Unit};
use crate::base::types::*;
use crate::blocks::analog::{diag_message, limit_outputs, magic, LIMIT_ABOVE, LIMIT_BELOW};

include!(concat!(env!("OUT_DIR"), "/abi/blocks/motion/slp.rs"));

const _: () = {
    use core::mem::{offset_of, size_of};
    assert!(offset_of!(FB_SLP, bRun) == 16 && offset_of!(FB_SLP, nSingleturnPos) == 24);
    assert!(offset_of!(FB_SLP, nMultiturnPosLL) == 44 && offset_of!(FB_SLP, dwOptions) == 64);
    assert!(offset_of!(FB_SLP, wInputActive) == 68 && offset_of!(FB_SLP, bError) == 72);
    assert!(offset_of!(FB_SLP, bAboveMax) == 75 && offset_of!(FB_SLP, nState) == 80);
    assert!(offset_of!(FB_SLP, nDiagTextId) == 84 && offset_of!(FB_SLP, dwDiagPar3) == 92);
    assert!(offset_of!(FB_SLP, stPrivate) == 96);
    assert!(size_of::<SL_SLP_PRIVATE>() == 64 && size_of::<FB_SLP>() == 160);
};

/// (diag bit, Text ID) of the two limit errors.
const MESSAGES: [(u16, u16); 2] = [
    (
        SL_DIAG_SLP_MULTITURN_LL_ABOVE_UL,
        SL_TEXT_SLP_MULTITURN_LL_ABOVE_UL,
    ),
    (
        SL_DIAG_SLP_SINGLETURN_LL_ABOVE_UL,
        SL_TEXT_SLP_SINGLETURN_LL_ABOVE_UL,
    ),
];

/// Type tag, name, states and diag texts (manual §4.29.2.3).
const INFO: BlockInfo = BlockInfo::of::<SlpState>(SL_TYPE_SLP, "SLP").diag(&[
    (
        SL_DIAG_SLP_MULTITURN_LL_ABOVE_UL,
        "MultiturnPos_LL>MultiturnPos_UL",
    ),
    (
        SL_DIAG_SLP_SINGLETURN_LL_ABOVE_UL,
        "MultiturnPos_LL=MultiturnPos_UL AND SingleturnPosLL>SingleturnPos_UL",
    ),
]);

crate::impl_member!([] FB_SLP {
    info: INFO,
    state: SlpState,
    private: SL_SLP_PRIVATE,
    input: [bSafePosValid, nSingleturnPos, nMultiturnPos, nSingleturnPosUL, nMultiturnPosUL,
        nSingleturnPosLL, nMultiturnPosLL],
    param: [nSingleturnPosULFix, nMultiturnPosULFix, nSingleturnPosLLFix, nMultiturnPosLLFix,
        dwOptions, wInputActive],
    output: [bError, bPositionInLimit, bBelowMin, bAboveMax],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

/// Parameters as the user wrote them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SlpParams {
    active: u16,
    options: u32,
    fix: [u32; 4],
}

/// A position or limit: its multi-turn and single-turn parts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Turns {
    multi: i32,
    single: u32,
}

impl Turns {
    /// "The complete 64 bits": MultiturnPos · 2³² + SingleturnPos.
    fn full(self) -> i64 {
        (i64::from(self.multi) << 32) | i64::from(self.single)
    }
}

/// One cycle's inputs: validity, position and the effective limits.
#[derive(Clone, Copy, Debug)]
pub struct SlpIn {
    valid: bool,
    pos: Turns,
    lower: Turns,
    upper: Turns,
}

/// Index of the limits in `adwFix`.
const UL: usize = 0;
const LL: usize = 2;

/// The multi-turn limit error of `lower` > `upper`: (diag bit, Par2, Par3), or `None`.
fn limit_error(lower: Turns, upper: Turns) -> Option<(u16, [u32; 2])> {
    if lower.multi > upper.multi {
        Some((
            SL_DIAG_SLP_MULTITURN_LL_ABOVE_UL,
            [lower.multi as u32, upper.multi as u32],
        ))
    } else if lower.multi == upper.multi && lower.single > upper.single {
        Some((
            SL_DIAG_SLP_SINGLETURN_LL_ABOVE_UL,
            [lower.single, upper.single],
        ))
    } else {
        None
    }
}

/// The limit stored at `at` in `fix`.
fn fixed(fix: &[u32; 4], at: usize) -> Turns {
    Turns {
        single: fix[at],
        multi: fix[at + 1] as i32,
    }
}

fn single_turn(options: u32) -> bool {
    options & SL_OPT_SLP_SINGLETURN != 0
}

/// The parameter-only limit error: multi-turn with both limits from the `…Fix` parameters
/// and LL > UL (ABI-2 §12.8).
fn config_error(p: &SlpParams) -> Option<(u16, [u32; 2])> {
    let from_inputs = SL_SLP_ACTIVE_SINGLETURNPOSUL | SL_SLP_ACTIVE_SINGLETURNPOSLL;
    if single_turn(p.options) || p.active & from_inputs != 0 {
        return None;
    }
    limit_error(fixed(&p.fix, LL), fixed(&p.fix, UL))
}

impl Block for FB_SLP {
    const MAGIC: u16 = magic(SL_TYPE_SLP);
    type Params = SlpParams;
    type In = SlpIn;

    #[inline(always)]
    fn live_params(&self) -> SlpParams {
        SlpParams {
            active: self.wInputActive,
            options: self.dwOptions,
            fix: [
                self.nSingleturnPosULFix,
                self.nMultiturnPosULFix as u32,
                self.nSingleturnPosLLFix,
                self.nMultiturnPosLLFix as u32,
            ],
        }
    }
    #[inline(always)]
    fn latched_params(&self) -> SlpParams {
        let p = self.private();
        SlpParams {
            active: p.wActive,
            options: p.dwOptions,
            fix: p.adwFix,
        }
    }
    /// SafePosValid and SingleturnPos active, MultiturnPos active in multi-turn, the two
    /// bits of each limit equal, no other bit or option (ABI-2 §10.5, §11.14); the
    /// parameter-only limit error with the manual's Text ID (semantics PL3).
    const RULES: &'static [RuleDef<SlpParams>] = &[
        rule!(no_bits_outside "wInputActive", |p| p.active, SL_SLP_ACTIVE_SAFEPOSVALID | 0x3F00),
        RuleDef::new("wInputActive", Rule::BitsSet, Unit::Hex, |p| {
            let required = SL_SLP_ACTIVE_SAFEPOSVALID
                | SL_SLP_ACTIVE_SINGLETURNPOS
                | if single_turn(p.options) {
                    0
                } else {
                    SL_SLP_ACTIVE_MULTITURNPOS
                };
            when(p.active & required != required, p.active, required)
        }),
        RuleDef::new("wInputActive", Rule::BothOrNeither, Unit::Hex, |p| {
            let m = SL_SLP_ACTIVE_SINGLETURNPOSUL | SL_SLP_ACTIVE_MULTITURNPOSUL;
            when(p.active & m != 0 && p.active & m != m, p.active, m)
        }),
        RuleDef::new("wInputActive", Rule::BothOrNeither, Unit::Hex, |p| {
            let m = SL_SLP_ACTIVE_SINGLETURNPOSLL | SL_SLP_ACTIVE_MULTITURNPOSLL;
            when(p.active & m != 0 && p.active & m != m, p.active, m)
        }),
        rule!(no_bits_outside "dwOptions", |p| p.options, SL_OPT_SLP_SINGLETURN),
        RuleDef::new(
            "nMultiturnPosLLFix",
            Rule::NotAbove("nMultiturnPosULFix"),
            Unit::Plain,
            |p| match config_error(p) {
                Some((SL_DIAG_SLP_MULTITURN_LL_ABOVE_UL, [lo, hi])) => {
                    when(true, lo as i32, hi as i32)
                }
                _ => None,
            },
        )
        .text_id(SL_TEXT_SLP_MULTITURN_LL_ABOVE_UL),
        RuleDef::new(
            "nSingleturnPosLLFix",
            Rule::NotAbove("nSingleturnPosULFix"),
            Unit::Plain,
            |p| match config_error(p) {
                Some((SL_DIAG_SLP_SINGLETURN_LL_ABOVE_UL, [lo, hi])) => when(true, lo, hi),
                _ => None,
            },
        )
        .text_id(SL_TEXT_SLP_SINGLETURN_LL_ABOVE_UL),
    ];
    fn store_params(&mut self, p: &SlpParams) {
        let q = self.private_mut();
        q.wActive = p.active;
        q.dwOptions = p.options;
        q.adwFix = p.fix;
    }
    fn latched_crc(&self) -> u16 {
        let p = self.private();
        let [a, b, c, d] = p.adwFix;
        param_crc(
            Self::MAGIC,
            0,
            0,
            0,
            &crc_words![u16 p.wActive, u32 p.dwOptions, u32 a, u32 b, u32 c, u32 d],
        )
    }
    /// An invalid SafePosValid byte reads FALSE (START).
    #[inline(always)]
    fn decode(&mut self) -> (SlpIn, bool) {
        let p = self.private();
        let raw = bools::pack([self.bSafePosValid]);
        let pick = |bit: u16, multi: i32, single: u32, at: usize| {
            if p.wActive & bit != 0 {
                Turns { multi, single }
            } else {
                fixed(&p.adwFix, at)
            }
        };
        (
            SlpIn {
                valid: raw.ones & 1 != 0,
                pos: Turns {
                    multi: self.nMultiturnPos,
                    single: self.nSingleturnPos,
                },
                lower: pick(
                    SL_SLP_ACTIVE_SINGLETURNPOSLL,
                    self.nMultiturnPosLL,
                    self.nSingleturnPosLL,
                    LL,
                ),
                upper: pick(
                    SL_SLP_ACTIVE_SINGLETURNPOSUL,
                    self.nMultiturnPosUL,
                    self.nSingleturnPosUL,
                    UL,
                ),
            },
            raw.invalid != 0,
        )
    }
    fn start(&mut self, inp: &SlpIn, now: u32) {
        self.step(inp, now);
    }
    /// The limit error first (it concerns the limits, whatever the position's validity),
    /// then START, RUN or SAFE (semantics PL1, PL2, PL4).
    #[inline(always)]
    fn step(&mut self, inp: &SlpIn, _now: u32) -> Status {
        let single = single_turn(self.private().dwOptions);
        if let Some((bit, par)) = self.live_limit_error(inp) {
            let p = self.private_mut();
            p.adwPar = par;
            p.stHeader.enter_error(bit);
            return Status::Ok;
        }
        let (state, aux) = match (inp.valid, single) {
            (false, _) => (SL_STATE_START, 0),
            (true, true) => {
                let (s, lo, hi) = (inp.pos.single, inp.lower.single, inp.upper.single);
                let in_limit = if lo <= hi {
                    lo <= s && s <= hi
                } else {
                    s >= lo || s <= hi
                };
                (
                    if in_limit {
                        SL_STATE_RUN
                    } else {
                        SL_STATE_SAFE
                    },
                    0,
                )
            }
            (true, false) => {
                let (v, lo, hi) = (inp.pos.full(), inp.lower.full(), inp.upper.full());
                if v < lo {
                    (SL_STATE_SAFE, LIMIT_BELOW)
                } else if v > hi {
                    (SL_STATE_SAFE, LIMIT_ABOVE)
                } else {
                    (SL_STATE_RUN, 0)
                }
            }
        };
        // PositionInLimit switching on is where the latched parameters are verified (C3).
        if self.corrupt_entering_run(state == SL_STATE_RUN) {
            return Status::Corrupt;
        }
        let h = &mut self.private_mut().stHeader;
        h.nState = state;
        h.wAux = aux;
        Status::Ok
    }
    /// The limits still cross (ABI-2 §12.5).
    fn error_remains(&mut self, inp: &SlpIn) -> bool {
        self.live_limit_error(inp).is_some()
    }
    #[inline(always)]
    fn write_outputs(&mut self) {
        let p = *self.private();
        let h = p.stHeader;
        [
            self.bError,
            self.bPositionInLimit,
            self.bBelowMin,
            self.bAboveMax,
        ] = limit_outputs(&h);
        self.nState = h.nState;
        self.nDiag = h.wDiag;
        // A refused configuration names its limit error (semantics PL3).
        let refused = h.nState == SL_STATE_STOP && h.flag(F_CFG_INVALID);
        let config = if refused {
            config_error(&self.latched_params())
        } else {
            None
        };
        (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) = match config {
            Some((bit, [lo, hi])) => {
                let text = MESSAGES.iter().find(|(b, _)| *b == bit).map_or(0, |m| m.1);
                // The diag bit of the same message, as in ERROR (semantics C15).
                self.nDiag = h.wDiag | bit;
                (text, lo, hi)
            }
            None => diag_message(&h, &MESSAGES, p.adwPar),
        };
    }
}

impl FB_SLP {
    /// The limit error of this cycle's limits: multi-turn only (ERROR "When in multi-turn
    /// mode"), with at least one limit from the inputs (LL_Active or UL_Active).
    fn live_limit_error(&self, inp: &SlpIn) -> Option<(u16, [u32; 2])> {
        let p = self.private();
        let from_inputs = SL_SLP_ACTIVE_SINGLETURNPOSUL | SL_SLP_ACTIVE_SINGLETURNPOSLL;
        if single_turn(p.dwOptions) || p.wActive & from_inputs == 0 {
            return None;
        }
        limit_error(inp.lower, inp.upper)
    }
}
