(G28: to the intermediate point in work coordinates, then the axes written to machine zero.)
(rs274 goes to its G28 position #5161-#5163, 0 without a parameter file: machine zero too.)
G17 G21 G90
G10 L2 P1 X100. Y50. Z-10.
G54 G0 X10. Y10. Z10.
G28 Z20.
G0 X1. Y1.
G28 X5. Y5.
(under G91 the intermediate point is relative: Z0 means where the tool is)
G91 G28 Z0
G90 G0 X0 Y0 Z0
M2
