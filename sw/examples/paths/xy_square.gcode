; A 4 mm square from where the axes are, at 20 mm/s (G91: relative moves),
; for the two-axis board: scurve board --port DEV path xy_square.gcode --accel 2000 --jerk 100000
G21 G91
G1 X4 F1200
G1 Y4
G1 X-4
G1 Y-4
