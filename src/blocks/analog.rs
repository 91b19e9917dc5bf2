//! What every block with analog signals shares (ABI-2 §10, §12): the integer type of a
//! variant and the magic of its private header. The blocks themselves are generic over
//! [`Analog`]; their variants are type aliases (`FB_ADD_INT`, `FB_LIMIT_UDINT` …).

use crate::registry::FieldType;

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


/// Magic of the private header of an analog block: its type tag in the analog family's
/// range, so that every variant (the layouts differ) has its own.
pub const fn magic(tag: u16) -> u16 {
    0xA700 | tag
}
