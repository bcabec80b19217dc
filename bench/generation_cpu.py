#!/usr/bin/python3
"""CPU time (user + sys, from os.wait4: microseconds, like `time`) of `offsetgen generate` runs, medians of N runs,
for one or two offsetgen binaries run alternately (so both see the same machine load).

Usage: generation_cpu.py [--runs N] OFFSETGEN [OTHER_OFFSETGEN]
Cases: gyroid Richardson orders 1, 4 and 8, projection order 4 on every catalog surface, the gyroid
as an --expr at order 4 (still swept), and `--version`.
"""

import argparse
import os
import statistics
import tempfile

SURFACES = "gyroid schwarzp diamond neovius iwp fischerkoch lidinoid splitp frd".split()
GYROID_EXPR = "sin(2*Pi*x)*cos(2*Pi*y)+sin(2*Pi*y)*cos(2*Pi*z)+sin(2*Pi*z)*cos(2*Pi*x)"
CASES = ([f"--surface gyroid --order {m}" for m in (1, 4)] +
         [f"--surface {s} --method projection --order 4" for s in SURFACES] +
         ["--surface gyroid --order 8", f"--expr {GYROID_EXPR} --name g --order 4"])


def cpu_ms(argv):
    # posix_spawn, not fork: a forked Python's copy of itself would count against the child.
    pid = os.posix_spawn(argv[0], argv, os.environ,
                         file_actions=[(os.POSIX_SPAWN_OPEN, fd, os.devnull, os.O_WRONLY, 0) for fd in (1, 2)])
    _, status, usage = os.wait4(pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"failed: {' '.join(argv)}")
    return (usage.ru_utime + usage.ru_stime) * 1000


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=11)
    parser.add_argument("binaries", nargs="+")
    args = parser.parse_args()
    out = os.path.join(tempfile.mkdtemp(), "x.h")
    print("load average at start:", " ".join(open("/proc/loadavg").read().split()[:3]))
    print("case\t" + "\t".join(f"ms CPU, {b}" for b in args.binaries))
    for case in CASES + ["--version"]:
        runs = [[] for _ in args.binaries]
        for _ in range(args.runs):
            for binary, times in zip(args.binaries, runs):
                if os.path.exists(out):
                    os.remove(out)
                argv = [binary, "--version"] if case == "--version" else \
                    [binary, "generate", *case.split(), "-o", out, "-q"]
                times.append(cpu_ms(argv))
        print(case.replace(GYROID_EXPR, "GYROID") + "\t" +
              "\t".join(f"{statistics.median(t):.1f}" for t in runs), flush=True)
    print("load average at end:", " ".join(open("/proc/loadavg").read().split()[:3]))


if __name__ == "__main__":
    main()
