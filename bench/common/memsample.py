#!/usr/bin/python3
"""memsample.py OUT COMMAND...: run COMMAND and write to OUT the peaks of
the resident memory of the largest process below it, split as the kernel
counts it (/proc/PID/status):

    VmRSS    kB   all resident pages (GNU time's "maximum resident set")
    RssAnon  kB   anonymous pages: the process's heap, stacks and maps,
                  i.e. its own data
    RssFile  kB   file-backed pages: the shared libraries' code and data
    RssShmem kB   shared memory (Open MPI's segments)

Why: the peak RSS above an empty case, per particle, is the benchmarks'
memory figure, but on 2 processes at 2,000 particles its noise is larger
than the figure: the shared libraries' pages that are mapped move by 5-10
MB between runs of the same build (bench/packedBed/NOTES.md, "Where the
2-process memory figure's noise comes from"). The anonymous peak is the
data that grows with the particles, without that noise.

COMMAND is usually GNU time running the code (common/prepare's timed):
the sampler stays outside it, so the CPU time GNU time reports is the
code's alone. Each key's peak is the largest over the processes below
the sampler (the code's). Sampled every 5 ms for the first 2 s (a short
run's peak), then every 50 ms (a poll reads a few small files, about
30 us each); the exit code is COMMAND's."""

import subprocess
import sys
import time

KEYS = ("VmRSS", "RssAnon", "RssFile", "RssShmem")


def descendants(pid):
    """The processes below pid (children, their children, ...)."""
    out, todo = [], [pid]
    while todo:
        p = todo.pop()
        try:
            with open("/proc/%d/task/%d/children" % (p, p)) as f:
                kids = [int(k) for k in f.read().split()]
        except (OSError, ValueError):
            kids = []
        out += kids
        todo += kids
    return out


def sample(pid, peak):
    for p in [pid] + descendants(pid):
        try:
            with open("/proc/%d/status" % p) as f:
                for line in f:
                    key = line.split(":", 1)[0]
                    if key in peak:
                        peak[key] = max(peak[key], int(line.split()[1]))
        except (OSError, ValueError, IndexError):
            pass


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, cmd = sys.argv[1], sys.argv[2:]
    peak = dict.fromkeys(KEYS, 0)
    child = subprocess.Popen(cmd)
    start = time.time()
    while child.poll() is None:
        sample(child.pid, peak)
        # Every 5 ms for the first 2 s (an empty case's whole run), then
        # every 50 ms
        time.sleep(0.005 if time.time() - start < 2 else 0.05)
    with open(out, "w") as f:
        for k in KEYS:
            f.write("%s %d\n" % (k, peak[k]))
    sys.exit(child.returncode)


if __name__ == "__main__":
    main()
