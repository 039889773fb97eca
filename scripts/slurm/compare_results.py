#!/usr/bin/env python3
"""Compare two `scurve regress` reports (results.json) test by test: the same
tests, the same verdicts and exit codes, the same commands, and the same
measured results except what depends on the machine (wall time, clocks per
second, log paths). Prints a table and the differences.

Usage: compare_results.py A.json B.json
Exit status: 0 when equal and every test passed, 1 when they differ or a
test failed, 2 on unreadable input.
"""
import json
import sys

# Machine-dependent: how fast, where, when.
VOLATILE = {"wall_s", "clocks_per_s", "realtime_ratio", "real_time_ratio", "log", "command", "elapsed_s", "time_s"}


def load(path):
    try:
        with open(path, encoding="utf-8") as f:
            report = json.load(f)
        return {r["name"]: r for r in report["results"]}, report
    except (OSError, ValueError, KeyError, TypeError) as e:
        print(f"error: {path}: not a regress report ({e})", file=sys.stderr)
        sys.exit(2)


def stable(value):
    if isinstance(value, dict):
        return {k: stable(v) for k, v in value.items() if k not in VOLATILE}
    if isinstance(value, list):
        return [stable(v) for v in value]
    return value


def diff(a, b, path=""):
    if isinstance(a, dict) and isinstance(b, dict):
        out = []
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                out.append(f"{path}{k}: only in {'the first' if k in a else 'the second'}")
            else:
                out += diff(a[k], b[k], f"{path}{k}.")
        return out
    if isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        return [x for i, (u, v) in enumerate(zip(a, b)) for x in diff(u, v, f"{path}{i}.")]
    return [] if a == b else [f"{path.rstrip('.')}: {a!r} != {b!r}"]


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    (a, ra), (b, rb) = load(sys.argv[1]), load(sys.argv[2])
    problems = []
    for name in sorted(set(a) - set(b)):
        problems.append(f"{name}: only in {sys.argv[1]}")
    for name in sorted(set(b) - set(a)):
        problems.append(f"{name}: only in {sys.argv[2]}")
    print(f"{'test':<28} {'first':>6} {'second':>6}  equal")
    for name in sorted(set(a) & set(b)):
        d = diff(stable(a[name]), stable(b[name]))
        print(f"{name:<28} {'pass' if a[name]['pass'] else 'FAIL':>6} {'pass' if b[name]['pass'] else 'FAIL':>6}  "
              f"{'yes' if not d else 'NO'}")
        problems += [f"{name}: {x}" for x in d]
        if not a[name]["pass"]:
            problems.append(f"{name}: failed ({a[name].get('failure', '')})")
    print(f"{len(a)} and {len(b)} tests, {ra.get('passed')} and {rb.get('passed')} passed")
    for p in problems:
        print(f"  {p}")
    print("equal" if not problems else f"{len(problems)} differences or failures")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
