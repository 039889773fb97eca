#!/usr/bin/env python3
"""Plan paper 000's group 1 move from Python and print its segments and the
UART frames that load it into the board (PYTHONPATH=build/python)."""
import scurve

plan = scurve.plan(distance=30000, v_cruise=3000, a_max=500, j_max=2500)
print(f"{plan['pulses']} pulses in {plan['duration_s']:.4f} s, peak {plan['peak_velocity']:.1f} pulses/s")
for s in plan["segments"]:
    print(f"  {s['phase']:<15} {s['clocks']:>10} clocks  jerk {s['jerk']:>10.1f} pulses/s^3")
for w in scurve.regs(distance=30000, v_cruise=3000, a_max=500, j_max=2500, uart=True)[-3:]:
    print(f"  {w['frame']}  # {w['reg']} = 0x{w['data']:08X}")
try:
    scurve.plan(distance=30000, v_cruise=3000, a_max=0, j_max=2500)
except scurve.Error as e:
    print(f"refused: {e} (parameter {e.parameter})")
