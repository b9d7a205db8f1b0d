#!/usr/bin/env python3
"""info_cpu_before_after.py BEFORE_BIN AFTER_BIN FILE ROUNDS: `shadetool info FILE` with two binaries,
alternating round-robin, process CPU time (user + sys of the child) per run, medians and their ratio,
/proc/loadavg at start and end."""
import os, resource, subprocess, statistics, sys, time
A, B, f, rounds = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
print("load at start:", open("/proc/loadavg").read().split()[:3])
def cpu(bin_):
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([bin_, "info", f], check=True, capture_output=True)
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
ta, tb = [], []
for i in range(rounds):
    ta.append(cpu(A)); tb.append(cpu(B))
print("before", ["%.3f" % x for x in ta]); print("after ", ["%.3f" % x for x in tb])
ma, mb = statistics.median(ta), statistics.median(tb)
print("median CPU s: before %.3f after %.3f  after/before %.3f" % (ma, mb, mb / ma))
print("load at end:", open("/proc/loadavg").read().split()[:3])
