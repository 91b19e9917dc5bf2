//! Shared pieces of the PLCopen `SF_` block tests: the (v2.01, v1.0) code pairs of the
//! research tables and the two diagnostic profiles.

use safelogic::*;

/// A state's DiagCode in the (v2.01, v1.0) profiles.
pub type Code = (u16, u16);

/// Both diagnostic profiles, v2.01 first.
pub fn profiles() -> [u8; 2] {
    [SL_SF_PROFILE_V201, SL_SF_PROFILE_V10]
}

/// The code of `s` in `profile`.
pub fn code(profile: u8, s: Code) -> u16 {
    if profile == SL_SF_PROFILE_V10 {
        s.1
    } else {
        s.0
    }
}

/// `const NAME: Code = (v2.01, v1.0);` for every entry and `ALL`, every one in order.
/// Several entries share a line: it is a table.
#[allow(unused_macros)]
macro_rules! codes {
    ($($name:ident = $v2:literal / $v1:literal),* $(,)?) => {
        $(const $name: Code = ($v2, $v1);)*
        const ALL: [Code; [$($v2),*].len()] = [$($name),*];
    };
}
#[allow(unused_imports)]
pub(crate) use codes;
