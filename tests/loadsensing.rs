//! FB LOADSENSING (manual §4.25, ABI-2 §11.8, §12; docs/semantics.md LS1–LS6) in all four
//! integer variants: one test per statement of the manual section, then random sequences
//! against a small model of the block (≥ 10,000 per variant) that assert what they reached.

mod common;

use common::{Rng, FIG_132};
use safelogic::blocks::analog::Analog;
use safelogic::*;

const XY: u16 = SL_LOADSENSING_ACTIVE_ANALOGINX | SL_LOADSENSING_ACTIVE_ANALOGINY;
const ALL: u16 = XY | SL_LOADSENSING_ACTIVE_INACTIVE;
const OUTSIDE: u32 = SL_OPT_LOADSENSING_OUTSIDE;

/// The manual's example table (Fig. 132: index, X, Y1, Y2, WY1, WY2), shifted by +1000 so
/// that every variant holds it. Row 1 as printed (Y2 −100, WY2 −80) breaks the manual's own
/// formula (WY2 ≤ Y2; the block refuses it, see `the_manuals_row_1_as_printed_is_refused`):
/// WY2 is taken as −120, the pattern of the other rows (Y2 − 10 … here −20).
const MANUAL: [[i128; 5]; 25] = {
    let mut out = [[0i128; 5]; 25];
    let mut i = 0;
    while i < 25 {
        let mut k = 0;
        while k < 5 {
            out[i][k] = FIG_132[i][k] as i128 + 1000;
            k += 1;
        }
        i += 1;
    }
    out[0][4] = -120 + 1000;
    out
};

common::analog_outputs!(valid: u8, warning: u8);

/// The four variants under one roof: values given as `i128`, stored as the variant's type.
macro_rules! variant {
    ($name:ident, $ty:ty, $t:ty) => {
        crate::common::analog_wrapper!($name, $ty, $t);
        impl $name {
            fn new(active: u16, options: u32, rows: &[[i128; 5]]) -> Self {
                let mut fb = <$ty>::default();
                fb.wInputActive = active;
                fb.dwOptions = options;
                fb.nRowCount = rows.len() as u16;
                for (r, v) in fb.aRow.iter_mut().zip(rows) {
                    r.nX = Self::t(v[0]);
                    r.nY1 = Self::t(v[1]);
                    r.nY2 = Self::t(v[2]);
                    r.nWY1 = Self::t(v[3]);
                    r.nWY2 = Self::t(v[4]);
                }
                Self(fb)
            }
            fn set_inputs(&mut self, inactive: u8, x: i128, y: i128) {
                self.0.bInactive = inactive;
                self.0.nAnalogInX = Self::t(x);
                self.0.nAnalogInY = Self::t(y);
            }
            fn outputs(&self) -> Outputs {
                let f = &self.0;
                crate::common::read_outputs!(f {
                    valid: f.bValid,
                    warning: f.bWarning,
                })
            }
        }
    };
}

variant!(LsInt, FB_LOADSENSING_INT, i16);
variant!(LsUint, FB_LOADSENSING_UINT, u16);
variant!(LsDint, FB_LOADSENSING_DINT, i32);
variant!(LsUdint, FB_LOADSENSING_UDINT, u32);

/// The model's state for a table, options and inputs: written from the manual's words, the
/// row found by a full scan (the largest index whose X is smaller than AnalogInX).
fn model_state(rows: &[[i128; 5]], outside: bool, inactive: bool, x: i128, y: i128) -> u8 {
    if inactive {
        return SL_STATE_LOADSENSING_INACTIVE;
    }
    let Some(i) = (0..rows.len()).filter(|&i| rows[i][0] < x).max() else {
        return SL_STATE_SAFE;
    };
    let [_, y1, y2, wy1, wy2] = rows[i];
    let (area_valid, warning) = if outside {
        let v = y <= y1 || y >= y2;
        (v, v && (wy1..=wy2).contains(&y))
    } else {
        let v = (y1..=y2).contains(&y);
        (v, v && !(wy1..=wy2).contains(&y))
    };
    match (area_valid, warning) {
        (false, _) => SL_STATE_SAFE,
        (true, false) => SL_STATE_RUN,
        (true, true) => SL_STATE_LOADSENSING_WARNING,
    }
}

/// The outputs of a state (manual §4.25.2 status table).
fn outputs_of(state: u8) -> Outputs {
    let (valid, warning) = match state {
        SL_STATE_RUN => (1, 0),
        SL_STATE_LOADSENSING_WARNING => (1, 1),
        _ => (0, 0),
    };
    Outputs {
        valid,
        warning,
        state,
        diag: 0,
        text: 0,
        par: (0, 0),
    }
}

macro_rules! loadsensing_tests {
    ($modname:ident, $v:ident, $t:ty) => {
        mod $modname {
            use super::*;

            type T = $t;
            const LO: i128 = T::MIN as i128;
            const HI: i128 = T::MAX as i128;

            fn running(active: u16, options: u32, rows: &[[i128; 5]], x: i128, y: i128) -> $v {
                let mut fb = $v::new(active, options, rows);
                assert_eq!(fb.init(), SL_OK);
                fb.set_inputs(0, x, y);
                fb.control(1, 0);
                assert_eq!(fb.cycle(0), SL_OK);
                fb
            }

            fn state_at(rows: &[[i128; 5]], options: u32, x: i128, y: i128) -> u8 {
                running(XY, options, rows, x, y).outputs().state
            }

            /// §4.25.2 RUN: "If InActive = FALSE and AreaValid = TRUE … Valid = 1 Warning = 0";
            /// §4.25.1 "If the value is within the switch-off level, the Valid output is set".
            /// Row 4 of the manual's table (X -15): Y inside WY1…WY2, bounds included.
            #[test]
            fn run_inside_the_warning_level() {
                let [_, _, _, wy1, wy2] = MANUAL[3];
                for y in [wy1, wy1 + 1, (wy1 + wy2) / 2, wy2 - 1, wy2] {
                    let fb = running(XY, 0, &MANUAL, MANUAL[3][0] + 1, y);
                    assert_eq!(fb.outputs(), outputs_of(SL_STATE_RUN), "{y}");
                    assert_eq!(fb.state_name(), "RUN");
                }
            }

            /// §4.25.2 WARNING (17): "If InActive = FALSE and AreaValidButWarning = TRUE …
            /// Valid = 1 Warning = 1"; §4.25.1 "If the value is between the Y1 and WY1 or Y2
            /// and WY2, the Warning output is set in addition" (switch-off bounds inclusive,
            /// warning bounds exclusive: LS4).
            #[test]
            fn warning_between_the_levels() {
                let [x, y1, y2, wy1, wy2] = MANUAL[3];
                for y in [y1, y1 + 1, wy1 - 1, wy2 + 1, y2 - 1, y2] {
                    let fb = running(XY, 0, &MANUAL, x + 1, y);
                    assert_eq!(fb.outputs(), outputs_of(SL_STATE_LOADSENSING_WARNING), "{y}");
                    assert_eq!(fb.state_name(), "WARNING");
                }
            }

            /// §4.25.2 SAFE: "If InActive = FALSE, AreaValid = FALSE and AreaValidButWarning
            /// = FALSE … Valid = 0 Warning = 0": outside the switch-off level.
            #[test]
            fn safe_outside_the_switch_off_level() {
                let [x, y1, y2, _, _] = MANUAL[3];
                for y in [y1 - 1, LO, y2 + 1, HI] {
                    let fb = running(XY, 0, &MANUAL, x + 1, y);
                    assert_eq!(fb.outputs(), outputs_of(SL_STATE_SAFE), "{y}");
                }
            }

            /// §4.25.1 "the largest index is determined whose corresponding X-value is still
            /// smaller than the AnalogInX input": strictly smaller (LS3). AnalogInX = X[i]
            /// still uses row i − 1; X[i] + 1 uses row i.
            #[test]
            fn the_row_is_the_last_x_strictly_below_analoginx() {
                for i in 1..25 {
                    let [x, _, _, wy1, _] = MANUAL[i];
                    // WY1 of row i is above Y2 of row i-1: RUN with row i, SAFE with row i-1.
                    assert_eq!(state_at(&MANUAL, 0, x, wy1), SL_STATE_SAFE, "row {i}");
                    assert_eq!(state_at(&MANUAL, 0, x + 1, wy1), SL_STATE_RUN, "row {i}");
                }
                // Beyond the last X: the last row.
                let [_, _, _, wy1, _] = MANUAL[24];
                assert_eq!(state_at(&MANUAL, 0, HI, wy1), SL_STATE_RUN);
            }

            /// No row lies below AnalogInX (AnalogInX ≤ X of row 1): SAFE whatever Y (LS3).
            #[test]
            fn no_row_below_analoginx_is_safe() {
                let [x, _, _, wy1, _] = MANUAL[0];
                for ax in [LO, x - 1, x] {
                    assert_eq!(state_at(&MANUAL, 0, ax, wy1), SL_STATE_SAFE, "{ax}");
                }
                assert_eq!(state_at(&MANUAL, 0, x + 1, wy1), SL_STATE_RUN);
            }

            /// Only rows 1…nRowCount are searched: the rows beyond are not used (LS5).
            #[test]
            fn rows_beyond_the_count_are_not_used() {
                let mut rows = MANUAL;
                // Row 4 unordered: ignored when only 3 rows are used.
                rows[3] = [0, 5, 1, 9, 9];
                let mut fb = $v::new(XY, 0, &rows[..3]);
                for (r, v) in fb.aRow.iter_mut().zip(&rows).skip(3) {
                    r.nX = $v::t(v[0]);
                    r.nY1 = $v::t(v[1]);
                }
                assert_eq!(fb.init(), SL_OK);
                fb.control(1, 0);
                // AnalogInX far above: row 3 (the last used), not row 25.
                let [_, _, _, wy1, _] = MANUAL[2];
                fb.set_inputs(0, HI, wy1);
                assert_eq!(fb.cycle(0), SL_OK);
                assert_eq!(fb.outputs().state, SL_STATE_RUN);
            }

            /// §4.25.1 "The Outside parameter can be used to reverse the test, in which case
            /// values outside Y1 and Y2 are valid … the warning level must be greater than the
            /// switch-off level": valid ⇔ Y ≤ Y1 ∨ Y ≥ Y2, warning ⇔ valid ∧ WY1 ≤ Y ≤ WY2.
            #[test]
            fn outside_reverses_the_test() {
                let rows = [[1000, 1100, 1200, 1050, 1250], [2000, 1100, 1200, 1100, 1200]];
                let at = |x, y| state_at(&rows, OUTSIDE, x, y);
                assert_eq!(at(1001, 1101), SL_STATE_SAFE);
                assert_eq!(at(1001, 1199), SL_STATE_SAFE);
                for y in [1100, 1099, 1050, 1200, 1201, 1250] {
                    assert_eq!(at(1001, y), SL_STATE_LOADSENSING_WARNING, "{y}");
                }
                for y in [1049, LO, 1251, HI] {
                    assert_eq!(at(1001, y), SL_STATE_RUN, "{y}");
                }
                // WY1 = Y1 and WY2 = Y2: only the levels themselves warn.
                assert_eq!(at(2001, 1100), SL_STATE_LOADSENSING_WARNING);
                assert_eq!(at(2001, 1099), SL_STATE_RUN);
                assert_eq!(at(2001, 1201), SL_STATE_RUN);
            }

            /// §4.25.2 INACTIVE (16): "If InActive = TRUE … Valid = 0 Warning = 0"; an
            /// invalid byte reads TRUE (ABI-2 §12.7) and the call says so; an inactive port
            /// reads FALSE and its byte is not read (LS1, LS2).
            #[test]
            fn inactive() {
                let [x, _, _, wy1, _] = MANUAL[3];
                let mut fb = running(ALL, 0, &MANUAL, x + 1, wy1);
                assert_eq!(fb.outputs().state, SL_STATE_RUN);
                fb.set_inputs(1, x + 1, wy1);
                assert_eq!(fb.cycle(1), SL_OK);
                assert_eq!(fb.outputs(), outputs_of(SL_STATE_LOADSENSING_INACTIVE));
                assert_eq!(fb.state_name(), "INACTIVE");
                fb.set_inputs(0, x + 1, wy1);
                assert_eq!(fb.cycle(2), SL_OK);
                assert_eq!(fb.outputs().state, SL_STATE_RUN);
                fb.set_inputs(2, x + 1, wy1);
                assert_eq!(fb.cycle(3), SL_E_INVALID_BOOL);
                assert_eq!(fb.outputs(), outputs_of(SL_STATE_LOADSENSING_INACTIVE));
                // Port inactive: TRUE and invalid bytes are ignored.
                let mut fb = running(XY, 0, &MANUAL, x + 1, wy1);
                for b in [1, 2, 255] {
                    fb.set_inputs(b, x + 1, wy1);
                    assert_eq!(fb.cycle(4), SL_OK);
                    assert_eq!(fb.outputs().state, SL_STATE_RUN);
                }
            }

            /// §4.25.2 STOP: "If the input FbRun = FALSE … Valid = 0 Warning = 0".
            #[test]
            fn stop_with_run_false() {
                let [x, _, _, wy1, _] = MANUAL[3];
                let mut fb = running(XY, 0, &MANUAL, x + 1, wy1);
                fb.control(0, 0);
                assert_eq!(fb.cycle(1), SL_OK);
                assert_eq!(fb.outputs(), outputs_of(SL_STATE_STOP));
                assert_eq!(fb.state_name(), "STOP");
            }

            /// §4.25.2 Diagnostic information "-", Diag Message "-": the block never shows a
            /// diag value or message; no Error output, no ERROR of its own.
            #[test]
            fn no_diag_values_and_no_messages() {
                let mut fb = running(ALL, 0, &MANUAL, 0, 0);
                for (i, (x, y)) in [(LO, LO), (HI, HI), (1000, 1000), (986, 1015)].iter().enumerate() {
                    fb.set_inputs((i % 2) as u8, *x, *y);
                    assert_eq!(fb.cycle(i as u32), SL_OK);
                    let o = fb.outputs();
                    assert_eq!((o.diag, o.text, o.par), (0, 0, (0, 0)));
                    assert_ne!(o.state, SL_STATE_ERROR);
                }
            }

            /// "There can be up to 25 indices": 1…25 rows, 0 and 26 are SL_E_CONFIG (LS5).
            #[test]
            fn row_count_limits() {
                for (n, rc) in [(0usize, SL_E_CONFIG), (1, SL_OK), (25, SL_OK)] {
                    let mut fb = $v::new(XY, 0, &MANUAL[..n]);
                    assert_eq!(fb.init(), rc, "{n}");
                }
                let mut fb = $v::new(XY, 0, &MANUAL);
                fb.nRowCount = 26;
                assert_eq!(fb.init(), SL_E_CONFIG);
                fb.control(1, 0);
                assert_eq!(fb.cycle(0), SL_E_CONFIG);
                assert_eq!(fb.outputs(), outputs_of(SL_STATE_STOP));
            }

            /// §4.25.1 "The data in the value table are checked based on the following
            /// formulas: Outside = FALSE: Y1 ≤ WY1 < WY2 ≤ Y2; Outside = TRUE: WY1 ≤ Y1 < Y2 ≤
            /// WY2", and X strictly increasing (LS5): each at its boundary.
            #[test]
            fn table_checks_at_their_boundaries() {
                let ok = |rows: &[[i128; 5]], options| $v::new(XY, options, rows).init();
                // Not outside.
                assert_eq!(ok(&[[0, 10, 40, 10, 40]], 0), SL_OK, "Y1 = WY1 < WY2 = Y2");
                assert_eq!(ok(&[[0, 10, 40, 10, 11]], 0), SL_OK, "Y1 = WY1");
                assert_eq!(ok(&[[0, 10, 40, 39, 40]], 0), SL_OK, "WY2 = Y2");
                assert_eq!(ok(&[[0, 10, 40, 9, 20]], 0), SL_E_CONFIG, "WY1 < Y1");
                assert_eq!(ok(&[[0, 10, 40, 20, 20]], 0), SL_E_CONFIG, "WY1 = WY2");
                assert_eq!(ok(&[[0, 10, 40, 20, 41]], 0), SL_E_CONFIG, "WY2 > Y2");
                // Outside.
                assert_eq!(ok(&[[0, 10, 40, 10, 40]], OUTSIDE), SL_OK, "WY1 = Y1, Y2 = WY2");
                assert_eq!(ok(&[[0, 10, 11, 5, 50]], OUTSIDE), SL_OK, "Y1 < Y2");
                assert_eq!(ok(&[[0, 10, 10, 5, 50]], OUTSIDE), SL_E_CONFIG, "Y1 = Y2");
                assert_eq!(ok(&[[0, 10, 40, 11, 50]], OUTSIDE), SL_E_CONFIG, "WY1 > Y1");
                assert_eq!(ok(&[[0, 10, 40, 5, 39]], OUTSIDE), SL_E_CONFIG, "WY2 < Y2");
                // X strictly increasing.
                let row = |x| [x, 10, 40, 20, 30];
                assert_eq!(ok(&[row(5), row(6)], 0), SL_OK);
                assert_eq!(ok(&[row(5), row(5)], 0), SL_E_CONFIG);
                assert_eq!(ok(&[row(6), row(5)], 0), SL_E_CONFIG);
                // The manual's example table is valid.
                assert_eq!(ok(&MANUAL, 0), SL_OK);
            }

            /// Fig. 132 row 1 as printed, Y2 −100 < WY2 −80, fails "Y1 ≤ WY1 < WY2 ≤ Y2".
            #[test]
            fn the_manuals_row_1_as_printed_is_refused() {
                let mut rows = MANUAL;
                rows[0][4] = -80 + 1000;
                assert_eq!($v::new(XY, 0, &rows).init(), SL_E_CONFIG);
            }

            /// ABI-2 §10.5: bits 8 and 9 required, bit 0 optional, no other bit; only the
            /// Outside option.
            #[test]
            fn active_bits_and_options() {
                for (active, rc) in [
                    (XY, SL_OK),
                    (ALL, SL_OK),
                    (SL_LOADSENSING_ACTIVE_ANALOGINX, SL_E_CONFIG),
                    (SL_LOADSENSING_ACTIVE_ANALOGINY | 1, SL_E_CONFIG),
                    (XY | 2, SL_E_CONFIG),
                    (XY | 1 << 10, SL_E_CONFIG),
                ] {
                    assert_eq!($v::new(active, 0, &MANUAL).init(), rc, "{active:#x}");
                }
                for (options, rc) in [(0, SL_OK), (OUTSIDE, SL_E_CONFIG), (1, SL_E_CONFIG), (1 << 9, SL_E_CONFIG)] {
                    // The manual's table is ordered for Outside FALSE only.
                    assert_eq!($v::new(XY, options, &MANUAL).init(), rc, "{options:#x}");
                }
            }

            /// ABI §7, semantics C5/LS6: a table value changed while running — in a used row
            /// or beyond the count — is SL_E_PARAM_CHANGED (ERROR, bit 13, outputs FALSE);
            /// acknowledged after bRun FALSE, the next start latches the new table.
            #[test]
            fn a_changed_row_is_a_parameter_change() {
                for row in [3usize, 24] {
                    let [x, _, _, wy1, _] = MANUAL[3];
                    let mut fb = running(XY, 0, &MANUAL[..10], x + 1, wy1);
                    fb.aRow[row].nWY2 = $v::t(MANUAL[row][4] - 1);
                    assert_eq!(fb.cycle(1), SL_E_PARAM_CHANGED, "row {row}");
                    let o = fb.outputs();
                    assert_eq!((o.state, o.valid, o.warning), (SL_STATE_ERROR, 0, 0));
                    assert_eq!(o.diag, SL_DIAG_PARAM_CHANGED);
                    // With bRun FALSE the acknowledging call returns as usual (C5).
                    fb.control(0, 1);
                    assert_eq!(fb.cycle(2), SL_OK);
                    assert_eq!(fb.outputs().state, SL_STATE_RESET);
                    fb.control(0, 0);
                    fb.cycle(3);
                    fb.control(1, 0);
                    assert_eq!(fb.cycle(4), SL_OK);
                    assert_eq!(fb.outputs().state, SL_STATE_RUN);
                }
            }

            /// Semantics C3/LS6: the latched table carries a CRC that is verified where Valid
            /// switches on; a latched row that no longer matches it is SL_E_CORRUPT.
            #[test]
            fn a_corrupted_latched_row_is_found_where_valid_switches_on() {
                let [x, _, _, wy1, _] = MANUAL[3];
                let mut fb = running(XY, 0, &MANUAL, x + 1, LO);
                assert_eq!(fb.outputs().state, SL_STATE_SAFE);
                // The same change in the live table and the latched copy: only the CRC sees it.
                let v = $v::t(MANUAL[20][1] + 1);
                fb.aRow[20].nY1 = v;
                fb.stPrivate.aRow[20].nY1 = v;
                fb.set_inputs(0, x + 1, LO);
                assert_eq!(fb.cycle(1), SL_OK);
                fb.set_inputs(0, x + 1, wy1);
                assert_eq!(fb.cycle(2), SL_E_CORRUPT);
                let o = fb.outputs();
                assert_eq!((o.state, o.valid, o.diag), (SL_STATE_ERROR, 0, SL_DIAG_CORRUPT));
            }

            /// A random ordered table of `n` rows over the whole range of T.
            fn table(rng: &mut Rng, outside: bool) -> Vec<[i128; 5]> {
                let n = 1 + (rng.next() % 25) as usize;
                let mut xs: Vec<i128> = (0..n).map(|_| value(rng, &[])).collect();
                xs.sort();
                xs.dedup();
                xs.iter()
                    .map(|&x| loop {
                        let mut v = [0; 4].map(|_| value(rng, &[x]));
                        v.sort();
                        if v[1] < v[2] {
                            let [a, b, c, d] = v;
                            break if outside { [x, b, c, a, d] } else { [x, a, d, b, c] };
                        }
                    })
                    .collect()
            }

            fn value(rng: &mut Rng, anchors: &[i128]) -> i128 {
                match rng.next() % 4 {
                    0 if !anchors.is_empty() => {
                        let a = anchors[(rng.next() % anchors.len() as u64) as usize];
                        (a + (rng.next() % 7) as i128 - 3).clamp(LO, HI)
                    }
                    1 => [LO, HI, 0.max(LO), LO + 1, HI - 1][(rng.next() % 5) as usize],
                    _ => LO + (rng.next() as i128).rem_euclid(HI - LO + 1),
                }
            }

            /// ≥ 10,000 random sequences: random ordered tables (both Outside settings), the
            /// inputs near the table's values, bRun, Inactive (invalid bytes included),
            /// against the model cycle by cycle. Asserts every state of the manual reached.
            #[test]
            fn random_sequences_against_the_model() {
                let mut rng = Rng(0x10AD_5E45 ^ (HI as u64));
                let mut reached = 0u64;
                const SEQUENCES: u32 = 10_000;
                for _ in 0..SEQUENCES {
                    let outside = rng.next() % 2 == 0;
                    let rows = table(&mut rng, outside);
                    let active = if rng.next() % 2 == 0 { ALL } else { XY };
                    let mut fb = $v::new(active, if outside { OUTSIDE } else { 0 }, &rows);
                    assert_eq!(fb.init(), SL_OK);
                    for t in 0..12u32 {
                        let r = rng.next();
                        let run = r % 8 != 0;
                        let inactive_byte = match r >> 3 & 15 {
                            0 => 1,
                            1 => 2 + (r >> 8) as u8 % 250,
                            _ => 0,
                        };
                        let row = rows[(r >> 16) as usize % rows.len()];
                        let x = value(&mut rng, &[row[0], row[0] + 1]);
                        let y = value(&mut rng, &row[1..]);
                        fb.control(u8::from(run), 0);
                        fb.set_inputs(inactive_byte, x, y);
                        let read = active & SL_LOADSENSING_ACTIVE_INACTIVE != 0;
                        let rc = fb.cycle(t);
                        let expected_rc = if read && inactive_byte > 1 { SL_E_INVALID_BOOL } else { SL_OK };
                        assert_eq!(rc, expected_rc);
                        let state = if run {
                            model_state(&rows, outside, read && inactive_byte != 0, x, y)
                        } else {
                            SL_STATE_STOP
                        };
                        assert_eq!(
                            fb.outputs(),
                            outputs_of(state),
                            "t {t}: x {x} y {y} inactive {inactive_byte} rows {rows:?} outside {outside}"
                        );
                        reached |= 1 << state;
                    }
                }
                crate::common::assert_reached(reached, [
                    SL_STATE_RUN,
                    SL_STATE_STOP,
                    SL_STATE_SAFE,
                    SL_STATE_LOADSENSING_INACTIVE,
                    SL_STATE_LOADSENSING_WARNING,
                ]);
            }
        }
    };
}

loadsensing_tests!(int, LsInt, i16);
loadsensing_tests!(uint, LsUint, u16);
loadsensing_tests!(dint, LsDint, i32);
loadsensing_tests!(udint, LsUdint, u32);
