#!/usr/bin/python3
"""A program stops where it must on LinuxCNC, and nothing moves after.

- A part beyond the search: the first G38.2 ends at its target without
  contact and LinuxCNC stops the program with its own error ("G38.2 move
  finished without making contact"); the probe stands at the search's end.
- An obstruction on a protected move (G38.3, then `o... if [#5070 EQ 1]
  (ABORT,...)`): a bore smaller than the program expects, so the move out to
  a touch's start hits the wall; a boss larger than expected, so the move
  down beside it lands on its top. The program stops with our ABORT message
  where the probe stopped on the obstruction.
- A bore 0.2 mm larger than expected with a size tolerance of 0.05 mm and
  cycle.tolerance_action stop: every touch is made, the program logs its
  result and "probecycle out of tolerance", closes its log and stops with our
  ABORT message; the import of that log gives the same verdict.
"Nothing moves after": the last servo period in which an axis moves belongs to
the failing move (a probing move, motion-type 5), none moves in the
lcnc_rig.AFTER_ERROR_S sampled after the program ended, and the position
where the program was left is that move's end or stop.
"""
import os
import sys
import time
import unittest


sys.dont_write_bytecode = True  # no __pycache__ beside the sources

import lcnc_analysis
import lcnc_rig
import lcnc_support

MACHINE = lcnc_rig.Machine(max_accel_mm_s2=800.0)
PROBE = lcnc_rig.Probe(pretravel_mm=0.005)
NO_CONTACT = "G38.2 move finished without making contact"
OBSTRUCTED = "the probe touched something during a protected move: the path is obstructed"
OUT_OF_TOLERANCE = "the measured size is out of tolerance"
FEATURE = {"feature_size_mm": 20.0, "clearance_mm": 5.0, "strategy": "two_touch",
           "probe_feed_mm_min": 2000, "measure_feed_mm_min": 200,
           "position_feed_mm_min": 3000}

# name: (--axis, cycle keys, part)
CASES = {
    # The program expects the surface 5 mm away (it searches up to the
    # model's stop past it); the part is 30 mm away.
    "surface_beyond_search": ("Z-", {"strategy": "two_touch", "probe_feed_mm_min": 2000,
                                     "measure_feed_mm_min": 200},
                              lcnc_rig.Part("surface", axis="Z", direction=-1, position=-30.0)),
    # A bore 20 mm across where the program expects one, at the stylus
    # centre, of 20 mm but 8 mm larger: the X+ touch searches 5 mm and the
    # model's stop past the expected wall, and finds none.
    "bore_beyond_search": ("X+", dict(FEATURE, feature="bore"),
                           lcnc_rig.Part("bore", centre=(0.0, 0.0, 0.0), size_mm=40.0)),
    # A bore of 6 mm where 20 mm is expected: the move out to the X+ start
    # (5 mm from the centre) hits the wall at 3 mm, far enough from its end
    # that it stops on the wall, not at its end.
    "bore_obstructed": (None, dict(FEATURE, feature="bore"),
                        lcnc_rig.Part("bore", centre=(0.0, 0.0, 0.0), size_mm=6.0)),
    # A boss of 34 mm where 20 mm is expected: the probe passes over it at the
    # clearance height to the X+ start (15 mm out), and the protected move
    # down lands on its top.
    "boss_obstructed": (None, dict(FEATURE, feature="boss"),
                        lcnc_rig.Part("boss", centre=(0.0, 0.0, 0.0), size_mm=34.0, top_mm=-2.5)),
    # A bore of 20.2 mm where 20 +- 0.05 mm is expected, the program set to stop.
    "bore_out_of_tolerance": (None, dict(FEATURE, feature="bore", size_tolerance_mm=0.05,
                                         tolerance_action="stop"),
                              lcnc_rig.Part("bore", centre=(0.0, 0.0, 0.0), size_mm=20.2)),
}


class FailuresOnLinuxCnc(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = lcnc_support.temp_folder(cls, "probecycle_failure_")
        cls.cases = {}
        cls.plan_paths = {}
        runs = []
        for name, (axis, cycle, part) in CASES.items():
            path = lcnc_support.scenario(MACHINE, PROBE, cycle, cls.folder, name)
            options = ("--axis", axis) if axis and cycle.get("feature") != "bore" else ()
            ngc, plan, plan_path = lcnc_support.program("cycle", path, cls.folder, name,
                                                        *options)
            cls.cases[name] = plan
            cls.plan_paths[name] = plan_path
            runs.append(lcnc_rig.Run(program=ngc, part=part, probe=PROBE, timeout_s=30.0,
                                     name=name))
        started = time.monotonic()
        results, facts = lcnc_rig.run_session(MACHINE, runs)
        cls.results = dict(zip(CASES, results))
        print("LinuxCNC session: %d programs, %.1f s (%.1f s in all)"
              % (len(runs), facts["session_s"], time.monotonic() - started), flush=True)

    def check_stopped_on(self, name, message):
        result = self.results[name]
        self.assertTrue(result.ended_on_error, "no error: %s" % result.messages)
        self.assertTrue(any(message in text for text in result.errors),
                        "expected %r among %s" % (message, result.errors))
        samples = result.samples
        moving = lcnc_analysis.moving_indices(samples)
        self.assertTrue(moving, "nothing moved")
        last = moving[-1]
        self.assertEqual(lcnc_analysis.motion_type_at(samples, last), lcnc_rig.MOTION_PROBING,
                         "the last motion is not the failing probing move")
        self.assertGreaterEqual(len(samples) - 1 - last,
                                int(0.9 * lcnc_rig.AFTER_ERROR_S / MACHINE.servo_period_s),
                                "too few samples after the last motion")
        # The program's end position is where that move left the probe.
        for axis, key in enumerate("xyz"):
            self.assertAlmostEqual(result.position[axis], samples[-1][key], delta=1e-6)
        return result, last

    def test_surface_beyond_search_stops_on_the_g38_2_error(self):
        result, _ = self.check_stopped_on("surface_beyond_search", NO_CONTACT)
        plan = self.cases["surface_beyond_search"]
        first = next(s for s in plan["steps"] if s["step"] == "probe")
        self.assertFalse(lcnc_analysis.touches(result, MACHINE.servo_period_s))
        # The probe stands at the first search's end: nothing moved after it.
        self.assertAlmostEqual(result.position[2], -first["distance_mm"], delta=1e-6)

    def test_bore_beyond_search_stops_on_the_g38_2_error(self):
        result, _ = self.check_stopped_on("bore_beyond_search", NO_CONTACT)
        plan = self.cases["bore_beyond_search"]
        steps = [s for s in plan["steps"] if s["step"] in ("guard", "probe")]
        self.assertEqual(steps[1]["step"], "probe")
        self.assertFalse(lcnc_analysis.touches(result, MACHINE.servo_period_s))
        # Out to the X+ start, then the whole first search.
        expected = steps[0]["distance_mm"] + steps[1]["distance_mm"]
        self.assertAlmostEqual(result.position[0], expected, delta=1e-6)

    def check_obstructed(self, name, axis):
        result, last = self.check_stopped_on(name, OBSTRUCTED)
        touches = lcnc_analysis.touches(result, MACHINE.servo_period_s)
        self.assertEqual(len(touches), 1, "one trip, on the protected move")
        touch = touches[0]
        self.assertEqual(touch.axis, axis)
        self.assertGreaterEqual(last, touch.seen_index)
        # It stopped on the obstruction, and nothing moved after that stop.
        for i, key in enumerate("xyz"):
            self.assertAlmostEqual(result.position[i], touch.stop[i], delta=1e-6)
        return touch

    def test_bore_obstructed_stops_on_the_abort(self):
        touch = self.check_obstructed("bore_obstructed", 0)
        self.assertAlmostEqual(touch.contact[0], 3.0, delta=1e-6)
        self.assertLess(touch.stop[0], 5.0 - 0.1, "it stopped on the wall, not at the move's end")

    def test_boss_obstructed_stops_on_the_abort(self):
        touch = self.check_obstructed("boss_obstructed", 2)
        self.assertAlmostEqual(touch.contact[2], -2.5, delta=1e-6)


    def test_bore_out_of_tolerance_stops_after_logging_its_result(self):
        result, _ = self.check_stopped_on("bore_out_of_tolerance", OUT_OF_TOLERANCE)
        plan = self.cases["bore_out_of_tolerance"]
        recorded = [s for s in plan["steps"] if s["step"] == "probe" and s["recorded"]]
        touches = lcnc_analysis.touches(result, MACHINE.servo_period_s)
        self.assertEqual(len(touches), len([s for s in plan["steps"] if s["step"] == "probe"]))
        # The log was closed before the abort: every touch, the result, the flag.
        text = result.files.get("probecycle_log.txt", "")
        self.assertEqual(len(lcnc_analysis.logged_touches(text)), len(recorded), text)
        logged, flagged = lcnc_analysis.logged_result(text)
        self.assertIsNotNone(logged, text)
        self.assertTrue(flagged, text)
        self.assertEqual(logged["T"], 1.0)
        log = os.path.join(self.folder, "bore_out_of_tolerance.log.txt")
        with open(log, "w") as f:
            f.write(text)
        imported = lcnc_support.cli_json("import", "--dialect", "linuxcnc", "--plan",
                                         self.plan_paths["bore_out_of_tolerance"], log, "--json")
        self.assertTrue(imported["tolerance"]["out_of_tolerance"])
        self.assertEqual(imported["tolerance"]["action"], "stop")
        self.assertAlmostEqual(imported["size_mm"], logged["S"], delta=1e-5)
        # 0.2 mm larger, and the calibration offset (under 0.02 mm here) on top.
        self.assertGreater(imported["deviation_mm"], 0.2)
        self.assertLess(imported["deviation_mm"], 0.22)


if __name__ == "__main__":
    lcnc_support.main()
