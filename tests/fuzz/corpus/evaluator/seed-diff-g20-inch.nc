1(G20: inch input for positions, arc centres and radii; machine positions compared in mm.)
(Every value has at most 4 decimals in inches, as rs274 prints them.)
G17 G20 G90
G0 X1. Y2. Z0.5
G1 X1.25 Y-0.5 Z-0.125 F20.
G91 G1 X0.75 Y0.5
G90 G2 X3. Y-1. I1. J0
G3 X2. Y0 R1.
G18 G2 X3. Z0.875 R1.
G19 G3 Y1. Z-0.125 R1.
G17 G53 G0 X0.5 Y0.5 Z0.5
G0 X0 Y0 Z0
G2 X0 Y0 I0.5 J0
M2
