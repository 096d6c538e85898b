#!/usr/bin/python3
"""The DISPLAY program of a headless LinuxCNC session (lcnc_rig.py writes the job).

LinuxCNC starts it as `SCRIPT -ini FILE.ini` once the HAL and the task are up;
when it exits, LinuxCNC shuts down. It runs the job's programs one after the
other in this one session: before each, the probe is cleared (every shape of
the simulated part switched off), the machine goes back to machine zero by MDI
and the HAL takes the program's part; at the k-th M0 pause the HAL takes the
job's changes for that pause (the ring program's spindle turn), and every
pause is resumed. The samples come from `halsampler`, the signal `run-index`
tells which program each belongs to. It must run under Debian's
/usr/bin/python3, where the `linuxcnc` module lives.
"""
import json
import os
import shutil
import subprocess
import sys
import time
import traceback

import linuxcnc

# How long the task may take to answer a command, or the motion to settle
COMMAND_TIMEOUT_S = 20.0
ERROR_KINDS = {linuxcnc.NML_ERROR: "error", linuxcnc.OPERATOR_ERROR: "error",
               linuxcnc.NML_TEXT: "text", linuxcnc.OPERATOR_TEXT: "text",
               linuxcnc.NML_DISPLAY: "display", linuxcnc.OPERATOR_DISPLAY: "display"}


def ini_path(argv):
    return argv[argv.index("-ini") + 1]


def halcmd(*args, script=None):
    done = subprocess.run(["halcmd", *args], input=script, capture_output=True, text=True,
                          timeout=COMMAND_TIMEOUT_S)
    if done.returncode != 0:
        raise RuntimeError("halcmd %s failed: %s%s" % (" ".join(args), done.stdout, done.stderr))


def set_hal(values):
    # One halcmd for all of them: each start of halcmd costs some 10 ms.
    if not values:
        return
    halcmd("-f", script="".join("setp %s %r\n" % item for item in values.items()))


class Session:
    def __init__(self, job):
        self.job = job
        self.stat = linuxcnc.stat()
        self.command = linuxcnc.command()
        self.errors = linuxcnc.error_channel()
        self.pending = []  # messages read while waiting for something else

    def check_rig(self):
        # A rig that was killed (a ctest timeout) leaves nobody to stop this
        # LinuxCNC: end the session instead of running on.
        try:
            os.kill(self.job["rig_pid"], 0)
        except ProcessLookupError:
            self.command.abort()
            raise RuntimeError("the rig (pid %d) is gone" % self.job["rig_pid"]) from None

    def wait(self, condition, timeout_s=COMMAND_TIMEOUT_S, what="the task"):
        deadline = time.monotonic() + timeout_s
        while time.monotonic() < deadline:
            self.stat.poll()
            self.drain()
            if condition():
                return
            self.check_rig()
            time.sleep(0.002)
        raise TimeoutError("waited %.0f s for %s" % (timeout_s, what))

    def drain(self):
        while True:
            message = self.errors.poll()
            if not message:
                return
            self.pending.append([ERROR_KINDS.get(message[0], str(message[0])), message[1]])

    def mode(self, mode):
        self.command.mode(mode)
        self.wait(lambda: self.stat.task_mode == mode, what="mode %d" % mode)

    def start(self):
        self.command.state(linuxcnc.STATE_ESTOP_RESET)
        self.wait(lambda: self.stat.task_state == linuxcnc.STATE_ESTOP_RESET, what="estop reset")
        self.command.state(linuxcnc.STATE_ON)
        self.wait(lambda: self.stat.task_state == linuxcnc.STATE_ON, what="machine on")
        self.mode(linuxcnc.MODE_MANUAL)
        self.command.home(-1)
        self.wait(lambda: all(self.stat.homed[:3]), what="homing")

    def to_machine_zero(self):
        self.mode(linuxcnc.MODE_MDI)
        self.command.mdi("G90 G53 G0 X0 Y0 Z0")
        self.wait(lambda: self.stat.interp_state == linuxcnc.INTERP_IDLE
                  and self.stat.inpos and self.stat.queue == 0
                  and all(abs(p) < 1e-9 for p in self.stat.actual_position[:3]),
                  what="the return to machine zero")

    def collect_files(self, run, folder):
        # LinuxCNC opens LOGOPEN/PROBEOPEN files relative to its working
        # directory, which `linuxcnc` sets to the INI file's folder.
        files = {}
        os.makedirs(folder, exist_ok=True)
        for name in run.get("files", []):
            source = os.path.join(self.job["workdir"], name)
            if os.path.exists(source):
                target = os.path.join(folder, name)
                shutil.move(source, target)
                with open(target, encoding="utf-8", errors="replace") as f:
                    files[name] = f.read()
        return files

    def run_program(self, index, run):
        set_hal(self.job["clear"])
        self.to_machine_zero()
        set_hal(run.get("hal", {}))
        time.sleep(0.01)  # a few servo periods with the new part before the start
        self.drain()
        self.pending = []
        self.mode(linuxcnc.MODE_AUTO)
        self.command.program_open(run["program"])
        halcmd("sets", "part-variant", "0")
        halcmd("sets", "run-index", str(index))
        started = time.monotonic()
        self.command.auto(linuxcnc.AUTO_RUN, 0)
        self.wait(lambda: self.stat.interp_state != linuxcnc.INTERP_IDLE, 5.0, "the start")
        pauses = 0
        deadline = started + run.get("timeout_s", 120.0)
        while True:
            if time.monotonic() > deadline:
                self.command.abort()
                raise TimeoutError("program %d did not end in %.0f s" % (index, run["timeout_s"]))
            self.check_rig()
            self.stat.poll()
            self.drain()
            if self.stat.interp_state == linuxcnc.INTERP_IDLE and self.stat.queue == 0:
                break
            if self.stat.paused and self.stat.interp_state == linuxcnc.INTERP_PAUSED:
                pauses += 1
                change = run.get("at_pause", {}).get(str(pauses))
                if change:
                    set_hal(change)
                    halcmd("sets", "part-variant", "1")
                self.command.auto(linuxcnc.AUTO_RESUME)
                self.wait(lambda: not self.stat.paused, 5.0, "the resume")
            time.sleep(0.001)
        self.wait(lambda: self.stat.inpos, 5.0, "in position")
        wall_s = time.monotonic() - started
        self.drain()
        # The samples after the end: a stretch after an error, to show that
        # nothing moves after it.
        error = any(kind == "error" for kind, _ in self.pending)
        time.sleep(self.job["after_error_s"] if error else 0.02)
        halcmd("sets", "run-index", "0")
        self.stat.poll()
        self.drain()
        messages = self.pending
        self.pending = []
        return {"messages": messages,
                "ended_on_error": any(kind == "error" for kind, _ in messages),
                "pauses": pauses,
                "wall_s": wall_s,
                "position": list(self.stat.actual_position[:3]),
                "probed": list(self.stat.probed_position[:3]),
                "files": self.collect_files(run, os.path.join(self.job["workdir"],
                                                              "run%d" % index))}


def main():
    ini = linuxcnc.ini(ini_path(sys.argv))
    with open(ini.find("PROBECYCLE", "JOB")) as f:
        job = json.load(f)
    result = {"runs": [], "error": None}
    sampler = None
    session = Session(job)
    try:
        with open(job["samples"], "w") as samples:
            sampler = subprocess.Popen(["halsampler", "-t"], stdout=samples)
            session.start()
            for index, run in enumerate(job["runs"], start=1):
                result["runs"].append(session.run_program(index, run))
            time.sleep(0.05)
    except Exception:  # reported to the rig, which fails the test with it
        result["error"] = traceback.format_exc()
    finally:
        if sampler is not None:
            sampler.terminate()
            sampler.wait(5)
        try:
            session.command.state(linuxcnc.STATE_OFF)
        except Exception:
            pass
        with open(job["result"] + ".tmp", "w") as f:
            json.dump(result, f, indent=1)
        os.replace(job["result"] + ".tmp", job["result"])


main()
