(Canned cycles in inches: R, Z and Q are inches; the peck clearance stays 0.010 inch.)
G17 G20 G90
G0 X0 Y0 Z0.5
G98 G83 X1. Y1. Z-0.35 R0.1 Q0.1 F10.
X2.
G99 G73 X3. Z-0.3 R0.05 Q0.12
G80
G0 Z0.5
M2
