(G10 L1, L10 and L11 write the tool table as LinuxCNC does, and G43 reads it when given.)
(rs274 reads g10-tool-table.tbl, m350-sim g10-tool-table.sim.tbl: the same two empty tools.)
(In G20 both take the table's numbers as inches: rs274 its machine unit, m350-sim the input unit.)
G17 G20 G90
G10 L2 P1 X1. Y2. Z-3.
G0 G54 X0 Y0 Z2.
(L1: tool 1 is 0.5 long)
G10 L1 P1 Z0.5
G0 G43 H1 Z1.
(L10: tool 1 so that here reads Z0.25, i.e. 1.25)
G10 L10 P1 Z0.25
G0 G43 H1 Z1.
(L11: tool 2 so that here reads Z0.5 from machine zero, i.e. -1.25)
G10 L11 P2 Z0.5
G0 G43 H2 Z1.
(G43 and G10 L10 in one block: G43 first, with tool 1's old length; the next G43 takes the new)
G43 H1 G10 L10 P1 Z0.75
G0 Z1.
G0 G43 H1 Z1.
G49 G0 Z2.
M2
