1(G2/G3 in the XY plane: centre by I J from the start point, and by R; under a work offset.)
G17 G21 G90
G10 L2 P1 X50. Y25. Z-10.
G54 G0 X0 Y0 Z0
G1 X10. F600.
(a quarter counter-clockwise about the work origin)
G3 X0 Y10. I-10. J0
(a quarter clockwise back)
G2 X10. Y0 I0 J-10.
(R: the short way for R > 0, the long way for R < 0)
G3 X0 Y10. R10.
G2 X10. Y0 R-10.
G2 X0 Y-10. R10.
(a full circle: start and end the same, centre by I J)
G3 X0 Y-10. I0 J10.
G2 X0 Y-10. I-5. J0
(incremental end point; I J are from the start in G90 and G91 alike)
G91 G2 X10. Y10. I10. J0
G3 X-5. Y5. R5.
G90 G2 X20. Y0 R15.
M2
