"""A headless LinuxCNC (Debian's linuxcnc-uspace 2.9) that runs our programs.

One session = one start of LinuxCNC on one machine (accelerations, servo
period, maximum velocity) running a list of programs, each on its own
simulated part. The drives are ideal loopbacks (joint.N.motor-pos-cmd =>
motor-pos-fb); the probe is built from HAL components in the servo thread
(below); `sampler` + `halsampler -t` log every servo period. Motion is
deterministic per servo period even though uspace is not hard real time, so
every time here is counted in samples x the servo period, never wall-clock.

The simulated probe works on the ball centre u = feedback + runout - centre
(sum2 per axis, the part's centre and the stylus runout in its offset): three
slabs, one per axis (two `comp`, `and2`: lo < u < hi; `xor2` inverts for a
pocket, whose material is outside the slab), a circle in XY (`hypot`, `comp`,
`xor2`: a bore trips outside its radius, a boss inside), each slab and the
circle gated by a top (`comp` on u_z, `and2`: a boss's or a web's material is
only below its top, so moves over it at the clearance height do not trip),
`or2` over the four, then `timedelay` for the interface delay. Sizes are
stylus-centre sizes, as in the scenario (a bore's diameter less the ball's).
The pretravel moves every threshold that far past the contact. A shape that is
off has its thresholds at +-1e9.

timedelay's timer starts at one period in the first period its input is true
and sets the output in the period where the timer reaches on-delay
(src/hal/components/timedelay.comp), so an on-delay D adds ceil(D/Ts) - 1
whole periods; the rig sets (n + 0.5) Ts for n periods, clear of that
rounding, and interface_delay_periods is the delay the model is given, n Ts.
"""
import dataclasses
import fcntl
import json
import math
import os
import shutil
import signal
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DRIVER = os.path.join(HERE, "lcnc_driver.py")
SYSTEM_PYTHON = "/usr/bin/python3"
LOCK_FILE = "/tmp/linuxcnc.lock"  # the `linuxcnc` script's
RIG_LOCK_FILE = "/tmp/probecycle-linuxcnc-rig.lock"
REALTIME = "/usr/lib/linuxcnc/realtime"
NOBODY_UID = 65534
FAR = 1e9  # a threshold no position reaches: the shape is off
# How long the samples go on after a program that ended on an error
AFTER_ERROR_S = 0.3
# What the programs open (LOGOPEN, PROBEOPEN), collected after each
PROGRAM_FILES = ("probecycle_log.txt", "probecycle_probes.txt")
LINUXCNC_PROCESSES = ("linuxcnc", "rtapi_app", "milltask", "linuxcncsvr")

# motion.motion-type (src/emc/nml_intf/motion_types.h)
MOTION_TRAVERSE, MOTION_FEED, MOTION_PROBING = 1, 2, 5

# The sampler's columns after the tag, in the HAL file's order
COLUMNS = ("x", "y", "z", "trip", "probe", "motion_type", "run", "variant")
SAMPLER_CFG = "fffbbsss"
AXES = "XYZ"


def unavailable_reason():
    """Why LinuxCNC cannot run here, or None when it can."""
    if shutil.which("linuxcnc") is None or shutil.which("halcmd") is None:
        return "linuxcnc is not on PATH (apt-get install linuxcnc-uspace)"
    if not os.access(SYSTEM_PYTHON, os.X_OK):
        return SYSTEM_PYTHON + " is missing"
    probe = subprocess.run([SYSTEM_PYTHON, "-c", "import linuxcnc, hal"], capture_output=True,
                           text=True)
    if probe.returncode != 0:
        return "the linuxcnc module is missing from " + SYSTEM_PYTHON + ": " + probe.stderr.strip()
    return None


@dataclasses.dataclass(frozen=True)
class Machine:
    """What the INI gives: the same on X, Y and Z."""
    max_accel_mm_s2: float = 800.0   # [AXIS_x] and [JOINT_n] MAX_ACCELERATION
    max_velocity_mm_s: float = 500.0  # [AXIS_x] MAX_VELOCITY and [TRAJ] MAX_LINEAR_VELOCITY
    servo_period_s: float = 0.001     # [EMCMOT] SERVO_PERIOD

    @property
    def servo_period_ns(self):
        return int(round(self.servo_period_s * 1e9))


@dataclasses.dataclass(frozen=True)
class Probe:
    pretravel_mm: float = 0.0
    interface_delay_periods: int = 0
    runout_mm: tuple = (0.0, 0.0)  # ball centre minus spindle centre in XY at spindle 0 deg


@dataclasses.dataclass
class Part:
    """A simulated part, positions in machine coordinates (the program starts at 0, 0, 0).

    surface: `axis` and `direction` of the touch; the material starts at
             `position` (the ball centre's coordinate at contact) and lies
             beyond it in the direction of travel.
    bore, boss: a circle in XY about `centre`, diameter `size_mm`.
    pocket, web: two walls along `axis` (X or Y), `size_mm` apart about `centre`.
    boss, web: material only below `top_mm` (Z); the others ignore it.
    """
    kind: str
    axis: str = "X"
    direction: int = 1
    position: float = 0.0
    centre: tuple = (0.0, 0.0, 0.0)
    size_mm: float = 0.0
    top_mm: float = FAR


def hal_clear():
    """Every shape off, no delay, no runout."""
    values = {}
    for a in "xyz":
        values.update({"pc-u%s.offset" % a: 0.0, "pc-%slo.in0" % a: FAR,
                       "pc-%shi.in1" % a: FAR, "pc-%sinv.in1" % a: 0})
    values.update({"pc-rc.in0": FAR, "pc-rinv.in1": 0, "pc-top.in1": FAR,
                   "pc-delay.on-delay": 0.0})
    return values


def runout_offsets(probe, turned):
    sign = -1.0 if turned else 1.0
    return (sign * probe.runout_mm[0], sign * probe.runout_mm[1])


def hal_part(part, probe, servo_period_s, turned=False):
    """The HAL parameters that put `part` under `probe` (spindle at 180 deg when `turned`)."""
    values = hal_clear()
    p = probe.pretravel_mm
    centre = part.centre if part.kind != "surface" else (0.0, 0.0, 0.0)
    runout = runout_offsets(probe, turned)
    values["pc-ux.offset"] = runout[0] - centre[0]
    values["pc-uy.offset"] = runout[1] - centre[1]
    values["pc-uz.offset"] = -centre[2]
    k = part.axis.lower()
    if part.kind == "surface":
        if part.direction > 0:
            values["pc-%slo.in0" % k] = part.position + p
        else:
            values["pc-%slo.in0" % k] = -FAR
            values["pc-%shi.in1" % k] = part.position - p
    elif part.kind == "pocket":
        values["pc-%slo.in0" % k] = -(part.size_mm / 2 + p)
        values["pc-%shi.in1" % k] = part.size_mm / 2 + p
        values["pc-%sinv.in1" % k] = 1
    elif part.kind == "web":
        values["pc-%slo.in0" % k] = -(part.size_mm / 2 - p)
        values["pc-%shi.in1" % k] = part.size_mm / 2 - p
    elif part.kind == "bore":
        values["pc-rc.in0"] = part.size_mm / 2 + p
    elif part.kind == "boss":
        values["pc-rc.in0"] = part.size_mm / 2 - p
        values["pc-rinv.in1"] = 1
    else:
        raise ValueError("unknown part kind " + part.kind)
    values["pc-top.in1"] = part.top_mm - centre[2] if part.top_mm < FAR else FAR
    n = probe.interface_delay_periods
    values["pc-delay.on-delay"] = (n + 0.5) * servo_period_s if n > 0 else 0.0
    return values


def trips(values, x, y, z):
    """The probe network of hal_part()'s values, before the delay, at one position."""
    u = (x + values["pc-ux.offset"], y + values["pc-uy.offset"], z + values["pc-uz.offset"])
    below_top = values["pc-top.in1"] > u[2]
    tripped = False
    for i, a in enumerate("xyz"):
        inside = u[i] > values["pc-%slo.in0" % a] and values["pc-%shi.in1" % a] > u[i]
        tripped |= (inside != bool(values["pc-%sinv.in1" % a])) and below_top
    outside = math.hypot(u[0], u[1]) > values["pc-rc.in0"]
    tripped |= (outside != bool(values["pc-rinv.in1"])) and below_top
    return tripped


def ini_text(machine, workdir, display):
    axes = []
    for a in AXES:
        axes.append("[AXIS_%s]\nMAX_VELOCITY = %r\nMAX_ACCELERATION = %r\n"
                    "MIN_LIMIT = -1000\nMAX_LIMIT = 1000\n"
                    % (a, machine.max_velocity_mm_s, machine.max_accel_mm_s2))
    for j in range(3):
        axes.append("[JOINT_%d]\nTYPE = LINEAR\nHOME = 0\nMAX_VELOCITY = %r\n"
                    "MAX_ACCELERATION = %r\nMIN_LIMIT = -1000\nMAX_LIMIT = 1000\n"
                    "FERROR = 100\nMIN_FERROR = 100\nHOME_SEARCH_VEL = 0\nHOME_SEQUENCE = 0\n"
                    % (j, machine.max_velocity_mm_s, machine.max_accel_mm_s2))
    return """[EMC]
VERSION = 1.1
MACHINE = probecycle-linuxcnc-test
[DISPLAY]
DISPLAY = {display}
[TASK]
TASK = milltask
CYCLE_TIME = 0.001
[RS274NGC]
PARAMETER_FILE = {workdir}/sim.var
[EMCMOT]
EMCMOT = motmod
COMM_TIMEOUT = 1.0
SERVO_PERIOD = {period}
[EMCIO]
EMCIO = io
CYCLE_TIME = 0.100
TOOL_TABLE = {workdir}/tool.tbl
[HAL]
HALFILE = {workdir}/machine.hal
[TRAJ]
COORDINATES = X Y Z
LINEAR_UNITS = mm
ANGULAR_UNITS = degree
DEFAULT_LINEAR_VELOCITY = 50
MAX_LINEAR_VELOCITY = {vmax!r}
[KINS]
KINEMATICS = trivkins
JOINTS = 3
{axes}[PROBECYCLE]
JOB = {workdir}/job.json
""".format(display=display, workdir=workdir, period=machine.servo_period_ns,
           vmax=machine.max_velocity_mm_s, axes="".join(axes))


def hal_text(sampler_depth):
    names = {
        "sum2": "pc-ux,pc-uy,pc-uz",
        "hypot": "pc-r",
        "comp": "pc-xlo,pc-xhi,pc-ylo,pc-yhi,pc-zlo,pc-zhi,pc-rc,pc-top",
        "and2": "pc-xin,pc-yin,pc-zin,pc-xg,pc-yg,pc-zg,pc-rg",
        "xor2": "pc-xinv,pc-yinv,pc-zinv,pc-rinv",
        "or2": "pc-or0,pc-or1,pc-or2",
        "timedelay": "pc-delay",
    }
    lines = ["loadrt [KINS]KINEMATICS",
             "loadrt [EMCMOT]EMCMOT servo_period_nsec=[EMCMOT]SERVO_PERIOD num_joints=[KINS]JOINTS"]
    lines += ["loadrt %s names=%s" % item for item in names.items()]
    lines.append("loadrt sampler depth=%d cfg=%s" % (sampler_depth, SAMPLER_CFG))
    # The probe chain runs after the motion controller, in data-flow order.
    functions = ["motion-command-handler", "motion-controller",
                 "pc-ux", "pc-uy", "pc-uz", "pc-r"]
    functions += ["pc-%s%s" % (a, s) for a in "xyz" for s in ("lo", "hi")] + ["pc-rc", "pc-top"]
    functions += ["pc-xin", "pc-yin", "pc-zin", "pc-xinv", "pc-yinv", "pc-zinv", "pc-rinv"]
    functions += ["pc-xg", "pc-yg", "pc-zg", "pc-rg", "pc-or0", "pc-or1", "pc-or2", "pc-delay",
                  "sampler.0"]
    lines += ["addf %s servo-thread" % f for f in functions]
    for j, a in enumerate("xyz"):
        lines.append("net %spos joint.%d.motor-pos-cmd => joint.%d.motor-pos-fb pc-u%s.in0 "
                     "sampler.0.pin.%d" % (a, j, j, a, j))
        lines.append("setp pc-u%s.gain0 1" % a)
        lines.append("net u%s pc-u%s.out => pc-%slo.in1 pc-%shi.in0" % (a, a, a, a))
        lines.append("net %s-in pc-%slo.out => pc-%sin.in0" % (a, a, a))
        lines.append("net %s-in-hi pc-%shi.out => pc-%sin.in1" % (a, a, a))
        lines.append("net %s-inside pc-%sin.out => pc-%sinv.in0" % (a, a, a))
        lines.append("net %s-material pc-%sinv.out => pc-%sg.in0" % (a, a, a))
        lines.append("net %s-trip pc-%sg.out" % (a, a))
    lines += ["net ux => pc-r.in0", "net uy => pc-r.in1",
              "net radius pc-r.out => pc-rc.in1",
              "net r-outside pc-rc.out => pc-rinv.in0",
              "net r-material pc-rinv.out => pc-rg.in0",
              "net r-trip pc-rg.out",
              "net uz => pc-top.in0",
              "net below-top pc-top.out => pc-xg.in1 pc-yg.in1 pc-zg.in1 pc-rg.in1",
              "net x-trip => pc-or0.in0", "net y-trip => pc-or0.in1",
              "net xy-trip pc-or0.out => pc-or1.in0", "net z-trip => pc-or1.in1",
              "net xyz-trip pc-or1.out => pc-or2.in0", "net r-trip => pc-or2.in1",
              "net trip pc-or2.out => pc-delay.in sampler.0.pin.3",
              "setp pc-delay.off-delay 0",
              "net probe pc-delay.out => motion.probe-input sampler.0.pin.4",
              "net mtype motion.motion-type => sampler.0.pin.5",
              "net run-index => sampler.0.pin.6",
              "net part-variant => sampler.0.pin.7",
              "net estop iocontrol.0.user-enable-out => iocontrol.0.emc-enable-in",
              "net tool-change iocontrol.0.tool-change => iocontrol.0.tool-changed",
              "net tool-prep iocontrol.0.tool-prepare => iocontrol.0.tool-prepared"]
    lines += ["setp %s %r" % item for item in hal_clear().items()]
    return "\n".join(lines) + "\n"


@dataclasses.dataclass
class Run:
    """One program of a session: the part it runs on, HAL changes at its pauses."""
    program: str
    part: Part
    probe: Probe = dataclasses.field(default_factory=Probe)
    turn_at_pause: int = 0  # at this M0 (1 = the first) the spindle turns 180 deg
    timeout_s: float = 60.0
    name: str = ""


@dataclasses.dataclass
class RunResult:
    run: Run
    hal: dict               # the part's HAL parameters (before any pause)
    turned_hal: dict        # after the spindle's turn at a pause (= hal without one)
    samples: list           # one dict per servo period: COLUMNS and "tag"
    messages: list          # [kind, text]: kind error, text or display
    ended_on_error: bool
    files: dict             # name -> text of the files the program wrote
    position: list          # where it stopped
    probed: list            # the last probe position
    pauses: int
    wall_s: float

    @property
    def errors(self):
        return [text for kind, text in self.messages if kind == "error"]


class SessionError(RuntimeError):
    pass


def _linuxcnc_processes():
    """[(pid, name)] of LinuxCNC's processes on this machine, whoever started them."""
    found = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open("/proc/%s/comm" % pid) as f:
                name = f.read().strip()
        except OSError:
            continue
        if name in LINUXCNC_PROCESSES:
            found.append((int(pid), name))
    return found


def _end_stale_rtapi(env=None, timeout_s=15.0):
    """Ends an rtapi_app that no LinuxCNC task owns any more (a session that was
    stopped, or killed): LinuxCNC's `realtime stop` (with the session's
    environment, which names its socket), then time to exit, then signals.
    True when none is left."""
    def stale():
        return [pid for pid, name in _linuxcnc_processes() if name == "rtapi_app"]
    if not stale():
        return True
    subprocess.run([REALTIME, "stop"], capture_output=True, timeout=30, env=env)
    deadline = time.monotonic() + timeout_s
    for sig in (None, signal.SIGTERM, signal.SIGKILL):
        if sig is not None:
            for pid in stale():
                try:
                    os.kill(pid, sig)
                except ProcessLookupError:
                    pass
            deadline = time.monotonic() + 5.0
        while time.monotonic() < deadline:
            if not stale():
                return True
            time.sleep(0.1)
    return not stale()


class _MachineLock:
    """Only one LinuxCNC runs on a machine (fixed shared memory keys, one lock file).

    Every rig on the machine, whatever build folder it runs from, takes
    RIG_LOCK_FILE (flock) for its whole session; ctest's RESOURCE_LOCK only
    orders the tests of one build. Holding it, a LinuxCNC still running is
    someone else's: wait for it, bounded. One with no task left (rtapi_app
    alone, or /tmp/linuxcnc.lock alone) was left by a killed run: stopped
    with LinuxCNC's own `realtime stop` (bounded), or the lock file removed,
    since `linuxcnc` would otherwise "clean up the other instance" itself.
    """

    def __init__(self, timeout_s):
        self.timeout_s = timeout_s
        self.file = None
        self.waited_s = 0.0

    def __enter__(self):
        started = time.monotonic()
        deadline = started + self.timeout_s
        self.file = open(RIG_LOCK_FILE, "a")
        while True:
            try:
                fcntl.flock(self.file, fcntl.LOCK_EX | fcntl.LOCK_NB)
                break
            except BlockingIOError:
                if time.monotonic() > deadline:
                    self.file.close()
                    raise SessionError("another ProbeCycle LinuxCNC session held %s for %.0f s"
                                       % (RIG_LOCK_FILE, self.timeout_s))
                time.sleep(0.5)
        while True:
            names = {name for _, name in _linuxcnc_processes()}
            if not names:
                if os.path.exists(LOCK_FILE):
                    os.remove(LOCK_FILE)
                break
            if names == {"rtapi_app"}:
                # Left by a session that ended (it may still be exiting) or was killed.
                if not _end_stale_rtapi():
                    self.__exit__()
                    raise SessionError("a stale rtapi_app survived `%s stop` and SIGKILL"
                                       % REALTIME)
                continue
            if time.monotonic() > deadline:
                self.__exit__()
                raise SessionError("another LinuxCNC is running (%s) and did not end in %.0f s"
                                   % (", ".join(sorted(names)), self.timeout_s))
            time.sleep(0.5)
        self.waited_s = time.monotonic() - started
        return self

    def __exit__(self, *exc):
        if self.file is not None:
            fcntl.flock(self.file, fcntl.LOCK_UN)
            self.file.close()
            self.file = None


def _stop(process, log, env):
    """Ends our own `linuxcnc` (its process group), bounded, then its realtime."""
    try:
        os.killpg(process.pid, signal.SIGTERM)  # the script's trap runs its Cleanup
        process.wait(20)
    except (ProcessLookupError, subprocess.TimeoutExpired):
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        process.wait(5)
    if not _end_stale_rtapi(env):
        log.write("rtapi_app did not end\n")
    if os.path.exists(LOCK_FILE) and not _linuxcnc_processes():
        os.remove(LOCK_FILE)


def _read_samples(path):
    samples = []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if len(fields) != len(COLUMNS) + 1:
                continue  # a line cut by the end of halsampler
            row = {"tag": int(fields[0])}
            for name, kind, text in zip(COLUMNS, SAMPLER_CFG, fields[1:]):
                row[name] = float(text) if kind == "f" else int(text)
            samples.append(row)
    return samples


def run_session(machine, runs, lock_timeout_s=300.0):
    """Runs `runs` in one LinuxCNC: (a RunResult per run, facts about the session).

    Each session runs in a folder of its own (LinuxCNC's working directory,
    where the programs' LOGOPEN and PROBEOPEN files land), removed afterwards
    unless PROBECYCLE_LINUXCNC_KEEP is set. Every wait is bounded: the driver
    stops a program after its Run.timeout_s, and the session is stopped after
    all of them plus a minute.
    """
    workdir = tempfile.mkdtemp(prefix="probecycle_lcnc_")
    os.chmod(workdir, 0o755)
    # rtapi_app refuses to run as root; as root it runs as RTAPI_UID and
    # makes its socket at RTAPI_FIFO_PATH, a file in a folder that user can
    # write (given a folder, rtapi_app waits for a master that never comes).
    fifo_dir = os.path.join(workdir, "rtapi")
    os.mkdir(fifo_dir)
    env = dict(os.environ)
    if os.geteuid() == 0:
        os.chown(fifo_dir, NOBODY_UID, -1)
        env["RTAPI_UID"] = str(NOBODY_UID)
        env["RTAPI_FIFO_PATH"] = os.path.join(fifo_dir, "rtapi_fifo")
    env.pop("DISPLAY", None)  # nothing may open a window
    display = os.path.join(workdir, "driver.py")
    shutil.copy(DRIVER, display)
    os.chmod(display, 0o755)
    ini = os.path.join(workdir, "machine.ini")
    with open(ini, "w") as f:
        f.write(ini_text(machine, workdir, display))
    # A FIFO of 4 s of samples: halsampler runs at ordinary priority, on a
    # CI machine busy with other tests.
    with open(os.path.join(workdir, "machine.hal"), "w") as f:
        f.write(hal_text(int(4.0 / machine.servo_period_s)))
    open(os.path.join(workdir, "tool.tbl"), "w").close()
    job_runs = []
    hal_values = []
    for run in runs:
        values = hal_part(run.part, run.probe, machine.servo_period_s)
        job_run = {"program": os.path.abspath(run.program), "hal": values,
                   "timeout_s": run.timeout_s, "files": list(PROGRAM_FILES)}
        turned = values
        if run.turn_at_pause:
            turned = hal_part(run.part, run.probe, machine.servo_period_s, turned=True)
            job_run["at_pause"] = {str(run.turn_at_pause): {
                k: v for k, v in turned.items() if values[k] != v}}
        job_runs.append(job_run)
        hal_values.append((values, turned))
    job = {"workdir": workdir, "samples": os.path.join(workdir, "samples.txt"),
           "result": os.path.join(workdir, "result.json"), "clear": hal_clear(),
           "after_error_s": AFTER_ERROR_S, "rig_pid": os.getpid(), "runs": job_runs}
    with open(os.path.join(workdir, "job.json"), "w") as f:
        json.dump(job, f, indent=1)

    log_path = os.path.join(workdir, "linuxcnc.log")
    timeout_s = 60.0 + sum(run.timeout_s for run in runs)
    with _MachineLock(lock_timeout_s) as lock, open(log_path, "w") as log:
        started = time.monotonic()
        process = subprocess.Popen(["linuxcnc", "-r", ini], cwd=workdir, env=env, stdout=log,
                                   stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                   start_new_session=True)
        try:
            process.wait(timeout_s)
        except subprocess.TimeoutExpired:
            raise SessionError("LinuxCNC did not end in %.0f s; its log: %s"
                               % (timeout_s, log_path)) from None
        finally:
            if process.poll() is None:
                _stop(process, log, env)
        session_s = time.monotonic() - started
    if not os.path.exists(job["result"]):
        with open(log_path) as f:
            raise SessionError("the driver wrote no result; LinuxCNC's log:\n" + f.read())
    with open(job["result"]) as f:
        result = json.load(f)
    if result["error"]:
        raise SessionError("the driver failed (the session's folder: %s):\n%s"
                           % (workdir, result["error"]))
    samples = _read_samples(job["samples"])
    tags = [s["tag"] for s in samples]
    gaps = [(a, b) for a, b in zip(tags, tags[1:]) if b != a + 1]
    if gaps:
        raise SessionError("halsampler lost samples between tags %s" % gaps[:5])
    if not samples or samples[-1]["run"] != 0:
        raise SessionError("halsampler stopped before the last program's end")
    by_run = {}
    for sample in samples:
        if sample["run"]:
            by_run.setdefault(sample["run"], []).append(sample)
    results = []
    for i, (run, (values, turned), out) in enumerate(zip(runs, hal_values, result["runs"]),
                                                     start=1):
        results.append(RunResult(run=run, hal=values, turned_hal=turned,
                                 samples=by_run.get(i, []), messages=out["messages"],
                                 ended_on_error=out["ended_on_error"], files=out["files"],
                                 position=out["position"], probed=out["probed"],
                                 pauses=out["pauses"], wall_s=out["wall_s"]))
    facts = {"workdir": workdir, "session_s": session_s, "waited_s": lock.waited_s,
             "samples": len(samples)}
    if os.environ.get("PROBECYCLE_LINUXCNC_KEEP"):
        print("the LinuxCNC session's folder: " + workdir, flush=True)
    else:
        shutil.rmtree(workdir, ignore_errors=True)
    return results, facts
