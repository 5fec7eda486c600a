(FANUC <vacant>: kept by a plain copy, 0 in arithmetic, told apart from 0 by EQ/NE)
#2=#1
#3=#1*5
#4=#1+#1
IF [#1 EQ #0] THEN #5=1
IF [#1 EQ 0] THEN #6=1
IF [#1 NE 0] THEN #7=1
IF [#1 GE 0] THEN #8=1
IF [#3 EQ 0] THEN #9=1
#100=#1
G90 G00 X10 Y#1
M30
