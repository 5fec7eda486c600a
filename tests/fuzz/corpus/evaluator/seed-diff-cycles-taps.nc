1(Tapping: G84 needs the spindle forward, feeds to Z, reverses it and feeds out to R, then turns)
(it forward again; G74 is the same with the directions swapped. Only G99 here: under G98 a)
(FANUC feeds out to R and rapids on to the initial level, LinuxCNC feeds out all the way.)
G17 G21 G90
G0 X0 Y0 Z10.
M3 S500
G99 G84 X5. Y5. Z-6. R2. F125.
X10.
Y10. Z-8.
G80
G0 Z10.
M4 S400
G99 G74 X20. Y5. Z-5. R3. F100.
X25.
G80
M5
G0 Z10.
M2
