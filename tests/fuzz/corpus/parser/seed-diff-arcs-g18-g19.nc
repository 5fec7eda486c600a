(G2/G3 in the ZX plane, G18, and the YZ plane, G19: centre by I K or J K, and by R.)
(The direction of an R arc decides which side of the chord its centre lies on.)
G17 G21 G90
G10 L2 P1 X10. Y20. Z30.
G54 G0 X0 Y0 Z0
G18 G2 X10. Z0 I5. K0 F600.
G3 X20. Z-10. I0 K-10.
G2 X30. Z0 R10.
G3 X10. Z0 R-15.
G2 X10. Z0 I-5. K0
G19 G0 X0 Y0 Z0
G2 Y10. Z0 J5. K0
G3 Y20. Z10. R10.
G2 Y0 Z0 R-12.
G3 Y10. Z0 R8.
G3 Y10. Z0 J0 K4.
G17 G0 X0 Y0 Z0
M2
