#!/usr/bin/python3
"""Plots topay-bench runs.

    plot_bench.py --out DIR RUN_DIR [RUN_DIR ...]

Each RUN_DIR is a topay-bench --out folder (summary.json and tasks.jsonl). Writes into DIR:
  success_rate.png          success rate per scene and range, one bar per method (grouped);
  planning_time.png         T.P. (ms) of the successful tasks per method, one box plot panel per
                            scene and range (the paper's statistics are over successes too);
  duration_vs_distance.png  trajectory duration T.D. (s) vs straight-line base distance (m) of
                            the successful tasks, one colour per method.
Needs python3 and matplotlib only (Agg backend). Exit codes: 0 written, 1 a missing or
malformed input file or an unwritable output, 2 a usage error.
"""
import argparse
import json
import math
import os
import sys

SUMMARY_KEYS = ("method", "scene", "range", "tasks", "success_rate")
LINE_KEYS = ("task", "scene", "range", "method", "success", "timings_ms", "duration_s",
             "base_distance_m")


class InputError(Exception):
    """A missing or malformed input file; the message names the file and what is wrong."""


def load_matplotlib():
    try:
        import matplotlib
    except ImportError:
        sys.exit("plot_bench.py: matplotlib is missing: install python3-matplotlib "
                 "(tools/install-deps.sh does)")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def read_summary(path):
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except OSError as e:
        raise InputError(f"{path}: cannot read: {e.strerror}")
    except json.JSONDecodeError as e:
        raise InputError(f"{path}: malformed JSON: {e}")
    if not isinstance(data, list):
        raise InputError(f"{path}: expected a JSON array of method objects")
    for i, entry in enumerate(data):
        missing = [k for k in SUMMARY_KEYS if not isinstance(entry, dict) or k not in entry]
        if missing:
            raise InputError(f"{path}: entry {i}: missing {', '.join(missing)}")
    return data


def read_lines(path):
    lines = []
    try:
        with open(path, encoding="utf-8") as f:
            for number, text in enumerate(f, start=1):
                if not text.strip():
                    continue
                try:
                    line = json.loads(text)
                except json.JSONDecodeError as e:
                    raise InputError(f"{path}:{number}: malformed JSON: {e}")
                missing = [k for k in LINE_KEYS if not isinstance(line, dict) or k not in line]
                if missing:
                    raise InputError(f"{path}:{number}: missing {', '.join(missing)}")
                if not isinstance(line["timings_ms"], dict) or "total" not in line["timings_ms"]:
                    raise InputError(f"{path}:{number}: timings_ms.total missing")
                lines.append(line)
    except OSError as e:
        raise InputError(f"{path}: cannot read: {e.strerror}")
    return lines


def read_runs(run_dirs):
    """All summaries and task lines of the runs."""
    summaries, lines = [], []
    for run in run_dirs:
        summaries += read_summary(os.path.join(run, "summary.json"))
        lines += read_lines(os.path.join(run, "tasks.jsonl"))
    return summaries, lines


def ordered(values):
    """Unique values in first-seen order."""
    seen = []
    for v in values:
        if v not in seen:
            seen.append(v)
    return seen


def plot_success_rate(plt, summaries, path):
    cells = ordered((s["scene"], s["range"]) for s in summaries)
    methods = ordered(s["method"] for s in summaries)
    rate = {(s["scene"], s["range"], s["method"]): 100.0 * s["success_rate"] for s in summaries}
    width = 0.8 / max(len(methods), 1)
    fig, ax = plt.subplots(figsize=(max(6, 1.8 * len(cells)), 4))
    for m, method in enumerate(methods):
        xs = [c + (m - (len(methods) - 1) / 2) * width for c in range(len(cells))]
        # NaN (no bar) where the method did not run, so that "not run" does not read as 0 %.
        ys = [rate.get((scene, rng, method), math.nan) for scene, rng in cells]
        ax.bar(xs, ys, width, label=method)
    ax.set_xticks(range(len(cells)))
    ax.set_xticklabels([f"{scene}\n{rng}" for scene, rng in cells])
    ax.set_ylabel("success rate (%)")
    ax.set_ylim(0, 125)
    ax.set_yticks(range(0, 101, 20))
    ax.set_title("Success rate per scene and range")
    ax.legend(loc="upper center", ncol=max(len(methods), 1), fontsize="small")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def plot_planning_time(plt, lines, path):
    cells = ordered((l["scene"], l["range"]) for l in lines)
    methods = ordered(l["method"] for l in lines)
    fig, axes = plt.subplots(1, max(len(cells), 1), figsize=(max(5, 4 * len(cells)), 4),
                             squeeze=False)
    for ax, (scene, rng) in zip(axes[0], cells):
        data = [[l["timings_ms"]["total"] for l in lines
                 if l["scene"] == scene and l["range"] == rng and l["method"] == m and l["success"]]
                for m in methods]
        # An empty box for a method without a success keeps the columns aligned.
        ax.boxplot([d if d else [math.nan] for d in data])
        ax.set_xticks(range(1, len(methods) + 1))
        ax.set_xticklabels(methods)
        ax.set_title(f"{scene}, {rng}")
        ax.set_ylabel("planning time T.P. (ms), successes")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def plot_duration_vs_distance(plt, lines, path):
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for method in ordered(l["method"] for l in lines):
        ok = [l for l in lines if l["method"] == method and l["success"]
              and l["duration_s"] is not None]
        ax.scatter([l["base_distance_m"] for l in ok], [l["duration_s"] for l in ok], s=14,
                   label=f"{method} ({len(ok)})")
    ax.set_xlabel("straight-line base distance (m)")
    ax.set_ylabel("trajectory duration T.D. (s)")
    ax.set_title("Trajectory duration vs distance (successes)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="output folder (created)")
    parser.add_argument("runs", nargs="+", metavar="RUN_DIR", help="topay-bench --out folders")
    args = parser.parse_args(argv)  # exits with 2 on a usage error
    plt = load_matplotlib()
    try:
        summaries, lines = read_runs(args.runs)
    except InputError as e:
        print(f"plot_bench.py: {e}", file=sys.stderr)
        return 1
    try:
        os.makedirs(args.out, exist_ok=True)
        plot_success_rate(plt, summaries, os.path.join(args.out, "success_rate.png"))
        plot_planning_time(plt, lines, os.path.join(args.out, "planning_time.png"))
        plot_duration_vs_distance(plt, lines, os.path.join(args.out, "duration_vs_distance.png"))
    except OSError as e:
        print(f"plot_bench.py: cannot write into {args.out}: {e}", file=sys.stderr)
        return 1
    print(f"wrote success_rate.png, planning_time.png, duration_vs_distance.png in {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
