1(FANUC loops are DO1 to DO3)
#1 = 0
WHILE [#1 LT 3] DO4
#1 = #1 + 1
END4
M30
