1(G92: the current point gets the coordinates given; the shift applies to every work system.)
(Not here: G92 under G43 - FANUC and LinuxCNC differ; G92.1 and G92.2 - LinuxCNC only.)
G17 G21 G90
G10 L2 P1 X10. Y20. Z30.
G10 L2 P2 X-10. Y-20. Z-30.
G54 G0 X5. Y5. Z5.
G92 X0 Y0 Z0
G1 X10. F500.
G0 Y10.
(only the axes written change)
G92 X100.
G0 X90. Z1.
G55 G0 X0 Y0 Z0
(machine coordinates ignore G92)
G53 G0 X1. Y2. Z3.
G54 G0 X0 Y0 Z0
G91 G1 X2. Y2.
G90 G92 X0 Y0
G0 X5. Y5.
(a new G54 offset under G92: both shifts count)
G10 L2 P1 X20.
G0 X0 Y0
M2
