1(G54-G59 with their offsets written by G10 L2 P1-P6.)
(Not here: G10 L2 under G91 - FANUC adds the values, LinuxCNC always sets them;)
(G10 L2 P0 - FANUC's external offset, LinuxCNC's active system.)
G17 G21 G90
G10 L2 P1 X100. Y50. Z-20.
G10 L2 P2 X-40. Y30. Z10.
G10 L2 P3 X5.5 Y-7.25 Z0
G10 L2 P4 X200. Y0 Z-50.
G10 L2 P5 X0 Y100. Z5.
G10 L2 P6 X-1. Y-2. Z-3.
G54 G0 X0 Y0 Z0
G1 X10. Y10. F1000.
G55 G0 X0 Y0 Z0
G1 X10. Y-10. Z-5.
G56 G0 X1. Y1. Z1.
G57 G0 X0 Y0 Z0
G58 G0 X0 Y0 Z0
G59 G0 X3. Y2. Z1.
(a system change moves only the axes written)
G55 G0 X0
G56 G1 Y0
(a new offset for the active system counts from the next absolute move)
G10 L2 P3 X10. Y20. Z30.
G0 X0 Y0 Z0
(only the axes written in G10 change)
G10 L2 P1 X50.
G54 G0 X0 Y0 Z0
(incremental moves go from where the tool is, whatever the offset)
G10 L2 P1 Y-50.
G91 G0 X1. Y1.
G90 G0 Z2.
G1 X1. Y2. Z3.
M2
