1(FANUC M98 opens no local level: the subprogram sees and changes the caller's #1)
#1 = 5
M98 P100
#100 = #1
M30
O100
#1 = #1 + 1
M99
