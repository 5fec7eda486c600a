(Canned cycles G81 and G82: rapid to the hole, rapid to R, feed to Z, dwell for G82, rapid out:)
(G98 to the level the cycle began at, G99 to R. The cycle repeats at every new position with)
(its Z R P kept, until G80 or a motion code. LinuxCNC starts in G99: give G98/G99 always, and)
(switch from G98 to G99 only, see README.md.)
(G82 P is milliseconds on a FANUC, seconds in LinuxCNC: the dwell is not compared.)
G17 G21 G90
G10 L2 P1 X10. Y20. Z30.
G54 G0 X0 Y0 Z10.
G98 G81 X5. Y6. Z-3. R2. F200.
X15.
Y16.
G99 X25.
X35. Y6.
G80
G0 Z20.
G98 G82 X40. Y10. Z-4.5 R1.5 P500
X45.
G99 Y15.
X50.
G80
G0 X0 Y0 Z10.
(the cycle ended by a motion code: the next one takes a new initial level)
G98 G81 X5. Y5. Z-2. R3.
G1 X10. Z6.
G98 G81 X12. Z-2. R3.
G80
G0 Z10.
M2
