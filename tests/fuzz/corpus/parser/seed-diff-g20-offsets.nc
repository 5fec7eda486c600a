(G20 set before any offset is written: G10 L2, G52 and G92 values are inches like the axis words.)
(Both FANUC and LinuxCNC read them in the input unit. Not here: offsets written in G21 and used)
(under G20 - a FANUC 0i keeps the number and reads it in the new unit, LinuxCNC converts it.)
G17 G20 G90
G10 L2 P1 X1. Y2. Z-0.5
G54 G0 X0 Y0 Z0
G1 X0.5 Y0.5 F20.
G52 X0.25 Y0.25
G0 X0 Y0
G52 X0 Y0
G0 X0 Y0
G92 X1. Y1.
G0 X0 Y0 Z0.125
M2
