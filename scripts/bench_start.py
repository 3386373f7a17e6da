#!/usr/bin/env python3
"""Wall time of whole commands, run in turns so that a noisy machine weighs on each alike.

    scripts/bench_start.py [--runs N] NAME=COMMAND [NAME=COMMAND ...]

Each round runs every command once, in the order given; prints each command's median,
lowest and highest seconds over N rounds (default 9), and each median over the first's.
A command that exits non-zero is reported but still timed (an error's time is a figure
too). Used for docs/BENCHMARKS.md's process start figures."""
import argparse
import shlex
import statistics
import subprocess
import sys
import time


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=9)
    parser.add_argument("commands", nargs="+", metavar="NAME=COMMAND")
    args = parser.parse_args()
    commands = []
    for item in args.commands:
        name, sep, command = item.partition("=")
        if not sep or not command:
            parser.error(f"expected NAME=COMMAND, got {item!r}")
        commands.append((name, shlex.split(command)))
    times = {name: [] for name, _ in commands}
    statuses = {name: set() for name, _ in commands}
    for _ in range(args.runs):
        for name, command in commands:
            start = time.perf_counter()
            done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            times[name].append(time.perf_counter() - start)
            statuses[name].add(done.returncode)
    first = statistics.median(times[commands[0][0]])
    print(f"{'command':<24} {'median s':>9} {'min s':>8} {'max s':>8} {'ratio':>7}  exit")
    for name, _ in commands:
        t = times[name]
        median = statistics.median(t)
        print(f"{name:<24} {median:9.4f} {min(t):8.4f} {max(t):8.4f} {median / first:7.3f}  "
              f"{','.join(map(str, sorted(statuses[name])))}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
