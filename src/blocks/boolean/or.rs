//! FB OR — manual §4.2: up to eight inputs, each a break or make contact (negated before
//! the OR), OrOut = OR of the active inputs; at least one input active. States RUN (1),
//! STOP (2), SAFE (3); diag always 0.

use super::logic::{LogicBlock, LogicIn, LogicParams, SL_LOGIC_PRIVATE};
use crate::base::block::BlockInfo;
use crate::base::bools;
use crate::base::types::*;

/// Block type tag of FB_OR.
pub const SL_TYPE_OR: u16 = 4;

/// FB OR instance (ABI §3, §9). Inputs at the manual's offsets (§4.2.2), output base 24.
/// Size: 104 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct FB_OR {
    /// Offset 0. Reserved, keep 0.
    pub aReserved0: [u8; 8],
    /// Offset 8. Input 1.
    pub bOrIn1: SL_BOOL,
    /// Offset 9.
    pub bOrIn2: SL_BOOL,
    /// Offset 10.
    pub bOrIn3: SL_BOOL,
    /// Offset 11.
    pub bOrIn4: SL_BOOL,
    /// Offset 12.
    pub bOrIn5: SL_BOOL,
    /// Offset 13.
    pub bOrIn6: SL_BOOL,
    /// Offset 14.
    pub bOrIn7: SL_BOOL,
    /// Offset 15.
    pub bOrIn8: SL_BOOL,
    /// Offset 16. FbRun of the owning group.
    pub bRun: SL_BOOL,
    /// Offset 17. ErrAck of the owning group.
    pub bErrAck: SL_BOOL,
    /// Offset 18. Reserved, keep 0.
    pub aReserved1: [u8; 2],
    /// Offset 20. Bit n-1 set: OrInn is active (at least one).
    pub wInputActive: u16,
    /// Offset 22. Bit n-1 set: OrInn is a make contact (negated before the OR).
    pub wInputNegated: u16,
    /// Offset 24 (output base + 0). Reserved.
    pub aReserved2: [u8; 1],
    /// Offset 25 (output base + 1). OR of the active inputs.
    pub bOrOut: SL_BOOL,
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
    /// The states of FB OR.
    OrState: Run, Stop, Safe, Error, Reset
);

/// Type tag, name and diag texts (manual §4.2.2).
const INFO: BlockInfo = BlockInfo {
    tag: SL_TYPE_OR,
    name: "OR",
    states: <OrState as crate::base::block::BlockState>::TABLE,
    diag: &[],
    diag_values: &[],
};

crate::impl_member!([] FB_OR {
    info: INFO,
    state: OrState,
    private: SL_LOGIC_PRIVATE,
    input: [bOrIn1, bOrIn2, bOrIn3, bOrIn4, bOrIn5, bOrIn6, bOrIn7, bOrIn8],
    param: [wInputActive, wInputNegated],
    output: [bOrOut],
    info_fields: [],
});

impl FB_OR {
    fn inputs(&self) -> [u8; 8] {
        [
            self.bOrIn1,
            self.bOrIn2,
            self.bOrIn3,
            self.bOrIn4,
            self.bOrIn5,
            self.bOrIn6,
            self.bOrIn7,
            self.bOrIn8,
        ]
    }
}

impl LogicBlock for FB_OR {
    const TAG: u16 = 0x0B01;
    const INPUTS: u16 = 0xFF;
    const NEGATABLE: u16 = 0xFF;
    const MIN_ACTIVE: u32 = 1;

    fn window(&self) -> Option<[u64; 2]> {
        Some(crate::base::envelope::window!(self, 2:
            bOrIn1, bOrIn2, bOrIn3, bOrIn4, bOrIn5, bOrIn6, bOrIn7, bOrIn8, bRun, bErrAck
        ))
    }
    fn params(&self) -> LogicParams {
        LogicParams {
            active: self.wInputActive,
            negated: self.wInputNegated,
        }
    }
    /// RUN when at least one active input is logically TRUE (ACTIVE_ORIN), else SAFE.
    fn evaluate(&self, active: u8, negated: u8) -> (LogicIn, bool) {
        let p = bools::pack(self.inputs());
        let any = bools::logical(p, active, negated) != 0;
        let state = if any { SL_STATE_RUN } else { SL_STATE_SAFE };
        (
            LogicIn {
                state,
                outputs: u8::from(any),
            },
            p.invalid & active != 0,
        )
    }
    fn set_outputs(&mut self, outputs: u8, state: u8, diag: u16) {
        self.bOrOut = outputs & 1;
        self.nState = state;
        self.nDiag = diag;
    }
}

super::logic::logic_block!(FB_OR);
