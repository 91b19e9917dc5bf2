//! FSoE connection benchmark (issue 11 item 7): one connection cycle in DATA with 16 bytes
//! of SafeData per direction — decode and check the partner's frame (CRC per 2-byte block,
//! sequence number, chain), the state machine, encode the answer — through the C function
//! `sl_fsoe_cycle`, as from C. A master and a slave answer each other, so every call sees a
//! new frame (the frame-received event). Prints median and p99 per call and the bytes of
//! private state per connection. `cargo bench --bench fsoe`. Reports, never asserts timing.

use safelogic::ffi::*;
use safelogic::*;
use std::hint::black_box;
use std::mem::size_of;
use std::time::Instant;

const PAIRS_PER_BATCH: u32 = 500;
const DATA: u16 = 16;
const TARGET_NS: f64 = 250.0;

fn conn(role: u16, seed: u16) -> SL_FSOE_CONN {
    SL_FSOE_CONN {
        nConnectionId: 7,
        nFsoeAddress: 3,
        nRole: role,
        nTxDataLen: DATA,
        nRxDataLen: DATA,
        tWatchdogTime: 1000,
        nSessionIdSeed: seed,
        bRun: 1,
        ..Default::default()
    }
}

fn main() {
    let quick = !std::env::args().any(|a| a == "--bench");
    let batches = if quick { 20 } else { 3000 };
    let spin = Instant::now();
    while spin.elapsed().as_millis() < if quick { 10 } else { 1500 } {
        black_box(spin.elapsed());
    }
    let mut m = conn(SL_FSOE_ROLE_MASTER, 0x1234);
    let mut s = conn(SL_FSOE_ROLE_SLAVE, 0x5678);
    let f: unsafe extern "C" fn(
        *mut SL_FSOE_CONN,
        u32,
        *const u8,
        usize,
        *mut u8,
        usize,
        *mut usize,
    ) -> i32 = black_box(sl_fsoe_cycle);
    let n = sl_fsoe_frame_len(usize::from(DATA));
    let (mut mf, mut sf) = ([0u8; 67], [0u8; 67]);
    let (mut mlen, mut slen) = (0usize, 0usize);
    // SAFETY (every call): live locals, buffers of 67 bytes, no overlap.
    unsafe {
        assert_eq!(sl_fsoe_init(&mut m), SL_OK);
        assert_eq!(sl_fsoe_init(&mut s), SL_OK);
    }
    let mut t = 0u32;
    // Start-up to DATA, then steady ProcessData both ways. Each buffer keeps the last frame
    // its node produced (a cyclic bus re-sends it).
    let mut slave_sent = false;
    for k in 0..200u32 {
        t = t.wrapping_add(1);
        m.aTxSafeData[0] = k as u8;
        s.aTxSafeData[1] = k as u8;
        unsafe {
            let (rx, len) = if slave_sent {
                (sf.as_ptr(), n)
            } else {
                (std::ptr::null(), 0)
            };
            f(&mut m, t, rx, len, mf.as_mut_ptr(), 67, &mut mlen);
            f(&mut s, t, mf.as_ptr(), n, sf.as_mut_ptr(), 67, &mut slen);
        }
        slave_sent |= slen > 0;
    }
    assert_eq!((m.nState, s.nState), (104, 104), "DATA");
    assert_eq!((m.bDataValid, s.bDataValid), (1, 1));
    let mut per_call = Vec::with_capacity(batches);
    for _ in 0..batches {
        let start = Instant::now();
        for _ in 0..PAIRS_PER_BATCH {
            t = t.wrapping_add(1);
            unsafe {
                black_box(f(
                    black_box(&mut m),
                    t,
                    sf.as_ptr(),
                    n,
                    mf.as_mut_ptr(),
                    67,
                    &mut mlen,
                ));
                black_box(f(
                    black_box(&mut s),
                    t,
                    mf.as_ptr(),
                    n,
                    sf.as_mut_ptr(),
                    67,
                    &mut slen,
                ));
            }
        }
        per_call.push(start.elapsed().as_nanos() as f64 / f64::from(2 * PAIRS_PER_BATCH));
    }
    assert_eq!(
        (m.nState, s.nState, mlen, slen),
        (104, 104, n, n),
        "still DATA"
    );
    assert_eq!((m.bComErr, s.bComErr), (0, 0));
    per_call.sort_by(f64::total_cmp);
    let at = |q: f64| per_call[((per_call.len() - 1) as f64 * q).round() as usize];
    println!(
        "FSoE connection cycle, DATA, {DATA} bytes SafeData ({n}-byte frames), decode + state machine + encode via sl_fsoe_cycle:"
    );
    println!(
        "  median {:.1} ns, p99 {:.1} ns per call (target <= {TARGET_NS} ns median: {})",
        at(0.5),
        at(0.99),
        if at(0.5) <= TARGET_NS {
            "met"
        } else {
            "MISSED"
        }
    );
    println!(
        "  SL_FSOE_CONN {} bytes, of which private state {} bytes ({} batches of {} calls)",
        size_of::<SL_FSOE_CONN>(),
        size_of::<SL_FSOE_CONN_PRIVATE>(),
        batches,
        2 * PAIRS_PER_BATCH
    );
}
