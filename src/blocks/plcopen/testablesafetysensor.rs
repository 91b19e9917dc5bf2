//! SF_TestableSafetySensor — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.15, §5,
//! §8.4): a testable single-channel sensor (type 2 ESPE) with a restart interlock and a
//! periodic automatic test. A rising edge of StartTest switches the sensor's transmitter
//! off (S_TestOut FALSE); its OSSD must drop within TestTime, and come back within TestTime
//! after S_TestOut is TRUE again; S_OSSD_Out stays TRUE during the test. After a failed
//! test a manual switching sequence of the sensor is required unless NoExternalTest. The
//! codes the research leaves open are chosen in docs/semantics.md QT1–QT9.

use crate::base::reason::rule;
use crate::base::reason::RuleDef;
use crate::base::sf::{self, ResetIn, SL_SF_PRIVATE};
use crate::base::time;
use crate::base::types::SL_BOOL;

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/plcopen/testablesafetysensor.rs"
));

/// One call's inputs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TssIn {
    /// S_OSSD_In: TRUE = sensor free.
    pub ossd: bool,
    /// R_TRIG(StartTest).Q.
    pub start_test: bool,
    /// S_StartReset.
    pub start_reset: bool,
    /// S_AutoReset.
    pub auto_reset: bool,
}

/// The transition table of research §4.15 with the readings of semantics QT1–QT9, first
/// matching guard wins. `t` = [TestTime, NoExternalTest (1 = TRUE)], latched; TestTime runs
/// from the entry into 8020 / 8030 (`in_state`, ms). IDLE → 8401 / C000 is the envelope's.
fn next(s: TssState, i: &TssIn, r: ResetIn, in_state: u32, t: [u32; 2]) -> TssState {
    use TssState::*;
    let elapsed = time::reached(in_state, 0, t[0]);
    let no_external_test = t[1] == 1;
    match s {
        Init if !i.ossd => Interrupted1,
        Init if i.start_reset => FreeNoTest,
        Init if r.held() => ErrReset1,
        Init if r.rising => FreeNoTest,
        ErrReset1 if !r.level => Init,
        Interrupted1 if i.ossd && i.auto_reset => FreeNoTest,
        Interrupted1 if i.ossd => WaitReset1,
        WaitReset1 if r.held() => ErrReset2,
        WaitReset1 if !i.ossd => Interrupted1,
        WaitReset1 if r.rising => FreeNoTest,
        ErrReset2 if !r.level => WaitReset1,
        FreeNoTest if !i.ossd => Interrupted1,
        Enabled if !i.ossd => Interrupted2,
        FreeNoTest | Enabled if i.start_test => TestRequest,
        TestRequest if elapsed => ErrTest1,
        TestRequest if !i.ossd => TestActive,
        TestActive if elapsed => ErrTest2,
        TestActive if i.ossd => Enabled,
        Interrupted2 if i.ossd && i.auto_reset => Enabled,
        Interrupted2 if i.ossd => WaitReset2,
        WaitReset2 if r.held() => ErrReset3,
        WaitReset2 if !i.ossd => Interrupted2,
        WaitReset2 if r.rising => Enabled,
        ErrReset3 if !r.level => WaitReset2,
        ErrTest1 | ErrTest2 if i.ossd && r.rising && no_external_test => FreeNoTest,
        ErrTest1 | ErrTest2 if i.ossd && r.rising => ExtTest,
        ExtTest if !i.ossd => ExtTestInterrupted,
        ExtTestInterrupted if i.ossd => ExtTestEnd,
        ExtTestEnd if r.held() => ErrReset4,
        ExtTestEnd if !i.ossd => ExtTestInterrupted,
        ExtTestEnd if r.rising => FreeNoTest,
        ErrReset4 if !r.level => ExtTestEnd,
        Idle | Init | ErrReset1 | Interrupted1 | WaitReset1 | ErrReset2 | FreeNoTest
        | TestRequest | TestActive | Enabled | Interrupted2 | WaitReset2 | ErrReset3 | ExtTest
        | ExtTestInterrupted | ExtTestEnd | ErrReset4 | ErrParam | ErrTest1 | ErrTest2 => s,
    }
}

/// The block's own outputs of a v2.01 code (research §4.15; semantics QT5): S_OSSD_Out,
/// S_TestOut, TestPossible, TestExecuted. `library`: a library fault (every output FALSE).
pub const fn sensor_outputs(code: u16, library: bool) -> [bool; 4] {
    let free = matches!(code, 0x8000 | 0x8010);
    [
        free || matches!(code, 0x8020 | 0x8030),
        !library && code != 0x8020,
        free,
        code == 0x8000,
    ]
}

crate::impl_sf_member!(SF_TestableSafetySensor {
    tag: SL_TYPE_SF_TESTABLESAFETYSENSOR,
    input: [
        Activate,
        S_OSSD_In,
        StartTest,
        NoExternalTest,
        S_StartReset,
        S_AutoReset,
        Reset
    ],
    param: [nDiagProfile, TestTime],
    output: [
        Ready,
        S_OSSD_Out,
        S_TestOut,
        TestPossible,
        TestExecuted,
        SafetyDemand,
        ResetRequest,
        Error
    ],
});

crate::impl_sf_block!(SF_TestableSafetySensor {
    tag: SL_TYPE_SF_TESTABLESAFETYSENSOR,
    diag: TssState,
    input: TssIn,
    reset: Reset,
    // NoExternalTest is a constant too: latched as the second "time" (its raw byte, so a
    // change is C3FD; only 1 reads TRUE).
    consts(s): [s.TestTime, u32::from(s.NoExternalTest)],
    rules: [sf::time0_rule("TestTime")],
    next: |s, inp, reset, in_state, times| next(s, inp, reset, in_state, times),
} {
    /// TestTime ≤ 150 ms (C000 otherwise).
    const PARAM_RULES: &'static [RuleDef<sf::SfConsts>] =
        &[rule!(at_most "TestTime" in Ms, |c| c.times[0], SF_TSS_MAX_TEST_TIME)];
    /// An invalid byte reads FALSE (S_OSSD_In: the demand; NoExternalTest: the manual test).
    #[inline(always)]
    fn decode(&self) -> (Self::In, bool) {
        let p = crate::base::bools::pack([
            self.S_OSSD_In,
            self.S_StartReset,
            self.S_AutoReset,
            self.StartTest,
            self.NoExternalTest,
        ]);
        let v = crate::base::bools::logical(p, 0b11111, 0);
        (
            TssIn {
                ossd: v & 1 != 0,
                start_test: sf::trigger_rising(&self.stPrivate, self.StartTest),
                start_reset: v & 2 != 0,
                auto_reset: v & 4 != 0,
            },
            p.invalid != 0,
        )
    }
    fn first(times: [u32; 2]) -> Self::Diag {
        crate::base::sf::first_checked::<Self>(times, TssState::Init, TssState::ErrParam)
    }
    #[inline(always)]
    fn write_outputs(&mut self, o: &sf::SfOut) {
        // The v2.01 state (a library code is no state of the block).
        let code = self.stPrivate.stHeader.wDiag;
        let library = <TssState as sf::DiagState>::decode(code).is_none();
        let [ossd, test_out, possible, executed] = sensor_outputs(code, library);
        self.Ready = u8::from(o.ready);
        self.S_OSSD_Out = u8::from(ossd);
        self.S_TestOut = u8::from(test_out);
        self.TestPossible = u8::from(possible);
        self.TestExecuted = u8::from(executed);
        self.SafetyDemand = u8::from(o.safety_demand);
        self.ResetRequest = u8::from(o.reset_request);
        self.Error = u8::from(o.error);
        self.DiagCode = o.diag_code;
        // The end of every call: the R_TRIG memory of StartTest.
        sf::store_trigger(&mut self.stPrivate, self.StartTest);
    }
});

// The steady-state fast path (`base::sf::SfSteady`): the key is every BOOL byte the call
// reads; the test states read the test time.
crate::sf_steady!(
    SF_TestableSafetySensor: [Activate, S_OSSD_In, StartTest, NoExternalTest, S_StartReset, S_AutoReset, Reset],
    timed: TssState::{TestRequest, TestActive}
);
