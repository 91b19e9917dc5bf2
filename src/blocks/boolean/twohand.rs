//! FB TWOHAND — manual §4.7 (functional description 4.7.1, signals, diag bits and states
//! 4.7.2, configuration 4.7.3).
//!
//! Two-hand control: input group 1 (TwoHand1/2) and input group 2 (TwoHand3/4), each a
//! single-channel input, a two-channel input, or a two-channel input with discrepancy
//! monitoring (`tDiscTime12`, `tDiscTime34`, shared pair monitor). The output is set only
//! when both groups are actuated together, starting from SAFE through 1BUTTON or 2BUTTON, and
//! is set again only after every active input was released (RELEASE → SAFE). With
//! `tDiscTimePairs` ≠ 0 the second group must follow the first within that time.
//! Readings of the manual: docs/semantics.md rows H1–H14.

use crate::base::block::{BlockInfo, Private};
use crate::base::bools;
use crate::base::envelope::Block;
use crate::base::header::{param_crc, SL_PRIVATE_HEADER};
use crate::base::reason::rule;
use crate::base::reason::{when, Rule, RuleDef, Unit};
use crate::base::types::*;
use crate::base::{pair, time};

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/twohand.rs"));

/// Type tag, name, states and diag texts (manual §4.7.2).
const INFO: BlockInfo = BlockInfo::of::<TwohandState>(SL_TYPE_TWOHAND, "TWOHAND").diag(&[
    (SL_DIAG_DISC1, "discrepancy error input pair 1"),
    (SL_DIAG_DISC2, "discrepancy error input pair 2"),
    (
        SL_DIAG_TWOHAND_PAIRS,
        "discrepancy error between the two input pairs",
    ),
    (
        SL_DIAG_TWOHAND_ERROR,
        "two-hand error: second input pair actuated, first no longer actuated",
    ),
    (
        SL_DIAG_SAFE_IN_DISC1,
        "pair 1 with Safe Inputs after Disc Error",
    ),
    (
        SL_DIAG_SAFE_IN_DISC2,
        "pair 2 with Safe Inputs after Disc Error",
    ),
    (
        SL_DIAG_TWOHAND_SAFE_IN_PAIRS,
        "between the pairs with Safe Inputs after Disc Error",
    ),
]);

crate::impl_member!([] FB_TWOHAND {
    info: INFO,
    state: TwohandState,
    private: SL_TWOHAND_PRIVATE,
    input: [bTwoHand1, bTwoHand2, bTwoHand3, bTwoHand4],
    param: [tDiscTime12, tDiscTime34, tDiscTimePairs, wInputActive, wInputNegated, dwOptions],
    output: [bError, bTwoHandOut],
    info_fields: [],
});

const T_DISC12: usize = 0;
const T_DISC34: usize = 1;
const T_PAIRS: usize = 2;
/// Input bits of group 1 and group 2.
const GROUP1: u8 = 0b0011;
const GROUP2: u8 = 0b1100;
/// wAux bits 0-1: pair timers running.
const AUX_PAIR_TIMERS: u16 = 0b11;
/// wAux bits 4-5: both channels of pair k requested the safe state together since the error.
const AUX_SAFE_SHIFT: u32 = 4;
/// wAux bit 6: every active input was released together since an error between the pairs.
const AUX_RELEASED: u16 = 1 << 6;
/// Options FB_TWOHAND accepts.
const OPTIONS: u32 = SL_OPT_SAFE_INPUTS_AFTER_DISC;

/// FB_TWOHAND parameters as the user wrote them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TwohandParams {
    pub disc: [u32; 2],
    pub pairs: u32,
    pub active: u16,
    pub negated: u16,
    pub options: u32,
}

/// Decoded inputs of one cycle.
#[derive(Clone, Copy, Debug, Default)]
pub struct TwohandIn {
    /// Logical values of the active inputs (an invalid byte reads FALSE).
    pub logical: u8,
    /// Active inputs whose byte is an invalid BOOL.
    pub invalid: u8,
    /// Every active input of group 1 is logically TRUE (the group is actuated).
    pub g1: bool,
    /// Every active input of group 2 is logically TRUE.
    pub g2: bool,
    /// Every active input is valid and logically FALSE (both groups released, H6).
    pub released: bool,
}

impl FB_TWOHAND {
    fn inputs(&self) -> [u8; 4] {
        [
            self.bTwoHand1,
            self.bTwoHand2,
            self.bTwoHand3,
            self.bTwoHand4,
        ]
    }

    fn safe_inputs_option(&self) -> bool {
        u32::from(self.stPrivate.stHeader.wOptions) & SL_OPT_SAFE_INPUTS_AFTER_DISC != 0
    }
}

/// Diag bits `d` with their "Safe Inputs after Disc Error" companions (bit + 8) when the
/// option is on (manual §4.7.2: "set in addition to bit 0/1/2").
#[inline]
fn with_safe_bits(d: u16, safe_inputs: bool) -> u16 {
    if safe_inputs {
        d | (d << 8)
    } else {
        d
    }
}

/// CRC of the latched parameters (header masks and the times).
fn twohand_crc(h: &SL_PRIVATE_HEADER, times: &[u16]) -> u16 {
    param_crc(
        <FB_TWOHAND as Block>::MAGIC,
        h.nActive,
        h.nNegated,
        h.wOptions,
        times,
    )
}

/// The output switches on: verify the latched parameters first (C3).
fn enable(h: &mut SL_PRIVATE_HEADER, times: &[u16]) -> Status {
    if twohand_crc(h, times) != h.wParamCrc {
        h.enter_error(SL_DIAG_CORRUPT);
        return Status::Corrupt;
    }
    h.nState = SL_STATE_RUN;
    Status::Ok
}

impl Block for FB_TWOHAND {
    const MAGIC: u16 = 0x2A4D;
    type Params = TwohandParams;
    type In = TwohandIn;

    fn live_params(&self) -> TwohandParams {
        TwohandParams {
            disc: [self.tDiscTime12, self.tDiscTime34],
            pairs: self.tDiscTimePairs,
            active: self.wInputActive,
            negated: self.wInputNegated,
            options: self.dwOptions,
        }
    }

    fn latched_params(&self) -> TwohandParams {
        let p = &self.stPrivate;
        let t = |i: usize| p.awTime.get(i).map_or(0, |&v| u32::from(v));
        TwohandParams {
            disc: [t(T_DISC12), t(T_DISC34)],
            pairs: t(T_PAIRS),
            active: u16::from(p.stHeader.nActive),
            negated: u16::from(p.stHeader.nNegated),
            options: u32::from(p.stHeader.wOptions),
        }
    }

    /// Each group needs an active input (a two-hand control has two groups, H2); a
    /// discrepancy time needs both inputs of its pair active (C6); the window is at most
    /// 2500 ms (§4.7.1).
    const RULES: &'static [RuleDef<TwohandParams>] = &[
        rule!(at_most "tDiscTime12" in Ms, |p| p.disc[0], SL_TIME_PARAM_MAX),
        rule!(at_most "tDiscTime34" in Ms, |p| p.disc[1], SL_TIME_PARAM_MAX),
        rule!(at_most "tDiscTimePairs" in Ms, |p| p.pairs, SL_TWOHAND_PAIRS_TIME_MAX),
        rule!(no_bits_outside "wInputActive", |p| p.active, 0x0F),
        rule!(no_bits_outside "wInputNegated", |p| p.negated, 0x0F),
        rule!(no_bits_outside "dwOptions", |p| p.options, OPTIONS),
        RuleDef::new("tDiscTime12", Rule::Needs("wInputActive"), Unit::Ms, |p| {
            let g = u16::from(GROUP1);
            when(p.disc[0] != 0 && p.active & g != g, p.disc[0], g)
        }),
        RuleDef::new("tDiscTime34", Rule::Needs("wInputActive"), Unit::Ms, |p| {
            let g = u16::from(GROUP2);
            when(p.disc[1] != 0 && p.active & g != g, p.disc[1], g)
        }),
        RuleDef::new("wInputActive", Rule::AnyBitOf, Unit::Hex, |p| {
            // One input of each group (a bit of 0x0003 and one of 0x000C).
            let g1 = u16::from(GROUP1);
            let g2 = u16::from(GROUP2);
            let missing = if p.active & g1 == 0 { g1 } else { g2 };
            when(p.active & g1 == 0 || p.active & g2 == 0, p.active, missing)
        }),
    ];

    fn store_params(&mut self, p: &TwohandParams) {
        let q = &mut self.stPrivate;
        // Exact for valid parameters; an invalid set is stored truncated and never runs.
        q.awTime = [p.disc[0] as u16, p.disc[1] as u16, p.pairs as u16, 0];
        q.stHeader.nActive = p.active as u8;
        q.stHeader.nNegated = p.negated as u8;
        q.stHeader.wOptions = p.options as u16;
    }

    fn latched_crc(&self) -> u16 {
        twohand_crc(&self.stPrivate.stHeader, &self.stPrivate.awTime)
    }

    fn decode(&mut self) -> (TwohandIn, bool) {
        let packed = bools::pack(self.inputs());
        let h = &self.stPrivate.stHeader;
        let active = h.nActive;
        let logical = bools::logical(packed, active, h.nNegated);
        let invalid = packed.invalid & active;
        let actuated = |g: u8| {
            let a = active & g;
            a != 0 && logical & a == a
        };
        let inp = TwohandIn {
            logical,
            invalid,
            g1: actuated(GROUP1),
            g2: actuated(GROUP2),
            released: (logical | invalid) & active == 0,
        };
        (inp, invalid != 0)
    }

    /// STOP → run and RESET → run: SAFE when every active input is released, else RELEASE
    /// (a button held through start-up must be let go first, H5).
    fn start(&mut self, inp: &TwohandIn, now: u32) {
        let h = &mut self.stPrivate.stHeader;
        h.wAux = 0;
        h.tPhase = now;
        h.nState = if inp.released {
            SL_STATE_SAFE
        } else {
            SL_STATE_TWOHAND_RELEASE
        };
    }

    fn step(&mut self, inp: &TwohandIn, now: u32) -> Status {
        let safe_inputs = self.safe_inputs_option();
        let p = &mut self.stPrivate;

        // Discrepancy monitoring of the two-channel groups runs in every running state (H7).
        let monitored =
            u8::from(p.awTime[T_DISC12] != 0) | (u8::from(p.awTime[T_DISC34] != 0) << 1);
        let mut running = (p.stHeader.wAux & AUX_PAIR_TIMERS) as u8;
        let disc = pair::monitor(
            inp.logical,
            monitored,
            &mut running,
            &mut p.atDiscStart,
            &p.awTime[..2],
            now,
        );
        let window = u32::from(p.awTime[T_PAIRS]);
        let times = p.awTime;
        let h = &mut p.stHeader;
        h.wAux = (h.wAux & !AUX_PAIR_TIMERS) | u16::from(running);
        if disc != 0 {
            h.enter_error(with_safe_bits(u16::from(disc), safe_inputs));
            return Status::Ok;
        }

        let state = h.nState;
        let next = match state {
            // §4.7.2 SAFE: "If all active inputs of an input group are TRUE, the FB TWOHAND
            // module leaves the SAFE state" (both at once: 1BUTTON first, H8).
            SL_STATE_SAFE => {
                if inp.g1 || inp.g2 {
                    h.tPhase = now;
                }
                if inp.g1 {
                    SL_STATE_TWOHAND_1BUTTON
                } else if inp.g2 {
                    SL_STATE_TWOHAND_2BUTTON
                } else {
                    SL_STATE_SAFE
                }
            }
            SL_STATE_TWOHAND_1BUTTON | SL_STATE_TWOHAND_2BUTTON => {
                let (first, second) = if state == SL_STATE_TWOHAND_1BUTTON {
                    (inp.g1, inp.g2)
                } else {
                    (inp.g2, inp.g1)
                };
                if second && first {
                    // RUN only from 1BUTTON/2BUTTON, with both groups actuated.
                    return enable(h, &times);
                } else if second {
                    // Diag bit 6: the second group came while the first was let go (H10).
                    h.enter_error(SL_DIAG_TWOHAND_ERROR);
                    return Status::Ok;
                } else if !first {
                    // The first group was let go before the second came: start over (H9).
                    if inp.released {
                        SL_STATE_SAFE
                    } else {
                        SL_STATE_TWOHAND_RELEASE
                    }
                } else if window != 0 && time::reached(now, h.tPhase, window) {
                    // Diag bit 2: the second group did not follow within tDiscTimePairs (H11).
                    h.enter_error(with_safe_bits(SL_DIAG_TWOHAND_PAIRS, safe_inputs));
                    return Status::Ok;
                } else {
                    state
                }
            }
            // §4.7.2 RUN "if all active inputs are TRUE"; RELEASE "If at least one active
            // input is FALSE" (H12).
            SL_STATE_RUN => {
                if inp.g1 && inp.g2 {
                    SL_STATE_RUN
                } else {
                    SL_STATE_TWOHAND_RELEASE
                }
            }
            // RELEASE: "If all active inputs are FALSE, the FB TWOHAND module leaves the
            // RELEASE state" — the re-trigger rule of §4.7.1.
            SL_STATE_TWOHAND_RELEASE => {
                if inp.released {
                    SL_STATE_SAFE
                } else {
                    SL_STATE_TWOHAND_RELEASE
                }
            }
            _ => {
                // A state value this block never takes: the private state cannot be trusted.
                h.enter_error(SL_DIAG_CORRUPT);
                return Status::Corrupt;
            }
        };
        h.nState = next;
        Status::Ok
    }

    /// H13: a failed pair must agree now with valid bytes; with "Safe Inputs after Disc
    /// Error" its two channels must also have requested the safe state together since the
    /// error (bits 8/9), and for the error between the pairs every active input must have
    /// been released together (bit 10). Errors 2 and 6 leave nothing that remains otherwise.
    fn error_remains(&mut self, inp: &TwohandIn) -> bool {
        let h = &mut self.stPrivate.stHeader;
        let failed = (h.wDiag & (SL_DIAG_DISC1 | SL_DIAG_DISC2)) as u8;
        let need_safe = (h.wDiag >> 8) as u8 & 0b11;
        // An invalid byte is not a safe-state request for this purpose.
        let safe_view = inp.logical | inp.invalid;
        let latched = (((h.wAux >> AUX_SAFE_SHIFT) as u8 & 0b11)
            | (pair::both_safe(safe_view) & need_safe))
            & need_safe;
        let need_released = h.wDiag & SL_DIAG_TWOHAND_SAFE_IN_PAIRS != 0;
        let released = need_released && (h.wAux & AUX_RELEASED != 0 || inp.released);
        h.wAux = (h.wAux & !(0b11 << AUX_SAFE_SHIFT) & !AUX_RELEASED)
            | (u16::from(latched) << AUX_SAFE_SHIFT)
            | if released { AUX_RELEASED } else { 0 };
        // A pair with an invalid byte cannot be shown to agree.
        let pair_invalid = !pair::both_safe(inp.invalid) & 0b11;
        let pair_bad = pair::differing(inp.logical) | pair_invalid;
        failed & pair_bad != 0 || need_safe & !latched != 0 || (need_released && !released)
    }

    crate::base::envelope::steady_hooks!();

    fn write_outputs(&mut self) {
        let h = self.stPrivate.stHeader;
        self.bError = u8::from(h.nState == SL_STATE_ERROR);
        self.bTwoHandOut = u8::from(h.nState == SL_STATE_RUN);
        self.nState = h.nState;
        self.nDiag = h.wDiag;
    }
}

/// The fast-path slot (`base::envelope`) in the private part's reserved word: the key
/// (gathered BOOL bytes) in bytes 0-1, its check word in bytes 2-3, little-endian. The
/// field keeps its name and size (ABI: the private part is opaque, its size is not).
impl crate::base::envelope::SteadyPrivate for SL_TWOHAND_PRIVATE {
    type Key = u16;
    #[inline(always)]
    fn head_mut(&mut self) -> &mut SL_PRIVATE_HEADER {
        &mut self.stHeader
    }
    #[inline(always)]
    fn slot(&self) -> [u16; 2] {
        let [a, b, c, d] = self.aReserved;
        [u16::from_le_bytes([a, b]), u16::from_le_bytes([c, d])]
    }
    #[inline(always)]
    fn set_slot(&mut self, slot: Option<[u16; 2]>) {
        let [key, check] = slot.unwrap_or_default();
        let [a, b] = key.to_le_bytes();
        let [c, d] = check.to_le_bytes();
        self.aReserved = [a, b, c, d];
    }
}

impl crate::base::envelope::Steady for FB_TWOHAND {
    /// The four buttons, bRun and bErrAck gathered into bits.
    #[inline(always)]
    fn steady_key(&self) -> Option<u16> {
        let [a, b, c, d] = self.inputs();
        bools::key([a, b, c, d, self.bRun, self.bErrAck])
    }
    /// No pair discrepancy timer runs and the window between the groups (1BUTTON,
    /// 2BUTTON) is not open: the outcome depends on the time only through the clock check.
    #[inline(always)]
    fn quiet(&self) -> bool {
        let h = &self.stPrivate.stHeader;
        h.wAux & AUX_PAIR_TIMERS == 0
            && !matches!(
                h.nState,
                SL_STATE_TWOHAND_1BUTTON | SL_STATE_TWOHAND_2BUTTON
            )
    }
}
