//! ABI §4 "A call is total" for the FSoE connection: random bytes in every field of
//! `SL_FSOE_CONN` (the private state included), random received frames and time steps,
//! through the C functions. Every call returns a documented status (never SL_E_INTERNAL),
//! the BOOL outputs are 0/1, `aRxSafeData` is 0 unless `bDataValid`, a refused cycle sends
//! nothing; and the pointer checks of `sl_fsoe_cycle` (NULL, misaligned, overlapping).

mod common;

use safelogic::ffi::{sl_fsoe_cycle, sl_fsoe_init};
use safelogic::fsoe::frame::frame_len;
use safelogic::*;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
}

fn bytes(c: &mut SL_FSOE_CONN) -> &mut [u8] {
    // SAFETY: SL_FSOE_CONN holds only integer fields, so every byte pattern is a valid
    // value; the slice covers exactly the instance.
    unsafe {
        std::slice::from_raw_parts_mut(
            (c as *mut SL_FSOE_CONN).cast::<u8>(),
            std::mem::size_of::<SL_FSOE_CONN>(),
        )
    }
}

const DOCUMENTED: [i32; 5] = [
    SL_OK,
    SL_E_CONFIG,
    SL_E_CORRUPT,
    SL_E_INVALID_BOOL,
    SL_E_LENGTH,
];

#[test]
fn random_bytes_everywhere_are_survived() {
    let mut rng = Rng(0xD1B5_4A32_D192_ED03);
    let mut statuses = std::collections::HashSet::new();
    let mut states = std::collections::HashSet::new();
    for round in 0..10_000 {
        let mut c = SL_FSOE_CONN::default();
        for b in bytes(&mut c).iter_mut() {
            *b = rng.next() as u8;
        }
        if round % 2 == 0 {
            // Valid parameters half of the time, so that init accepts.
            c.nConnectionId = 1 + (rng.next() % 1000) as u16;
            c.nRole = 1 + (rng.next() % 2) as u16;
            c.nTxDataLen = [1, 2, 4, 8][rng.next() as usize % 4];
            c.nRxDataLen = [1, 2, 4, 8][rng.next() as usize % 4];
            c.nAppParaLen = (rng.next() % 65) as u16;
            c.tWatchdogTime = 1 + (rng.next() % 200) as u32;
            c.dwOptions = (rng.next() % 8) as u32;
        }
        if round % 3 != 0 {
            // SAFETY: a live, exclusively borrowed instance.
            let rc = unsafe { sl_fsoe_init(&mut c) };
            assert!(rc == SL_OK || rc == SL_E_CONFIG, "init {rc}");
        }
        let mut now = rng.next() as u32;
        for _ in 0..40 {
            let r = rng.next();
            for b in bytes(&mut c)[..5].iter_mut() {
                *b = if r % 5 == 0 {
                    r as u8
                } else {
                    (rng.next() & 1) as u8
                };
            }
            let n = frame_len(usize::from(c.nRxDataLen)).max(1);
            let mut rx = vec![0u8; if r % 7 == 0 { n + 1 } else { n }];
            for b in rx.iter_mut() {
                *b = rng.next() as u8;
            }
            if r % 3 == 0 {
                rx[0] = [0x2A, 0x4E, 0x64, 0x52, 0x36, 0x08][(r >> 8) as usize % 6];
            }
            let mut tx = [0xEEu8; 80];
            let mut len = 12345usize;
            now = now.wrapping_add((rng.next() % 150) as u32);
            let use_rx = r % 4 != 0;
            // SAFETY: disjoint, live buffers of the given lengths.
            let rc = unsafe {
                sl_fsoe_cycle(
                    &mut c,
                    now,
                    if use_rx {
                        rx.as_ptr()
                    } else {
                        std::ptr::null()
                    },
                    if use_rx { rx.len() } else { 0 },
                    tx.as_mut_ptr(),
                    tx.len(),
                    &mut len,
                )
            };
            assert!(DOCUMENTED.contains(&rc), "status {rc}");
            statuses.insert(rc);
            assert!(len <= 67);
            assert!(
                tx[len..].iter().all(|&b| b == 0xEE),
                "written beyond the frame"
            );
            if rc == SL_E_CONFIG || rc == SL_E_CORRUPT {
                assert_eq!(len, 0);
            }
            common::fsoe::assert_bool_outputs(&c);
            if rc != SL_E_CONFIG && c.bDataValid == 0 {
                assert_eq!(c.aRxSafeData, [0; 32]);
            }
            if rc == SL_OK || rc == SL_E_INVALID_BOOL {
                states.insert(c.nState);
            }
            if rc == SL_E_CORRUPT {
                break;
            }
        }
    }
    for s in [
        SL_OK,
        SL_E_CONFIG,
        SL_E_CORRUPT,
        SL_E_INVALID_BOOL,
        SL_E_LENGTH,
    ] {
        assert!(statuses.contains(&s), "status {s} never reached");
    }
    assert!(states.contains(&100) && states.contains(&101), "{states:?}");
}

#[test]
fn cycle_refuses_bad_pointers_and_overlapping_buffers() {
    let mut c = SL_FSOE_CONN {
        nConnectionId: 1,
        nRole: 1,
        nTxDataLen: 2,
        nRxDataLen: 2,
        tWatchdogTime: 10,
        ..Default::default()
    };
    let mut tx = [0u8; 67];
    let mut len = 0usize;
    // SAFETY: every pointer below is NULL, misaligned on purpose, or valid for its length.
    unsafe {
        assert_eq!(sl_fsoe_init(std::ptr::null_mut()), SL_E_NULL);
        assert_eq!(sl_fsoe_init(&mut c), SL_OK);
        let p = &mut c as *mut SL_FSOE_CONN;
        assert_eq!(
            sl_fsoe_cycle(
                p,
                0,
                std::ptr::null(),
                0,
                std::ptr::null_mut(),
                67,
                &mut len
            ),
            SL_E_NULL
        );
        assert_eq!(
            sl_fsoe_cycle(
                p,
                0,
                std::ptr::null(),
                0,
                tx.as_mut_ptr(),
                67,
                std::ptr::null_mut()
            ),
            SL_E_NULL
        );
        let misaligned = (p as *mut u8).add(1).cast::<SL_FSOE_CONN>();
        assert_eq!(
            sl_fsoe_cycle(
                misaligned,
                0,
                std::ptr::null(),
                0,
                tx.as_mut_ptr(),
                67,
                &mut len
            ),
            SL_E_ALIGNMENT
        );
        // The transmit buffer inside the connection, or the received frame inside the
        // transmit buffer.
        let inside = (p as *mut u8).add(16);
        assert_eq!(
            sl_fsoe_cycle(p, 0, std::ptr::null(), 0, inside, 16, &mut len),
            SL_E_CONFIG
        );
        assert_eq!(
            sl_fsoe_cycle(p, 0, tx.as_ptr().add(2), 7, tx.as_mut_ptr(), 67, &mut len),
            SL_E_CONFIG
        );
        assert_eq!(c.nState, 100);
        assert_eq!(
            sl_fsoe_cycle(p, 0, std::ptr::null(), 0, tx.as_mut_ptr(), 67, &mut len),
            SL_OK
        );
        assert_eq!(len, 7);
    }
}
