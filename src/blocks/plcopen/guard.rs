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

/// Block type tag of SF_Guard (`SL_MEMBER.nType`, `sl_diag_text`).
pub const SL_TYPE_SF_GUARD: u16 = 517;

crate::sf_states!(
    /// The states of SF_Guard: values = v2.01 DiagCodes (CS-LIB FBS_GUARD), with the v1.0
    /// codes of SF_GuardMonitoring (research §4.4).
    SfGuardState, init: Init {
        Idle = 0x0000, 0x0000, "IDLE", "FB not activated";
        Init = 0x8001, 0x8001, "INIT", "activated; checks the switches and S_StartReset";
        Normal = 0x8000, 0x8000, "NORMAL", "guard closed and the safe state acknowledged, S_GuardOut TRUE";
        OpenStart = 0x8802, 0x8002, "OPEN_START", "a guard switch is open: a complete opening (both switches FALSE) is required";
        GuardOpened = 0x8804, 0x8012, "GUARD_OPENED", "both guard switches open";
        WaitSwitch2 = 0x8806, 0x8004, "WAIT_FOR_SWITCH2", "S_GuardSwitch1 closed, waiting for S_GuardSwitch2; discrepancy timer running";
        WaitSwitch1 = 0x8808, 0x8014, "WAIT_FOR_SWITCH1", "S_GuardSwitch2 closed, waiting for S_GuardSwitch1; discrepancy timer running";
        GuardClosed = 0x8002, 0x8005, "GUARD_CLOSED", "guard closed; S_AutoReset decides whether a Reset is awaited";
        WaitReset = 0x8402, 0x8003, "WAIT_FOR_RESET", "guard closed, waiting for a rising edge of Reset";
        ErrReset = 0xC001, 0xC001, "ERR_RESET", "static Reset while waiting for the reset";
        ErrDisc1 = 0xC010, 0xC011, "ERR_DISC_TIME_1", "DiscrepancyTime elapsed waiting for S_GuardSwitch2";
        ErrDisc2 = 0xC020, 0xC012, "ERR_DISC_TIME_2", "DiscrepancyTime elapsed waiting for S_GuardSwitch1";
    }
);

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

crate::base::layout::block_struct! {
    /// SF_Guard instance (v1.0: SF_GuardMonitoring, whose output S_GuardMonitoring is
    /// `S_GuardOut` here): the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
    /// Size: 64 bytes.
    SF_Guard {
        /// Offset 0. Activate: FALSE = idle (DiagCode 0000, every output FALSE), highest priority.
        pub Activate: SL_BOOL,
        /// Offset 1. S_GuardSwitch1: guard switch 1, FALSE = guard open.
        pub S_GuardSwitch1: SL_BOOL,
        /// Offset 2. S_GuardSwitch2: guard switch 2, FALSE = guard open (bridge it to S_GuardSwitch1 for a guard with one switch).
        pub S_GuardSwitch2: SL_BOOL,
        /// Offset 3. Library extension, constant: DiagCode profile, 0 = v2.01 (default), 1 = v1.0 (SF_GuardMonitoring); latched at activation.
        pub nDiagProfile: u8,
        /// Offset 4. DiscrepancyTime (constant, ms): how long the switches may differ while the guard closes; latched at activation.
        pub DiscrepancyTime: u32,
        /// Offset 8. S_StartReset: TRUE = automatic reset at activation (start-up).
        pub S_StartReset: SL_BOOL,
        /// Offset 9. S_AutoReset: TRUE = automatic reset when the guard is closed again.
        pub S_AutoReset: SL_BOOL,
        /// Offset 10. Reset: a rising edge resets; held TRUE into the wait-for-reset state it is a static-reset error.
        pub Reset: SL_BOOL,
        /// Offset 11. Reserved, keep 0.
        pub aReserved0: [u8; 5],
        /// Offset 16 (output base). Ready: TRUE while activated (DiagCode != 0000).
        pub Ready: SL_BOOL,
        /// Offset 17. S_GuardOut: the safety output (v1.0: S_GuardMonitoring), TRUE only at DiagCode 8000.
        pub S_GuardOut: SL_BOOL,
        /// Offset 18. SafetyDemand: the safety function is demanded (v2.01 code bit 0x0800).
        pub SafetyDemand: SL_BOOL,
        /// Offset 19. ResetRequest: a reset is awaited (v2.01 code bit 0x0400) and Reset is FALSE.
        pub ResetRequest: SL_BOOL,
        /// Offset 20. Error: DiagCode >= C000.
        pub Error: SL_BOOL,
        /// Offset 21. Reserved.
        pub aReserved1: [u8; 1],
        /// Offset 22. DiagCode: the state or error, in the profile of nDiagProfile.
        pub DiagCode: u16,
    } private 24: SL_SF_PRIVATE, 40
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
