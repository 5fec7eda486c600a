(G41/G42 cutter radius compensation in the G18 ZX plane: as G17, with Z and X in the roles of X and Y,)
(seen from +Y. m350-sim takes the radius from offset 1, #2001 = 6.35 mm; rs274 from g41-g18.tbl, 0.5 in.)
#2001=6.35
G18 G21 G90 G40
(a loop counterclockwise, its corner rounded: G41 keeps the tool inside, every corner inside)
G0 X-20. Y0 Z-20.
G41 D1 G1 X0 Z0 F300.
G1 Z40.
G1 X30.
G3 X50. Z20. K-20. I0
G1 Z0
G1 X0
G40 G1 X-20. Z-20.
(the same loop with G42: the tool outside, arcs around the corners)
G42 D1 G1 X0 Z0
G1 Z40.
G1 X30.
G3 X50. Z20. K-20. I0
G1 Z0
G1 X0
G40 G1 X-20. Z-20.
M2
