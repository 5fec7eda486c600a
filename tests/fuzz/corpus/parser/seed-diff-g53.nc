(G53: one block in machine coordinates, whatever work offset is active.)
(Only as G53 G0 here: FANUC's G53 is always a rapid, LinuxCNC's follows G0 or G1.)
(Not here: G53 under G91, an error in LinuxCNC; G53 under G43, where the two differ.)
G17 G21 G90
G10 L2 P1 X100. Y-50. Z-25.
G10 L2 P2 X-10. Y10. Z10.
G54 G0 X0 Y0 Z0
G53 G0 X10. Y20. Z-5.
(G53 is one-shot: the next block is in G54 again)
G1 X1. F500.
G0 Y2.
G53 G0 Z0
G55 G1 X0 Y0 Z0
G53 G0 X0 Y0
G1 Z1.
G53 G0 X-10.5 Y0.25 Z-1.75
M2
