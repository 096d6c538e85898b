#!/usr/bin/env python3
"""Kill test of ProbeCycle's writers (docs/files.md): each writer is started again
and again over its own earlier output and killed (SIGKILL) at a random moment;
after every kill each output must still be whole, one complete version and
never a mix:

- `program` with `--plan`: the program and the plan each equal one of the two
  variants' complete files (a new program beside an old plan is allowed: the
  plan id the program prints tells them apart at the import);
- `compare simulate --out DIR`: the folder holds one seed's whole set;
- the window's `--report-pdf` and `--screenshot`: a complete PDF or PNG.

usage: kill_writers.py CLI GUI SECONDS_PER_WRITER [SEED]
"""
import os
import random
import signal
import subprocess
import sys
import tempfile
import time

CLI, GUI = sys.argv[1], sys.argv[2]
SECONDS = float(sys.argv[3])
random.seed(int(sys.argv[4]) if len(sys.argv) > 4 else 29)
ENV = dict(os.environ, QT_QPA_PLATFORM="offscreen")
failures = []


def read(path):
    with open(path, "rb") as f:
        return f.read()


def run(args):
    """Runs args to the end; returns how long it took, s."""
    start = time.monotonic()
    subprocess.run(args, check=True, env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.monotonic() - start


def killed_run(args, longest_s):
    """Starts args, kills it after a random time up to longest_s; True if killed."""
    proc = subprocess.Popen(args, env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(random.uniform(0.0, longest_s))
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    return proc.returncode == -signal.SIGKILL


def visible(folder):
    """The entries a reader sees (temporary files are hidden, named .NAME.tmp-...)."""
    return sorted(n for n in os.listdir(folder) if not n.startswith("."))


def program_and_plan(work):
    variants = [["--feeds", "30,300,2000"], ["--feeds", "50,500,3000"]]
    refs = []
    for i, feeds in enumerate(variants):
        prog, plan = os.path.join(work, f"ref{i}.ngc"), os.path.join(work, f"ref{i}.json")
        run([CLI, "program", "delay", "--dialect", "linuxcnc", *feeds, "--out", prog, "--plan", plan])
        refs.append((read(prog), read(plan)))
    # The reference files differ, but for the date they would be equal across runs.
    prog, plan = os.path.join(work, "probe.ngc"), os.path.join(work, "probe.json")
    took = run([CLI, "program", "delay", "--dialect", "linuxcnc", *variants[0], "--out", prog,
                "--plan", plan])
    kills, end = 0, time.monotonic() + SECONDS
    while time.monotonic() < end:
        feeds = random.choice(variants)
        kills += killed_run([CLI, "program", "delay", "--dialect", "linuxcnc", *feeds, "--out", prog,
                             "--plan", plan], 1.2 * took)
        if read(prog) not in [r[0] for r in refs]:
            failures.append("program: the program is not one whole version")
        if read(plan) not in [r[1] for r in refs]:
            failures.append("program: the plan is not one whole version")
    return kills


def simulated_set(work):
    refs = {}
    for seed in ("1", "2"):
        folder = os.path.join(work, "ref" + seed)
        run([CLI, "compare", "simulate", "--seed", seed, "--noise-mm", "0.001", "--out", folder])
        refs[seed] = {n: read(os.path.join(folder, n)) for n in visible(folder)}
    target = os.path.join(work, "set")
    took = run([CLI, "compare", "simulate", "--seed", "1", "--noise-mm", "0.001", "--out", target])
    kills, end = 0, time.monotonic() + SECONDS
    while time.monotonic() < end:
        seed = random.choice(["1", "2"])
        kills += killed_run([CLI, "compare", "simulate", "--seed", seed, "--noise-mm", "0.001",
                             "--out", target], 1.2 * took)
        got = {n: read(os.path.join(target, n)) for n in visible(target)}
        if got not in refs.values():
            failures.append("simulate: the folder is not one seed's whole set: " + ", ".join(got))
    return kills


def window_file(work, option, suffix, whole):
    target = os.path.join(work, "out" + suffix)
    took = run([GUI, option, target])
    kills, end = 0, time.monotonic() + SECONDS
    while time.monotonic() < end:
        kills += killed_run([GUI, option, target], 1.2 * took)
        if not whole(read(target)):
            failures.append(f"{option}: {target} is not a whole file")
    return kills


def main():
    with tempfile.TemporaryDirectory(prefix="probecycle-kill-") as work:
        counts = {
            "program+plan": program_and_plan(work),
            "compare simulate": simulated_set(work),
            "--report-pdf": window_file(work, "--report-pdf", ".pdf",
                                        lambda b: b.startswith(b"%PDF") and b.rstrip().endswith(b"%%EOF")),
            "--screenshot": window_file(work, "--screenshot", ".png",
                                        lambda b: b.startswith(b"\x89PNG") and b.endswith(b"IEND\xaeB`\x82")),
        }
    for writer, kills in counts.items():
        print(f"{writer}: {kills} runs killed")
    for f in sorted(set(failures)):
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
