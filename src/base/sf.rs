//! The PLCopen Safety envelope every `SF_` block runs in (PLCopen TC5 Part 1 generic
//! parameters and DiagCodes, `plcopen-safety-generic-diag.txt`; research
//! `plcopen_safety.md` §3, §9): the PLCopen counterpart of [`super::envelope`].
//!
//! One call: (1) the integrity check of the private state, the clock check, the R_TRIG of
//! `Reset` — every call, before anything else, so a Reset held into a wait-for-reset state
//! is a static-reset error; (2) `Activate` FALSE (or the owning group not running the
//! block) has the highest priority: DiagCode 0000, every output FALSE; otherwise 0000 →
//! the block's init state latches the constant inputs, and any other state takes the
//! block's one transition (first matching guard wins); (3) every output from the *new*
//! state in the same call. The block's state is its v2.01 DiagCode (the default profile);
//! the v1.0 DiagCodes are a per-instance option (`nDiagProfile`), latched at activation,
//! so one instance never mixes them. The library's own faults are DiagCodes of the error
//! range (`SL_SF_DIAG_*`, docs/semantics.md PO1–PO10).

use super::bools::{self, Edge};
use super::header::{crc_words, param_crc, F_RESTART_PREV, F_TIME_VALID, SL_PRIVATE_HEADER};
use super::layout::Zeroed;
use super::reason::{when, Refusal, Rule, RuleDef, Unit};
use super::time;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/base/sf.rs"));

/// Previous level of a block's own R_TRIG input (SF_EDM's S_OutControl,
/// SF_TestableSafetySensor's StartTest): bit 7 of the header's `nFlags`, sealed with it.
const F_TRIGGER_PREV: u8 = 1 << 7;

/// R_TRIG(raw).Q of a block's own trigger input, read in `SfBlock::decode`; the memory is
/// written by [`store_trigger`] from `SfBlock::write_outputs`, which runs at the end of
/// every call (idle included), so the R_TRIG runs in every call as Reset's does.
pub fn trigger_rising(p: &SL_SF_PRIVATE, raw: u8) -> bool {
    bools::is_true(raw) && !p.stHeader.flag(F_TRIGGER_PREV)
}

/// Stores the level of the trigger input for the next call's [`trigger_rising`].
pub fn store_trigger(p: &mut SL_SF_PRIVATE, raw: u8) {
    p.stHeader.set_flag(F_TRIGGER_PREV, bools::is_true(raw));
}

/// The library's DiagCodes with their texts (the same in both profiles).
pub const LIBRARY_CODES: &[(u16, &str)] = &[
    (SL_SF_DIAG_CORRUPT, "library: private state corrupt"),
    (SL_SF_DIAG_CLOCK, "library: clock went backwards"),
    (
        SL_SF_DIAG_CONST_CHANGED,
        "library: constant input changed while activated",
    ),
    (
        SL_SF_DIAG_CONFIG,
        "library: invalid constant input at activation",
    ),
];

const fn is_library(code: u16) -> bool {
    code == SL_SF_DIAG_CORRUPT
        || code == SL_SF_DIAG_CLOCK
        || code == SL_SF_DIAG_CONST_CHANGED
        || code == SL_SF_DIAG_CONFIG
}

const fn phase_of(code: u16) -> u8 {
    if code == 0 {
        SL_STATE_STOP
    } else if is_library(code) {
        SL_STATE_ERROR
    } else {
        SL_STATE_RUN
    }
}

/// A block's states: an enum whose values are its v2.01 DiagCodes, declared with
/// `sf_states!`, with the v1.0 code and the text of each.
pub trait DiagState: Copy + core::fmt::Debug + Eq + 'static {
    /// (v2.01 code, v1.0 code, name, text) of every state, IDLE first.
    const TABLE: &'static [(u16, u16, &'static str, &'static str)];
    /// (code, text) of both profiles (v2.01 first): what `sl_diag_text` reads.
    const TEXTS: &'static [(u16, &'static str)];
    /// The state the block enters from IDLE (its INIT).
    const INIT: Self;
    /// The state with this v2.01 code; `None` for a code the block does not have.
    fn decode(code: u16) -> Option<Self>;
    /// The v2.01 DiagCode.
    fn code(self) -> u16;
    /// The v1.0 DiagCode.
    fn code_v10(self) -> u16;
    /// The v1.0 DiagCode of the state whose v2.01 code is `code`; `None` for a code the
    /// block does not have (one match: [`Self::decode`] and [`Self::code_v10`] in one).
    fn v10_of(code: u16) -> Option<u16>;
    /// The DiagCode in `profile`.
    #[inline]
    fn code_in(self, profile: u8) -> u16 {
        if profile != SL_SF_PROFILE_V10 {
            return self.code();
        }
        self.code_v10()
    }
}

/// Declares an `SF_` block's states once: `pub enum $name` (values = the v2.01 DiagCodes),
/// with the v1.0 code, name and text of each: `Init = 0x8001, 0x8001, "INIT", "…";`.
/// The first entry is IDLE (0x0000); `init:` names the state entered from IDLE.
#[macro_export]
#[doc(hidden)]
macro_rules! sf_states {
    ($(#[$meta:meta])* $enum:ident, init: $init:ident {
        $($v:ident = $code:literal, $v1:literal, $name:literal, $text:literal;)+
    }) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        #[repr(u16)]
        pub enum $enum {
            $(
                #[doc = concat!($name, " (v2.01 ", stringify!($code), ", v1.0 ", stringify!($v1), "): ", $text, ".")]
                $v = $code,
            )+
        }
        impl $crate::base::sf::DiagState for $enum {
            const TABLE: &'static [(u16, u16, &'static str, &'static str)] =
                &[$(($code, $v1, $name, $text)),+];
            const TEXTS: &'static [(u16, &'static str)] = &[$(($code, $text),)+ $(($v1, $text)),+];
            const INIT: Self = $enum::$init;
            #[inline]
            fn decode(code: u16) -> Option<Self> {
                $(if code == $code {
                    return Some($enum::$v);
                })+
                None
            }
            #[inline]
            fn code(self) -> u16 {
                self as u16
            }
            #[inline]
            fn code_v10(self) -> u16 {
                match self {
                    $($enum::$v => $v1,)+
                }
            }
            #[inline(always)]
            fn v10_of(code: u16) -> Option<u16> {
                match code {
                    $($code => Some($v1),)+
                    _ => None,
                }
            }
        }
    };
}

/// The constant inputs of an `SF_` block: the profile and up to two monitored times.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SfConsts {
    /// `nDiagProfile`.
    pub profile: u8,
    /// The block's times (ms), unused ones 0.
    pub times: [u32; 2],
}

/// The R_TRIG of `Reset`, evaluated every call (an invalid byte reads FALSE).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ResetIn {
    /// `Reset` is TRUE.
    pub level: bool,
    /// R_TRIG(Reset).Q.
    pub rising: bool,
}

impl ResetIn {
    /// "Static reset": Reset TRUE without a rising edge in this call.
    #[inline]
    pub const fn held(self) -> bool {
        self.level && !self.rising
    }
}

/// The outputs every `SF_` block derives from its new state.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SfOut {
    /// Ready: DiagCode ≠ 0000.
    pub ready: bool,
    /// The safety output: the state is 0x8000.
    pub enabled: bool,
    /// SafetyDemand: bit 0x0800 of the v2.01 code.
    pub safety_demand: bool,
    /// ResetRequest: bit 0x0400 of the v2.01 code, FALSE while Reset is TRUE.
    pub reset_request: bool,
    /// Error: DiagCode ≥ 0xC000.
    pub error: bool,
    /// DiagCode in the instance's profile.
    pub diag_code: u16,
}

/// The fields every `SF_` block has under the same names (`stPrivate`, `Activate`);
/// implemented by `impl_sf_member!`.
pub trait SfInstance {
    /// `&self.stPrivate`.
    fn sf_private(&self) -> &SL_SF_PRIVATE;
    /// `&mut self.stPrivate`.
    fn sf_private_mut(&mut self) -> &mut SL_SF_PRIVATE;
    /// The raw `Activate` byte (SF_ResetButton: `ResetRequested`, its activation).
    fn activate_raw(&self) -> u8;
    /// Writes the `Activate` byte (SF_ResetButton: `ResetRequested`): for generic drivers.
    fn set_activate_raw(&mut self, v: u8);
}

/// What an `SF_` block supplies to the envelope (the plumbing of [`SfInstance`] comes from
/// `impl_sf_member!`).
pub trait SfBlock: SfInstance + Sized {
    /// Type tag stored in the private header.
    const MAGIC: u16;
    /// The block's states (values = v2.01 DiagCodes).
    type Diag: DiagState;
    /// Inputs of one call after BOOL decoding.
    type In: Copy;
    /// The block exists in PLCopen v1.0 (the v1.0 profile may be chosen).
    const HAS_V10: bool = true;
    /// Number of monitored times the block has (`SfConsts::times`).
    const TIMES: usize = 0;
    /// The rules of the block's constant inputs besides `nDiagProfile` (its times within
    /// [`SL_SF_TIME_MAX`], a BOOL constant 0 or 1): a broken one is SL_E_CONFIG.
    const CONST_RULES: &'static [RuleDef<SfConsts>] = &[];
    /// The block's own limits of its constants, checked by [`Self::first`] at activation:
    /// a broken one is the block's parameter error state (DiagCode C000), not SL_E_CONFIG.
    const PARAM_RULES: &'static [RuleDef<SfConsts>] = &[];

    /// The raw `Reset` byte (0 for a block without Reset).
    fn reset_raw(&self) -> u8;
    /// The constant inputs as written.
    fn live_consts(&self) -> SfConsts;
    /// Reads the block's own input bytes (not Activate, not Reset); whether one was an
    /// invalid BOOL (it reads FALSE, the safe value of every `S_` input).
    fn decode(&self) -> (Self::In, bool);
    /// [`Self::decode`] plus the block's own edge memories (a block with an R_TRIG on an
    /// input of its own, kept in the private header's flags): called once in every call,
    /// whatever the state, like the R_TRIG of Reset. Default: no edge of its own.
    #[inline(always)]
    fn decode_edges(&mut self) -> (Self::In, bool) {
        self.decode()
    }
    /// The next state from a state other than IDLE: the block's one match, first matching
    /// guard wins. `in_state` is the time since the state was entered (ms), `times` the
    /// latched constant times.
    fn next(
        s: Self::Diag,
        inp: &Self::In,
        reset: ResetIn,
        in_state: u32,
        times: [u32; 2],
    ) -> Self::Diag;
    /// Writes the block's output fields.
    fn write_outputs(&mut self, o: &SfOut);
    /// The state entered from IDLE with valid latched constants (`times`): INIT. A block
    /// whose constant inputs have limits of its own (SF_ResetButton's trailing times)
    /// enters its parameter error here, in the activating call.
    fn first(times: [u32; 2]) -> Self::Diag {
        let _ = times;
        Self::Diag::INIT
    }
    /// Called in every call after [`Self::decode`], before `Activate` is evaluated (edge
    /// detectors run every call, research §3.3): a block with memory beyond its state
    /// (edges of inputs other than Reset, a held selection, in the header's `wAux`, which
    /// the integrity check covers, or in its own private fields) completes `inp` from it
    /// and updates it. The header's `wDiag` is still the state before this call. Default:
    /// nothing (SF_ModeSelector has memory).
    #[inline(always)]
    fn track(&mut self, _inp: &mut Self::In, _now: u32) {}
}

/// The private-header magic of an `SF_` block type (distinct from every TwinSAFE magic).
pub const fn magic(tag: u16) -> u16 {
    0x5F00 ^ tag
}

/// The part of an `impl SfBlock` that every `SF_` block writes alike, declared once: the
/// magic from the type tag, the state and input types, the `Reset` byte (`none`: a block
/// without Reset reads 0), the constants latched at activation (`consts(s): [..]`, up to
/// two words read from `s`, the block; their number is `TIMES`) and their rules, and a
/// `next` that hands over to the block's transition function (`next: |s, inp, reset,
/// in_state, times| …`); the rest of the impl (decode, write_outputs, …) follows in braces.
#[macro_export]
#[doc(hidden)]
macro_rules! impl_sf_block {
    (@reset $s:ident none) => { 0 };
    (@reset $s:ident $field:ident) => { $s.$field };
    (@times) => { [0; 2] };
    (@times $a:expr) => { [$a, 0] };
    (@times $a:expr, $b:expr) => { [$a, $b] };
    ($ty:ty {
        tag: $tag:expr,
        diag: $diag:ty,
        input: $in:ty,
        reset: $reset:ident,
        consts($s:ident): [$($t:expr),* $(,)?]
        $(, rules: [$($rule:expr),* $(,)?])?
        $(, next: |$ns:pat_param, $ni:pat_param, $nr:pat_param, $nis:pat_param, $nt:pat_param| $next:expr)? $(,)?
    } { $($body:tt)* }) => {
        impl $crate::base::sf::SfBlock for $ty {
            const MAGIC: u16 = $crate::base::sf::magic($tag);
            type Diag = $diag;
            type In = $in;
            const TIMES: usize = <[&str]>::len(&[$(stringify!($t)),*]);
            $(const CONST_RULES: &'static [$crate::base::reason::RuleDef<$crate::base::sf::SfConsts>] =
                &[$($rule),*];)?
            #[inline(always)]
            fn reset_raw(&self) -> u8 {
                $crate::impl_sf_block!(@reset self $reset)
            }
            fn live_consts(&self) -> $crate::base::sf::SfConsts {
                let $s = self;
                $crate::base::sf::SfConsts {
                    profile: $s.nDiagProfile,
                    times: $crate::impl_sf_block!(@times $($t),*),
                }
            }
            $(
                #[inline(always)]
                fn next(
                    $ns: Self::Diag,
                    $ni: &Self::In,
                    $nr: $crate::base::sf::ResetIn,
                    $nis: u32,
                    $nt: [u32; 2],
                ) -> Self::Diag {
                    $next
                }
            )?
            $($body)*
        }
    };
}

/// Writes an `SF_` block's standard outputs from `o` (a statement list inside
/// `write_outputs`): Ready, the safety output (`o.enabled`), the block's further BOOL
/// outputs (`+ Field = value`), those of SafetyDemand and ResetRequest the block has,
/// Error, DiagCode.
#[macro_export]
#[doc(hidden)]
macro_rules! sf_outputs {
    (@f $s:ident $o:ident SafetyDemand) => {
        $s.SafetyDemand = u8::from($o.safety_demand)
    };
    (@f $s:ident $o:ident ResetRequest) => {
        $s.ResetRequest = u8::from($o.reset_request)
    };
    ($s:ident, $o:ident, $out:ident $(+ $xf:ident = $xv:expr)* $(, $f:ident)*) => {
        $s.Ready = u8::from($o.ready);
        $s.$out = u8::from($o.enabled);
        $($s.$xf = u8::from($xv);)*
        $($crate::sf_outputs!(@f $s $o $f);)*
        $s.Error = u8::from($o.error);
        $s.DiagCode = $o.diag_code;
    };
}

/// `nDiagProfile` of a block that has both profiles.
static PROFILE_BOTH: RuleDef<SfConsts> = RuleDef::new(
    "nDiagProfile",
    Rule::OneOf("0 (v2.01), 1 (v1.0)"),
    Unit::Plain,
    |c| when(c.profile > SL_SF_PROFILE_V10, c.profile, 0),
);
/// `nDiagProfile` of a block that exists in v2.x only.
static PROFILE_V201: RuleDef<SfConsts> =
    RuleDef::new("nDiagProfile", Rule::OneOf("0 (v2.01)"), Unit::Plain, |c| {
        when(c.profile != SL_SF_PROFILE_V201, c.profile, 0)
    });

/// A time constant (`SfConsts::times[0]`) named `name`: at most [`SL_SF_TIME_MAX`].
pub const fn time0_rule(name: &'static str) -> RuleDef<SfConsts> {
    RuleDef::new(name, Rule::AtMost, Unit::Ms, |c| {
        when(c.times[0] > SL_SF_TIME_MAX, c.times[0], SL_SF_TIME_MAX)
    })
}

/// A time constant (`SfConsts::times[1]`) named `name`: at most [`SL_SF_TIME_MAX`].
pub const fn time1_rule(name: &'static str) -> RuleDef<SfConsts> {
    RuleDef::new(name, Rule::AtMost, Unit::Ms, |c| {
        when(c.times[1] > SL_SF_TIME_MAX, c.times[1], SL_SF_TIME_MAX)
    })
}

/// The value a BOOL constant stands for in `SfConsts::times`: itself when 0 or 1, otherwise
/// bit 31 set with the byte in the low bits (above every valid time).
pub const fn bool_const(byte: u8) -> u32 {
    match byte {
        0 | 1 => byte as u32,
        _ => BOOL_CONST_INVALID | byte as u32,
    }
}

/// The mark of an invalid BOOL constant in `SfConsts::times` ([`bool_const`]).
const BOOL_CONST_INVALID: u32 = 0x8000_0000;

/// A BOOL constant stored by [`bool_const`] in `SfConsts::times[0]`, named `name`.
pub const fn bool0_rule(name: &'static str) -> RuleDef<SfConsts> {
    RuleDef::new(name, Rule::OneOf("0 (FALSE), 1 (TRUE)"), Unit::Plain, |c| {
        when(c.times[0] > 1, c.times[0] & 0xFF, 0)
    })
}

/// A BOOL constant stored by [`bool_const`] in `SfConsts::times[1]`, named `name`.
pub const fn bool1_rule(name: &'static str) -> RuleDef<SfConsts> {
    RuleDef::new(name, Rule::OneOf("0 (FALSE), 1 (TRUE)"), Unit::Plain, |c| {
        when(c.times[1] > 1, c.times[1] & 0xFF, 0)
    })
}

/// The block's rules in the order they are checked: `nDiagProfile`, then
/// [`SfBlock::CONST_RULES`] (SL_E_CONFIG), then [`SfBlock::PARAM_RULES`] (the block's
/// parameter error state).
pub fn rules<B: SfBlock>() -> impl Iterator<Item = &'static RuleDef<SfConsts>> {
    let profile = if B::HAS_V10 {
        &PROFILE_BOTH
    } else {
        &PROFILE_V201
    };
    core::iter::once(profile)
        .chain(B::CONST_RULES)
        .chain(B::PARAM_RULES)
}

/// The first rule of [`rules`] that `c` breaks.
pub fn refusal<B: SfBlock>(c: &SfConsts) -> Option<Refusal> {
    rules::<B>().enumerate().find_map(|(i, r)| {
        (r.test)(c).map(|hit| Refusal {
            index: i,
            info: r.info,
            hit,
        })
    })
}

/// The latched constants are valid: a known profile the block has, its constants within
/// their rules (the block's own limits are [`SfBlock::first`]'s), unused times 0.
fn consts_valid<B: SfBlock>(c: &SfConsts) -> bool {
    let config = 1 + B::CONST_RULES.len();
    rules::<B>().take(config).all(|r| (r.test)(c).is_none())
        && c.times[B::TIMES..].iter().all(|&t| t == 0)
}

/// [`SfBlock::first`] of a block with [`SfBlock::PARAM_RULES`]: `init` when the latched
/// times pass them, `error` (the block's parameter error state) otherwise.
pub fn first_checked<B: SfBlock>(times: [u32; 2], init: B::Diag, error: B::Diag) -> B::Diag {
    let c = SfConsts { profile: 0, times };
    if B::PARAM_RULES.iter().all(|r| (r.test)(&c).is_none()) {
        init
    } else {
        error
    }
}

fn consts_crc<B: SfBlock>(p: &SL_SF_PRIVATE) -> u16 {
    let [a, b] = p.adwTime;
    param_crc(
        B::MAGIC,
        p.stHeader.nActive,
        0,
        0,
        &crc_words![u32 a, u32 b],
    )
}

fn latched<B: SfBlock>(fb: &B) -> SfConsts {
    let p = fb.sf_private();
    SfConsts {
        profile: p.stHeader.nActive,
        times: p.adwTime,
    }
}

/// Latches the live constants; whether they are valid.
fn latch<B: SfBlock>(fb: &mut B) -> bool {
    let c = fb.live_consts();
    let p = fb.sf_private_mut();
    p.stHeader.nActive = c.profile;
    p.adwTime = c.times;
    let crc = consts_crc::<B>(fb.sf_private());
    fb.sf_private_mut().stHeader.wParamCrc = crc;
    consts_valid::<B>(&c)
}

/// Enters `code` (a state of the block or a library code) at `now`.
fn enter(h: &mut SL_PRIVATE_HEADER, code: u16, now: u32) {
    if h.wDiag != code {
        h.tPhase = now;
    }
    h.wDiag = code;
    h.nState = phase_of(code);
}

/// Power-up: a fresh private state in IDLE. Only `keep` (a consistent instance going idle)
/// keeps the R_TRIG memory, the clock and the group's halt; init and a corrupt state start
/// from nothing (the owning group writes its halt again before each of its calls).
fn idle<B: SfBlock>(fb: &mut B, keep: bool) {
    let old = *fb.sf_private();
    let p = fb.sf_private_mut();
    *p = SL_SF_PRIVATE::ZERO;
    p.stHeader.wMagic = B::MAGIC;
    p.stHeader.nState = SL_STATE_STOP;
    if keep {
        p.nGroupHalt = old.nGroupHalt;
        p.stHeader.nFlags = old.stHeader.nFlags & (F_RESTART_PREV | F_TIME_VALID);
        p.stHeader.tLast = old.stHeader.tLast;
    }
}

/// The outputs of a code. Inline: in the fast path a call would cost more than the
/// compares (the result is packed into a register and unpacked again).
#[inline(always)]
fn outputs(code: u16, reset_level: bool, state_code: Option<u16>) -> SfOut {
    // The v2.01 code carries the SafetyDemand / reset-request bits whatever the profile.
    let v2 = state_code.unwrap_or(code);
    let active = code != 0;
    let library = is_library(v2);
    SfOut {
        ready: active,
        enabled: v2 == SF_ENABLED,
        safety_demand: active && !library && v2 & 0x0800 != 0,
        reset_request: active && !library && v2 & 0x0400 != 0 && !reset_level,
        error: code >= 0xC000,
        diag_code: code,
    }
}

/// Inline: the fast path's outputs cost one match (the v1.0 code) and a few compares.
#[inline(always)]
fn write<B: SfBlock>(fb: &mut B, reset_level: bool) {
    let h = fb.sf_private().stHeader;
    // A state of the block in the v1.0 profile: its v1.0 code; otherwise the code itself
    // (every v2.01 code, and a library code in either profile).
    let code = if h.nActive == SL_SF_PROFILE_V10 {
        B::Diag::v10_of(h.wDiag).unwrap_or(h.wDiag)
    } else {
        h.wDiag
    };
    let o = outputs(code, reset_level, Some(h.wDiag));
    fb.write_outputs(&o);
}

/// `sl_sf_<name>_init`: IDLE with the constants latched (SL_OK or SL_E_CONFIG), every
/// output FALSE. Never touches an input field.
pub fn init<B: SfBlock>(fb: &mut B) -> Status {
    idle(fb, false);
    let ok = latch(fb);
    write(fb, false);
    fb.sf_private_mut().stHeader.seal();
    if ok {
        Status::Ok
    } else {
        Status::Config
    }
}

/// The private state is consistent: magic and complements, a code the block has (or a
/// library code) and the phase that goes with it.
fn consistent<B: SfBlock>(fb: &B) -> bool {
    let h = &fb.sf_private().stHeader;
    h.intact(B::MAGIC)
        && (B::Diag::decode(h.wDiag).is_some() || is_library(h.wDiag))
        && h.nState == phase_of(h.wDiag)
}

/// The full call at `now` (ms, wrapping): what [`cycle`] runs when the fast path does not
/// serve the call.
#[inline(always)]
fn full_cycle<B: SfBlock>(fb: &mut B, now: u32) -> Status {
    let mut status = Status::Ok;
    let mut fault = None;
    if !consistent(fb) {
        let zero = fb.sf_private().stHeader.is_zero();
        idle(fb, false);
        latch(fb);
        if !zero {
            status = Status::Corrupt;
            fault = Some(SL_SF_DIAG_CORRUPT);
        }
    }
    let h = &mut fb.sf_private_mut().stHeader;
    if h.flag(F_TIME_VALID) && time::went_backwards(now, h.tLast) {
        status = status.worst(Status::Clock);
        fault = fault.or(Some(SL_SF_DIAG_CLOCK));
    }
    h.tLast = now;
    h.set_flag(F_TIME_VALID, true);

    // The R_TRIG of Reset runs in every call, whatever the state (research §3.3).
    let reset_raw = fb.reset_raw();
    let Edge { level, rising, .. } = bools::edge(
        reset_raw,
        &mut fb.sf_private_mut().stHeader.nFlags,
        F_RESTART_PREV,
    );
    let reset = ResetIn { level, rising };
    let activate_raw = fb.activate_raw();
    let (mut inp, invalid) = fb.decode_edges();
    fb.track(&mut inp, now);
    if invalid || activate_raw > 1 || reset_raw > 1 {
        status = status.worst(Status::InvalidBool);
    }
    let activate = bools::is_true(activate_raw) && fb.sf_private().nGroupHalt == 0;

    let code = fb.sf_private().stHeader.wDiag;
    if !activate {
        // Highest priority: IDLE, whatever the state (a fault included).
        if code != 0 {
            idle(fb, true);
        }
    } else if let Some(f) = fault {
        enter(&mut fb.sf_private_mut().stHeader, f, now);
    } else if is_library(code) {
        // A library fault stays until Activate FALSE; report it again.
        status = status.worst(match code {
            SL_SF_DIAG_CLOCK => Status::Clock,
            SL_SF_DIAG_CONST_CHANGED => Status::ParamChanged,
            SL_SF_DIAG_CONFIG => Status::Config,
            _ => Status::Corrupt,
        });
    } else if code == 0 {
        // 0000 → INIT: the constant inputs are latched here (they may not change while
        // the block is activated).
        let next = if latch(fb) {
            B::first(fb.sf_private().adwTime).code()
        } else {
            status = status.worst(Status::Config);
            SL_SF_DIAG_CONFIG
        };
        enter(&mut fb.sf_private_mut().stHeader, next, now);
    } else if fb.live_consts() != latched(fb) {
        let p = fb.sf_private();
        let (next, s) = if consts_crc::<B>(p) != p.stHeader.wParamCrc {
            (SL_SF_DIAG_CORRUPT, Status::Corrupt)
        } else {
            (SL_SF_DIAG_CONST_CHANGED, Status::ParamChanged)
        };
        status = status.worst(s);
        enter(&mut fb.sf_private_mut().stHeader, next, now);
    } else if let Some(state) = B::Diag::decode(code) {
        let p = fb.sf_private();
        let in_state = time::elapsed(now, p.stHeader.tPhase);
        let mut next = B::next(state, &inp, reset, in_state, p.adwTime).code();
        // The safety output switching on is where the latched constants are verified.
        if next == SF_ENABLED && code != SF_ENABLED && consts_crc::<B>(p) != p.stHeader.wParamCrc {
            status = status.worst(Status::Corrupt);
            next = SL_SF_DIAG_CORRUPT;
        }
        enter(&mut fb.sf_private_mut().stHeader, next, now);
    }
    write(fb, reset.level);
    fb.sf_private_mut().stHeader.seal();
    status
}

/// What an `SF_` block with a steady-state fast path supplies besides [`SfBlock`]
/// (docs/performance.md, "The fast path of the PLCopen envelope"). Every `SF_` block
/// implements it; one without a fast path keeps the defaults (no key: every call is full).
pub trait SfSteady: SfBlock {
    /// The key of this call: every BOOL byte the cycle reads from the struct (Activate, the
    /// block's inputs, Reset, a BOOL constant), byte i as bit i (`bools::key`); `None` when
    /// one is neither 0 nor 1, or the block has no fast path.
    #[inline(always)]
    fn steady_key(&self) -> Option<u16> {
        None
    }
    /// A monitored time runs in the state the private state holds: the next call may take
    /// another transition at another time with the same inputs (`next` reads `in_state`
    /// in this state, or the block's memory holds a running time). Asked after a full call
    /// that was a fixed point; such a state stores no key.
    #[inline(always)]
    fn timed(&self) -> bool {
        true
    }
}

/// The fast path of an `SF_` block ([`SfSteady`]), from the BOOL fields of its key in key
/// order and when a monitored time runs: never (no `timed`), in the listed states
/// (`timed: State::{A, B}`), or where an expression over the block says so
/// (`timed: |b| …`).
#[macro_export]
#[doc(hidden)]
macro_rules! sf_steady {
    ($ty:ty: [$($f:ident),+ $(,)?]) => {
        impl $crate::base::sf::SfSteady for $ty {
            $crate::sf_steady!(@key $($f),+);
            #[inline(always)]
            fn timed(&self) -> bool {
                false
            }
        }
    };
    ($ty:ty: [$($f:ident),+ $(,)?], timed: $state:ident::{$($s:ident),+ $(,)?}) => {
        $crate::sf_steady!($ty: [$($f),+], timed: |b| matches!(b.diag_state(), Some($($state::$s)|+)));
    };
    ($ty:ty: [$($f:ident),+ $(,)?], timed: |$b:ident| $timed:expr) => {
        impl $crate::base::sf::SfSteady for $ty {
            $crate::sf_steady!(@key $($f),+);
            fn timed(&self) -> bool {
                let $b = self;
                $timed
            }
        }
    };
    (@key $($f:ident),+) => {
        #[inline(always)]
        fn steady_key(&self) -> Option<u16> {
            $crate::base::sf::key([$(&self.$f),+])
        }
    };
}

/// The key of BOOL bytes: byte i as bit i; `None` when one is neither 0 nor 1. Built byte
/// by byte through references, as bits (no shift makes adjacent bytes one wider value, so
/// every byte stays its own load): a caller writes these bytes one by one right before the
/// call, and one load wider than those stores would wait until they reach the cache
/// (docs/performance.md, "store forwarding").
#[inline(always)]
pub fn key<const N: usize>(bytes: [&u8; N]) -> Option<u16> {
    const { assert!(N <= 16) };
    let mut key = 0u16;
    let mut any = 0u8;
    for (i, b) in bytes.into_iter().enumerate() {
        any |= *b;
        key |= u16::from(*b) << i;
    }
    (any <= 1).then_some(key)
}

/// The slot of `key` in the state whose control word (state, flags, DiagCode) is `ctrl`:
/// the key XOR the DiagCode, then a check byte, the complement of the state XOR the flags.
/// Equal slots mean the same key in the same DiagCode, state and flags. A zeroed slot holds
/// no key: its check byte would need state XOR flags = 0xFF, and an `SF_` block's state is
/// below 8 and its flags use bits 0, 2 and 7 only.
#[inline(always)]
fn slot_of(key: u16, ctrl: u32) -> [u8; 3] {
    let [lo, hi] = (key ^ (ctrl >> 16) as u16).to_le_bytes();
    [lo, hi, !(ctrl as u8 ^ (ctrl >> 8) as u8)]
}

/// `sl_sf_<name>_cycle`: one call at `now` (ms, wrapping): the fast path, else the full
/// call ([`settle`]).
#[inline(always)]
pub fn cycle<B: SfSteady>(fb: &mut B, now: u32) -> Status {
    cycle_traced(fb, now).0
}

/// [`cycle`], also telling whether the fast path served the call (for the tests that pin
/// the fast path to the full one).
#[doc(hidden)]
#[inline(always)]
pub fn cycle_traced<B: SfSteady>(fb: &mut B, now: u32) -> (Status, bool) {
    if fast(fb, now) {
        (Status::Ok, true)
    } else {
        (settle(fb, now), false)
    }
}

/// The full call only, keeping the slot as [`cycle`] does (the reference the fast path is
/// tested against).
#[doc(hidden)]
pub fn cycle_full<B: SfSteady>(fb: &mut B, now: u32) -> Status {
    settle(fb, now)
}

/// The fast path: whether it served the call (`SL_OK`); [`settle`] must run when it did
/// not. Served only when this call's key, bound to the control word the private header
/// holds now, is the stored slot (a full call at these bytes in this state was a fixed
/// point and no time runs there), the group does not halt the block, the private header is
/// intact (magic, complements), the clock did not go backwards and the constant inputs are
/// the latched ones. It then does what that full call would do again: stores `tLast` and
/// writes the outputs from the state.
#[inline(always)]
pub fn fast<B: SfSteady>(fb: &mut B, now: u32) -> bool {
    let Some(key) = fb.steady_key() else {
        return false;
    };
    let p = fb.sf_private();
    let h = &p.stHeader;
    let [lo, hi, check] = slot_of(key, h.ctrl());
    let served = p.aReserved[0] == lo
        && p.aReserved[1] == hi
        && p.aReserved[2] == check
        && p.nGroupHalt == 0
        && h.intact(B::MAGIC)
        && !time::went_backwards(now, h.tLast)
        && fb.live_consts() == latched(fb);
    if served {
        fb.sf_private_mut().stHeader.tLast = now;
        let reset_level = bools::is_true(fb.reset_raw());
        write(fb, reset_level);
    }
    served
}

/// The full call, then this call's key stored when the call returned `SL_OK`, the group
/// did not halt the block, the private state after it equals the one before it but for
/// `tLast` (a fixed point: no state, flag, edge memory, entry time or latched constant
/// changed) and no time runs in that state ([`SfSteady::timed`]); the slot cleared
/// otherwise. Out of line: the fast path stays small.
#[inline(never)]
pub fn settle<B: SfSteady>(fb: &mut B, now: u32) -> Status {
    let Some(key) = fb.steady_key() else {
        let status = full_cycle(fb, now);
        fb.sf_private_mut().aReserved = [0; 3];
        return status;
    };
    let mut before = *fb.sf_private();
    let status = full_cycle(fb, now);
    let after = fb.sf_private();
    before.stHeader.tLast = after.stHeader.tLast;
    before.aReserved = after.aReserved;
    let fixed = status == Status::Ok && after.nGroupHalt == 0 && before == *after && !fb.timed();
    let slot = if fixed {
        slot_of(key, fb.sf_private().stHeader.ctrl())
    } else {
        [0; 3]
    };
    fb.sf_private_mut().aReserved = slot;
    status
}

/// After a caught panic: the instance is forced into the library fault with its outputs
/// FALSE (only Activate FALSE leaves it).
pub fn force_fault<B: SfBlock>(fb: &mut B) {
    if !consistent(fb) {
        idle(fb, false);
    }
    fb.sf_private_mut().aReserved = [0; 3];
    let now = fb.sf_private().stHeader.tLast;
    enter(&mut fb.sf_private_mut().stHeader, SL_SF_DIAG_CORRUPT, now);
    write(fb, false);
    fb.sf_private_mut().stHeader.seal();
}

/// The DiagCode text of a block's states or of a library code.
pub fn diag_text(texts: &[(u16, &'static str)], code: u16) -> Option<&'static str> {
    if code == 0 {
        return Some("FB not activated (idle)");
    }
    texts
        .iter()
        .chain(LIBRARY_CODES)
        .find(|(c, _)| *c == code)
        .map(|(_, t)| *t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn library_codes_are_errors_without_demand_or_reset_bits() {
        for (c, _) in LIBRARY_CODES {
            assert!(*c >= 0xC000 && c & 0x0C00 == 0);
            assert_eq!(phase_of(*c), SL_STATE_ERROR);
        }
        assert_eq!(phase_of(0), SL_STATE_STOP);
        assert_eq!(phase_of(0x8001), SL_STATE_RUN);
    }

    #[test]
    fn the_trigger_memory_gives_one_rising_edge() {
        let mut p = SL_SF_PRIVATE::ZERO;
        assert!(!trigger_rising(&p, 0));
        assert!(trigger_rising(&p, 1));
        assert!(!trigger_rising(&p, 2), "an invalid byte is FALSE");
        store_trigger(&mut p, 1);
        assert!(!trigger_rising(&p, 1), "held");
        assert_eq!(p.stHeader.nFlags, F_TRIGGER_PREV);
        store_trigger(&mut p, 2);
        assert!(trigger_rising(&p, 1));
        assert_eq!(p.stHeader.nFlags, 0);
    }

    #[test]
    fn outputs_follow_the_code() {
        let o = outputs(0x8402, false, None);
        assert!(o.ready && o.reset_request && !o.safety_demand && !o.enabled && !o.error);
        assert!(!outputs(0x8402, true, None).reset_request);
        assert!(outputs(0x8000, false, None).enabled);
        assert_eq!(outputs(0, false, None), SfOut::default());
        let e = outputs(SL_SF_DIAG_CORRUPT, false, None);
        assert!(e.error && e.ready && !e.safety_demand && !e.reset_request);
    }
}
