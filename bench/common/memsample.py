#!/usr/bin/python3
"""memsample.py OUT COMMAND...: run COMMAND and write to OUT the peaks of
its resident memory, split as the kernel counts it (/proc/PID/status):

    VmRSS    kB   all resident pages (GNU time's "maximum resident set")
    RssAnon  kB   anonymous pages: the process's heap, stacks and maps,
                  i.e. its own data
    RssFile  kB   file-backed pages: the shared libraries' code and data
    RssShmem kB   shared memory (Open MPI's segments)

Why: the peak RSS above an empty case, per particle, is the benchmarks'
memory figure, but on 2 processes at 2,000 particles its noise is larger
than the figure: the shared libraries' pages that are mapped move by 5-10
MB between runs of the same build (bench/README.md section 8, "Where the
2-process memory figure's noise comes from"). The anonymous peak is the
data that grows with the particles, without that noise. Sampled every
5 ms for the first 2 s (a short run's peak), then every 50 ms (a poll
reads one small file, about 30 us); the exit code is COMMAND's."""

import subprocess
import sys
import time

KEYS = ("VmRSS", "RssAnon", "RssFile", "RssShmem")


def sample(pid, peak):
    try:
        with open("/proc/%d/status" % pid) as f:
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
