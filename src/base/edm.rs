//! External device monitoring (ABI §7 "EDM with manual restart", "EDM reset time";
//! manual §4.4.1, §4.4.5, §4.5.1, §4.5.5). EDMx feeds back the contact state of the
//! contactor driven by output x: TRUE while it is released (outputs off).

use super::time;
use crate::base::types::{SL_DIAG_EDM1, SL_DIAG_EDM2};

/// EDM inputs of one cycle and their configuration.
#[derive(Clone, Copy, Debug, Default)]
pub struct Edm {
    /// Feedback loop x is active (option EDM1 / EDM2).
    pub active: [bool; 2],
    /// The input byte is exactly TRUE.
    pub is_true: [bool; 2],
    /// The input byte is exactly FALSE.
    pub is_false: [bool; 2],
}

const DIAG: [u16; 2] = [SL_DIAG_EDM1, SL_DIAG_EDM2];

impl Edm {
    /// Every active feedback reads TRUE: the contactors have released.
    #[inline]
    pub fn all_released(&self) -> bool {
        (!self.active[0] || self.is_true[0]) && (!self.active[1] || self.is_true[1])
    }

    /// Diag bits of the active feedback loops that do not read TRUE (restart check,
    /// and the condition that keeps an EDM error from being acknowledged).
    #[inline]
    pub fn not_released(&self) -> u16 {
        (0..2)
            .filter(|&x| self.active[x] && !self.is_true[x])
            .fold(0, |d, x| d | DIAG[x])
    }

    /// Diag bits of the active feedback loops that do not read FALSE: the contactors have
    /// not (all) picked up (SF_EDM's check after switching on).
    #[inline]
    pub fn not_switched(&self) -> u16 {
        (0..2)
            .filter(|&x| self.active[x] && !self.is_false[x])
            .fold(0, |d, x| d | DIAG[x])
    }

    /// EDM reset-time check while the outputs are on. `pending` bit x (1 << x) stays set
    /// until EDMx reads FALSE; when `reset_time[x]` ms have passed since `t_on` with the
    /// bit still set, the EDMx diag bit is returned.
    #[inline]
    pub fn reset_time_check(
        &self,
        pending: &mut u8,
        t_on: u32,
        reset_time: [u32; 2],
        now: u32,
    ) -> u16 {
        if *pending == 0 {
            return 0;
        }
        let mut d = 0;
        for (x, diag) in DIAG.iter().enumerate() {
            let bit = 1u8 << x;
            if *pending & bit == 0 {
                continue;
            }
            if self.is_false[x] {
                *pending &= !bit;
            } else if time::reached(now, t_on, reset_time[x]) {
                d |= diag;
            }
        }
        d
    }

    /// The pending bits to arm when the outputs switch on.
    #[inline]
    pub fn arm(&self, reset_time: [u32; 2]) -> u8 {
        u8::from(self.active[0] && reset_time[0] != 0)
            | (u8::from(self.active[1] && reset_time[1] != 0) << 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn edm(active: [bool; 2], raw: [u8; 2]) -> Edm {
        Edm {
            active,
            is_true: raw.map(|b| b == 1),
            is_false: raw.map(|b| b == 0),
        }
    }

    #[test]
    fn released_and_switched_name_the_loops_that_are_not() {
        let both = [true, true];
        assert_eq!(edm(both, [1, 1]).not_released(), 0);
        assert_eq!(edm(both, [0, 1]).not_released(), SL_DIAG_EDM1);
        assert_eq!(edm(both, [1, 2]).not_released(), SL_DIAG_EDM2);
        assert_eq!(edm(both, [0, 0]).not_switched(), 0);
        assert_eq!(edm(both, [1, 0]).not_switched(), SL_DIAG_EDM1);
        assert_eq!(
            edm(both, [0, 7]).not_switched(),
            SL_DIAG_EDM2,
            "invalid: not switched"
        );
        assert_eq!(
            edm(both, [1, 1]).not_switched(),
            SL_DIAG_EDM1 | SL_DIAG_EDM2
        );
        assert_eq!(
            edm([false, true], [1, 0]).not_switched(),
            0,
            "inactive loop"
        );
        assert_eq!(edm([true, false], [1, 1]).not_switched(), SL_DIAG_EDM1);
    }
}
