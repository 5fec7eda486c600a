1(Where a cycle starts and ends: a cycle begun below R first rises to R where the tool stands, and)
(R is then its initial level; R and Z change between holes; a block with Z alone drills again)
(where the tool stands.)
G17 G21 G90
G0 X0 Y0 Z0
G98 G81 X5. Z-3. R2. F100.
X10. R4.
X15. R1.
Z-5.
G80
G0 Z10.
G99 G81 X20. Z-2. R1.
Z-3.
X25. Z-4. R0.5
G80
G0 Z10.
M2
