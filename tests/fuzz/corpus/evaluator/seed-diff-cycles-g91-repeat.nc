1(Canned cycles under G91: R is the distance from the initial level, Z the distance from R, and)
(X Y steps repeat L times, L as LinuxCNC writes it, K on a FANUC. Under G90, L drills the same)
(hole again.)
G17 G21 G90
G0 X0 Y0 Z10.
G91 G98 G81 X10. Y5. Z-6. R-8. L3 F200.
G99 X-5. L2
G90 G80
G0 X0 Y0 Z10.
G91 G98 G83 X4. Z-7. R-9. Q2. L2 F200.
G99 G73 Y4. Z-5. R-8. Q1.5 L2
G90 G80
G0 Z10.
G90 G98 G81 X3. Y3. Z-1. R2. L2
G80
G0 Z10.
M2
