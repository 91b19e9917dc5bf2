//! FB TON2 — manual §4.13 (functional description 4.13.1 with the timing diagram, signals
//! and states 4.13.2; the timebases of the TON extension 4.12.4 apply): FB TON
//! (`ton`) extended by "Starts with remaining time". The block keeps the elapsed time of its
//! delay timer (the manual's "ExpiredTime" in the FRAM). The library has no storage of its
//! own: the host reads the value with `sl_ton2_get_elapsed` after its cycles, persists it,
//! and hands it back with `sl_ton2_restore_elapsed` after power-up (after `sl_ton2_init`,
//! before the first cycle with bRun TRUE). With SL_OPT_TON2_REMAINING_TIME set and Enable
//! TRUE when TonIn rises, the delay starts with the remaining time; a stored elapsed time
//! greater than the delay is the manual's global shutdown (error code 0x3510): ERROR with
//! diag bit 12 and SL_E_RESTORE. States RUN (1), STOP (2), SAFE (3), DELAYIN (9).
//! docs/semantics.md T10–T17.

use super::timer::{SL_DIAG_TON2_RESTORE, SL_OPT_TON2_REMAINING_TIME, SL_TIMER_PRIVATE};
use crate::base::block::BlockInfo;
use crate::base::envelope::{self, Block, Instance};
use crate::base::header::F_CFG_INVALID;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/ton2.rs"));

/// Type tag, name, states and diag texts (manual §4.13.2).
const INFO: BlockInfo = BlockInfo::of::<Ton2State>(SL_TYPE_TON2, "TON2").diag(&[(
    SL_DIAG_TON2_RESTORE,
    "restored elapsed time refused (greater than the delay time: global shutdown 0x3510)",
)]);

crate::impl_member!([] FB_TON2 {
    info: INFO,
    state: Ton2State,
    private: SL_TIMER_PRIVATE,
    input: [bTonIn1, bEnable],
    param: [tDelay, nTimeBase, wInputActive, wInputNegated, dwOptions],
    output: [bTonOut],
    info_fields: [],
});

/// `sl_ton2_get_elapsed`: the stored elapsed time in ms, to be persisted by the host
/// (docs/semantics.md T11, T15). Any state; 0 for a never-initialised instance;
/// `Err(SL_E_CORRUPT)` when the private head or the stored value fails its check (nothing
/// to persist then; the next cycle puts the block into ERROR). Does not modify the block.
pub fn elapsed(fb: &FB_TON2) -> Result<u32, Status> {
    let p = &fb.stPrivate;
    if p.stHeader.is_zero() {
        return Ok(0);
    }
    if !p.stHeader.intact(<FB_TON2 as Block>::MAGIC) || !p.elapsed_intact() {
        return Err(Status::Corrupt);
    }
    Ok(p.tElapsed)
}

/// `sl_ton2_restore_elapsed`: hands back the elapsed time persisted before a power cycle
/// (docs/semantics.md T13, T14). Allowed while the block is in STOP with valid latched
/// parameters: after `sl_ton2_init` and before the first cycle with bRun TRUE (or while the
/// block is stopped). A never-initialised instance is initialised first.
///
/// - `SL_OK`: stored; it is used when TonIn next rises with Enable TRUE and the option set.
/// - `SL_E_CONFIG`: the latched parameters are invalid; nothing stored, block in STOP.
/// - `SL_E_RESTORE`: `elapsed_ms` > the latched tDelay (global shutdown 0x3510), or the
///   block was not in STOP: ERROR with diag bit 12, the stored value is discarded (0).
/// - `SL_E_CORRUPT`: the private state failed its check: ERROR with diag bit 15, the stored
///   value is discarded (0).
pub fn restore_elapsed(fb: &mut FB_TON2, elapsed_ms: u32) -> Status {
    if fb.header().is_zero() {
        let status = envelope::init(fb);
        if status != Status::Ok {
            return status;
        }
    }
    // The stored time changes outside a cycle: the next call takes the full cycle.
    fb.forget_key();
    let crc = fb.latched_crc();
    let p = &mut fb.stPrivate;
    if !p.stHeader.intact(<FB_TON2 as Block>::MAGIC)
        || !p.timers_intact()
        || crc != p.stHeader.wParamCrc
    {
        p.repair_timers();
        envelope::force_error(fb);
        return Status::Corrupt;
    }
    if p.stHeader.flag(F_CFG_INVALID) {
        return Status::Config;
    }
    if p.stHeader.nState != SL_STATE_STOP || elapsed_ms > p.dwDelay {
        p.set_elapsed(0);
        p.stHeader.enter_error(SL_DIAG_TON2_RESTORE);
        fb.write_outputs();
        fb.header_mut().seal();
        return Status::Restore;
    }
    p.set_elapsed(elapsed_ms);
    Status::Ok
}

super::timer::timer_block!(FB_TON2 {
    tag: 0x7014,
    off_delay: false,
    persists: true,
    timing_state: SL_STATE_TON2_DELAYIN,
    input: bTonIn1,
    output: bTonOut,
    enable: bEnable,
    options: dwOptions = SL_OPT_TON2_REMAINING_TIME,
});
