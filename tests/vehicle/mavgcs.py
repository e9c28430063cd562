# SPDX-License-Identifier: Apache-2.0
"""A ground station for the vehicle's tests, made of pymavlink's own mavutil (the pinned
pymavlink that tools/bootstrap.sh installs into .tools/pymavlink): it listens on a UDP port
as QGroundControl and MAVProxy do, starts the SITL with --mavlink pointed at that port and
records every message the vehicle sends.

    with Session(sitl_binary, ["--speedup", "20", mission]) as s:
        hb = s.wait("HEARTBEAT")
        ...
    s.out  # the SITL's console output, s.rc its exit status (SIGINT at the end of the session)
"""

import os
import re
import signal
import subprocess
import sys
import threading
import time
import types

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, ".tools", "pymavlink"))
os.environ["MAVLINK20"] = "1"
from pymavlink import mavutil, mavwp  # noqa: E402
from pymavlink.dialects.v20 import ardupilotmega as mav  # noqa: E402

GCS_SYSID = 255
GCS_COMPID = mav.MAV_COMP_ID_MISSIONPLANNER


class Timeout(TimeoutError):
    pass


class Session:
    """The SITL connected to this ground station for the length of a with-block."""

    def __init__(self, binary, args, timeout=90):
        self.binary, self.args, self.timeout = binary, args, timeout
        # a ground station sends its heartbeat at 1 Hz of its own (wall) time; at --speedup N
        # that is 1 Hz of the vehicle's time only if sent N times faster (else FS_GCS_TIMEOUT,
        # in vehicle time, sees the link lost)
        speedup = float(args[args.index("--speedup") + 1]) if "--speedup" in args else 1.0
        self.hb_period = 1.0 / speedup
        self.hb_on = True  # False: the ground station goes silent (link-loss tests)
        # every wait below is seconds * scale of wall time (FirmwareSession: the vehicle's time does
        # not run at --speedup there)
        self.scale = 1.0
        self.msgs = []          # (wall time, message) of every message received, in order
        self.rc, self.out, self.err = None, "", ""
        self.uploaded_at = 0    # FirmwareSession: the mark after its upload of the mission file

    def __enter__(self):
        self.conn = mavutil.mavlink_connection("udpin:127.0.0.1:0", source_system=GCS_SYSID,
                                               source_component=GCS_COMPID, dialect="ardupilotmega")
        port = self.conn.port.getsockname()[1]
        self.proc = subprocess.Popen([self.binary, "--mavlink", "udp:127.0.0.1:%d" % port] + self.args,
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
        self.deadline = time.time() + self.timeout * self.scale
        self.last_hb = 0.0
        return self

    def __exit__(self, *exc):
        self.stop()
        self.conn.close()
        return False

    def stop(self):
        """SIGINT: the SITL prints its summary and exits; keep its output."""
        if self.rc is None:
            if self.proc.poll() is None:
                self.proc.send_signal(signal.SIGINT)
            try:
                self.out, self.err = self.proc.communicate(timeout=30)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.out, self.err = self.proc.communicate()
            self.rc = self.proc.returncode

    def rx_drops(self):
        """Datagrams the kernel dropped at this ground station's socket (receive buffer full:
        the vehicle sent them, this side did not read in time; /proc/net/udp, column drops)."""
        inode = str(os.fstat(self.conn.port.fileno()).st_ino)
        with open("/proc/net/udp", encoding="ascii") as f:
            for line in f.readlines()[1:]:
                cols = line.split()
                if cols[9] == inode:
                    return int(cols[12])
        raise RuntimeError("socket inode %s not in /proc/net/udp" % inode)

    def vehicle(self):
        """The vehicle's target (system, component) for the messages the GCS sends."""
        return self.conn.target_system, self.conn.target_component

    def poll(self, block=0.05):
        """Receive what has arrived; send the GCS heartbeat at 1 Hz (wall clock)."""
        now = time.time()
        if self.hb_on and now - self.last_hb >= self.hb_period:
            self.conn.mav.heartbeat_send(mav.MAV_TYPE_GCS, mav.MAV_AUTOPILOT_INVALID, 0, 0, 0)
            self.last_hb = now
        m = self.conn.recv_match(blocking=True, timeout=block)
        if m is not None and m.get_type() != "BAD_DATA":
            self.msgs.append((time.time(), m))
        if self.proc.poll() is not None and m is None:
            raise Timeout("the SITL exited (rc %s)" % self.proc.returncode)
        if time.time() > self.deadline:
            raise Timeout("no answer in %d s" % (self.timeout * self.scale))
        return m

    def mark(self):
        """A position in the messages received so far (for wait's since)."""
        return len(self.msgs)

    def wait(self, mtype, cond=lambda m: True, seconds=30, since=None):
        """The first message of type mtype satisfying cond from now on, or from the mark since
        (messages already received after it count)."""
        if since is not None:
            for _, m in self.msgs[since:]:
                if m.get_type() == mtype and cond(m):
                    return m
        end = time.time() + seconds * self.scale
        while time.time() < end:
            m = self.poll()
            if m is not None and m.get_type() == mtype and cond(m):
                return m
        raise Timeout("no %s in %d s" % (mtype, seconds))

    def wait_any(self, mtype, since, seconds):
        """The first message of type mtype received after the mark since, waiting up to seconds
        for it; None if none came."""
        end = time.time() + seconds * self.scale
        while True:
            for _, m in self.msgs[since:]:
                if m.get_type() == mtype:
                    return m
            if time.time() > end:
                return None
            self.poll()

    def lines(self, since=0, complete=False):
        """Console lines (STATUSTEXT, the chunks of one id joined in chunk_seq order) received
        after the mark since. A line whose first chunk came before the mark is left out, and so
        is one whose last chunk has not come yet unless complete (then it is an error); a chunk
        out of order is an error (ValueError)."""
        out, parts = [], {}
        for _, m in self.msgs[since:]:
            if m.get_type() != "STATUSTEXT":
                continue
            if m.id == 0:
                out.append(m.text)
                continue
            if m.chunk_seq == 0:
                parts[m.id] = []
            if m.id not in parts:
                continue
            if m.chunk_seq != len(parts[m.id]):
                raise ValueError("STATUSTEXT id %d: chunk %d after %s" % (m.id, m.chunk_seq, parts[m.id]))
            parts[m.id].append(m.text)
            if len(m.text) < 50:
                out.append("".join(parts.pop(m.id)))
        if complete and parts:
            raise ValueError("unfinished STATUSTEXT lines: %s" % parts)
        return out

    def wait_text(self, cond, seconds=30, since=None):
        """The first console line satisfying cond (called with an object whose .text is the
        line), from now on or from the mark since."""
        start = self.mark() if since is None else since
        seen = 0
        end = time.time() + seconds * self.scale
        while True:
            lines = self.lines(start)
            for t in lines[seen:]:
                if cond(types.SimpleNamespace(text=t)):
                    return t
            seen = len(lines)
            if time.time() > end:
                raise Timeout("no console line as expected in %d s" % seconds)
            self.poll()

    def of(self, mtype):
        return [m for _, m in self.msgs if m.get_type() == mtype]

    # ---- the mission protocol, as a ground station drives it -----------------------------

    def upload(self, items, seconds=30, legacy=False, answer=None):
        """Upload items (dicts of MISSION_ITEM_INT fields; legacy: as MISSION_ITEM with x and y
        in degrees). answer(seq) may return the seq to send instead (None: do not answer).
        Returns (the MISSION_ACK that ends the upload, the seqs the vehicle asked for, in
        order); self.acks lists every MISSION_ACK seen."""
        sys_, comp = 1, 1
        self.conn.mav.mission_count_send(sys_, comp, len(items), mav.MAV_MISSION_TYPE_MISSION)
        asked = []
        self.acks = []  # every MISSION_ACK of this upload, INVALID_SEQUENCE ones included
        end = time.time() + seconds * self.scale
        while time.time() < end:
            m = self.poll()
            if m is None:
                continue
            t = m.get_type()
            if t == "MISSION_ACK" and m.get_srcSystem() == 1:
                self.acks.append(m.type)
                if m.type != mav.MAV_MISSION_INVALID_SEQUENCE:  # that one does not end an upload
                    return m, asked
                continue
            if t == "MISSION_REQUEST_INT":
                asked.append(m.seq)
                seq = m.seq if answer is None else answer(m.seq)
                if seq is None:
                    continue
                it = dict(items[seq], seq=seq)
                if legacy:
                    self.conn.mav.mission_item_send(sys_, comp, it["seq"], it["frame"], it["command"], 0,
                                                    it["autocontinue"], it["param1"], it["param2"],
                                                    it["param3"], it["param4"], it["x"] * 1e-7,
                                                    it["y"] * 1e-7, it["z"], mav.MAV_MISSION_TYPE_MISSION)
                else:
                    self.conn.mav.mission_item_int_send(sys_, comp, it["seq"], it["frame"], it["command"], 0,
                                                        it["autocontinue"], it["param1"], it["param2"],
                                                        it["param3"], it["param4"], it["x"], it["y"],
                                                        it["z"], mav.MAV_MISSION_TYPE_MISSION)
        raise Timeout("upload: no MISSION_ACK in %d s" % seconds)

    def command(self, cmd, p1=0.0, p2=0.0, seconds=10, p7=0.0):
        """COMMAND_LONG to the vehicle; its COMMAND_ACK. self.sent_at marks the messages from
        the moment it was sent (what the command caused may arrive before its ACK)."""
        self.sent_at = self.mark()
        self.conn.mav.command_long_send(1, 1, cmd, 0, p1, p2, 0, 0, 0, 0, p7)
        return self.wait("COMMAND_ACK", lambda m: m.command == cmd, seconds=seconds, since=self.sent_at)

    def unanswered(self, cmd, p1=0.0, seconds=2):
        """COMMAND_LONG to the vehicle (signed or not, as the connection is set up): True when
        no COMMAND_ACK comes within seconds."""
        mark = self.mark()
        self.conn.mav.command_long_send(1, 1, cmd, 0, p1, 0, 0, 0, 0, 0, 0)
        return self.wait_any("COMMAND_ACK", since=mark, seconds=seconds) is None

    def arm_and_auto(self, seconds=30):
        """Arm (again while the pre-arm checks refuse: the barometer calibrates, the GPS needs
        fixes), then AUTO: the ACKs of both."""
        end = time.time() + seconds * self.scale
        while True:
            a = self.command(mav.MAV_CMD_COMPONENT_ARM_DISARM, 1.0)
            if a.result == mav.MAV_RESULT_ACCEPTED or time.time() > end:
                break
            time.sleep(0.05)
        b = self.command(mav.MAV_CMD_DO_SET_MODE, float(mav.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED),
                         float(mav.COPTER_MODE_AUTO))
        return a, b

    def download(self, seconds=30):
        """The mission on board: a list of MISSION_ITEM_INT messages."""
        self.conn.mav.mission_request_list_send(1, 1, mav.MAV_MISSION_TYPE_MISSION)
        n = self.wait("MISSION_COUNT", seconds=seconds).count
        items = []
        for seq in range(n):
            self.conn.mav.mission_request_int_send(1, 1, seq, mav.MAV_MISSION_TYPE_MISSION)
            items.append(self.wait("MISSION_ITEM_INT", lambda m, s=seq: m.seq == s, seconds=seconds))
        self.conn.mav.mission_ack_send(1, 1, mav.MAV_MISSION_ACCEPTED, mav.MAV_MISSION_TYPE_MISSION)
        return items


class Unsupported(Exception):
    """What the firmware session cannot do (the reason)."""


# QEMU for the firmware's ground-station session: the console (UART0) on stdio, the link UART
# (UART1: QEMU gives UARTn its n-th -serial) a TCP server on a free port that QEMU waits on
# before the guest starts. -icount shift=5,sleep=off: guest time is the instruction count (32 ns
# each; tasks.def's costs were measured so) and idle time (the idle thread sleeps in WFI) is
# skipped, so vehicle time runs ahead of the host's clock by a factor that depends on the host
# and the guest's load (hal_chibios/README.md: "The link UART and time").
FW_QEMU = ["qemu-system-arm", "-M", "mps2-an386", "-display", "none", "-monitor", "none",
           "-serial", "stdio", "-serial", "tcp:127.0.0.1:0,server=on,wait=on,nodelay=on",
           "-semihosting-config", "enable=on,target=native", "-icount", "shift=5,sleep=off"]
# The slowest vehicle time per wall second assumed (measured 2-5 on 2 shared cores): the tests'
# waits, written for --speedup N (N vehicle seconds per wall second), are stretched by N / this.
FW_MIN_RATE = 1.0


class Qemu:
    """The firmware under QEMU (FW_QEMU): its console (UART0) read all along, its link UART a TCP
    server on self.port that QEMU waits on before the guest starts. finish() ends the session with
    'q' on the console and checks the firmware's own verdict."""

    def __init__(self, elf):
        self.proc = subprocess.Popen(FW_QEMU + ["-kernel", elf], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=ROOT)
        # "QEMU waiting for connection on: disconnected:tcp:127.0.0.1:PORT,server=on"
        line = self.proc.stderr.readline().decode(errors="replace")
        ports = re.findall(r"tcp:127\.0\.0\.1:(\d+)", line)
        if not ports or ports[-1] == "0":
            self.proc.kill()
            raise Timeout("QEMU did not open the link's socket: %s" % line.strip())
        self.port = int(ports[-1])
        # the console and QEMU's messages are read all along (a full pipe would stall the UART)
        self.console, self.errbuf = [], []
        self.readers = [threading.Thread(target=self._read, args=(f, buf), daemon=True)
                        for f, buf in ((self.proc.stdout, self.console), (self.proc.stderr, self.errbuf))]
        for t in self.readers:
            t.start()

    @staticmethod
    def _read(f, buf):
        for chunk in iter(lambda: f.read1(4096), b""):
            buf.append(chunk)

    def quit(self):
        """'q' on the console: the firmware prints its summary and exits through semihosting."""
        if self.proc.poll() is None:
            try:
                self.proc.stdin.write(b"q")
                self.proc.stdin.flush()
            except OSError:
                pass

    def finish(self):
        """Wait for the exit: (rc, console, QEMU's stderr). The firmware's own checks (every byte
        received reached the vehicle, every byte sent left, the log intact, no task over its
        budget): a failed one raises ValueError."""
        try:
            self.proc.wait(timeout=60)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        for t in self.readers:
            t.join(timeout=10)
        out = b"".join(self.console).decode(errors="replace").replace("\r", "")
        err = b"".join(self.errbuf).decode(errors="replace")
        failed = [l for l in out.splitlines() if l.startswith(("CHECK FAILED", "HALT", "FAULT"))]
        if failed or "== flight summary ==" not in out:
            raise ValueError("the firmware's session: %s\n%s" % (failed, out[-1500:]))
        return self.proc.returncode, out, err


class FirmwareSession(Session):
    """The ChibiOS firmware's ground-station session (the FW_GCS=1 build: make test-vehicle-fw) under
    QEMU, its link UART a TCP socket, in place of the SITL. The arguments are the SITL's: --quiet
    (the session build prints no status lines anyway), --speedup N (only the scale of the waits and
    the heartbeat rate: vehicle time runs at the pace QEMU gives it) and a .waypoints file, which
    this ground station uploads over MAVLink first (the firmware has no file system). Anything else
    raises Unsupported. stop() sends 'q' on the console: the firmware prints its summary and exits
    through semihosting (out, rc)."""

    def __init__(self, elf, args, timeout=90):
        super().__init__(elf, args, timeout)
        self.mission = None
        speedup = 1.0
        i = 0
        while i < len(args):
            a = args[i]
            if a == "--quiet":
                pass
            elif a == "--speedup" and i + 1 < len(args):
                speedup = float(args[i + 1])
                i += 1
            elif not a.startswith("-") and a.endswith(".waypoints") and self.mission is None:
                self.mission = a
            else:
                raise Unsupported("the firmware session has no %s (a SITL option)" % a)
            i += 1
        self.scale = speedup / FW_MIN_RATE
        self.replay = []

    def __enter__(self):
        self.qemu = Qemu(self.binary)
        self.proc = self.qemu.proc
        end = time.time() + 10
        while True:
            try:
                self.conn = mavutil.mavlink_connection("tcp:127.0.0.1:%d" % self.qemu.port, source_system=GCS_SYSID,
                                                       source_component=GCS_COMPID, dialect="ardupilotmega",
                                                       autoreconnect=False)
                break
            except OSError:
                if time.time() > end:
                    self.proc.kill()
                    raise
                time.sleep(0.05)
        self.deadline = time.time() + self.timeout * self.scale
        self.last_hb = 0.0
        if self.mission is not None:
            ack, _ = self.upload(wpl_items(self.mission))
            if ack.type != mav.MAV_MISSION_ACCEPTED:
                self.stop()
                raise Timeout("the firmware refused %s: %s" % (self.mission, ack))
            self.uploaded_at = self.mark()
            # the test's first look for the vehicle's HEARTBEAT is answered with the last one that
            # came during the upload, as the SITL's first one would be: its next requests then reach
            # the vehicle as early in its boot as on the SITL (tests that expect arming refused
            # before the pre-arm checks pass depend on it)
            self.replay = [m for _, m in self.msgs if m.get_type() == "HEARTBEAT"][-1:]
        return self

    def poll(self, block=0.05):
        if self.replay:
            return self.replay.pop()
        return super().poll(block)

    def stop(self):
        """The ground station falls silent, then 'q' on the console: the summary, then the exit
        through semihosting. (On a byte stream a frame can be cut by the end of the session: the
        summary would count its first bytes as not in a valid frame. A UDP datagram is whole.)"""
        if self.rc is None:
            if self.proc.poll() is None:
                self.hb_on = False
                end = time.time() + 0.3
                try:
                    while time.time() < end:
                        self.poll()
                except Timeout:
                    pass
                self.qemu.quit()
            try:
                self.rc, self.out, self.err = self.qemu.finish()
            finally:
                self.rc = self.proc.returncode  # a second stop (the with-block's exit) does nothing


def wpl_items(path):
    """A QGC WPL file as MISSION_ITEM_INT fields, read by pymavlink's own loader (mavwp); x and
    y from the file's text at full precision (1e-7 degree)."""
    loader = mavwp.MAVWPLoader()
    loader.load(path)
    out = []
    for i in range(loader.count()):
        w = loader.wp(i)
        out.append(dict(seq=w.seq, frame=w.frame, command=w.command, autocontinue=w.autocontinue,
                        param1=w.param1, param2=w.param2, param3=w.param3, param4=w.param4,
                        x=int(round(w.x * 1e7)), y=int(round(w.y * 1e7)), z=w.z))
    return out
