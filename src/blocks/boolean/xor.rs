//! FB XOR — manual §4.34: up to eight XOR functions; XorOutY = (Xor1InY XOR Xor2InY) AND
//! "FB Input Active"(Y). States RUN (1), STOP (2); diag always 0 ("No diagnostic
//! information"). Not available in the KL6904, EL6900 and EL6910 SW ≤ 03 (the library
//! offers it everywhere). Member of the combinational family (`logic`).

use super::logic::{LogicBlock, LogicIn, LogicParams, SL_LOGIC_PRIVATE};
use crate::base::block::BlockInfo;
use crate::base::bools;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/xor.rs"));

/// Type tag, name and diag texts (manual §4.34.2: no diagnostic information).
const INFO: BlockInfo = BlockInfo::of::<XorState>(SL_TYPE_XOR, "XOR");

crate::impl_member!([] FB_XOR {
    info: INFO,
    state: XorState,
    private: SL_LOGIC_PRIVATE,
    input: [bXor1In1, bXor2In1, bXor1In2, bXor2In2, bXor1In3, bXor2In3, bXor1In4, bXor2In4, bXor1In5, bXor2In5, bXor1In6, bXor2In6, bXor1In7, bXor2In7, bXor1In8, bXor2In8],
    param: [wInputActive],
    output: [bXorOut1, bXorOut2, bXorOut3, bXorOut4, bXorOut5, bXorOut6, bXorOut7, bXorOut8],
    info_fields: [],
});

impl FB_XOR {
    /// Input 1 of XOR functions 1…8.
    fn first(&self) -> [u8; 8] {
        [
            self.bXor1In1,
            self.bXor1In2,
            self.bXor1In3,
            self.bXor1In4,
            self.bXor1In5,
            self.bXor1In6,
            self.bXor1In7,
            self.bXor1In8,
        ]
    }

    /// Input 2 of XOR functions 1…8.
    fn second(&self) -> [u8; 8] {
        [
            self.bXor2In1,
            self.bXor2In2,
            self.bXor2In3,
            self.bXor2In4,
            self.bXor2In5,
            self.bXor2In6,
            self.bXor2In7,
            self.bXor2In8,
        ]
    }
}

impl LogicBlock for FB_XOR {
    const TAG: u16 = 0x7C05;
    const INPUTS: u16 = 0xFF;
    const NEGATABLE: u16 = 0;
    const MIN_ACTIVE: u32 = 1;

    /// Sixteen input bytes and bRun, bErrAck: more than a window of two words holds, so
    /// the inputs are gathered into bits (`bools::key`: `None` when one is neither 0 nor
    /// 1) and bRun, bErrAck follow as they are, in the first word; the second word is 0.
    fn window(&self) -> Option<[u64; 2]> {
        let inputs = crate::base::bools::key([
            self.bXor1In1,
            self.bXor2In1,
            self.bXor1In2,
            self.bXor2In2,
            self.bXor1In3,
            self.bXor2In3,
            self.bXor1In4,
            self.bXor2In4,
            self.bXor1In5,
            self.bXor2In5,
            self.bXor1In6,
            self.bXor2In6,
            self.bXor1In7,
            self.bXor2In7,
            self.bXor1In8,
            self.bXor2In8,
        ])?;
        let controls = u64::from(self.bRun) << 16 | u64::from(self.bErrAck) << 24;
        Some([u64::from(inputs) | controls, 0])
    }
    fn params(&self) -> LogicParams {
        LogicParams {
            active: self.wInputActive,
            negated: 0,
        }
    }
    /// Always RUN (the manual has no SAFE state for XOR). An invalid byte in an active
    /// function makes that output FALSE, its safe state, whatever the other input: reading
    /// the byte as FALSE would let the other input switch the output on (semantics X3).
    fn evaluate(&self, active: u8, _negated: u8) -> (LogicIn, bool) {
        let a = bools::pack(self.first());
        let b = bools::pack(self.second());
        let invalid = (a.invalid | b.invalid) & active;
        let outputs = (a.ones ^ b.ones) & active & !invalid;
        (
            LogicIn {
                state: SL_STATE_RUN,
                outputs,
            },
            invalid != 0,
        )
    }
    fn set_outputs(&mut self, outputs: u8, state: u8, diag: u16) {
        let bit = |k: u8| (outputs >> k) & 1;
        self.bXorOut1 = bit(0);
        self.bXorOut2 = bit(1);
        self.bXorOut3 = bit(2);
        self.bXorOut4 = bit(3);
        self.bXorOut5 = bit(4);
        self.bXorOut6 = bit(5);
        self.bXorOut7 = bit(6);
        self.bXorOut8 = bit(7);
        self.nState = state;
        self.nDiag = diag;
    }
}

super::logic::logic_block!(FB_XOR);
