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

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/plcopen/safetyrequest.rs"
));

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
