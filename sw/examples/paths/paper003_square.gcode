%
(Paper 003's quadrilateral path on an X-Y table: from the origin to corner 1,)
(then around the 60 mm x 60 mm square through corners 2, 3 and 4.)
(The paper's limits for both motors, as printed: v_max 0.6 mm/s,)
(a_max 0.009 mm/s^2, j_max 1.01e5 mm/s^3. G-code carries the feed only:)
(acceleration and jerk come with the command, e.g. --accel 0.009 --jerk 1.01e5.)
G21 G90               ; mm, absolute
N10 G1 X12 Y80 F36    ; corner 1, 36 mm/min = 0.6 mm/s
N20 X72               ; corner 2
N30 Y140              ; corner 3
N40 X12               ; corner 4
%
