//! What every block with analog signals shares (ABI-2 §10, §12): the integer type of a
//! variant and the magic of its private header. The blocks themselves are generic over
//! [`Analog`]; their variants are type aliases (`FB_ADD_INT`, `FB_LIMIT_UDINT` …).

use crate::prim::header::SL_PRIVATE_HEADER;
use crate::registry::FieldType;
use crate::types::{LIBRARY_DIAG_BITS, SL_STATE_ERROR};

/// An integer type of the analog variants (ABI-2 §10.3).
pub trait Analog: FieldType + Copy + Default + PartialEq + core::fmt::Debug + 'static {
    /// Index of the variant: 0 INT, 1 UINT, 2 DINT, 3 UDINT.
    const VARIANT: usize;
    /// Smallest value.
    const MIN: i128;
    /// Largest value.
    const MAX: i128;
    /// The exact value.
    fn wide(self) -> i128;
    /// The value of an `i128` known to lie in `MIN..=MAX`.
    fn narrow(v: i128) -> Self;
    /// 0.
    const ZERO: Self;
}

macro_rules! analog {
    ($($t:ty => $i:literal),*) => {$(
        impl Analog for $t {
            const VARIANT: usize = $i;
            const MIN: i128 = <$t>::MIN as i128;
            const MAX: i128 = <$t>::MAX as i128;
            const ZERO: Self = 0;
            #[inline(always)]
            fn wide(self) -> i128 {
                self as i128
            }
            #[inline(always)]
            fn narrow(v: i128) -> Self {
                v as $t
            }
        }
    )*};
}
analog!(i16 => 0, u16 => 1, i32 => 2, u32 => 3);

/// Diag value 1 of every analog block with a range check (ABI-2 §12.1): the result is
/// below the smallest value of the type.
pub const SL_DIAG_VALUE_UNDERFLOW: u16 = 1;
/// Diag value 2: the result is above the largest value of the type.
pub const SL_DIAG_VALUE_OVERFLOW: u16 = 2;

/// `v` as a value of `T`, or the diag value of the range error it makes (ABI-2 §12.1:
/// exact result, nothing wraps, nothing saturates): underflow below `T::MIN`, overflow
/// above `T::MAX`.
#[inline(always)]
pub fn in_range<T: Analog>(v: i128) -> Result<T, u16> {
    if v < T::MIN {
        Err(SL_DIAG_VALUE_UNDERFLOW)
    } else if v > T::MAX {
        Err(SL_DIAG_VALUE_OVERFLOW)
    } else {
        Ok(T::narrow(v))
    }
}

/// Magic of the private header of an analog block: its type tag in the analog family's
/// range, so that every variant (the layouts differ) has its own.
pub const fn magic(tag: u16) -> u16 {
    0xA700 | tag
}

/// The diag message of the info data (ABI-2 §10.4): in ERROR with a diag value of `texts`
/// (value, Text ID), that Text ID with the parameters latched at the ERROR entry; otherwise
/// none (0, 0, 0). Cleared with the diag value on ERROR → RESET.
pub fn diag_message(h: &SL_PRIVATE_HEADER, texts: &[(u16, u16)], par: [u32; 2]) -> (u16, u32, u32) {
    let value = h.wDiag & !LIBRARY_DIAG_BITS;
    match texts.iter().find(|(v, _)| *v == value) {
        Some((_, text)) if h.nState == SL_STATE_ERROR => (*text, par[0], par[1]),
        _ => (0, 0, 0),
    }
}

/// The unsigned variants (UINT, UDINT): blocks whose manual types are "UINT16 (n=2)
/// UINT32 (n=4)" only, such as VIOLATIONCOUNTER.
pub trait Unsigned: Analog {}
impl Unsigned for u16 {}
impl Unsigned for u32 {}
