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

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/plcopen/outcontrol.rs"
));

/// The R_TRIG memory of ProcessControl in the private header's flags: the PLCopen family
/// has no ErrAck, whose bit it takes (semantics QO5).
const F_PROCESS_PREV: u8 = F_ERRACK_PREV;

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
