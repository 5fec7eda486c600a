1(G52: a local coordinate system shifted from every work system.)
(Not mixed with G92: LinuxCNC keeps G52 and G92 in one offset, FANUC keeps them apart.)
G17 G21 G90
G10 L2 P1 X100. Y100. Z0
G10 L2 P2 X-100. Y0 Z10.
G54 G0 X0 Y0 Z0
G52 X10. Y-5.
G0 X0 Y0
G1 X5. Y5. F500.
G55 G0 X0 Y0 Z0
(only the axes written change)
G52 Z2.
G0 Z0
G52 X0 Y0
G0 X0 Y0 Z0
G54 G1 X1. Y1. Z1.
G52 Z0
G0 Z1.
M2
