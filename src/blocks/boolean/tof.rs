//! FB TOF — manual §4.14 (functional description 4.14.1, signals, states and diag 4.14.2,
//! EL6910 TOF extension with timebases 4.14.4; the 100 and 1000 ms timebases of the TON
//! extension 4.12.4 apply as well, ABI §9: up to 60,000 s): switch-off delay. TofOut is
//! TRUE while TofIn is TRUE and stays TRUE until TofIn has been FALSE for the delay time; a
//! TRUE TofIn before that keeps it on. bRun FALSE (STOP) and ERROR switch it off at once.
//! States RUN (1), STOP (2), SAFE (3), DELAYOUT (8); the manual's diag value is always 0.
//! The state machine is the shared timer (`timer`, docs/semantics.md T1–T5, T7–T9, T16).

use super::timer::SL_TIMER_PRIVATE;
use crate::base::block::BlockInfo;
use crate::base::types::*;

/// Block type tag of FB_TOF.
pub const SL_TYPE_TOF: u16 = 15;

/// FB TOF instance (ABI §3, §9). Input at the manual's offset (§4.14.2), output base 32.
/// Size: 112 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct FB_TOF {
    /// Offset 0. Reserved, keep 0.
    pub aReserved0: [u8; 8],
    /// Offset 8. TofIn1: TRUE switches TofOut on at once; FALSE switches it off after the
    /// delay (break or make contact: wInputNegated bit 0).
    pub bTofIn1: SL_BOOL,
    /// Offset 9. Reserved, keep 0.
    pub aReserved1: [u8; 7],
    /// Offset 16. FbRun of the owning group: TRUE = the block executes.
    pub bRun: SL_BOOL,
    /// Offset 17. ErrAck of the owning group.
    pub bErrAck: SL_BOOL,
    /// Offset 18. Reserved, keep 0.
    pub aReserved2: [u8; 2],
    /// Offset 20. Switch-off delay in ms: 1 to 60,000 steps of the timebase (at most
    /// 60,000,000 ms = 60,000 s), a whole number of steps.
    pub tDelay: u32,
    /// Offset 24. Timebase in ms: SL_TIMEBASE_1MS, _10MS, _100MS, _1000MS, or
    /// SL_TIMEBASE_AUTO (0) = the smallest one whose range holds tDelay.
    pub nTimeBase: u16,
    /// Offset 26. Bit 0 must be set: TofIn1 is active.
    pub wInputActive: u16,
    /// Offset 28. Bit 0 set: TofIn1 is a make contact (negated before evaluation).
    pub wInputNegated: u16,
    /// Offset 30. Reserved, keep 0.
    pub aReserved3: [u8; 2],
    /// Offset 32 (output base + 0). Reserved (the manual's error output is inactive).
    pub aReserved4: [u8; 1],
    /// Offset 33 (output base + 1). TofOut: TRUE in RUN and DELAYOUT.
    pub bTofOut: SL_BOOL,
    /// Offset 34. Reserved.
    pub aReserved5: [u8; 6],
    /// Offset 40. The manual's status value (SL_STATE_*).
    pub nState: u8,
    /// Offset 41. Reserved.
    pub aReserved6: [u8; 1],
    /// Offset 42. Diagnostic bits (only the library bits 13-15).
    pub nDiag: u16,
    /// Offset 44. Reserved.
    pub aReserved7: [u8; 4],
    /// Offset 48. Private state, 64 bytes: never write it.
    pub stPrivate: SL_TIMER_PRIVATE,
}

crate::base::block::block_states!(
    /// The states of FB TOF.
    TofState: Run, Stop, Safe, Error, Reset, DelayOut
);

/// Type tag, name, states and diag texts (manual §4.14.2: diag always 0).
const INFO: BlockInfo = BlockInfo {
    tag: SL_TYPE_TOF,
    name: "TOF",
    states: <TofState as crate::base::block::BlockState>::TABLE,
    diag: &[],
    diag_values: &[],
};

crate::impl_member!([] FB_TOF {
    info: INFO,
    state: TofState,
    private: SL_TIMER_PRIVATE,
    input: [bTofIn1],
    param: [tDelay, nTimeBase, wInputActive, wInputNegated],
    output: [bTofOut],
    info_fields: [],
});

super::timer::timer_block!(FB_TOF {
    tag: 0x70F5,
    off_delay: true,
    persists: false,
    timing_state: SL_STATE_DELAYOUT,
    input: bTofIn1,
    output: bTofOut,
});
