#!/usr/bin/python3
"""The delay lab end to end on LinuxCNC.

A simulated probe with a known interface delay (whole servo periods in HAL)
-> `program delay --dialect linuxcnc` (two programs: X+ and Z-) -> LinuxCNC
-> its LOG file -> `import --dialect linuxcnc` -> `latency fit`.

What the fit measures as the total delay: #5061 is the feedback of the servo
period that sees the probe, past the trigger point by the interface delay's
travel v t_i plus the scan wait's d in [0, v Ts). Over many touches whose trip
phase varies, d averages v Ts / 2, so the fitted slope is t_i + Ts/2: the HAL
delay plus LinuxCNC's mean scan wait (the controller's further latency of two
periods moves the stop, not #5061). The fit must recover it within one servo
period, and its stability check (the scatter at each feed) must pass: here the
scatter is the scan wait alone, under v Ts.
"""
import os
import sys
import time
import unittest


sys.dont_write_bytecode = True  # no __pycache__ beside the sources

import lcnc_rig
import lcnc_support

MACHINE = lcnc_rig.Machine(max_accel_mm_s2=800.0)
DELAY_PERIODS = 3
PROBE = lcnc_rig.Probe(pretravel_mm=0.010, interface_delay_periods=DELAY_PERIODS)
FEEDS = "100,300,1000,2000,3000"
REPEATS = "3"
# How far the probe stands from the surface at the start, per program: not
# the same, so that the two programs trip at other phases of the servo period.
PLACEMENT_MM = {"X+": 2.0, "Z-": 2.3713}


class DelayLabOnLinuxCnc(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = lcnc_support.temp_folder(cls, "probecycle_delay_")
        path = lcnc_support.scenario(MACHINE, PROBE, {}, cls.folder, "delay")
        cls.plans = {}
        runs = []
        for axis in PLACEMENT_MM:
            name = "delay_" + axis[0].lower()
            ngc, _, plan_path = lcnc_support.program(
                "delay", path, cls.folder, name, "--axis", axis, "--feeds", FEEDS,
                "--repeats", REPEATS, "--margin-mm", "0.5", "--placement-mm", "3")
            cls.plans[axis] = plan_path
            direction = 1 if axis[1] == "+" else -1
            part = lcnc_rig.Part("surface", axis=axis[0], direction=direction,
                                 position=direction * PLACEMENT_MM[axis])
            runs.append(lcnc_rig.Run(program=ngc, part=part, probe=PROBE, timeout_s=60.0,
                                     name=name))
        started = time.monotonic()
        results, facts = lcnc_rig.run_session(MACHINE, runs)
        cls.results = dict(zip(PLACEMENT_MM, results))
        print("LinuxCNC session: %d programs, %.1f s (%.1f s in all)"
              % (len(runs), facts["session_s"], time.monotonic() - started), flush=True)

    def test_the_fit_recovers_the_hal_delay_plus_half_a_servo_period(self):
        csv_files = []
        for axis, result in self.results.items():
            self.assertFalse(result.ended_on_error, result.errors)
            log = os.path.join(self.folder, "log_%s.txt" % axis[0])
            with open(log, "w") as f:
                f.write(result.files["probecycle_log.txt"])
            csv_text = lcnc_support.cli("import", "--dialect", "linuxcnc", "--plan",
                                        self.plans[axis], log).stdout
            csv_files.append(csv_text)
        # Both programs' imports pasted together, as docs/programs.md says.
        lines = csv_files[0].splitlines()
        for more in csv_files[1:]:
            lines += [line for line in more.splitlines()[1:] if not line.startswith("#")][1:]
        touches = os.path.join(self.folder, "touches.csv")
        with open(touches, "w") as f:
            f.write("\n".join(lines) + "\n")
        fit = lcnc_support.cli_json("latency", "fit", touches, "--interpolation-period-s",
                                    repr(MACHINE.servo_period_s))
        Ts = MACHINE.servo_period_s
        expected_s = DELAY_PERIODS * Ts + Ts / 2
        groups = fit["groups"]
        self.assertEqual([(g["axis"], g["direction"]) for g in groups], [("X", 1), ("Z", -1)])
        for group, placement in zip(groups, PLACEMENT_MM.values()):
            print("  %s%+d: delay %.4f ms (expected %.4f ms = %d Ts + Ts/2), zero-speed "
                  "position %.6f mm (the trigger point %.6f mm), 2 sigma %.4f mm"
                  % (group["axis"], group["direction"], 1000 * group["delay_s"],
                     1000 * expected_s, DELAY_PERIODS, group["zero_speed_position_mm"],
                     group["direction"] * (placement + PROBE.pretravel_mm),
                     group["residual_2sigma_mm"]), flush=True)
            self.assertAlmostEqual(group["delay_s"], expected_s, delta=Ts)
        # The stability check: no feed scatters more than the others predict,
        # no curvature, no delay against the travel.
        self.assertEqual(fit["warnings"], [])

if __name__ == "__main__":
    lcnc_support.main()
