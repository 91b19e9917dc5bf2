//! FB CONNECTION SHUTDOWN — manual §4.15 (functional description 4.15.1, signals and
//! states 4.15.2, configuration 4.15.3, NOTICE 4.15.4); layout and readings ABI-2 §11.1,
//! §13.5, §14 rows 21/22; docs/semantics.md CS1–CS8.
//!
//! Deactivate1/2 (pair 1 with discrepancy time `tDiscTime12`) request the shutdown of the
//! FSoE connection with Connection ID `nConnectionId`: while the block is in SAFE or RUN the
//! request is `bShutdownRequest`, which the group copies to that connection's
//! `bShutdownRequest`; the connection's `bShutdown` comes back as `bConnShutdown`, and the
//! block is in RUN (`bDeactivated` TRUE) exactly while it is TRUE — after the connection
//! was shut down, by this request or by the partner, until it is in DATA again. A shutdown
//! is no error: the group sees neither ComErr nor ComStartup.

use crate::base::block::BlockInfo;
use crate::base::envelope::Block;
use crate::base::header::{param_crc, SL_PRIVATE_HEADER};
use crate::base::member::{Member, Wiring};
use crate::base::reason::rule;
use crate::base::reason::{when, Rule, RuleDef, Unit};
use crate::base::types::*;
use crate::base::{bools, pair};
use core::mem::offset_of;

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/connection/connshutdown.rs"
));

const INFO: BlockInfo =
    BlockInfo::of::<ConnShutdownState>(SL_TYPE_CONNECTION_SHUTDOWN, "CONNECTION_SHUTDOWN")
        .diag(&[(SL_DIAG_DISC1, "discrepancy error input group 1")]);

crate::impl_member!([] FB_CONNECTION_SHUTDOWN {
    info: INFO,
    state: ConnShutdownState,
    private: SL_CONNSHUT_PRIVATE,
    input: [bDeactivate1, bDeactivate2, bConnShutdown],
    param: [tDiscTime12, nConnectionId, wInputActive, wInputNegated],
    output: [bError, bDeactivated, bShutdownRequest],
    info_fields: [],
    wiring: (before_cycle, after_cycle),
});

/// wAux bit 0: the discrepancy timer of pair 1 runs.
const AUX_DISC: u16 = 1 << 0;
/// wAux bit 1: the request of this cycle (every active DeactivateX logically TRUE).
const AUX_REQUEST: u16 = 1 << 1;

const OFF_ID: u16 = offset_of!(FB_CONNECTION_SHUTDOWN, nConnectionId) as u16;
const OFF_CONN_SHUTDOWN: u16 = offset_of!(FB_CONNECTION_SHUTDOWN, bConnShutdown) as u16;
const OFF_REQUEST: u16 = offset_of!(FB_CONNECTION_SHUTDOWN, bShutdownRequest) as u16;

/// Before the block's cycle in a group: `bConnShutdown` from the connection(s) with its
/// Connection ID that ran earlier in this group cycle (FALSE when there is none).
pub fn before_cycle<B: Member + ?Sized>(b: &mut B, w: &mut Wiring) {
    let id = b.field_bits(OFF_ID).unwrap_or(0) as u16;
    b.set_input_bits(OFF_CONN_SHUTDOWN, u32::from(w.conn_shutdown(id)));
}

/// After the block's cycle in a group: its request for the connection(s) with its
/// Connection ID.
pub fn after_cycle<B: Member + ?Sized>(b: &mut B, w: &mut Wiring) {
    let id = b.field_bits(OFF_ID).unwrap_or(0) as u16;
    w.request(id, b.output(OFF_REQUEST).unwrap_or(0));
}

/// The parameters as the user wrote them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ConnShutdownParams {
    pub disc: u32,
    pub id: u16,
    pub active: u16,
    pub negated: u16,
}

/// The inputs of one cycle.
#[derive(Clone, Copy, Debug, Default)]
pub struct ConnShutdownIn {
    /// Logical values of the active inputs (invalid bytes FALSE).
    pub logical: u8,
    /// Invalid bytes among the active inputs.
    pub invalid: u8,
    /// bConnShutdown is exactly 1.
    pub conn_shutdown: bool,
}

fn crc(h: &SL_PRIVATE_HEADER, p: &[u16; 2]) -> u16 {
    param_crc(
        <FB_CONNECTION_SHUTDOWN as Block>::MAGIC,
        h.nActive,
        h.nNegated,
        h.wOptions,
        p,
    )
}

impl Block for FB_CONNECTION_SHUTDOWN {
    const MAGIC: u16 = 0xC5D0;
    type Params = ConnShutdownParams;
    type In = ConnShutdownIn;

    fn live_params(&self) -> ConnShutdownParams {
        ConnShutdownParams {
            disc: self.tDiscTime12,
            id: self.nConnectionId,
            active: self.wInputActive,
            negated: self.wInputNegated,
        }
    }

    fn latched_params(&self) -> ConnShutdownParams {
        let p = &self.stPrivate;
        ConnShutdownParams {
            disc: u32::from(p.awParam[0]),
            id: p.awParam[1],
            active: u16::from(p.stHeader.nActive),
            negated: u16::from(p.stHeader.nNegated),
        }
    }

    /// Semantics CS4: no active input is valid (the opposite side of a connection); a
    /// discrepancy time needs both inputs active; Connection ID 0 is refused.
    const RULES: &'static [RuleDef<ConnShutdownParams>] = &[
        rule!(no_bits_outside "wInputActive", |p| p.active, 0b11),
        rule!(no_bits_outside "wInputNegated", |p| p.negated, 0b11),
        rule!(at_most "tDiscTime12" in Ms, |p| p.disc, SL_TIME_PARAM_MAX),
        RuleDef::new("tDiscTime12", Rule::Needs("wInputActive"), Unit::Ms, |p| {
            when(p.disc != 0 && p.active & 0b11 != 0b11, p.disc, 0b11)
        }),
        rule!(not_zero "nConnectionId" in Plain, |p| p.id),
    ];

    fn store_params(&mut self, p: &ConnShutdownParams) {
        let q = &mut self.stPrivate;
        q.awParam = [p.disc as u16, p.id];
        q.stHeader.nActive = p.active as u8;
        q.stHeader.nNegated = p.negated as u8;
        q.stHeader.wOptions = 0;
    }

    fn latched_crc(&self) -> u16 {
        crc(&self.stPrivate.stHeader, &self.stPrivate.awParam)
    }

    fn decode(&mut self) -> (ConnShutdownIn, bool) {
        let packed = bools::pack([self.bDeactivate1, self.bDeactivate2]);
        let h = &mut self.stPrivate.stHeader;
        let active = h.nActive & 0b11;
        let logical = bools::logical(packed, active, h.nNegated);
        let invalid = packed.invalid & active;
        let request = active != 0 && logical & active == active;
        h.wAux = (h.wAux & !AUX_REQUEST) | if request { AUX_REQUEST } else { 0 };
        let inp = ConnShutdownIn {
            logical,
            invalid,
            conn_shutdown: self.bConnShutdown == 1,
        };
        (inp, invalid != 0 || self.bConnShutdown > 1)
    }

    fn start(&mut self, inp: &ConnShutdownIn, _now: u32) {
        let h = &mut self.stPrivate.stHeader;
        h.wAux &= !AUX_DISC;
        h.nState = SL_STATE_SAFE;
        if inp.conn_shutdown && self.params_intact() {
            self.stPrivate.stHeader.nState = SL_STATE_RUN;
        }
    }

    fn step(&mut self, inp: &ConnShutdownIn, now: u32) -> Status {
        let p = &mut self.stPrivate;
        let both = p.stHeader.nActive & 0b11 == 0b11;
        let monitored = u8::from(p.awParam[0] != 0 && both);
        let mut running = (p.stHeader.wAux & AUX_DISC) as u8;
        let mut starts = [p.tDiscStart];
        let disc = pair::monitor(
            inp.logical,
            monitored,
            &mut running,
            &mut starts,
            &p.awParam[..1],
            now,
        );
        p.tDiscStart = starts[0];
        p.stHeader.wAux = (p.stHeader.wAux & !AUX_DISC) | u16::from(running & 1);
        if disc != 0 {
            p.stHeader.enter_error(SL_DIAG_DISC1);
            return Status::Ok;
        }
        // RUN exactly while the connection reports its shutdown (semantics CS1); the latched
        // parameters are checked where the output switches on (C3).
        if self.corrupt_entering_run(inp.conn_shutdown) {
            return Status::Corrupt;
        }
        self.stPrivate.stHeader.nState = if inp.conn_shutdown {
            SL_STATE_RUN
        } else {
            SL_STATE_SAFE
        };
        Status::Ok
    }

    /// The pair must agree again with valid bytes (semantics CS6).
    fn error_remains(&mut self, inp: &ConnShutdownIn) -> bool {
        let h = &self.stPrivate.stHeader;
        if h.wDiag & SL_DIAG_DISC1 == 0 {
            return false;
        }
        let both = h.nActive & 0b11 == 0b11;
        both && (pair::differing(inp.logical) & 1 != 0 || inp.invalid != 0)
    }

    fn write_outputs(&mut self) {
        let h = self.stPrivate.stHeader;
        let running = h.nState == SL_STATE_SAFE || h.nState == SL_STATE_RUN;
        self.bError = u8::from(h.nState == SL_STATE_ERROR);
        self.bDeactivated = u8::from(h.nState == SL_STATE_RUN);
        self.bShutdownRequest = u8::from(running && h.wAux & AUX_REQUEST != 0);
        self.nState = h.nState;
        self.nDiag = h.wDiag;
    }
}
