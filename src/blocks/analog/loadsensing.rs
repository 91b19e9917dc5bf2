//! FB LOADSENSING — manual §4.25; layout ABI-2 §11.8, rules ABI-2 §12.
//!
//! A characteristic-curve check: row i is the largest of rows 1…`nRowCount` whose X is
//! strictly smaller than AnalogInX; AnalogInY is checked against that row's switch-off level
//! [Y1, Y2] and warning level [WY1, WY2] (or outside them with `SL_OPT_LOADSENSING_OUTSIDE`).
//! RUN (Valid) inside the warning level, WARNING (Valid and Warning) between the levels, SAFE
//! otherwise and when no row lies below AnalogInX; Inactive TRUE → INACTIVE. The table is a
//! parameter: its ordering is checked at latch time (`SL_E_CONFIG`, ABI-2 §12.8). States RUN
//! (1), STOP (2), SAFE (3), INACTIVE (16), WARNING (17); ERROR (4) and RESET (5) only for the
//! library's own faults (no Error output, no diag values). Readings: docs/semantics.md
//! LS1–LS6. One implementation for the four integer types.

#![allow(non_camel_case_types)] // the ABI's names (FB_LOADSENSING_INT …)

use super::{magic, Analog};
use crate::base::block::{Private, Registered};
use crate::base::envelope::Block;
use crate::base::header::{param_crc, put_crc_words, SL_PRIVATE_HEADER};
use crate::base::reason::rule;
use crate::base::reason::{when, Hit, Rule, RuleDef, Unit};
use crate::base::types::*;

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/analog/loadsensing.rs"
));

/// The table's length in the structs (written out there: the header's array bound must be a
/// number for its layout checks).
const ROWS: usize = SL_LOADSENSING_ROWS_MAX as usize;
const _: () = assert!(ROWS == 25);

/// One row of the value table (ABI-2 §10.6): the manual's index, X, Y1, Y2, WY1, WY2, all of
/// the variant's type (10 or 20 bytes, no padding).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_snake_case)]
pub struct SL_LOADSENSING_ROW<T> {
    /// X: the row applies while its X is the largest below AnalogInX.
    pub nX: T,
    /// Y1: lower switch-off level.
    pub nY1: T,
    /// Y2: upper switch-off level.
    pub nY2: T,
    /// WY1: lower warning level.
    pub nWY1: T,
    /// WY2: upper warning level.
    pub nWY2: T,
}

/// A value-table row of FB_LOADSENSING_INT.
pub type SL_LOADSENSING_ROW_INT = SL_LOADSENSING_ROW<i16>;
/// A value-table row of FB_LOADSENSING_UINT.
pub type SL_LOADSENSING_ROW_UINT = SL_LOADSENSING_ROW<u16>;
/// A value-table row of FB_LOADSENSING_DINT.
pub type SL_LOADSENSING_ROW_DINT = SL_LOADSENSING_ROW<i32>;
/// A value-table row of FB_LOADSENSING_UDINT.
pub type SL_LOADSENSING_ROW_UDINT = SL_LOADSENSING_ROW<u32>;

/// Private state of FB LOADSENSING (16-bit: 288 bytes, 32-bit: 536). Never written by the
/// user. It holds the latched copy of the whole value table: the cycle evaluates the copy,
/// and the per-call change check compares the live table with it exactly (semantics LS6).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(non_snake_case)]
pub struct SL_LOADSENSING_PRIVATE<T, const PR: usize> {
    /// Common head.
    pub stHeader: SL_PRIVATE_HEADER,
    /// Latched `dwOptions`.
    pub dwOptions: u32,
    /// Latched `nRowCount`.
    pub nRowCount: u16,
    /// Latched `wInputActive`.
    pub wActive: u16,
    /// Latched value table, all 25 rows.
    pub aRow: [SL_LOADSENSING_ROW<T>; 25],
    /// Reserved up to a multiple of 8 (16-bit: 2 bytes, 32-bit: none).
    pub aReserved: [u8; PR],
}

/// Private state of FB_LOADSENSING_INT.
pub type SL_LOADSENSING_PRIVATE_INT = SL_LOADSENSING_PRIVATE<i16, 2>;
/// Private state of FB_LOADSENSING_UINT.
pub type SL_LOADSENSING_PRIVATE_UINT = SL_LOADSENSING_PRIVATE<u16, 2>;
/// Private state of FB_LOADSENSING_DINT.
pub type SL_LOADSENSING_PRIVATE_DINT = SL_LOADSENSING_PRIVATE<i32, 0>;
/// Private state of FB_LOADSENSING_UDINT.
pub type SL_LOADSENSING_PRIVATE_UDINT = SL_LOADSENSING_PRIVATE<u32, 0>;

impl<T: Analog, const PR: usize> Default for SL_LOADSENSING_PRIVATE<T, PR> {
    fn default() -> Self {
        Self {
            stHeader: SL_PRIVATE_HEADER::ZERO,
            dwOptions: 0,
            nRowCount: 0,
            wActive: 0,
            aRow: [SL_LOADSENSING_ROW::default(); ROWS],
            aReserved: [0; PR],
        }
    }
}

/// FB LOADSENSING instance (ABI-2 §11.8), generic over the signal type `T`; `P1` is the
/// reserved gap before the output base and `PR` the private state's tail, the two places
/// where the 16- and 32-bit layouts differ beyond the width.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(non_snake_case)]
pub struct FB_LOADSENSING<T, const P1: usize, const PR: usize> {
    /// Offset 0. Reserved, keep 0.
    pub aReserved0: [u8; 6],
    /// Offset 6. Inactive: TRUE = INACTIVE (active bit 0; clear: reads FALSE).
    pub bInactive: SL_BOOL,
    /// Offset 7. Reserved, keep 0.
    pub aReserved1: [u8; 9],
    /// Offset 16. FbRun of the owning group: TRUE = the block executes.
    pub bRun: SL_BOOL,
    /// Offset 17. ErrAck of the owning group.
    pub bErrAck: SL_BOOL,
    /// Offset 18. Reserved, keep 0.
    pub aReserved2: [u8; 6],
    /// At the analog input base 24: AnalogInX, selects the row (active bit 8, required).
    pub nAnalogInX: T,
    /// At 24 + W: AnalogInY, the value checked (active bit 9, required).
    pub nAnalogInY: T,
    /// At 24 + 2W: SL_OPT_LOADSENSING_OUTSIDE ("Outside [y1; y2]"); no other bit.
    pub dwOptions: u32,
    /// At 28 + 2W: the value table; row i is the manual's index i + 1.
    pub aRow: [SL_LOADSENSING_ROW<T>; 25],
    /// At 28 + 127W: rows used, 1…25.
    pub nRowCount: u16,
    /// At 30 + 127W: bits 8 and 9 must be set, bit 0 activates Inactive.
    pub wInputActive: u16,
    /// Reserved up to the output base (16-bit: 2 bytes, 32-bit: 4).
    pub aReserved3: [u8; P1],
    /// Output base + 0. Reserved (the block has no Error output).
    pub aReserved4: [u8; 1],
    /// Output base + 1: Valid, TRUE in RUN and WARNING.
    pub bValid: SL_BOOL,
    /// Output base + 2: Warning, TRUE in WARNING.
    pub bWarning: SL_BOOL,
    /// Reserved up to the info data.
    pub aReserved5: [u8; 5],
    /// Info + 0: the manual's status value (RUN, STOP, SAFE, INACTIVE, WARNING; ERROR,
    /// RESET).
    pub nState: u8,
    /// Info + 1. Reserved.
    pub aReserved6: [u8; 1],
    /// Info + 2: 0 (no diag values) + library bits 13-15.
    pub nDiag: u16,
    /// Info + 4: always 0 (the block has no diag message).
    pub nDiagTextId: u16,
    /// Info + 6. Reserved.
    pub aReserved7: [u8; 2],
    /// Info + 8: always 0.
    pub dwDiagPar2: u32,
    /// Info + 12: always 0.
    pub dwDiagPar3: u32,
    /// Info + 16: private state (16-bit: 288 bytes, 32-bit: 536): never write it.
    pub stPrivate: SL_LOADSENSING_PRIVATE<T, PR>,
}

// The ABI-2 §11.8 numbers of the two layouts (value table, output base, private state).
const _: () = {
    use core::mem::{offset_of, size_of};
    assert!(
        offset_of!(FB_LOADSENSING_INT, aRow) == 32 && offset_of!(FB_LOADSENSING_DINT, aRow) == 36
    );
    assert!(
        size_of::<SL_LOADSENSING_ROW<i16>>() == 10 && size_of::<SL_LOADSENSING_ROW<u32>>() == 20
    );
    assert!(offset_of!(FB_LOADSENSING_UINT, nRowCount) == 282);
    assert!(offset_of!(FB_LOADSENSING_UDINT, nRowCount) == 536);
    assert!(
        offset_of!(FB_LOADSENSING_INT, bValid) == 289
            && offset_of!(FB_LOADSENSING_UDINT, bValid) == 545
    );
    assert!(
        offset_of!(FB_LOADSENSING_INT, stPrivate) == 312
            && offset_of!(FB_LOADSENSING_DINT, stPrivate) == 568
    );
    assert!(size_of::<FB_LOADSENSING_UINT>() == 600 && size_of::<FB_LOADSENSING_UDINT>() == 1104);
};

crate::impl_member!([T: Analog, const P1: usize, const PR: usize] FB_LOADSENSING<T, P1, PR> {
    info: crate::blocks::analog::variant_info!(T, "LOADSENSING", LoadSensingState, &[(0, "No diagnostic information")];
        INT = SL_TYPE_LOADSENSING_INT, UINT = SL_TYPE_LOADSENSING_UINT, DINT = SL_TYPE_LOADSENSING_DINT, UDINT = SL_TYPE_LOADSENSING_UDINT),
    state: LoadSensingState,
    private: SL_LOADSENSING_PRIVATE<T, PR>,
    table_params: [aRow],
    input: [bInactive, nAnalogInX, nAnalogInY],
    param: [dwOptions, nRowCount, wInputActive],
    output: [bValid, bWarning],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

impl<T: Analog, const P1: usize, const PR: usize> FB_LOADSENSING<T, P1, PR> {
    /// An all-zero instance (valid: it initialises itself on the first cycle, ABI §3.6).
    pub fn zeroed() -> Self {
        Self {
            aReserved0: [0; 6],
            bInactive: 0,
            aReserved1: [0; 9],
            bRun: 0,
            bErrAck: 0,
            aReserved2: [0; 6],
            nAnalogInX: T::ZERO,
            nAnalogInY: T::ZERO,
            dwOptions: 0,
            aRow: [SL_LOADSENSING_ROW::default(); ROWS],
            nRowCount: 0,
            wInputActive: 0,
            aReserved3: [0; P1],
            aReserved4: [0; 1],
            bValid: 0,
            bWarning: 0,
            aReserved5: [0; 5],
            nState: 0,
            aReserved6: [0; 1],
            nDiag: 0,
            nDiagTextId: 0,
            aReserved7: [0; 2],
            dwDiagPar2: 0,
            dwDiagPar3: 0,
            stPrivate: SL_LOADSENSING_PRIVATE::default(),
        }
    }
}

impl<T: Analog, const P1: usize, const PR: usize> Default for FB_LOADSENSING<T, P1, PR> {
    fn default() -> Self {
        Self::zeroed()
    }
}

/// Parameters as the user wrote them: the scalars and the whole table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LoadSensingParams<T> {
    active: u16,
    options: u32,
    count: u16,
    rows: [SL_LOADSENSING_ROW<T>; ROWS],
}

/// One cycle's inputs: Inactive after decoding, AnalogInX and AnalogInY.
#[derive(Clone, Copy, Debug)]
pub struct LoadSensingIn<T> {
    inactive: bool,
    x: T,
    y: T,
}

/// The exact values of a row.
fn wide_row<T: Analog>(r: &SL_LOADSENSING_ROW<T>) -> [i128; 5] {
    [r.nX, r.nY1, r.nY2, r.nWY1, r.nWY2].map(Analog::wide)
}

/// AnalogInX and AnalogInY: the inputs every configuration has active.
const REQUIRED: u16 = SL_LOADSENSING_ACTIVE_ANALOGINX | SL_LOADSENSING_ACTIVE_ANALOGINY;

/// The rows the block uses (1…`nRowCount`, at least one).
fn used_rows<T: Analog>(p: &LoadSensingParams<T>) -> &[SL_LOADSENSING_ROW<T>] {
    &p.rows[..usize::from(p.count.clamp(1, SL_LOADSENSING_ROWS_MAX))]
}

/// The first used row (1-based) whose values `[X, Y1, Y2, WY1, WY2]` break a comparison of
/// the manual's formula for the Outside setting `outside` (`bad` gives the two values
/// compared), if the table is configured with that setting.
fn first_row<T: Analog>(
    p: &LoadSensingParams<T>,
    outside: bool,
    bad: impl Fn([i64; 5]) -> Option<(i64, i64)>,
) -> Option<Hit> {
    if (p.options & SL_OPT_LOADSENSING_OUTSIDE != 0) != outside {
        return None;
    }
    used_rows(p).iter().enumerate().find_map(|(i, r)| {
        let (a, b) = bad(wide_row(r).map(|v| v as i64))?;
        when(true, a, b).map(|h| h.in_row(i as u8 + 1))
    })
}

/// The state AnalogInX and AnalogInY give with the table `rows` (semantics LS3, LS4): the
/// row is the last whose X is strictly below AnalogInX (X strictly increasing, so the search
/// stops at the first X that is not); none → SAFE.
fn evaluate<T: Analog>(rows: &[SL_LOADSENSING_ROW<T>], outside: bool, x: T, y: T) -> u8 {
    let (x, y) = (x.wide(), y.wide());
    let mut row = None;
    for r in rows {
        if r.nX.wide() >= x {
            break;
        }
        row = Some(r);
    }
    let Some(r) = row else {
        return SL_STATE_SAFE;
    };
    let [_, y1, y2, wy1, wy2] = wide_row(r);
    let (valid, warning) = if outside {
        let valid = y <= y1 || y >= y2;
        (valid, valid && wy1 <= y && y <= wy2)
    } else {
        let valid = y1 <= y && y <= y2;
        (valid, valid && (y < wy1 || y > wy2))
    };
    match (valid, warning) {
        (true, false) => SL_STATE_RUN,
        (true, true) => SL_STATE_LOADSENSING_WARNING,
        (false, _) => SL_STATE_SAFE,
    }
}

/// Valid is on in these states.
const fn valid(state: u8) -> bool {
    state == SL_STATE_RUN || state == SL_STATE_LOADSENSING_WARNING
}

impl<T: Analog, const P1: usize, const PR: usize> Block for FB_LOADSENSING<T, P1, PR> {
    const MAGIC: u16 = magic(<Self as Registered>::INFO.tag);
    type Params = LoadSensingParams<T>;
    type In = LoadSensingIn<T>;

    #[inline(always)]
    fn live_params(&self) -> LoadSensingParams<T> {
        LoadSensingParams {
            active: self.wInputActive,
            options: self.dwOptions,
            count: self.nRowCount,
            rows: self.aRow,
        }
    }
    #[inline(always)]
    fn latched_params(&self) -> LoadSensingParams<T> {
        let p = self.private();
        LoadSensingParams {
            active: p.wActive,
            options: p.dwOptions,
            count: p.nRowCount,
            rows: p.aRow,
        }
    }
    /// AnalogInX and AnalogInY active, Inactive optional, no other bit (ABI-2 §10.5); only
    /// the Outside option; 1…25 rows; in the rows used, X strictly increasing and each row
    /// ordered as the manual's formula for its Outside setting (ABI-2 §11.8, semantics LS5).
    const RULES: &'static [RuleDef<LoadSensingParams<T>>] = &[
        rule!(no_bits_outside "wInputActive", |p| p.active, REQUIRED | SL_LOADSENSING_ACTIVE_INACTIVE),
        RuleDef::new("wInputActive", Rule::BitsSet, Unit::Hex, |p| {
            when(p.active & REQUIRED != REQUIRED, p.active, REQUIRED)
        }),
        rule!(no_bits_outside "dwOptions", |p| p.options, SL_OPT_LOADSENSING_OUTSIDE),
        RuleDef::new("nRowCount", Rule::AtLeast, Unit::Plain, |p| {
            when(p.count == 0, 0, 1)
        }),
        rule!(at_most "nRowCount" in Plain, |p| p.count, SL_LOADSENSING_ROWS_MAX),
        // The manual's formula, one comparison at a time: "Outside = FALSE: Y1 ≤ WY1 < WY2 ≤ Y2".
        RuleDef::new("nY1", Rule::NotAbove("nWY1"), Unit::Plain, |p| {
            first_row(p, false, |[_, y1, _, wy1, _]| {
                (y1 > wy1).then_some((y1, wy1))
            })
        }),
        RuleDef::new("nWY1", Rule::Below("nWY2"), Unit::Plain, |p| {
            first_row(p, false, |[_, _, _, wy1, wy2]| {
                (wy1 >= wy2).then_some((wy1, wy2))
            })
        }),
        RuleDef::new("nWY2", Rule::NotAbove("nY2"), Unit::Plain, |p| {
            first_row(p, false, |[_, _, y2, _, wy2]| {
                (wy2 > y2).then_some((wy2, y2))
            })
        }),
        // "Outside = TRUE: WY1 ≤ Y1 < Y2 ≤ WY2".
        RuleDef::new("nWY1", Rule::NotAbove("nY1"), Unit::Plain, |p| {
            first_row(p, true, |[_, y1, _, wy1, _]| {
                (wy1 > y1).then_some((wy1, y1))
            })
        }),
        RuleDef::new("nY1", Rule::Below("nY2"), Unit::Plain, |p| {
            first_row(p, true, |[_, y1, y2, _, _]| (y1 >= y2).then_some((y1, y2)))
        }),
        RuleDef::new("nY2", Rule::NotAbove("nWY2"), Unit::Plain, |p| {
            first_row(p, true, |[_, _, y2, _, wy2]| {
                (y2 > wy2).then_some((y2, wy2))
            })
        }),
        // X strictly increasing (the row search, semantics LS3).
        RuleDef::new(
            "nX",
            Rule::Above("nX of the row before"),
            Unit::Plain,
            |p| {
                let used = used_rows(p);
                used.windows(2).enumerate().find_map(|(i, w)| {
                    let (before, x) = (w[0].nX.wide() as i64, w[1].nX.wide() as i64);
                    when(x <= before, x, before).map(|h| h.in_row(i as u8 + 2))
                })
            },
        ),
    ];
    fn store_params(&mut self, p: &LoadSensingParams<T>) {
        let q = self.private_mut();
        q.wActive = p.active;
        q.dwOptions = p.options;
        q.nRowCount = p.count;
        q.aRow = p.rows;
    }
    /// CRC-16 over the scalars and every value of all 25 latched rows (as 32-bit patterns).
    fn latched_crc(&self) -> u16 {
        let p = self.private();
        let mut words = [0u16; 3 + 10 * ROWS];
        words[0] = p.wActive;
        words[1] = p.nRowCount;
        words[2] = (p.dwOptions >> 16) as u16;
        let values = p
            .aRow
            .iter()
            .flat_map(|r| [r.nX, r.nY1, r.nY2, r.nWY1, r.nWY2]);
        put_crc_words(&mut words[3..], values.map(|v| v.to_bits()));
        param_crc(Self::MAGIC, 0, 0, p.dwOptions as u16, &words)
    }
    /// An active Inactive byte that is not 0 or 1 reads TRUE (INACTIVE, Valid 0: ABI-2
    /// §12.7); an inactive port reads FALSE and its byte is not read (semantics C7).
    #[inline(always)]
    fn decode(&mut self) -> (LoadSensingIn<T>, bool) {
        let used = self.private().wActive & SL_LOADSENSING_ACTIVE_INACTIVE != 0;
        let raw = self.bInactive;
        (
            LoadSensingIn {
                inactive: used && raw != 0,
                x: self.nAnalogInX,
                y: self.nAnalogInY,
            },
            used && raw > 1,
        )
    }
    fn start(&mut self, inp: &LoadSensingIn<T>, now: u32) {
        self.step(inp, now);
    }
    #[inline(always)]
    fn step(&mut self, inp: &LoadSensingIn<T>, _now: u32) -> Status {
        let p = self.private();
        let next = if inp.inactive {
            SL_STATE_LOADSENSING_INACTIVE
        } else {
            let count = usize::from(p.nRowCount).min(ROWS);
            let outside = p.dwOptions & SL_OPT_LOADSENSING_OUTSIDE != 0;
            evaluate(&p.aRow[..count], outside, inp.x, inp.y)
        };
        // Valid switching on is where the latched parameters are verified (C3).
        if self.corrupt_at_switch_on(valid(next) && !valid(p.stHeader.nState)) {
            return Status::Corrupt;
        }
        self.private_mut().stHeader.nState = next;
        Status::Ok
    }
    // Only the library's faults lead to ERROR; none of them remains: `error_remains` keeps
    // its default (false).
    #[inline(always)]
    fn write_outputs(&mut self) {
        let h = self.private().stHeader;
        self.bValid = u8::from(valid(h.nState));
        self.bWarning = u8::from(h.nState == SL_STATE_LOADSENSING_WARNING);
        self.nState = h.nState;
        self.nDiag = h.wDiag;
        (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) = (0, 0, 0);
    }
}
