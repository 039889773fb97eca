#!/usr/bin/env python3
"""Checks that the FuseSoC core's RTL file set (scurve_servo.core, fileset
`rtl`) holds exactly the files scripts/rtl_deps.py lists for the tops and
every .sv file of the RTL directory, the package first, so FuseSoC users
compile what the other flows compile.
Run with the project's virtual environment (PyYAML comes with FuseSoC):
  .venv/bin/python scripts/check_core.py scurve_servo.core rtl sc_board_top sc_axi_axis ...
Exit 0 in sync, 1 not in sync (the difference on stderr)."""
import subprocess
import sys
from pathlib import Path

import yaml


def main() -> int:
    if len(sys.argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    core, rtl_dir, tops = Path(sys.argv[1]), Path(sys.argv[2]), sys.argv[3:]
    root = core.resolve().parent
    text = core.read_text()
    if not text.startswith("CAPI=2:"):
        print(f"{core}: does not start with CAPI=2:", file=sys.stderr)
        return 1
    files = yaml.safe_load(text)["filesets"]["rtl"]["files"]
    listed = [f if isinstance(f, str) else next(iter(f)) for f in files]
    deps = Path(__file__).with_name("rtl_deps.py")
    wanted = set()
    for top in tops:
        out = subprocess.run([sys.executable, str(deps), str(rtl_dir), top], check=True,
                             capture_output=True, text=True).stdout.split()
        wanted.update(str(Path(f).resolve().relative_to(root)) for f in out)
    # Every module file of the RTL directory belongs to some top.
    wanted.update(str(f.resolve().relative_to(root)) for f in Path(rtl_dir).glob("*.sv"))
    ok = True
    if listed[0] != "rtl/sc_pkg.sv":
        print(f"{core}: the package rtl/sc_pkg.sv must come first, got {listed[0]}", file=sys.stderr)
        ok = False
    if len(set(listed)) != len(listed):
        print(f"{core}: a file is listed twice", file=sys.stderr)
        ok = False
    for f in sorted(wanted - set(listed)):
        print(f"{core}: missing {f} (needed by {', '.join(tops)})", file=sys.stderr)
        ok = False
    for f in sorted(set(listed) - wanted):
        print(f"{core}: lists {f}, which no top needs", file=sys.stderr)
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
