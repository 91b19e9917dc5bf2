//! Two processes over a real black channel (issue 11 item 5): the FSoE slave ("remote safe
//! I/O", examples/fsoe_slave.rs) and the logic master running a group with an ESTOP fed by
//! the received bits (examples/fsoe_master.rs) exchange frames over UDP on 127.0.0.1.
//! The safe signal arrives; the slave process is killed and the master's group enters
//! ERROR (ComErr, diag 2) with EStopOut FALSE within the watchdog time; the slave is
//! started again and the master recovers through ErrAck.
//!
//! The two programs are the examples themselves, compiled into this test and run as child
//! processes of this test binary (it re-executes itself with `SAFELOGIC_UDP_ROLE` set), so
//! `cargo test --release` needs nothing built beforehand.

#[allow(dead_code)]
#[path = "../examples/fsoe_master.rs"]
mod master;
#[allow(dead_code)]
#[path = "../examples/fsoe_slave.rs"]
mod slave;

use std::io::{BufRead, BufReader, Write};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::{self, Receiver};
use std::time::{Duration, Instant};

const ROLE: &str = "SAFELOGIC_UDP_ROLE";
const PORTS: &str = "SAFELOGIC_UDP_PORTS";

/// The child processes' entry: runs a node when this binary was started as one.
#[test]
fn udp_child_process() {
    let Ok(role) = std::env::var(ROLE) else {
        return;
    };
    let ports: Vec<u16> = std::env::var(PORTS)
        .unwrap()
        .split(',')
        .map(|p| p.parse().unwrap())
        .collect();
    match role.as_str() {
        "master" => master::run(ports[0], ports[1]),
        _ => slave::run(ports[0], ports[1]),
    }
    std::process::exit(0);
}

/// A node process with its status lines (received with the time they arrived).
struct Node {
    child: Child,
    lines: Receiver<(Instant, String)>,
    last: String,
}

impl Node {
    fn start(role: &str, own: u16, peer: u16) -> Node {
        let mut child = Command::new(std::env::current_exe().unwrap())
            .args([
                "--exact",
                "udp_child_process",
                "--nocapture",
                "--test-threads=1",
            ])
            .env(ROLE, role)
            .env(PORTS, format!("{own},{peer}"))
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("spawn");
        let out = child.stdout.take().unwrap();
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || {
            for line in BufReader::new(out).lines() {
                let Ok(line) = line else { break };
                if line.starts_with("status ") && tx.send((Instant::now(), line)).is_err() {
                    break;
                }
            }
        });
        Node {
            child,
            lines: rx,
            last: String::new(),
        }
    }
    fn send(&mut self, cmd: &str) {
        let stdin = self.child.stdin.as_mut().unwrap();
        writeln!(stdin, "{cmd}").unwrap();
        stdin.flush().unwrap();
    }
    /// Waits for a status line for which `f` holds; returns it and its arrival time.
    fn wait(&mut self, what: &str, f: impl Fn(&Fields) -> bool) -> (Fields, Instant) {
        if !self.last.is_empty() {
            let fl = Fields::parse(&self.last);
            if f(&fl) {
                return (fl, Instant::now());
            }
        }
        let deadline = Instant::now() + Duration::from_secs(20);
        loop {
            let left = deadline.saturating_duration_since(Instant::now());
            match self.lines.recv_timeout(left) {
                Ok((at, line)) => {
                    self.last = line;
                    let fl = Fields::parse(&self.last);
                    if f(&fl) {
                        return (fl, at);
                    }
                }
                Err(_) => panic!("timed out waiting for {what}; last status: {}", self.last),
            }
        }
    }
    fn kill(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Drop for Node {
    fn drop(&mut self) {
        self.kill();
    }
}

/// The `key=value` fields of a status line.
struct Fields(Vec<(String, String)>);

impl Fields {
    fn parse(line: &str) -> Fields {
        Fields(
            line.split_whitespace()
                .filter_map(|kv| kv.split_once('='))
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect(),
        )
    }
    fn get(&self, k: &str) -> &str {
        self.0
            .iter()
            .find(|(key, _)| key == k)
            .map_or("", |(_, v)| v.as_str())
    }
    fn num(&self, k: &str) -> u32 {
        self.get(k).parse().unwrap_or(u32::MAX)
    }
}

/// Two free UDP ports on 127.0.0.1.
fn free_ports() -> (u16, u16) {
    let a = std::net::UdpSocket::bind("127.0.0.1:0").unwrap();
    let b = std::net::UdpSocket::bind("127.0.0.1:0").unwrap();
    (
        a.local_addr().unwrap().port(),
        b.local_addr().unwrap().port(),
    )
}

#[test]
fn master_and_slave_processes_over_udp() {
    let (mp, sp) = free_ports();
    let mut m = Node::start("master", mp, sp);
    let mut s = Node::start("slave", sp, mp);

    // DATA, group RUN, and the slave's released e-stop at the ESTOP's inputs.
    m.wait("master RUN with both channels TRUE", |f| {
        f.num("group") == 1 && f.num("conn") == 104 && f.get("in") == "11"
    });
    m.send("restart");
    m.wait("EStopOut TRUE", |f| f.num("out") == 1);
    // The master's output reaches the slave's safe output (TXBIT → RXBIT).
    s.wait("slave DecOut3 TRUE", |f| f.num("out3") == 1);
    // The e-stop pressed on the slave: the master's output falls.
    s.send("press");
    m.wait("EStopOut FALSE after press", |f| {
        f.num("out") == 0 && f.get("in") == "00"
    });
    s.send("release");
    m.wait("inputs TRUE again", |f| f.get("in") == "11");
    m.send("restart");
    m.wait("EStopOut TRUE again", |f| f.num("out") == 1);

    // Kill the slave: ComErr, group ERROR diag 2, EStopOut FALSE within the watchdog.
    let killed = Instant::now();
    s.kill();
    let (f, at) = m.wait("group ERROR with ComErr", |f| {
        f.num("group") == 4 && f.num("comerr") == 1
    });
    assert_eq!(f.num("diag"), 2, "COMERROR");
    assert_eq!(f.num("out"), 0);
    // The master's own measure: the time since the last frame from the slave is at most the
    // watchdog plus the cycle that detected it (the previous cycle had not yet expired; its
    // length is `gap`, 1 ms plus the sleep's overshoot on an idle machine).
    let (since, gap) = (f.num("since_rx"), f.num("gap"));
    assert!(
        since <= master::WATCHDOG_MS + gap,
        "ERROR {since} ms after the last frame (cycle {gap} ms)"
    );
    assert!(
        since >= master::WATCHDOG_MS,
        "not before the watchdog: {since} ms"
    );
    // Wall clock from the kill to the status line, with room for a loaded machine.
    let wall = at.duration_since(killed).as_millis() as u32;
    assert!(
        wall <= master::WATCHDOG_MS + 2000,
        "ERROR seen {wall} ms after the kill"
    );

    // The slave comes back: DATA again, ComErr latched until ErrAck.
    let mut s = Node::start("slave", sp, mp);
    m.wait("connection in DATA again", |f| f.num("conn") == 104);
    s.wait("slave connection in DATA", |f| f.num("conn") == 104);
    std::thread::sleep(Duration::from_millis(50));
    m.wait("still ERROR before ErrAck", |f| {
        f.num("group") == 4 && f.num("comerr") == 1
    });
    m.send("ack");
    m.wait("group RUN after ErrAck", |f| {
        f.num("group") == 1 && f.num("comerr") == 0 && f.get("in") == "11"
    });
    m.send("restart");
    m.wait("EStopOut TRUE after recovery", |f| f.num("out") == 1);
    s.wait("slave DecOut3 TRUE after recovery", |f| f.num("out3") == 1);
    m.send("quit");
    s.send("quit");
}
