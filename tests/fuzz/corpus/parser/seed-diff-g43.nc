(G43 H tool length offset and G49, with and without a work offset.)
(m350-sim takes offsets H1 and H2 from #2001 and #2002, the FANUC tool offset memory;)
(rs274 takes them from g43.tbl, where tools 1 and 2 say the same lengths in inches.)
(To LinuxCNC, #2001 and #2002 are plain numbered parameters.)
(Every G43 and G49 comes with a Z word, in G90: alone or under G91 FANUC and LinuxCNC differ)
(in when the new offset moves the tool. G44 is not here: LinuxCNC has no G44.)
#2001=12.7
#2002=-3.175
G17 G21 G90
G10 L2 P1 X10. Y10. Z-100.
G54 G0 X0 Y0 Z50.
(the offset applies to the Z of the same block)
G0 G43 H1 Z20.
G1 Z5. F300.
G1 X20.
(another offset)
G0 G43 H2 Z10.
G0 X0 Y0
G1 Z-1.
(cancel with a move)
G49 G0 Z50.
G0 G43 H1 Z0
G2 X10. Y10. I5. J5.
G91 G1 Z-2.
G90 G49 G0 Z60.
M2
