#!/usr/bin/env python3
"""Figures of the process graph runtime (docs/benchmarks.md, "Process graph runtime"):
  1. start-up of a 3-process graph to every first heartbeat (N runs),
  2. restart after kill -9 to the new process's first heartbeat (N kills),
  3. one-way LCM latency between two processes, 2 kB and 1 MB messages,
  4. idle CPU of a process (topay-kinematic-sim, heartbeat only).
Runs itself inside a private network namespace (unshare -rn, loopback multicast route): no
multicast leaves the machine. Usage: tools/graph_runtime_bench.py [BIN_DIR] [--runs N]
"""
import json, os, re, signal, statistics, subprocess, sys, tempfile, time
from datetime import datetime

if os.environ.get("TOPAY_BENCH_NS") != "1":
    os.environ["TOPAY_BENCH_NS"] = "1"
    setup = "ip link set lo up; ip route add 224.0.0.0/4 dev lo; exec python3 \"$0\" \"$@\""
    os.execvp("unshare", ["unshare", "-rn", "sh", "-c", setup, sys.argv[0]] + sys.argv[1:])

args = [a for a in sys.argv[1:]]
runs = 20
if "--runs" in args:
    i = args.index("--runs"); runs = int(args[i + 1]); del args[i:i + 2]
bin_dir = os.path.abspath(args[0] if args else "build/bin")
work = tempfile.mkdtemp(prefix="topay-graph-bench-")

def stamp(line):  # launch.log lines start with "%F %T.mmm"
    return datetime.strptime(line[:23], "%Y-%m-%d %H:%M:%S.%f").timestamp()

def pct(values, q):
    s = sorted(values); return s[min(len(s) - 1, max(0, int(-(-q * len(s) // 1)) - 1))]

def summary(name, values, unit="ms", scale=1000.0):
    v = [x * scale for x in values]
    print(f"{name}: n {len(v)}, median {statistics.median(v):.1f} {unit}, p95 {pct(v, 0.95):.1f} {unit}, max {max(v):.1f} {unit}")

graph = os.path.join(work, "graph.yaml")
with open(graph, "w") as f:
    f.write("""name: bench
processes:
  - {name: robot-model, command: "${BIN_DIR}/topay-kinematic-sim", restart_delay_s: 0.1, restart_delay_max_s: 0.1}
  - {name: commands, command: "${BIN_DIR}/topay-command-pattern", args: [--rate-hz, "10"], depends_on: [robot-model]}
  - {name: robot-model-2, command: "${BIN_DIR}/topay-kinematic-sim", depends_on: [robot-model]}
""")

def launch(run_dir):
    os.makedirs(run_dir, exist_ok=True)
    out = open(os.path.join(run_dir, "launcher.out"), "w")
    t0 = time.time()
    p = subprocess.Popen([f"{bin_dir}/topay-launch", graph, "--plain", "--run-dir", run_dir], stdout=out, stderr=out)
    return p, t0

def first_heartbeats(run_dir):
    try:
        with open(os.path.join(run_dir, "launch.log")) as f:
            return [l for l in f if "first heartbeat" in l]
    except FileNotFoundError:
        return []

# 1. Start-up to all heartbeats (from the launcher's exec to the last first heartbeat).
startup = []
for i in range(runs):
    run_dir = os.path.join(work, f"start{i}")
    p, t0 = launch(run_dir)
    while len(first_heartbeats(run_dir)) < 3: time.sleep(0.005)
    startup.append(max(stamp(l) for l in first_heartbeats(run_dir)) - t0)
    p.send_signal(signal.SIGTERM); p.wait()
summary("graph start-up (3 processes, exec of topay-launch -> every first heartbeat)", startup)

# 2. Restart after kill -9 (kill -> the new process's first heartbeat, from launch.log).
run_dir = os.path.join(work, "restart")
p, _ = launch(run_dir)
while len(first_heartbeats(run_dir)) < 3: time.sleep(0.01)
restart = []
for i in range(runs):
    time.sleep(0.5)
    lines = first_heartbeats(run_dir)
    pid = int(re.search(r"robot-model: .*\(pid (\d+)\)", [l for l in lines if " robot-model:" in l][-1]).group(1))
    t0 = time.time(); os.kill(pid, signal.SIGKILL)
    while True:
        new = [l for l in first_heartbeats(run_dir) if " robot-model:" in l and f"(pid {pid})" not in l][len([l for l in lines if " robot-model:" in l]) - 1:]
        if new: restart.append(stamp(new[0]) - t0); break
        time.sleep(0.002)
p.send_signal(signal.SIGTERM); p.wait()
summary("restart after kill -9 -> first heartbeat (restart delay 0.1 s)", restart)

# 3. LCM latency between two processes.
def latency(size, count, rate, url):
    env = dict(os.environ, LCM_DEFAULT_URL=url)
    rx = subprocess.Popen([f"{bin_dir}/topay-lcm-latency", "--role", "receive", "--count", str(count), "--size", str(size),
                           "--timeout", "60"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, env=env, text=True)
    time.sleep(0.3)
    subprocess.run([f"{bin_dir}/topay-lcm-latency", "--role", "send", "--count", str(count), "--size", str(size),
                    "--rate-hz", str(rate)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    print("LCM one-way latency,", rx.communicate()[0].strip())
latency(2048, 2000, 200, "udpm://239.255.76.67:7667")
latency(1 << 20, 200, 20, "udpm://239.255.76.67:7667?recv_buf_size=8388608")

# 4. Idle CPU of a process: topay-kinematic-sim with no input (state_rate_hz 0), heartbeat only.
cfg = os.path.join(work, "idle.yaml")
open(cfg, "w").write("state_rate_hz: 0\n")
idle = subprocess.Popen([f"{bin_dir}/topay-kinematic-sim", "--config", cfg], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
def cpu_s(pid):
    fields = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
time.sleep(1.0); c0, t0 = cpu_s(idle.pid), time.time()
time.sleep(30.0); c1, t1 = cpu_s(idle.pid), time.time()
idle.terminate(); idle.wait()
print(f"idle CPU of topay-kinematic-sim (heartbeat only) over {t1 - t0:.0f} s: {100 * (c1 - c0) / (t1 - t0):.3f} % of one core "
      f"({(c1 - c0) * 1000:.0f} ms CPU; clock tick {1000 / os.sysconf('SC_CLK_TCK'):.0f} ms)")

# 5. CPU of topay-launch supervising the 3-process graph (status every second, heartbeats).
run_dir = os.path.join(work, "launcher-cpu")
p, _ = launch(run_dir)
while len(first_heartbeats(run_dir)) < 3: time.sleep(0.01)
time.sleep(1.0); c0, t0 = cpu_s(p.pid), time.time()
time.sleep(30.0); c1, t1 = cpu_s(p.pid), time.time()
p.send_signal(signal.SIGTERM); p.wait()
print(f"CPU of topay-launch supervising 3 processes over {t1 - t0:.0f} s: {100 * (c1 - c0) / (t1 - t0):.3f} % of one core "
      f"({(c1 - c0) * 1000:.0f} ms CPU)")
