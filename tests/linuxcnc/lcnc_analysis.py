"""What a program did on the LinuxCNC rig, from its samples (one per servo period).

Times are counted in servo periods. A sample k holds the feedback the motion
controller put out in period k and the probe network's view of it in the same
period (the chain runs after the motion controller), so `trip` (the probe's
own output) turns true in the first period whose feedback is past the trigger
threshold, and `probe` (after the interface delay) in the period whose
feedback LinuxCNC latches as #5061.
"""
import dataclasses

import lcnc_rig

AXES = ("x", "y", "z")


def position(sample):
    return (sample["x"], sample["y"], sample["z"])


def moving_indices(samples):
    """Indices k whose position differs from sample k - 1's: the axes moved in period k."""
    return [k for k in range(1, len(samples)) if position(samples[k]) != position(samples[k - 1])]


def motion_time_s(samples, servo_period_s):
    """First to last period in which any axis moves, both counted."""
    moving = moving_indices(samples)
    if not moving:
        return 0.0
    return (moving[-1] - moving[0] + 1) * servo_period_s


def motion_type_at(samples, index):
    """The motion type of the move running at `index`: motion.motion-type reads 0 in the
    last periods of a move, so the last non-zero type at or before it."""
    for k in range(index, -1, -1):
        if samples[k]["motion_type"]:
            return samples[k]["motion_type"]
    return 0


def segments(samples):
    """The moves: runs of periods with the same direction of motion on every axis (a block
    change splits there: exact stop turns or stops the axes), as (first, last) sample
    indices, and the idle periods (no axis moves) between consecutive runs."""
    runs = []
    direction = None
    for k in range(1, len(samples)):
        step = tuple((b > a) - (b < a) for a, b in zip(position(samples[k - 1]),
                                                       position(samples[k])))
        if step == (0, 0, 0):
            direction = None
            continue
        if step != direction or not runs or runs[-1][1] != k - 1:
            runs.append([k, k])
        runs[-1][1] = k
        direction = step
    idle = [b[0] - a[1] - 1 for a, b in zip(runs, runs[1:])]
    return [tuple(r) for r in runs], idle


def _crossing(values, a, b):
    """Where along a -> b the probe network first reads true (a false, b true), by bisection."""
    lo, hi = 0.0, 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        p = [a[i] + mid * (b[i] - a[i]) for i in range(3)]
        if lcnc_rig.trips(values, *p):
            hi = mid
        else:
            lo = mid
    return [a[i] + hi * (b[i] - a[i]) for i in range(3)]


@dataclasses.dataclass
class Touch:
    axis: int              # 0 X, 1 Y, 2 Z
    direction: int         # +1 / -1 along that axis
    speed_mm_s: float      # at the trigger
    motion_type: int       # 5 a probing move (G38.x)
    contact: list          # where the ball met the surface (no pretravel)
    trigger: list          # where the probe's threshold was crossed
    trip_index: int        # first sample with the probe's own output (before the delay)
    seen_index: int        # first sample with the probe input (after the interface delay)
    seen: list             # that sample's feedback: LinuxCNC's #5061-#5063
    stop: list             # where the axis came to rest after the trip

    def along(self, p):
        return self.direction * p[self.axis]

    @property
    def overtravel_mm(self):
        """Past the surface, along the move, to the stop (the model's overtravel)."""
        return self.along(self.stop) - self.along(self.contact)

    @property
    def pretravel_mm(self):
        return self.along(self.trigger) - self.along(self.contact)

    def trip_error_mm(self, interface_delay_s):
        """#5061 past the trigger less the travel during the interface delay:
        the scan wait's travel d, in [0, v Ts]."""
        return (self.along(self.seen) - self.along(self.trigger)
                - self.speed_mm_s * interface_delay_s)


def touches(result, servo_period_s):
    """Every trip of the probe in a program's samples, in order."""
    samples = result.samples
    values_by_variant = {0: result.hal, 1: result.turned_hal}
    found = []
    for k in range(1, len(samples)):
        if not samples[k]["trip"] or samples[k - 1]["trip"]:
            continue
        a, b = position(samples[k - 1]), position(samples[k])
        step = [b[i] - a[i] for i in range(3)]
        axis = max(range(3), key=lambda i: abs(step[i]))
        direction = 1 if step[axis] > 0 else -1
        values = values_by_variant[samples[k]["variant"]]
        trigger = _crossing(values, a, b)
        # The contact: the same network without the pretravel, searched back
        # from the trip (a pretravel may span several periods).
        p = result.run.probe.pretravel_mm
        bare = lcnc_rig.hal_part(result.run.part,
                                 dataclasses.replace(result.run.probe, pretravel_mm=0.0),
                                 servo_period_s, turned=samples[k]["variant"] == 1)
        j = k
        while j > 0 and lcnc_rig.trips(bare, *position(samples[j - 1])):
            j -= 1
        contact = _crossing(bare, position(samples[j - 1]), position(samples[j])) \
            if p > 0 else trigger
        seen_index = k
        while seen_index < len(samples) and not samples[seen_index]["probe"]:
            seen_index += 1
        stop_index = seen_index
        while stop_index + 1 < len(samples) and \
                direction * (samples[stop_index + 1][AXES[axis]]
                             - samples[stop_index][AXES[axis]]) > 0:
            stop_index += 1
        found.append(Touch(axis=axis, direction=direction,
                           speed_mm_s=abs(step[axis]) / servo_period_s,
                           motion_type=motion_type_at(samples, k), contact=contact,
                           trigger=trigger, trip_index=k, seen_index=seen_index,
                           seen=list(position(samples[min(seen_index, len(samples) - 1)])),
                           stop=list(position(samples[stop_index]))))
    return found


def logged_touches(text):
    """The LOG file's recorded touches: [(n, [x, y, z])] from "probecycle touch n x y z"."""
    out = []
    for line in text.splitlines():
        fields = line.split()
        if len(fields) == 6 and fields[:2] == ["probecycle", "touch"]:
            out.append((int(fields[2]), [float(v) for v in fields[3:]]))
    return out


def logged_result(text):
    """The LOG file's result line: {"S": size, "X": .., "Y": .., "D": .., "T": ..} from
    "probecycle result S s X x Y y D d T t", or None; and whether it logged
    "probecycle out of tolerance"."""
    result = None
    out_of_tolerance = False
    for line in text.splitlines():
        fields = line.split()
        if len(fields) == 12 and fields[:2] == ["probecycle", "result"]:
            result = {fields[i]: float(fields[i + 1]) for i in range(2, 12, 2)}
        if fields == ["probecycle", "out", "of", "tolerance"]:
            out_of_tolerance = True
    return result, out_of_tolerance


def model_overtravel_bounds(model_mm, speed_mm_s, servo_period_s, accel_mm_s2):
    """The model takes the worst scan wait, a full period; LinuxCNC's d lies in [0, v Ts).
    Its servo thread brakes in whole periods, which ends up to a Ts^2/8 past v^2/2a
    (0.03-0.10 um measured at 800 mm/s^2). So a measured overtravel lies in
    [model - v Ts, model + a Ts^2/8]."""
    return (model_mm - speed_mm_s * servo_period_s,
            model_mm + accel_mm_s2 * servo_period_s ** 2 / 8)
