#!/usr/bin/env python3
"""Drive a board from Python: identify it, run a move, read it back.

    PYTHONPATH=build/python python3 sw/python/examples/drive_board.py /dev/ttyUSB1
    build/bin/scurve virtual-board --pty-link /tmp/arty &   # no board at hand
    PYTHONPATH=build/python python3 sw/python/examples/drive_board.py /tmp/arty
"""
import sys

import scurve

port = sys.argv[1] if len(sys.argv) > 1 else "/dev/ttyUSB1"
try:
    board = scurve.Board(port)                     # opens the port, reads ID
    print("board:", board.info())
    run = board.run(distance=2000, v_cruise=100000, a_max=1e7, j_max=1e10)
    status = run["status"]
    print(f"ran {run['distance']} pulses: REF_POS {status['ref_pos']}, PULSE_COUNT {status['pulse_count']}")
    back = board.run(distance=-2000, v_cruise=100000, a_max=1e7, j_max=1e10)
    print("and back: REF_POS", back["status"]["ref_pos"], "- link:", board.link())
except scurve.Error as e:                          # e.parameter: "port", "board" or the request field
    sys.exit(f"error: {e}")
