//! The state machine of the combinational blocks AND (manual §4.1), OR (§4.2), XOR (§4.34)
//! and DECOUPLE (§4.6): outputs are a function of this cycle's inputs; RUN (1) when the
//! block's function is satisfied, SAFE (3) otherwise (blocks without SAFE stay in RUN with
//! FALSE outputs). No block errors of their own: ERROR (4) only comes from the envelope.

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/logic.rs"));

crate::base::envelope::steady_private!(SL_LOGIC_PRIVATE, adwSteady, window 2);

const _: () = assert!(core::mem::size_of::<SL_LOGIC_PRIVATE>() == 64);

/// Parameters of a combinational block as the user wrote them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LogicParams {
    pub active: u16,
    pub negated: u16,
}

/// Result of evaluating one cycle's inputs.
#[derive(Clone, Copy, Debug, Default)]
pub struct LogicIn {
    /// RUN or SAFE.
    pub state: u8,
    /// Output bits valid in RUN (bit n = n-th output).
    pub outputs: u8,
}

/// What distinguishes AND, OR, XOR and DECOUPLE.
pub trait LogicBlock: crate::base::block::Private<P = SL_LOGIC_PRIVATE> {
    /// Type tag stored in the private header.
    const TAG: u16;
    /// Bits of wInputActive that exist.
    const INPUTS: u16;
    /// Bits of wInputNegated that exist.
    const NEGATABLE: u16;
    /// At least this many inputs must be active.
    const MIN_ACTIVE: u32;

    fn params(&self) -> LogicParams;
    /// The fast-path key: the bytes [8, 18) of the struct (the inputs, bRun, bErrAck;
    /// `base::envelope::window!`), or (XOR, whose bytes do not fit) its inputs gathered
    /// into bits with bRun and bErrAck.
    fn window(&self) -> Option<[u64; 2]>;
    /// Evaluates the input bytes with the latched masks; the flag tells whether an active
    /// input byte was an invalid BOOL.
    fn evaluate(&self, active: u8, negated: u8) -> (LogicIn, bool);
    /// Writes the output fields (`outputs` already FALSE outside RUN) and info data.
    fn set_outputs(&mut self, outputs: u8, state: u8, diag: u16);
}

/// The envelope's view of a block of this family; invoked in the member's own file.
macro_rules! logic_block {
    ($t:ty) => {
        const _: () = {
            $crate::base::envelope::family_prelude!($crate::blocks::boolean::logic);

            impl $t {
                /// Every rule of the family; `Block::RULES` leaves the last (negation) out
                /// for a block without `wInputNegated`.
                const LOGIC_RULES: [$crate::base::reason::RuleDef<LogicParams>; 3] = {
                    use $crate::base::reason::{when, Rule, RuleDef, Unit};
                    [
                        $crate::base::reason::rule!(no_bits_outside "wInputActive", |p| p.active, Self::INPUTS),
                        RuleDef::new("wInputActive", Rule::MinBits, Unit::Hex, |p| {
                            let min = Self::MIN_ACTIVE;
                            when(p.active.count_ones() < min, p.active, min)
                        }),
                        $crate::base::reason::rule!(no_bits_outside "wInputNegated", |p| p.negated, Self::NEGATABLE),
                    ]
                };
            }

            impl Block for $t {
                const MAGIC: u16 = <$t as LogicBlock>::TAG;
                type Params = LogicParams;
                type In = LogicIn;

                #[inline(always)]
                fn live_params(&self) -> LogicParams {
                    self.params()
                }
                #[inline(always)]
                fn latched_params(&self) -> LogicParams {
                    let h = &self.private().stHeader;
                    LogicParams {
                        active: u16::from(h.nActive),
                        negated: u16::from(h.nNegated),
                    }
                }
                /// Known inputs, at least the block's number active; negation only where the
                /// block has `wInputNegated` (the last rule).
                const RULES: &'static [$crate::base::reason::RuleDef<LogicParams>] =
                    if Self::NEGATABLE == 0 {
                        Self::LOGIC_RULES.split_at(2).0
                    } else {
                        &Self::LOGIC_RULES
                    };
                #[inline(always)]
                fn store_params(&mut self, p: &LogicParams) {
                    let h = &mut self.private_mut().stHeader;
                    h.nActive = p.active as u8;
                    h.nNegated = p.negated as u8;
                }
                #[inline(always)]
                fn latched_crc(&self) -> u16 {
                    let h = &self.private().stHeader;
                    param_crc(Self::MAGIC, h.nActive, h.nNegated, h.wOptions, &[])
                }
                #[inline(always)]
                fn decode(&mut self) -> (LogicIn, bool) {
                    let h = &self.private().stHeader;
                    self.evaluate(h.nActive, h.nNegated)
                }
                #[inline(always)]
                fn start(&mut self, inp: &LogicIn, now: u32) {
                    self.step(inp, now);
                }
                #[inline(always)]
                fn step(&mut self, inp: &LogicIn, _now: u32) -> Status {
                    // An output switching on is where the latched parameters are verified (C3).
                    let was_on = if self.private().stHeader.nState == SL_STATE_RUN {
                        self.private().stHeader.wAux as u8
                    } else {
                        0
                    };
                    let rising = inp.state == SL_STATE_RUN && inp.outputs & !was_on != 0;
                    if rising && self.latched_crc() != self.private().stHeader.wParamCrc {
                        self.private_mut().stHeader.enter_error(SL_DIAG_CORRUPT);
                        return Status::Corrupt;
                    }
                    let h = &mut self.private_mut().stHeader;
                    h.nState = inp.state;
                    h.wAux = u16::from(inp.outputs);
                    Status::Ok
                }
                $crate::base::envelope::steady_hooks!();
                #[inline(always)]
                fn write_outputs(&mut self) {
                    let h = self.private().stHeader;
                    let outputs = if h.nState == SL_STATE_RUN {
                        h.wAux as u8
                    } else {
                        0
                    };
                    self.set_outputs(outputs, h.nState, h.wDiag);
                }
            }

            impl $crate::base::envelope::Steady for $t {
                #[inline(always)]
                fn steady_key(&self) -> Option<[u64; 2]> {
                    self.window()
                }
                /// Combinational: nothing depends on the time.
                #[inline(always)]
                fn quiet(&self) -> bool {
                    true
                }
                /// RUN or SAFE and the outputs are a function of this call's inputs, in
                /// `start` as in `step`; the envelope's own transitions (STOP → run, ERROR →
                /// RESET on the ErrAck edge, RESET → run or STOP on its fall, bRun FALSE →
                /// STOP) end in a state the same bytes keep: the edge memory then holds the
                /// level, and a latch or an error that would differ returns another status.
                const IDEMPOTENT: bool = true;
            }
        };
    };
}
pub(crate) use logic_block;

/// The struct of the eight-input gates AND (manual §4.1) and OR (§4.2), declared once: they
/// differ in the field names and a few words of the docs (`$op` "And"/"Or", `$OP`
/// "AND"/"OR", `$in1` the doc of input 1, `$least` the minimum of active inputs).
/// build.rs writes every invocation out for cbindgen (`build_support/expand.rs`).
macro_rules! gate8_struct {
    ($(#[doc = $doc:literal])* $name:ident: $op:literal, $OP:literal, $in1:literal, $least:literal;
     [$i1:ident, $i2:ident, $i3:ident, $i4:ident, $i5:ident, $i6:ident, $i7:ident, $i8:ident]
     => $out:ident) => {
        $crate::base::layout::block_struct! {
            $(#[doc = $doc])*
            $name {
                /// Offset 0. Reserved, keep 0.
                pub aReserved0: [u8; 8],
                #[doc = concat!(" Offset 8. ", $in1)]
                pub $i1: SL_BOOL,
                /// Offset 9.
                pub $i2: SL_BOOL,
                /// Offset 10.
                pub $i3: SL_BOOL,
                /// Offset 11.
                pub $i4: SL_BOOL,
                /// Offset 12.
                pub $i5: SL_BOOL,
                /// Offset 13.
                pub $i6: SL_BOOL,
                /// Offset 14.
                pub $i7: SL_BOOL,
                /// Offset 15.
                pub $i8: SL_BOOL,
                /// Offset 16. FbRun of the owning group.
                pub bRun: SL_BOOL,
                /// Offset 17. ErrAck of the owning group.
                pub bErrAck: SL_BOOL,
                /// Offset 18. Reserved, keep 0.
                pub aReserved1: [u8; 2],
                #[doc = concat!(" Offset 20. Bit n-1 set: ", $op, "Inn is active ", $least, ".")]
                pub wInputActive: u16,
                #[doc = concat!(" Offset 22. Bit n-1 set: ", $op, "Inn is a make contact (negated before the ", $OP, ").")]
                pub wInputNegated: u16,
                /// Offset 24 (output base + 0). Reserved.
                pub aReserved2: [u8; 1],
                #[doc = concat!(" Offset 25 (output base + 1). ", $OP, " of the active inputs.")]
                pub $out: SL_BOOL,
                /// Offset 26. Reserved.
                pub aReserved3: [u8; 6],
            } tail 32 33 34 36 40 [aReserved4, aReserved5] $crate::blocks::boolean::logic::SL_LOGIC_PRIVATE, 64:
                "(SL_STATE_*)", "Diagnostic bits (only the library bits 13-15)."
        }
    };
}
pub(crate) use gate8_struct;

/// Every logically TRUE active input (AND): RUN, else SAFE.
#[inline(always)]
pub(crate) const fn all(logical: u8, active: u8) -> bool {
    logical == active
}

/// At least one logically TRUE active input (OR): RUN, else SAFE.
#[inline(always)]
pub(crate) const fn any(logical: u8, _active: u8) -> bool {
    logical != 0
}

/// The block behind a `gate8_struct!`: its states, `BlockInfo`, member and family impls.
/// `$run` says from the logical and the active input bits whether the gate is in RUN.
macro_rules! gate8_block {
    ($(#[doc = $doc:literal])* $name:ident: $state:ident, $tag:ident, $label:literal,
     magic $magic:literal, min $min:literal, $run:path;
     [$($i:ident),*] => $out:ident) => {
        $crate::base::block::block_states!(
            $(#[doc = $doc])*
            $state: Run, Stop, Safe, Error, Reset
        );

        $crate::impl_member!([] $name {
            info: $crate::base::block::BlockInfo::of::<$state>($tag, $label),
            state: $state,
            private: $crate::blocks::boolean::logic::SL_LOGIC_PRIVATE,
            input: [$($i),*],
            param: [wInputActive, wInputNegated],
            output: [$out],
            info_fields: [],
        });

        impl $crate::blocks::boolean::logic::LogicBlock for $name {
            const TAG: u16 = $magic;
            const INPUTS: u16 = 0xFF;
            const NEGATABLE: u16 = 0xFF;
            const MIN_ACTIVE: u32 = $min;

            fn window(&self) -> Option<[u64; 2]> {
                Some($crate::base::envelope::window!(self, 2: $($i,)* bRun, bErrAck))
            }
            fn params(&self) -> $crate::blocks::boolean::logic::LogicParams {
                $crate::blocks::boolean::logic::LogicParams {
                    active: self.wInputActive,
                    negated: self.wInputNegated,
                }
            }
            fn evaluate(
                &self,
                active: u8,
                negated: u8,
            ) -> ($crate::blocks::boolean::logic::LogicIn, bool) {
                let p = $crate::base::bools::pack([$(self.$i),*]);
                let on = $run($crate::base::bools::logical(p, active, negated), active);
                let state = if on {
                    $crate::base::types::SL_STATE_RUN
                } else {
                    $crate::base::types::SL_STATE_SAFE
                };
                (
                    $crate::blocks::boolean::logic::LogicIn {
                        state,
                        outputs: u8::from(on),
                    },
                    p.invalid & active != 0,
                )
            }
            fn set_outputs(&mut self, outputs: u8, state: u8, diag: u16) {
                self.$out = outputs & 1;
                self.nState = state;
                self.nDiag = diag;
            }
        }

        $crate::blocks::boolean::logic::logic_block!($name);
    };
}
pub(crate) use gate8_block;
