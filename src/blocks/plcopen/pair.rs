//! The two-channel machine of SF_Equivalent and SF_Antivalent (PLCopen TC5 Part 1;
//! research `plcopen_safety.md` §4.11, §4.12, §5): two channels → one output, the time the
//! channels may differ monitored from the entry into each waiting state (DiscrepancyTime,
//! a constant); no Reset, no restart interlock: an error is left by switching both
//! channels to their inactive state. SF_Antivalent is the same machine on (NC, NOT NO)
//! (§4.12's table is §4.11's with A = NC, B = NOT NO; semantics PP2).

use crate::base::time;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/plcopen/pair.rs"));

/// One call's channels, in the active sense (Equivalent: A, B; Antivalent: NC, NOT NO).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PairIn {
    /// Channel A active.
    pub a: bool,
    /// Channel B active.
    pub b: bool,
}

/// The transition table of research §4.11 (v2.01 codes), first matching guard wins; the
/// discrepancy time runs from the entry into the waiting state (`in_state`, ms) and has
/// elapsed at `in_state >= t` (T#0: at the first evaluation, research §8.13).
pub fn next(s: PairState, i: &PairIn, in_state: u32, t: u32) -> PairState {
    use PairState::*;
    let elapsed = time::reached(in_state, 0, t);
    let none = !i.a && !i.b;
    match s {
        Init if i.a && !i.b => WaitB,
        Init if i.b && !i.a => WaitA,
        Init if i.a && i.b => Enabled,
        WaitB if elapsed => Error1,
        WaitB if !i.a => Init,
        WaitB if i.b => Enabled,
        WaitA if elapsed => Error2,
        WaitA if !i.b => Init,
        WaitA if i.a => Enabled,
        Enabled if i.a != i.b => FromActiveWait,
        Enabled if none => Init,
        FromActiveWait if elapsed => Error3,
        FromActiveWait if none => Init,
        Error1 | Error2 | Error3 if none => Init,
        Idle | Init | WaitB | WaitA | Enabled | FromActiveWait | Error1 | Error2 | Error3 => s,
    }
}

/// The struct of SF_Equivalent and SF_Antivalent, declared once: they differ in the names
/// and docs of the channels and the output's name.
/// build.rs writes every invocation out for cbindgen (`build_support/expand.rs`).
#[macro_export]
#[doc(hidden)]
macro_rules! pair_struct {
    ($(#[doc = $doc:literal])* $name:ident: $a:ident $a_doc:literal, $b:ident $b_doc:literal => $output:ident) => {
        $crate::base::layout::block_struct! {
            $(#[doc = $doc])*
            $name {
                /// Offset 0. Activate: FALSE = idle (DiagCode 0000, every output FALSE), highest priority.
                pub Activate: SL_BOOL,
                #[doc = concat!(" Offset 1. ", stringify!($a), ": ", $a_doc)]
                pub $a: SL_BOOL,
                #[doc = concat!(" Offset 2. ", stringify!($b), ": ", $b_doc)]
                pub $b: SL_BOOL,
                /// Offset 3. Library extension, constant: DiagCode profile, 0 = v2.01 (default), 1 = v1.0; latched at activation.
                pub nDiagProfile: u8,
                /// Offset 4. DiscrepancyTime (constant, ms): how long the channels may differ; latched at activation.
                pub DiscrepancyTime: u32,
                /// Offset 8 (output base). Ready: TRUE while activated (DiagCode != 0000).
                pub Ready: SL_BOOL,
                #[doc = concat!(" Offset 9. ", stringify!($output), ": the safety output, TRUE only at DiagCode 8000.")]
                pub $output: SL_BOOL,
                /// Offset 10. SafetyDemand: the safety function is demanded (v2.01 code bit 0x0800).
                pub SafetyDemand: SL_BOOL,
                /// Offset 11. Error: DiagCode >= C000.
                pub Error: SL_BOOL,
                /// Offset 12. Reserved.
                pub aReserved1: [u8; 2],
                /// Offset 14. DiagCode: the state or error, in the profile of nDiagProfile.
                pub DiagCode: u16,
            } private 16: $crate::base::sf::SL_SF_PRIVATE, 40
        }
    };
}

/// Declares a two-channel block's envelope plumbing from its struct: tag, name, the two
/// channel fields, whether channel B is read inverted (Antivalent's NO), the output.
#[macro_export]
#[doc(hidden)]
macro_rules! pair_block {
    ($ty:ident, $tag:expr, $a:ident, $b:ident, b_negated: $neg:expr, $output:ident) => {
        $crate::impl_sf_member!($ty {
            tag: $tag,
            input: [Activate, $a, $b],
            param: [nDiagProfile, DiscrepancyTime],
            output: [Ready, $output, SafetyDemand, Error],
        });

        $crate::impl_sf_block!($ty {
            tag: $tag,
            diag: $crate::blocks::plcopen::pair::PairState,
            input: $crate::blocks::plcopen::pair::PairIn,
            reset: none,
            consts(s): [s.DiscrepancyTime],
            rules: [$crate::base::sf::time0_rule("DiscrepancyTime")],
            next: |s, inp, _reset, in_state, times| {
                $crate::blocks::plcopen::pair::next(s, inp, in_state, times[0])
            },
        } {
            /// An invalid byte reads as the channel's inactive value (NC FALSE, NO TRUE).
            #[inline(always)]
            fn decode(&self) -> (Self::In, bool) {
                let p = $crate::base::bools::pack([self.$a, self.$b]);
                let neg = if $neg { 0b10 } else { 0 };
                let v = $crate::base::bools::logical(p, 0b11, neg);
                (
                    $crate::blocks::plcopen::pair::PairIn {
                        a: v & 1 != 0,
                        b: v & 2 != 0,
                    },
                    p.invalid != 0,
                )
            }
            #[inline(always)]
            fn write_outputs(&mut self, o: &$crate::base::sf::SfOut) {
                $crate::sf_outputs!(self, o, $output, SafetyDemand);
            }
        });
    };
}

/// The steady-state fast path of a two-channel block (`base::sf::SfSteady`): the key is
/// Activate and the two channels; the waiting states read the discrepancy time.
#[macro_export]
#[doc(hidden)]
macro_rules! pair_steady {
    ($ty:ident, $a:ident, $b:ident) => {
        $crate::sf_steady!($ty: [Activate, $a, $b], timed: |b| {
            use $crate::blocks::plcopen::pair::PairState::*;
            !matches!(b.diag_state(), Some(Idle | Init | Enabled | Error1 | Error2 | Error3))
        });
    };
}
