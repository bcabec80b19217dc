#!/usr/bin/python3
"""Runs a command several times and prints one TSV line per run: wall_s user_s sys_s maxrss_kb.

Per-run resource usage comes from os.wait4 on that very child (microsecond resolution, unlike
/usr/bin/time's 10 ms), wall time from time.perf_counter around fork/exec/wait.

Usage: time_cli.py --runs N [--prefix TEXT] [--before CMD] -- COMMAND ARGS...
  --prefix  text prepended to each line (e.g. "gyroid\t4\t")
  --before  shell command run (untimed) before each run, e.g. "rm -f out.h"
Exits non-zero if any run fails (after printing its stderr).
"""

import argparse
import os
import subprocess
import sys
import time


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--runs", type=int, default=1)
    p.add_argument("--prefix", default="")
    p.add_argument("--before", default=None)
    p.add_argument("command", nargs=argparse.REMAINDER)
    args = p.parse_args(argv)
    command = args.command[1:] if args.command and args.command[0] == "--" else args.command
    if not command:
        p.error("no command")
    prefix = args.prefix.encode().decode("unicode_escape")
    for rep in range(1, args.runs + 1):
        if args.before:
            subprocess.run(args.before, shell=True, check=True)
        start = time.perf_counter()
        child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        _, status, usage = os.wait4(child.pid, 0)
        wall = time.perf_counter() - start
        child.returncode = os.waitstatus_to_exitcode(status)
        stderr = child.stderr.read().decode(errors="replace")
        child.stderr.close()
        if child.returncode != 0:
            sys.stderr.write(stderr)
            sys.stderr.write("time_cli: %s exited with %d\n" % (" ".join(command), child.returncode))
            return 1
        print("%s%d\t%.6f\t%.6f\t%.6f\t%d" % (prefix, rep, wall, usage.ru_utime, usage.ru_stime, usage.ru_maxrss),
              flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
