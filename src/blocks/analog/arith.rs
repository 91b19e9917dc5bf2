//! FB ADD, FB SUB, FB MUL, FB DIV — manual §4.16–§4.19; layout ABI-2 §11.2, rules ABI-2 §12.
//!
//! `AnalogOut = AnalogIn1 (+ − · ÷) AnalogIn2`, computed exactly (in `i128`) and then
//! compared with the range of the variant's type: below it → ERROR, diag value 1, message
//! 0x4080; above it → ERROR, diag value 2, message 0x4081 (parameters 2 and 3: the two
//! inputs). In ERROR, STOP and RESET the output is 0 and `bError` is TRUE only in ERROR.
//! DIV by 0 gives 0 without an error; the quotient is rounded per `nRounding`
//! (docs/semantics.md A2). States RUN (1), STOP (2), ERROR (4), RESET (5): no SAFE.
//!
//! One implementation for the four operations and the four integer types: the operation is
//! a type parameter ([`ArithOp`]), the integer type another ([`Analog`]); the two structs
//! differ only in DIV's `nRounding`. The variants are type aliases (`FB_ADD_INT` …), which
//! cbindgen writes as structs of those names (build.rs).

#![allow(non_camel_case_types)] // the ABI's names (FB_ADD_INT …)

use super::{
    magic, range_message, set_computed, value_if, Analog, SL_DIAG_VALUE_OVERFLOW,
    SL_DIAG_VALUE_UNDERFLOW,
};
use crate::base::block::BlockInfo;
use crate::base::block::FieldType;
use crate::base::envelope::Block;
use crate::base::header::param_crc;
use crate::base::reason::rule;
use crate::base::reason::RuleDef;
use crate::base::types::*;
use core::marker::PhantomData;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/analog/arith.rs"));

/// An operation: ADD, SUB, MUL (same layout) or DIV.
pub trait ArithOp: 'static {
    /// The block has `nRounding` (DIV).
    const ROUNDING: bool = false;
    /// Type tags per variant.
    const TAGS: [u16; 4];
    /// Registry names per variant.
    const NAMES: [&'static str; 4];
    /// The exact result; `rounding` only matters to DIV.
    fn apply(a: i128, b: i128, rounding: u16) -> i128;
}

/// FB ADD (manual §4.16).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Add;
/// FB SUB (manual §4.17).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Sub;
/// FB MUL (manual §4.18).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Mul;
/// FB DIV (manual §4.19).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Div;

/// An operation's variant tags, its registry names (`ADD_INT` …), whether it has
/// `nRounding`, and its exact result.
macro_rules! arith_op {
    ($op:ident $name:literal [$($tag:ident),+] $(rounding $rnd:literal)?;
     |$a:ident, $b:ident, $r:pat_param| $body:expr) => {
        impl ArithOp for $op {
            $(const ROUNDING: bool = $rnd;)?
            const TAGS: [u16; 4] = [$($tag),+];
            const NAMES: [&'static str; 4] = [
                concat!($name, "_INT"),
                concat!($name, "_UINT"),
                concat!($name, "_DINT"),
                concat!($name, "_UDINT"),
            ];
            fn apply($a: i128, $b: i128, $r: u16) -> i128 {
                $body
            }
        }
    };
}

arith_op!(Add "ADD" [SL_TYPE_ADD_INT, SL_TYPE_ADD_UINT, SL_TYPE_ADD_DINT, SL_TYPE_ADD_UDINT];
    |a, b, _| a + b);
arith_op!(Sub "SUB" [SL_TYPE_SUB_INT, SL_TYPE_SUB_UINT, SL_TYPE_SUB_DINT, SL_TYPE_SUB_UDINT];
    |a, b, _| a - b);
arith_op!(Mul "MUL" [SL_TYPE_MUL_INT, SL_TYPE_MUL_UINT, SL_TYPE_MUL_DINT, SL_TYPE_MUL_UDINT];
    |a, b, _| a * b);
arith_op!(Div "DIV" [SL_TYPE_DIV_INT, SL_TYPE_DIV_UINT, SL_TYPE_DIV_DINT, SL_TYPE_DIV_UDINT]
rounding true;
|a, b, rounding| {
    if b == 0 {
        // Manual §4.19: "If the AnalogIn2 input is 0, the AnalogOut output is set to 0.
        // In this case no error is output."
        return 0;
    }
    divide(a, b, rounding)
});

/// `a / b` (b ≠ 0) rounded per `rounding` (docs/semantics.md A2).
pub fn divide(a: i128, b: i128, rounding: u16) -> i128 {
    let q = a / b; // toward zero
    let r = a % b;
    if r == 0 {
        return q;
    }
    let negative = (a < 0) != (b < 0);
    match rounding {
        SL_ROUNDING_FLOOR => q - i128::from(negative),
        SL_ROUNDING_CEIL => q + i128::from(!negative),
        // Half away from zero: |r| ≥ |b| − |r| rounds the magnitude up.
        _ => {
            if 2 * r.abs() >= b.abs() {
                if negative {
                    q - 1
                } else {
                    q + 1
                }
            } else {
                q
            }
        }
    }
}

const _: () = assert!(core::mem::size_of::<SL_ARITH_PRIVATE>() == 48);

// The ABI-2 §11.2 numbers of the two DIV layouts (the one place `nRounding` sits).
const _: () = {
    use core::mem::offset_of;
    assert!(offset_of!(FB_DIV_INT, nRounding) == 28 && offset_of!(FB_DIV_INT, wInputActive) == 30);
    assert!(
        offset_of!(FB_DIV_DINT, nRounding) == 32 && offset_of!(FB_DIV_DINT, wInputActive) == 34
    );
    assert!(
        offset_of!(FB_ADD_INT, wInputActive) == 28 && offset_of!(FB_ADD_DINT, wInputActive) == 32
    );
    assert!(offset_of!(FB_ADD_INT, stPrivate) == 64 && offset_of!(FB_ADD_DINT, stPrivate) == 72);
};

/// Diag value texts of every arithmetic block (manual §4.16.2 ff.).
const DIAG_VALUES: &[(u16, &str)] =
    super::range_diag_values!("AnalogOut", "The output AnalogOut is correct", "");

const fn info<O: ArithOp, T: Analog>() -> BlockInfo {
    BlockInfo::of::<ArithState>(O::TAGS[T::VARIANT], O::NAMES[T::VARIANT]).diag_values(DIAG_VALUES)
}

crate::impl_member!([O: ArithOp, T: Analog, const P1: usize, const P2: usize] FB_ARITH<O, T, P1, P2> {
    info: info::<O, T>(),
    state: ArithState,
    private: SL_ARITH_PRIVATE,
    input: [nAnalogIn1, nAnalogIn2],
    param: [wInputActive],
    output: [bError, nAnalogOut],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

crate::impl_member!([T: Analog, const P1: usize, const P2: usize] FB_DIV<T, P1, P2> {
    info: info::<Div, T>(),
    state: ArithState,
    private: SL_ARITH_PRIVATE,
    input: [nAnalogIn1, nAnalogIn2],
    param: [nRounding, wInputActive],
    output: [bError, nAnalogOut],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

/// What the envelope needs of the two structs; everything else is shared below.
pub trait ArithFb: crate::base::block::Private<P = SL_ARITH_PRIVATE> {
    /// The integer type.
    type T: Analog;
    /// The operation.
    type Op: ArithOp;
    /// AnalogIn1, AnalogIn2.
    fn operands(&self) -> (Self::T, Self::T);
    /// The live `nRounding` (0 where the block has none).
    fn rounding(&self) -> u16;
    /// The live `wInputActive`.
    fn active(&self) -> u16;
    /// Writes bError, AnalogOut and the info data.
    fn set_outputs(
        &mut self,
        error: bool,
        out: Self::T,
        state: u8,
        diag: u16,
        msg: (u16, u32, u32),
    );
}

macro_rules! arith_fb {
    ([$($gen:tt)*] $ty:ty, $op:ty, $rounding:expr) => {
        impl<$($gen)*> ArithFb for $ty {
            type T = T;
            type Op = $op;
            #[inline(always)]
            fn operands(&self) -> (T, T) {
                (self.nAnalogIn1, self.nAnalogIn2)
            }
            #[inline(always)]
            fn rounding(&self) -> u16 {
                $rounding(self)
            }
            #[inline(always)]
            fn active(&self) -> u16 {
                self.wInputActive
            }
            #[inline(always)]
            fn set_outputs(&mut self, error: bool, out: T, state: u8, diag: u16, msg: (u16, u32, u32)) {
                self.bError = u8::from(error);
                self.nAnalogOut = out;
                self.nState = state;
                self.nDiag = diag;
                (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) = msg;
            }
        }
    };
}

arith_fb!([O: ArithOp, T: Analog, const P1: usize, const P2: usize] FB_ARITH<O, T, P1, P2>, O, |_: &Self| 0);
arith_fb!([T: Analog, const P1: usize, const P2: usize] FB_DIV<T, P1, P2>, Div, |s: &Self| s.nRounding);

/// Parameters as the user wrote them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ArithParams {
    active: u16,
    rounding: u16,
}

/// One cycle's inputs: the operands and their exact result.
#[derive(Clone, Copy, Debug)]
pub struct ArithIn {
    a: u32,
    b: u32,
    /// The exact result in range (as a pattern), or the diag value of the range error.
    result: Result<u32, u16>,
}

/// The parameter rules of the arithmetic blocks; the second (`nRounding`) is DIV's only.
const ARITH_RULES: [RuleDef<ArithParams>; 2] = [
    rule!(equals "wInputActive", |p| p.active, ARITH_ACTIVE),
    rule!(at_most "nRounding" in Plain, |p| p.rounding, SL_ROUNDING_ROUND),
];

impl<B: ArithFb + crate::base::envelope::Instance + crate::base::block::Registered> Block for B {
    const MAGIC: u16 = magic(<B as crate::base::block::Registered>::INFO.tag);
    type Params = ArithParams;
    type In = ArithIn;

    #[inline(always)]
    fn live_params(&self) -> ArithParams {
        ArithParams {
            active: self.active(),
            rounding: self.rounding(),
        }
    }
    #[inline(always)]
    fn latched_params(&self) -> ArithParams {
        let p = self.private();
        ArithParams {
            active: p.wActive,
            rounding: p.wRounding,
        }
    }
    /// Both inputs active; DIV's rounding one of its three modes (the other operations
    /// have no `nRounding`).
    const RULES: &'static [RuleDef<ArithParams>] = if <B::Op as ArithOp>::ROUNDING {
        &ARITH_RULES
    } else {
        ARITH_RULES.split_at(1).0
    };
    fn store_params(&mut self, p: &ArithParams) {
        let q = self.private_mut();
        q.wActive = p.active;
        q.wRounding = p.rounding;
    }
    fn latched_crc(&self) -> u16 {
        let p = self.private();
        param_crc(Self::MAGIC, 0, 0, 0, &[p.wActive, p.wRounding])
    }
    #[inline(always)]
    fn decode(&mut self) -> (ArithIn, bool) {
        let (a, b) = self.operands();
        let exact = <B::Op as ArithOp>::apply(a.wide(), b.wide(), self.private().wRounding);
        let result = if exact < B::T::MIN {
            Err(SL_DIAG_VALUE_UNDERFLOW)
        } else if exact > B::T::MAX {
            Err(SL_DIAG_VALUE_OVERFLOW)
        } else {
            Ok(B::T::narrow(exact).to_bits())
        };
        (
            ArithIn {
                a: a.to_bits(),
                b: b.to_bits(),
                result,
            },
            false,
        )
    }
    fn start(&mut self, inp: &ArithIn, now: u32) {
        self.step(inp, now);
    }
    #[inline(always)]
    fn step(&mut self, inp: &ArithIn, _now: u32) -> Status {
        // Entering RUN is where the output starts to carry a value: verify the latched
        // parameters first (C3).
        if self.corrupt_entering_run(inp.result.is_ok()) {
            return Status::Corrupt;
        }
        let p = self.private_mut();
        if set_computed(&mut p.stHeader, &mut p.dwOut, inp.result).is_err() {
            p.adwPar = [inp.a, inp.b];
        }
        Status::Ok
    }
    fn error_remains(&mut self, inp: &ArithIn) -> bool {
        inp.result.is_err()
    }
    #[inline(always)]
    fn write_outputs(&mut self) {
        let p = *self.private();
        let h = p.stHeader;
        let run = h.nState == SL_STATE_RUN;
        let error = h.nState == SL_STATE_ERROR;
        let msg = range_message(
            &h,
            [SL_TEXT_ARITH_UNDERFLOW, SL_TEXT_ARITH_OVERFLOW],
            p.adwPar,
        );
        let out = value_if::<B::T>(run, p.dwOut);
        self.set_outputs(error, out, h.nState, h.wDiag, msg);
    }
}
