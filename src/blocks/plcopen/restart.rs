//! The restart-interlock machine of SF_EmergencyStop, SF_ESPE and SF_PSE (PLCopen TC5
//! Part 1; research `plcopen_safety.md` §4.1–§4.3, §5): one safety input, S_StartReset,
//! S_AutoReset, Reset, one safety output. "The functions of SF_ESPE and SF_EmergencyStop
//! FB are identical" (§4.2); SF_PSE has "the same code set and comments one-to-one" (§4.3)
//! and exists in v2.x only. The blocks differ in their field names only; each block's
//! file declares its struct and calls `restart_interlock_block!`.

use crate::base::sf::{ResetIn, SL_SF_PRIVATE};

include!(concat!(env!("OUT_DIR"), "/abi/blocks/plcopen/restart.rs"));

/// One call's inputs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RestartIn {
    /// The safety input (S_EStopIn, S_ESPE_In, S_PSE_In): FALSE = safety demand.
    pub input: bool,
    /// S_StartReset: automatic reset at activation.
    pub start_reset: bool,
    /// S_AutoReset: automatic reset after a safety demand.
    pub auto_reset: bool,
}

/// The transition table of research §4.1 (v2.01 codes), first matching guard wins. IDLE →
/// INIT is the envelope's (Activate).
pub fn next(s: RestartState, i: &RestartIn, r: ResetIn) -> RestartState {
    use RestartState::*;
    match s {
        Init if !i.start_reset => WaitIn1,
        Init if !i.input => WaitIn2,
        Init => Enabled,
        WaitIn1 if i.input => WaitReset1,
        WaitReset1 if r.held() => ErrReset1,
        WaitReset1 if !i.input => WaitIn1,
        WaitReset1 if r.rising => Enabled,
        ErrReset1 if !r.level => WaitReset1,
        WaitIn2 if i.input && !i.auto_reset => WaitReset2,
        WaitIn2 if i.input => Enabled,
        WaitReset2 if r.held() => ErrReset2,
        WaitReset2 if !i.input => WaitIn2,
        WaitReset2 if r.rising || i.auto_reset => Enabled,
        ErrReset2 if !r.level => WaitReset2,
        Enabled if !i.input => WaitIn2,
        Idle | WaitIn1 | WaitReset1 | ErrReset1 | WaitIn2 | WaitReset2 | ErrReset2 | Enabled => s,
    }
}

/// The struct of SF_EmergencyStop, SF_ESPE and SF_PSE, declared once: they differ in the
/// names of the safety input and output and the input's doc (`$in_doc`).
/// build.rs writes every invocation out for cbindgen (`build_support/expand.rs`).
#[macro_export]
#[doc(hidden)]
macro_rules! restart_interlock_struct {
    ($(#[doc = $doc:literal])* $name:ident: $input:ident $in_doc:literal => $output:ident) => {
        $crate::base::layout::block_struct! {
            $(#[doc = $doc])*
            $name {
                /// Offset 0. Activate: FALSE = idle (DiagCode 0000, every output FALSE), highest priority.
                pub Activate: SL_BOOL,
                #[doc = concat!(" Offset 1. ", stringify!($input), ": ", $in_doc)]
                pub $input: SL_BOOL,
                /// Offset 2. S_StartReset: TRUE = automatic reset at activation (start-up).
                pub S_StartReset: SL_BOOL,
                /// Offset 3. S_AutoReset: TRUE = automatic reset when the safety demand ends.
                pub S_AutoReset: SL_BOOL,
                /// Offset 4. Reset: a rising edge resets; held TRUE into a wait-for-reset state it is a static-reset error.
                pub Reset: SL_BOOL,
                /// Offset 5. Reserved, keep 0.
                pub aReserved0: [u8; 2],
                /// Offset 7. Library extension, constant: DiagCode profile, 0 = v2.01 (default), 1 = v1.0; latched at activation.
                pub nDiagProfile: u8,
                /// Offset 8 (output base). Ready: TRUE while activated (DiagCode != 0000).
                pub Ready: SL_BOOL,
                #[doc = concat!(" Offset 9. ", stringify!($output), ": the safety output, TRUE only at DiagCode 8000.")]
                pub $output: SL_BOOL,
                /// Offset 10. SafetyDemand: the safety function is demanded (v2.01 code bit 0x0800).
                pub SafetyDemand: SL_BOOL,
                /// Offset 11. ResetRequest: a reset is awaited (v2.01 code bit 0x0400) and Reset is FALSE.
                pub ResetRequest: SL_BOOL,
                /// Offset 12. Error: DiagCode >= C000.
                pub Error: SL_BOOL,
                /// Offset 13. Reserved.
                pub aReserved1: [u8; 1],
                /// Offset 14. DiagCode: the state or error, in the profile of nDiagProfile.
                pub DiagCode: u16,
            } private 16: $crate::base::sf::SL_SF_PRIVATE, 40
        }
    };
}

/// Declares a restart-interlock block's envelope plumbing from its struct: tag, the names
/// of its safety input and output, whether it exists in PLCopen v1.0.
#[macro_export]
#[doc(hidden)]
macro_rules! restart_interlock_block {
    ($ty:ident, $tag:expr, $input:ident, $output:ident, has_v10: $v10:expr) => {
        $crate::impl_sf_member!($ty {
            tag: $tag,
            input: [Activate, $input, S_StartReset, S_AutoReset, Reset],
            param: [nDiagProfile],
            output: [Ready, $output, SafetyDemand, ResetRequest, Error],
        });

        $crate::impl_sf_block!($ty {
            tag: $tag,
            diag: $crate::blocks::plcopen::restart::RestartState,
            input: $crate::blocks::plcopen::restart::RestartIn,
            reset: Reset,
            consts(s): [],
            next: |s, inp, reset, _in_state, _times| {
                $crate::blocks::plcopen::restart::next(s, inp, reset)
            },
        } {
            const HAS_V10: bool = $v10;
            #[inline(always)]
            fn decode(&self) -> (Self::In, bool) {
                let p =
                    $crate::base::bools::pack([self.$input, self.S_StartReset, self.S_AutoReset]);
                let v = $crate::base::bools::logical(p, 0b111, 0);
                (
                    $crate::blocks::plcopen::restart::RestartIn {
                        input: v & 1 != 0,
                        start_reset: v & 2 != 0,
                        auto_reset: v & 4 != 0,
                    },
                    p.invalid != 0,
                )
            }
            #[inline(always)]
            fn write_outputs(&mut self, o: &$crate::base::sf::SfOut) {
                $crate::sf_outputs!(self, o, $output, SafetyDemand, ResetRequest);
            }
        });
    };
}

/// The private state's size is part of every `SF_` struct's layout (ABI: 40 bytes).
const _: () = assert!(core::mem::size_of::<SL_SF_PRIVATE>() == 40);

/// The steady-state fast path of a restart-interlock block (`base::sf::SfSteady`): the
/// key is its five BOOL inputs; no state reads the time.
#[macro_export]
#[doc(hidden)]
macro_rules! restart_interlock_steady {
    ($ty:ident, $input:ident) => {
        $crate::sf_steady!($ty: [Activate, $input, S_StartReset, S_AutoReset, Reset]);
    };
}
