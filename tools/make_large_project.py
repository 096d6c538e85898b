#!/usr/bin/env python3
"""Writes a project at the input limits, for measuring the window with large data.

    tools/make_large_project.py OUT_DIR [--ring N] [--touches N] [--comparison N]

OUT_DIR/large.probecycle holds N ring points (in the paste box and behind the
fit, as after an import) and N delay touches; the comparison's four files
(OUT_DIR/plan.csv, reference_cmm.csv, test_omm.csv, reference_omm.csv) hold N
points of a gently curved surface. The defaults keep every file under the
16 MiB input limit. Fixed seed: the same files every run.
"""

import argparse
import json
import math
import os
import random

LIMIT = 16 * 1024 * 1024


def ring_csv(n, rng):
    # A 50 mm gauge at X100 Y-200, a 3 mm ball, runout (3, -2) um, 1 um noise.
    lines = ["orientation_deg,x_mm,y_mm"]
    for k in range(n):
        orientation = 0 if k % 2 == 0 else 180
        sign = 1 if orientation == 0 else -1
        angle = rng.uniform(0.0, 2.0 * math.pi)
        r = 23.5 + rng.gauss(0.0, 0.001)
        x = 100.0 + sign * 0.003 + r * math.cos(angle)
        y = -200.0 - sign * 0.002 + r * math.sin(angle)
        lines.append(f"{orientation},{x:.4f},{y:.4f}")
    return "\n".join(lines) + "\n"


def delay_csv(n, rng):
    # X+ with an 8.5 ms delay from 10 mm, Z- with 9 ms from -50 mm, 1 um noise.
    feeds = [30, 100, 300, 1000, 2000, 3000]
    lines = ["axis,direction,feed_mm_min,measured_mm"]
    for k in range(n):
        feed = feeds[k % len(feeds)]
        if (k // len(feeds)) % 2 == 0:
            value = 10.0 + feed / 60.0 * 0.0085 + rng.gauss(0.0, 0.001)
            lines.append(f"X,1,{feed},{value:.4f}")
        else:
            value = -50.0 - feed / 60.0 * 0.009 + rng.gauss(0.0, 0.001)
            lines.append(f"Z,-1,{feed},{value:.4f}")
    return "\n".join(lines) + "\n"


def comparison_files(out, n, rng):
    # z = 20 + 2 sin(x/20) cos(y/30) over 200 x 100 mm, from X200 Y0 outwards.
    side = max(4, int(math.sqrt(2 * n)))
    nx, ny = side, max(4, n // side)
    names = ["plan", "reference_cmm", "test_omm", "reference_omm"]
    files = {name: open(os.path.join(out, name + ".csv"), "w") for name in names}
    files["plan"].write("x_mm,y_mm,z_mm,i,j,k\n")
    for name in names[1:]:
        files[name].write("x_mm,y_mm,z_mm\n")
    for a in range(nx):
        for b in range(ny):
            x = 210.0 + 200.0 * a / (nx - 1)
            y = -50.0 + 100.0 * b / (ny - 1)
            z = 20.0 + 2.0 * math.sin(x / 20.0) * math.cos(y / 30.0)
            dzdx = 0.1 * math.cos(x / 20.0) * math.cos(y / 30.0)
            dzdy = -2.0 / 30.0 * math.sin(x / 20.0) * math.sin(y / 30.0)
            norm = math.sqrt(dzdx * dzdx + dzdy * dzdy + 1.0)
            i, j, k = -dzdx / norm, -dzdy / norm, 1.0 / norm
            files["plan"].write(f"{x:.4f},{y:.4f},{z:.4f},{i:.5f},{j:.5f},{k:.5f}\n")
            for name, offset in (("reference_cmm", 0.0), ("test_omm", 0.015), ("reference_omm", 0.012)):
                d = offset + rng.gauss(0.0, 0.0005)
                files[name].write(f"{x + d * i:.4f},{y + d * j:.4f},{z + d * k:.4f}\n")
    for f in files.values():
        f.close()
    return nx * ny


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    parser.add_argument("out")
    parser.add_argument("--ring", type=int, default=290000)
    parser.add_argument("--touches", type=int, default=10000)
    parser.add_argument("--comparison", type=int, default=200000)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rng = random.Random(1)

    with open(os.path.join(os.path.dirname(__file__), "..", "tests", "data", "golden",
                           "project.probecycle")) as f:
        project = json.load(f)
    ring = ring_csv(args.ring, rng)
    project["ring"].update(points_csv=ring, fitted_csv=ring, gauge_diameter_mm=50.0,
                           runout_limit_mm=0.02, residual_limit_mm=0.005, magnification=0.0)
    delay = delay_csv(args.touches, rng)
    project["delay"].update(touches_csv=delay, fitted_csv=delay, applied_group="X+")
    points = comparison_files(args.out, args.comparison, rng) if args.comparison > 0 else 0
    project["comparison"].update(plan="plan.csv", reference_cmm="reference_cmm.csv",
                                 test_omm="test_omm.csv", reference_omm="reference_omm.csv",
                                 c_axis_x_mm=200.0, c_axis_y_mm=0.0, tolerance_mm=0.02)
    if points == 0:
        project.pop("comparison")
    path = os.path.join(args.out, "large.probecycle")
    with open(path, "w") as f:
        json.dump(project, f, indent=2)
        f.write("\n")
    for name in os.listdir(args.out):
        size = os.path.getsize(os.path.join(args.out, name))
        flag = "  OVER THE LIMIT" if size > LIMIT else ""
        print(f"{name}: {size / 1048576:.1f} MiB{flag}")
    print(f"ring points {args.ring}, touches {args.touches}, comparison points {points}")


if __name__ == "__main__":
    main()
