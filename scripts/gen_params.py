#!/usr/bin/env python3
"""Generate the C++ view of rtl/sc_pkg.sv (the single source of widths/codes).

Usage: gen_params.py <sc_pkg.sv> <out.h>
Every `localparam int Name = value;` (decimal, or sized hex such as 8'h1C)
becomes `inline constexpr int Name`, and
the phase codes `localparam logic [3:0] PhX = 4'dN;` become
`enum class Phase : uint8_t` with the same names.
Fails loudly on anything it does not understand, so a new package entry can
never be silently missing from the model. The generated section at the end
of the package (scripts/gen_layout.py) is left to that script's header,
sc_layout.h.
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_regmap  # noqa: E402


def main(src, dst):
    text = open(src, encoding="utf-8").read()
    # the generated section (scripts/gen_layout.py) has its own C++ header, sc_layout.h
    text = re.sub(r"[^\n]*// ---- generated section.*?// ---- end of generated section[^\n]*\n", "", text,
                  flags=re.S)
    body = re.sub(r"//[^\n]*", "", text)
    params = re.findall(r"localparam\s+int\s+(\w+)\s*=\s*([0-9_]+|[0-9]+'h[0-9a-fA-F_]+)\s*;", body)
    if not params:
        sys.exit(f"{src}: no localparam int found")
    phases = re.findall(r"localparam\s+logic\s*\[3:0\]\s*(Ph\w+)\s*=\s*4'd(\d+)\s*;", body)
    # constants wider than an int (up to 64 bits): localparam logic [W-1:0] Name = W'dN;
    wide = re.findall(r"localparam\s+logic\s*\[(\d+):0\]\s*((?!Ph)\w+)\s*=\s*(\d+)'d([0-9_]+)\s*;", body)
    all_lp = re.findall(r"localparam\b[^;]*;", body)
    if len(all_lp) != len(params) + len(phases) + len(wide):
        sys.exit(f"{src}: {len(all_lp)} localparams but only {len(params) + len(phases) + len(wide)} of the forms "
                 "'localparam int Name = N;', 'localparam logic [3:0] PhName = 4'dN;', "
                 "'localparam logic [W-1:0] Name = W'dN;' - extend gen_params.py")
    if not phases:
        sys.exit(f"{src}: no phase codes (localparam logic [3:0] Ph* = 4'dN;) found")
    items = phases
    out = [
        "// Generated from rtl/sc_pkg.sv by scripts/gen_params.py - do not edit.",
        "#pragma once",
        "#include <cstdint>",
        "",
        "namespace sc {",
        "",
    ]
    for name, value in params:
        v = value.replace("_", "")
        if "'h" in v:  # sized hex (register addresses): must fit its size and an int
            size, digits = v.split("'h")
            v = int(digits, 16)
            if v >= (1 << int(size)) or v >= (1 << 31):
                sys.exit(f"{src}: {name} = {value} does not fit {size} bits / int")
        out.append(f"inline constexpr int {name} = {v};")
    for msb, name, size, value in wide:
        width, v = int(msb) + 1, int(value.replace("_", ""))
        if int(size) != width or width > 64 or v >= (1 << width):
            sys.exit(f"{src}: {name} = {size}'d{value} does not fit logic [{msb}:0] / 64 bits")
        out.append(f"inline constexpr uint64_t {name} = {v}ull;")
    out += ["", "enum class Phase : uint8_t {"]
    for name, value in items:
        out.append(f"  {name} = {value},")
    out += ["};", "", "}  // namespace sc", ""]
    gen_regmap.write_if_changed(dst, "\n".join(out))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
