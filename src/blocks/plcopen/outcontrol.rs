//! SF_OutControl — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.13, DiagCodes §5):
//! drives a safety output from a signal of the standard application (`ProcessControl`)
//! and a safety signal (`S_SafeControl`, from preceding SF_ blocks), with the start-up
//! inhibit (S_StartReset) and the restart inhibit after a triggered safety function
//! (S_AutoReset), both left by a rising edge of Reset. `StaticControl` (a constant) FALSE
//! requires a rising edge of ProcessControl after the activation and after every inhibit;
//! a ProcessControl that is already TRUE then is the error C010 (docs/semantics.md
//! QO1–QO6).

use crate::base::bools;
use crate::base::header::F_ERRACK_PREV;
use crate::base::sf::{ResetIn, SfOut, SL_SF_PRIVATE};
use crate::base::types::SL_BOOL;

/// Block type tag of SF_OutControl (`SL_MEMBER.nType`, `sl_diag_text`).
pub const SL_TYPE_SF_OUTCONTROL: u16 = 519;

/// The R_TRIG memory of ProcessControl in the private header's flags: the PLCopen family
/// has no ErrAck, whose bit it takes (semantics QO5).
const F_PROCESS_PREV: u8 = F_ERRACK_PREV;

crate::sf_states!(
    /// The states of SF_OutControl: values = v2.01 DiagCodes (CS-LIB FBS_OUTCONTROL), with
    /// the v1.0 codes of research §4.13 (recollection, unverified: semantics QO6).
    OutControlState, init: Init {
        Idle = 0x0000, 0x0000, "IDLE", "FB not activated";
        Init = 0x8401, 0x8001, "INIT", "activated: start-up inhibit active, a rising edge of Reset (or S_StartReset) is required";
        Safe = 0x8802, 0x8002, "SAFE", "safety function triggered (S_SafeControl FALSE)";
        Lock = 0x8404, 0x8003, "LOCK", "restart inhibit after the safety function: a rising edge of Reset is required";
        OutputDisable = 0x8006, 0x8010, "OUTPUT_DISABLE", "safety enabled, ProcessControl not active (or waiting for its rising edge)";
        OutputEnable = 0x8000, 0x8000, "OUTPUT_ENABLE", "ProcessControl active and safety enabled, S_OutControl TRUE";
        ErrReset1 = 0xC001, 0xC001, "ERR_RESET_1", "static Reset in INIT";
        ErrReset2 = 0xC011, 0xC002, "ERR_RESET_2", "static Reset in LOCK";
        ErrControl = 0xC010, 0xC010, "ERR_CONTROL", "static ProcessControl in OUTPUT_DISABLE with StaticControl FALSE (a rising edge is required)";
        ErrInit = 0xC020, 0xC011, "ERR_INIT", "rising edges of Reset and ProcessControl in the same call in INIT";
        ErrLock = 0xC030, 0xC111, "ERR_LOCK", "rising edges of Reset and ProcessControl in the same call in LOCK";
    }
);

/// One call's inputs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OutControlIn {
    /// S_SafeControl: TRUE = the safety function is not triggered.
    pub safe: bool,
    /// ProcessControl: the standard application requests the output.
    pub process: bool,
    /// R_TRIG(ProcessControl).Q of this call.
    pub process_rising: bool,
    /// S_StartReset: automatic reset at activation.
    pub start_reset: bool,
    /// S_AutoReset: automatic reset after the safety function.
    pub auto_reset: bool,
}

crate::base::layout::block_struct! {
    /// SF_OutControl instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
    /// Size: 56 bytes.
    SF_OutControl {
        /// Offset 0. Activate: FALSE = idle (DiagCode 0000, every output FALSE), highest priority.
        pub Activate: SL_BOOL,
        /// Offset 1. S_SafeControl: from the preceding safety blocks, FALSE = safety function triggered.
        pub S_SafeControl: SL_BOOL,
        /// Offset 2. ProcessControl: from the standard application, TRUE = output requested.
        pub ProcessControl: SL_BOOL,
        /// Offset 3. StaticControl (constant): FALSE = a rising edge of ProcessControl is required after activation and after an inhibit; latched at activation.
        pub StaticControl: SL_BOOL,
        /// Offset 4. S_StartReset: TRUE = automatic reset at activation (no start-up inhibit).
        pub S_StartReset: SL_BOOL,
        /// Offset 5. S_AutoReset: TRUE = automatic reset when S_SafeControl is TRUE again (no restart inhibit).
        pub S_AutoReset: SL_BOOL,
        /// Offset 6. Reset: a rising edge leaves an inhibit; held TRUE into it, a static-reset error.
        pub Reset: SL_BOOL,
        /// Offset 7. Library extension, constant: DiagCode profile, 0 = v2.01 (default), 1 = v1.0; latched at activation.
        pub nDiagProfile: u8,
        /// Offset 8 (output base). Ready: TRUE while activated (DiagCode != 0000).
        pub Ready: SL_BOOL,
        /// Offset 9. S_OutControl: the safety output, TRUE only at DiagCode 8000.
        pub S_OutControl: SL_BOOL,
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
    } private 16: SL_SF_PRIVATE, 40
}

crate::impl_sf_member!(SF_OutControl {
    tag: SL_TYPE_SF_OUTCONTROL,
    input: [
        Activate,
        S_SafeControl,
        ProcessControl,
        S_StartReset,
        S_AutoReset,
        Reset
    ],
    param: [StaticControl, nDiagProfile],
    output: [Ready, S_OutControl, SafetyDemand, ResetRequest, Error],
});

crate::impl_sf_block!(SF_OutControl {
    tag: SL_TYPE_SF_OUTCONTROL,
    diag: OutControlState,
    input: OutControlIn,
    reset: Reset,
    // StaticControl is latched as the envelope's first constant: 0 or 1, an invalid byte
    // as a value above `SL_SF_TIME_MAX`, refused at activation (C3FC; semantics QO4).
    consts(s): [crate::base::sf::bool_const(s.StaticControl)],
    rules: [crate::base::sf::bool0_rule("StaticControl")],
} {
    #[inline(always)]
    fn decode(&self) -> (OutControlIn, bool) {
        let p = bools::pack([
            self.S_SafeControl,
            self.ProcessControl,
            self.S_StartReset,
            self.S_AutoReset,
        ]);
        let v = bools::logical(p, 0b1111, 0);
        (
            OutControlIn {
                safe: v & 1 != 0,
                process: v & 2 != 0,
                process_rising: false,
                start_reset: v & 4 != 0,
                auto_reset: v & 8 != 0,
            },
            p.invalid != 0,
        )
    }
    /// The R_TRIG of ProcessControl runs in every call, like Reset's.
    #[inline(always)]
    fn decode_edges(&mut self) -> (OutControlIn, bool) {
        let (mut inp, invalid) = self.decode();
        let pc = bools::edge(
            self.ProcessControl,
            &mut self.stPrivate.stHeader.nFlags,
            F_PROCESS_PREV,
        );
        inp.process_rising = pc.rising;
        (inp, invalid)
    }
    /// Research §4.13's v2.01 state machine (derived from the code comments), first
    /// matching guard wins (semantics QO1–QO3).
    fn next(
        s: OutControlState,
        i: &OutControlIn,
        r: ResetIn,
        _in_state: u32,
        consts: [u32; 2],
    ) -> OutControlState {
        use OutControlState::*;
        let static_control = consts[0] == 1;
        match s {
            Init if i.start_reset => OutputDisable,
            Init if r.held() => ErrReset1,
            Init if r.rising && i.process_rising => ErrInit,
            Init if r.rising => OutputDisable,
            ErrReset1 if !r.level => Init,
            OutputDisable if !i.safe => Safe,
            OutputDisable if i.process_rising || (static_control && i.process) => OutputEnable,
            OutputDisable if i.process => ErrControl,
            OutputEnable if !i.safe => Safe,
            OutputEnable if !i.process => OutputDisable,
            Safe if i.safe && i.auto_reset => OutputDisable,
            Safe if i.safe => Lock,
            Lock if !i.safe => Safe,
            Lock if r.held() => ErrReset2,
            Lock if r.rising && i.process_rising => ErrLock,
            Lock if r.rising => OutputDisable,
            ErrReset2 if !r.level => Lock,
            ErrControl if !i.process => OutputDisable,
            ErrInit if !r.level && !i.process => Init,
            ErrLock if !r.level && !i.process => Lock,
            Idle | Init | Safe | Lock | OutputDisable | OutputEnable | ErrReset1 | ErrReset2
            | ErrControl | ErrInit | ErrLock => s,
        }
    }
    #[inline(always)]
    fn write_outputs(&mut self, o: &SfOut) {
        crate::sf_outputs!(self, o, S_OutControl, SafetyDemand, ResetRequest);
    }
});

// The steady-state fast path (`base::sf::SfSteady`): the key is every BOOL byte the call
// reads; no state reads the time.
crate::sf_steady!(
    SF_OutControl: [Activate, S_SafeControl, ProcessControl,
        StaticControl, S_StartReset, S_AutoReset, Reset]
);
