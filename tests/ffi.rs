//! The C functions (ABI §4, §5): NULL and misaligned pointers, never-initialised, garbage
//! and foreign private state, the struct layout of ABI §3/§8, and a scenario driven only
//! through `sl_estop_*` / `sl_mon_*`.
//!
//! References: "ABI §n" = shared/design/ABI.md; "Cn"/"Gn" = docs/semantics.md rows;
//! "§4.4.x"/"§4.5.x" = twinsafe-logic-fb-manual.txt.

mod common;
use common::*;
use safelogic::ffi::{
    sl_estop_cycle, sl_estop_init, sl_mon_cycle, sl_mon_init, sl_status_str, sl_version,
    sl_version_compatible,
};
use safelogic::*;
use std::ffi::CStr;
use std::mem::{align_of, offset_of, size_of};
use std::ptr;

/// ABI §5 SL_E_NULL "a required pointer is NULL".
#[test]
fn null_pointers_are_sl_e_null() {
    assert_eq!(unsafe { sl_estop_init(ptr::null_mut()) }, SL_E_NULL);
    assert_eq!(unsafe { sl_estop_cycle(ptr::null_mut(), 0) }, SL_E_NULL);
    assert_eq!(unsafe { sl_estop_cycle(ptr::null_mut(), T0) }, SL_E_NULL);
    assert_eq!(unsafe { sl_mon_init(ptr::null_mut()) }, SL_E_NULL);
    assert_eq!(unsafe { sl_mon_cycle(ptr::null_mut(), 0) }, SL_E_NULL);
    assert_eq!(
        unsafe { sl_mon_cycle(ptr::null_mut(), u32::MAX) },
        SL_E_NULL
    );
}

/// A buffer with room for one block at any byte offset 0..8, 8-byte aligned.
#[repr(C, align(8))]
struct Buf([u8; 256]);

/// C11 "Status SL_E_ALIGNMENT (-8): instance pointer not 4-byte aligned; nothing written."
#[test]
fn misaligned_pointer_is_sl_e_alignment_and_nothing_is_written() {
    let mut fb = estop(0b1);
    fb.bRestart = 1;
    let mut m = mon(0b1, 0);
    m.bRestart = 1;
    for off in [1usize, 2, 3, 5, 6, 7] {
        let mut buf = Buf([0xCC; 256]);
        let base = buf.0.as_mut_ptr();
        // SAFETY: the offset stays inside the buffer; the unaligned write copies bytes.
        unsafe {
            let p = base.add(off).cast::<FB_ESTOP>();
            ptr::write_unaligned(p, fb);
            let before = buf.0;
            let p = buf.0.as_mut_ptr().add(off).cast::<FB_ESTOP>();
            assert_eq!(sl_estop_init(p), SL_E_ALIGNMENT, "offset {off}");
            assert_eq!(sl_estop_cycle(p, T0), SL_E_ALIGNMENT, "offset {off}");
            assert_eq!(buf.0, before, "bytes written through a misaligned pointer");

            let p = buf.0.as_mut_ptr().add(off).cast::<FB_MON>();
            ptr::write_unaligned(p, m);
            let before = buf.0;
            let p = buf.0.as_mut_ptr().add(off).cast::<FB_MON>();
            assert_eq!(sl_mon_init(p), SL_E_ALIGNMENT, "offset {off}");
            assert_eq!(sl_mon_cycle(p, T0), SL_E_ALIGNMENT, "offset {off}");
            assert_eq!(buf.0, before, "bytes written through a misaligned pointer");
        }
    }
}

/// C11: only 4-byte alignment is required — an instance at an address that is 4 but not 8
/// aligned works.
#[test]
fn four_byte_aligned_instance_is_accepted() {
    let mut buf = Buf([0; 256]);
    // SAFETY: offset 4 of an 8-aligned buffer is 4-aligned (align_of::<FB_ESTOP>() is 4,
    // checked below) and inside the buffer.
    unsafe {
        assert!(align_of::<FB_ESTOP>() <= 4);
        let p = buf.0.as_mut_ptr().add(4).cast::<FB_ESTOP>();
        ptr::write(p, estop(0b1));
        assert_eq!(sl_estop_init(p), SL_OK);
        assert_eq!(sl_estop_cycle(p, T0), SL_OK);
        expect(&*p, SL_STATE_SAFE);
    }
}

/// ABI §3.6 "A private area of all zero bytes is a valid never-initialised instance"; ABI
/// §4 "cycle on a never-initialised instance initialises it first"; C2.
#[test]
fn zeroed_private_state_through_the_c_functions() {
    let mut e = estop(0b11);
    assert_eq!(unsafe { sl_estop_cycle(&mut e, T0) }, SL_OK);
    expect(&e, SL_STATE_SAFE);
    let mut m = mon(0b11, 0);
    assert_eq!(unsafe { sl_mon_cycle(&mut m, T0) }, SL_OK);
    expect(&m, SL_STATE_SAFE);
    assert_eq!(unsafe { sl_mon_cycle(&mut m, T0 + 1) }, SL_OK);
    expect(&m, SL_STATE_RUN);
    // zeroing the private area again: a never-initialised instance, outputs off
    m.stPrivate = SL_GUARD_PRIVATE::default();
    assert_eq!(unsafe { sl_mon_cycle(&mut m, T0 + 2) }, SL_OK);
    expect(&m, SL_STATE_SAFE);
}

fn fill_private(p: &mut SL_GUARD_PRIVATE, byte: u8) {
    // SAFETY: SL_GUARD_PRIVATE holds only integers (ABI §3.6); any byte pattern is valid.
    unsafe {
        ptr::write_bytes(
            (p as *mut SL_GUARD_PRIVATE).cast::<u8>(),
            byte,
            size_of::<SL_GUARD_PRIVATE>(),
        );
    }
}

/// ABI §5 SL_E_CORRUPT "ERROR (4), bError TRUE"; C3 "put into ERROR with diag bit 15";
/// every other output FALSE (ABI §7 Errors).
#[test]
fn garbage_private_state_through_the_c_functions() {
    for byte in [0xA5u8, 0xFF, 0x5A, 0x01] {
        let mut e = estop(0b1);
        assert_eq!(unsafe { sl_estop_init(&mut e) }, SL_OK);
        assert_eq!(unsafe { sl_estop_cycle(&mut e, T0) }, SL_OK);
        fill_private(&mut e.stPrivate, byte);
        assert_eq!(unsafe { sl_estop_cycle(&mut e, T0 + 1) }, SL_E_CORRUPT);
        expect_error(&e, SL_DIAG_CORRUPT);
        assert_eq!((e.bError, e.bEStopOut, e.bEStopDelOut), (1, 0, 0));

        let mut m = mon(0b1, 0);
        assert_eq!(unsafe { sl_mon_init(&mut m) }, SL_OK);
        assert_eq!(unsafe { sl_mon_cycle(&mut m, T0) }, SL_OK);
        assert_eq!(unsafe { sl_mon_cycle(&mut m, T0 + 1) }, SL_OK);
        expect(&m, SL_STATE_RUN);
        fill_private(&mut m.stPrivate, byte);
        assert_eq!(unsafe { sl_mon_cycle(&mut m, T0 + 2) }, SL_E_CORRUPT);
        expect_error(&m, SL_DIAG_CORRUPT);
        assert_eq!((m.bError, m.bMonOut, m.bMonDelOut), (1, 0, 0));
    }
}

/// C3 "the block's magic word": an FB_MON's private state copied into an FB_ESTOP is
/// SL_E_CORRUPT, ERROR, diag bit 15, outputs FALSE.
#[test]
fn mon_private_state_copied_into_an_estop_is_corrupt() {
    let mut m = mon(0b1, 0);
    assert_eq!(unsafe { sl_mon_init(&mut m) }, SL_OK);
    assert_eq!(unsafe { sl_mon_cycle(&mut m, T0) }, SL_OK);
    assert_eq!(unsafe { sl_mon_cycle(&mut m, T0 + 1) }, SL_OK);
    expect(&m, SL_STATE_RUN);

    let mut e = estop(0b1);
    assert_eq!(unsafe { sl_estop_init(&mut e) }, SL_OK);
    assert_eq!(unsafe { sl_estop_cycle(&mut e, T0) }, SL_OK);
    e.stPrivate = m.stPrivate;
    assert_eq!(unsafe { sl_estop_cycle(&mut e, T0 + 2) }, SL_E_CORRUPT);
    expect_error(&e, SL_DIAG_CORRUPT);

    // also into a never-cycled (only init'ed) ESTOP
    let mut e = estop(0b1);
    assert_eq!(unsafe { sl_estop_init(&mut e) }, SL_OK);
    e.stPrivate = m.stPrivate;
    assert_eq!(unsafe { sl_estop_cycle(&mut e, T0 + 2) }, SL_E_CORRUPT);
    expect_error(&e, SL_DIAG_CORRUPT);
}

/// ABI §5 SL_E_CONFIG through the C functions: "safe (all FALSE), nState = STOP (2)".
#[test]
fn config_error_through_the_c_functions() {
    let mut e = estop(0b1);
    e.dwOptions = SL_OPT_FUNCTION_TEST;
    assert_eq!(unsafe { sl_estop_init(&mut e) }, SL_E_CONFIG);
    expect(&e, SL_STATE_STOP);
    assert_eq!(unsafe { sl_estop_cycle(&mut e, T0) }, SL_E_CONFIG);
    expect(&e, SL_STATE_STOP);
    let mut m = mon(0b11_0000, 0);
    assert_eq!(unsafe { sl_mon_init(&mut m) }, SL_E_CONFIG);
    assert_eq!(unsafe { sl_mon_cycle(&mut m, T0) }, SL_E_CONFIG);
    expect(&m, SL_STATE_STOP);
}

/// ABI §5 SL_E_CLOCK through the C function.
#[test]
fn clock_error_through_the_c_functions() {
    let mut e = estop(0b1);
    assert_eq!(unsafe { sl_estop_cycle(&mut e, T0) }, SL_OK);
    assert_eq!(unsafe { sl_estop_cycle(&mut e, T0 - 1) }, SL_E_CLOCK);
    expect_error(&e, SL_DIAG_CLOCK);
}

/// §4.4.4 Sample 1 driven only through the C functions.
#[test]
fn estop_scenario_through_the_c_functions() {
    let mut e = estop(0b11);
    e.tDiscTime12 = 100;
    e.tEStopDelOutDelay = 50;
    e.dwOptions = SL_OPT_EDM1 | SL_OPT_EDM2;
    assert_eq!(unsafe { sl_estop_init(&mut e) }, SL_OK);
    let mut t = T0;
    let mut call = |e: &mut FB_ESTOP, dt: u32, state: u8| {
        t += dt;
        assert_eq!(unsafe { sl_estop_cycle(e, t) }, SL_OK, "t={t}");
        expect(e, state);
    };
    call(&mut e, 1, SL_STATE_SAFE);
    e.bRestart = 1;
    call(&mut e, 1, SL_STATE_START);
    e.bRestart = 0;
    call(&mut e, 1, SL_STATE_RUN);
    e.bEDM1 = 0;
    e.bEDM2 = 0;
    call(&mut e, 10, SL_STATE_RUN);
    e.bEStopIn1 = 0;
    e.bEStopIn2 = 0;
    call(&mut e, 10, SL_STATE_DELAYOUT);
    e.bEDM1 = 1;
    call(&mut e, 49, SL_STATE_DELAYOUT);
    call(&mut e, 1, SL_STATE_SAFE);
    e.bEDM2 = 1;
    e.bEStopIn1 = 1;
    e.bEStopIn2 = 1;
    call(&mut e, 10, SL_STATE_SAFE);
    e.bRestart = 1;
    call(&mut e, 10, SL_STATE_START);
    e.bRestart = 0;
    call(&mut e, 10, SL_STATE_RUN);
}

/// §4.5 MON with automatic restart and Secure bypass through the C functions.
#[test]
fn mon_scenario_through_the_c_functions() {
    let mut m = mon(0b1 | 0b11_0000, 0);
    m.bSecure1 = 0;
    m.bSecure2 = 0;
    assert_eq!(unsafe { sl_mon_init(&mut m) }, SL_OK);
    assert_eq!(unsafe { sl_mon_cycle(&mut m, 1) }, SL_OK);
    expect(&m, SL_STATE_SAFE);
    assert_eq!(unsafe { sl_mon_cycle(&mut m, 2) }, SL_OK);
    expect(&m, SL_STATE_RUN);
    m.bMonIn1 = 0;
    assert_eq!(unsafe { sl_mon_cycle(&mut m, 3) }, SL_OK);
    expect(&m, SL_STATE_SAFE);
    m.bSecure1 = 1;
    m.bSecure2 = 1;
    assert_eq!(unsafe { sl_mon_cycle(&mut m, 4) }, SL_OK);
    expect(&m, SL_STATE_RUN);
}

/// ABI §5 "`const char *sl_status_str(int32_t)` returns a static, human-readable text for
/// each".
#[test]
fn status_texts_exist_for_every_code() {
    let mut seen = Vec::new();
    for code in DOCUMENTED_STATUS {
        let p = sl_status_str(code);
        assert!(!p.is_null());
        // SAFETY: non-null, NUL-terminated static text (ABI §5).
        let s = unsafe { CStr::from_ptr(p) }.to_str().unwrap().to_owned();
        assert!(!s.is_empty(), "code {code}");
        assert!(!seen.contains(&s), "two codes share the text {s:?}");
        seen.push(s);
    }
    for code in [1, -9, i32::MIN, i32::MAX] {
        assert!(!sl_status_str(code).is_null());
    }
}

/// One version source: sl_version() and the header's SL_VERSION_* macros are Cargo's
/// version; sl_version_compatible accepts exactly the same major with a minor not newer
/// than the library's.
#[test]
fn version_text_macros_and_compatibility() {
    // SAFETY: sl_version returns static, NUL-terminated text (ABI §5).
    let text = unsafe { CStr::from_ptr(sl_version()) }.to_str().unwrap();
    assert_eq!(text, env!("CARGO_PKG_VERSION"));
    let header = include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/include/safelogic.h"));
    let macro_value = |name: &str| -> u32 {
        let line = header
            .lines()
            .find_map(|l| l.strip_prefix(&format!("#define {name} ")))
            .unwrap_or_else(|| panic!("{name} missing from the header"));
        line.trim().parse().unwrap()
    };
    let (major, minor, patch) = (
        macro_value("SL_VERSION_MAJOR"),
        macro_value("SL_VERSION_MINOR"),
        macro_value("SL_VERSION_PATCH"),
    );
    assert_eq!(text, format!("{major}.{minor}.{patch}"));
    assert_eq!(sl_version_compatible(major, minor), 1);
    for older in 0..minor {
        assert_eq!(sl_version_compatible(major, older), 1, "minor {older}");
    }
    assert_eq!(sl_version_compatible(major, minor + 1), 0, "a newer header");
    assert_eq!(sl_version_compatible(major + 1, 0), 0, "the next major");
    assert_eq!(
        sl_version_compatible(major.wrapping_sub(1), minor),
        0,
        "the previous major"
    );
    assert_eq!(sl_version_compatible(u32::MAX, u32::MAX), 0);
}

/// ABI §5 numeric values, ABI §6 option bits, manual §4.4.2/§4.5.2 state values and diag
/// bits.
#[test]
fn abi_constants() {
    // SL_OK, SL_E_NULL, _CONFIG, _PARAM_CHANGED, _CORRUPT, _INVALID_BOOL, _CLOCK, and
    // _INTERNAL, _ALIGNMENT (C11).
    assert_eq!(DOCUMENTED_STATUS, [0, -1, -2, -3, -4, -5, -6, -7, -8]);
    assert_eq!((SL_E_INTERNAL, SL_E_ALIGNMENT), (-7, -8)); // C11
    assert_eq!(
        [
            SL_OPT_EDM1,
            SL_OPT_EDM2,
            SL_OPT_SAFE_INPUTS_AFTER_DISC,
            SL_OPT_MANUAL_RESTART,
            SL_OPT_FUNCTION_TEST
        ],
        [1, 2, 4, 8, 16]
    );
    assert_eq!(
        CORE_STATES
            .into_iter()
            .chain([SL_STATE_START, SL_STATE_ERRORDELAY])
            .chain([SL_STATE_DELAYOUT, SL_STATE_FUNCTEST])
            .collect::<Vec<_>>(),
        [1, 2, 3, 4, 5, 6, 7, 8, 9]
    );
    assert_eq!(
        [
            SL_DIAG_DISC1,
            SL_DIAG_DISC2,
            SL_DIAG_DISC3,
            SL_DIAG_DISC4,
            SL_DIAG_EDM1,
            SL_DIAG_EDM2,
            SL_DIAG_SAFE_IN_DISC1,
            SL_DIAG_SAFE_IN_DISC2,
            SL_DIAG_SAFE_IN_DISC3,
            SL_DIAG_SAFE_IN_DISC4,
            SL_DIAG_PARAM_CHANGED,
            SL_DIAG_CLOCK,
            SL_DIAG_CORRUPT
        ],
        [
            1 << 0,
            1 << 1,
            1 << 2,
            1 << 3,
            1 << 4,
            1 << 5,
            1 << 8,
            1 << 9,
            1 << 10,
            1 << 11,
            1 << 13,
            1 << 14,
            1 << 15
        ]
    );
}

/// ABI §3 and §8: inputs at the manual's offsets (§4.4.2 / §4.5.2 Offset columns), outputs
/// at an output base that is a multiple of 8 plus the manual's offsets, size a multiple of
/// 8, every member at a multiple of its size.
#[test]
fn struct_layout_matches_the_manual_offsets() {
    assert_eq!(offset_of!(FB_ESTOP, bRestart), 0);
    assert_eq!(offset_of!(FB_ESTOP, bEDM1), 1);
    assert_eq!(offset_of!(FB_ESTOP, bEDM2), 2);
    let ins = [
        offset_of!(FB_ESTOP, bEStopIn1),
        offset_of!(FB_ESTOP, bEStopIn2),
        offset_of!(FB_ESTOP, bEStopIn3),
        offset_of!(FB_ESTOP, bEStopIn4),
        offset_of!(FB_ESTOP, bEStopIn5),
        offset_of!(FB_ESTOP, bEStopIn6),
        offset_of!(FB_ESTOP, bEStopIn7),
        offset_of!(FB_ESTOP, bEStopIn8),
    ];
    assert_eq!(ins, [8, 9, 10, 11, 12, 13, 14, 15]);
    let base = offset_of!(FB_ESTOP, bError);
    assert_eq!(base % 8, 0);
    assert_eq!(offset_of!(FB_ESTOP, bEStopOut) - base, 1);
    assert_eq!(offset_of!(FB_ESTOP, bEStopDelOut) - base, 2);
    assert_eq!(size_of::<FB_ESTOP>() % 8, 0);
    assert_eq!(offset_of!(FB_ESTOP, stPrivate) % 8, 0);
    for (off, size) in [
        (offset_of!(FB_ESTOP, tDiscTime12), 4),
        (offset_of!(FB_ESTOP, tDiscTime34), 4),
        (offset_of!(FB_ESTOP, tDiscTime56), 4),
        (offset_of!(FB_ESTOP, tDiscTime78), 4),
        (offset_of!(FB_ESTOP, tEDM1ResetTime), 4),
        (offset_of!(FB_ESTOP, tEDM2ResetTime), 4),
        (offset_of!(FB_ESTOP, tEStopDelOutDelay), 4),
        (offset_of!(FB_ESTOP, wInputActive), 2),
        (offset_of!(FB_ESTOP, wInputNegated), 2),
        (offset_of!(FB_ESTOP, dwOptions), 4),
        (offset_of!(FB_ESTOP, nDiag), 2),
    ] {
        assert_eq!(off % size, 0, "ESTOP member at {off}");
    }

    assert_eq!(offset_of!(FB_MON, bRestart), 0);
    assert_eq!(offset_of!(FB_MON, bEDM1), 1);
    assert_eq!(offset_of!(FB_MON, bEDM2), 2);
    let ins = [
        offset_of!(FB_MON, bMonIn1),
        offset_of!(FB_MON, bMonIn2),
        offset_of!(FB_MON, bMonIn3),
        offset_of!(FB_MON, bMonIn4),
        offset_of!(FB_MON, bSecure1),
        offset_of!(FB_MON, bSecure2),
    ];
    assert_eq!(ins, [8, 9, 10, 11, 12, 13]);
    let base = offset_of!(FB_MON, bError);
    assert_eq!(base % 8, 0);
    assert_eq!(offset_of!(FB_MON, bMonOut) - base, 1);
    assert_eq!(offset_of!(FB_MON, bMonDelOut) - base, 2);
    assert_eq!(size_of::<FB_MON>() % 8, 0);
    assert_eq!(offset_of!(FB_MON, stPrivate) % 8, 0);
    for (off, size) in [
        (offset_of!(FB_MON, tDiscTime12), 4),
        (offset_of!(FB_MON, tDiscTime34), 4),
        (offset_of!(FB_MON, tDiscTimeSecure12), 4),
        (offset_of!(FB_MON, tEDM1ResetTime), 4),
        (offset_of!(FB_MON, tEDM2ResetTime), 4),
        (offset_of!(FB_MON, tMonDelOutDelay), 4),
        (offset_of!(FB_MON, wInputActive), 2),
        (offset_of!(FB_MON, wInputNegated), 2),
        (offset_of!(FB_MON, dwOptions), 4),
        (offset_of!(FB_MON, nDiag), 2),
    ] {
        assert_eq!(off % size, 0, "MON member at {off}");
    }
}
