#!/usr/bin/env python3
"""peak_memory.py: peak private memory (RssAnon) and peak RSS (VmHWM) of one command.

Usage: peak_memory.py [--trace FILE] COMMAND... ; prints `rss_anon_peak_bytes vm_hwm_bytes wall_s`
(--trace: every sample as `seconds rss_anon_bytes` lines, to see which stage holds the peak).
RssAnon (anonymous, i.e. private, resident memory: heap, mmap'd arrays) is sampled from
/proc/PID/status every 0.5 ms; VmHWM (peak resident set, file-backed pages included: an input
mapped with mmap counts there, not in RssAnon) is read at the process's exit, before it is reaped
(the child is traced to a stop at exit with ptrace's PTRACE_O_TRACEEXIT would be exact; here the
last sample before exit is used, and /usr/bin/time -v's maximum resident set is the same VmHWM).
"""
import subprocess, sys, time

def field(pid, name):
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith(name + ":"):
                    return int(line.split()[1]) * 1024
    except (FileNotFoundError, ProcessLookupError):
        return None
    return None

args = sys.argv[1:]
trace = None
if args[:1] == ["--trace"]:
    trace = open(args[1], "w")
    args = args[2:]
t0 = time.monotonic()
p = subprocess.Popen(args, stdout=sys.stderr)  # the command's own output (--json) on stderr
anon = hwm = 0
while p.poll() is None:
    a = field(p.pid, "RssAnon")
    h = field(p.pid, "VmHWM")
    if a is not None:
        anon = max(anon, a)
        if trace: trace.write(f"{time.monotonic() - t0:.4f} {a}\n")
    if h is not None: hwm = max(hwm, h)
    time.sleep(0.0005)
wall = time.monotonic() - t0
if p.returncode != 0:
    sys.exit(f"command failed ({p.returncode})")
print(anon, hwm, f"{wall:.2f}")
