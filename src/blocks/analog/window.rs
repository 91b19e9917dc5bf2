//! The state machine FB SLI (manual §4.27) and FB SLI2 (§4.28) have in common: a rising
//! edge of SLI latches Position (LatchPosition) and enters RUN; while SLI stays TRUE,
//! PositionDiff = Position − LatchPosition is checked against −Limit neg ≤ PositionDiff ≤
//! Limit pos (SLIActive); leaving the window is an ERROR (diag value 1 underflow / 2
//! overflow, message 0x40C0 / 0x40C1 with Position and LatchPosition) or, SLI2 with
//! `SL_OPT_SLI2_EXCEEDED_SUPPORT`, EXCEEDED (7) until SLI falls; SLI FALSE → SAFE. Layouts
//! ABI-2 §11.9, §11.10; readings docs/semantics.md SI1–SI8. The two blocks differ only in
//! their structs, the options they offer and the outputs they have ([`WindowFb`]); the
//! state machine below exists once, for every variant of both.

use super::Analog;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/analog/window.rs"));

const _: () = assert!(core::mem::size_of::<SL_SLI_PRIVATE>() == 64);

/// Parameters as the user wrote them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WindowParams {
    pub active: u16,
    /// Limit pos, Limit neg.
    pub limits: [u32; 2],
    pub options: u32,
}

/// One cycle's inputs after BOOL decoding.
#[derive(Clone, Copy, Debug)]
pub struct WindowIn {
    /// SLI's level (an invalid byte reads FALSE).
    pub sli: bool,
    /// SLI rose in this call.
    pub rising: bool,
    /// Position as a 32-bit pattern of its type.
    pub position: u32,
}

/// What a block shows, decided by [`outputs`] from the private state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WindowOut {
    pub error: bool,
    pub sli_active: bool,
    /// BelowMin (SLI2 only): in EXCEEDED, below the window.
    pub below: bool,
    /// AboveMax (SLI2 only): in EXCEEDED, above the window.
    pub above: bool,
    /// PositionDiff as a 32-bit pattern of the output type.
    pub diff: u32,
}

/// What distinguishes FB SLI from FB SLI2.
pub trait WindowFb: crate::base::block::Private<P = SL_SLI_PRIVATE> {
    /// Type of Position (the variant).
    type T: Analog;
    /// Type of PositionDiff: INT16 for the 16-bit variants, INT32 for the 32-bit ones.
    type TS: Analog;
    /// `dwOptions` bits the block offers (SLI: none).
    const OPTIONS: u32;
    /// The live parameter fields.
    fn params(&self) -> WindowParams;
    /// SLI's byte.
    fn sli_raw(&self) -> u8;
    fn position(&self) -> Self::T;
    /// Writes the output fields and the info data.
    fn set_outputs(&mut self, out: WindowOut, state: u8, diag: u16, msg: (u16, u32, u32));
}

/// `wAux` bits.
pub(crate) const PREV_SLI: u8 = 1 << 0;
pub(crate) const BELOW: u16 = 1 << 1;
pub(crate) const ABOVE: u16 = 1 << 2;

/// Where a PositionDiff lies relative to the window −Limit neg … Limit pos.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Zone {
    Inside,
    /// PositionDiff < −Limit neg: underflow (diag value 1).
    Below,
    /// PositionDiff > Limit pos: overflow (diag value 2).
    Above,
}

/// PositionDiff = Position − LatchPosition, exact; with `modular` (SLI2
/// `SL_OPT_SLI2_OVERFLOW_ALLOWED`) reduced modulo 2^W into the signed range of W bits, so
/// a wrap of the position counter is the short move it is (semantics SI6).
#[inline(always)]
pub fn difference<T: Analog>(position: i128, latch: i128, modular: bool) -> i128 {
    let d = position - latch;
    if !modular {
        return d;
    }
    let span = T::MAX - T::MIN + 1;
    let r = d.rem_euclid(span);
    if r >= span / 2 {
        r - span
    } else {
        r
    }
}

/// The zone of `diff` (both bounds inclusive: "−NegLimit ≤ PositionDiff ≤ PosLimit").
#[inline(always)]
pub fn zone(diff: i128, limits: [u32; 2]) -> Zone {
    if diff < -i128::from(limits[1]) {
        Zone::Below
    } else if diff > i128::from(limits[0]) {
        Zone::Above
    } else {
        Zone::Inside
    }
}

/// The outputs of a state (manual §4.27.2, §4.28.2.3 status tables).
#[inline(always)]
pub fn outputs(p: &SL_SLI_PRIVATE) -> WindowOut {
    let h = &p.stHeader;
    let (error, sli_active, diff) = match h.nState {
        SL_STATE_RUN => (false, true, p.dwDiff),
        SL_STATE_SLI2_EXCEEDED => (false, false, p.dwDiff),
        SL_STATE_ERROR => (true, false, 0),
        _ => (false, false, 0),
    };
    let exceeded = h.nState == SL_STATE_SLI2_EXCEEDED;
    WindowOut {
        error,
        sli_active,
        below: exceeded && h.wAux & BELOW != 0,
        above: exceeded && h.wAux & ABOVE != 0,
        diff,
    }
}

/// A block of this family from its struct: [`WindowFb`] over the fields every member has
/// (SLI, Position, the limits, wInputActive, Error, SLIActive, PositionDiff and the info
/// data), the options it offers and the field that carries them (`0`: none), the BOOL
/// outputs of its own (`bBelowMin = below`), and the envelope's view; invoked in the
/// member's own file with the struct's generic parameters and its two type parameters.
macro_rules! window_block {
    ([$($gen:tt)*] $t:ty; $tt:ident, $ts:ident; options $opts:expr => $live:tt;
     outputs [$($o:ident = $w:ident),*]) => {
        impl<$($gen)*> $crate::blocks::analog::window::WindowFb for $t {
            type T = $tt;
            type TS = $ts;
            const OPTIONS: u32 = $opts;
            #[inline(always)]
            fn params(&self) -> $crate::blocks::analog::window::WindowParams {
                $crate::blocks::analog::window::WindowParams {
                    active: self.wInputActive,
                    limits: [self.nLimitPos, self.nLimitNeg],
                    options: $crate::blocks::analog::window::window_block!(@options self $live),
                }
            }
            #[inline(always)]
            fn sli_raw(&self) -> u8 {
                self.bSLI
            }
            #[inline(always)]
            fn position(&self) -> $tt {
                self.nPosition
            }
            #[inline(always)]
            fn set_outputs(
                &mut self,
                out: $crate::blocks::analog::window::WindowOut,
                state: u8,
                diag: u16,
                msg: (u16, u32, u32),
            ) {
                self.bError = u8::from(out.error);
                self.bSLIActive = u8::from(out.sli_active);
                $(self.$o = u8::from(out.$w);)*
                self.nPositionDiff = $crate::base::block::FieldType::from_bits(out.diff);
                self.nState = state;
                self.nDiag = diag;
                (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) = msg;
            }
        }
        $crate::blocks::analog::window::window_block!([$($gen)*] $t);
    };
    (@options $s:ident 0) => { 0 };
    (@options $s:ident $f:ident) => { $s.$f };
    ([$($gen:tt)*] $t:ty) => {
        const _: () = {
            use $crate::blocks::analog::{
                magic, range_message, Analog, SL_DIAG_VALUE_OVERFLOW, SL_DIAG_VALUE_UNDERFLOW,
            };
            use $crate::blocks::analog::window::{
                SL_OPT_SLI2_EXCEEDED_SUPPORT, SL_OPT_SLI2_OVERFLOW_ALLOWED, SL_STATE_SLI2_EXCEEDED,
                SL_SLI_ACTIVE, SL_TEXT_SLI_OVERFLOW, SL_TEXT_SLI_UNDERFLOW,
                difference, outputs, zone, WindowFb, WindowIn, WindowParams, Zone, ABOVE, BELOW,
                PREV_SLI,
            };
            use $crate::base::envelope::Block;
            use $crate::base::{bools, header::{crc_words, param_crc}};
            use $crate::base::block::{Private, Registered};
            use $crate::base::types::*;

            type Pos<B> = <B as WindowFb>::T;
            type Diff<B> = <B as WindowFb>::TS;

            impl<$($gen)*> $t {
                /// Every rule of the family; `Block::RULES` leaves the last (options) out
                /// for a block without `dwOptions`.
                const WINDOW_RULES: [$crate::base::reason::RuleDef<WindowParams>; 4] = {
                    use $crate::base::reason::{when, Rule, RuleDef, Unit};
                    [
                        $crate::base::reason::rule!(equals "wInputActive", |p| p.active, SL_SLI_ACTIVE),
                        RuleDef::new("nLimitPos", Rule::AtMost, Unit::Plain, |p| {
                            let max = Diff::<Self>::MAX as i64;
                            when(i64::from(p.limits[0]) > max, p.limits[0], max)
                        }),
                        RuleDef::new("nLimitNeg", Rule::AtMost, Unit::Plain, |p| {
                            let max = Diff::<Self>::MAX as i64;
                            when(i64::from(p.limits[1]) > max, p.limits[1], max)
                        }),
                        $crate::base::reason::rule!(no_bits_outside "dwOptions", |p| p.options, <Self as WindowFb>::OPTIONS),
                    ]
                };
            }

            impl<$($gen)*> Block for $t {
                const MAGIC: u16 = magic(<Self as Registered>::INFO.tag);
                type Params = WindowParams;
                type In = WindowIn;

                #[inline(always)]
                fn live_params(&self) -> WindowParams {
                    self.params()
                }
                #[inline(always)]
                fn latched_params(&self) -> WindowParams {
                    let p = self.private();
                    WindowParams {
                        active: p.wActive,
                        limits: p.adwLimit,
                        options: p.dwOptions,
                    }
                }
                /// SLI and Position active, nothing else; each limit within the range of
                /// PositionDiff's type, so every in-window difference fits the output
                /// (ABI-2 §11.9, §12.8, semantics SI5); only the block's own options (the
                /// last rule, for the block that has `dwOptions`).
                const RULES: &'static [$crate::base::reason::RuleDef<WindowParams>] =
                    if <Self as WindowFb>::OPTIONS == 0 {
                        Self::WINDOW_RULES.split_at(3).0
                    } else {
                        &Self::WINDOW_RULES
                    };
                fn store_params(&mut self, p: &WindowParams) {
                    let q = self.private_mut();
                    q.wActive = p.active;
                    q.adwLimit = p.limits;
                    q.dwOptions = p.options;
                }
                fn latched_crc(&self) -> u16 {
                    let p = self.private();
                    let [pos, neg] = p.adwLimit;
                    let o = p.dwOptions;
                    param_crc(
                        Self::MAGIC,
                        0,
                        0,
                        0,
                        &crc_words![u16 p.wActive, u32 pos, u32 neg, u32 o],
                    )
                }
                /// SLI reads FALSE when invalid and then makes no edge (ABI-2 §12.7). The
                /// edge memory follows SLI in every state, so an SLI held TRUE through
                /// STOP → run or RESET is no edge (semantics SI3).
                #[inline(always)]
                fn decode(&mut self) -> (WindowIn, bool) {
                    let raw = self.sli_raw();
                    let position = self.position().to_bits();
                    let h = &mut self.private_mut().stHeader;
                    let mut prev = h.wAux as u8;
                    let sli = bools::edge(raw, &mut prev, PREV_SLI);
                    h.wAux = (h.wAux & !u16::from(PREV_SLI)) | u16::from(prev & PREV_SLI);
                    (
                        WindowIn {
                            sli: sli.level,
                            rising: sli.rising,
                            position,
                        },
                        raw > 1,
                    )
                }
                /// Start state SAFE; this call's rising edge already latches.
                fn start(&mut self, inp: &WindowIn, now: u32) {
                    let h = &mut self.private_mut().stHeader;
                    h.nState = SL_STATE_SAFE;
                    h.wAux &= u16::from(PREV_SLI);
                    self.step(inp, now);
                }
                #[inline(always)]
                fn step(&mut self, inp: &WindowIn, _now: u32) -> Status {
                    let p = *self.private();
                    let state = p.stHeader.nState;
                    let exceeded_support = p.dwOptions & SL_OPT_SLI2_EXCEEDED_SUPPORT != 0;
                    let running = matches!(state, SL_STATE_RUN | SL_STATE_SLI2_EXCEEDED);
                    // A corrupted latch would move the window: checked before it is used.
                    if running && p.dwLatch != !p.dwLatchCheck {
                        self.private_mut().stHeader.enter_error(SL_DIAG_CORRUPT);
                        return Status::Corrupt;
                    }
                    let latch = if state == SL_STATE_SAFE { inp.position } else { p.dwLatch };
                    let position = Pos::<Self>::from_bits(inp.position).wide();
                    let diff = difference::<Pos<Self>>(
                        position,
                        Pos::<Self>::from_bits(latch).wide(),
                        p.dwOptions & SL_OPT_SLI2_OVERFLOW_ALLOWED != 0,
                    );
                    let zone = zone(diff, p.adwLimit);
                    let next = match (state, inp.sli, inp.rising, zone) {
                        (SL_STATE_SAFE, _, true, _) => SL_STATE_RUN,
                        (SL_STATE_SAFE, _, false, _) => SL_STATE_SAFE,
                        (SL_STATE_RUN | SL_STATE_SLI2_EXCEEDED, false, _, _) => SL_STATE_SAFE,
                        (SL_STATE_RUN, true, _, Zone::Inside) => SL_STATE_RUN,
                        (SL_STATE_RUN, true, _, _) if exceeded_support => SL_STATE_SLI2_EXCEEDED,
                        (SL_STATE_RUN, true, _, _) => SL_STATE_ERROR,
                        (SL_STATE_SLI2_EXCEEDED, true, _, _) => SL_STATE_SLI2_EXCEEDED,
                        // No other running state exists (the envelope refuses other values).
                        _ => {
                            self.private_mut().stHeader.enter_error(SL_DIAG_CORRUPT);
                            return Status::Corrupt;
                        }
                    };
                    // SLIActive switches on: verify the latched parameters first (C3).
                    if self.corrupt_at_switch_on(next == SL_STATE_RUN && state != SL_STATE_RUN) {
                        return Status::Corrupt;
                    }
                    let q = self.private_mut();
                    let h = &mut q.stHeader;
                    h.wAux &= u16::from(PREV_SLI);
                    match next {
                        SL_STATE_RUN => {
                            q.dwLatch = latch;
                            q.dwLatchCheck = !latch;
                            // In the window, so within Limit pos/neg ≤ the output's maximum.
                            q.dwDiff = Diff::<Self>::narrow(diff).to_bits();
                            h.nState = SL_STATE_RUN;
                        }
                        SL_STATE_SLI2_EXCEEDED => {
                            h.wAux |= match zone {
                                Zone::Below => BELOW,
                                Zone::Above => ABOVE,
                                Zone::Inside => 0,
                            };
                            let saturated = diff.clamp(Diff::<Self>::MIN, Diff::<Self>::MAX);
                            q.dwDiff = Diff::<Self>::narrow(saturated).to_bits();
                            h.nState = SL_STATE_SLI2_EXCEEDED;
                        }
                        SL_STATE_ERROR => {
                            q.dwDiff = 0;
                            q.adwPar = [inp.position, latch];
                            h.enter_error(if zone == Zone::Below {
                                SL_DIAG_VALUE_UNDERFLOW
                            } else {
                                SL_DIAG_VALUE_OVERFLOW
                            });
                        }
                        _ => {
                            q.dwDiff = 0;
                            h.nState = SL_STATE_SAFE;
                        }
                    }
                    Status::Ok
                }
                // A window violation is an event: nothing remains (ABI-2 §12.5, SI4).
                // `error_remains` keeps its default (false).
                /// "Should only exit the RESET state if ErrAck=FALSE and SLI=FALSE" (SI4).
                fn may_leave_reset(&self, inp: &WindowIn) -> bool {
                    !inp.sli
                }
                #[inline(always)]
                fn write_outputs(&mut self) {
                    let p = *self.private();
                    let h = p.stHeader;
                    let msg = range_message(&h, [SL_TEXT_SLI_UNDERFLOW, SL_TEXT_SLI_OVERFLOW], p.adwPar);
                    self.set_outputs(outputs(&p), h.nState, h.wDiag, msg);
                }
            }
        };
    };
}
pub(crate) use window_block;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn modular_difference_is_the_short_way_round() {
        assert_eq!(difference::<u16>(2, 65_534, true), 4);
        assert_eq!(difference::<u16>(65_534, 2, true), -4);
        assert_eq!(difference::<u16>(2, 65_534, false), -65_532);
        assert_eq!(difference::<i16>(-32_768, 32_767, true), 1);
        assert_eq!(difference::<u32>(0, 0x8000_0000, true), -0x8000_0000);
        assert_eq!(difference::<i32>(5, -5, true), 10);
    }

    #[test]
    fn zone_bounds_are_inclusive() {
        assert_eq!(zone(-3, [5, 3]), Zone::Inside);
        assert_eq!(zone(-4, [5, 3]), Zone::Below);
        assert_eq!(zone(5, [5, 3]), Zone::Inside);
        assert_eq!(zone(6, [5, 3]), Zone::Above);
    }
}
