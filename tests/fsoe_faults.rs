//! FSoE fault injection (ABI-2 §13.5, fsoe.md §15 item 4): a bit flipped at every position
//! of every CRC-protected frame of a connection, a frame lost / duplicated / replayed /
//! from an old session / delayed past the watchdog, wrong ConnID, wrong slave address,
//! wrong watchdog or application parameters, a peer reset in DATA, a peer that stops
//! sending — each with its reaction; and the property that a receiver never presents
//! SafeData the sender did not send (sent data or zeros) under random faults.

mod common;

use safelogic::fsoe::conn::{cycle, init};
use safelogic::fsoe::frame::encode;
use safelogic::fsoe::*;
use safelogic::*;
use std::collections::HashSet;

/// [`common::fsoe::conn`] running, with 3 bytes of application parameters.
fn conn(role: u16, tx: u16, rx: u16, seed: u16) -> SL_FSOE_CONN {
    let mut c = SL_FSOE_CONN {
        nAppParaLen: 3,
        bRun: 1,
        ..common::fsoe::conn(role, tx, rx, seed)
    };
    c.aAppPara[..3].copy_from_slice(&[0x11, 0x22, 0x33]);
    c
}

fn new(c: SL_FSOE_CONN) -> SL_FSOE_CONN {
    let mut c = c;
    assert_eq!(init(&mut c), Status::Ok);
    c
}

/// One cycle; the frame produced, if any.
fn step(c: &mut SL_FSOE_CONN, now: u32, rx: Option<&[u8]>) -> Option<Vec<u8>> {
    let mut tx = [0u8; 67];
    let (st, len) = cycle(c, now, rx, &mut tx);
    assert_eq!(st, Status::Ok);
    assert!(c.bDataValid == 1 || c.aRxSafeData == [0; 32]);
    (len > 0).then(|| tx[..len].to_vec())
}

fn pair(tx: u16, rx: u16) -> (SL_FSOE_CONN, SL_FSOE_CONN) {
    (
        new(conn(SL_FSOE_ROLE_MASTER, tx, rx, 0x3412)),
        new(conn(SL_FSOE_ROLE_SLAVE, rx, tx, 0x5678)),
    )
}

/// Ping-pong: frame k is master→slave for even k, slave→master for odd k. Delivers the
/// first `count` frames of a clean run (data changing every frame) and returns them.
fn ping_pong(m: &mut SL_FSOE_CONN, s: &mut SL_FSOE_CONN, count: usize) -> Vec<Vec<u8>> {
    let mut frames = vec![step(m, 0, None).unwrap()];
    for k in 1..count {
        let t = k as u32;
        m.aTxSafeData = [k as u8; 32];
        s.aTxSafeData = [0x80 | k as u8; 32];
        let f = if k % 2 == 1 {
            step(s, t, Some(&frames[k - 1]))
        } else {
            step(m, t, Some(&frames[k - 1]))
        };
        frames.push(f.unwrap_or_else(|| panic!("no frame {k}")));
    }
    frames
}

const ERRORS: [u8; 7] = [1, 2, 3, 4, 6, 7, 9];

#[test]
fn every_bit_flip_of_every_frame_is_rejected() {
    let mut cases = 0;
    let mut ignored = 0;
    for (tx, rx) in [(4u16, 4u16), (1, 1), (2, 6), (8, 2)] {
        let (mut m, mut s) = pair(tx, rx);
        let clean = ping_pong(&mut m, &mut s, 44);
        assert_eq!((m.nState, s.nState), (104, 104), "{tx}/{rx}");
        // Frames 0 and 1 are Reset frames (not CRC-checked by the receiver, fsoe.md §6).
        for k in 2..clean.len() {
            for bit in 0..clean[k].len() * 8 {
                let (mut m, mut s) = pair(tx, rx);
                let mut frames = vec![step(&mut m, 0, None).unwrap()];
                for j in 1..k {
                    m.aTxSafeData = [j as u8; 32];
                    s.aTxSafeData = [0x80 | j as u8; 32];
                    let f = if j % 2 == 1 {
                        step(&mut s, j as u32, Some(&frames[j - 1]))
                    } else {
                        step(&mut m, j as u32, Some(&frames[j - 1]))
                    };
                    frames.push(f.unwrap());
                }
                assert_eq!(frames[k - 1], clean[k - 1]);
                let mut bad = clean[k].clone();
                bad[bit / 8] ^= 1 << (bit % 8);
                let receiver = if k % 2 == 1 { &mut m } else { &mut s };
                let before = receiver.nState;
                let out = step(receiver, k as u32, Some(&bad));
                cases += 1;
                assert_eq!(receiver.bDataValid, 0, "{tx}/{rx} frame {k} bit {bit}");
                match out {
                    Some(f) => {
                        assert_eq!(f[0], SL_FSOE_CMD_RESET, "{tx}/{rx} frame {k} bit {bit}");
                        assert!(ERRORS.contains(&f[1]), "code {} frame {k} bit {bit}", f[1]);
                        assert_eq!((receiver.nState, receiver.bComErr), (100, 1));
                    }
                    None => {
                        // Only the master's SESSION_STAY2 ignores a bad frame.
                        assert_eq!((before, receiver.nState), (101, 101), "frame {k} bit {bit}");
                        assert_eq!(receiver.nRole, SL_FSOE_ROLE_MASTER);
                        ignored += 1;
                    }
                }
            }
        }
    }
    assert!(cases > 5000, "{cases}");
    assert!(ignored > 0);
}

/// Establishes DATA on a cyclic bus; returns the time.
fn bus(m: &mut SL_FSOE_CONN, s: &mut SL_FSOE_CONN, mb: &mut Vec<u8>, sb: &mut Vec<u8>, t: u32) {
    if let Some(f) = step(m, t, (!sb.is_empty()).then_some(&sb[..])) {
        *mb = f;
    }
    if let Some(f) = step(s, t, (!mb.is_empty()).then_some(&mb[..])) {
        *sb = f;
    }
}

fn connect(m: &mut SL_FSOE_CONN, s: &mut SL_FSOE_CONN, mb: &mut Vec<u8>, sb: &mut Vec<u8>) -> u32 {
    for t in 0..200 {
        bus(m, s, mb, sb, t);
        if m.nState == 104 && s.nState == 104 {
            return t + 1;
        }
    }
    panic!(
        "no DATA: {} {} codes {} {}",
        m.nState, s.nState, m.nResetCode, s.nResetCode
    );
}

/// A 4/4-byte pair connected to DATA: (master, slave, their last frames, the time reached).
fn connected() -> (SL_FSOE_CONN, SL_FSOE_CONN, Vec<u8>, Vec<u8>, u32) {
    let (mut m, mut s) = pair(4, 4);
    let (mut mb, mut sb) = (Vec::new(), Vec::new());
    let t = connect(&mut m, &mut s, &mut mb, &mut sb);
    (m, s, mb, sb, t)
}

#[test]
fn a_lost_frame_ends_in_the_watchdog_at_exactly_its_time() {
    let (mut m, mut s, _, sb, t) = connected();
    // The master's next frame is produced at t and lost; the slave sent its last at t - 1.
    let f = step(&mut m, t, Some(&sb));
    assert!(f.is_some());
    assert!(step(&mut s, t + 98, None).is_none());
    assert_eq!(s.nState, 104);
    let r = step(&mut s, t + 99, None).unwrap();
    assert_eq!((r[0], r[1], s.nState, s.bComErr), (0x2A, 5, 100, 1));
    assert_eq!(s.nDiag & 0x1F, 5 | SL_FSOE_DIAG_SLAVE_ERROR);
    assert!(step(&mut m, t + 99, None).is_none());
    let r = step(&mut m, t + 100, None).unwrap();
    assert_eq!((r[1], m.nState, m.bComErr), (5, 100, 1));
}

#[test]
fn a_duplicated_frame_is_no_event() {
    let (mut m, mut s, _, sb, t) = connected();
    let f = step(&mut m, t, Some(&sb)).unwrap();
    let a = step(&mut s, t, Some(&f)).unwrap();
    let snapshot = s;
    assert!(step(&mut s, t + 1, Some(&f)).is_none());
    assert_eq!(
        (s.nState, s.bComErr, s.aRxSafeData),
        (104, 0, snapshot.aRxSafeData)
    );
    assert!(step(&mut m, t + 1, Some(&a)).is_some());
}

#[test]
fn a_replayed_frame_is_refused() {
    let (mut m, mut s, mut mb, mut sb, mut t) = connected();
    let mut history = Vec::new();
    for _ in 0..5 {
        s.aTxSafeData[0] = t as u8;
        bus(&mut m, &mut s, &mut mb, &mut sb, t);
        history.push(sb.clone());
        t += 1;
    }
    // An older frame of the slave, from the same session.
    let f = step(&mut m, t, Some(&history[1])).unwrap();
    assert_eq!((f[0], f[1], m.nState, m.bComErr), (0x2A, 4, 100, 1));
}

#[test]
fn a_frame_of_an_old_session_is_refused() {
    let (mut m, mut s, mut mb, mut sb, t) = connected();
    for dt in 0..3 {
        bus(&mut m, &mut s, &mut mb, &mut sb, t + dt);
    }
    let old: Vec<Vec<u8>> = vec![sb.clone()];
    // A new session with other session IDs.
    let (mut m, mut s) = (
        new(conn(SL_FSOE_ROLE_MASTER, 4, 4, 0x1111)),
        new(conn(SL_FSOE_ROLE_SLAVE, 4, 4, 0x2222)),
    );
    let (mut mb, mut sb) = (Vec::new(), Vec::new());
    let mut t = connect(&mut m, &mut s, &mut mb, &mut sb);
    for _ in 0..3 {
        bus(&mut m, &mut s, &mut mb, &mut sb, t);
        t += 1;
    }
    let f = step(&mut m, t, Some(&old[0])).unwrap();
    assert_eq!((f[1], m.nState), (4, 100));
}

#[test]
fn a_frame_delayed_past_the_watchdog_is_not_processed() {
    let (mut m, mut s, _, sb, t) = connected();
    let f = step(&mut m, t, Some(&sb)).unwrap();
    let a = step(&mut s, t, Some(&f)).unwrap();
    let r = step(&mut m, t + 100, Some(&a)).unwrap();
    assert_eq!((r[1], m.nState, m.bDataValid), (5, 100, 0));
}

/// Runs the bus until the slave sends a Reset with an error code; returns (code, master code).
fn handshake_error(mc: SL_FSOE_CONN, sc: SL_FSOE_CONN) -> (u8, u8, u16, u16) {
    let (mut m, mut s) = (new(mc), new(sc));
    let (mut mb, mut sb) = (Vec::new(), Vec::new());
    for t in 0..50 {
        bus(&mut m, &mut s, &mut mb, &mut sb, t);
        assert_ne!(s.nState, 104, "the slave must not reach DATA");
        if s.bComErr == 1 {
            bus(&mut m, &mut s, &mut mb, &mut sb, t + 1);
            return (s.nResetCode, m.nResetCode, s.nDiag, m.nDiag);
        }
    }
    panic!("no error");
}

#[test]
fn wrong_conn_id_address_watchdog_and_application_parameters() {
    let m = conn(SL_FSOE_ROLE_MASTER, 4, 4, 1);
    let s = conn(SL_FSOE_ROLE_SLAVE, 4, 4, 2);
    type Case = (fn(&mut SL_FSOE_CONN), u8);
    let cases: [Case; 5] = [
        // A slave pinned to another Connection ID (without the pin it takes the master's).
        (
            |c| {
                c.nConnectionId = 8;
                c.dwOptions = SL_FSOE_OPT_PIN_CONNID;
            },
            3,
        ),
        (|c| c.nFsoeAddress = 4, 6),
        (|c| c.tWatchdogTime = 200, 9),
        (|c| c.nAppParaLen = 2, 10),
        (|c| c.aAppPara[2] = 0x34, 11),
    ];
    for (f, code) in cases {
        let mut sc = s;
        f(&mut sc);
        let (scode, mcode, sdiag, mdiag) = handshake_error(m, sc);
        assert_eq!((scode, mcode), (code, code), "code {code}");
        let want = u16::from(code) | SL_FSOE_DIAG_SLAVE_ERROR | SL_FSOE_DIAG_STARTUP;
        assert_eq!((sdiag, mdiag), (want, want), "code {code}");
    }
    // The same parameters on the master's side instead of the slave's.
    let mut mc = m;
    mc.nFsoeAddress = 9;
    assert_eq!(handshake_error(mc, s).0, 6);
}

#[test]
fn wrong_conn_id_in_data_and_comm_para_len() {
    let (mut m, _, _, sb, t) = connected();
    // A Data frame whose ConnID field reads 9: ConnID is checked before the CRC (mm::etg
    // order), so the reaction is Reset 3, not 4.
    let mut bad = sb.clone();
    let n = bad.len();
    bad[n - 2] = 9;
    let f = step(&mut m, t, Some(&bad)).unwrap();
    assert_eq!((f[1], m.nState), (3, 100));
    // CommParaLen 4 instead of 2: a master that sends it gets Reset(8).
    let mut sl = new(conn(SL_FSOE_ROLE_SLAVE, 4, 4, 2));
    let mut seq = 1u16;
    let mut out = [0u8; 67];
    let mut send = |cmd: u8, d: [u8; 4], conn: u16, recv: u16, seq: &mut u16| {
        let (len, crc) = encode(&mut out, cmd, &d, conn, recv, seq, 0, cmd != 0x4E).unwrap();
        *seq += 1;
        (out[..len].to_vec(), crc)
    };
    let mut t = 0;
    let mut feed = |sl: &mut SL_FSOE_CONN, f: Vec<u8>| {
        t += 1;
        step(sl, t, Some(&f))
    };
    let (f, c) = send(0x4E, [1, 2, 0, 0], 0, 0, &mut seq);
    let a = feed(&mut sl, f).unwrap();
    let mut last = u16::from_le_bytes([a[3], a[4]]);
    let _ = c;
    let steps: [(u8, [u8; 4]); 4] = [
        (0x64, [7, 0, 3, 0]),
        (0x52, [4, 0, 100, 0]),
        (0x52, [3, 0, 0, 0]),
        (0x52, [0, 0, 0, 0]),
    ];
    for (cmd, d) in steps {
        let (f, _) = send(cmd, d, 7, last, &mut seq);
        let a = feed(&mut sl, f).unwrap();
        assert_eq!(a[0], cmd, "echo");
        last = u16::from_le_bytes([a[3], a[4]]);
    }
    let (f, _) = send(0x08, [0; 4], 7, last, &mut seq);
    let a = feed(&mut sl, f).unwrap();
    assert_eq!((a[0], a[1], sl.nState), (0x2A, 8, 100));
}

#[test]
fn peer_reset_in_data_and_a_peer_that_stops_sending() {
    // The slave is re-initialised in DATA: the master's next frame is unexpected in its
    // Reset state (Reset 1), the master latches the error and reconnects.
    let (mut m, _, mut mb, mut sb, t) = connected();
    let mut s = new(conn(SL_FSOE_ROLE_SLAVE, 4, 4, 0x9999));
    sb.clear();
    for dt in 0..3 {
        bus(&mut m, &mut s, &mut mb, &mut sb, t + dt);
    }
    assert_eq!(m.nResetCode, 1);
    assert_eq!(m.bComErr, 1);
    connect(&mut m, &mut s, &mut mb, &mut sb);
    // The master stops sending: the slave's watchdog.
    let (mut m, mut s) = pair(2, 2);
    let (mut mb, mut sb) = (Vec::new(), Vec::new());
    let t = connect(&mut m, &mut s, &mut mb, &mut sb);
    for dt in 0..99 {
        assert!(step(&mut s, t + dt, Some(&mb)).is_none());
    }
    let r = step(&mut s, t + 99, Some(&mb)).unwrap();
    assert_eq!((r[1], s.nState, s.bComErr), (5, 100, 1));
}

/// The payload of a ProcessData frame.
fn payload(f: &[u8], n: usize) -> Option<Vec<u8>> {
    if f[0] != SL_FSOE_CMD_PROCESSDATA {
        return None;
    }
    if n == 1 {
        return Some(vec![f[1]]);
    }
    Some(
        (0..n / 2)
            .flat_map(|k| [f[1 + 4 * k], f[2 + 4 * k]])
            .collect(),
    )
}

/// Random faults on a cyclic bus: the received SafeData is always zeros or exactly a value
/// the sender put into a ProcessData frame (10,000 sequences of 120 cycles).
#[test]
fn the_receiver_never_presents_data_the_sender_did_not_send() {
    let mut x = 0x9E37_79B9_7F4A_7C15u64;
    let mut rnd = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x
    };
    let lens = [1u16, 2, 4, 8];
    let mut valid_seen = 0u64;
    for seqno in 0..10_000 {
        let r = rnd();
        let (tx, rx) = (lens[r as usize % 4], lens[(r >> 8) as usize % 4]);
        let (mut m, mut s) = (
            new(conn(SL_FSOE_ROLE_MASTER, tx, rx, (r >> 16) as u16)),
            new(conn(SL_FSOE_ROLE_SLAVE, rx, tx, (r >> 32) as u16)),
        );
        let (mut mb, mut sb) = (Vec::<u8>::new(), Vec::<u8>::new());
        let mut m_sent: HashSet<Vec<u8>> = HashSet::new();
        let mut s_sent: HashSet<Vec<u8>> = HashSet::new();
        let mut hist_m: Vec<Vec<u8>> = Vec::new();
        let mut hist_s: Vec<Vec<u8>> = Vec::new();
        let mut t = 0u32;
        for _ in 0..120 {
            let r = rnd();
            for i in 0..32 {
                m.aTxSafeData[i] = (r >> (i % 8)) as u8 & 3;
                s.aTxSafeData[i] = (r >> (i % 8 + 8)) as u8 & 3;
            }
            m.bErrAck = ((r >> 20) & 1) as u8;
            s.bErrAck = ((r >> 21) & 1) as u8;
            t += 1 + if r >> 60 == 0 { 150 } else { 0 };
            // Fault on the slave's frame as the master reads it.
            let fault = (r >> 24) % 16;
            let mut rxm = sb.clone();
            if !rxm.is_empty() {
                match fault {
                    0 => rxm.clear(),
                    1 => {
                        let b = (r >> 32) as usize % (rxm.len() * 8);
                        rxm[b / 8] ^= 1 << (b % 8);
                    }
                    2 if !hist_s.is_empty() => {
                        rxm = hist_s[(r >> 40) as usize % hist_s.len()].clone()
                    }
                    _ => {}
                }
            }
            if let Some(f) = step(&mut m, t, (!rxm.is_empty()).then_some(&rxm[..])) {
                if let Some(p) = payload(&f, tx as usize) {
                    m_sent.insert(p);
                }
                mb = f;
            }
            let fault = (r >> 28) % 16;
            let mut rxs = mb.clone();
            match fault {
                0 => rxs.clear(),
                1 => {
                    let b = (r >> 44) as usize % (rxs.len() * 8);
                    rxs[b / 8] ^= 1 << (b % 8);
                }
                2 if !hist_m.is_empty() => rxs = hist_m[(r >> 50) as usize % hist_m.len()].clone(),
                _ => {}
            }
            if let Some(f) = step(&mut s, t, (!rxs.is_empty()).then_some(&rxs[..])) {
                if let Some(p) = payload(&f, rx as usize) {
                    s_sent.insert(p);
                }
                sb = f;
            }
            hist_m.push(mb.clone());
            if !sb.is_empty() {
                hist_s.push(sb.clone());
            }
            for (c, sent, n) in [(&m, &s_sent, rx), (&s, &m_sent, tx)] {
                let n = usize::from(n);
                if c.bDataValid == 1 {
                    valid_seen += 1;
                    assert!(
                        sent.contains(&c.aRxSafeData[..n].to_vec()),
                        "sequence {seqno}"
                    );
                    assert!(c.aRxSafeData[n..].iter().all(|&b| b == 0));
                } else {
                    assert_eq!(c.aRxSafeData, [0; 32], "sequence {seqno}");
                }
            }
        }
    }
    assert!(valid_seen > 10_000, "{valid_seen}");
}

#[test]
fn unknown_and_unexpected_commands() {
    let (mut m, _, _, sb, t) = connected();
    // Unknown command 0x99 → Reset 2 (checked before anything else).
    let mut bad = sb.clone();
    bad[0] = 0x99;
    let f = step(&mut m, t, Some(&bad)).unwrap();
    assert_eq!((f[1], m.nState, m.bComErr), (2, 100, 1));
    // A known command that DATA does not expect (Session, CRC irrelevant) → Reset 1.
    let (_, mut s, mb, _, t) = connected();
    let mut bad = mb.clone();
    bad[0] = SL_FSOE_CMD_CONNECTION;
    let f = step(&mut s, t, Some(&bad)).unwrap();
    assert_eq!((f[1], s.nState, s.bComErr), (1, 100, 1));
    assert_eq!(s.nDiag & 0x1F, 1 | SL_FSOE_DIAG_SLAVE_ERROR);
}
