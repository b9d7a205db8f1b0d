# tests/support/at_terminal.sh, sourced by the shell tests that need a terminal (cli_output.sh,
# cli_progress.sh): at_terminal COMMAND... runs COMMAND with a pseudo-terminal as its stdout and
# stderr and prints what it wrote there, exiting with its status. script(1) (bsdutils) when it
# gives a terminal here, else python3's pty module. A caller checks first that it works
# (`at_terminal test -t 1`) and skips or leaves those checks out when it does not.
at_terminal() {
  if command -v script > /dev/null && script -qec "test -t 1 && test -t 2" /dev/null > /dev/null 2>&1; then
    script -qec "$(printf '%q ' "$@")" /dev/null
    return
  fi
  python3 - "$@" <<'PY'
import os, pty, subprocess, sys
master, slave = os.openpty()
p = subprocess.Popen(sys.argv[1:], stdout=slave, stderr=slave, stdin=subprocess.DEVNULL)
os.close(slave)
out = b""
while True:
    try:
        chunk = os.read(master, 4096)
    except OSError:
        break
    if not chunk:
        break
    out += chunk
sys.stdout.buffer.write(out)
sys.exit(p.wait())
PY
}
