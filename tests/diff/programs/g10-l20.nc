(G10 L20 P1-P6: the offset of system P such that the current position reads the values given.)
(LinuxCNC's meaning, which m350-sim follows; a FANUC 0i uses L20 for the G54.1 systems.)
G17 G21 G90
G10 L2 P1 X10. Y10. Z0
G54 G0 X5. Y5. Z5.
(the active system)
G10 L20 P1 X0 Y0
G0 X1. Y1.
(an inactive system)
G10 L20 P2 X0 Z0
G55 G0 X0 Y0 Z0
G10 L20 P3 X1. Y2. Z3.
G56 G0 X0 Y0 Z0
G1 X-3. Y4.5 F800.
(only the axes written change)
G10 L20 P3 Z10.
G0 X0 Y0 Z0
M2
