//! FB DECOUPLE — manual §4.6: eight inputs looped through to eight outputs one to one, to
//! pass the signals of a TwinSAFE connection on to other groups. States RUN (1:
//! DecOutX = DecInX), STOP (2: all outputs FALSE); diag "always 0"; no error output.
//! Member of the combinational family (`logic`).

use super::logic::{LogicBlock, LogicIn, LogicParams, SL_LOGIC_PRIVATE};
use crate::base::block::BlockInfo;
use crate::base::bools;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/decouple.rs"));

/// Type tag, name and diag texts (manual §4.6.2: diag "always 0").
const INFO: BlockInfo = BlockInfo::of::<DecoupleState>(SL_TYPE_DECOUPLE, "DECOUPLE");

crate::impl_member!([] FB_DECOUPLE {
    info: INFO,
    state: DecoupleState,
    private: SL_LOGIC_PRIVATE,
    input: [bDecIn1, bDecIn2, bDecIn3, bDecIn4, bDecIn5, bDecIn6, bDecIn7, bDecIn8],
    param: [wInputActive],
    output: [bDecOut1, bDecOut2, bDecOut3, bDecOut4, bDecOut5, bDecOut6, bDecOut7, bDecOut8],
    info_fields: [],
});

impl FB_DECOUPLE {
    fn inputs(&self) -> [u8; 8] {
        [
            self.bDecIn1,
            self.bDecIn2,
            self.bDecIn3,
            self.bDecIn4,
            self.bDecIn5,
            self.bDecIn6,
            self.bDecIn7,
            self.bDecIn8,
        ]
    }
}

impl LogicBlock for FB_DECOUPLE {
    const TAG: u16 = 0xDEC6;
    const INPUTS: u16 = 0xFF;
    const NEGATABLE: u16 = 0;
    const MIN_ACTIVE: u32 = 1;

    fn window(&self) -> Option<[u64; 2]> {
        Some(crate::base::envelope::window!(self, 2:
            bDecIn1, bDecIn2, bDecIn3, bDecIn4, bDecIn5, bDecIn6, bDecIn7, bDecIn8, bRun, bErrAck
        ))
    }
    fn params(&self) -> LogicParams {
        LogicParams {
            active: self.wInputActive,
            negated: 0,
        }
    }
    /// Always RUN; each used channel passes its input through, an invalid byte as FALSE
    /// (ABI §2), an unused channel stays FALSE (semantics D2, D3).
    fn evaluate(&self, active: u8, _negated: u8) -> (LogicIn, bool) {
        let p = bools::pack(self.inputs());
        (
            LogicIn {
                state: SL_STATE_RUN,
                outputs: bools::logical(p, active, 0),
            },
            p.invalid & active != 0,
        )
    }
    fn set_outputs(&mut self, outputs: u8, state: u8, diag: u16) {
        let bit = |k: u8| (outputs >> k) & 1;
        self.bDecOut1 = bit(0);
        self.bDecOut2 = bit(1);
        self.bDecOut3 = bit(2);
        self.bDecOut4 = bit(3);
        self.bDecOut5 = bit(4);
        self.bDecOut6 = bit(5);
        self.bDecOut7 = bit(6);
        self.bDecOut8 = bit(7);
        self.nState = state;
        self.nDiag = diag;
    }
}

super::logic::logic_block!(FB_DECOUPLE);
