//! SF_Guard — PLCopen TC5 Part 1 v2.x (v1.0 name SF_GuardMonitoring; research
//! `plcopen_safety.md` §4.4, DiagCodes §5): monitors a guard (door) with two switches, a
//! two-stage interlock without guard locking. The guard output goes FALSE as soon as one
//! switch opens; to close again, both switches must first have been open and then close
//! within DiscrepancyTime (a constant; only the closing is time-monitored), then the
//! restart interlock (S_AutoReset or a rising edge of Reset). One struct for both PLCopen
//! versions: the v2.01 names (`S_GuardOut`), the v1.0 DiagCodes per instance
//! (`nDiagProfile`; docs/semantics.md QG1–QG5).

use crate::base::bools;
use crate::base::sf::{ResetIn, SfOut, SL_SF_PRIVATE};
use crate::base::time;
use crate::base::types::SL_BOOL;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/plcopen/guard.rs"));

/// One call's inputs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SfGuardIn {
    /// S_GuardSwitch1 closed.
    pub s1: bool,
    /// S_GuardSwitch2 closed.
    pub s2: bool,
    /// S_StartReset: automatic reset at activation.
    pub start_reset: bool,
    /// S_AutoReset: automatic reset when the guard is closed again.
    pub auto_reset: bool,
}

crate::impl_sf_member!(SF_Guard {
    tag: SL_TYPE_SF_GUARD,
    input: [
        Activate,
        S_GuardSwitch1,
        S_GuardSwitch2,
        S_StartReset,
        S_AutoReset,
        Reset
    ],
    param: [nDiagProfile, DiscrepancyTime],
    output: [Ready, S_GuardOut, SafetyDemand, ResetRequest, Error],
});

crate::impl_sf_block!(SF_Guard {
    tag: SL_TYPE_SF_GUARD,
    diag: SfGuardState,
    input: SfGuardIn,
    reset: Reset,
    consts(s): [s.DiscrepancyTime],
    rules: [crate::base::sf::time0_rule("DiscrepancyTime")],
} {
    #[inline(always)]
    fn decode(&self) -> (SfGuardIn, bool) {
        let p = bools::pack([
            self.S_GuardSwitch1,
            self.S_GuardSwitch2,
            self.S_StartReset,
            self.S_AutoReset,
        ]);
        let v = bools::logical(p, 0b1111, 0);
        (
            SfGuardIn {
                s1: v & 1 != 0,
                s2: v & 2 != 0,
                start_reset: v & 4 != 0,
                auto_reset: v & 8 != 0,
            },
            p.invalid != 0,
        )
    }
    /// Research §4.4's table (v2.01 codes), first matching guard wins; the discrepancy
    /// time runs from the entry into 8806 / 8808 and comes before every other guard there
    /// (T#0: at the first evaluation, semantics QG2).
    fn next(
        s: SfGuardState,
        i: &SfGuardIn,
        r: ResetIn,
        in_state: u32,
        times: [u32; 2],
    ) -> SfGuardState {
        use SfGuardState::*;
        let closed = i.s1 && i.s2;
        let open = !i.s1 && !i.s2;
        let elapsed = time::reached(in_state, 0, times[0]);
        match s {
            Init if !closed => OpenStart,
            Init if !i.start_reset => WaitReset,
            Init => Normal,
            OpenStart if open => GuardOpened,
            GuardOpened if i.s1 => WaitSwitch2,
            GuardOpened if i.s2 => WaitSwitch1,
            WaitSwitch2 if elapsed => ErrDisc1,
            WaitSwitch2 if !i.s1 => OpenStart,
            WaitSwitch2 if i.s2 => GuardClosed,
            WaitSwitch1 if elapsed => ErrDisc2,
            WaitSwitch1 if !i.s2 => OpenStart,
            WaitSwitch1 if i.s1 => GuardClosed,
            GuardClosed if !closed => OpenStart,
            GuardClosed if !i.auto_reset => WaitReset,
            GuardClosed => Normal,
            WaitReset if r.held() => ErrReset,
            WaitReset if !closed => OpenStart,
            WaitReset if r.rising => Normal,
            ErrReset if !r.level => WaitReset,
            ErrDisc1 | ErrDisc2 if open => GuardOpened,
            Normal if !closed => OpenStart,
            Idle | Normal | OpenStart | GuardOpened | WaitSwitch2 | WaitSwitch1 | WaitReset
            | ErrReset | ErrDisc1 | ErrDisc2 => s,
        }
    }
    #[inline(always)]
    fn write_outputs(&mut self, o: &SfOut) {
        crate::sf_outputs!(self, o, S_GuardOut, SafetyDemand, ResetRequest);
    }
});

// The steady-state fast path (`base::sf::SfSteady`): the key is the six BOOL inputs; the
// states waiting for the second switch read the discrepancy time.
crate::sf_steady!(
    SF_Guard: [Activate, S_GuardSwitch1, S_GuardSwitch2, S_StartReset, S_AutoReset, Reset],
    timed: SfGuardState::{WaitSwitch1, WaitSwitch2}
);
