//! The state machine of the combinational blocks AND (manual §4.1), OR (§4.2), XOR (§4.34)
//! and DECOUPLE (§4.6): outputs are a function of this cycle's inputs; RUN (1) when the
//! block's function is satisfied, SAFE (3) otherwise (blocks without SAFE stay in RUN with
//! FALSE outputs). No block errors of their own: ERROR (4) only comes from the envelope.

use crate::base::header::SL_PRIVATE_HEADER;

/// Private state of the combinational blocks (64 bytes). Never written by the user.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct SL_LOGIC_PRIVATE {
    pub stHeader: SL_PRIVATE_HEADER,
    /// Reserved, 0.
    pub aReserved: [u8; 4],
    /// Fast-path slot (`base::envelope`): the key window (two 64-bit words), then its check
    /// words.
    pub adwSteady: [u32; 8],
}

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
    /// `base::envelope::window!`), `None` where they do not fit (XOR).
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
                #[inline(always)]
                fn params_valid(p: &LogicParams) -> bool {
                    p.active & !Self::INPUTS == 0
                        && p.negated & !Self::NEGATABLE == 0
                        && p.active.count_ones() >= Self::MIN_ACTIVE
                }
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
                #[inline(always)]
                fn error_remains(&mut self, _inp: &LogicIn) -> bool {
                    false
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
