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

super::analog_variants! {
    FB_ARITH:
        INT SL_TYPE_ADD_INT = 16 => FB_ADD_INT[Add, i16, 2, 6], UINT SL_TYPE_ADD_UINT = 17 => FB_ADD_UINT[Add, u16, 2, 6],
        DINT SL_TYPE_ADD_DINT = 18 => FB_ADD_DINT[Add, i32, 6, 4], UDINT SL_TYPE_ADD_UDINT = 19 => FB_ADD_UDINT[Add, u32, 6, 4],
        INT SL_TYPE_SUB_INT = 20 => FB_SUB_INT[Sub, i16, 2, 6], UINT SL_TYPE_SUB_UINT = 21 => FB_SUB_UINT[Sub, u16, 2, 6],
        DINT SL_TYPE_SUB_DINT = 22 => FB_SUB_DINT[Sub, i32, 6, 4], UDINT SL_TYPE_SUB_UDINT = 23 => FB_SUB_UDINT[Sub, u32, 6, 4],
        INT SL_TYPE_MUL_INT = 24 => FB_MUL_INT[Mul, i16, 2, 6], UINT SL_TYPE_MUL_UINT = 25 => FB_MUL_UINT[Mul, u16, 2, 6],
        DINT SL_TYPE_MUL_DINT = 26 => FB_MUL_DINT[Mul, i32, 6, 4], UDINT SL_TYPE_MUL_UDINT = 27 => FB_MUL_UDINT[Mul, u32, 6, 4]
}
super::analog_variants! {
    FB_DIV:
        INT SL_TYPE_DIV_INT = 28 => FB_DIV_INT[i16, 0, 6], UINT SL_TYPE_DIV_UINT = 29 => FB_DIV_UINT[u16, 0, 6],
        DINT SL_TYPE_DIV_DINT = 30 => FB_DIV_DINT[i32, 4, 4], UDINT SL_TYPE_DIV_UDINT = 31 => FB_DIV_UDINT[u32, 4, 4]
}

/// `nRounding` Floor: toward −∞ (docs/semantics.md A2).
pub const SL_ROUNDING_FLOOR: u16 = 0;
/// `nRounding` Ceil: toward +∞.
pub const SL_ROUNDING_CEIL: u16 = 1;
/// `nRounding` Round: commercial rounding, half away from zero (2.5 → 3, −2.5 → −3).
pub const SL_ROUNDING_ROUND: u16 = 2;

/// Diag message "An underflow has occurred" (parameters: AnalogIn1, AnalogIn2).
pub const SL_TEXT_ARITH_UNDERFLOW: u16 = 0x4080;
/// Diag message "An overflow has occurred" (parameters: AnalogIn1, AnalogIn2).
pub const SL_TEXT_ARITH_OVERFLOW: u16 = 0x4081;

/// `wInputActive` of every arithmetic block: AnalogIn1 (bit 8) and AnalogIn2 (bit 9),
/// both required (ABI-2 §10.5).
pub const ARITH_ACTIVE: u16 = 0x0300;

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

crate::base::layout::private_struct! {
    /// Private state of the arithmetic blocks (48 bytes). Never written by the user.
    SL_ARITH_PRIVATE {
        /// Latched `wInputActive`.
        pub wActive: u16,
        /// Latched `nRounding` (0 for ADD, SUB, MUL).
        pub wRounding: u16,
        /// The result of the last RUN cycle as a 32-bit pattern.
        pub dwOut: u32,
        /// Diag message parameters 2 and 3 latched at the ERROR entry.
        pub adwPar: [u32; 2],
        pub aReserved: [u8; 4],
    }
}

const _: () = assert!(core::mem::size_of::<SL_ARITH_PRIVATE>() == 48);

crate::base::layout::block_struct! {
    /// FB ADD / SUB / MUL instance (ABI-2 §11.2). `P1` and `P2` are the reserved bytes that
    /// make the 16- and 32-bit layouts differ (after the parameters, after AnalogOut).
    FB_ARITH[O: ArithOp, T: Analog; P1, P2] {
        no_bool_inputs;
        /// At the analog input base 24: AnalogIn1 (active bit 8, required).
        pub nAnalogIn1: T,
        /// At 24 + W: AnalogIn2 (active bit 9, required).
        pub nAnalogIn2: T,
        /// At 24 + 2W: bits 8 and 9 must be set, no other (ARITH_ACTIVE).
        pub wInputActive: u16,
        /// Reserved up to the output base (16-bit: 2 bytes, 32-bit: 6).
        pub aReserved2: [u8; P1],
        /// At the output base (16-bit 32, 32-bit 40): Error, TRUE in ERROR only.
        pub bError: SL_BOOL,
        /// Reserved up to the analog output base.
        pub aReserved3: [u8; 7],
        /// At the output base + 8: AnalogOut, the result in RUN, else 0.
        pub nAnalogOut: T,
        /// Reserved up to the info data.
        pub aReserved4: [u8; P2],
    } info [aReserved5, aReserved6] SL_ARITH_PRIVATE, "48 bytes":
        "the manual's status value (RUN, STOP, ERROR, RESET).",
        "diag value (1 underflow, 2 overflow) + library bits 13-15.",
        "Text ID of the latched diag message (0x4080, 0x4081), 0 = none.",
        "message parameter 2 (AnalogIn1 as a 32-bit pattern).", "message parameter 3 (AnalogIn2).";
    /// The operation (no bytes).
    pub _op: PhantomData<O>
}

crate::base::layout::block_struct! {
    /// FB DIV instance (ABI-2 §11.2): as [`FB_ARITH`] with `nRounding` before `wInputActive`.
    FB_DIV[T: Analog; P1, P2] {
        no_bool_inputs;
        /// At the analog input base 24: AnalogIn1, the dividend (active bit 8, required).
        pub nAnalogIn1: T,
        /// At 24 + W: AnalogIn2, the divisor (active bit 9, required); 0 gives 0, no error.
        pub nAnalogIn2: T,
        /// At 24 + 2W: "Division Rounding": SL_ROUNDING_FLOOR, _CEIL, _ROUND.
        pub nRounding: u16,
        /// At 26 + 2W: bits 8 and 9 must be set, no other (ARITH_ACTIVE).
        pub wInputActive: u16,
        /// Reserved up to the output base (16-bit: none, 32-bit: 4 bytes).
        pub aReserved2: [u8; P1],
        /// At the output base (16-bit 32, 32-bit 40): Error, TRUE in ERROR only.
        pub bError: SL_BOOL,
        /// Reserved up to the analog output base.
        pub aReserved3: [u8; 7],
        /// At the output base + 8: AnalogOut, the rounded quotient in RUN, else 0.
        pub nAnalogOut: T,
        /// Reserved up to the info data.
        pub aReserved4: [u8; P2],
    } info [aReserved5, aReserved6] SL_ARITH_PRIVATE, "48 bytes":
        "the manual's status value (RUN, STOP, ERROR, RESET).",
        "diag value (2 overflow: MIN ÷ −1) + library bits 13-15.",
        "Text ID of the latched diag message (0x4081), 0 = none.",
        "message parameter 2 (AnalogIn1 as a 32-bit pattern).", "message parameter 3 (AnalogIn2)."
}

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

crate::base::block::block_states!(
    /// The states of FB ADD, SUB, MUL and DIV, every variant (manual §4.16.2 ff.).
    ArithState: Run, Stop, Error, Reset
);

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
