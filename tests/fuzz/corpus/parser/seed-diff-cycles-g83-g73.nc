(Peck drilling. G83 feeds Q deeper, rapids out to R, rapids back to 0.254 mm above the depth)
(drilled and feeds on; G73 only backs off 0.254 mm. 0.254 mm, LinuxCNC's 0.010 inch, is what)
(m350-sim uses while parameter 224 is 0. The last peck stops at Z, also when Z is no multiple of Q.)
G17 G21 G90
G0 X0 Y0 Z10.
G98 G83 X5. Y5. Z-10. R2. Q3. F150.
X10.
G99 Y10.
X15. Z-4.5
G80
G0 Z8.
G98 G73 X20. Y0 Z-9. R1. Q2.5 F150.
X25.
G99 Y5.
X30. Q4.
G80
G0 Z8.
(a peck deeper than the hole: one feed to Z)
G98 G83 X35. Y0 Z-1. R1. Q5.
G80
G0 Z10.
M2
