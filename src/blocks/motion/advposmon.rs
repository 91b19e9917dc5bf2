//! FB ADVPOSMON (advanced position monitoring, SIL 3 EnDat 3 jump monitoring) — manual
//! §4.31; layout ABI-2 §11.16, rules ABI-2 §12.
//!
//! The drive-side signals (SDFB_ERROR, POS_REF_OK, POS_CHECK_OK and the SAFEDRIVEFEEDBACK
//! instance in error) exist only inside the drive; the library takes them as link inputs
//! 18–21 and implements the block's state machine. SDFB_ERROR → ERROR (diag value = the
//! instance, message 0x38D1), remaining while SDFB_ERROR is TRUE. Enable FALSE → SAFE;
//! Enable TRUE → RUN with Active = POS_REF_OK ∧ POS_CHECK_OK, Wait = ¬POS_REF_OK,
//! OverRange = POS_REF_OK ∧ ¬POS_CHECK_OK. With Restart active (RESTART_ACTIVE), OverRange
//! in RUN → WAIT-FOR-RESTART (16), Restart TRUE → START, its falling edge → RUN (the
//! restart primitive). States RUN (1), STOP (2), SAFE (3), ERROR (4), RESET (5), START (6),
//! WAIT-FOR-RESTART (16). Readings: docs/semantics.md AP1–AP5.

#![allow(non_camel_case_types)] // the ABI's names

use crate::base::block::BlockInfo;
use crate::base::block::Private;
use crate::base::bools::{self, edge};
use crate::base::envelope::{params_map, Block};
use crate::base::header::{param_crc, F_RESTART_PREV};
use crate::base::reason::rule;
use crate::base::reason::{when, Rule, RuleDef, Unit};
use crate::base::restart::{self, Restart};
use crate::base::types::*;
use crate::blocks::analog::magic;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/motion/advposmon.rs"));

const _: () = {
    use core::mem::{offset_of, size_of};
    assert!(offset_of!(FB_ADVPOSMON, bRestart) == 8 && offset_of!(FB_ADVPOSMON, bRun) == 16);
    assert!(offset_of!(FB_ADVPOSMON, bSdfbError) == 18);
    assert!(offset_of!(FB_ADVPOSMON, nSdfbInstance) == 21);
    assert!(offset_of!(FB_ADVPOSMON, nChAPrimaryFeedback) == 24);
    assert!(offset_of!(FB_ADVPOSMON, wInputActive) == 32);
    assert!(offset_of!(FB_ADVPOSMON, bError) == 40 && offset_of!(FB_ADVPOSMON, bOverRange) == 43);
    assert!(offset_of!(FB_ADVPOSMON, nState) == 48 && offset_of!(FB_ADVPOSMON, nDiag) == 50);
    assert!(offset_of!(FB_ADVPOSMON, nDiagTextId) == 52);
    assert!(offset_of!(FB_ADVPOSMON, dwDiagPar3) == 60);
    assert!(offset_of!(FB_ADVPOSMON, stPrivate) == 64);
    assert!(size_of::<SL_ADVPOSMON_PRIVATE>() == 40 && size_of::<FB_ADVPOSMON>() == 104);
};

/// Type tag, name, states and diag values (manual §4.31.2.3 "FB Diag").
const INFO: BlockInfo = BlockInfo::of::<AdvPosMonState>(SL_TYPE_ADVPOSMON, "ADVPOSMON")
    .diag_values(&[
        (0, "No diagnostic information"),
        (
            1,
            "SAFEDRIVEFEEDBACK instance 1 has changed to the ERROR state",
        ),
        (
            2,
            "SAFEDRIVEFEEDBACK instance 2 has changed to the ERROR state",
        ),
        (
            3,
            "SAFEDRIVEFEEDBACK instance 3 has changed to the ERROR state",
        ),
        (
            4,
            "SAFEDRIVEFEEDBACK instance 4 has changed to the ERROR state",
        ),
    ]);

crate::impl_member!([] FB_ADVPOSMON {
    info: INFO,
    state: AdvPosMonState,
    private: SL_ADVPOSMON_PRIVATE,
    input: [bEnable, bRestart, bSdfbError, bPosRefOk, bPosCheckOk, nSdfbInstance],
    param: [nChAPrimaryFeedback, nChASecondaryFeedback, nChBPrimaryFeedback,
        nChBSecondaryFeedback, wInputActive],
    output: [bError, bActive, bWait, bOverRange],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

/// Parameters as the user wrote them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AdvPosMonParams {
    active: u16,
    feedback: [u16; 4],
}

/// One cycle's inputs after BOOL decoding.
#[derive(Clone, Copy, Debug)]
pub struct AdvPosMonIn {
    enable: bool,
    restart: bools::Edge,
    sdfb_error: bool,
    ref_ok: bool,
    check_ok: bool,
    instance: u8,
}

/// `wAux` bits: the RUN outputs, and ERROR entered by SDFB_ERROR (carries the message).
const ACTIVE: u16 = 1;
const WAIT: u16 = 2;
const OVER_RANGE: u16 = 4;
const SDFB: u16 = 8;

impl Block for FB_ADVPOSMON {
    const MAGIC: u16 = magic(SL_TYPE_ADVPOSMON);
    params_map!(AdvPosMonParams {
        active: wInputActive => wActive,
        feedback: [
            nChAPrimaryFeedback,
            nChASecondaryFeedback,
            nChBPrimaryFeedback,
            nChBSecondaryFeedback
        ] => awFeedback,
    });
    type In = AdvPosMonIn;

    /// Enable active, only bits 0 and 1, feedback instances 0-3 (ABI-2 §11.16, §12.9).
    const RULES: &'static [RuleDef<AdvPosMonParams>] = &[
        rule!(no_bits_outside "wInputActive", |p| p.active, SL_ADVPOSMON_ACTIVE_ENABLE | SL_ADVPOSMON_ACTIVE_RESTART),
        RuleDef::new("wInputActive", Rule::BitsSet, Unit::Hex, |p| {
            let need = SL_ADVPOSMON_ACTIVE_ENABLE;
            when(p.active & need == 0, p.active, need)
        }),
        RuleDef::new("nChAPrimaryFeedback", Rule::AtMost, Unit::Plain, |p| {
            const NAMES: [&str; 4] = [
                "nChAPrimaryFeedback",
                "nChASecondaryFeedback",
                "nChBPrimaryFeedback",
                "nChBSecondaryFeedback",
            ];
            let max = SL_ADVPOSMON_FEEDBACK_MAX;
            let k = p.feedback.iter().position(|&f| f > max)?;
            when(true, p.feedback[k], max).map(|h| h.in_field(NAMES[k]))
        }),
    ];
    fn latched_crc(&self) -> u16 {
        let p = self.private();
        let [a, b, c, d] = p.awFeedback;
        param_crc(Self::MAGIC, 0, 0, 0, &[p.wActive, a, b, c, d])
    }
    /// Enable, Restart, POS_REF_OK, POS_CHECK_OK: an invalid byte reads FALSE (Restart
    /// without an edge); SDFB_ERROR: an invalid byte reads TRUE (ABI-2 §12.7).
    #[inline(always)]
    fn decode(&mut self) -> (AdvPosMonIn, bool) {
        let raw = bools::pack([
            self.bEnable,
            self.bSdfbError,
            self.bPosRefOk,
            self.bPosCheckOk,
        ]);
        let restart_raw = self.bRestart;
        let instance = self.nSdfbInstance;
        let restart = edge(
            restart_raw,
            &mut self.private_mut().stHeader.nFlags,
            F_RESTART_PREV,
        );
        (
            AdvPosMonIn {
                enable: raw.ones & 1 != 0,
                restart,
                sdfb_error: (raw.ones | raw.invalid) & 2 != 0,
                ref_ok: raw.ones & 4 != 0,
                check_ok: raw.ones & 8 != 0,
                instance,
            },
            raw.invalid != 0 || restart_raw > 1,
        )
    }
    fn start(&mut self, inp: &AdvPosMonIn, now: u32) {
        self.step(inp, now);
    }
    #[inline(always)]
    fn step(&mut self, inp: &AdvPosMonIn, _now: u32) -> Status {
        let h = self.private().stHeader;
        if inp.sdfb_error {
            let h = &mut self.private_mut().stHeader;
            // Instances 1-4 name the feedback; any other value is not a diag value.
            h.enter_error(if (1..=4).contains(&inp.instance) {
                u16::from(inp.instance)
            } else {
                0
            });
            h.wAux = SDFB;
            return Status::Ok;
        }
        let restart_active = self.private().wActive & SL_ADVPOSMON_ACTIVE_RESTART != 0;
        let over_range = inp.ref_ok && !inp.check_ok;
        let waiting = SL_STATE_ADVPOSMON_WAIT_FOR_RESTART;
        let next = match (inp.enable, h.nState) {
            (false, _) => SL_STATE_SAFE,
            (true, s) if s == waiting || s == SL_STATE_START => {
                match restart::step(s == SL_STATE_START, inp.restart, false) {
                    Restart::Wait => waiting,
                    Restart::Start => SL_STATE_START,
                    Restart::Enable => SL_STATE_RUN,
                }
            }
            (true, _) => SL_STATE_RUN,
        };
        let next = if next == SL_STATE_RUN && over_range && restart_active {
            waiting
        } else {
            next
        };
        let aux = if next == SL_STATE_RUN {
            if !inp.ref_ok {
                WAIT
            } else if inp.check_ok {
                ACTIVE
            } else {
                OVER_RANGE
            }
        } else {
            0
        };
        // Active switching on is where the latched parameters are verified (C3).
        if self.corrupt_at_switch_on(aux == ACTIVE && h.wAux != ACTIVE) {
            return Status::Corrupt;
        }
        let h = &mut self.private_mut().stHeader;
        h.nState = next;
        h.wAux = aux;
        Status::Ok
    }
    /// SDFB_ERROR is still TRUE (ABI-2 §12.5).
    fn error_remains(&mut self, inp: &AdvPosMonIn) -> bool {
        inp.sdfb_error
    }
    #[inline(always)]
    fn write_outputs(&mut self) {
        let h = self.private().stHeader;
        let (error, aux) = match h.nState {
            SL_STATE_ERROR => (true, 0),
            SL_STATE_RUN => (false, h.wAux),
            SL_STATE_START | SL_STATE_ADVPOSMON_WAIT_FOR_RESTART => (false, OVER_RANGE),
            _ => (false, 0),
        };
        self.bError = u8::from(error);
        self.bActive = u8::from(aux == ACTIVE);
        self.bWait = u8::from(aux == WAIT);
        self.bOverRange = u8::from(aux == OVER_RANGE);
        self.nState = h.nState;
        self.nDiag = h.wDiag;
        self.nDiagTextId = if error && h.wAux == SDFB {
            SL_TEXT_ADVPOSMON_SDFB_ERROR
        } else {
            0
        };
        (self.dwDiagPar2, self.dwDiagPar3) = (0, 0);
    }
}
