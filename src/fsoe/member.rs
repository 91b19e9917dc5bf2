//! An FSoE connection as a member of a TwinSAFE group (ABI-2 §13.5, docs/semantics.md
//! FS17–FS21): type tag `SL_TYPE_FSOE_CONN`, run by the group before its blocks with the
//! frames of its mailbox; its bComErr / bComStartup are ORed into the group's ComErr /
//! ComStartup; its SafeData bits are reached by `SL_LINK_RXBIT` / `SL_LINK_TXBIT` links,
//! its BOOL inputs and outputs by ordinary BOOL links.

use super::conn::{self, SL_FSOE_CONN};
use crate::base::block::{Dir, Field, Kind};
use crate::base::member::{ConnReport, Member, Ran, Wiring};
use crate::base::types::Status;
use core::mem::offset_of;

/// Byte offset of `bShutdownRequest` (the group copies a CONNECTION SHUTDOWN block's
/// request there).
pub const OFFSET_SHUTDOWN_REQUEST: u16 = offset_of!(SL_FSOE_CONN, bShutdownRequest) as u16;

macro_rules! field {
    ($name:ident, $kind:ident, $dir:ident) => {
        Field {
            name: stringify!($name),
            offset: offset_of!(SL_FSOE_CONN, $name) as u16,
            kind: Kind::$kind,
            dir: Dir::$dir,
        }
    };
}

/// The connection's field table (its scalar fields; the SafeData arrays are reached bit by
/// bit through RXBIT / TXBIT links).
pub const FIELDS: &[Field] = &[
    field!(bRun, Bool, Control),
    field!(bErrAck, Bool, Control),
    field!(bComErrAck, Bool, Input),
    field!(bShutdownRequest, Bool, Input),
    field!(bModuleFault, Bool, Input),
    field!(nConnectionId, U16, Param),
    field!(nFsoeAddress, U16, Param),
    field!(nRole, U16, Param),
    field!(nTxDataLen, U16, Param),
    field!(nRxDataLen, U16, Param),
    field!(nAppParaLen, U16, Param),
    field!(tWatchdogTime, U32, Param),
    field!(dwOptions, U32, Param),
    field!(bComErr, Bool, Output),
    field!(bComStartup, Bool, Output),
    field!(bDataValid, Bool, Output),
    field!(bShutdown, Bool, Output),
    field!(bPeerFailSafe, Bool, Output),
    field!(nState, U8, Info),
    field!(nResetCode, U8, Info),
    field!(nDiag, U16, Info),
];

fn field_at(offset: u16, dirs: &[Dir]) -> Option<&'static Field> {
    FIELDS
        .iter()
        .find(|f| f.offset == offset && dirs.contains(&f.dir))
}

/// Reads a field of the table as a 32-bit pattern.
fn read(c: &SL_FSOE_CONN, f: &Field) -> u32 {
    match f.name {
        "bRun" => u32::from(c.bRun),
        "bErrAck" => u32::from(c.bErrAck),
        "bComErrAck" => u32::from(c.bComErrAck),
        "bShutdownRequest" => u32::from(c.bShutdownRequest),
        "bModuleFault" => u32::from(c.bModuleFault),
        "nConnectionId" => u32::from(c.nConnectionId),
        "nFsoeAddress" => u32::from(c.nFsoeAddress),
        "nRole" => u32::from(c.nRole),
        "nTxDataLen" => u32::from(c.nTxDataLen),
        "nRxDataLen" => u32::from(c.nRxDataLen),
        "nAppParaLen" => u32::from(c.nAppParaLen),
        "tWatchdogTime" => c.tWatchdogTime,
        "dwOptions" => c.dwOptions,
        "bComErr" => u32::from(c.bComErr),
        "bComStartup" => u32::from(c.bComStartup),
        "bDataValid" => u32::from(c.bDataValid),
        "bShutdown" => u32::from(c.bShutdown),
        "bPeerFailSafe" => u32::from(c.bPeerFailSafe),
        "nState" => u32::from(c.nState),
        "nResetCode" => u32::from(c.nResetCode),
        _ => u32::from(c.nDiag),
    }
}

impl Member for SL_FSOE_CONN {
    fn drive(&mut self, run: u8, ack: u8) {
        self.bRun = run;
        self.bErrAck = ack;
    }
    fn execute(&mut self, now: u32) -> Status {
        conn::cycle_mailbox(self, now)
    }
    fn state(&self) -> u8 {
        self.nState
    }
    fn fields(&self) -> &'static [Field] {
        FIELDS
    }
    fn input_mut(&mut self, offset: u16) -> Option<&mut u8> {
        match field_at(offset, &[Dir::Input])?.name {
            "bComErrAck" => Some(&mut self.bComErrAck),
            "bShutdownRequest" => Some(&mut self.bShutdownRequest),
            _ => Some(&mut self.bModuleFault),
        }
    }
    fn output(&self, offset: u16) -> Option<u8> {
        let f = field_at(offset, &[Dir::Output])?;
        Some(read(self, f) as u8)
    }
    fn output_bits(&self, offset: u16) -> Option<u32> {
        let f = field_at(offset, &[Dir::Output])?;
        Some(read(self, f))
    }
    fn set_input_bits(&mut self, offset: u16, bits: u32) -> bool {
        match self.input_mut(offset) {
            Some(b) => {
                *b = bits as u8;
                true
            }
            None => false,
        }
    }
    fn field_bits(&self, offset: u16) -> Option<u32> {
        let f = FIELDS.iter().find(|f| f.offset == offset)?;
        Some(read(self, f))
    }
    fn set_param_bits(&mut self, offset: u16, bits: u32) -> bool {
        let Some(f) = field_at(offset, &[Dir::Param]) else {
            return false;
        };
        match f.name {
            "nConnectionId" => self.nConnectionId = bits as u16,
            "nFsoeAddress" => self.nFsoeAddress = bits as u16,
            "nRole" => self.nRole = bits as u16,
            "nTxDataLen" => self.nTxDataLen = bits as u16,
            "nRxDataLen" => self.nRxDataLen = bits as u16,
            "nAppParaLen" => self.nAppParaLen = bits as u16,
            "tWatchdogTime" => self.tWatchdogTime = bits,
            _ => self.dwOptions = bits,
        }
        true
    }
    fn run_in_group(&mut self, run: u8, ack: u8, now: u32, w: &mut Wiring) -> Ran {
        let _ = w;
        self.drive(run, ack);
        let status = conn::cycle_mailbox(self, now);
        Ran {
            status,
            state: self.nState,
            conn: Some(ConnReport {
                // A connection that never ran its init (or whose init was refused) cannot
                // communicate: an error for the group, like a corrupt one.
                com_err: self.bComErr != 0 || status == Status::Config,
                startup: self.bComStartup != 0,
                shutdown: self.bShutdown != 0,
                id: conn::conn_id(self),
            }),
        }
    }
    fn safe_data_bits(&self) -> (u16, u16) {
        // Before init (or when corrupt) no bit can be linked.
        conn::data_lens(self).map_or((0, 0), |(rx, tx)| (u16::from(rx) * 8, u16::from(tx) * 8))
    }
    fn rx_bit(&self, bit: u16) -> Option<u8> {
        let byte = self.aRxSafeData.get(usize::from(bit / 8))?;
        Some((byte >> (bit % 8)) & 1)
    }
    fn set_tx_bit(&mut self, bit: u16, value: u8) {
        let Some(byte) = self.aTxSafeData.get_mut(usize::from(bit / 8)) else {
            return;
        };
        let mask = 1u8 << (bit % 8);
        if value == 1 {
            *byte |= mask;
        } else {
            *byte &= !mask;
        }
    }
}
