//! The state machine FB ESTOP (manual §4.4) and FB MON (manual §4.5) have in common:
//! inputs that request the safe state, up to four two-channel pairs with discrepancy
//! monitoring, EDM1/EDM2 feedback loops (restart check and EL6910 reset time), manual or
//! automatic restart, an undelayed and a delayed output, and for MON the ERRORDELAY and
//! FUNCTEST states. The states are the manual's status values (§4.4.2, §4.5.2).

use crate::base::bools::Edge;
use crate::base::edm::Edm;
use crate::base::header::{param_crc, EDM_PENDING_SHIFT, F_EDM_PENDING, SL_PRIVATE_HEADER};
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/guard.rs"));

crate::base::envelope::steady_private!(SL_GUARD_PRIVATE, awSteady, u16);

const _: () = assert!(core::mem::size_of::<SL_GUARD_PRIVATE>() == 80);
const _: () = assert!(core::mem::size_of::<SL_PRIVATE_HEADER>() == 28);

pub(crate) const T_EDM1: usize = 4;
pub(crate) const T_EDM2: usize = 5;
pub(crate) const T_DELAY: usize = 6;
/// The latched input masks in `adwTime` (wInputActive | wInputNegated << 16).
pub(crate) const T_MASKS: usize = 7;

impl SL_GUARD_PRIVATE {
    /// The latched wInputActive (the inputs are bits 0–7 of every valid set).
    pub(crate) fn active(&self) -> u8 {
        self.adwTime[T_MASKS] as u8
    }
    /// The latched wInputNegated.
    pub(crate) fn negated(&self) -> u8 {
        (self.adwTime[T_MASKS] >> 16) as u8
    }
}

/// Guard parameters as the user wrote them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GuardParams {
    pub disc: [u32; 4],
    pub edm_reset: [u32; 2],
    pub delay: u32,
    pub active: u16,
    pub negated: u16,
    pub options: u32,
}

/// Raw input bytes of one cycle.
#[derive(Clone, Copy, Debug, Default)]
pub struct GuardRaw {
    pub restart: u8,
    pub edm: [u8; 2],
    /// Safety inputs in the order of the active/negated bits.
    pub inputs: [u8; 8],
}

/// Decoded inputs of one cycle.
#[derive(Clone, Copy, Debug, Default)]
pub struct GuardIn {
    /// Logical values of the active inputs (bit per input; FALSE requests the safe state).
    pub logical: u8,
    /// Something requests the safe state.
    pub request: bool,
    /// MonIn inputs requesting the safe state now (function test progress).
    pub test_req: u8,
    pub restart: Edge,
    pub edm: Edm,
}

/// What distinguishes ESTOP from MON.
pub trait GuardBlock: crate::base::block::Private<P = SL_GUARD_PRIVATE> {
    /// Type tag stored in the private header.
    const TAG: u16;
    /// Option bits the block accepts.
    const OPTIONS: u32;
    /// Bits of wInputActive / wInputNegated that exist.
    const INPUTS: u16;
    /// At least one of these inputs must be active.
    const REQUIRED: u16;
    /// Pairs that exist (bit k = inputs 2k and 2k+1).
    const PAIRS: u8;
    /// The field names of the discrepancy times of the pairs ("" for a pair that does not
    /// exist), for the refusal's sentence.
    const DISC_NAMES: [&'static str; 4];
    /// The field name of the delay time.
    const DELAY_NAME: &'static str;
    /// Inputs taking part in the manual function test.
    const TEST_INPUTS: u8;
    /// The block has ERRORDELAY (MON).
    const ERROR_DELAY: bool;
    /// Restart is always manual (ESTOP).
    const ALWAYS_MANUAL: bool;

    fn params(&self) -> GuardParams;
    fn raw(&self) -> GuardRaw;
    /// Safe-state request from the logical values of the active inputs.
    fn request(logical: u8, active: u8) -> bool;
    fn set_outputs(&mut self, error: bool, out: bool, del_out: bool, state: u8, diag: u16);
}

/// The struct side of a guard block (ESTOP, MON), from its field names: the discrepancy
/// times of the four pairs, the delay, the eight BOOL inputs (`0` for a pair or an input the
/// block does not have) and the two outputs; the rest of the struct is the family's. Writes
/// [`GuardBlock`]'s `DISC_NAMES`, `DELAY_NAME`, `params`, `raw` and `set_outputs`.
macro_rules! guard_fields {
    (disc: [$($d:tt),+], delay: $delay:ident, inputs: [$($i:tt),+], outputs: [$out:ident, $del:ident] $(,)?) => {
        const DISC_NAMES: [&'static str; 4] =
            [$($crate::blocks::boolean::guard::guard_fields!(@name $d)),+];
        const DELAY_NAME: &'static str = stringify!($delay);
        fn params(&self) -> $crate::blocks::boolean::guard::GuardParams {
            $crate::blocks::boolean::guard::GuardParams {
                disc: [$($crate::blocks::boolean::guard::guard_fields!(@field self $d)),+],
                edm_reset: [self.tEDM1ResetTime, self.tEDM2ResetTime],
                delay: self.$delay,
                active: self.wInputActive,
                negated: self.wInputNegated,
                options: self.dwOptions,
            }
        }
        fn raw(&self) -> $crate::blocks::boolean::guard::GuardRaw {
            $crate::blocks::boolean::guard::GuardRaw {
                restart: self.bRestart,
                edm: [self.bEDM1, self.bEDM2],
                inputs: [$($crate::blocks::boolean::guard::guard_fields!(@field self $i)),+],
            }
        }
        fn set_outputs(&mut self, error: bool, out: bool, del_out: bool, state: u8, diag: u16) {
            self.bError = u8::from(error);
            self.$out = u8::from(out);
            self.$del = u8::from(del_out);
            self.nState = state;
            self.nDiag = diag;
        }
    };
    (@name 0) => { "" };
    (@name $f:ident) => { stringify!($f) };
    (@field $s:ident 0) => { 0 };
    (@field $s:ident $f:ident) => { $s.$f };
}
pub(crate) use guard_fields;

/// The diag texts ESTOP and MON share (input groups 1 and 2, EDM1, EDM2), followed by the
/// block's own: `guard_diag![(SL_DIAG_DISC3, "..."), ...]`, a `BlockInfo::diag` table.
macro_rules! guard_diag {
    ($($own:expr),* $(,)?) => {
        &[
            ($crate::base::types::SL_DIAG_DISC1, "discrepancy error input group 1"),
            ($crate::base::types::SL_DIAG_DISC2, "discrepancy error input group 2"),
            ($crate::base::types::SL_DIAG_EDM1, "EDM monitoring error EDM1"),
            ($crate::base::types::SL_DIAG_EDM2, "EDM monitoring error EDM2"),
            ($crate::base::types::SL_DIAG_SAFE_IN_DISC1, "group 1 with Safe Inputs after Disc Error"),
            ($crate::base::types::SL_DIAG_SAFE_IN_DISC2, "group 2 with Safe Inputs after Disc Error"),
            $($own,)*
        ]
    };
}
pub(crate) use guard_diag;

/// The rule "a reset time belongs to an active feedback loop" of EDM `K + 1`: its reset
/// time is 0 unless `dwOptions` has its option bit.
pub(crate) const fn edm_reset_rule<const K: usize>() -> crate::base::reason::RuleDef<GuardParams> {
    use crate::base::reason::{when, Rule, RuleDef, Unit};
    const FIELDS: [&str; 2] = ["tEDM1ResetTime", "tEDM2ResetTime"];
    const UNLESS: [&str; 2] = ["dwOptions has SL_OPT_EDM1", "dwOptions has SL_OPT_EDM2"];
    RuleDef::new(FIELDS[K], Rule::ZeroUnless(UNLESS[K]), Unit::Ms, |p| {
        let t = p.edm_reset[K];
        when(
            t != 0 && p.options & [SL_OPT_EDM1, SL_OPT_EDM2][K] == 0,
            t,
            0,
        )
    })
}

/// Diag bits for pair errors, with the "Safe Inputs after Disc Error" bits when it is on.
#[inline]
pub(crate) fn disc_diag(pairs: u8, safe_inputs: bool) -> u16 {
    let d = u16::from(pairs);
    if safe_inputs {
        d | (d << 8)
    } else {
        d
    }
}

pub(crate) fn manual_restart<T: GuardBlock>(options: u16) -> bool {
    T::ALWAYS_MANUAL || u32::from(options) & SL_OPT_MANUAL_RESTART != 0
}

/// CRC of a guard block's latched parameters: the times' low halves, the masks' low bytes,
/// and the OR of the times' high halves and the masks' high bytes, which is 0 in every
/// valid set (a time is at most `SL_TIME_PARAM_MAX`, the inputs are bits 0–7). A corrupted
/// high part is found as well, at the CRC length of 16-bit times: the CRC runs wherever an
/// output switches on, and 32-bit times cost MON 10 ns per such call.
pub(crate) fn latched_crc<T: GuardBlock>(p: &SL_GUARD_PRIVATE) -> u16 {
    let [times @ .., masks] = p.adwTime;
    let [active, active_high, negated, negated_high] = masks.to_le_bytes();
    let high = times
        .iter()
        .fold(u16::from(active_high | negated_high), |o, &x| {
            o | (x >> 16) as u16
        });
    let words: [u16; 8] = core::array::from_fn(|i| times.get(i).map_or(high, |&x| x as u16));
    param_crc(T::TAG, active, negated, p.stHeader.wOptions, &words)
}

/// Outputs switch on: verify the latched parameters first (ABI §3.6 integrity), then RUN
/// with the EDM reset-time checks armed.
pub(crate) fn enable<T: GuardBlock>(p: &mut SL_GUARD_PRIVATE, edm: &Edm, now: u32) -> (u8, Status) {
    if latched_crc::<T>(p) != p.stHeader.wParamCrc {
        p.stHeader.enter_error(SL_DIAG_CORRUPT);
        return (SL_STATE_ERROR, Status::Corrupt);
    }
    let pending = edm.arm([p.adwTime[T_EDM1], p.adwTime[T_EDM2]]);
    let h = &mut p.stHeader;
    h.nFlags = (h.nFlags & !F_EDM_PENDING) | (pending << EDM_PENDING_SHIFT);
    h.tPhase = now;
    (SL_STATE_RUN, Status::Ok)
}

/// The envelope's view of a block of this family; invoked in the member's own file.
macro_rules! guard_block {
    ($t:ty) => {
        const _: () = {
            $crate::base::envelope::family_prelude!($crate::blocks::boolean::guard);

            impl Block for $t {
                const MAGIC: u16 = <$t as GuardBlock>::TAG;
                type Params = GuardParams;
                type In = GuardIn;

                fn live_params(&self) -> GuardParams {
                    self.params()
                }

                fn latched_params(&self) -> GuardParams {
                    let p = self.private();
                    let t = &p.adwTime;
                    GuardParams {
                        disc: [t[0], t[1], t[2], t[3]],
                        edm_reset: [t[T_EDM1], t[T_EDM2]],
                        delay: t[T_DELAY],
                        active: t[T_MASKS] as u16,
                        negated: (t[T_MASKS] >> 16) as u16,
                        options: u32::from(p.stHeader.wOptions),
                    }
                }

                const RULES: &'static [$crate::base::reason::RuleDef<GuardParams>] = {
                    use $crate::base::reason::{when, Hit, Rule, RuleDef, Unit};
                    /// The first pair (index, time, both inputs) whose discrepancy time `bad` refuses.
                    fn first_pair(
                        p: &GuardParams,
                        bad: impl Fn(usize, u32, u16) -> bool,
                    ) -> Option<(usize, u32, u16)> {
                        (0..4)
                            .map(|k| (k, p.disc[k], 0b11u16 << (2 * k)))
                            .find(|&(k, t, both)| bad(k, t, both))
                    }
                    fn named(k: usize, hit: Option<Hit>) -> Option<Hit> {
                        hit.map(|h| h.in_field(<$t as GuardBlock>::DISC_NAMES[k]))
                    }
                    &[
                        $crate::base::reason::rule!(no_bits_outside "wInputActive", |p| p.active, Self::INPUTS),
                        $crate::base::reason::rule!(no_bits_outside "wInputNegated", |p| p.negated, Self::INPUTS),
                        $crate::base::reason::rule!(no_bits_outside "dwOptions", |p| p.options, Self::OPTIONS),
                        RuleDef::new("tDiscTime", Rule::AtMost, Unit::Ms, |p| {
                            first_pair(p, |_, t, _| t > SL_TIME_PARAM_MAX)
                                .and_then(|(k, t, _)| named(k, when(true, t, SL_TIME_PARAM_MAX)))
                        }),
                        $crate::base::reason::rule!(at_most "tEDM1ResetTime" in Ms, |p| p.edm_reset[0], SL_TIME_PARAM_MAX),
                        $crate::base::reason::rule!(at_most "tEDM2ResetTime" in Ms, |p| p.edm_reset[1], SL_TIME_PARAM_MAX),
                        RuleDef::new(
                            <$t as GuardBlock>::DELAY_NAME,
                            Rule::AtMost,
                            Unit::Ms,
                            |p| when(p.delay > SL_TIME_PARAM_MAX, p.delay, SL_TIME_PARAM_MAX),
                        ),
                        // A discrepancy time belongs to a pair that exists and has both inputs active.
                        RuleDef::new("tDiscTime", Rule::Needs("wInputActive"), Unit::Ms, |p| {
                            first_pair(p, |k, t, both| {
                                t != 0 && (Self::PAIRS & (1 << k) == 0 || p.active & both != both)
                            })
                            .and_then(|(k, t, both)| named(k, when(true, t, both)))
                        }),
                        $crate::blocks::boolean::guard::edm_reset_rule::<0>(),
                        $crate::blocks::boolean::guard::edm_reset_rule::<1>(),
                        RuleDef::new("wInputActive", Rule::AnyBitOf, Unit::Hex, |p| {
                            when(p.active & Self::REQUIRED == 0, p.active, Self::REQUIRED)
                        }),
                    ]
                };

                fn store_params(&mut self, p: &GuardParams) {
                    let q = self.private_mut();
                    q.adwTime = [
                        p.disc[0],
                        p.disc[1],
                        p.disc[2],
                        p.disc[3],
                        p.edm_reset[0],
                        p.edm_reset[1],
                        p.delay,
                        u32::from(p.active) | u32::from(p.negated) << 16,
                    ];
                    q.stHeader.wOptions = p.options as u16;
                }

                fn latched_crc(&self) -> u16 {
                    latched_crc::<Self>(self.private())
                }

                // Inlined into the full cycle (`settle`), as `step`: no call, no `GuardIn`
                // through memory (docs/performance.md).
                #[inline(always)]
                fn decode(&mut self) -> (GuardIn, bool) {
                    let raw = self.raw();
                    let p = self.private_mut();
                    let (active, negated) = (p.active(), p.negated());
                    let h = &mut p.stHeader;
                    let packed = bools::pack(raw.inputs);
                    let logical = bools::logical(packed, active, negated);
                    let restart = bools::edge(raw.restart, &mut h.nFlags, F_RESTART_PREV);
                    let options = u32::from(h.wOptions);
                    let edm = Edm {
                        active: [options & SL_OPT_EDM1 != 0, options & SL_OPT_EDM2 != 0],
                        is_true: [bools::is_true(raw.edm[0]), bools::is_true(raw.edm[1])],
                        is_false: [bools::is_false(raw.edm[0]), bools::is_false(raw.edm[1])],
                    };
                    // Only bytes the block reads count as invalid: active inputs and active EDMs, and
                    // Restart where a manual restart uses it.
                    let invalid = packed.invalid & active != 0
                        || (edm.active[0] && raw.edm[0] > 1)
                        || (edm.active[1] && raw.edm[1] > 1)
                        || (manual_restart::<Self>(h.wOptions) && raw.restart > 1);
                    let inp = GuardIn {
                        logical,
                        request: Self::request(logical, active),
                        test_req: !logical & active & Self::TEST_INPUTS,
                        restart,
                        edm,
                    };
                    (inp, invalid)
                }

                fn start(&mut self, _inp: &GuardIn, now: u32) {
                    let h = &mut self.private_mut().stHeader;
                    h.wAux = 0;
                    h.nFlags &= !F_EDM_PENDING;
                    h.tPhase = now;
                    h.nState = if u32::from(h.wOptions) & SL_OPT_FUNCTION_TEST != 0 {
                        SL_STATE_FUNCTEST
                    } else {
                        SL_STATE_SAFE
                    };
                }

                #[inline(always)]
                fn step(&mut self, inp: &GuardIn, now: u32) -> Status {
                    let p = self.private_mut();
                    let state = p.stHeader.nState;
                    let options = u32::from(p.stHeader.wOptions);
                    let manual = manual_restart::<Self>(p.stHeader.wOptions);
                    let delay = p.adwTime[T_DELAY];

                    // Discrepancy monitoring runs in every running state.
                    let monitored = p.adwTime[..4]
                        .iter()
                        .enumerate()
                        .fold(0u8, |m, (k, &t)| m | (u8::from(t != 0) << k));
                    let mut running = (p.stHeader.wAux & 0xF) as u8;
                    let disc = pair::monitor(
                        inp.logical,
                        monitored,
                        &mut running,
                        &mut p.atDiscStart,
                        &p.adwTime[..4],
                        now,
                    );
                    p.stHeader.wAux = (p.stHeader.wAux & !0xF) | u16::from(running);
                    let mut err = disc_diag(disc, options & SL_OPT_SAFE_INPUTS_AFTER_DISC != 0);

                    // EDM with manual restart: while the outputs are safe and Restart is TRUE (and at
                    // its falling edge in START), every active feedback must read TRUE (sample 3).
                    let outputs_safe =
                        matches!(state, SL_STATE_SAFE | SL_STATE_START | SL_STATE_FUNCTEST);
                    if manual
                        && outputs_safe
                        && (inp.restart.level || (state == SL_STATE_START && inp.restart.falling))
                    {
                        err |= inp.edm.not_released();
                    }
                    // EL6910 EDM reset time: after switching on, each checked feedback must drop.
                    if state == SL_STATE_RUN {
                        let h = &mut p.stHeader;
                        let mut pending = (h.nFlags >> EDM_PENDING_SHIFT) & 0b11;
                        err |= inp.edm.reset_time_check(
                            &mut pending,
                            h.tPhase,
                            [p.adwTime[T_EDM1], p.adwTime[T_EDM2]],
                            now,
                        );
                        h.nFlags = (h.nFlags & !F_EDM_PENDING) | (pending << EDM_PENDING_SHIFT);
                    }

                    // MON: a discrepancy error while MonDelOut is still on waits for the output delay.
                    let delayable = Self::ERROR_DELAY
                        && delay != 0
                        && err & (SL_DIAG_EDM1 | SL_DIAG_EDM2) == 0
                        && matches!(
                            state,
                            SL_STATE_RUN | SL_STATE_DELAYOUT | SL_STATE_ERRORDELAY
                        );
                    if err != 0 && !delayable {
                        p.stHeader.enter_error(err);
                        return Status::Ok;
                    }
                    p.stHeader.wDiag |= err;

                    let mut status = Status::Ok;
                    let next = match state {
                        SL_STATE_RUN | SL_STATE_DELAYOUT if err != 0 => {
                            if state == SL_STATE_RUN {
                                p.stHeader.tPhase = now;
                            }
                            SL_STATE_ERRORDELAY
                        }
                        SL_STATE_ERRORDELAY => {
                            if time::reached(now, p.stHeader.tPhase, delay) {
                                p.stHeader.enter_error(0);
                                SL_STATE_ERROR
                            } else {
                                SL_STATE_ERRORDELAY
                            }
                        }
                        SL_STATE_FUNCTEST => {
                            let active = p.active();
                            let h = &mut p.stHeader;
                            h.wAux |= u16::from(inp.test_req) << 8;
                            let tested = (h.wAux >> 8) as u8 & Self::TEST_INPUTS;
                            if tested == active & Self::TEST_INPUTS {
                                SL_STATE_SAFE
                            } else {
                                SL_STATE_FUNCTEST
                            }
                        }
                        SL_STATE_SAFE | SL_STATE_START if manual => {
                            match restart::step(state == SL_STATE_START, inp.restart, inp.request) {
                                Restart::Wait => SL_STATE_SAFE,
                                Restart::Start => SL_STATE_START,
                                Restart::Enable => {
                                    let (s, st) = enable::<$t>(p, &inp.edm, now);
                                    status = st;
                                    s
                                }
                            }
                        }
                        SL_STATE_SAFE => {
                            if !inp.request && inp.edm.all_released() {
                                let (s, st) = enable::<$t>(p, &inp.edm, now);
                                status = st;
                                s
                            } else {
                                SL_STATE_SAFE
                            }
                        }
                        SL_STATE_RUN => {
                            if !inp.request {
                                SL_STATE_RUN
                            } else if delay != 0 {
                                p.stHeader.tPhase = now;
                                SL_STATE_DELAYOUT
                            } else {
                                SL_STATE_SAFE
                            }
                        }
                        SL_STATE_DELAYOUT => {
                            if time::reached(now, p.stHeader.tPhase, delay) {
                                SL_STATE_SAFE
                            } else {
                                SL_STATE_DELAYOUT
                            }
                        }
                        _ => {
                            // A state value this block never takes (START without manual restart
                            // included): the private state cannot be trusted.
                            p.stHeader.enter_error(SL_DIAG_CORRUPT);
                            status = Status::Corrupt;
                            SL_STATE_ERROR
                        }
                    };
                    p.stHeader.nState = next;
                    status
                }

                fn stop(&mut self) {
                    let h = &mut self.private_mut().stHeader;
                    // A pending discrepancy error stays an error; every other running state stops.
                    if h.nState == SL_STATE_ERRORDELAY {
                        h.enter_error(0);
                    } else {
                        h.nState = SL_STATE_STOP;
                    }
                }

                fn error_remains(&mut self, inp: &GuardIn) -> bool {
                    let h = &mut self.private_mut().stHeader;
                    let failed = (h.wDiag & 0xF) as u8;
                    let need_safe = (h.wDiag >> 8) as u8 & 0xF;
                    // "Safe Inputs after Disc Error": both channels must have requested the safe
                    // state together since the error.
                    let mut latched =
                        ((h.wAux >> 4) as u8 & 0xF) | (pair::both_safe(inp.logical) & need_safe);
                    latched &= need_safe;
                    h.wAux = (h.wAux & !0xF0) | (u16::from(latched) << 4);
                    let disc_remains =
                        failed & pair::differing(inp.logical) != 0 || need_safe & !latched != 0;
                    let edm_remains = h.wDiag & inp.edm.not_released() != 0;
                    disc_remains || edm_remains
                }

                $crate::base::envelope::steady_hooks!();

                fn write_outputs(&mut self) {
                    let h = self.private().stHeader;
                    let (error, out, del_out) = match h.nState {
                        SL_STATE_RUN => (false, true, true),
                        SL_STATE_DELAYOUT | SL_STATE_ERRORDELAY => (false, false, true),
                        SL_STATE_ERROR => (true, false, false),
                        _ => (false, false, false),
                    };
                    self.set_outputs(error, out, del_out, h.nState, h.wDiag);
                }
            }

            impl $crate::base::envelope::Steady for $t {
                #[inline(always)]
                fn steady_key(&self) -> Option<u16> {
                    let r = self.raw();
                    let [a, b, c, d, e, f, g, h] = r.inputs;
                    bools::key([
                        a,
                        b,
                        c,
                        d,
                        e,
                        f,
                        g,
                        h,
                        r.restart,
                        r.edm[0],
                        r.edm[1],
                        self.run_raw(),
                        self.errack_raw(),
                    ])
                }

                /// No discrepancy timer, output delay, error delay or EDM reset time runs.
                #[inline(always)]
                fn quiet(&self) -> bool {
                    let h = &self.private().stHeader;
                    !matches!(h.nState, SL_STATE_DELAYOUT | SL_STATE_ERRORDELAY)
                        && h.wAux & 0xF == 0
                        && h.nFlags & F_EDM_PENDING == 0
                }
            }
        };
    };
}
pub(crate) use guard_block;
