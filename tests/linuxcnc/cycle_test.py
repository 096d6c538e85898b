#!/usr/bin/python3
"""The tuned cycle on LinuxCNC's motion controller against the model.

`probecycle-cli program cycle --dialect linuxcnc` writes each case's program;
one LinuxCNC session per machine (`--machine a` or `b`, the acceleration) runs
them all, each on its simulated part. For every case:
- the program ends without an error (with the part off its nominal position,
  by less than cycle.part_position_uncertainty_mm, too);
- the model's cycle time (`evaluate`) lies within 1 % plus 1 ms a block of the
  measured motion time (first to last servo period in which an axis moves;
  the block change is a fit, known to about 1 ms a block, and LinuxCNC's task
  waits longer or shorter from run to run), on the cases with
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
  d in [0, v Ts);
- the feature's result the program computed and logged (#114-#118, the
  "probecycle result" line) is the one `probecycle-cli import` computes from
  the logged touches (to 1e-5 mm), and it is the simulated part's known
  geometry (its size, centre or position as a calibrated probe sees it: each
  point past its surface by the pretravel, the interface delay's travel and
  the mean scan wait v Ts/2, which a calibration takes out; with the ball
  diameter given to the program) within the model's scan range v Ts, the
  range each point's wait lies in: a size within v Ts, a centre or a surface
  within v Ts/2. The model's expanded uncertainty (k = 2), which takes the
  touches' waits as independent, is printed beside: on this rig they are not
  (every touch at a feed meets its wall at the same phase of the servo
  period, trip err/vTs above), so a size can lie past it; the tolerance flag
  where the case sets one.
"""
import argparse
import json
import os
import sys
import time
import unittest


sys.dont_write_bytecode = True  # no __pycache__ beside the sources

import lcnc_analysis
import lcnc_rig
import lcnc_support

TOLERANCE_MM = 2e-6  # halsampler and LinuxCNC's LOG print positions to 1 nm
TIME_TOLERANCE = 0.01
# The model's block change (core/program/linuxcnc_ini.cpp: 2 servo periods and
# 1.6 task cycles) is a fit to LinuxCNC 2.9 runs, the measurements within
# about 1 ms a block of it; on this rig the task's wait varied from run to run
# by as much (pocket_x_two_touch_4000, 12 blocks: +1.37 to +2.12 ms a block in seven
# runs, two of them over the 1 % alone).
BLOCK_TOLERANCE_S = 0.001

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


# Cases whose program is given a ball diameter (--ball-diameter-mm): the
# simulated part is in stylus-centre coordinates, so the result is its size
# plus (pocket, bore) or less (web, boss) that, a surface half of it further.
BALL_MM = {"bore_two_touch_3000": 6.0, "web_y_single_3000": 4.0,
           "surface_y_minus_single_300": 2.0, "boss_two_touch_1500": 6.0}
# Cases with a size tolerance (flag): one far inside, one the calibration
# offset (about 10 um between the stylus centres) takes out of it.
TOLERANCE = {"boss_two_touch_1500": 0.5, "pocket_x_two_touch_4000": 0.001,
             "pocket_y_single_2000_repeats": 0.5, "bore_single_2000": 0.001}


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
        if name in TOLERANCE:
            self.cycle.update(size_tolerance_mm=TOLERANCE[name], tolerance_action="flag")
        self.machine = machine
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
        self.ball_mm = BALL_MM.get(name, 0.0)
        if self.ball_mm:
            options += ("--ball-diameter-mm", str(self.ball_mm))
        self.folder = folder
        self.program, self.plan, self.plan_path = lcnc_support.program("cycle", path, folder,
                                                                        name, *options)
        self.probes = [s for s in self.plan["steps"] if s["step"] == "probe"]
        self.blocks = sum(1 for s in self.plan["steps"] if s["step"] != "pause")
        self.part = part_for(cycle, axis, offset, model_scenario)
        self.nominal = offset == 0.0
        self.result = None

    def run(self):
        return lcnc_rig.Run(program=self.program, part=self.part, probe=self.probe,
                            timeout_s=10.0 + 3.0 * self.model["cycle_time_s"], name=self.name)

    def expected_result(self):
        """The part's known geometry as a calibrated probe with the program's ball sees it:
        (size or position, centre x, centre y), a centre None where not measured."""
        Ts = self.machine.servo_period_s
        recorded = [s for s in self.plan["steps"] if s["step"] == "probe" and s["recorded"]]
        v = recorded[0]["feed_mm_min"] / 60.0
        # Past its surface a recorded point lies the pretravel, the interface
        # delay's travel and d in [0, v Ts): a calibration takes out their mean.
        past = self.probe.pretravel_mm + v * self.probe.interface_delay_periods * Ts + v * Ts / 2
        part = self.part
        if part.kind == "surface":
            return part.position + part.direction * (past + self.ball_mm / 2), None, None
        inside = part.kind in ("pocket", "bore")
        size = part.size_mm + (1 if inside else -1) * (2 * past + self.ball_mm)
        if part.kind in ("bore", "boss"):
            return size, part.centre[0], part.centre[1]
        x = part.centre[0] if part.axis == "X" else None
        y = part.centre[1] if part.axis == "Y" else None
        return size, x, y

    def imported(self, log_text):
        log = os.path.join(self.folder, self.name + ".log.txt")
        with open(log, "w") as f:
            f.write(log_text)
        return lcnc_support.cli_json("import", "--dialect", "linuxcnc", "--plan",
                                     self.plan_path, log, "--json")

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

    results = []

    @classmethod
    def tearDownClass(cls):
        # The figures of the feature results: the program's, the import's, the
        # part's (as a calibrated probe sees it) and the model's uncertainty.
        if cls.results:
            print("\n%-40s %12s %12s %12s %8s %8s %8s  %s" % (
                "case", "program mm", "import mm", "part mm", "diff um", "vTs um", "U um",
                "centre diff/U um"))
            for row in cls.results:
                print("%-40s %12.6f %12.6f %12.6f %+8.2f %8.2f %8.2f  %s" % row)
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
        self.assertLessEqual(abs(measured - model),
                             TIME_TOLERANCE * measured + BLOCK_TOLERANCE_S * case.blocks,
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


    def check_feature_result(self, name):
        case = self.case(name)
        text = case.result.files.get("probecycle_log.txt", "")
        program, flagged = lcnc_analysis.logged_result(text)
        self.assertIsNotNone(program, "no result line in the log:\n" + text)
        imported = case.imported(text)
        surface = imported["feature"] == "surface"
        size = imported["position_mm" if surface else "size_mm"]
        centre = (imported.get("centre_x_mm"), imported.get("centre_y_mm"))
        # The program's own arithmetic is the import's.
        self.assertAlmostEqual(program["S"], size, delta=1e-5)
        for key, value in zip("XY", centre):
            self.assertAlmostEqual(program[key], value or 0.0, delta=1e-5, msg=key)
        if not surface:
            self.assertAlmostEqual(program["D"], imported["deviation_mm"], delta=1e-5)
        tolerance = imported["tolerance"]
        out = bool(tolerance and tolerance["out_of_tolerance"])
        self.assertEqual(program["T"], 1.0 if out else 0.0)
        self.assertEqual(flagged, out)
        if name in TOLERANCE:
            self.assertIsNotNone(tolerance)
            self.assertEqual(out, TOLERANCE[name] < 0.01, "the flag the case expects")
        # The known geometry within the model's scan range (a point's wait
        # lies in [0, v Ts): its calibrated mean is off by v Ts/2 at most).
        expected = case.expected_result()
        scan = case.model["scan_range_mm"]
        bound = scan / 2 if surface else scan
        self.assertLessEqual(abs(size - expected[0]), bound + TOLERANCE_MM,
                             "%s %.6f mm, the part %.6f mm, beyond the model's v Ts %.6f mm"
                             % ("position" if surface else "size", size, expected[0], bound))
        centre_text = "-"
        for axis, (got, want) in enumerate(zip(centre, expected[1:])):
            self.assertEqual(got is None, want is None, "XY"[axis])
            if got is None:
                continue
            self.assertLessEqual(abs(got - want), scan / 2 + TOLERANCE_MM,
                                 "centre %s %.6f mm, the part %.6f mm, v Ts/2 %.6f"
                                 % ("XY"[axis], got, want, scan / 2))
            centre_text = ("" if centre_text == "-" else centre_text + " ") + "%s %+.2f/%.2f" % (
                "XY"[axis], 1000 * (got - want), 1000 * imported["centre_uncertainty_mm"])
        u_size = imported["position_uncertainty_mm" if surface else "size_uncertainty_mm"]
        type(self).results.append((name, program["S"], size, expected[0],
                                   1000 * (size - expected[0]), 1000 * bound, 1000 * u_size,
                                   centre_text))


def add_case_tests(cls, names):
    for name in names:
        for check in ("ends_without_error", "cycle_time", "overtravel", "trip_positions",
                      "feature_result"):
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
