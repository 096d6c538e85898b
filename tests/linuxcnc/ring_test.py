#!/usr/bin/python3
"""The ring-gauge calibration end to end on LinuxCNC.

A ring gauge of known diameter, off the start by less than the centre
tolerance, and a stylus whose ball centre is off the spindle by a known
runout (which turns with the spindle: at the program's second pause, "turn
the spindle to 180 deg", the rig flips it) -> `program ring --dialect
linuxcnc` -> LinuxCNC -> `import` -> `calibrate ring`.

Each recorded point (#5061-#5062, the spindle's position) lies past the
contact by the pretravel, the interface delay's travel v t_i and the scan
wait's d in [0, v Ts) at the measuring feed v. So `calibrate ring` must give:
the gauge centre and the runout within v Ts; every direction's effective
ball radius (the gauge radius less the distance from the centre to the
trigger point, as it reports it) in [b/2 - p - v t_i - v Ts, b/2 - p - v t_i];
each orientation's circle of recorded points (radius_mm) the gauge's radius
less b/2 plus p + v t_i + d.
"""
import os
import sys
import time
import unittest


sys.dont_write_bytecode = True  # no __pycache__ beside the sources

import lcnc_rig
import lcnc_support

MACHINE = lcnc_rig.Machine(max_accel_mm_s2=800.0)
RUNOUT_MM = (0.012, -0.008)
PROBE = lcnc_rig.Probe(pretravel_mm=0.005, interface_delay_periods=1, runout_mm=RUNOUT_MM)
GAUGE_MM = 30.0
BALL_MM = 6.0
CENTRE = (0.4, -0.3, 0.0)  # the gauge's centre from where the spindle starts
MEASURE_FEED = 200.0
TOLERANCE_MM = 2e-6


class RingOnLinuxCnc(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = lcnc_support.temp_folder(cls, "probecycle_ring_")
        path = lcnc_support.scenario(MACHINE, PROBE, {"probe_feed_mm_min": 2000,
                                                      "measure_feed_mm_min": MEASURE_FEED},
                                     cls.folder, "ring")
        ngc, _, cls.plan = lcnc_support.program(
            "ring", path, cls.folder, "ring", "--gauge-diameter-mm", repr(GAUGE_MM),
            "--ball-diameter-mm", repr(BALL_MM), "--centre-tolerance-mm", "1")
        # The ball centre's bore: the gauge less the ball.
        part = lcnc_rig.Part("bore", centre=CENTRE, size_mm=GAUGE_MM - BALL_MM)
        # Pause 1 checks the set-up, pause 2 turns the spindle to 180 deg.
        run = lcnc_rig.Run(program=ngc, part=part, probe=PROBE, turn_at_pause=2, timeout_s=60.0,
                           name="ring")
        started = time.monotonic()
        (cls.result,), facts = lcnc_rig.run_session(MACHINE, [run])
        print("LinuxCNC session: 1 program, %.1f s (%.1f s in all)"
              % (facts["session_s"], time.monotonic() - started), flush=True)

    def test_calibrate_ring_recovers_the_gauge_the_ball_and_the_runout(self):
        result = self.result
        self.assertFalse(result.ended_on_error, result.errors)
        self.assertEqual(result.pauses, 2)
        log = os.path.join(self.folder, "ring_log.txt")
        with open(log, "w") as f:
            f.write(result.files["probecycle_log.txt"])
        csv_path = os.path.join(self.folder, "ring.csv")
        lcnc_support.cli("import", "--dialect", "linuxcnc", "--plan", self.plan, "--out",
                         csv_path, log)
        ring = lcnc_support.cli_json("calibrate", "ring", csv_path, "--gauge-diameter",
                                     repr(GAUGE_MM))
        Ts = MACHINE.servo_period_s
        v = MEASURE_FEED / 60.0
        scan = v * Ts
        lag = PROBE.pretravel_mm + v * PROBE.interface_delay_periods * Ts
        print("  centre (%.6f, %.6f) mm, true (%.6f, %.6f); runout (%.6f, %.6f), true (%.6f, "
              "%.6f); effective ball radius %.6f mm, expected %.6f-%.6f; v Ts %.6f mm"
              % (ring["center_x_mm"], ring["center_y_mm"], CENTRE[0], CENTRE[1],
                 ring["runout_x_mm"], ring["runout_y_mm"], RUNOUT_MM[0], RUNOUT_MM[1],
                 ring["effective_radius_mm"], BALL_MM / 2 - lag - scan, BALL_MM / 2 - lag, scan),
              flush=True)
        self.assertAlmostEqual(ring["gauge_diameter_mm"], GAUGE_MM)
        self.assertAlmostEqual(ring["center_x_mm"], CENTRE[0], delta=scan)
        self.assertAlmostEqual(ring["center_y_mm"], CENTRE[1], delta=scan)
        self.assertAlmostEqual(ring["runout_x_mm"], RUNOUT_MM[0], delta=scan)
        self.assertAlmostEqual(ring["runout_y_mm"], RUNOUT_MM[1], delta=scan)
        for name, radius in [("all", ring["effective_radius_mm"]),
                             *ring["radius_by_direction"].items()]:
            self.assertTrue(BALL_MM / 2 - lag - scan - TOLERANCE_MM <= radius
                            <= BALL_MM / 2 - lag + TOLERANCE_MM,
                            "%s: effective ball radius %.6f mm" % (name, radius))
        self.assertEqual([f["orientation_deg"] for f in ring["fits"]], [0, 180])
        for fit in ring["fits"]:
            radius = (GAUGE_MM - BALL_MM) / 2 + lag
            self.assertTrue(radius - TOLERANCE_MM <= fit["radius_mm"]
                            <= radius + scan + TOLERANCE_MM, fit)


if __name__ == "__main__":
    lcnc_support.main()
