1(G54.1 P1-P3, the additional work systems whose offsets G10 L20 P1-P3 write, side by side with)
(LinuxCNC's G59.1-G59.3 written by G10 L2 P7-P9 in g54-1.ngc: LinuxCNC has no G54.1.)
G17 G21 G90
G10 L20 P1 X100. Y50. Z-20.
G10 L20 P2 X-40. Y30. Z10.
G10 L20 P3 X5.5 Y-7.25 Z0
G54.1 P1 G0 X0 Y0 Z0
G1 X10. Y10. F1000.
G54.1 P2 G0 X0 Y0 Z0
G1 X10. Y-10. Z-5.
G54.1 P3 G0 X1. Y1. Z1.
(a system change moves only the axes written)
G54.1 P1 G0 X0
G54 G1 Y0
(a new offset for the active system counts from the next absolute move)
G54.1 P3 G0 X0 Y0 Z0
G10 L20 P3 X10. Y20. Z30.
G0 X0 Y0 Z0
(only the axes written in G10 change)
G10 L20 P2 X50.
G54.1 P2 G0 X0 Y0 Z0
M2
