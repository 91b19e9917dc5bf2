//! FB DECOUPLE — manual §4.6: eight inputs looped through to eight outputs one to one, to
//! pass the signals of a TwinSAFE connection on to other groups. States RUN (1:
//! DecOutX = DecInX), STOP (2: all outputs FALSE); diag "always 0"; no error output.
//! Member of the combinational family (`logic`).

use super::logic::{LogicBlock, LogicIn, LogicParams, SL_LOGIC_PRIVATE};
use crate::base::block::BlockInfo;
use crate::base::bools;
use crate::base::types::*;

/// Block type tag of FB_DECOUPLE.
pub const SL_TYPE_DECOUPLE: u16 = 6;

crate::base::layout::block_struct! {
    /// FB DECOUPLE instance (ABI §3, §9). Inputs at the manual's offsets 8…15 (§4.6.2), output
    /// base 24 (outputs at base + 8 … base + 15).
    /// Size: 112 bytes.
    FB_DECOUPLE {
        /// Offset 0. Reserved, keep 0.
        pub aReserved0: [u8; 8],
        /// Offset 8. 1st input channel.
        pub bDecIn1: SL_BOOL,
        /// Offset 9. 2nd input channel.
        pub bDecIn2: SL_BOOL,
        /// Offset 10. 3rd input channel.
        pub bDecIn3: SL_BOOL,
        /// Offset 11. 4th input channel.
        pub bDecIn4: SL_BOOL,
        /// Offset 12. 5th input channel.
        pub bDecIn5: SL_BOOL,
        /// Offset 13. 6th input channel.
        pub bDecIn6: SL_BOOL,
        /// Offset 14. 7th input channel.
        pub bDecIn7: SL_BOOL,
        /// Offset 15. 8th input channel.
        pub bDecIn8: SL_BOOL,
        /// Offset 16. FbRun of the owning group.
        pub bRun: SL_BOOL,
        /// Offset 17. ErrAck of the owning group.
        pub bErrAck: SL_BOOL,
        /// Offset 18. Reserved, keep 0.
        pub aReserved1: [u8; 2],
        /// Offset 20. Bit n-1 set: channel n (DecInn → DecOutn) is used (at least one).
        pub wInputActive: u16,
        /// Offset 22. Reserved, keep 0 (the manual offers no negation for DECOUPLE).
        pub aReserved2: [u8; 2],
        /// Offset 24 (output base + 0). Reserved.
        pub aReserved3: [u8; 8],
        /// Offset 32 (output base + 8). 1st output channel: DecIn1 in RUN, else FALSE.
        pub bDecOut1: SL_BOOL,
        /// Offset 33 (output base + 9). 2nd output channel.
        pub bDecOut2: SL_BOOL,
        /// Offset 34 (output base + 10). 3rd output channel.
        pub bDecOut3: SL_BOOL,
        /// Offset 35 (output base + 11). 4th output channel.
        pub bDecOut4: SL_BOOL,
        /// Offset 36 (output base + 12). 5th output channel.
        pub bDecOut5: SL_BOOL,
        /// Offset 37 (output base + 13). 6th output channel.
        pub bDecOut6: SL_BOOL,
        /// Offset 38 (output base + 14). 7th output channel.
        pub bDecOut7: SL_BOOL,
        /// Offset 39 (output base + 15). 8th output channel.
        pub bDecOut8: SL_BOOL,
    } tail 40 41 42 44 48 [aReserved4, aReserved5] SL_LOGIC_PRIVATE, 64:
        "(SL_STATE_*)", "Diagnostic bits (only the library bits 13-15)."
}

crate::base::block::block_states!(
    /// The states of FB DECOUPLE.
    DecoupleState: Run, Stop, Error, Reset
);

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
