1(Helices: an arc in the active plane with a move along the third axis.)
G17 G21 G90
G10 L2 P1 X5. Y5. Z5.
G54 G0 X10. Y0 Z0
(half a turn down Z)
G3 X-10. Y0 Z-5. I-10. J0 F600.
(a full turn: same start and end in the plane)
G3 X-10. Y0 Z-10. I10. J0
G2 X0 Y10. Z-12.5 R10.
(ZX plane, along Y)
G18 G2 X10. Y5. Z-2.5 I10. K0
(YZ plane, along X)
G19 G3 X0 Y-5. Z-2.5 J-5. K0
(incremental full turn)
G17 G91 G2 X0 Y0 Z-2. I-5. J0
G90 G0 Z10.
M2
