//! FB AND — manual §4.1: up to eight inputs, each a break or make contact (negated before
//! the AND), AndOut = AND of the active inputs; at least two inputs active. States RUN (1),
//! STOP (2), SAFE (3); diag always 0.

use super::logic::{LogicBlock, LogicIn, LogicParams, SL_LOGIC_PRIVATE};
use crate::base::block::BlockInfo;
use crate::base::bools;
use crate::base::types::*;

/// Block type tag of FB_AND.
pub const SL_TYPE_AND: u16 = 3;

/// FB AND instance (ABI §3, §9). Inputs at the manual's offsets (§4.1.2), output base 24.
/// Size: 104 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct FB_AND {
    /// Offset 0. Reserved, keep 0.
    pub aReserved0: [u8; 8],
    /// Offset 8. Input 1 (may be a standard signal: it can only switch off).
    pub bAndIn1: SL_BOOL,
    /// Offset 9.
    pub bAndIn2: SL_BOOL,
    /// Offset 10.
    pub bAndIn3: SL_BOOL,
    /// Offset 11.
    pub bAndIn4: SL_BOOL,
    /// Offset 12.
    pub bAndIn5: SL_BOOL,
    /// Offset 13.
    pub bAndIn6: SL_BOOL,
    /// Offset 14.
    pub bAndIn7: SL_BOOL,
    /// Offset 15.
    pub bAndIn8: SL_BOOL,
    /// Offset 16. FbRun of the owning group.
    pub bRun: SL_BOOL,
    /// Offset 17. ErrAck of the owning group.
    pub bErrAck: SL_BOOL,
    /// Offset 18. Reserved, keep 0.
    pub aReserved1: [u8; 2],
    /// Offset 20. Bit n-1 set: AndInn is active (at least two).
    pub wInputActive: u16,
    /// Offset 22. Bit n-1 set: AndInn is a make contact (negated before the AND).
    pub wInputNegated: u16,
    /// Offset 24 (output base + 0). Reserved.
    pub aReserved2: [u8; 1],
    /// Offset 25 (output base + 1). AND of the active inputs.
    pub bAndOut: SL_BOOL,
    /// Offset 26. Reserved.
    pub aReserved3: [u8; 6],
    /// Offset 32. The manual's status value (SL_STATE_*).
    pub nState: u8,
    /// Offset 33. Reserved.
    pub aReserved4: [u8; 1],
    /// Offset 34. Diagnostic bits (only the library bits 13-15).
    pub nDiag: u16,
    /// Offset 36. Reserved.
    pub aReserved5: [u8; 4],
    /// Offset 40. Private state, 64 bytes: never write it.
    pub stPrivate: SL_LOGIC_PRIVATE,
}

crate::base::block::block_states!(
    /// The states of FB AND.
    AndState: Run, Stop, Safe, Error, Reset
);

/// Type tag, name and diag texts (manual §4.1.2).
const INFO: BlockInfo = BlockInfo {
    tag: SL_TYPE_AND,
    name: "AND",
    states: <AndState as crate::base::block::BlockState>::TABLE,
    diag: &[],
    diag_values: &[],
};

crate::impl_member!([] FB_AND {
    info: INFO,
    state: AndState,
    private: SL_LOGIC_PRIVATE,
    input: [bAndIn1, bAndIn2, bAndIn3, bAndIn4, bAndIn5, bAndIn6, bAndIn7, bAndIn8],
    param: [wInputActive, wInputNegated],
    output: [bAndOut],
    info_fields: [],
});

impl FB_AND {
    fn inputs(&self) -> [u8; 8] {
        [
            self.bAndIn1,
            self.bAndIn2,
            self.bAndIn3,
            self.bAndIn4,
            self.bAndIn5,
            self.bAndIn6,
            self.bAndIn7,
            self.bAndIn8,
        ]
    }
}

impl LogicBlock for FB_AND {
    const TAG: u16 = 0xA2D1;
    const INPUTS: u16 = 0xFF;
    const NEGATABLE: u16 = 0xFF;
    const MIN_ACTIVE: u32 = 2;

    fn window(&self) -> Option<[u64; 2]> {
        Some(crate::base::envelope::window!(self, 2:
            bAndIn1, bAndIn2, bAndIn3, bAndIn4, bAndIn5, bAndIn6, bAndIn7, bAndIn8, bRun, bErrAck
        ))
    }
    fn params(&self) -> LogicParams {
        LogicParams {
            active: self.wInputActive,
            negated: self.wInputNegated,
        }
    }
    /// RUN when every active input is logically TRUE (ACTIVE_ANDIN), else SAFE.
    fn evaluate(&self, active: u8, negated: u8) -> (LogicIn, bool) {
        let p = bools::pack(self.inputs());
        let all = bools::logical(p, active, negated) == active;
        let state = if all { SL_STATE_RUN } else { SL_STATE_SAFE };
        (
            LogicIn {
                state,
                outputs: u8::from(all),
            },
            p.invalid & active != 0,
        )
    }
    fn set_outputs(&mut self, outputs: u8, state: u8, diag: u16) {
        self.bAndOut = outputs & 1;
        self.nState = state;
        self.nDiag = diag;
    }
}

super::logic::logic_block!(FB_AND);
