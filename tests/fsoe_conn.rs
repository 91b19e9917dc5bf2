//! FSoE master and slave of this library talking to each other (ABI-2 §13.2–§13.5,
//! fsoe.md §5–§10): the 13-frame trace of fsoe.md §12.2 byte for byte, every SafeData
//! length, the watchdog, FailSafeData, session IDs, acknowledgement, shutdown, diag byte.

mod common;

use safelogic::fsoe::conn::{cycle, init};
use safelogic::fsoe::*;
use safelogic::*;

pub struct Node {
    pub c: SL_FSOE_CONN,
    /// The node's transmit buffer (a cyclic bus keeps re-sending it).
    pub buf: Vec<u8>,
    /// Frames produced, in order.
    pub sent: Vec<Vec<u8>>,
}

use common::fsoe::conn;

impl Node {
    pub fn new(c: SL_FSOE_CONN) -> Node {
        let mut c = c;
        assert_eq!(init(&mut c), Status::Ok);
        assert_eq!(c.nState, SL_FSOE_STATE_RESET);
        Node {
            c,
            buf: Vec::new(),
            sent: Vec::new(),
        }
    }
    /// One cycle with `rx`; returns the new frame if one was produced.
    pub fn step(&mut self, now: u32, rx: Option<&[u8]>) -> Option<Vec<u8>> {
        let mut tx = [0u8; 67];
        let (st, len) = cycle(&mut self.c, now, rx, &mut tx);
        assert_eq!(st, Status::Ok);
        check_invariants(&self.c);
        if len > 0 {
            self.buf = tx[..len].to_vec();
            self.sent.push(self.buf.clone());
            Some(self.buf.clone())
        } else {
            None
        }
    }
}

/// Outputs consistent with the state (ABI-2 §13.1).
pub fn check_invariants(c: &SL_FSOE_CONN) {
    assert!((100..=106).contains(&c.nState), "state {}", c.nState);
    common::fsoe::assert_bool_outputs(c);
    if c.bDataValid == 0 {
        assert_eq!(c.aRxSafeData, [0; 32]);
    } else {
        assert_eq!(c.nState, SL_FSOE_STATE_DATA);
        assert_eq!(c.bComErr, 0);
    }
    assert_eq!(c.bComStartup == 1, c.nState <= 103 && c.bShutdown == 0);
    assert_eq!(c.nDiag & SL_FSOE_DIAG_STARTUP != 0, c.bComStartup == 1);
}

/// One bus cycle: master, then slave, each reading the other's buffer.
pub fn bus(m: &mut Node, s: &mut Node, now: u32) {
    let sb = s.buf.clone();
    m.step(now, (!sb.is_empty()).then_some(&sb[..]));
    let mb = m.buf.clone();
    s.step(now, (!mb.is_empty()).then_some(&mb[..]));
}

fn hex(s: &str) -> Vec<u8> {
    s.split_whitespace()
        .map(|b| u8::from_str_radix(b, 16).unwrap())
        .collect()
}

#[test]
fn trace_of_fsoe_md_12_2_byte_for_byte() {
    let want = [
        "2A 00 00 C4 2D 00 00 B9 14 00 00",
        "2A 00 00 C4 2D 00 00 B9 14 00 00",
        "4E 12 34 07 4D 00 00 43 4E 00 00",
        "4E 78 56 D3 B9 00 00 38 73 00 00",
        "64 07 00 9F 29 03 00 F0 07 07 00",
        "64 07 00 5B 5D 03 00 03 A3 07 00",
        "52 02 00 A1 A5 64 00 D8 52 07 00",
        "52 02 00 97 D1 64 00 8E DA 07 00",
        "52 00 00 39 A6 00 00 BB 5B 07 00",
        "52 00 00 AD 00 00 00 98 A4 07 00",
        "08 00 00 A6 00 00 00 4E 1A 07 00",
        "36 01 02 C1 8B 03 04 EB C3 07 00",
        "36 AA 55 A0 38 00 FF 07 36 07 00",
    ];
    let (mut m, mut s) = pair(4, 4, 0x3412, 0x5678);
    s.c.bRun = 1;
    s.c.aTxSafeData[..4].copy_from_slice(&[1, 2, 3, 4]);
    let mut frames = Vec::new();
    let mut last = m.step(0, None).unwrap();
    assert_eq!(m.c.nDiag & 0x0F, 15, "slave not yet started");
    frames.push(last.clone());
    let states = [
        (101, 100),
        (102, 101),
        (103, 102),
        (103, 103),
        (104, 103),
        (104, 104),
    ];
    for (i, (ms, ss)) in states.iter().enumerate() {
        last = s.step(1 + i as u32, Some(&last)).unwrap();
        frames.push(last.clone());
        if i == 5 {
            m.c.bRun = 1;
            m.c.aTxSafeData[..4].copy_from_slice(&[0xAA, 0x55, 0, 0xFF]);
        }
        last = m.step(1 + i as u32, Some(&last)).unwrap();
        frames.push(last.clone());
        assert_eq!((m.c.nState, s.c.nState), (*ms, *ss), "after pair {i}");
    }
    for (i, (f, w)) in frames.iter().zip(want).enumerate() {
        assert_eq!(f, &hex(w), "frame {}", i + 1);
    }
    assert_eq!(frames.len(), 13);
    // Master: DATA, valid inputs 01 02 03 04; slave: outputs after the 13th frame.
    assert_eq!(
        (m.c.nState, m.c.bDataValid, m.c.bComErr, m.c.bComStartup),
        (104, 1, 0, 0)
    );
    assert_eq!(&m.c.aRxSafeData[..4], &[1, 2, 3, 4]);
    assert_eq!(
        s.c.bPeerFailSafe, 1,
        "the master's first Data frame was FailSafeData"
    );
    assert_eq!(s.c.nDiag, SL_FSOE_DIAG_MASTER_FAILSAFE);
    s.step(10, Some(&frames[12]));
    assert_eq!((s.c.nState, s.c.bDataValid, s.c.bPeerFailSafe), (104, 1, 0));
    assert_eq!(&s.c.aRxSafeData[..4], &[0xAA, 0x55, 0, 0xFF]);
    assert_eq!(s.c.nDiag, 0);
}

/// Runs the bus until both are in DATA; returns the time.
/// A master sending `tx` and receiving `rx` bytes with session seed `m_seed`, and its slave
/// (the mirror sizes) with `s_seed`.
fn pair(tx: u16, rx: u16, m_seed: u16, s_seed: u16) -> (Node, Node) {
    (
        Node::new(conn(SL_FSOE_ROLE_MASTER, tx, rx, m_seed)),
        Node::new(conn(SL_FSOE_ROLE_SLAVE, rx, tx, s_seed)),
    )
}

pub fn connect(m: &mut Node, s: &mut Node, mut t: u32) -> u32 {
    for _ in 0..400 {
        bus(m, s, t);
        t += 1;
        if m.c.nState == 104 && s.c.nState == 104 {
            return t;
        }
    }
    panic!("no DATA: master {} slave {}", m.c.nState, s.c.nState);
}

#[test]
fn every_length_pair_and_app_para_length_reaches_data_and_carries_data() {
    let lens = [1u16, 2, 4, 6, 10, 16, 32];
    let mut x = 0x1234_5678u32;
    for &a in &lens {
        for &b in &lens {
            for app in [0u16, 1, 7, 64] {
                let mut mc = conn(SL_FSOE_ROLE_MASTER, a, b, (a * 100 + b) ^ app);
                let mut sc = conn(SL_FSOE_ROLE_SLAVE, b, a, 0xBEEF ^ app);
                mc.nAppParaLen = app;
                sc.nAppParaLen = app;
                for i in 0..64 {
                    mc.aAppPara[i] = i as u8 * 3;
                    sc.aAppPara[i] = i as u8 * 3;
                }
                let mut m = Node::new(mc);
                let mut s = Node::new(sc);
                m.c.bRun = 1;
                s.c.bRun = 1;
                let mut t = connect(&mut m, &mut s, 0);
                for _ in 0..6 {
                    for i in 0..32 {
                        x = x.wrapping_mul(1_103_515_245).wrapping_add(12_345);
                        m.c.aTxSafeData[i] = (x >> 16) as u8;
                        s.c.aTxSafeData[i] = (x >> 8) as u8;
                    }
                    for _ in 0..3 {
                        bus(&mut m, &mut s, t);
                        t += 1;
                    }
                    assert_eq!((m.c.bDataValid, s.c.bDataValid), (1, 1), "{a} {b} {app}");
                    assert_eq!(
                        &s.c.aRxSafeData[..a as usize],
                        &m.c.aTxSafeData[..a as usize]
                    );
                    assert_eq!(
                        &m.c.aRxSafeData[..b as usize],
                        &s.c.aTxSafeData[..b as usize]
                    );
                    assert!(s.c.aRxSafeData[a as usize..].iter().all(|&v| v == 0));
                }
                assert_eq!((m.c.bComErr, s.c.bComErr), (0, 0));
            }
        }
    }
}

#[test]
fn session_ids_come_from_the_seed() {
    let (mut m, mut s) = pair(2, 2, 0xA1B2, 0xC3D4);
    m.c.nSessionIdSeed = 0xA1B2;
    connect(&mut m, &mut s, 0);
    assert_eq!(&m.sent[1][..3], &[0x4E, 0xB2, 0xA1]);
    assert_eq!(&s.sent[1][..3], &[0x4E, 0xD4, 0xC3]);
}

#[test]
fn a_missing_slave_is_start_up_not_an_error() {
    let mut m = Node::new(conn(SL_FSOE_ROLE_MASTER, 2, 2, 1));
    for t in 0..1000 {
        m.step(t, None);
        assert_eq!((m.c.bComErr, m.c.bComStartup), (0, 1), "t {t}");
        assert_eq!(m.c.nDiag & 0x0F, 15);
    }
}

#[test]
fn watchdog_expiry_resets_with_code_5_at_exactly_the_watchdog_time() {
    let (mut m, mut s) = pair(2, 2, 1, 2);
    m.c.bRun = 1;
    s.c.bRun = 1;
    let t = connect(&mut m, &mut s, 0);
    bus(&mut m, &mut s, t);
    // The slave stops answering: the master's last frame was sent at t.
    let sent_at = t;
    assert!(m.step(sent_at + 99, None).is_none());
    assert_eq!(m.c.nState, 104);
    let f = m.step(sent_at + 100, None).unwrap();
    assert_eq!(f, vec![0x2A, 5, 0, 0x25, 0xAE, 0, 0]);
    assert_eq!((m.c.nState, m.c.nResetCode, m.c.bComErr), (100, 5, 1));
    assert_eq!(m.c.nDiag & 0x1F, 5, "master detected: bit 4 clear");
    // The slave receives Reset(5): it latches the error and acknowledges with Reset(0).
    // (Delivered before the slave's own watchdog would expire.)
    let ack = s.step(sent_at + 50, Some(&f)).unwrap();
    assert_eq!(ack, vec![0x2A, 0, 0, 0xC4, 0x2D, 0, 0]);
    assert_eq!((s.c.nState, s.c.nResetCode, s.c.bComErr), (100, 5, 1));
    // Reconnect; data stay FailSafeData until acknowledged.
    let mut t = connect(&mut m, &mut s, sent_at + 102);
    for _ in 0..4 {
        bus(&mut m, &mut s, t);
        t += 1;
    }
    assert_eq!((m.c.bComErr, m.c.bDataValid, s.c.bDataValid), (1, 0, 0));
    assert_eq!(s.c.bPeerFailSafe, 1);
    assert_eq!(
        m.c.nDiag & SL_FSOE_DIAG_MASTER_FAILSAFE,
        SL_FSOE_DIAG_MASTER_FAILSAFE
    );
    m.c.bErrAck = 1;
    s.c.bErrAck = 1;
    bus(&mut m, &mut s, t);
    assert_eq!((m.c.bComErr, s.c.bComErr), (0, 0));
    m.c.bErrAck = 0;
    s.c.bErrAck = 0;
    for _ in 0..4 {
        t += 1;
        bus(&mut m, &mut s, t);
    }
    assert_eq!((m.c.bDataValid, s.c.bDataValid), (1, 1));
    assert_eq!((m.c.nDiag, s.c.nDiag), (0, 0));
}

#[test]
fn comerrack_option_needs_comerrack_before_errack() {
    let mut mc = conn(SL_FSOE_ROLE_MASTER, 2, 2, 1);
    mc.dwOptions = SL_FSOE_OPT_COMERRACK;
    let mut m = Node::new(mc);
    let mut s = Node::new(conn(SL_FSOE_ROLE_SLAVE, 2, 2, 2));
    let t = connect(&mut m, &mut s, 0);
    m.step(t + 500, None);
    assert_eq!(m.c.bComErr, 1);
    let mut t = connect(&mut m, &mut s, t + 501);
    m.c.bErrAck = 1;
    bus(&mut m, &mut s, t);
    assert_eq!(m.c.bComErr, 1, "ErrAck alone does not acknowledge");
    m.c.bErrAck = 0;
    m.c.bComErrAck = 1;
    t += 1;
    bus(&mut m, &mut s, t);
    assert_eq!(m.c.bComErr, 1);
    m.c.bErrAck = 1;
    t += 1;
    bus(&mut m, &mut s, t);
    assert_eq!(m.c.bComErr, 0);
}

#[test]
fn errack_outside_data_does_not_acknowledge() {
    let (mut m, mut s) = pair(2, 2, 1, 2);
    let t = connect(&mut m, &mut s, 0);
    m.step(t + 500, None);
    assert_eq!((m.c.bComErr, m.c.nState), (1, 100));
    m.c.bErrAck = 1;
    m.step(t + 501, None);
    assert_eq!(m.c.bComErr, 1);
    m.c.bErrAck = 0;
    // A level held through DATA is no edge either.
    m.c.bErrAck = 1;
    let t = connect(&mut m, &mut s, t + 502);
    bus(&mut m, &mut s, t);
    assert_eq!(m.c.bComErr, 1);
}

#[test]
fn run_false_sends_failsafe_data_and_the_receiver_reads_zeros() {
    let (mut m, mut s) = pair(4, 2, 1, 2);
    m.c.bRun = 1;
    s.c.bRun = 1;
    m.c.aTxSafeData[..4].copy_from_slice(&[9, 8, 7, 6]);
    s.c.aTxSafeData[..2].copy_from_slice(&[5, 4]);
    let mut t = connect(&mut m, &mut s, 0);
    for _ in 0..3 {
        bus(&mut m, &mut s, t);
        t += 1;
    }
    assert_eq!(&s.c.aRxSafeData[..4], &[9, 8, 7, 6]);
    s.c.bRun = 0;
    for _ in 0..3 {
        bus(&mut m, &mut s, t);
        t += 1;
    }
    assert_eq!(s.sent.last().unwrap()[0], SL_FSOE_CMD_FAILSAFEDATA);
    assert_eq!(&s.sent.last().unwrap()[1..3], &[0, 0]);
    assert_eq!((m.c.bDataValid, m.c.bPeerFailSafe), (0, 1));
    assert_eq!(m.c.aRxSafeData, [0; 32]);
    assert_eq!(m.c.nDiag, SL_FSOE_DIAG_SLAVE_FAILSAFE);
    assert_eq!(s.c.nDiag, SL_FSOE_DIAG_SLAVE_FAILSAFE);
    assert_eq!(s.c.bDataValid, 0, "bRun FALSE: aRxSafeData reads 0");
    assert_eq!(s.c.aRxSafeData, [0; 32]);
    assert_eq!((m.c.nState, s.c.nState, m.c.bComErr), (104, 104, 0));
    s.c.bRun = 1;
    for _ in 0..3 {
        bus(&mut m, &mut s, t);
        t += 1;
    }
    assert_eq!((m.c.bDataValid, s.c.bDataValid), (1, 1));
    assert_eq!(&m.c.aRxSafeData[..2], &[5, 4]);
}

#[test]
fn module_fault_option_is_a_communication_error() {
    let mut mc = conn(SL_FSOE_ROLE_MASTER, 2, 2, 1);
    mc.dwOptions = SL_FSOE_OPT_MODULE_ERR_IS_COMERR;
    let mut m = Node::new(mc);
    let mut s = Node::new(conn(SL_FSOE_ROLE_SLAVE, 2, 2, 2));
    let mut t = connect(&mut m, &mut s, 0);
    m.c.bModuleFault = 1;
    bus(&mut m, &mut s, t);
    assert_eq!((m.c.bComErr, m.c.nDiag & 0x0F), (1, 13));
    m.c.bErrAck = 1;
    t += 1;
    bus(&mut m, &mut s, t);
    assert_eq!(m.c.bComErr, 1, "the condition remains");
    m.c.bErrAck = 0;
    m.c.bModuleFault = 0;
    t += 1;
    bus(&mut m, &mut s, t);
    m.c.bErrAck = 1;
    t += 1;
    bus(&mut m, &mut s, t);
    assert_eq!((m.c.bComErr, m.c.nDiag & 0x0F), (0, 0));
    // Without the option the module fault is ignored.
    let mut m2 = Node::new(conn(SL_FSOE_ROLE_MASTER, 2, 2, 1));
    m2.c.bModuleFault = 1;
    m2.step(0, None);
    assert_eq!(m2.c.bComErr, 0);
}

#[test]
fn shutdown_by_the_master_and_by_the_slave() {
    for by_master in [true, false] {
        let (mut m, mut s) = pair(2, 2, 1, 2);
        m.c.bRun = 1;
        s.c.bRun = 1;
        let mut t = connect(&mut m, &mut s, 0);
        if by_master {
            m.c.bShutdownRequest = 1;
        } else {
            s.c.bShutdownRequest = 1;
        }
        for _ in 0..500 {
            bus(&mut m, &mut s, t);
            t += 1;
        }
        let (me, peer) = if by_master { (&m, &s) } else { (&s, &m) };
        assert_eq!(
            (me.c.nState, peer.c.nState),
            (106, 105),
            "by master {by_master}"
        );
        for n in [&m, &s] {
            assert_eq!(
                (n.c.bShutdown, n.c.bComErr, n.c.bComStartup, n.c.bDataValid),
                (1, 0, 0, 0)
            );
        }
        m.c.bShutdownRequest = 0;
        s.c.bShutdownRequest = 0;
        connect(&mut m, &mut s, t);
        for n in [&m, &s] {
            assert_eq!((n.c.bShutdown, n.c.bComErr), (0, 0));
        }
    }
}

#[test]
fn shutdown_request_outside_data_is_ignored() {
    let mut m = Node::new(conn(SL_FSOE_ROLE_MASTER, 2, 2, 1));
    m.c.bShutdownRequest = 1;
    for t in 0..300 {
        m.step(t, None);
        assert_ne!(m.c.nState, 106);
    }
}

#[test]
fn master_reset_in_data_shows_diag_12_on_the_slave() {
    let (mut m, mut s) = pair(2, 2, 1, 2);
    let t = connect(&mut m, &mut s, 0);
    // The master is re-initialised (power cycle): Reset(0).
    let mut m = Node::new(conn(SL_FSOE_ROLE_MASTER, 2, 2, 9));
    let f = m.step(t, None).unwrap();
    s.step(t, Some(&f));
    assert_eq!((s.c.nState, s.c.bComErr, s.c.nDiag & 0x0F), (100, 0, 12));
    connect(&mut m, &mut s, t + 1);
    assert_eq!(s.c.nDiag & 0x0F, 0);
}

#[test]
fn invalid_bool_bytes_read_as_the_abi_says() {
    let (mut m, mut s) = pair(2, 2, 1, 2);
    let t = connect(&mut m, &mut s, 0);
    m.c.bRun = 7;
    let mut tx = [0u8; 67];
    let sb = s.buf.clone();
    let (st, _) = cycle(&mut m.c, t, Some(&sb), &mut tx);
    assert_eq!(st, Status::InvalidBool);
    assert_eq!(m.c.bDataValid, 0);
}

#[test]
fn init_refuses_invalid_parameters_and_cycle_checks_lengths() {
    let good = conn(SL_FSOE_ROLE_MASTER, 2, 2, 1);
    let bad: [fn(&mut SL_FSOE_CONN); 8] = [
        |c| c.nConnectionId = 0,
        |c| c.nRole = 3,
        |c| c.nTxDataLen = 3,
        |c| c.nRxDataLen = 34,
        |c| c.nAppParaLen = 65,
        |c| c.tWatchdogTime = 0,
        |c| c.tWatchdogTime = 65_536,
        |c| c.dwOptions = 8,
    ];
    for f in bad {
        let mut c = good;
        f(&mut c);
        assert_eq!(init(&mut c), Status::Config);
        let mut tx = [0u8; 67];
        assert_eq!(cycle(&mut c, 0, None, &mut tx), (Status::Config, 0));
        assert_eq!(tx, [0; 67]);
    }
    let mut c = good;
    assert_eq!(init(&mut c), Status::Ok);
    let mut tx = [0u8; 6];
    assert_eq!(cycle(&mut c, 0, None, &mut tx), (Status::Length, 0));
    assert_eq!(tx, [0; 6]);
    let mut tx = [0u8; 7];
    assert_eq!(
        cycle(&mut c, 0, Some(&[0; 8]), &mut tx),
        (Status::Length, 7)
    );
    // A corrupted private state is refused.
    c.stPrivate.nStateInv ^= 1;
    assert_eq!(cycle(&mut c, 1, None, &mut tx).0, Status::Corrupt);
    assert_eq!(c.bComErr, 1);
}

/// `sl_state_str` names a connection's states (manual §3.2.1.3) by its member tag, and
/// nothing else.
#[test]
fn state_names_of_a_connection() {
    let name = |s: u8| {
        let p = safelogic::ffi::sl_state_str(SL_TYPE_FSOE_CONN, s);
        unsafe { std::ffi::CStr::from_ptr(p) }
            .to_str()
            .unwrap()
            .to_string()
    };
    let want = [
        "RESET",
        "SESSION",
        "CONNECTION",
        "PARAMETER",
        "DATA",
        "SHUTDOWN",
        "SHUTDOWN-DEACTIVE",
    ];
    for (k, w) in want.iter().enumerate() {
        assert_eq!(name(SL_FSOE_STATE_RESET + k as u8), *w);
    }
    for s in (0..=u8::MAX).filter(|s| !(100..=106).contains(s)) {
        assert_eq!(name(s), "?", "state {s}");
    }
    assert_eq!(safelogic::group::state_name(SL_TYPE_FSOE_CONN, 104), "DATA");
}

/// fsoe.md §7/§11: the slave takes the non-zero Connection ID the master sends (checking
/// the FSoE address as before). A master that assigns a new ID at each (re)initialisation,
/// as a configurator may, reaches DATA after every restart; the slave's own
/// `nConnectionId` does not have to match (semantics FS11).
#[test]
fn slave_takes_the_connection_id_the_master_assigns_at_each_start() {
    let mut sc = conn(SL_FSOE_ROLE_SLAVE, 2, 2, 2);
    sc.nConnectionId = 500;
    let mut s = Node::new(sc);
    s.c.bRun = 1;
    let mut t = 0;
    for (k, id) in [7u16, 8, 0x1234, 65_535, 1].into_iter().enumerate() {
        let mut mc = conn(SL_FSOE_ROLE_MASTER, 2, 2, 40 + k as u16);
        mc.nConnectionId = id;
        let mut m = Node::new(mc);
        m.c.bRun = 1;
        t = connect(&mut m, &mut s, t);
        for _ in 0..3 {
            bus(&mut m, &mut s, t);
            t += 1;
        }
        assert_eq!((m.c.bDataValid, s.c.bDataValid), (1, 1), "ID {id}");
        // The slave's frames carry the master's ID (last two octets, little endian).
        let n = s.buf.len();
        assert_eq!(u16::from_le_bytes([s.buf[n - 2], s.buf[n - 1]]), id);
        assert_eq!(s.c.nConnectionId, 500, "the parameter is not written");
        assert_eq!((m.c.bComErr, s.c.bComErr), (0, 0), "ID {id}");
    }
    // The FSoE address is still checked: a master for another address is refused (6).
    let mut mc = conn(SL_FSOE_ROLE_MASTER, 2, 2, 99);
    mc.nConnectionId = 42;
    mc.nFsoeAddress = 4;
    let mut m = Node::new(mc);
    let mut code = 0;
    for _ in 0..50 {
        bus(&mut m, &mut s, t);
        t += 1;
        assert_ne!(s.c.nState, SL_FSOE_STATE_DATA);
        if s.c.nResetCode != 0 {
            code = s.c.nResetCode;
            break;
        }
    }
    assert_eq!(code, SL_FSOE_RESET_INVALID_ADDRESS);
}

/// With `SL_FSOE_OPT_PIN_CONNID` the slave accepts only its configured `nConnectionId`
/// (Reset 3 otherwise), and still reaches DATA with a master that sends it.
#[test]
fn a_pinned_connection_id_refuses_any_other() {
    let mut sc = conn(SL_FSOE_ROLE_SLAVE, 2, 2, 2);
    sc.dwOptions = SL_FSOE_OPT_PIN_CONNID;
    let mut s = Node::new(sc);
    let mut mc = conn(SL_FSOE_ROLE_MASTER, 2, 2, 3);
    mc.nConnectionId = 8;
    let mut m = Node::new(mc);
    let mut code = 0;
    for t in 0..50 {
        bus(&mut m, &mut s, t);
        assert_ne!(s.c.nState, SL_FSOE_STATE_DATA);
        if s.c.nResetCode != 0 {
            code = s.c.nResetCode;
            break;
        }
    }
    assert_eq!(code, SL_FSOE_RESET_INVALID_CONNID);
    let mut m = Node::new(conn(SL_FSOE_ROLE_MASTER, 2, 2, 4));
    connect(&mut m, &mut s, 100);
}
