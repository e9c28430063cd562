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
import signal
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, ".tools", "pymavlink"))
os.environ["MAVLINK20"] = "1"
from pymavlink import mavutil  # noqa: E402
from pymavlink.dialects.v20 import ardupilotmega as mav  # noqa: E402

GCS_SYSID = 255
GCS_COMPID = mav.MAV_COMP_ID_MISSIONPLANNER


class Timeout(Exception):
    pass


class Session:
    """The SITL connected to this ground station for the length of a with-block."""

    def __init__(self, binary, args, timeout=90):
        self.binary, self.args, self.timeout = binary, args, timeout
        self.msgs = []          # (wall time, message) of every message received, in order
        self.rc, self.out, self.err = None, "", ""

    def __enter__(self):
        self.conn = mavutil.mavlink_connection("udpin:127.0.0.1:0", source_system=GCS_SYSID,
                                               source_component=GCS_COMPID, dialect="ardupilotmega")
        port = self.conn.port.getsockname()[1]
        self.proc = subprocess.Popen([self.binary, "--mavlink", "udp:127.0.0.1:%d" % port] + self.args,
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
        self.deadline = time.time() + self.timeout
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

    def vehicle(self):
        """The vehicle's target (system, component) for the messages the GCS sends."""
        return self.conn.target_system, self.conn.target_component

    def poll(self, block=0.05):
        """Receive what has arrived; send the GCS heartbeat at 1 Hz (wall clock)."""
        now = time.time()
        if now - self.last_hb >= 1.0:
            self.conn.mav.heartbeat_send(mav.MAV_TYPE_GCS, mav.MAV_AUTOPILOT_INVALID, 0, 0, 0)
            self.last_hb = now
        m = self.conn.recv_match(blocking=True, timeout=block)
        if m is not None and m.get_type() != "BAD_DATA":
            self.msgs.append((time.time(), m))
        if self.proc.poll() is not None and m is None:
            raise Timeout("the SITL exited (rc %s)" % self.proc.returncode)
        if time.time() > self.deadline:
            raise Timeout("no answer in %d s" % self.timeout)
        return m

    def wait(self, mtype, cond=lambda m: True, seconds=30):
        """The first message of type mtype satisfying cond from now on."""
        end = time.time() + seconds
        while time.time() < end:
            m = self.poll()
            if m is not None and m.get_type() == mtype and cond(m):
                return m
        raise Timeout("no %s in %d s" % (mtype, seconds))

    def of(self, mtype):
        return [m for _, m in self.msgs if m.get_type() == mtype]
