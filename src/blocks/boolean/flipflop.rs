//! The state machine FB RS (manual §4.10, reset dominant) and FB SR (§4.11, set dominant)
//! have in common: Set TRUE with Reset FALSE → SET (9, output TRUE); Reset TRUE with Set
//! FALSE → SAFE (3, output FALSE); both TRUE → the dominant input decides; both FALSE → the
//! output keeps its current state. The blocks differ only in `SET_DOMINANT`. Neither
//! reports an error of its own: ERROR (4) only comes from the envelope.

use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/flipflop.rs"));

const _: () = assert!(core::mem::size_of::<SL_FLIPFLOP_PRIVATE>() == 64);

crate::base::envelope::steady_private!(SL_FLIPFLOP_PRIVATE, adwSteady, window 2);

/// Input bits: bit 0 = Reset, bit 1 = Set (ABI §9).
pub(crate) const RESET: u8 = 1 << 0;
pub(crate) const SET: u8 = 1 << 1;
pub(crate) const INPUTS: u16 = (RESET | SET) as u16;

/// The state value SET (9); FB_RS and FB_SR use the same number.
pub(crate) const STATE_SET: u8 = SL_STATE_RS_SET;
const _: () = assert!(SL_STATE_RS_SET == SL_STATE_SR_SET);

/// Parameters as the user wrote them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FlipFlopParams {
    pub active: u16,
    pub negated: u16,
}

/// Logical inputs of one cycle, invalid bytes already read as their safe value.
#[derive(Clone, Copy, Debug, Default)]
pub struct FlipFlopIn {
    pub reset: bool,
    pub set: bool,
}

/// What distinguishes RS from SR.
pub trait FlipFlopBlock: crate::base::block::Private<P = SL_FLIPFLOP_PRIVATE> {
    /// Type tag stored in the private header.
    const TAG: u16;
    /// Both inputs TRUE: SET (SR) or SAFE (RS).
    const SET_DOMINANT: bool;

    fn params(&self) -> FlipFlopParams;
    /// Raw input bytes: Reset, Set.
    fn raw(&self) -> [u8; 2];
    fn set_outputs(&mut self, out: bool, state: u8, diag: u16);
}

/// The next output from the current one (manual §4.10.1 / §4.11.1).
#[inline]
pub const fn next(is_set: bool, inp: FlipFlopIn, set_dominant: bool) -> bool {
    match (inp.reset, inp.set) {
        (true, true) => set_dominant,
        (true, false) => false,
        (false, true) => true,
        (false, false) => is_set,
    }
}

#[inline]
pub(crate) const fn state_of(is_set: bool) -> u8 {
    if is_set {
        STATE_SET
    } else {
        SL_STATE_SAFE
    }
}

/// The struct of FB RS and FB SR, declared once: they differ in the output's name and in
/// which input's doc says "(dominant)" (`$reset`, `$set`: the two inputs' docs).
/// build.rs writes every invocation out for cbindgen (`build_support/expand.rs`).
macro_rules! flipflop_struct {
    ($(#[doc = $doc:literal])* $name:ident: $reset:literal, $set:literal => $out:ident) => {
        $crate::base::layout::block_struct! {
            $(#[doc = $doc])*
            $name {
                /// Offset 0. Reserved, keep 0.
                pub aReserved0: [u8; 8],
                #[doc = concat!(" Offset 8. Reset: logic 1 switches the output off", $reset, ".")]
                pub bReset: SL_BOOL,
                #[doc = concat!(" Offset 9. Set: logic 1 switches the output on", $set, ".")]
                pub bSet: SL_BOOL,
                /// Offset 10. Reserved, keep 0.
                pub aReserved1: [u8; 6],
                /// Offset 16. FbRun of the owning group.
                pub bRun: SL_BOOL,
                /// Offset 17. ErrAck of the owning group.
                pub bErrAck: SL_BOOL,
                /// Offset 18. Reserved, keep 0.
                pub aReserved2: [u8; 2],
                /// Offset 20. Bit 0: Reset is active, bit 1: Set is active (at least one).
                pub wInputActive: u16,
                /// Offset 22. Same bits: the input is a make contact (negated before evaluation).
                pub wInputNegated: u16,
                /// Offset 24 (output base + 0). Reserved.
                pub aReserved3: [u8; 1],
                /// Offset 25 (output base + 1). TRUE in SET; the safe state is FALSE.
                pub $out: SL_BOOL,
                /// Offset 26. Reserved.
                pub aReserved4: [u8; 6],
            } tail 32 33 34 36 40 [aReserved5, aReserved6] $crate::blocks::boolean::flipflop::SL_FLIPFLOP_PRIVATE, 64:
                "(SL_STATE_*)", "Diagnostic bits (only the library bits 13-15)."
        }
    };
}
pub(crate) use flipflop_struct;

/// The block behind a `flipflop_struct!`: its states, `BlockInfo`, member and the
/// envelope's view; invoked in the member's own file.
macro_rules! flipflop_block {
    // The whole block: states (`$set` the SET state's constant), info and member.
    ($(#[doc = $doc:literal])* $t:ident: $state:ident, $tag:ident, $label:literal, $set:ident;
     magic $magic:literal, set_dominant $dom:literal, output $out:ident) => {
        $crate::base::block::block_states!(
            $(#[doc = $doc])*
            $state: Stop, Safe, Error, Reset, Set = $set, "SET"
        );

        $crate::impl_member!([] $t {
            info: $crate::base::block::BlockInfo::of::<$state>($tag, $label),
            state: $state,
            private: $crate::blocks::boolean::flipflop::SL_FLIPFLOP_PRIVATE,
            input: [bReset, bSet],
            param: [wInputActive, wInputNegated],
            output: [$out],
            info_fields: [],
        });

        $crate::blocks::boolean::flipflop::flipflop_block!($t {
            tag: $magic,
            set_dominant: $dom,
            output: $out,
        });
    };
    // A member from its description: RS and SR differ only in these.
    ($t:ty { tag: $tag:expr, set_dominant: $dom:expr, output: $out:ident $(,)? }) => {
        impl $crate::blocks::boolean::flipflop::FlipFlopBlock for $t {
            const TAG: u16 = $tag;
            const SET_DOMINANT: bool = $dom;

            fn params(&self) -> $crate::blocks::boolean::flipflop::FlipFlopParams {
                $crate::blocks::boolean::flipflop::FlipFlopParams {
                    active: self.wInputActive,
                    negated: self.wInputNegated,
                }
            }
            fn raw(&self) -> [u8; 2] {
                [self.bReset, self.bSet]
            }
            fn set_outputs(&mut self, out: bool, state: u8, diag: u16) {
                self.$out = u8::from(out);
                self.nState = state;
                self.nDiag = diag;
            }
        }
        $crate::blocks::boolean::flipflop::flipflop_block!($t);
    };
    ($t:ty) => {
        const _: () = {
            $crate::base::envelope::family_prelude!($crate::blocks::boolean::flipflop);

            impl Block for $t {
                const MAGIC: u16 = <$t as FlipFlopBlock>::TAG;
                type Params = FlipFlopParams;
                type In = FlipFlopIn;

                fn live_params(&self) -> FlipFlopParams {
                    self.params()
                }
                fn latched_params(&self) -> FlipFlopParams {
                    let h = &self.private().stHeader;
                    FlipFlopParams {
                        active: u16::from(h.nActive),
                        negated: u16::from(h.nNegated),
                    }
                }
                /// At least one input active, no bits for inputs the block does not have
                /// (semantics R1).
                const RULES: &'static [$crate::base::reason::RuleDef<FlipFlopParams>] = {
                    use $crate::base::reason::{when, Rule, RuleDef, Unit};
                    &[
                        $crate::base::reason::rule!(no_bits_outside "wInputActive", |p| p.active, INPUTS),
                        $crate::base::reason::rule!(no_bits_outside "wInputNegated", |p| p.negated, INPUTS),
                        RuleDef::new("wInputActive", Rule::AnyBitOf, Unit::Hex, |p| {
                            when(p.active == 0, p.active, INPUTS)
                        }),
                    ]
                };
                fn store_params(&mut self, p: &FlipFlopParams) {
                    let h = &mut self.private_mut().stHeader;
                    h.nActive = p.active as u8;
                    h.nNegated = p.negated as u8;
                }
                fn latched_crc(&self) -> u16 {
                    let h = &self.private().stHeader;
                    param_crc(Self::MAGIC, h.nActive, h.nNegated, h.wOptions, &[])
                }
                /// An inactive input reads FALSE (no command). An invalid byte reads as the value
                /// that demands the safe state of the output: Reset TRUE, Set FALSE, whatever
                /// the negation bit (ABI §2, semantics R3).
                fn decode(&mut self) -> (FlipFlopIn, bool) {
                    let h = &self.private().stHeader;
                    let active = h.nActive;
                    let p = bools::pack(self.raw());
                    let logical = bools::logical(p, active, h.nNegated);
                    let invalid = p.invalid & active;
                    let inp = FlipFlopIn {
                        reset: (logical | invalid) & RESET != 0,
                        set: logical & SET != 0,
                    };
                    (inp, invalid != 0)
                }
                /// STOP → run and RESET → run: the output was FALSE, so "remains in its current
                /// state" means SAFE unless this cycle's inputs set it (semantics R4). The
                /// parameters were latched, or compared with the live ones, in this same call.
                fn start(&mut self, inp: &FlipFlopIn, _now: u32) {
                    let h = &mut self.private_mut().stHeader;
                    h.nState = state_of(next(false, *inp, Self::SET_DOMINANT));
                }
                fn step(&mut self, inp: &FlipFlopIn, _now: u32) -> Status {
                    let is_set = match self.private().stHeader.nState {
                        SL_STATE_SAFE => false,
                        STATE_SET => true,
                        // A state value this block never takes: the memory cannot be trusted.
                        _ => false,
                    };
                    let known = matches!(self.private().stHeader.nState, SL_STATE_SAFE | STATE_SET);
                    let set = next(is_set, *inp, Self::SET_DOMINANT);
                    // The output switches on: verify the latched parameters first (C3).
                    if !known || (set && !is_set && !self.params_intact()) {
                        self.private_mut().stHeader.enter_error(SL_DIAG_CORRUPT);
                        return Status::Corrupt;
                    }
                    self.private_mut().stHeader.nState = state_of(set);
                    Status::Ok
                }
                $crate::base::envelope::steady_hooks!();
                fn write_outputs(&mut self) {
                    let h = self.private().stHeader;
                    self.set_outputs(h.nState == STATE_SET, h.nState, h.wDiag);
                }
            }

            impl $crate::base::envelope::Steady for $t {
                /// The bytes [8, 18): Reset, Set, bRun, bErrAck.
                #[inline(always)]
                fn steady_key(&self) -> Option<[u64; 2]> {
                    Some($crate::base::envelope::window!(self, 2:
                        bReset, bSet, aReserved1, bRun, bErrAck
                    ))
                }
                /// A memory without timers: nothing depends on the time.
                #[inline(always)]
                fn quiet(&self) -> bool {
                    true
                }
                /// The next state is Reset's or Set's command, or the state held when there
                /// is none, from every state, in `start` as in `step` (`next` applied twice
                /// to the same inputs gives what it gave once); the envelope's transitions
                /// as for the combinational blocks (`logic.rs`).
                const IDEMPOTENT: bool = true;
            }
        };
    };
}
pub(crate) use flipflop_block;

#[cfg(test)]
mod tests {
    use super::*;

    fn inp(reset: bool, set: bool) -> FlipFlopIn {
        FlipFlopIn { reset, set }
    }

    #[test]
    fn truth_tables() {
        for is_set in [false, true] {
            for dominant in [false, true] {
                assert!(next(is_set, inp(false, true), dominant));
                assert!(!next(is_set, inp(true, false), dominant));
                assert_eq!(next(is_set, inp(false, false), dominant), is_set);
                assert_eq!(next(is_set, inp(true, true), dominant), dominant);
            }
        }
    }
}
