//! FB OPMODE — manual §4.3 (functional description 4.3.1, signals, states and diag bit 4.3.2,
//! configuration 4.3.3, restart behaviour and samples 1–2 4.3.4).
//!
//! An operating mode selector: eight inputs looped through one-to-one to eight outputs. The
//! output of the one active input that is TRUE is set; with none or more than one TRUE all
//! outputs are FALSE. With `SL_OPT_MANUAL_RESTART` ("Restart" activated) the outputs leave
//! the safe state at start-up and after every change of mode only through the restart
//! sequence. `tDiscTime` (≠ 0) limits how long no mode or more than one mode may be
//! selected (the change from one mode to the next); beyond it: ERROR, diag bit 0.
//! Readings of the manual: docs/semantics.md rows O1–O12.

use crate::base::block::BlockInfo;
use crate::base::bools::{self, Edge};
use crate::base::envelope::Block;
use crate::base::header::{param_crc, F_RESTART_PREV, SL_PRIVATE_HEADER};
use crate::base::reason::rule;
use crate::base::reason::{when, Rule, RuleDef, Unit};
use crate::base::restart::{self, Restart};
use crate::base::time;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/opmode.rs"));

/// Type tag, name, states and diag texts (manual §4.3.2).
const INFO: BlockInfo = BlockInfo::of::<OpmodeState>(SL_TYPE_OPMODE, "OPMODE")
    .diag(&[(SL_DIAG_OPMODE_DISC, "discrepancy monitoring error")]);

crate::impl_member!([] FB_OPMODE {
    info: INFO,
    state: OpmodeState,
    private: SL_OPMODE_PRIVATE,
    input: [bRestart, bOpIn1, bOpIn2, bOpIn3, bOpIn4, bOpIn5, bOpIn6, bOpIn7, bOpIn8],
    param: [tDiscTime, wInputActive, dwOptions],
    output: [bError, bOpOut1, bOpOut2, bOpOut3, bOpOut4, bOpOut5, bOpOut6, bOpOut7, bOpOut8],
    info_fields: [],
});

/// wAux bits 0-7: the latched mode.
const AUX_MODE: u16 = 0x00FF;
/// wAux bit 8: the mode-change timer runs.
const AUX_DISC_RUNNING: u16 = 1 << 8;
/// Options FB_OPMODE accepts.
const OPTIONS: u32 = SL_OPT_MANUAL_RESTART;

/// FB_OPMODE parameters as the user wrote them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OpmodeParams {
    pub disc: u32,
    pub active: u16,
    pub options: u32,
}

/// Decoded inputs of one cycle.
#[derive(Clone, Copy, Debug, Default)]
pub struct OpmodeIn {
    /// The selected mode as its input bit: the one active input that is TRUE. 0 when none
    /// or more than one active input is TRUE, or an active input byte is invalid (O5).
    pub mode: u8,
    pub restart: Edge,
}

impl FB_OPMODE {
    fn inputs(&self) -> [u8; 8] {
        [
            self.bOpIn1,
            self.bOpIn2,
            self.bOpIn3,
            self.bOpIn4,
            self.bOpIn5,
            self.bOpIn6,
            self.bOpIn7,
            self.bOpIn8,
        ]
    }

    fn manual_restart(&self) -> bool {
        u32::from(self.stPrivate.stHeader.wOptions) & SL_OPT_MANUAL_RESTART != 0
    }
}

/// CRC of the latched parameters (header masks and the discrepancy time).
fn opmode_crc(h: &SL_PRIVATE_HEADER, disc: u16) -> u16 {
    param_crc(
        <FB_OPMODE as Block>::MAGIC,
        h.nActive,
        h.nNegated,
        h.wOptions,
        &[disc],
    )
}

/// A mode output switches on: verify the latched parameters first (C3), then RUN with it.
fn enable(h: &mut SL_PRIVATE_HEADER, disc: u16, mode: u8) -> (u8, Status) {
    if opmode_crc(h, disc) != h.wParamCrc {
        h.enter_error(SL_DIAG_CORRUPT);
        return (SL_STATE_ERROR, Status::Corrupt);
    }
    h.wAux = (h.wAux & !AUX_MODE) | u16::from(mode);
    (SL_STATE_RUN, Status::Ok)
}

impl Block for FB_OPMODE {
    const MAGIC: u16 = 0x0D7E;
    type Params = OpmodeParams;
    type In = OpmodeIn;

    fn live_params(&self) -> OpmodeParams {
        OpmodeParams {
            disc: self.tDiscTime,
            active: self.wInputActive,
            options: self.dwOptions,
        }
    }

    fn latched_params(&self) -> OpmodeParams {
        let p = &self.stPrivate;
        OpmodeParams {
            disc: u32::from(p.wDiscTime),
            active: u16::from(p.stHeader.nActive),
            options: u32::from(p.stHeader.wOptions),
        }
    }

    /// Manual §4.3.1 "At least two inputs of FB OPMODE must be connected"; C6 strictness.
    const RULES: &'static [RuleDef<OpmodeParams>] = &[
        rule!(at_most "tDiscTime" in Ms, |p| p.disc, SL_TIME_PARAM_MAX),
        rule!(no_bits_outside "wInputActive", |p| p.active, 0xFF),
        RuleDef::new("wInputActive", Rule::MinBits, Unit::Hex, |p| {
            when(p.active.count_ones() < 2, p.active, 2)
        }),
        rule!(no_bits_outside "dwOptions", |p| p.options, OPTIONS),
    ];

    fn store_params(&mut self, p: &OpmodeParams) {
        let q = &mut self.stPrivate;
        // Exact for valid parameters; an invalid set is stored truncated and never runs.
        q.wDiscTime = p.disc as u16;
        q.stHeader.nActive = p.active as u8;
        q.stHeader.nNegated = 0;
        q.stHeader.wOptions = p.options as u16;
    }

    fn latched_crc(&self) -> u16 {
        opmode_crc(&self.stPrivate.stHeader, self.stPrivate.wDiscTime)
    }

    fn decode(&mut self) -> (OpmodeIn, bool) {
        let packed = bools::pack(self.inputs());
        let manual = self.manual_restart();
        let restart_raw = self.bRestart;
        let h = &mut self.stPrivate.stHeader;
        let active = h.nActive;
        let on = bools::logical(packed, active, 0);
        let bad = packed.invalid & active;
        // An invalid byte on an active input makes the whole selection untrustworthy: no
        // mode (O5). Only bytes the block reads count (C7): Restart only with the option.
        let mode = if bad == 0 && on.count_ones() == 1 {
            on
        } else {
            0
        };
        let restart = bools::edge(restart_raw, &mut h.nFlags, F_RESTART_PREV);
        let invalid = bad != 0 || (manual && restart_raw > 1);
        (OpmodeIn { mode, restart }, invalid)
    }

    /// STOP → run and RESET → run: SAFE with the timer stopped (O7); the next call decides.
    fn start(&mut self, _inp: &OpmodeIn, now: u32) {
        let h = &mut self.stPrivate.stHeader;
        h.wAux = 0;
        h.tPhase = now;
        h.nState = SL_STATE_SAFE;
    }

    fn step(&mut self, inp: &OpmodeIn, now: u32) -> Status {
        let manual = self.manual_restart();
        let p = &mut self.stPrivate;
        let disc = u32::from(p.wDiscTime);
        let h = &mut p.stHeader;
        let state = h.nState;
        let latched = (h.wAux & AUX_MODE) as u8;

        // RUN and START hold exactly one active mode bit; anything else is corruption.
        let latched_ok = latched.count_ones() == 1 && latched & !h.nActive == 0;
        if matches!(state, SL_STATE_RUN | SL_STATE_START) && !latched_ok {
            h.enter_error(SL_DIAG_CORRUPT);
            return Status::Corrupt;
        }

        // Mode-change monitoring (§4.3.1 "A discrepancy time can be specified to monitor the
        // change from one operation mode to the next"): no mode or more than one mode must not
        // last the full tDiscTime (O3).
        if disc != 0 && inp.mode == 0 {
            if h.wAux & AUX_DISC_RUNNING == 0 {
                h.wAux |= AUX_DISC_RUNNING;
                h.tPhase = now;
            } else if time::reached(now, h.tPhase, disc) {
                h.enter_error(SL_DIAG_OPMODE_DISC);
                return Status::Ok;
            }
        } else {
            h.wAux &= !AUX_DISC_RUNNING;
        }

        let mut status = Status::Ok;
        let (next, mode) = match state {
            SL_STATE_SAFE | SL_STATE_START if manual => {
                let in_start = state == SL_STATE_START;
                // In START the restart confirms the mode that was selected when START was
                // entered: another selection is a request for the safe state (O8).
                let request = inp.mode == 0 || (in_start && inp.mode != latched);
                match restart::step(in_start, inp.restart, request) {
                    Restart::Wait => (SL_STATE_SAFE, 0),
                    Restart::Start => (SL_STATE_START, inp.mode),
                    Restart::Enable => {
                        let (s, st) = enable(h, disc as u16, latched);
                        status = st;
                        (s, latched)
                    }
                }
            }
            SL_STATE_SAFE => {
                if inp.mode != 0 {
                    let (s, st) = enable(h, disc as u16, inp.mode);
                    status = st;
                    (s, inp.mode)
                } else {
                    (SL_STATE_SAFE, 0)
                }
            }
            SL_STATE_RUN => {
                if inp.mode == latched {
                    (SL_STATE_RUN, latched)
                } else if inp.mode != 0 && !manual {
                    // Automatic: OpOutX = OpInX, a direct change of mode switches over (O9).
                    let (s, st) = enable(h, disc as u16, inp.mode);
                    status = st;
                    (s, inp.mode)
                } else {
                    // No valid mode, or a change of mode that needs a restart (§4.3.1).
                    (SL_STATE_SAFE, 0)
                }
            }
            _ => {
                // A state value this block never takes (START without manual restart
                // included): the private state cannot be trusted.
                h.enter_error(SL_DIAG_CORRUPT);
                return Status::Corrupt;
            }
        };
        if h.nState != SL_STATE_ERROR {
            h.nState = next;
            h.wAux = (h.wAux & !AUX_MODE) | u16::from(mode);
        }
        status
    }

    /// A discrepancy error remains while no single valid mode is selected (O6).
    fn error_remains(&mut self, inp: &OpmodeIn) -> bool {
        self.stPrivate.stHeader.wDiag & SL_DIAG_OPMODE_DISC != 0 && inp.mode == 0
    }

    fn write_outputs(&mut self) {
        let h = self.stPrivate.stHeader;
        let mode = (h.wAux & AUX_MODE) as u8;
        // Only RUN drives an output, and only a single active mode bit (never two outputs).
        let out = if h.nState == SL_STATE_RUN && mode.count_ones() == 1 && mode & !h.nActive == 0 {
            mode
        } else {
            0
        };
        let bit = |n: u8| (out >> n) & 1;
        self.bError = u8::from(h.nState == SL_STATE_ERROR);
        self.bOpOut1 = bit(0);
        self.bOpOut2 = bit(1);
        self.bOpOut3 = bit(2);
        self.bOpOut4 = bit(3);
        self.bOpOut5 = bit(4);
        self.bOpOut6 = bit(5);
        self.bOpOut7 = bit(6);
        self.bOpOut8 = bit(7);
        self.nState = h.nState;
        self.nDiag = h.wDiag;
    }
}
