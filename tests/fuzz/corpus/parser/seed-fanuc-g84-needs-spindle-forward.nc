(G84 right-hand tapping needs the spindle turning forward: without M3 the cycle block alarms)
(before it moves, and the tool stays where the previous block left it)
G90 G00 X0 Y0 Z10.
G98 G84 X5. Z-3. R2. F100.
M30
