#!/usr/bin/env python3
"""Checks a GTKWave save file against an FST trace: every signal the save
file shows exists in the trace (full hierarchical name with its bit range),
so opening the pair shows no missing traces. Reads the trace's header with
gtkwave's fst2vcd.
  scripts/check_gtkw.py docs/waves/sc_axis_core.gtkw run.fst
Exit 0 all found, 1 some missing (listed), 2 bad input."""
import subprocess
import sys


def trace_signals(fst: str) -> set:
    try:
        vcd = subprocess.run(["fst2vcd", "-f", fst], check=True, capture_output=True, text=True).stdout
    except (OSError, subprocess.CalledProcessError) as e:
        print(f"error: fst={fst}: fst2vcd cannot read it ({e})", file=sys.stderr)
        sys.exit(2)
    scopes, names = [], set()
    for line in vcd.splitlines():
        f = line.split()
        if not f:
            continue
        if f[0] == "$scope":
            scopes.append(f[2])
        elif f[0] == "$upscope":
            scopes.pop()
        elif f[0] == "$var":
            rng = f[5] if len(f) > 6 and f[5].startswith("[") else ""
            names.add(".".join(scopes + [f[4]]) + rng)
        elif f[0] == "$enddefinitions":
            break
    return names


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    save, fst = sys.argv[1], sys.argv[2]
    try:
        lines = open(save).read().splitlines()
    except OSError as e:
        print(f"error: save file={save}: {e.strerror}", file=sys.stderr)
        return 2
    shown = [l for l in lines if l and l[0] not in "[*@-"]
    have = trace_signals(fst)
    missing = [s for s in shown if s not in have]
    for s in missing:
        print(f"{save}: {s} is not in {fst}", file=sys.stderr)
    analog = sum(1 for l in lines if l.startswith("@") and int(l[1:], 16) & 0x18000)
    print(f"{save}: {len(shown)} signals, {analog} analog, {len(missing)} missing in {fst}")
    return 1 if missing or not shown else 0


if __name__ == "__main__":
    sys.exit(main())
