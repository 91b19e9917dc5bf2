//! FB TOF — manual §4.14 (functional description 4.14.1, signals, states and diag 4.14.2,
//! EL6910 TOF extension with timebases 4.14.4; the 100 and 1000 ms timebases of the TON
//! extension 4.12.4 apply as well, ABI §9: up to 60,000 s): switch-off delay. TofOut is
//! TRUE while TofIn is TRUE and stays TRUE until TofIn has been FALSE for the delay time; a
//! TRUE TofIn before that keeps it on. bRun FALSE (STOP) and ERROR switch it off at once.
//! States RUN (1), STOP (2), SAFE (3), DELAYOUT (8); the manual's diag value is always 0.
//! The state machine is the shared timer (`timer`, docs/semantics.md T1–T5, T7–T9, T16).

use super::timer::{delay_block, delay_struct};
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/tof.rs"));

delay_struct! {
    /// FB TOF instance (ABI §3, §9). Input at the manual's offset (§4.14.2), output base 32.
    /// Size: 112 bytes.
    FB_TOF: "Tof", "off", ["TRUE switches TofOut on at once; FALSE switches it off after the", " delay (break or make contact: wInputNegated bit 0)."], "RUN and DELAYOUT", "";
    bTofIn1 => bTofOut
}

delay_block! {
    /// The states of FB TOF.
    FB_TOF: TofState [DelayOut], SL_TYPE_TOF, "TOF"; magic 0x70F5, off_delay true, timing SL_STATE_DELAYOUT;
    bTofIn1 => bTofOut
}
