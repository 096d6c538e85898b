#!/usr/bin/python3
"""What the path mode (G61, G61.1, G64) does to ProbeCycle's programs on LinuxCNC.

The same two-touch surface program, as `program cycle --dialect linuxcnc`
writes it (G61.1, exact stop; its backoff, 4 mm, clears the first touch's
stop under G64 too) and with G61 (exact path) or G64 (blending) in its place,
each run REPEATS times, then a short sequence of plain moves (a reversal, a
corner, rapids) in each mode. Printed: the motion time, each
move's servo periods and the idle periods at each block change (periods in
which no axis moves; the motion is split where an axis stops or turns).

Checked: under G61 and G61.1 the probing moves brake at the INI's full
acceleration, as the model takes it (the first touch stops d + 2 v Ts +
v^2/2a past its trigger point, d in [0, v Ts)), and every move of the program
(one axis at a time) takes the same servo periods in both; under G64,
LinuxCNC 2.9 plans the probing move at half the acceleration, so it stops
d + 2 v Ts + v^2/a past the trigger point. The idle periods after a probing
move, where the interpreter waits to read #5061, vary from run to run and
with the machine's load (they come from the task's cycle, not the servo
thread): only that there is at least one is checked.
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
PROBE = lcnc_rig.Probe()
MODES = ("G61.1", "G61", "G64")
REPEATS = 3
FEED = 3000.0
PLAIN_MOVES = """G21 G91 G94 {mode}
M0
G1 X5 F3000
G1 X-5 F3000
G1 X5 F3000
G1 Y5 F3000
G0 X10
G0 X-10
G0 Y-5
G0 X-5
M2
"""


def periods_and_idle(samples):
    moves, idle = lcnc_analysis.segments(samples)
    return [last - first + 1 for first, last in moves], idle


class PathModesOnLinuxCnc(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = lcnc_support.temp_folder(cls, "probecycle_modes_")
        path = lcnc_support.scenario(MACHINE, PROBE, {"strategy": "two_touch",
                                                      "probe_feed_mm_min": FEED,
                                                      "measure_feed_mm_min": 300,
                                                      "backoff_mm": 4.0},
                                     cls.folder, "surface")
        ngc, _, _ = lcnc_support.program("cycle", path, cls.folder, "surface", "--axis", "X+")
        with open(ngc) as f:
            text = f.read()
        if "G21 G91 G94 G61.1" not in text:
            raise AssertionError("the program no longer starts with G21 G91 G94 G61.1")
        part = lcnc_rig.Part("surface", axis="X", direction=1, position=5.0)
        plain_part = lcnc_rig.Part("surface", axis="X", direction=1, position=100.0)
        runs = []
        cls.keys = []
        for mode in MODES:
            program = os.path.join(cls.folder, "surface_%s.ngc" % mode)
            with open(program, "w") as f:
                f.write(text.replace("G21 G91 G94 G61.1", "G21 G91 G94 " + mode, 1))
            for i in range(REPEATS):
                runs.append(lcnc_rig.Run(program=program, part=part, probe=PROBE,
                                         timeout_s=20.0))
                cls.keys.append(("program", mode, i))
            plain = os.path.join(cls.folder, "plain_%s.ngc" % mode)
            with open(plain, "w") as f:
                f.write(PLAIN_MOVES.format(mode=mode))
            runs.append(lcnc_rig.Run(program=plain, part=plain_part, probe=PROBE, timeout_s=20.0))
            cls.keys.append(("plain", mode, 0))
        started = time.monotonic()
        results, facts = lcnc_rig.run_session(MACHINE, runs)
        cls.results = dict(zip(cls.keys, results))
        print("LinuxCNC session: %d programs, %.1f s (%.1f s in all)"
              % (len(runs), facts["session_s"], time.monotonic() - started), flush=True)
        Ts = MACHINE.servo_period_s
        print("%-8s %-6s %8s  %-34s %s" % ("program", "mode", "time s", "periods per move",
                                           "idle periods at each block change"))
        for (kind, mode, i), result in cls.results.items():
            periods, idle = periods_and_idle(result.samples)
            print("%-8s %-6s %8.3f  %-34s %s" % (
                kind, mode, lcnc_analysis.motion_time_s(result.samples, Ts),
                " ".join(map(str, periods)), " ".join(map(str, idle))))

    def first_touch(self, mode, i):
        result = self.results[("program", mode, i)]
        self.assertFalse(result.ended_on_error, result.errors)
        touches = lcnc_analysis.touches(result, MACHINE.servo_period_s)
        self.assertEqual(len(touches), 2)
        return touches[0]

    def check_braking(self, mode, accel):
        Ts = MACHINE.servo_period_s
        v = FEED / 60.0
        for i in range(REPEATS):
            touch = self.first_touch(mode, i)
            past_trigger = touch.along(touch.stop) - touch.along(touch.trigger)
            d = touch.trip_error_mm(0.0)
            expected = d + 2 * v * Ts + v * v / (2 * accel)
            # The servo thread brakes in whole periods: up to a Ts^2/8 further.
            self.assertTrue(expected - 1e-6 <= past_trigger <= expected + accel * Ts * Ts / 8
                            + 1e-6, "%s: stopped %.6f mm past the trigger, expected %.6f mm"
                            % (mode, past_trigger, expected))

    def test_exact_stop_g61_1_brakes_at_the_full_acceleration(self):
        self.check_braking("G61.1", MACHINE.max_accel_mm_s2)

    def test_exact_path_g61_brakes_at_the_full_acceleration(self):
        self.check_braking("G61", MACHINE.max_accel_mm_s2)

    def test_blending_g64_brakes_a_probing_move_at_half_the_acceleration(self):
        self.check_braking("G64", MACHINE.max_accel_mm_s2 / 2)

    def test_g61_and_g61_1_move_alike_in_our_programs(self):
        # One axis at a time: exact path and exact stop plan the same moves.
        for i in range(REPEATS):
            exact_stop, _ = periods_and_idle(self.results[("program", "G61.1", i)].samples)
            exact_path, _ = periods_and_idle(self.results[("program", "G61", i)].samples)
            self.assertEqual(exact_stop, exact_path)

    def test_linuxcnc_waits_after_every_probing_move(self):
        # The program's moves: first touch, backoff, measuring touch, return.
        # The interpreter reads #5061 before it queues the next move, so at
        # least one idle period follows each touch, in every mode.
        for (kind, mode, i), result in self.results.items():
            if kind != "program":
                continue
            periods, idle = periods_and_idle(result.samples)
            self.assertEqual(len(periods), 4, "%s run %d: moves %s" % (mode, i, periods))
            self.assertGreaterEqual(idle[0], 1, "%s run %d: idle %s" % (mode, i, idle))
            self.assertGreaterEqual(idle[2], 1, "%s run %d: idle %s" % (mode, i, idle))

if __name__ == "__main__":
    lcnc_support.main()
