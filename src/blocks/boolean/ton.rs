//! FB TON — manual §4.12 (functional description 4.12.1, signals, states and diag 4.12.2,
//! EL6910 TON extension with the timebases 1, 10, 100 and 1000 ms 4.12.4): switch-on delay.
//! TonOut becomes TRUE when TonIn has been TRUE for the delay time; TonIn FALSE switches it
//! off at once and discards the running delay. States RUN (1), STOP (2), SAFE (3), DELAYIN
//! (9); the manual's diag value is always 0. The state machine is the shared timer
//! (`timer`, docs/semantics.md T1–T6, T8, T9, T16).

use super::timer::SL_TIMER_PRIVATE;
use crate::base::block::BlockInfo;
use crate::base::types::*;

/// FB_TON state DELAYIN (9): TonIn is TRUE and the delay has not yet expired.
pub const SL_STATE_TON_DELAYIN: u8 = 9;

/// Block type tag of FB_TON.
pub const SL_TYPE_TON: u16 = 13;

/// FB TON instance (ABI §3, §9). Input at the manual's offset (§4.12.2), output base 32.
/// Size: 112 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct FB_TON {
    /// Offset 0. Reserved, keep 0.
    pub aReserved0: [u8; 8],
    /// Offset 8. TonIn1: the input whose TRUE level is passed on after the delay (break or
    /// make contact: wInputNegated bit 0).
    pub bTonIn1: SL_BOOL,
    /// Offset 9. Reserved, keep 0.
    pub aReserved1: [u8; 7],
    /// Offset 16. FbRun of the owning group: TRUE = the block executes.
    pub bRun: SL_BOOL,
    /// Offset 17. ErrAck of the owning group.
    pub bErrAck: SL_BOOL,
    /// Offset 18. Reserved, keep 0.
    pub aReserved2: [u8; 2],
    /// Offset 20. Switch-on delay in ms: 1 to 60,000 steps of the timebase (at most
    /// 60,000,000 ms = 60,000 s), a whole number of steps.
    pub tDelay: u32,
    /// Offset 24. Timebase in ms: SL_TIMEBASE_1MS, _10MS, _100MS, _1000MS, or
    /// SL_TIMEBASE_AUTO (0) = the smallest one whose range holds tDelay.
    pub nTimeBase: u16,
    /// Offset 26. Bit 0 must be set: TonIn1 is active.
    pub wInputActive: u16,
    /// Offset 28. Bit 0 set: TonIn1 is a make contact (negated before evaluation).
    pub wInputNegated: u16,
    /// Offset 30. Reserved, keep 0.
    pub aReserved3: [u8; 2],
    /// Offset 32 (output base + 0). Reserved (the manual's error output is inactive).
    pub aReserved4: [u8; 1],
    /// Offset 33 (output base + 1). TonOut: TRUE in RUN only.
    pub bTonOut: SL_BOOL,
    /// Offset 34. Reserved.
    pub aReserved5: [u8; 6],
    /// Offset 40. The manual's status value (SL_STATE_*, SL_STATE_TON_DELAYIN).
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
    /// The states of FB TON.
    TonState: Run, Stop, Safe, Error, Reset, DelayIn = SL_STATE_TON_DELAYIN, "DELAYIN"
);

/// Type tag, name, states and diag texts (manual §4.12.2: diag always 0).
const INFO: BlockInfo = BlockInfo {
    tag: SL_TYPE_TON,
    name: "TON",
    states: <TonState as crate::base::block::BlockState>::TABLE,
    diag: &[],
    diag_values: &[],
};

crate::impl_member!([] FB_TON {
    info: INFO,
    state: TonState,
    private: SL_TIMER_PRIVATE,
    input: [bTonIn1],
    param: [tDelay, nTimeBase, wInputActive, wInputNegated],
    output: [bTonOut],
    info_fields: [],
});

super::timer::timer_block!(FB_TON {
    tag: 0x7013,
    off_delay: false,
    persists: false,
    timing_state: SL_STATE_TON_DELAYIN,
    input: bTonIn1,
    output: bTonOut,
});
