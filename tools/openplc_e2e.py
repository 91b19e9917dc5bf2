#!/usr/bin/env python3
"""End-to-end: safety projects exported with `safelogic export-st`, built into the real OpenPLC v3
runtime (../shared/vendor/openplc/build_runtime.sh, libsafelogic.a linked in), started with its
Modbus TCP server on 127.0.0.1, and driven by a Modbus TCP client (pymodbus) that plays each
project's scenario file. Every expectation must hold as it does in `safelogic sim`.

    python3 tools/openplc_e2e.py --safelogic target/release/safelogic \
        --lib target/release/libsafelogic.a --openplc ../shared/vendor/openplc --workdir build/openplc-e2e

How scenario time maps onto scans (docs/plc-integration.md, "Scenario time and scans"):
- The program waits for its start coil (`[plc] start`); its first cycle (setup, time 0) runs in the
  first scan that reads it TRUE. The client writes step 0's inputs, then the start coil.
- The program's time advances by the project cycle per cycle; the clock register (`[plc] clock`)
  holds the time of the next cycle. A step at time t is written while the clock reads t (after
  cycle t - cycle ran, before cycle t runs), and its expectations are read while the clock reads
  t + cycle (after cycle t, before cycle t + cycle). The clock is read again after every write and
  every read; if it moved, that request may have landed in another scan, and the attempt counts as
  a timing miss: the runtime is stopped and the scenario played again from a fresh start (at most
  --attempts times). So an expectation is never checked with a tolerance: it is read in its scan.
- The runtime scans on its own clock (the task interval = the project cycle).

Also checked on the KL6904 5.1 project: the e-stop input dropped -> K1K2 FALSE after the next
cycle; a Modbus client that disconnects (closed, or reset in the middle of a request) -> the outputs
and states unchanged and the scans go on; the runtime stopped (quit()) and started again -> the
program starts from its initial state (waits for start, then behaves as at scenario time 0).

Prints one line per check and "N passed, M failed" last; exit status 1 on any failure.
Run inside a private network namespace when possible (OpenPLC's control port 43628 is fixed):
tools/openplc_e2e.sh does that.
"""
from __future__ import annotations

import argparse
import json
import os
import socket
import struct
import subprocess
import sys
import time
import tomllib
from pathlib import Path

from pymodbus.client import ModbusTcpClient
import pymodbus
if os.environ.get("E2E_DEBUG"):
    pymodbus.pymodbus_apply_logging_config("DEBUG")

ROOT = Path(__file__).resolve().parent.parent
CONTROL_PORT = 43628  # OpenPLC's interactive server (hard-coded in core/utils.cpp)

# (project, scenario) under examples/projects
PROJECTS = [("kl6904_5_1", "kl6904_5_1"), ("kl6904_5_2", "kl6904_5_2"), ("speed_monitor", "speed_monitor")]

passed = 0
failed = 0


def check(ok: bool, what: str) -> bool:
    global passed, failed
    if ok:
        passed += 1
        print(f"ok    {what}", flush=True)
    else:
        failed += 1
        print(f"FAIL  {what}", flush=True)
    return ok


class Miss(Exception):
    """A request that may have landed in another scan than the one it was meant for."""


def loopback_up() -> None:
    """Brings `lo` up in a fresh network namespace (SIOCSIFFLAGS; no iproute2 needed)."""
    import fcntl

    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        ifr = struct.pack("16sH14s", b"lo", 0x1 | 0x8 | 0x40, b"\0" * 14)  # UP | LOOPBACK | RUNNING
        fcntl.ioctl(s, 0x8914, ifr)
    finally:
        s.close()


def control(cmd: str, timeout: float = 2.0) -> str:
    """One command to OpenPLC's interactive server (one connection per command, as its web UI)."""
    with socket.create_connection(("127.0.0.1", CONTROL_PORT), timeout=timeout) as s:
        s.sendall((cmd + "\n").encode())
        data = b""
        while not data.endswith(b"\n"):
            chunk = s.recv(4096)
            if not chunk:
                break
            data += chunk
    return data.decode(errors="replace").strip()


class Runtime:
    """One `openplc` process, started and stopped by its own pid."""

    live: list["Runtime"] = []

    def __init__(self, binary: Path, rundir: Path, port: int):
        self.binary, self.rundir, self.port = binary, rundir, port
        self.proc: subprocess.Popen | None = None
        self.starts = 0

    def start(self) -> None:
        self.rundir.mkdir(parents=True, exist_ok=True)
        self.starts += 1
        log = open(self.rundir / f"runtime-{self.starts}.log", "w")
        self.proc = subprocess.Popen([str(self.binary)], cwd=self.rundir, stdout=log, stderr=subprocess.STDOUT)
        Runtime.live.append(self)
        deadline = time.monotonic() + 20
        while True:
            try:
                control("exec_time()")
                break
            except OSError:
                if self.proc.poll() is not None or time.monotonic() > deadline:
                    raise RuntimeError(f"openplc did not open its control port (exit {self.proc.poll()})")
                time.sleep(0.05)
        r = control(f"start_modbus({self.port})")
        if r != "OK":
            raise RuntimeError(f"start_modbus: {r!r}")

    def stop(self) -> int:
        """quit(), then the exit status (killed by pid after 10 s: -9)."""
        assert self.proc is not None
        Runtime.live.remove(self)
        try:
            control("quit()")
        except OSError:
            pass
        try:
            return self.proc.wait(10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
            return -9
        finally:
            self.proc = None

    def summary(self) -> str:
        """The runtime's own cycle-time summary line (printed when it quits)."""
        text = (self.rundir / f"runtime-{self.starts}.log").read_text(errors="replace")
        return "\n".join(l for l in text.splitlines() if l.startswith("###Summary"))


def parse_time(s: str) -> int:
    s = s.strip()
    for unit, f in (("min", 60000), ("ms", 1), ("s", 1000)):
        if s.endswith(unit):
            return int(s[: -len(unit)].strip()) * f
    raise ValueError(f"not a time: {s!r}")


class Plc:
    """The running program seen through its Modbus map (export-st --map)."""

    def __init__(self, client: ModbusTcpClient, m: dict):
        self.c, self.m = client, m
        self.cycle = m["cycle_ms"]
        self.sig = {s["name"]: s for s in m["inputs"] + m["outputs"]}
        self.states = {s["name"]: s for s in m["states"]}
        self.inputs = {s["name"]: 0 for s in m["inputs"]}
        # Every coil the client writes, as it last wrote it: OpenPLC's FC15 writes whole bytes
        # (8 coils per data byte from the start address, whatever the quantity), so a write
        # sends the full bytes it touches with the values the client knows.
        self.coils = {s["modbus"]["address"]: False for s in m["inputs"] if s["modbus"]["table"] == "coil"}
        self.coils[m["start"]["modbus"]["address"]] = False

    @staticmethod
    def _ok(r, what: str):
        if r.isError():
            raise RuntimeError(f"Modbus {what}: {r}")
        return r

    def _regs(self, address: int, count: int) -> list[int]:
        return self._ok(self.c.read_holding_registers(address, count=count), f"read HR {address}").registers

    def clock(self) -> int:
        hi, lo = self._regs(self.m["clock"]["modbus"]["address"], 2)
        return (hi << 16) | lo

    def write(self, values: dict[str, int], start: bool | None = None) -> None:
        """Writes inputs (and the start coil): the coil bytes they touch in one FC15 request per
        contiguous run of bytes, the registers in one FC16 request per contiguous run."""
        self.inputs.update(values)
        touched: set[int] = set()
        regs: dict[int, int] = {}
        for name, v in values.items():
            mb = self.sig[name]["modbus"]
            if mb["table"] == "coil":
                self.coils[mb["address"]] = bool(v)
                touched.add(mb["address"] // 8)
            elif mb["words"] == 2:
                u = v & 0xFFFFFFFF
                regs[mb["address"]], regs[mb["address"] + 1] = u >> 16, u & 0xFFFF
            else:
                regs[mb["address"]] = v & 0xFFFF
        if start is not None:
            a = self.m["start"]["modbus"]["address"]
            self.coils[a] = start
            touched.add(a // 8)

        def runs(keys):
            keys = sorted(keys)
            while keys:
                run = [keys.pop(0)]
                while keys and keys[0] == run[-1] + 1:
                    run.append(keys.pop(0))
                yield run

        for run in runs(regs):
            self._ok(self.c.write_registers(run[0], [regs[a] for a in run]), "write registers")
        for run in runs(touched):
            first = run[0] * 8
            vals = [self.coils.get(a, False) for a in range(first, (run[-1] + 1) * 8)]
            self._ok(self.c.write_coils(first, vals), "write coils")

    def read(self, labels: list[str]) -> dict[str, object]:
        """Outputs (numbers, signed by type) and states (names) by label."""
        out: dict[str, object] = {}
        for label in labels:
            if label in self.sig:
                s = self.sig[label]
                mb = s["modbus"]
                if mb["table"] == "coil":
                    out[label] = int(self._ok(self.c.read_coils(mb["address"], count=1), "read coil").bits[0])
                else:
                    regs = self._regs(mb["address"], mb["words"])
                    v = regs[0] if mb["words"] == 1 else (regs[0] << 16) | regs[1]
                    bits = 16 * mb["words"]
                    if s["type"] in ("INT", "DINT") and v >= 1 << (bits - 1):
                        v -= 1 << bits
                    out[label] = v
            elif label in self.states:
                st = self.states[label]
                v = self._regs(st["modbus"]["address"], 1)[0]
                out[label] = st["values"].get(str(v), f"?{v}")
            else:
                raise KeyError(f"`{label}` is not observable over Modbus (not an output or a state word)")
        return out

    def wait_clock(self, target: int) -> None:
        """Returns while the clock reads `target`; Miss if it is already past it."""
        while True:
            c = self.clock()
            if c == target:
                return
            if c > target:
                raise Miss(f"clock {c} ms passed {target} ms")
            ahead = (target - c) / 1000.0
            time.sleep(max(ahead - 0.006, 0.0005))

    def wait_past(self, target: int) -> None:
        """Returns once the clock reads `target` or more."""
        while self.clock() < target:
            time.sleep(0.002)


def want_value(v) -> object:
    return int(v) if isinstance(v, (bool, int)) else v


def play(plc: Plc, sc: dict, tag: str) -> list[str]:
    """Plays a scenario from the program's start; the failed expectations (Miss on timing)."""
    steps: dict[int, dict] = {}
    for st in sc.get("step", []):
        at = parse_time(st["at"])
        s = steps.setdefault(at, {"set": {}, "expect": {}})
        s["set"].update({k: int(v) for k, v in st.get("set", {}).items()})
        s["expect"].update(st.get("expect", {}))
    cyc = plc.cycle
    until = max(steps)
    if "until" in sc["scenario"]:
        until = max(until, parse_time(sc["scenario"]["until"]))
    if plc.clock() != 0:
        raise RuntimeError("the program ran before its start coil was set")
    fails = []
    for n, at in enumerate(sorted(steps)):
        s = steps[at]
        if n == 0:
            if at != 0:
                plc.write({}, start=True)
            else:
                plc.write(s["set"], start=True)  # cycle 0 runs in the next scan, with these inputs
        else:
            plc.wait_clock(at)
            if s["set"]:
                plc.write(s["set"])
                if plc.clock() != at:
                    raise Miss(f"the inputs of {at} ms may have landed after cycle {at} ms")
        if s["expect"]:
            plc.wait_clock(at + cyc)
            got = plc.read(list(s["expect"]))
            if plc.clock() != at + cyc:
                raise Miss(f"the outputs of {at} ms may have been read after cycle {at + cyc} ms")
            for label, want in s["expect"].items():
                w = want_value(want)
                if got[label] != w:
                    fails.append(f"{tag} {at} ms: {label} = {got[label]}, expected {w}")
    plc.wait_clock(until + cyc)
    return fails


def build(args, name: str) -> tuple[Path, dict]:
    """export-st + map, then build_runtime.sh with libsafelogic.a; the binary and the map."""
    proj = ROOT / "examples/projects" / f"{name}.toml"
    work = args.workdir / name
    work.mkdir(parents=True, exist_ok=True)
    st, mp = work / "program.st", work / "map.json"
    subprocess.run([args.safelogic, "export-st", str(proj), "--dialect", "iec", "-o", str(st), "--map", str(mp)], check=True)
    env = dict(os.environ, OPENPLC_CACHE_DIR=str(args.cache))
    t0 = time.monotonic()
    r = subprocess.run(["bash", str(args.openplc / "build_runtime.sh"), str(st), str(work / "bin"), str(args.lib),
                        "-lpthread", "-ldl", "-lm"], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    (work / "build.log").write_text(r.stdout)
    if r.returncode != 0:
        print(r.stdout[-4000:])
        raise RuntimeError(f"build_runtime.sh failed for {name} (log: {work / 'build.log'})")
    print(f"built {name}: {work / 'bin/openplc'} ({time.monotonic() - t0:.1f} s, {st.stat().st_size // 1024} KiB of ST)", flush=True)
    return work / "bin/openplc", json.loads(mp.read_text())


def connect(port: int) -> ModbusTcpClient:
    """The one client connection, retried until the server listens. No probe connection before
    it: OpenPLC's server can hand two connections accepted in quick succession to the same
    thread (the accept loop reuses the argument block it passes to the new thread)."""
    deadline = time.monotonic() + 10
    while True:
        c = ModbusTcpClient("127.0.0.1", port=port, timeout=2, retries=0)
        if c.connect():
            return c
        if time.monotonic() > deadline:
            raise RuntimeError("Modbus TCP connect failed")
        time.sleep(0.1)


def run_scenario(args, name: str, scenario: str, binary: Path, m: dict) -> tuple[Runtime, ModbusTcpClient, Plc] | None:
    """Plays the scenario (a fresh runtime per attempt); returns the runtime left running."""
    sc_path = ROOT / "examples/projects" / f"{scenario}.scenario.toml"
    sc = tomllib.loads(sc_path.read_text())
    n_expect = sum(len(s.get("expect", {})) for s in sc.get("step", []))
    sim = subprocess.run([args.safelogic, "sim", str(ROOT / "examples/projects" / f"{name}.toml"), str(sc_path)],
                         stdout=subprocess.PIPE, text=True)
    check(sim.returncode == 0, f"[{name}] safelogic sim passes the scenario: {sim.stdout.strip().splitlines()[-1]}")
    rt = Runtime(binary, args.workdir / name / "run", args.port)
    for attempt in range(1, args.attempts + 1):
        rt.start()
        client = connect(args.port)
        plc = Plc(client, m)
        try:
            fails = play(plc, sc, f"[{name}]")
        except Miss as e:
            print(f"      [{name}] attempt {attempt}: timing miss ({e}); the runtime is restarted", flush=True)
            client.close()
            rt.stop()
            continue
        for f in fails:
            check(False, f)
        check(not fails, f"[{name}] scenario \"{sc['scenario']['name']}\" in OpenPLC over Modbus TCP: "
              f"{n_expect - len(fails)} of {n_expect} expectations hold, each read in its own scan "
              f"(attempt {attempt})")
        return rt, client, plc
    check(False, f"[{name}] scenario: {args.attempts} attempts, every one had a timing miss")
    return None


def estop_checks(args, name: str, rt: Runtime, client: ModbusTcpClient, plc: Plc, m: dict) -> None:
    """The KL6904 5.1 checks after its scenario (K1K2 on, estop RUN)."""
    cyc = plc.cycle
    labels = ["K1K2", "EStopErr", "estop.state", "safety.state"]
    # K1/K2 pulled in: their feedback contacts open (EDM1 FALSE) within tEDM1ResetTime (200 ms)
    plc.write({"K1K2_fb": 0})
    before = plc.read(labels)
    check(before["K1K2"] == 1 and before["estop.state"] == "RUN", f"[{name}] K1K2 on, estop RUN at the end of the scenario: {before}")

    # 1. The client disconnects: closed cleanly, then reset in the middle of a request.
    c0 = plc.clock()
    client.close()
    time.sleep(0.3)
    raw = socket.create_connection(("127.0.0.1", args.port), timeout=2)
    raw.sendall(bytes([0x00, 0x01, 0x00, 0x00, 0x00, 0x06, 0x01]))  # half a request
    raw.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
    raw.close()  # RST
    time.sleep(0.3)
    client = connect(args.port)
    plc.c = client
    after = plc.read(labels)
    c1 = plc.clock()
    check(after == before and c1 - c0 >= 30 * cyc,
          f"[{name}] Modbus client closed, another reset mid-request: outputs and states unchanged {after}, "
          f"the program kept scanning ({(c1 - c0) // cyc} cycles meanwhile)")

    # 2. E-stop input dropped: K1K2 FALSE after the next cycle.
    def arm() -> None:
        """S1 released, feedback closed, a restart pulse, then the feedback opens (K1/K2 on)."""
        plc.write({"S1_1": 1, "S1_2": 1, "K1K2_fb": 1})
        for v in (1, 0):
            plc.write({"S2": v})
            plc.wait_past(plc.clock() + 5 * cyc)
        plc.write({"K1K2_fb": 0})

    for attempt in range(1, args.attempts + 1):
        if attempt > 1:
            arm()
        if plc.read(["K1K2"])["K1K2"] != 1:
            check(False, f"[{name}] re-armed before the e-stop test: K1K2 is not on")
            break
        plc.write({"S1_1": 0, "S1_2": 0})  # one FC15 request (coils 800-801)
        cw = plc.clock()  # the write landed before cycle cw ran
        try:
            plc.wait_clock(cw + cyc)
            got = plc.read(["K1K2", "estop.state"])
            if plc.clock() != cw + cyc:
                raise Miss("read after the next cycle")
        except Miss as e:
            print(f"      [{name}] e-stop attempt {attempt}: timing miss ({e})", flush=True)
            continue
        check(got["K1K2"] == 0 and got["estop.state"] == "SAFE",
              f"[{name}] e-stop dropped (written before cycle {cw} ms): after that cycle K1K2 = {got['K1K2']}, "
              f"estop {got['estop.state']} (attempt {attempt})")
        break
    else:
        check(False, f"[{name}] e-stop drop: every attempt had a timing miss")
    arm()
    check(plc.read(["K1K2"])["K1K2"] == 1, f"[{name}] re-armed: S1 released, restart pulse, K1K2 on")

    # 3. Runtime stopped and started again: the program starts from its initial state.
    client.close()
    rc = rt.stop()
    check(rc == 0, f"[{name}] quit(): the runtime exits with status {rc}")
    rt.start()
    client = connect(args.port)
    plc = Plc(client, m)
    time.sleep(0.2)
    held = plc.read(labels)
    check(plc.clock() == 0 and held == {"K1K2": 0, "EStopErr": 0, "estop.state": "?0", "safety.state": "?0"},
          f"[{name}] started again: the program waits for its start coil (clock 0, no state yet, outputs off): {held}")
    plc.write({"S1_1": 1, "S1_2": 1, "K1K2_fb": 1}, start=True)
    plc.wait_past(cyc)
    first = plc.read(labels)
    check(first == {"K1K2": 0, "EStopErr": 0, "estop.state": "SAFE", "safety.state": "RUN"},
          f"[{name}] after the restart, as at scenario time 0: {first}")
    plc.wait_past(30 * cyc)
    check(plc.read(["K1K2"])["K1K2"] == 0, f"[{name}] 30 cycles with S1 released and no restart edge: K1K2 stays off (the block needs its restart again)")
    for v in (1, 0):
        plc.write({"S2": v})
        plc.wait_past(plc.clock() + 5 * cyc)
    plc.write({"K1K2_fb": 0})
    check(plc.read(["K1K2"])["K1K2"] == 1, f"[{name}] restart pulse after the restart: K1K2 on")
    client.close()
    rc = rt.stop()
    check(rc == 0, f"[{name}] quit(): exit status {rc}")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--safelogic", required=True)
    ap.add_argument("--lib", required=True, type=Path)
    ap.add_argument("--openplc", required=True, type=Path, help="the folder with build_runtime.sh")
    ap.add_argument("--workdir", required=True, type=Path)
    ap.add_argument("--cache", type=Path, help="OPENPLC_CACHE_DIR (default WORKDIR/../openplc-cache)")
    ap.add_argument("--port", type=int, default=5020)
    ap.add_argument("--attempts", type=int, default=5)
    ap.add_argument("--only", help="one project name")
    args = ap.parse_args()
    args.workdir = args.workdir.resolve()
    args.lib = args.lib.resolve()
    args.cache = (args.cache or args.workdir.parent / "openplc-cache").resolve()
    if os.environ.get("OPENPLC_E2E_NETNS") == "1":
        loopback_up()
    try:
        control("exec_time()", timeout=0.5)
        print(f"FAIL  another OpenPLC runtime answers on 127.0.0.1:{CONTROL_PORT}; stop it or run in a network namespace")
        return 1
    except OSError:
        pass
    try:
        for name, scenario in PROJECTS:
            if args.only and name != args.only:
                continue
            binary, m = build(args, name)
            left = run_scenario(args, name, scenario, binary, m)
            if left is None:
                continue
            rt, client, plc = left
            if name == "kl6904_5_1":
                estop_checks(args, name, rt, client, plc, m)
            else:
                client.close()
                rc = rt.stop()
                check(rc == 0, f"[{name}] quit(): exit status {rc}")
            print(f"      [{name}] the runtime's own figures: {rt.summary()}", flush=True)
    finally:
        for rt in list(Runtime.live):
            rt.stop()
    print(f"{passed} passed, {failed} failed")
    return 1 if failed or not passed else 0


if __name__ == "__main__":
    sys.exit(main())
