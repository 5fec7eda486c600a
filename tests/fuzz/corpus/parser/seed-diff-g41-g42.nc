(G41/G42 cutter radius compensation in G17: entry, outside and inside corners, arcs, exit.)
(m350-sim takes the radius from offset 1: #2001, FANUC offset memory A, D1 = 6.35 mm;)
(rs274 takes D1 as tool 1's diameter from g41-g42.tbl: 0.5 in = 12.7 mm.)
#2001=6.35
G17 G21 G90 G40
G0 X-20. Y-20. Z5.
G1 Z-1. F300.
G41 D1 G1 X0 Y0
G1 X40.
G1 Y30.
G3 X20. Y50. I-20. J0
G1 X0
G1 Y0
G40 G1 X-20. Y-20.
G0 Z5.
(the other side, around a pocket: every corner is inside)
G0 X80. Y-20.
G1 Z-1.
G42 D1 G1 X60. Y0
G1 X100.
G1 Y40.
G2 X80. Y60. I-20. J0
G1 X60.
G1 Y0
G40 G1 X80. Y-20.
G0 Z5.
M2
