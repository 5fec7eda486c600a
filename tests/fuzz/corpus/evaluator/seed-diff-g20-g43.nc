1(G43 under G20: a FANUC offset value is in the input unit, so #2001=0.5 is half an inch;)
(rs274 reads tool 1 of g20-g43.tbl, 0.5 inch too.)
G17 G20 G90
#2001=0.5
G0 X1. Y1. Z2.
G0 G43 H1 Z1.
G1 Z0 F20.
G49 G0 Z2.
M2
