//! How the C structs of the blocks are declared: the attributes every one carries, the
//! info data every TwinSAFE block ends with (`block_struct!`) and the common head of every
//! private state (`private_struct!`). Both are `*_struct` macros: build.rs writes each
//! invocation out as plain Rust for cbindgen (`build_support/expand.rs`), so the header
//! shows literal declarations. [`Zeroed`] gives the all-zero value of a struct whose
//! arrays have no `Default` (generic or longer than 32) in a `const fn` (`zeroed_struct!`).

use core::marker::PhantomData;

/// The all-zero value of a type (every C struct of the ABI may be zero: a block initialises
/// itself on its first cycle, ABI §3.6).
pub trait Zeroed: Sized {
    /// All bytes zero.
    const ZERO: Self;
}

macro_rules! zeroed_scalars {
    ($($t:ty),*) => {$(
        impl Zeroed for $t {
            const ZERO: Self = 0;
        }
    )*};
}
zeroed_scalars!(u8, u16, u32, i16, i32);

impl<T: Zeroed + Copy, const N: usize> Zeroed for [T; N] {
    const ZERO: Self = [T::ZERO; N];
}

impl<T> Zeroed for PhantomData<T> {
    const ZERO: Self = PhantomData;
}

impl Zeroed for crate::base::header::SL_PRIVATE_HEADER {
    const ZERO: Self = Self::ZERO;
}

/// Declares a block's instance struct (ABI §3): `#[repr(C)]`, the derives, the fields the
/// block has of its own, then the info data every TwinSAFE block ends with: nState, a
/// reserved byte, nDiag, a reserved word and the private state. `tail` gives the offsets of
/// those five fields (the "Offset N." the header prints and build.rs checks), the names of
/// the two reserved fields (the header's names differ between blocks), the private type,
/// the docs of nState (after "The manual's status value ") and nDiag, and the size of the
/// private state. A generic struct (`FB_X[T, const P: usize]`) derives no `Default`: its
/// reserved gaps are arrays of generic length.
macro_rules! block_struct {
    ($(#[doc = $doc:literal])* $name:ident { $($body:tt)* }
     tail $so:literal $ro:literal $do:literal $qo:literal $po:literal
         [$r:ident, $q:ident] $private:ty, $bytes:literal: $sdoc:expr, $ddoc:expr) => {
        $(#[doc = $doc])*
        #[repr(C)]
        #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
        #[allow(non_snake_case, non_camel_case_types)]
        pub struct $name {
            $($body)*
            #[doc = concat!(" Offset ", $so, ". The manual's status value ", $sdoc, ".")]
            pub nState: u8,
            #[doc = concat!(" Offset ", $ro, ". Reserved.")]
            pub $r: [u8; 1],
            #[doc = concat!(" Offset ", $do, ". ", $ddoc)]
            pub nDiag: u16,
            #[doc = concat!(" Offset ", $qo, ". Reserved.")]
            pub $q: [u8; 4],
            #[doc = concat!(" Offset ", $po, ". Private state, ", $bytes, " bytes: never write it.")]
            pub stPrivate: $private,
        }
    };
    // A block whose own fields end at its private state (the PLCopen SF_ blocks:
    // `private 24: SL_SF_PRIVATE, 40`, the offset, type and size of the private state);
    // `zeroed()` and `Default` from [`Zeroed`].
    ($(#[doc = $doc:literal])* $name:ident {
        $($(#[doc = $fd:expr])* pub $f:ident: $ft:ty,)*
    } private $po:literal: $private:ty, $bytes:literal) => {
        $crate::base::layout::zeroed_struct! {
            $(#[doc = $doc])*
            $name {
                $($(#[doc = $fd])* pub $f: $ft,)*
                #[doc = concat!(" Offset ", $po, ". Private state, ", $bytes, " bytes: never write it.")]
                pub stPrivate: $private,
            }
        }

        impl $name {
            /// An all-zero instance (valid: it initialises itself on the first call).
            pub const fn zeroed() -> Self {
                <Self as $crate::base::layout::Zeroed>::ZERO
            }
        }
    };
    // ABI-2 §10.4: the info data of the blocks with a diag message (analog, motion) —
    // nState, nDiag, the message's Text ID and parameters 2 and 3, the private state — at
    // offsets relative to the info base ("Info + N"), the same for every width. After the
    // reserved fields' names, the private type and size come the docs of nState, nDiag,
    // nDiagTextId, dwDiagPar2 and dwDiagPar3. Non-generic.
    ($(#[doc = $doc:literal])* $name:ident { $($body:tt)* } info $($info:tt)*) => {
        $crate::base::layout::block_struct!(@info
            [$(#[doc = $doc])* #[derive(Default)]] $name [] { $($body)* } $($info)* {});
    };
    // ABI-2 §10.2: the head of an analog block without BOOL inputs (16 reserved bytes,
    // bRun, bErrAck, 6 reserved bytes up to the analog input base 24), written as
    // `no_bool_inputs;` at the start of the fields.
    ($(#[doc = $doc:literal])* $name:ident [$($gen:tt)*] { no_bool_inputs; $($rest:tt)* }
     $($tail:tt)*) => {
        $crate::base::layout::block_struct! {
            $(#[doc = $doc])*
            $name [$($gen)*] {
                /// Offset 0. Reserved, keep 0 (no BOOL inputs).
                pub aReserved0: [u8; 16],
                /// Offset 16. FbRun of the owning group: TRUE = the block executes.
                pub bRun: $crate::base::types::SL_BOOL,
                /// Offset 17. ErrAck of the owning group.
                pub bErrAck: $crate::base::types::SL_BOOL,
                /// Offset 18. Reserved, keep 0.
                pub aReserved1: [u8; 6],
                $($rest)*
            } $($tail)*
        }
    };
    // Generic over the signal type(s) `$t` with reserved gaps of lengths `$c`
    // (`FB_SPEED[T: Analog; P1, P2]`, each bound implying [`Zeroed`] where a field has the
    // type): no `Default` derive, `zeroed()` and `Default` from [`Zeroed`] instead. After
    // the docs, `; pub _op: PhantomData<O>` is a zero-sized field after the private state
    // (FB_ARITH's operation: where it always was, for the debug info abidiff reads).
    ($(#[doc = $doc:literal])* $name:ident [$($t:ident: $bound:path),*; $($c:ident),*] {
        $($(#[doc = $fd:literal])* pub $f:ident: $ft:ty,)*
    } info [$r:ident, $q:ident] $private:ty, $bytes:literal:
        $s:literal, $d:literal, $x:literal, $p:literal, $o:literal
        $(; $(#[doc = $zd:literal])* pub $z:ident: $zt:ty)?) => {
        $crate::base::layout::block_struct!(@info [$(#[doc = $doc])*]
            $name [$($t,)* $(const $c: usize),*] { $($(#[doc = $fd])* pub $f: $ft,)* }
            [$r, $q] $private, $bytes: $s, $d, $x, $p, $o { $($(#[doc = $zd])* pub $z: $zt,)? });

        impl<$($t: $bound,)* $(const $c: usize),*> $name<$($t,)* $($c),*> {
            /// An all-zero instance (valid: it initialises itself on the first cycle,
            /// ABI §3.6).
            pub const fn zeroed() -> Self {
                use $crate::base::layout::Zeroed;
                Self {
                    $($f: <$ft as Zeroed>::ZERO,)*
                    nState: 0,
                    $r: [0; 1],
                    nDiag: 0,
                    nDiagTextId: 0,
                    $q: [0; 2],
                    dwDiagPar2: 0,
                    dwDiagPar3: 0,
                    stPrivate: <$private as Zeroed>::ZERO,
                    $($z: <$zt as Zeroed>::ZERO,)?
                }
            }
        }

        impl<$($t: $bound,)* $(const $c: usize),*> Default for $name<$($t,)* $($c),*> {
            fn default() -> Self {
                Self::zeroed()
            }
        }
    };
    (@info [$($attr:tt)*] $name:ident [$($gen:tt)*] { $($body:tt)* }
     [$r:ident, $q:ident] $private:ty, $bytes:literal:
     $s:literal, $d:literal, $x:literal, $p:literal, $o:literal { $($after:tt)* }) => {
        $($attr)*
        #[repr(C)]
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        #[allow(non_snake_case, non_camel_case_types)]
        pub struct $name<$($gen)*> {
            $($body)*
            #[doc = concat!(" Info + 0: ", $s)]
            pub nState: u8,
            /// Info + 1. Reserved.
            pub $r: [u8; 1],
            #[doc = concat!(" Info + 2: ", $d)]
            pub nDiag: u16,
            #[doc = concat!(" Info + 4: ", $x)]
            pub nDiagTextId: u16,
            /// Info + 6. Reserved.
            pub $q: [u8; 2],
            #[doc = concat!(" Info + 8: ", $p)]
            pub dwDiagPar2: u32,
            #[doc = concat!(" Info + 12: ", $o)]
            pub dwDiagPar3: u32,
            #[doc = concat!(" Info + 16: private state, ", $bytes, ": never write it.")]
            pub stPrivate: $private,
            $($after)*
        }
    };
}
pub(crate) use block_struct;

/// Declares a block's private state (ABI §3.5): `#[repr(C)]`, the derives and the common
/// head [`SL_PRIVATE_HEADER`](crate::base::header::SL_PRIVATE_HEADER), then the block's
/// own fields. Never written by the user. The head's doc is "Common head." unless the
/// struct gives its own (doc comments, then `stHeader;`: what the block keeps in it).
macro_rules! private_struct {
    ($(#[doc = $doc:literal])* $name:ident {
        $(#[doc = $head:literal])+ stHeader;
        $($(#[doc = $fd:literal])* pub $f:ident: $ft:ty,)*
    }) => {
        $(#[doc = $doc])*
        #[repr(C)]
        #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
        #[allow(non_snake_case, non_camel_case_types)]
        pub struct $name {
            $(#[doc = $head])+
            pub stHeader: $crate::base::header::SL_PRIVATE_HEADER,
            $($(#[doc = $fd])* pub $f: $ft,)*
        }

        impl $crate::base::layout::Zeroed for $name {
            const ZERO: Self = Self {
                stHeader: $crate::base::header::SL_PRIVATE_HEADER::ZERO,
                $($f: <$ft as $crate::base::layout::Zeroed>::ZERO,)*
            };
        }
    };
    ($(#[doc = $doc:literal])* $name:ident { $($body:tt)* }) => {
        $crate::base::layout::private_struct! {
            $(#[doc = $doc])*
            $name {
                /// Common head.
                stHeader;
                $($body)*
            }
        }
    };
}
pub(crate) use private_struct;

/// Declares a C struct whose all-zero value is its `Default` (arrays longer than 32 bytes
/// have no derived one): `#[repr(C)]`, the derives, the fields, [`Zeroed`] and `Default`.
macro_rules! zeroed_struct {
    ($(#[doc = $doc:literal])* $name:ident {
        $($(#[doc = $fd:expr])* pub $f:ident: $ft:ty,)*
    }) => {
        $(#[doc = $doc])*
        #[repr(C)]
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        #[allow(non_snake_case, non_camel_case_types)]
        pub struct $name {
            $($(#[doc = $fd])* pub $f: $ft,)*
        }

        impl $crate::base::layout::Zeroed for $name {
            const ZERO: Self = Self {
                $($f: <$ft as $crate::base::layout::Zeroed>::ZERO,)*
            };
        }

        impl Default for $name {
            fn default() -> Self {
                <Self as $crate::base::layout::Zeroed>::ZERO
            }
        }
    };
}
pub(crate) use zeroed_struct;
