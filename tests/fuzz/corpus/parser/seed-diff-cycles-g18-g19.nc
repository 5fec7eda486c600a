(Canned cycles in the ZX plane, G18, drilling along Y, and in the YZ plane, G19, drilling along X.)
G17 G21 G90
G0 X0 Y10. Z0
G18 G98 G81 X5. Z3. Y-3. R2. F100.
X8.
G99 Z6.
G80
G0 Y10.
G98 G83 X12. Z3. Y-4. R1. Q2.
G80
G19 G0 X10. Y0 Z0
G99 G83 Y5. Z7. X-3. R2. Q2. F100.
Y9.
G98 G81 Z9. X-1. R1.
G80
G17 G0 X10. Y0 Z10.
M2
