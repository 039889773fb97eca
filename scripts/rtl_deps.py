#!/usr/bin/env python3
"""Print the RTL files a top module needs, in read order (sc_pkg.sv first).

Usage: rtl_deps.py <rtl_dir> <top>
Relies on the project rule "one module per file, named after the module":
follows `sc_* [#(...)] u_name (` instantiations from rtl/<top>.sv, so a
half-written module elsewhere in rtl/ does not break an unrelated build.
Vendor primitives (MMCME2_BASE, BUFG) are not project files and are skipped.
"""
import os
import re
import sys

INST = re.compile(r"^\s*(sc_\w+)\s*(?:#\s*\(|\w+\s*\()", re.M)


def deps(rtl, top):
    order, seen, todo = [], set(), [top]
    while todo:
        mod = todo.pop(0)
        if mod in seen:
            continue
        seen.add(mod)
        path = os.path.join(rtl, mod + ".sv")
        if not os.path.exists(path):
            sys.exit(f"rtl_deps: module {mod} has no file {path}")
        order.append(path)
        text = re.sub(r"//[^\n]*", "", open(path, encoding="utf-8").read())
        for m in INST.findall(text):
            if m != mod and m not in seen:
                todo.append(m)
    pkg = os.path.join(rtl, "sc_pkg.sv")
    return [pkg] + list(reversed(order))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    print("\n".join(deps(sys.argv[1], sys.argv[2])))
