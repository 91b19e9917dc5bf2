//! SF_SafetyRequest — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.14, DiagCodes
//! §5): the interface to a generic safety actuator (safety drive, valve). The block
//! requests the safe state (`S_SafetyRequest` FALSE) when `S_OpMode` goes FALSE, monitors
//! the actuator's acknowledgement `S_Acknowledge` within MonitoringTime (a constant) and
//! sets `S_SafetyActive` while the safe state is confirmed; the safety function itself is
//! the actuator's. Errors (acknowledgement lost, time elapsed) need a rising edge of Reset
//! and then `S_OpMode` TRUE (docs/semantics.md QR1–QR6).

use crate::base::bools;
use crate::base::sf::{ResetIn, SfOut, SL_SF_PRIVATE};
use crate::base::time;
use crate::base::types::SL_BOOL;

/// Block type tag of SF_SafetyRequest (`SL_MEMBER.nType`, `sl_diag_text`).
pub const SL_TYPE_SF_SAFETYREQUEST: u16 = 518;

crate::sf_states!(
    /// The states of SF_SafetyRequest: values = v2.01 DiagCodes (CS-LIB FBS_SAFEREQ), with
    /// the v1.0 codes (research §4.14; ERR_RESET_1's v1.0 code is ours, semantics QR2).
    SafetyRequestState, init: Init {
        Idle = 0x0000, 0x0000, "IDLE", "FB not activated";
        Init = 0x8401, 0x8001, "INIT", "activated or after Activate: waiting for a rising edge of Reset (or S_StartReset), then S_Acknowledge is evaluated";
        SafeMode = 0x8000, 0x8000, "SAFE_MODE", "actuator in the safe state confirmed, S_SafetyActive TRUE";
        OpMode = 0x8802, 0x8002, "OP_MODE", "operation mode: S_SafetyRequest TRUE, the actuator does not acknowledge the safe state";
        WaitConfOpMode = 0x8804, 0x8012, "WAIT_FOR_CONF_OPMODE", "operation mode requested (S_SafetyRequest TRUE), the actuator still acknowledges the safe state";
        WaitConf = 0x8002, 0x8003, "WAIT_FOR_CONF", "safe state requested, waiting for S_Acknowledge; MonitoringTime running";
        WaitOpMode = 0x8004, 0x8005, "WAIT_FOR_OPMODE", "error reset: waiting for S_OpMode TRUE";
        ErrReset1 = 0xC001, 0xC001, "ERR_RESET_1", "static Reset in INIT";
        ErrAckLost = 0xC010, 0xC002, "ERR_ACK_LOST", "S_Acknowledge lost while the safe state was confirmed";
        ErrMonTime = 0xC020, 0xC003, "ERR_MONTIME", "S_Acknowledge not TRUE within MonitoringTime after the safe state was requested";
        ErrReset2 = 0xC014, 0xC004, "ERR_RESET_2", "static Reset in ERR_ACK_LOST";
        ErrReset3 = 0xC011, 0xC005, "ERR_RESET_3", "static Reset in ERR_MONTIME";
    }
);

/// One call's inputs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SafetyRequestIn {
    /// S_OpMode: TRUE = operation mode requested, FALSE = safe mode requested.
    pub op_mode: bool,
    /// S_Acknowledge: TRUE = the actuator confirms its safe state.
    pub ack: bool,
    /// S_StartReset: automatic reset at activation.
    pub start_reset: bool,
}

crate::base::layout::block_struct! {
    /// SF_SafetyRequest instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
    /// Size: 64 bytes.
    SF_SafetyRequest {
        /// Offset 0. Activate: FALSE = idle (DiagCode 0000, every output FALSE), highest priority.
        pub Activate: SL_BOOL,
        /// Offset 1. S_OpMode: requested mode, TRUE = operation mode, FALSE = safe mode requested.
        pub S_OpMode: SL_BOOL,
        /// Offset 2. S_Acknowledge: the actuator's confirmation, TRUE = actuator in its safe state.
        pub S_Acknowledge: SL_BOOL,
        /// Offset 3. Library extension, constant: DiagCode profile, 0 = v2.01 (default), 1 = v1.0; latched at activation.
        pub nDiagProfile: u8,
        /// Offset 4. MonitoringTime (constant, ms): longest time from the safe-state request to S_Acknowledge TRUE; latched at activation.
        pub MonitoringTime: u32,
        /// Offset 8. S_StartReset: TRUE = automatic reset at activation (start-up; v2.x input, keep FALSE for the v1.0 behaviour).
        pub S_StartReset: SL_BOOL,
        /// Offset 9. Reset: a rising edge resets INIT and the errors; held TRUE it is a static-reset error.
        pub Reset: SL_BOOL,
        /// Offset 10. Reserved, keep 0.
        pub aReserved0: [u8; 6],
        /// Offset 16 (output base). Ready: TRUE while activated (DiagCode != 0000).
        pub Ready: SL_BOOL,
        /// Offset 17. S_SafetyActive: the safe state of the actuator is confirmed, TRUE only at DiagCode 8000.
        pub S_SafetyActive: SL_BOOL,
        /// Offset 18. S_SafetyRequest: to the actuator, FALSE = safe state requested; TRUE only in OP_MODE / WAIT_FOR_CONF_OPMODE (8802 / 8804).
        pub S_SafetyRequest: SL_BOOL,
        /// Offset 19. SafetyDemand: v2.01 code bit 0x0800 (8802, 8804).
        pub SafetyDemand: SL_BOOL,
        /// Offset 20. ResetRequest: a reset is awaited (v2.01 code bit 0x0400: INIT) and Reset is FALSE.
        pub ResetRequest: SL_BOOL,
        /// Offset 21. Error: DiagCode >= C000.
        pub Error: SL_BOOL,
        /// Offset 22. DiagCode: the state or error, in the profile of nDiagProfile.
        pub DiagCode: u16,
    } private 24: SL_SF_PRIVATE, 40
}

crate::impl_sf_member!(SF_SafetyRequest {
    tag: SL_TYPE_SF_SAFETYREQUEST,
    input: [Activate, S_OpMode, S_Acknowledge, S_StartReset, Reset],
    param: [nDiagProfile, MonitoringTime],
    output: [
        Ready,
        S_SafetyActive,
        S_SafetyRequest,
        SafetyDemand,
        ResetRequest,
        Error
    ],
});

crate::impl_sf_block!(SF_SafetyRequest {
    tag: SL_TYPE_SF_SAFETYREQUEST,
    diag: SafetyRequestState,
    input: SafetyRequestIn,
    reset: Reset,
    consts(s): [s.MonitoringTime],
    rules: [crate::base::sf::time0_rule("MonitoringTime")],
} {
    #[inline(always)]
    fn decode(&self) -> (SafetyRequestIn, bool) {
        let p = bools::pack([self.S_OpMode, self.S_Acknowledge, self.S_StartReset]);
        let v = bools::logical(p, 0b111, 0);
        (
            SafetyRequestIn {
                op_mode: v & 1 != 0,
                ack: v & 2 != 0,
                start_reset: v & 4 != 0,
            },
            p.invalid != 0,
        )
    }
    /// Research §4.14's table (v2.01 codes), first matching guard wins, with v2.01's
    /// static-reset check and S_StartReset in INIT (semantics QR1, QR2); MonitoringTime runs
    /// from the entry into WAIT_FOR_CONF and comes first there (T#0: at the first
    /// evaluation, QR4).
    fn next(
        s: SafetyRequestState,
        i: &SafetyRequestIn,
        r: ResetIn,
        in_state: u32,
        times: [u32; 2],
    ) -> SafetyRequestState {
        use SafetyRequestState::*;
        let elapsed = time::reached(in_state, 0, times[0]);
        match s {
            Init if i.start_reset && !i.ack => OpMode,
            Init if i.start_reset => WaitConfOpMode,
            Init if r.held() => ErrReset1,
            Init if r.rising && !i.ack => OpMode,
            Init if r.rising => WaitConfOpMode,
            ErrReset1 if !r.level => Init,
            OpMode if !i.op_mode => WaitConf,
            OpMode if i.ack => WaitConfOpMode,
            WaitConfOpMode if !i.ack => OpMode,
            WaitConfOpMode if !i.op_mode => WaitConf,
            WaitConf if elapsed => ErrMonTime,
            WaitConf if i.op_mode => WaitConfOpMode,
            WaitConf if i.ack => SafeMode,
            SafeMode if !i.ack => ErrAckLost,
            SafeMode if i.op_mode => WaitConfOpMode,
            ErrAckLost if r.held() => ErrReset2,
            ErrAckLost if r.rising => WaitOpMode,
            ErrMonTime if r.held() => ErrReset3,
            ErrMonTime if r.rising => WaitOpMode,
            ErrReset2 if !r.level => ErrAckLost,
            ErrReset3 if !r.level => ErrMonTime,
            WaitOpMode if i.op_mode => WaitConfOpMode,
            Idle | Init | SafeMode | OpMode | WaitConfOpMode | WaitConf | WaitOpMode
            | ErrReset1 | ErrAckLost | ErrMonTime | ErrReset2 | ErrReset3 => s,
        }
    }
    #[inline(always)]
    fn write_outputs(&mut self, o: &SfOut) {
        // The request to leave the safe state follows the state too (the header holds it,
        // a library code included: then FALSE).
        let request = matches!(
            self.diag_state(),
            Some(SafetyRequestState::OpMode | SafetyRequestState::WaitConfOpMode)
        );
        crate::sf_outputs!(
            self,
            o,
            S_SafetyActive + S_SafetyRequest = request,
            SafetyDemand,
            ResetRequest
        );
    }
});

// The steady-state fast path (`base::sf::SfSteady`): the key is the five BOOL inputs;
// WAIT_FOR_CONF reads the monitoring time.
crate::sf_steady!(
    SF_SafetyRequest: [Activate, S_OpMode, S_Acknowledge, S_StartReset, Reset],
    timed: SafetyRequestState::{WaitConf}
);
