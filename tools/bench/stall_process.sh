#!/bin/bash
# Stalls a process the way an overloaded machine does, to reproduce what a stall does to the
# graph (docs/reliability.md, finding 34): while a process named NAME (exactly, as pgrep -x)
# runs, it is stopped (SIGSTOP) for STOP_S seconds every PERIOD_S seconds, then continued
# (SIGCONT). Runs until SIGTERM or SIGINT or DURATION_S seconds (0: until stopped); prints how
# many stalls it made. (A job a script starts in the background ignores SIGINT: stop it with kill.) Example, beside a mission campaign:
#   tools/bench/stall_process.sh topay-sim 0.5 1.5 0 &   build-test/bin/topay-missions ...
set -u
NAME=${1:?usage: stall_process.sh NAME STOP_S PERIOD_S [DURATION_S]}
STOP_S=${2:?STOP_S}
PERIOD_S=${3:?PERIOD_S}
DURATION_S=${4:-0}
stalls=0
pids=""
resume() { [ -n "$pids" ] && kill -CONT $pids 2>/dev/null; echo "stall_process: $stalls stalls of ${STOP_S} s"; exit 0; }
trap resume INT TERM
start=$(date +%s)
while [ "$DURATION_S" = 0 ] || [ $(( $(date +%s) - start )) -lt "${DURATION_S%.*}" ]; do
  sleep "$(awk "BEGIN { print $PERIOD_S - $STOP_S }")"
  pids=$(pgrep -x -- "$NAME" | tr '\n' ' ')
  [ -z "$pids" ] && continue
  kill -STOP $pids 2>/dev/null && stalls=$((stalls + 1))
  sleep "$STOP_S"
  kill -CONT $pids 2>/dev/null
  pids=""
done
resume
