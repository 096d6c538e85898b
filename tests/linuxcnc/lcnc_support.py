"""What every LinuxCNC test shares: probecycle-cli, scenarios, the skip and the timing.

A test file is run by ctest as `/usr/bin/python3 FILE --cli PATH`. Without
LinuxCNC it prints why and exits with SKIP_CODE (ctest's SKIP_RETURN_CODE),
unless PROBECYCLE_REQUIRE_LINUXCNC=1 (CI), where a missing LinuxCNC fails.
"""
import argparse
import functools
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

import lcnc_rig

SKIP_CODE = 77
CLI = None  # set by main()


def cli(*args, check=True):
    done = subprocess.run([CLI, *args], capture_output=True, text=True, timeout=120)
    if check and done.returncode != 0:
        raise AssertionError("probecycle-cli %s failed (%d): %s"
                             % (" ".join(args), done.returncode, done.stderr.strip()))
    return done


def cli_json(*args):
    return json.loads(cli(*args).stdout)


@functools.lru_cache(maxsize=None)
def has_machine_linuxcnc():
    return cli("machine", "linuxcnc", "--help", check=False).returncode == 0


def expected_machine_section(machine):
    """The scenario's machine for a LinuxCNC 2.9 INI under exact stop (G61.1), as
    measured: the TP plans at [AXIS_x] MAX_ACCELERATION, sees the probe in the servo
    period after the trigger (a scan of Ts) and brakes two periods later."""
    return {"accel_model": "constant_accel", "max_accel_mm_s2": machine.max_accel_mm_s2,
            "scan_period_s": machine.servo_period_s,
            "controller_latency_s": 2 * machine.servo_period_s, "latched_input": False,
            "filter": "none", "servo_time_constant_s": 0.0,
            "rapid_feed_mm_min": 60.0 * machine.max_velocity_mm_s}


@functools.lru_cache(maxsize=None)
def machine_section(machine):
    """`probecycle-cli machine linuxcnc` on the rig's INI; written here where the CLI
    lacks the command."""
    if not has_machine_linuxcnc():
        return expected_machine_section(machine)
    with tempfile.TemporaryDirectory() as folder:
        ini = os.path.join(folder, "machine.ini")
        with open(ini, "w") as f:
            f.write(lcnc_rig.ini_text(machine, folder, os.path.join(folder, "driver.py")))
        return cli_json("machine", "linuxcnc", ini)["machine"]


def scenario(machine, probe, cycle, folder, name):
    """A scenario file: the defaults, the machine the INI gives, the simulated probe, `cycle`."""
    s = cli_json("defaults")
    s["machine"].update(machine_section(machine))
    s["probe"].update({"pretravel_mm": probe.pretravel_mm,
                       "interface_delay_s": probe.interface_delay_periods * machine.servo_period_s,
                       # the simulated stylus has no limit; the searches go halfway to it
                       "overtravel_limit_mm": 10.0,
                       # The simulated probe and machine have no repeatability, lobing,
                       # calibration artefact or drift: the model's uncertainty budget holds
                       # the scan wait alone, as the rig does (like with like).
                       "repeatability_2sigma_mm": 0.0, "lobing_mm": 0.0,
                       "artefact_uncertainty_mm": 0.0})
    s["machine"].update({"repeatability_2sigma_mm": 0.0, "thermal_drift_mm": 0.0})
    # LinuxCNC runs the programs at 100 % feed override: the model's checks at
    # a higher override (cycle.feed_override_max_pct) are the core tests'.
    s["cycle"]["feed_override_max_pct"] = 100.0
    s["cycle"].update(cycle)
    path = os.path.join(folder, name + ".json")
    with open(path, "w") as f:
        json.dump(s, f, indent=1)
    return path


def program(kind, scenario_path, folder, name, *options):
    """`probecycle-cli program KIND --dialect linuxcnc`: (program path, plan dict, plan path)."""
    ngc = os.path.join(folder, name + ".ngc")
    plan = os.path.join(folder, name + ".plan.json")
    cli("program", kind, scenario_path, "--dialect", "linuxcnc", "--plan", plan, "--out", ngc,
        *options)
    with open(plan) as f:
        return ngc, json.load(f), plan


def temp_folder(test_class, prefix):
    """A folder for a test class's files, removed after the class (even when its set-up
    fails) unless PROBECYCLE_LINUXCNC_KEEP is set."""
    folder = tempfile.mkdtemp(prefix=prefix)
    if os.environ.get("PROBECYCLE_LINUXCNC_KEEP"):
        print("the test's folder: " + folder, flush=True)
    else:
        test_class.addClassCleanup(shutil.rmtree, folder, ignore_errors=True)
    return folder


def main():
    global CLI
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True, help="the built probecycle-cli")
    args, rest = parser.parse_known_args()
    CLI = os.path.abspath(args.cli)
    reason = lcnc_rig.unavailable_reason()
    if reason is not None:
        if os.environ.get("PROBECYCLE_REQUIRE_LINUXCNC") == "1":
            print("LinuxCNC is required (PROBECYCLE_REQUIRE_LINUXCNC=1) but " + reason)
            sys.exit(1)
        print("Skipped: " + reason)
        sys.exit(SKIP_CODE)
    started = time.monotonic()
    program_ = unittest.main(argv=[sys.argv[0], "-v", *rest], exit=False)
    print("%s: %.1f s in all" % (os.path.basename(sys.argv[0]), time.monotonic() - started))
    sys.exit(0 if program_.result.wasSuccessful() else 1)
