//! FB TON — manual §4.12 (functional description 4.12.1, signals, states and diag 4.12.2,
//! EL6910 TON extension with the timebases 1, 10, 100 and 1000 ms 4.12.4): switch-on delay.
//! TonOut becomes TRUE when TonIn has been TRUE for the delay time; TonIn FALSE switches it
//! off at once and discards the running delay. States RUN (1), STOP (2), SAFE (3), DELAYIN
//! (9); the manual's diag value is always 0. The state machine is the shared timer
//! (`timer`, docs/semantics.md T1–T6, T8, T9, T16).

use super::timer::{delay_block, delay_struct};
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/ton.rs"));

delay_struct! {
    /// FB TON instance (ABI §3, §9). Input at the manual's offset (§4.12.2), output base 32.
    /// Size: 112 bytes.
    FB_TON: "Ton", "on", ["the input whose TRUE level is passed on after the delay (break or", " make contact: wInputNegated bit 0)."], "RUN only", ", SL_STATE_TON_DELAYIN";
    bTonIn1 => bTonOut
}

delay_block! {
    /// The states of FB TON.
    FB_TON: TonState [DelayIn = SL_STATE_TON_DELAYIN, "DELAYIN"], SL_TYPE_TON, "TON"; magic 0x7013, off_delay false, timing SL_STATE_TON_DELAYIN;
    bTonIn1 => bTonOut
}
