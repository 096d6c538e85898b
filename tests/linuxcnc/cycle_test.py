#!/usr/bin/python3
"""The tuned cycle on LinuxCNC's motion controller against the model.

`probecycle-cli program cycle --dialect linuxcnc` writes each case's program;
one LinuxCNC session per machine (`--machine a` or `b`, the acceleration) runs
them all, each on its simulated part. For every case:
- the program ends without an error (with the part off its nominal position,
  by less than cycle.part_position_uncertainty_mm, too);
- the model's cycle time (`evaluate`) lies within 1 % of the measured motion
  time (first to last servo period in which an axis moves), on the cases with
  the part at its nominal position: off it, every approach and return is
  longer or shorter by the offset, which the model does not know;
- every touch trips at its programmed feed and stops where the model says:
  LinuxCNC stops d + 2 v Ts + v^2/2a past the trigger point, d in [0, v Ts)
  the travel between the trigger and the servo period that sees it; the model
  takes the worst case, d = v Ts, so the measured overtravel lies in
  [model - v Ts, model] (and up to a Ts^2/8 more: the servo thread brakes in
  whole periods);
- #5061-#5063 as the program logged them are the feedback of the period that
  saw the probe: past the trigger point by the interface delay's travel plus
  d in [0, v Ts).
"""
import argparse
import json
import sys
import time
import unittest


sys.dont_write_bytecode = True  # no __pycache__ beside the sources

import lcnc_analysis
import lcnc_rig
import lcnc_support

TOLERANCE_MM = 2e-6  # halsampler and LinuxCNC's LOG print positions to 1 nm
TIME_TOLERANCE = 0.01

MACHINES = {
    "a": lcnc_rig.Machine(max_accel_mm_s2=800.0),
    "b": lcnc_rig.Machine(max_accel_mm_s2=400.0),
}

P0 = lcnc_rig.Probe()
P5 = lcnc_rig.Probe(pretravel_mm=0.005)
P5D2 = lcnc_rig.Probe(pretravel_mm=0.005, interface_delay_periods=2)
P20D1 = lcnc_rig.Probe(pretravel_mm=0.020, interface_delay_periods=1)

FEATURE = {"feature_size_mm": 20.0, "clearance_mm": 5.0, "position_feed_mm_min": 5000.0}
# The surfaces' start, long enough that a cycle of few blocks lasts over a
# second: LinuxCNC's task waits a few servo periods more or less at a block
# change from run to run (uspace is not hard real time), and 1 % of a 0.5 s
# cycle of 4 blocks is less than that spread.
LONG_START = {"approach_mm": 20.0}
SINGLE = {"strategy": "single_touch"}
TWO = {"strategy": "two_touch"}

# Per machine, name: (--axis or None, the simulated probe, the cycle's keys,
# the part's offset from nominal in mm: along the touch for a surface, of the
# centre for a feature, (x, y) or along --axis)
CASES = {
    "a": {
        "surface_x_plus_two_touch_3000": ("X+", P5, dict(TWO, **LONG_START, probe_feed_mm_min=3000,
                                                             measure_feed_mm_min=200), 0.0),
        "surface_x_minus_single_4000_repeats": ("X-", P0, dict(SINGLE, **LONG_START,
                                                                   probe_feed_mm_min=4000,
                                                                   repeats=2), 0.0),
        "surface_y_plus_two_touch_4000_repeats": ("Y+", P5D2, dict(
            TWO, **LONG_START, probe_feed_mm_min=4000, measure_feed_mm_min=300, repeats=2), 0.0),
        "surface_y_minus_single_300": ("Y-", P20D1, dict(SINGLE, probe_feed_mm_min=300), 0.0),
        "surface_z_minus_two_touch_uncertain_far": ("Z-", P5, dict(
            TWO, probe_feed_mm_min=2000, measure_feed_mm_min=100,
            part_position_uncertainty_mm=1.0), 0.6),
        "surface_z_plus_single_uncertain_near": ("Z+", P5D2, dict(
            SINGLE, probe_feed_mm_min=1000, part_position_uncertainty_mm=0.5), -0.4),
        "bore_two_touch_3000": (None, P5, dict(FEATURE, **TWO, feature="bore",
                                               probe_feed_mm_min=3000,
                                               measure_feed_mm_min=200), 0.0),
        "boss_single_2000_repeats": (None, P0, dict(FEATURE, **SINGLE, feature="boss",
                                                    probe_feed_mm_min=2000, repeats=2), 0.0),
        "pocket_x_two_touch_4000": ("X+", P5D2, dict(FEATURE, **TWO, feature="pocket",
                                                     feature_size_mm=40.0,
                                                     probe_feed_mm_min=4000,
                                                     measure_feed_mm_min=300), 0.0),
        "web_y_single_3000": ("Y+", P5, dict(FEATURE, **SINGLE, feature="web",
                                             probe_feed_mm_min=3000), 0.0),
    },
    "b": {
        "surface_x_plus_single_4000": ("X+", P5, dict(SINGLE, **LONG_START, probe_feed_mm_min=4000),
                                       0.0),
        "surface_z_minus_two_touch_3000": ("Z-", P5D2, dict(TWO, **LONG_START, probe_feed_mm_min=3000,
                                                            measure_feed_mm_min=200), 0.0),
        "surface_y_minus_two_touch_1000": ("Y-", P20D1, dict(TWO, **LONG_START, probe_feed_mm_min=1000,
                                                             measure_feed_mm_min=100), 0.0),
        "bore_single_4000_uncertain": (None, P5, dict(
            FEATURE, **SINGLE, feature="bore", feature_size_mm=24.0, probe_feed_mm_min=4000,
            approach_mm=7.0, part_position_uncertainty_mm=0.5), (0.3, -0.4)),
        "bore_single_2000": (None, P0, dict(FEATURE, **SINGLE, feature="bore",
                                            probe_feed_mm_min=2000), 0.0),
        "boss_two_touch_3000_uncertain": (None, P5D2, dict(
            FEATURE, **TWO, feature="boss", probe_feed_mm_min=3000, measure_feed_mm_min=150,
            part_position_uncertainty_mm=0.5), (-0.4, 0.2)),
        "boss_two_touch_1500": (None, P5, dict(FEATURE, **TWO, feature="boss",
                                               probe_feed_mm_min=1500,
                                               measure_feed_mm_min=200), 0.0),
        "pocket_y_single_2000_repeats": ("Y+", P0, dict(FEATURE, **SINGLE, feature="pocket",
                                                        probe_feed_mm_min=2000, repeats=2), 0.0),
        "web_x_two_touch_4000": ("X+", P5, dict(FEATURE, **TWO, feature="web",
                                                probe_feed_mm_min=4000, measure_feed_mm_min=250,
                                                approach_mm=7.0), 0.0),
    },
}


def part_for(cycle, axis, offset, model_scenario):
    """The simulated part where the program expects it, moved by `offset`."""
    feature = cycle.get("feature", "surface")
    approach = model_scenario["cycle"]["approach_mm"]
    size = model_scenario["cycle"]["feature_size_mm"]
    clearance = model_scenario["cycle"]["clearance_mm"]
    if feature == "surface":
        direction = 1 if axis[1] == "+" else -1
        return lcnc_rig.Part("surface", axis=axis[0], direction=direction,
                             position=direction * (approach + offset))
    centre = (offset[0], offset[1], 0.0) if isinstance(offset, tuple) else (
        (offset, 0.0, 0.0) if axis and axis[0] == "X" else (0.0, offset, 0.0))
    # A boss or web stands `clearance` above the measuring depth: its top
    # lies between the ball's start and that depth.
    top = -clearance / 2 if feature in ("boss", "web") else lcnc_rig.FAR
    return lcnc_rig.Part(feature, axis=axis[0] if axis else "X", centre=centre, size_mm=size,
                         top_mm=top)


class Case:
    def __init__(self, name, machine, axis, probe, cycle, offset, folder):
        self.name, self.probe, self.offset = name, probe, offset
        self.cycle = dict(cycle)
        path = lcnc_support.scenario(machine, probe, self.cycle, folder, name)
        if self.cycle.get("strategy") == "two_touch" and "backoff_mm" not in self.cycle:
            # The backoff that clears the fast touch's stop, as recommended.
            backoff = lcnc_support.cli_json("evaluate", path)["recommended_backoff_mm"]
            self.cycle["backoff_mm"] = backoff
            path = lcnc_support.scenario(machine, probe, self.cycle, folder, name)
        self.model = lcnc_support.cli_json("evaluate", path)
        with open(path) as f:
            model_scenario = json.load(f)
        options = ("--axis", axis) if axis else ()
        self.program, self.plan, _ = lcnc_support.program("cycle", path, folder, name, *options)
        self.probes = [s for s in self.plan["steps"] if s["step"] == "probe"]
        self.blocks = sum(1 for s in self.plan["steps"] if s["step"] != "pause")
        self.part = part_for(cycle, axis, offset, model_scenario)
        self.nominal = offset == 0.0
        self.result = None

    def run(self):
        return lcnc_rig.Run(program=self.program, part=self.part, probe=self.probe,
                            timeout_s=10.0 + 3.0 * self.model["cycle_time_s"], name=self.name)

    def model_touch(self, step):
        two_touch = self.cycle.get("strategy") == "two_touch"
        return self.model["measuring_touch" if two_touch and step["recorded"] else "first_touch"]


class CycleOnLinuxCnc(unittest.TestCase):
    machine_key = "a"
    cases = {}
    figures = []

    @classmethod
    def setUpClass(cls):
        cls.folder = lcnc_support.temp_folder(cls, "probecycle_cycle_")
        cls.machine = MACHINES[cls.machine_key]
        started = time.monotonic()
        cls.cases = {name: Case(name, cls.machine, *spec, cls.folder)
                     for name, spec in CASES[cls.machine_key].items()}
        programs_s = time.monotonic() - started
        results, facts = lcnc_rig.run_session(cls.machine, [c.run() for c in cls.cases.values()])
        for case, result in zip(cls.cases.values(), results):
            case.result = result
            case.touches = lcnc_analysis.touches(result, cls.machine.servo_period_s)
        print("machine %s (a = %g mm/s^2, Ts = %g s): %d programs written in %.1f s, "
              "LinuxCNC session %.1f s"
              % (cls.machine_key, cls.machine.max_accel_mm_s2, cls.machine.servo_period_s,
                 len(cls.cases), programs_s, facts["session_s"]), flush=True)

    @classmethod
    def tearDownClass(cls):
        # The figures: the model against LinuxCNC, per case. Overtravel: the
        # model's (worst case) and the measured range, per kind of touch.
        Ts = cls.machine.servo_period_s
        print("\n%-40s %7s %7s %6s %8s %5s  %-22s %-22s %s" % (
            "case", "model s", "meas s", "diff %", "ms/block", "idle", "first touch OT mm",
            "measuring touch OT mm", "trip err/vTs"))
        for case in cls.cases.values():
            if case.result is None:
                continue
            measured = lcnc_analysis.motion_time_s(case.result.samples, Ts)
            model = case.model["cycle_time_s"]
            _, idle = lcnc_analysis.segments(case.result.samples)
            kinds = {}
            trips = []
            for step, touch in zip(case.probes, case.touches):
                two_touch = case.cycle.get("strategy") == "two_touch"
                kind = "measuring_touch" if two_touch and step["recorded"] else "first_touch"
                kinds.setdefault(kind, []).append(touch.overtravel_mm)
                trips.append(touch.trip_error_mm(case.probe.interface_delay_periods * Ts)
                             / (touch.speed_mm_s * Ts))
            columns = []
            for kind in ("first_touch", "measuring_touch"):
                got = kinds.get(kind)
                columns.append("%.4f/%.4f-%.4f" % (case.model[kind]["overtravel_mm"], min(got),
                                                   max(got)) if got else "-")
            print("%-40s %7.4f %7.4f %+6.2f %8.2f %5d  %-22s %-22s %s" % (
                case.name + ("" if case.nominal else " (off)"), model, measured,
                100 * (measured - model) / model, 1000 * (measured - model) / case.blocks,
                sum(idle), *columns,
                "%.2f-%.2f" % (min(trips), max(trips)) if trips else "-"))

    def test_machine_section_is_what_linuxcnc_does(self):
        # The scenario's machine, from `probecycle-cli machine linuxcnc` on the
        # rig's INI, is the one these measurements bear out.
        if not lcnc_support.has_machine_linuxcnc():
            self.skipTest("probecycle-cli has no `machine linuxcnc`")
        section = lcnc_support.machine_section(self.machine)
        for key, value in lcnc_support.expected_machine_section(self.machine).items():
            self.assertEqual(section[key], value, key)

    def case(self, name):
        case = self.cases[name]
        self.assertIsNotNone(case.result, "the session did not run")
        return case

    def check_ends_without_error(self, name):
        case = self.case(name)
        self.assertFalse(case.result.ended_on_error, case.result.errors)
        self.assertEqual(len(case.touches), len(case.probes),
                         "probes tripped: %d, the plan's probing moves: %d"
                         % (len(case.touches), len(case.probes)))
        # Every trip is a probing move's (G38.2); none on a protected move.
        for touch in case.touches:
            self.assertEqual(touch.motion_type, lcnc_rig.MOTION_PROBING)

    def check_cycle_time(self, name):
        case = self.case(name)
        if not case.nominal:
            self.skipTest("the part is off its nominal position: the model's time is nominal")
        measured = lcnc_analysis.motion_time_s(case.result.samples, self.machine.servo_period_s)
        model = case.model["cycle_time_s"]
        self.assertLessEqual(abs(measured - model), TIME_TOLERANCE * measured,
                             "model %.4f s, LinuxCNC %.4f s (%+.2f %%, %+.2f ms a block over %d "
                             "blocks)" % (model, measured, 100 * (measured - model) / model,
                                          1000 * (measured - model) / case.blocks, case.blocks))

    def check_overtravel(self, name):
        case = self.case(name)
        Ts = self.machine.servo_period_s
        self.assertEqual(len(case.touches), len(case.probes))
        for i, (step, touch) in enumerate(zip(case.probes, case.touches), start=1):
            v = step["feed_mm_min"] / 60.0
            self.assertAlmostEqual(touch.speed_mm_s, v, delta=1e-3 * v,
                                   msg="touch %d trips below its feed" % i)
            model = case.model_touch(step)["overtravel_mm"]
            low, high = lcnc_analysis.model_overtravel_bounds(model, v, Ts,
                                                              self.machine.max_accel_mm_s2)
            self.assertTrue(low - TOLERANCE_MM <= touch.overtravel_mm <= high + TOLERANCE_MM,
                            "touch %d (%s): overtravel %.6f mm outside [%.6f, %.6f]: the "
                            "model's %.6f mm less v Ts = %.6f, plus a Ts^2/8"
                            % (i, step["text"], touch.overtravel_mm, low, high, model, v * Ts))

    def check_trip_positions(self, name):
        case = self.case(name)
        Ts = self.machine.servo_period_s
        delay_s = case.probe.interface_delay_periods * Ts
        recorded = [t for s, t in zip(case.probes, case.touches) if s["recorded"]]
        logged = lcnc_analysis.logged_touches(case.result.files.get("probecycle_log.txt", ""))
        self.assertEqual([n for n, _ in logged], list(range(1, len(recorded) + 1)))
        for (n, position), touch in zip(logged, recorded):
            for axis in range(3):
                self.assertAlmostEqual(position[axis], touch.seen[axis], delta=TOLERANCE_MM,
                                       msg="touch %d: #506%d logged" % (n, axis + 1))
            error = touch.trip_error_mm(delay_s)
            self.assertTrue(-TOLERANCE_MM <= error <= touch.speed_mm_s * Ts + TOLERANCE_MM,
                            "touch %d: #5061 is %.6f mm past the trigger point after the "
                            "interface delay's travel, outside [0, v Ts = %.6f]"
                            % (n, error, touch.speed_mm_s * Ts))


def add_case_tests(cls, names):
    for name in names:
        for check in ("ends_without_error", "cycle_time", "overtravel", "trip_positions"):
            def test(self, name=name, check=check):
                getattr(self, "check_" + check)(name)
            setattr(cls, "test_%s_%s" % (name, check), test)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(add_help=False)
    parser.add_argument("--machine", choices=sorted(MACHINES), default="a")
    known, rest = parser.parse_known_args()
    sys.argv = [sys.argv[0], *rest]
    CycleOnLinuxCnc.machine_key = known.machine
    add_case_tests(CycleOnLinuxCnc, CASES[known.machine])
    lcnc_support.main()
