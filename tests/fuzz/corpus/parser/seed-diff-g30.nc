(G30: to the intermediate point in work coordinates, then the axes written to reference point 2.)
(fanuc-0i's point 2 is machine X0 Y0 Z-20; rs274 takes its G30 position from #5181-#5183, set)
(in g30.var, in inches as rs274 keeps its parameters: -0.787401574803 inch is -20 mm.)
(Not here: G30 P3 - LinuxCNC's G30 has no P.)
G17 G21 G90
G10 L2 P1 X10. Y10. Z10.
G54 G0 X5. Y5. Z5.
G30 Z10.
G0 X0
G30 X1. Y1.
G0 X2. Y3. Z4.
G91 G30 Z0
G90
M2
