(LinuxCNC's tool table codes on a machine that keeps a tool.tbl: M61 sets the tool number, G10 L0)
(reloads the table and keeps what G10 L1 wrote, G43 H reads it, G43.1 gives the length itself.)
(rs274 reads linuxcnc-tool-codes.tbl in inches, m350-sim linuxcnc-tool-codes.sim.tbl in mm.)
G17 G21 G90
M61 Q0
G10 L2 P1 X1. Y2. Z-50.
G0 G54 X0 Y0 Z10.
(tool 1 becomes 25.4 long; the reload reads the file and keeps it, as LinuxCNC wrote it there)
G10 L1 P1 Z25.4
G10 L0
G43 H1 G0 Z5.
T2 M6
G43 H2 G0 Z5.
(tool 1 in the spindle without a change; its length when G43 H1 reads it)
M61 Q1
G43 H1 G0 Z4.
(a length without a table entry, applied by the next move)
G43.1 Z3.175
G0 Z2.
G49 G0 Z1.
M2
